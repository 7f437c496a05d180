/* Tessera renderer: the public API. No GL types cross this header (ARCHITECTURE.md).
 *
 * The shape follows Filament and sokol: a context owns every GPU object; a scene holds
 * meshes placed with materials plus lights; a view says where the camera is and what size
 * to render; rd_render draws a view of a scene into the context's float target, tone maps
 * it, and the result is read back with rd_read_rgba8 / rd_read_linear.
 * Units: metres, right-handed, Z up. Colours: linear RGB. */
#ifndef RENDER_RENDER_H
#define RENDER_RENDER_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rd_result {
    RD_OK = 0,
    RD_ERR_INVALID_ARGUMENT,
    RD_ERR_BACKEND_UNAVAILABLE,
    RD_ERR_GL,
    RD_ERR_SHADER,
    RD_ERR_OUT_OF_MEMORY,
    RD_ERR_TOO_LARGE,
    RD_ERR_STALE_HANDLE,
} rd_result;

/* The message of the last failure on this thread ("" if none). */
const char *rd_last_error(void);
const char *rd_result_name(rd_result r);

/* ---- context ---------------------------------------------------------------------------- */

typedef enum rd_backend {
    RD_BACKEND_DEFAULT = 0, /* TESSERA_GL if set, else EGL, else OSMesa */
    RD_BACKEND_EGL,         /* EGL on Mesa's surfaceless platform (or a device) */
    RD_BACKEND_OSMESA,      /* Mesa's off-screen library */
    RD_BACKEND_ADOPT,       /* the caller's current context (the GLFW window) */
} rd_backend;

/* "egl", "osmesa", "adopt" -> backend; returns RD_ERR_INVALID_ARGUMENT for anything else. */
rd_result rd_backend_parse(const char *name, rd_backend *out);
const char *rd_backend_name(rd_backend b);

typedef struct rd_context rd_context;

typedef struct rd_context_desc {
    rd_backend backend;
    /* RD_BACKEND_ADOPT only: the window library's loader (glfwGetProcAddress). */
    void *(*get_proc_address)(const char *name);
} rd_context_desc;

rd_result rd_context_create(const rd_context_desc *desc, rd_context **out);
void rd_context_destroy(rd_context *ctx);
rd_backend rd_context_backend(const rd_context *ctx);
/* GL_RENDERER and GL_VERSION as one line, e.g. "llvmpipe (LLVM 15.0.6, 256 bits); 4.5 (Core
 * Profile) Mesa 22.3.6". */
const char *rd_context_description(const rd_context *ctx);
/* The largest render target side this context can make (before supersampling). */
int rd_context_max_size(const rd_context *ctx);
/* Waits until all submitted GPU work has finished (for timing). */
void rd_finish(rd_context *ctx);

/* ---- GPU resources: handles with a generation, so a stale handle is detected ------------- */

typedef struct rd_mesh {
    uint32_t id;
} rd_mesh;
typedef struct rd_texture {
    uint32_t id;
} rd_texture;

typedef struct rd_mesh_desc {
    const float *positions; /* 3 per vertex */
    const float *normals;   /* 3 per vertex */
    const float *uvs;       /* 2 per vertex, may be NULL */
    const uint32_t *indices;
    int vertex_count;
    int index_count; /* a multiple of 3 */
} rd_mesh_desc;

rd_mesh rd_mesh_create(rd_context *ctx, const rd_mesh_desc *desc); /* id 0 on failure */
void rd_mesh_destroy(rd_context *ctx, rd_mesh mesh);

typedef struct rd_texture_desc {
    int width, height;
    const float *rgba; /* 4 floats per texel, top row first */
    int srgb_encoded;  /* 1: values are sRGB display values, decoded to linear on sampling */
} rd_texture_desc;

rd_texture rd_texture_create(rd_context *ctx, const rd_texture_desc *desc);
void rd_texture_destroy(rd_context *ctx, rd_texture tex);

/* ---- scene -------------------------------------------------------------------------------- */

/* RENDERING.md section 1; the same struct feeds the CPU reference (shade_ref.h). */
typedef struct rd_material {
    float ambient[3];  /* C_a */
    float diffuse[3];  /* C_d, multiplied by the texture if any */
    float specular[3]; /* C_s */
    float emissive[3]; /* C_emissive, combined by per-channel max (seed 002 eq. 7) */
    float shininess;   /* n, 0 .. 1e6 */
    rd_texture diffuse_texture;
    float uv_scale[2]; /* texture repeats per unit of the mesh's UVs; 0 = 1 */
} rd_material;

typedef enum rd_light_type {
    RD_LIGHT_POINT = 0,
    RD_LIGHT_SPOT,
    RD_LIGHT_DIRECTIONAL,
} rd_light_type;

typedef struct rd_light {
    rd_light_type type;
    float position[3];    /* point, spot */
    float direction[3];   /* spot, directional: the direction light travels (normalised here) */
    float diffuse[3];     /* I_d */
    float specular[3];    /* I_s */
    float attenuation[3]; /* constant, linear, quadratic: 1 / (c + l d + q d^2), d in metres */
    float spot_inner_cos; /* full intensity inside this cone (cosine of the half-angle) */
    float spot_outer_cos; /* zero outside; smoothstep in between */
} rd_light;

#define RD_MAX_LIGHTS 16

typedef struct rd_scene rd_scene;

typedef struct rd_object_desc {
    rd_mesh mesh;
    rd_material material;
    float transform[16]; /* column-major model matrix; all zero = identity */
    int background;      /* 1 for large enclosing surfaces (room walls): drawn after the rest */
    int double_sided;    /* 1: draw back faces too (open sheets); 0: closed, back faces culled */
} rd_object_desc;

rd_scene *rd_scene_create(rd_context *ctx);
void rd_scene_destroy(rd_scene *scene);
rd_result rd_scene_add_object(rd_scene *scene, const rd_object_desc *desc);
rd_result rd_scene_add_light(rd_scene *scene, const rd_light *light);
void rd_scene_set_ambient(rd_scene *scene, const float intensity[3]); /* I_a */
int rd_scene_object_count(const rd_scene *scene);

/* ---- view and render ---------------------------------------------------------------------- */

typedef enum rd_tonemap {
    RD_TONEMAP_PHOTOGRAPHIC = 0, /* Reinhard et al. 2002, eq. 4, on luminance, with L_white */
    RD_TONEMAP_CLAMP,            /* exposure then clamp to [0, 1] */
} rd_tonemap;

typedef struct rd_view {
    float eye[3], target[3], up[3]; /* up all zero = +Z */
    float fov_y_deg;                /* 0 = 60 */
    float near_m, far_m;            /* 0 = fitted to the scene */
    int width, height;              /* output pixels */
    int supersample;                /* 0 or 1 = none; 2..4 = s x s samples per pixel */
    float exposure_ev;              /* scale by 2^ev before the tone map */
    rd_tonemap tonemap;
    float white;   /* L_white of the photographic operator; 0 = 4 */
    int to_window; /* RD_BACKEND_ADOPT: also draw the result into framebuffer 0 */
} rd_view;

rd_result rd_render(rd_context *ctx, rd_scene *scene, const rd_view *view);

/* The timing "floor" of the benchmark: one full-screen pass of the same lighting program,
 * with the scene's lights, into the same float target at the view's size. */
rd_result rd_render_floor(rd_context *ctx, rd_scene *scene, const rd_view *view);

/* Read back the last rd_render: tone-mapped sRGB bytes (RGBA, top row first, width*height*4),
 * or linear radiance after exposure (RGBA float, width*height*4), both at output size. */
rd_result rd_read_rgba8(rd_context *ctx, uint8_t *out, size_t out_size);
rd_result rd_read_linear(rd_context *ctx, float *out, size_t out_count);

#ifdef __cplusplus
}
#endif
#endif
