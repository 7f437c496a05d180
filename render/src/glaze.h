/* Glazes: glossy surfaces with no probe of their own (glazed tiles, glossy ceramic) that
 * reflect the room probe by Schlick's Fresnel for glass (lit.frag's GLAZE variant). */
#ifndef RENDER_GLAZE_H
#define RENDER_GLAZE_H

#include "render_internal.h"
#include "scene_internal.h"

#include <cglm/cglm.h>

/* A glaze's highlight is at least this strong and this narrow (RENDERING.md section 1's C_s
 * and n): a glossy tile (C_s 0.25, n 64) is one, a matt tile (0.1, 16), grout (0.05, 8) or
 * wood (0.15, 40) is not. */
#define RD_GLAZE_MIN_SPECULAR 0.2f
#define RD_GLAZE_MIN_SHININESS 32.0f

/* Whether a material is a glaze: opaque, not glowing, not reflecting through a probe of its
 * own (k_r = 0), with a highlight at least as strong and narrow as the limits above. */
int rd_material_glazed(const rd_material *m);

/* The glossiness g (RENDERING.md section 5, n = 2^(13 g)) whose Phong lobe about R is as wide
 * as a Blinn-Phong highlight of exponent n_h about N: n = n_h / 4, as the half vector turns by
 * half the reflected ray's angle (cos^n_h(t / 2) ~ exp(-n_h t^2 / 8) = exp(-n t^2 / 2)). */
float rd_glaze_glossiness(float shininess);

/* With the scene's glaze switch on: the glazes inside the view's frustum planes (their count),
 * and the range of every glaze's glossiness, in view or not, for the room probe's blur (a
 * tiled render's tiles then share one room probe). 0 and an empty range when off. */
int rd_glazes_in_view(const rd_scene *s, vec4 planes[6], float *g_min, float *g_max);

#endif
