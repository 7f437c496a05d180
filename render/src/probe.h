/* Reflection probes: which objects get one, when they are captured, how they are blurred. */
#ifndef RENDER_PROBE_H
#define RENDER_PROBE_H

#include "render_internal.h"
#include "scene_internal.h"

/* The probe key of object i: its group, or -(i + 1) when it stands alone. */
int rd_object_key(const rd_scene *s, int i);

/* Rebuilds the probe list after objects were added (CPU only; GL textures come later). */
rd_result rd_probes_sync(rd_scene *s);
/* Frees the probes' GL textures and the list. */
void rd_probes_destroy(rd_scene *s);

/* Captures and filters what this frame's policies ask for, before the main pass. The eye,
 * the main view's projection scale (pixels per unit of tan) and the supersampling decide the
 * "auto" resolutions; `planar` (probe_planar.h) the planar mirrors'. capture_view_proj (NULL:
 * view_proj) is the frustum whose cube probes and glazes count as in view: a strip of a
 * split capture passes the whole image's, so every probe the picture needs is captured (or
 * held) whichever strip is drawn. hold_sizes (a live view's moving frame, rd_view.live): a
 * probe that has a size keeps it. */
struct rd_planar_view;
rd_result rd_probes_update(rd_context *ctx, rd_scene *s, const float view_proj[16],
                           const float capture_view_proj[16], const float eye[3],
                           float pixels_per_tan, int supersample,
                           const struct rd_planar_view *planar, int hold_sizes,
                           rd_frame_stats *stats);

/* The effective settings of object i's material and probe after the scene's defaults. */
/* Under a scene-wide "depth" correction, materials with k_r and g both below these take the
 * box (probe.c). */
#define RD_DEPTH_MIN_REFLECTIVITY 0.25f
#define RD_DEPTH_MIN_GLOSSINESS 0.8f
rd_correction rd_effective_correction(const rd_scene *s, const rd_material *m);
rd_blur_method rd_effective_blur(const rd_scene *s);
void rd_effective_proxy(const rd_scene *s, float bmin[3], float bmax[3]);
float rd_probe_lod(const rd_probe *p, float glossiness);
unsigned rd_probe_texture(const rd_scene *s, const rd_probe *p);

/* Every object's world bounding sphere for this frame (for culling). */
rd_result rd_scene_update_spheres(rd_context *ctx, rd_scene *s);

int rd_level_count(int size);
rd_result rd_reference_blur_level(rd_probe *p, unsigned source, int source_size, int level);
rd_result rd_alloc_cube(unsigned *name, int size, int levels);
/* Renders face `face` of p's capture from p->centre, leaving out p->key's objects. */
rd_result rd_probe_capture_face(rd_context *ctx, rd_scene *s, rd_probe *p, int face, float far_m);
/* The scene's ambient probe and its SH9 coefficients (ambient_sh.c), when the ambient model
 * asks for them. */
rd_result rd_ambient_update(rd_context *ctx, rd_scene *s, rd_frame_stats *stats);
/* Sphere maps of the probes whose materials ask for one, for this view (sphere_map_gpu.c). */
rd_result rd_sphere_maps_update(rd_context *ctx, rd_scene *s, const float view_rot[9]);

/* World bounds of object i (its mesh bounds through its transform). */
void rd_object_world_bounds(rd_context *ctx, const rd_object_desc *o, float lo[3], float hi[3]);

#endif
