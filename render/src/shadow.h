/* Shadow maps (docs/rendering.md, "Shadows"): one depth atlas per scene holding a cube (six
 * tiles) per point light and per wide spot light, one tile per narrow spot and directional
 * light; made before the main pass when the scene or its lights changed, read by the
 * HAS_SHADOWS variant of lit.frag (render/shaders/shadow.glsl). */
#ifndef RENDER_SHADOW_H
#define RENDER_SHADOW_H

#include "render_internal.h"

typedef struct rd_shadow_maps rd_shadow_maps;

/* Makes (or keeps, when nothing changed) the scene's shadow maps. No-op when shadows are off. */
rd_result rd_shadow_maps_update(rd_context *ctx, rd_scene *scene);
/* 1 when the main pass should use the HAS_SHADOWS variant. */
int rd_shadows_active(const rd_scene *scene);
/* This frame's taps per sample and window origin (before the main pass). */
void rd_shadow_frame(rd_scene *scene, const rd_view *v, int samples);
/* Sets the shadow uniforms of a HAS_SHADOWS lit program (in use) and binds the atlas. */
void rd_shadow_set_uniforms(const rd_program *p, const rd_scene *scene);
void rd_shadow_maps_destroy(rd_scene *scene);

/* programs.c: links embedded shaders (names separated by spaces) with #defines; 0 on failure. */
unsigned rd_link_program(const char *vert, const char *frag, const char *defines);

#endif
