/* Draws a scene's objects with the lit programs: the main view and every probe face. */
#ifndef RENDER_DRAW_H
#define RENDER_DRAW_H

#include "render_internal.h"
#include "scene_internal.h"

typedef struct rd_pass {
    const float *view_proj; /* column-major 4x4 */
    const float *view_rot;  /* column-major 3x3 world-to-view rotation (sphere maps) */
    const float *eye;
    int exclude_key;        /* objects of this probe key are left out (a probe's owner); 0 = none */
    int reflections;        /* 1: reflective objects use their probes; 0: drawn plain (in probes) */
    int planar_off;         /* 1: a planar mirror's capture: other planar mirrors drawn plain,
                               no self-reflections traced */
    float min_solid_radius; /* skip objects whose radius / distance is below this; 0 = none */
    int specular_off;       /* draw without the Blinn-Phong highlight term */
    int store_distance;     /* a probe capture: alpha = distance from the eye ("depth" lookup) */
    int shadows;            /* 1: the scene's shadow maps darken what they cover (main view) */
    int depth_prepass;      /* 1: depth only first, then shade each visible pixel once */
    int isotropic_textures; /* 1: trilinear textures without anisotropy (probe captures) */
    int full_meshes;        /* 1: a capture draws objects' full meshes, not probe meshes */
    int exclude_emitters;   /* 1: the scene's analytic emitters are left out (emitters.c) */
    const rd_self_bvh *exclude_traced; /* its parts are left out: the lookups trace them */
    int sample_grid; /* the view's samples a pixel side (the lookups' lobe strata); 0 = 1 */
    int rect_lights_as_points; /* 1: unshadowed programs light with rectangle lights as point
                                  lights of their power (rd_view.live) */
    int panes_over;  /* 1: thin panes with their probes are blended over what was drawn behind
                        them, last (a planar mirror's capture: draw.c, pane_over) */
    int all_objects; /* 1: no frustum culling (rd_view.all_objects: a shader warm-up) */
} rd_pass;

rd_result rd_draw_objects(rd_context *ctx, rd_scene *scene, const rd_pass *pass);
/* The view's own pass: reflections, shadows, the depth prepass (renderer.c, and the adaptive
 * refinement of renderer_adaptive.c). */
rd_result rd_draw_view(rd_context *ctx, rd_scene *scene, const float *view_proj,
                       const float *view_rot, const float *eye, int sample_grid, int live,
                       int all_objects);

/* Per-frame (view, lights) and per-object (model, material) uniforms of a lit program. */
void rd_set_frame_uniforms(const rd_program *p, const rd_scene *s, const float vp[16],
                           const float eye[3]);
void rd_set_object_uniforms(const rd_program *p, const float model[16], const rd_material *m);

#endif
