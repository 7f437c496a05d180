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
    int bake; /* 0 none, 1 per-vertex light (location 3), 2 lightmap coordinates (location 4) */
} rd_mesh_slot;

typedef struct rd_texture_slot {
    uint32_t generation;
    bool live;
    unsigned name;
    int size; /* cube maps: texels per face side */
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
        u_light_attenuation, u_light_spot, u_light_half_width, u_light_half_height, u_rect_count,
        u_rect_index, /* area_light.glsl */
        u_local_count, u_local_index, u_other_count, u_other_index;
    int u_mat_ambient, u_mat_diffuse, u_mat_specular, u_mat_emissive, u_mat_shininess;
    int u_diffuse_texture, u_uv_scale, u_joint_width, u_joint_color, u_wood_grain_dir;
    int u_specular_scale;
    int u_sh, u_sphere_map, u_view_rot;
    int u_lightmap, u_bake_from_lightmap;
    int u_probe, u_probe_centre, u_correction, u_proxy_min, u_proxy_max, u_proxy_radius, u_kr,
        u_lod, u_blend, u_transparency, u_ior, u_dispersion, u_thin, u_pane_over;
    int u_probe_distance, u_store_distance; /* the "depth" correction (reflect.glsl) */
    int u_planar, u_planar_view_proj;       /* a flat mirror's planar capture (probe_planar.c) */
    int u_probe_surface, u_surface_highlights, u_lobe_exponent, u_depth_steps;
    int u_room_active, u_room_probe, u_room_distance, u_room_surface, u_room_centre, u_room_lod,
        u_group_min, u_group_max;
    int u_emitter_count, u_emitter_shape, u_emitter_to_local, u_emitter_ambient, u_emitter_diffuse,
        u_emitter_specular, u_emitter_emissive, u_emitter_shininess,
        u_emitter_sphere; /* emitters.c */
    int u_self_nodes, u_self_tris, u_self_textures, u_self_base, u_self_ambient, u_self_diffuse,
        u_self_specular, u_self_emissive, u_self_shininess, u_self_kr, u_self_blend, u_self_slot,
        u_self_uv_scale, u_self_epsilon, u_self_rays, u_self_grid; /* self_trace.c */
} rd_program;

/* Lit program variants by material feature: a bit each. */
enum {
    RD_LIT_TEXTURED = 1,
    RD_LIT_REFLECTING = 2,
    RD_LIT_PER_VERTEX = 4,
    RD_LIT_SPHERE_MAP = 8,
    RD_LIT_SH9 = 16,
    RD_LIT_SHADOWS = 32,       /* shadow.glsl: shadow maps of every light */
    RD_LIT_BOX_OPAQUE = 64,    /* reflecting with the box correction only, opaque, no surface
                                  highlights: llvmpipe runs untaken uniform branches */
    RD_LIT_DEPTH_ONLY = 128,   /* alone: lit.vert with depth_only.frag (the depth prepass) */
    RD_LIT_NO_SPECULAR = 256,  /* probe captures that leave highlights out: no specular code */
    RD_LIT_PLANAR = 512,       /* a flat mirror's lookup in its planar capture (probe_planar.c) */
    RD_LIT_SELF_TRACE = 1024,  /* the lookup traces the product's own parts (self_trace.c) */
    RD_LIT_AREA_LIGHTS = 2048, /* area_light.glsl: rectangle lights and window portals */
    RD_LIT_BAKED = 4096,       /* the ambient intensity from the bake (ref/ref_bake.h) */
    RD_LIT_GLAZE = 8192,       /* no probe of its own: the room probe by Fresnel (glaze.c) */
    RD_LIT_WOOD = 16384,       /* wood.glsl: the procedural grain (rd_material.pattern) */
    RD_LIT_BOX_GLASS = 32768,  /* as RD_LIT_BOX_OPAQUE, with the refraction of glass */
    RD_LIT_VARIANTS = 65536
};
/* Fixed-light lit programs kept at once (rd_lit_program_fixed). */
#define RD_LIT_FIXED_SLOTS 32

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
    rd_texture_slot *cubemaps; /* static cube maps (rd_cubemap handles) */
    int cubemap_capacity;

    unsigned probe_fbo;
    unsigned blit_fbo;
    unsigned isotropic_sampler; /* trilinear, no anisotropy: probe captures' textures */
    unsigned probe_depth;       /* depth buffer of probe captures, probe_depth_size square */
    int probe_depth_size;
    unsigned planar_depth; /* depth buffer of planar mirror captures, planar_depth_w x _h: kept
                              apart, so the cube captures do not clear a buffer that big */
    int planar_depth_w, planar_depth_h;
    unsigned prefilter_program;
    unsigned sphere_program; /* sphere map from a cube map (sphere_map_gen.frag) */
    int sm_u_source, sm_u_view_rot, sm_u_size;
    int pf_u_source, pf_u_face, pf_u_size, pf_u_exponent, pf_u_clamp, pf_u_source_size,
        pf_u_samples;
    rd_frame_stats stats;

    rd_program *lit[RD_LIT_VARIANTS]; /* by RD_LIT_* bits, each allocated when first made */
    /* Lit programs whose light loops run a fixed number of lights (rd_lit_program_fixed). */
    struct rd_fixed_lit {
        int variant, local_lights, other_lights, lamp_lookups;
        rd_program program;
    } lit_fixed[RD_LIT_FIXED_SLOTS];
    int lit_fixed_next; /* the slot a new one takes when all are in use */
    int drew_live; /* a live view's moving frame has been drawn (rd_pass.rect_lights_as_points) */
    /* Tone map variants by samples per side (1..4) and output (display, linear); made on
     * first use. */
    struct rd_tonemap_program {
        unsigned id;
        int u_source, u_exposure, u_white, u_mode, u_wb;
        int u_refined, u_threshold, u_samples; /* adaptive supersampling only */
    } tonemap[4][2];
    /* Adaptive supersampling (renderer_adaptive.c): the resolves by samples per side and
     * output, and the edge mask, made on first use. */
    struct rd_tonemap_program tonemap_adaptive[4][2], edge_mask, mask_stencil;
    /* Auto exposure (exposure_meter.c): log luminance at a grid of the main pass's samples. */
    struct rd_tonemap_program exposure_meter;
    rd_target meter;
    struct rd_adaptive_target {
        unsigned fbo, color, depth_stencil; /* s x s samples; the stencil marks refined pixels */
        int width, height;
        rd_target mask; /* one texel a pixel: 1 to refine */
    } adaptive;
    unsigned empty_vao;

    rd_target hdr;      /* scene radiance at supersampled size */
    rd_target display;  /* RGBA8 tone-mapped output */
    rd_target composed; /* RGBA8 image from the caller (rd_present_rgba8) */
    rd_target linear;   /* RGBA32F exposed radiance at output size (for EXR) */
    int out_width, out_height, has_frame;
    rd_view frame_view;      /* the last rendered view, for rd_read_linear */
    float frame_exposure_ev; /* the EV it was resolved with (rd_exposure_resolve) */
    int frame_samples;
    rd_mesh floor_quad; /* the benchmark floor's full-screen quad */
};

rd_mesh_slot *rd_mesh_lookup(rd_context *ctx, rd_mesh mesh);
rd_texture_slot *rd_texture_lookup(rd_context *ctx, rd_texture tex);
rd_texture_slot *rd_cubemap_lookup(rd_context *ctx, rd_cubemap map);
/* A depth buffer of at least size x size attached to ctx->probe_fbo (bound). */
rd_result rd_probe_depth_ensure(rd_context *ctx, int size);
/* (Re)specifies *name (made when 0) as a w x h RGBA16F texture, linear filtering, clamped to
 * its edges; `mipmapped`: trilinear over mips to be generated, else level 0 only. */
void rd_float_texture_2d(unsigned *name, int w, int h, int mipmapped);
/* The same for a planar mirror's w x h capture (probe_planar.c). */
rd_result rd_planar_depth_ensure(rd_context *ctx, int w, int h);
void rd_resources_destroy_all(rd_context *ctx);

rd_result rd_programs_create(rd_context *ctx);
/* The lit program of a variant (RD_LIT_* bits), compiled on first use; NULL on failure. */
/* 1 when the scene has a rectangle light or a directional light with a portal: its lit
 * programs are the AREA_LIGHTS variant (area_light.glsl). */
int rd_scene_has_area_lights(const rd_scene *s);
const rd_program *rd_lit_program(rd_context *ctx, int variant);
/* The lit program of a variant whose main light loops run exactly local_lights point, spot
 * and rectangle-as-point lights and other_lights directional ones, as set_light_uniforms
 * (draw.c) packs them, and no rectangle loop: loops of a bound known when the shader is
 * compiled are unrolled, and llvmpipe then reads each light's uniforms once for all pixels
 * instead of gathering them pixel by pixel. lamp_lookups 0: no lookup of lamps in reflections
 * (emitters.c; the object's probe kept them). NULL on failure. */
const rd_program *rd_lit_program_fixed(rd_context *ctx, int variant, int local_lights,
                                       int other_lights, int lamp_lookups);
/* The tone map program for s samples per side, display or linear output; NULL on failure. */
const struct rd_tonemap_program *rd_tonemap_program(rd_context *ctx, int samples, int linear);
/* Adaptive supersampling's programs (renderer_adaptive.c): the resolve of a once-per-pixel
 * render and its refined pixels' s x s samples (display or linear), and the edge mask. */
const struct rd_tonemap_program *rd_tonemap_adaptive_program(rd_context *ctx, int samples,
                                                             int linear);
const struct rd_tonemap_program *rd_edge_mask_program(rd_context *ctx);
const struct rd_tonemap_program *rd_mask_stencil_program(rd_context *ctx);
const struct rd_tonemap_program *rd_exposure_meter_program(rd_context *ctx);
/* Sets the tone map uniforms every program over tonemap.glsl reads (exposure 2^ev, white,
 * mode, white balance) on the program in use. */
void rd_tonemap_uniforms(const struct rd_tonemap_program *t, const rd_view *v, float exposure_ev);
/* The EV a view is resolved with: v->exposure_ev, or with v->auto_exposure the EV measured
 * from the radiance in ctx->hdr (the main pass just drawn) plus v->exposure_ev. */
rd_result rd_exposure_resolve(rd_context *ctx, const rd_view *v, float *ev);
/* After the once-per-pixel main pass of an adaptive view (v->adaptive, samples > 1): marks
 * the pixels to refine and renders their s x s samples (renderer_adaptive.c). */
rd_result rd_adaptive_refine(rd_context *ctx, rd_scene *scene, const rd_view *v, int samples,
                             const float vp[16], const float view_rot[9]);
/* Binds the refined samples the adaptive resolve reads to texture unit 1. */
void rd_adaptive_bind_samples(rd_context *ctx);
void rd_adaptive_destroy(rd_context *ctx);
void rd_programs_destroy(rd_context *ctx);
rd_result rd_prefilter_program_create(rd_context *ctx);
rd_result rd_sphere_program_create(rd_context *ctx);

rd_result rd_target_ensure(rd_target *t, int width, int height, unsigned internal_format,
                           bool with_depth);
void rd_target_destroy(rd_target *t);

/* Throws away pending GL errors; returns the first one (GL_NO_ERROR if none). */
unsigned rd_gl_drain_errors(void);

#endif
