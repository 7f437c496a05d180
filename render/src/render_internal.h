/* Internals shared by the renderer's .c files; nothing here is public. */
#ifndef RENDER_INTERNAL_H
#define RENDER_INTERNAL_H

#include "render/render.h"

#include <stdarg.h>
#include <stdbool.h>
#include <string.h>

/* Sets the thread's last error (printf-style) and returns it for chaining. */
void rd_set_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
rd_result rd_fail(rd_result r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* One file per backend (STYLE.md, raylib/Filament): each fills this table. */
typedef struct rd_backend_ops {
    void (*make_current)(void *state);
    void (*destroy)(void *state);
} rd_backend_ops;

rd_result rd_backend_egl_create(void **state, const rd_backend_ops **ops,
                                void *(**gpa)(const char *));
rd_result rd_backend_osmesa_create(void **state, const rd_backend_ops **ops,
                                   void *(**gpa)(const char *));

typedef struct rd_mesh_slot {
    uint32_t generation;
    bool live;
    unsigned vao, vbo, ibo;
    int index_count;
    float bounds_min[3], bounds_max[3];
} rd_mesh_slot;

typedef struct rd_texture_slot {
    uint32_t generation;
    bool live;
    unsigned name;
} rd_texture_slot;

/* A float colour target with depth, resized on demand. */
typedef struct rd_target {
    unsigned fbo, color, depth;
    int width, height;
    unsigned color_internal_format;
} rd_target;

typedef struct rd_program {
    unsigned id;
    int u_model, u_normal_matrix, u_view_proj, u_eye;
    int u_ambient_light, u_light_count;
    int u_light_type, u_light_position, u_light_direction, u_light_diffuse, u_light_specular,
        u_light_attenuation, u_light_spot;
    int u_mat_ambient, u_mat_diffuse, u_mat_specular, u_mat_emissive, u_mat_shininess;
    int u_diffuse_texture, u_uv_scale;
} rd_program;

struct rd_context {
    rd_backend backend;
    void *backend_state;
    const rd_backend_ops *ops;
    char description[256];
    int max_size;

    rd_mesh_slot *meshes;
    int mesh_capacity;
    rd_texture_slot *textures;
    int texture_capacity;

    /* Shader variants by material feature: [0] plain, [1] with a diffuse texture. */
    rd_program lit[2];
    /* Tone map variants by samples per side (1..4) and output (display, linear); made on
     * first use. */
    struct rd_tonemap_program {
        unsigned id;
        int u_source, u_exposure, u_white, u_mode;
    } tonemap[4][2];
    unsigned empty_vao;

    rd_target hdr;     /* scene radiance at supersampled size */
    rd_target display; /* RGBA8 tone-mapped output */
    rd_target linear;  /* RGBA32F exposed radiance at output size (for EXR) */
    int out_width, out_height, has_frame;
    rd_view frame_view; /* the last rendered view, for rd_read_linear */
    int frame_samples;
    rd_mesh floor_quad; /* the benchmark floor's full-screen quad */
};

rd_mesh_slot *rd_mesh_lookup(rd_context *ctx, rd_mesh mesh);
rd_texture_slot *rd_texture_lookup(rd_context *ctx, rd_texture tex);
void rd_resources_destroy_all(rd_context *ctx);

rd_result rd_programs_create(rd_context *ctx);
/* The tone map program for s samples per side, display or linear output; NULL on failure. */
const struct rd_tonemap_program *rd_tonemap_program(rd_context *ctx, int samples, int linear);
void rd_programs_destroy(rd_context *ctx);

rd_result rd_target_ensure(rd_target *t, int width, int height, unsigned internal_format,
                           bool with_depth);
void rd_target_destroy(rd_target *t);

/* Throws away pending GL errors; returns the first one (GL_NO_ERROR if none). */
unsigned rd_gl_drain_errors(void);

#endif
