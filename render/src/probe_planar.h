/* Planar mirrors: a flat mirror's probe captured from the eye's mirror image (probe_planar.c). */
#ifndef RENDER_PROBE_PLANAR_H
#define RENDER_PROBE_PLANAR_H

#include "probe.h"

/* Whether object o's material and probe settings allow a planar mirror (the scene's
 * planar_mirrors on, a sharp opaque mirror, nothing that asks for another lookup). Such an
 * object takes a probe of its own (rd_object_key): a mirror's back panel in its product's
 * group needs a blurred ordinary probe. */
int rd_planar_candidate(const rd_scene *s, const rd_object_desc *o);
/* Decides whether p is a planar mirror for this eye; if so sets p->planar, p->plane, p->quad
 * and moves p->centre to the eye's image. Returns p->planar. */
int rd_probe_plan_planar(rd_context *ctx, const rd_scene *s, rd_probe *p, const float eye[3]);
/* The planes of what a planar mirror p shows (p->planar set): the pyramid from the eye's image
 * through the mirror's quad, cut by the mirror's plane; each n.x + d >= 0 inside. */
void rd_planar_pyramid(const rd_probe *p, float planes[5][4]);
/* The main view a planar capture is made for: the samples its main pass shades (an adaptive
 * view's one a pixel, read at a texel a pixel: renderer.c). */
typedef struct rd_planar_view {
    const float *view_proj;  /* column-major 4x4 */
    float samples[2];        /* the samples across and down view_proj's image */
    float samples_per_tan;   /* the whole image's pixels per unit of tan x supersampling */
    float texels_per_sample; /* the capture's texels a sample across; 0: 1.5 */
} rd_planar_view;
/* Renders p's planar capture (p->planar_texture, p->planar_view_proj) for this frame, with as
 * many texels as the mirror covers samples of the view (at most 4096 a side). */
rd_result rd_planar_capture(rd_context *ctx, rd_scene *s, rd_probe *p, const rd_planar_view *v,
                            float far_m);

#endif
