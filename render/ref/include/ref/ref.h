/* Tessera's ground truth: a CPU ray tracer on Embree over the renderer's own scene data
 * (RENDERING.md section 10).
 *
 * It sees what rd_render sees -- the same triangles, materials, lights, camera, exposure and
 * tone map -- and shades with the same CPU twins of the shaders (render/shade_ref.h,
 * render/reflect_ref.h), so that the only difference left between the two is the reflection
 * method: where the GPU looks reflections up in per-object cube maps, this tracer follows the
 * reflected ray into the real geometry (one mirror bounce for glossiness 1, Monte-Carlo over the
 * same normalised Phong lobe for glossiness < 1). With bounces (ref_render_desc.bounces) it
 * becomes a path tracer with indirect light and area lights: the physical ground truth.
 * docs/reference.md describes every rule.
 *
 * A separate library (tessera_ref), linked by app and the tests only (ARCHITECTURE.md). Units:
 * metres, right-handed, Z up; colours linear RGB. Nothing here aborts; calls that can fail
 * return a ref_result and leave a message for ref_last_error(). */
#ifndef REF_REF_H
#define REF_REF_H

#include "render/reflect_ref.h"
#include "render/render.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum ref_result {
    REF_OK = 0,
    REF_ERR_INVALID_ARGUMENT,
    REF_ERR_OUT_OF_MEMORY,
    REF_ERR_TOO_LARGE,
    REF_ERR_EMBREE,    /* the Embree device or scene could not be made */
    REF_ERR_CANCELLED, /* the caller asked to stop (ref_bake_desc.progress_fn) */
} ref_result;

/* The message of the last failure on this thread ("" if none). */
const char *ref_last_error(void);
const char *ref_result_name(ref_result r);

/* ---- scene -------------------------------------------------------------------------------- */

typedef struct ref_scene ref_scene;

/* NULL on failure (out of memory; ref_last_error says so). The Embree device is made on the
 * first ref_scene_commit. */
ref_scene *ref_scene_create(void);
void ref_scene_destroy(ref_scene *s);

/* A diffuse texture: LINEAR RGBA floats (decode sRGB files first), top row first, sampled as the
 * GPU samples its textures (repeat, bilinear, mip-mapped with a box-filtered chain). Returns its
 * id (>= 1) for ref_mesh_desc.texture, or 0 on failure. Non-finite texels become 0. */
typedef struct ref_texture_desc {
    int width, height;
    const float *rgba;
} ref_texture_desc;
int ref_scene_add_texture(ref_scene *s, const ref_texture_desc *d);

/* One triangle mesh placed in the world, as rd_object_desc places an rd_mesh. The data is
 * copied (transformed to world space) and may be freed after the call. */
typedef struct ref_mesh_desc {
    const float *positions; /* 3 per vertex, model space */
    const float *normals;   /* 3 per vertex, model space (transformed by the inverse transpose) */
    const float *uvs;       /* 2 per vertex, may be NULL (all 0) */
    const uint32_t *indices;
    int vertex_count;
    int index_count;      /* a multiple of 3 */
    float transform[16];  /* column-major model matrix; all zero = identity */
    rd_material material; /* diffuse_texture and correction are ignored here */
    int texture;          /* from ref_scene_add_texture; 0 = none */
    /* As rd_object_desc.double_sided: 0 = closed, back faces are invisible (the GPU culls
     * them); 1 = an open sheet seen from both sides, and glass on it passes light straight
     * through (a thin pane) instead of refracting. */
    int double_sided;
    /* As rd_object_desc.background: an enclosing room surface, which casts no shadow. */
    int background;
    /* An emitting surface whose light the scene's lights already carry (a window's exterior
     * panel and the window's rectangle light and sun): seen, but not an area light. */
    int light_stand_in;
} ref_mesh_desc;
ref_result ref_scene_add_mesh(ref_scene *s, const ref_mesh_desc *d);

/* As rd_scene_add_light: at most RD_MAX_LIGHTS; spot and directional directions are
 * normalised here (a zero direction is refused). */
ref_result ref_scene_add_light(ref_scene *s, const rd_light *light);
void ref_scene_set_ambient(ref_scene *s, const float intensity[3]); /* I_a */
/* RENDERING.md section 7's second ambient model, as the GPU makes it (render/src/ambient_sh.c):
 * the ambient intensity at a surface of normal N is max(E(N), 0) / pi, E from nine SH
 * coefficients projected from what a 32-texel cube capture at `centre` (the box proxy's centre)
 * sees, box-filtered to 8 texels: surfaces lit by direct light without ambient (the GPU's
 * capture runs before any coefficients exist), highlights seen from the centre, reflective
 * objects plain, glass left out. NULL: back to the constant I_a. The coefficients are made by
 * ref_render (after the scene's commit). */
void ref_scene_set_ambient_sh9(ref_scene *s, const float centre[3]);
/* The nine coefficients the last ref_render used; 0 when SH9 is off or not made yet. */
int ref_scene_ambient_sh9(const ref_scene *s, rd_sh9 *out);
int ref_scene_mesh_count(const ref_scene *s);
/* Shadows as rd_scene_set_shadows draws them (docs/reference.md, "Shadows"): at a primary hit,
 * one shadow ray toward each light (HARD), or one from each of the GPU's PCF taps (SOFT: the
 * same Vogel disk of softness_m in the receiver's tangent plane), occluded by anything but
 * background meshes and glass. Reflected and transmitted hits stay unshadowed, as the GPU's
 * probe captures are. Default off. */
void ref_scene_set_shadows(ref_scene *s, const rd_shadow_settings *settings);

/* Builds the acceleration structure. ref_render and ref_scene_intersect call it when the
 * scene changed; call it yourself to time the build apart. Not thread-safe with itself. */
ref_result ref_scene_commit(ref_scene *s);

/* ---- render ------------------------------------------------------------------------------- */

typedef struct ref_render_desc {
    /* Camera, size, exposure and tone map exactly as rd_render reads them (near/far are not
     * used). supersample s (0 or 1 = none, up to 16): s x s rays per pixel through the centres
     * of a regular subpixel grid -- the GPU's own sample positions at s <= 4. */
    rd_view view;
    int samples;   /* rays per glossy lookup (glossiness < 1) per subpixel; 0 = 64 */
    int threads;   /* worker threads; 0 = the online processors */
    uint32_t seed; /* Monte-Carlo seed: the same seed gives the same image for any threads */
    int tile;      /* tile side in pixels handed to a thread at a time; 0 = 16 */
    int progress;  /* 1: redraw a progress bar on stderr (only when stderr is a terminal) */
    /* Indirect light (docs/reference.md, "Indirect light"): 0 = the direct-only mode above;
     * N >= 1 = a path tracer with up to N diffuse/glossy bounces, next-event estimation of
     * every light and of emitting meshes (area lights), always shadowed, without the ambient
     * term. `samples` is then the paths per subpixel. At most REF_MAX_BOUNCES. */
    int bounces;
} ref_render_desc;

#define REF_MAX_BOUNCES 1024
/* The indirect bounces of `tessera reference` and of the bake (ref_bake.h) by default: the
 * GPU's baked image carries the same light as the ground truth it is measured against. */
#define REF_DEFAULT_BOUNCES 4

typedef struct ref_image {
    int width, height;
    /* Linear radiance after exposure, averaged over the subpixels: what rd_read_linear gives
     * (RGBA float, alpha 1, top row first). */
    float *linear;
    /* Display bytes: exposure, tone map per subpixel, average, sRGB encode -- what
     * rd_read_rgba8 gives (RGBA, alpha 255, top row first). */
    unsigned char *rgba8;
    /* One byte per pixel: 1 where at least half of the pixel's subpixel rays first hit a
     * surface with reflectivity > 0 or transparency > 0 (the GPU's probe objects), else 0. */
    unsigned char *mask;
    long long rays;    /* rays traced, primary and secondary */
    double seconds;    /* wall time of the trace (the commit excluded) */
    int threads_used;  /* worker threads that ran */
    float exposure_ev; /* the exposure used (view.auto_exposure: measured as rd_render does) */
} ref_image;

/* Traces a view of the scene. On success *out owns its arrays (ref_image_free); on failure it
 * is zeroed. */
ref_result ref_render(ref_scene *s, const ref_render_desc *d, ref_image *out);
void ref_image_free(ref_image *img);

/* The largest finite half float: an .exr keeps linear radiance in halves. */
#define REF_HALF_MAX 65504.0f
/* Clamps img->linear to [0, REF_HALF_MAX] (NaN -> 0) so that no value turns into Inf when it is
 * written as half floats (a lamp of 1e6 is brighter than any half). */
void ref_image_clamp_half(ref_image *img);

/* ---- single rays, for tests and diagnostics ------------------------------------------------ */

/* The primary ray through the image point (x, y) in output pixels (0..width, 0..height, origin
 * at the top-left corner; a pixel's centre is at +0.5): origin = the eye, dir unit. The same
 * lookAt and perspective as the GPU camera (render/src/camera.c). */
ref_result ref_camera_ray(const rd_view *v, float x, float y, float origin[3], float dir[3]);

typedef struct ref_hit {
    float t;           /* distance along the (unit) ray */
    float position[3]; /* interpolated from the triangle's world vertices */
    float normal[3];   /* shading normal, unit, flipped toward the ray's origin on back faces */
    float uv[2];       /* the mesh's UVs (before uv_scale) */
    int mesh;          /* index in the order meshes were added */
    int triangle;
    int front; /* 1: the ray hit the triangle's front (counter-clockwise) side */
} ref_hit;

/* The first surface the ray meets (back faces of closed meshes are skipped, as the GPU culls
 * them). Returns 1 on a hit, 0 on a miss or an error. dir need not be unit. */
int ref_scene_intersect(ref_scene *s, const float origin[3], const float dir[3], ref_hit *hit);

/* The radiance one primary ray brings back, before exposure: direct light at its first hit and,
 * on a reflective or transparent surface, the traced reflection and transmission blended as in
 * section 6 (textures sampled without a pixel footprint). `samples` and `seed` as in
 * ref_render_desc. Black on a miss. */
ref_result ref_trace_ray(ref_scene *s, const float origin[3], const float dir[3], int samples,
                         uint32_t seed, float out[3]);

#ifdef __cplusplus
}
#endif
#endif
