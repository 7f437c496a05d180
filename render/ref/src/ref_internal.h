/* Internals shared by the tracer's .c files; nothing here is public. */
#ifndef REF_INTERNAL_H
#define REF_INTERNAL_H

#include "ref/ref.h"

#include <embree3/rtcore.h>
#include <stdbool.h>

/* Sets the thread's last error (printf-style) and returns r for chaining. */
ref_result ref_fail(ref_result r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* ---- textures (ref_texture.c) ------------------------------------------------------------- */

typedef struct ref_mip {
    int width, height;
    float *rgb; /* 3 floats per texel, top row first */
} ref_mip;

typedef struct ref_texture {
    int levels;
    ref_mip *mips; /* level 0 is the image; each next one halves the sides (at least 1) */
} ref_texture;

ref_result ref_texture_build(const ref_texture_desc *d, ref_texture *out);
void ref_texture_free(ref_texture *t);

/* The GPU's texture lookup: repeat wrap, bilinear within a level, linear between levels
 * (GL_LINEAR_MIPMAP_LINEAR), lod <= 0 = level 0 (magnification, GL_LINEAR). */
void ref_texture_sample(const ref_texture *t, float u, float v, float lod, float out[3]);

/* A lookup over a pixel footprint given by the UV derivatives along the image's x and y
 * (per subpixel), as EXT_texture_filter_anisotropic defines it with max_aniso probes along the
 * major axis; max_aniso 1 = isotropic trilinear. */
void ref_texture_sample_footprint(const ref_texture *t, const float uv[2], const float duv_dx[2],
                                  const float duv_dy[2], int max_aniso, float out[3]);

/* ---- scene (ref_scene.c) ------------------------------------------------------------------ */

typedef struct ref_mesh {
    float *positions; /* world, 3 per vertex */
    float *normals;   /* world (inverse transpose), not normalised: the GPU interpolates these */
    float *uvs;       /* 2 per vertex */
    float *object_positions; /* model space, 3 per vertex, for a patterned material; else NULL */
    uint32_t *indices;
    float *tri_normals; /* world geometric normal (p1 - p0) x (p2 - p0) per triangle */
    int vertex_count, triangle_count;
    rd_material material;
    int texture; /* index + 1 into ref_scene.textures, 0 = none */
    int double_sided;
    bool glass;      /* transparency > 0: invisible to secondary rays (the GPU probes skip it) */
    bool reflective; /* reflectivity > 0 or transparency > 0: the GPU gives it a probe */
    bool background; /* casts no shadow (ref_shadow.c) */
    bool light_stand_in; /* ref_mesh_desc.light_stand_in */
    float uv_scale[2];
    float emission[3]; /* max(C_emissive, 0): the radiance it emits as an area light */
} ref_mesh;

/* The emitting triangles the path tracer samples for next-event estimation (ref_path.c): each
 * picked with probability area x power / total, power the mean of its emission. */
typedef struct ref_emitters {
    int count;
    int *mesh, *prim;
    double *cdf;  /* running sum of area x power, cdf[count - 1] = total */
    double total; /* 0: no area lights */
} ref_emitters;

struct ref_scene {
    ref_mesh *meshes;
    int mesh_count, mesh_capacity;
    ref_texture *textures;
    int texture_count, texture_capacity;
    rd_light lights[RD_MAX_LIGHTS];
    int light_count;
    float ambient[3];
    /* SH9 ambient (ref_scene_set_ambient_sh9): 0 off, 1 wanted, 2 the capture is being traced
     * (ambient 0, as on the GPU), 3 made. */
    int sh9_state;
    float sh9_centre[3];
    rd_sh9 sh9;
    rd_shadow_settings shadows;
    int shadow_taps; /* per sample: rd_shadow_taps_per_sample at the render's supersampling */
    float bounds_min[3], bounds_max[3]; /* world bounds of every vertex */
    float epsilon;                      /* ray offset: 1e-5 of the scene's diagonal */
    RTCDevice device;
    RTCScene rtc;
    bool dirty;            /* meshes were added since the last commit */
    ref_emitters emitters; /* made by ref_render for path tracing (ref_path.c) */
};

/* ---- tracing (ref_trace.c) ---------------------------------------------------------------- */

/* A ray's differentials for texture filtering: the directions of the rays one subpixel to the
 * right and one below (NULL = no footprint: level 0). */
typedef struct ref_ray_diff {
    float dir_dx[3], dir_dy[3];
} ref_ray_diff;

typedef struct ref_trace_stats {
    long long rays;
} ref_trace_stats;

/* A ray's first hit with the shading data lit.frag would have there. */
typedef struct ref_surface {
    const ref_mesh *mesh;
    unsigned geom, prim;
    float t;
    float p[3];
    float n[3]; /* shading normal as lit.frag makes it: unit (or V), flipped on back faces */
    float uv[2];
    float object_p[3]; /* the point in model space (patterned materials only) */
    int front;
} ref_surface;

/* The first surface along (org, dir) past tnear, leaving out triangle (skip_geom, skip_prim),
 * back faces of closed meshes and, when `secondary`, glass. 1 on a hit. */
int ref_intersect(const ref_scene *s, const float org[3], const float dir[3], float tnear,
                  unsigned skip_geom, unsigned skip_prim, int secondary, ref_surface *out,
                  ref_trace_stats *stats);

/* The diffuse texture's colour at the hit (1 without a texture); with the primary ray's
 * differentials (diff, from org) filtered over its footprint, else level 0. */
void ref_surface_albedo(const ref_scene *s, const ref_surface *sf, const float org[3],
                        const float dir[3], const ref_ray_diff *diff, float out[3]);

/* Deterministic uniform numbers in [0, 1): index-th of the stream `key` (splitmix64). */
uint64_t ref_mix64(uint64_t z);
float ref_uniform01(uint64_t key, uint64_t index);
/* An orthonormal basis around unit a (Duff et al. 2017). */
void ref_basis(const float a[3], float t[3], float b[3]);

/* ---- path tracing (ref_path.c) ------------------------------------------------------------ */

/* Builds s->emitters from the meshes' emission (after the commit). */
ref_result ref_emitters_prepare(ref_scene *s);
void ref_emitters_free(ref_emitters *e);

/* The mean radiance of `paths` paths through one primary ray with up to `bounces` indirect
 * bounces (docs/reference.md, "Indirect light"); *reflective as ref_trace_primary. */
void ref_path_primary(const ref_scene *s, const float origin[3], const float dir[3],
                      const ref_ray_diff *diff, int bounces, int paths, uint64_t rng_key,
                      float out[3], int *reflective, ref_trace_stats *stats);

/* The radiance of one primary ray (before exposure); *reflective gets the mask bit of its first
 * hit. rng_key seeds this ray's Monte-Carlo samples. */
void ref_trace_primary(const ref_scene *s, const float origin[3], const float dir[3],
                       const ref_ray_diff *diff, int samples, uint64_t rng_key, float out[3],
                       int *reflective, ref_trace_stats *stats);

/* Makes the SH9 ambient coefficients when the scene asks for them (ref_trace.c). */
ref_result ref_ambient_prepare(ref_scene *s);

/* ---- shadows (ref_shadow.c) --------------------------------------------------------------- */

/* The fraction of each light that reaches point p (shading normal n, unit geometric normal ng
 * of the triangle hit, on n's side): 1 everywhere when the scene's shadows are off. */
void ref_shadow_visibility(const ref_scene *s, const float p[3], const float n[3],
                           const float ng[3], float rotation, float vis[RD_MAX_LIGHTS],
                           ref_trace_stats *stats);
/* The same with the given mode and taps (the path tracer shadows every vertex). */
void ref_shadow_visibility_mode(const ref_scene *s, rd_shadow_mode mode, int taps, const float p[3],
                                const float n[3], const float ng[3], float rotation,
                                float vis[RD_MAX_LIGHTS], ref_trace_stats *stats);
/* 1 when the segment from p to q (both excluded by the ray epsilon) meets no surface. */
int ref_segment_clear(const ref_scene *s, const float p[3], const float q[3],
                      ref_trace_stats *stats);

/* ---- camera (ref_camera.c) ---------------------------------------------------------------- */

typedef struct ref_camera {
    float eye[3];
    float forward[3], right[3], up[3]; /* right and up scaled by tan(fov/2) (and the aspect) */
    int width, height;
} ref_camera;

ref_result ref_camera_make(const rd_view *v, ref_camera *out);
/* Unit direction through image point (x, y) (output pixels, top-left origin). */
void ref_camera_dir(const ref_camera *c, float x, float y, float dir[3]);

/* ---- small vector helpers ----------------------------------------------------------------- */

static inline float ref_dot(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void ref_cross(const float a[3], const float b[3], float out[3])
{
    float r[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    out[0] = r[0];
    out[1] = r[1];
    out[2] = r[2];
}

#endif
