/* Compiles the embedded GLSL into program variants. A variant is chosen by material features
 * (ARCHITECTURE.md): code a material does not need is not in its program. */
#include "gl_funcs.h"
#include "render/shade_ref.h"
#include "render_internal.h"
#include "scene_internal.h"
#include "shadow.h"

#include <stdio.h>
#include <stdlib.h>

extern const struct {
    const char *name;
    const char *text;
} rd_shader_table[];

static const char *shader_text(const char *name)
{
    for (int i = 0; rd_shader_table[i].name; i++)
        if (!strcmp(rd_shader_table[i].name, name))
            return rd_shader_table[i].text;
    return NULL;
}

/* `names` lists the embedded files to join, separated by spaces ("reflect.glsl lit.frag"). */
static GLuint compile(GLenum stage, const char *names, const char *defines)
{
    enum { MAX_PARTS = 16 };
    const char *parts[MAX_PARTS] = {"#version 330 core\n", defines};
    int count = 2;
    char name[64];
    for (const char *p = names; *p;) {
        size_t n = strcspn(p, " ");
        if (count == MAX_PARTS) {
            rd_set_error("shader list \"%s\" has more than %d files", names, MAX_PARTS - 2);
            return 0;
        }
        snprintf(name, sizeof name, "%.*s", (int)n, p);
        parts[count] = shader_text(name);
        if (!parts[count]) {
            rd_set_error("shader %s is not embedded in this build", name);
            return 0;
        }
        count++;
        p += n;
        p += strspn(p, " ");
    }
    GLuint s = glCreateShader(stage);
    glShaderSource(s, count, parts, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = "";
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        rd_set_error("shader %s does not compile: %s", name, log);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

static GLuint link(const char *vert, const char *frag, const char *defines)
{
    GLuint vs = compile(GL_VERTEX_SHADER, vert, defines);
    if (!vs)
        return 0;
    GLuint fs = compile(GL_FRAGMENT_SHADER, frag, defines);
    if (!fs) {
        glDeleteShader(vs);
        return 0;
    }
    GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glLinkProgram(p);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = "";
        glGetProgramInfoLog(p, sizeof log, NULL, log);
        rd_set_error("program %s + %s does not link: %s", vert, frag, log);
        glDeleteProgram(p);
        return 0;
    }
    return p;
}

unsigned rd_link_program(const char *vert, const char *frag, const char *defines)
{
    return link(vert, frag, defines);
}

static void locate_lit(rd_program *p)
{
    GLuint id = p->id;
    p->u_model = glGetUniformLocation(id, "u_model");
    p->u_normal_matrix = glGetUniformLocation(id, "u_normal_matrix");
    p->u_view_proj = glGetUniformLocation(id, "u_view_proj");
    p->u_eye = glGetUniformLocation(id, "u_eye");
    p->u_ambient_light = glGetUniformLocation(id, "u_ambient_light");
    p->u_light_count = glGetUniformLocation(id, "u_light_count");
    p->u_light_type = glGetUniformLocation(id, "u_light_type");
    p->u_light_position = glGetUniformLocation(id, "u_light_position");
    p->u_light_direction = glGetUniformLocation(id, "u_light_direction");
    p->u_light_diffuse = glGetUniformLocation(id, "u_light_diffuse");
    p->u_light_specular = glGetUniformLocation(id, "u_light_specular");
    p->u_light_attenuation = glGetUniformLocation(id, "u_light_attenuation");
    p->u_light_spot = glGetUniformLocation(id, "u_light_spot");
    p->u_light_half_width = glGetUniformLocation(id, "u_light_half_width");
    p->u_light_half_height = glGetUniformLocation(id, "u_light_half_height");
    p->u_rect_count = glGetUniformLocation(id, "u_rect_count");
    p->u_rect_index = glGetUniformLocation(id, "u_rect_index");
    p->u_local_count = glGetUniformLocation(id, "u_local_count");
    p->u_local_index = glGetUniformLocation(id, "u_local_index");
    p->u_other_count = glGetUniformLocation(id, "u_other_count");
    p->u_other_index = glGetUniformLocation(id, "u_other_index");
    p->u_mat_ambient = glGetUniformLocation(id, "u_mat_ambient");
    p->u_mat_diffuse = glGetUniformLocation(id, "u_mat_diffuse");
    p->u_mat_specular = glGetUniformLocation(id, "u_mat_specular");
    p->u_mat_emissive = glGetUniformLocation(id, "u_mat_emissive");
    p->u_mat_shininess = glGetUniformLocation(id, "u_mat_shininess");
    p->u_diffuse_texture = glGetUniformLocation(id, "u_diffuse_texture");
    p->u_uv_scale = glGetUniformLocation(id, "u_uv_scale");
    p->u_joint_width = glGetUniformLocation(id, "u_joint_width");
    p->u_joint_color = glGetUniformLocation(id, "u_joint_color");
    p->u_wood_grain_dir = glGetUniformLocation(id, "u_wood_grain_dir");
    p->u_specular_scale = glGetUniformLocation(id, "u_specular_scale");
    p->u_sphere_map = glGetUniformLocation(id, "u_sphere_map");
    p->u_view_rot = glGetUniformLocation(id, "u_view_rot");
    p->u_sh = glGetUniformLocation(id, "u_sh");
    p->u_lightmap = glGetUniformLocation(id, "u_lightmap");
    p->u_bake_from_lightmap = glGetUniformLocation(id, "u_bake_from_lightmap");
    p->u_probe = glGetUniformLocation(id, "u_probe");
    p->u_probe_centre = glGetUniformLocation(id, "u_probe_centre");
    p->u_correction = glGetUniformLocation(id, "u_correction");
    p->u_proxy_min = glGetUniformLocation(id, "u_proxy_min");
    p->u_proxy_max = glGetUniformLocation(id, "u_proxy_max");
    p->u_proxy_radius = glGetUniformLocation(id, "u_proxy_radius");
    p->u_kr = glGetUniformLocation(id, "u_kr");
    p->u_lod = glGetUniformLocation(id, "u_lod");
    p->u_blend = glGetUniformLocation(id, "u_blend");
    p->u_transparency = glGetUniformLocation(id, "u_transparency");
    p->u_ior = glGetUniformLocation(id, "u_ior");
    p->u_dispersion = glGetUniformLocation(id, "u_dispersion");
    p->u_thin = glGetUniformLocation(id, "u_thin");
    p->u_pane_over = glGetUniformLocation(id, "u_pane_over");
    p->u_probe_distance = glGetUniformLocation(id, "u_probe_distance");
    p->u_store_distance = glGetUniformLocation(id, "u_store_distance");
    p->u_planar = glGetUniformLocation(id, "u_planar");
    p->u_planar_view_proj = glGetUniformLocation(id, "u_planar_view_proj");
    p->u_probe_surface = glGetUniformLocation(id, "u_probe_surface");
    p->u_surface_highlights = glGetUniformLocation(id, "u_surface_highlights");
    p->u_lobe_exponent = glGetUniformLocation(id, "u_lobe_exponent");
    p->u_depth_steps = glGetUniformLocation(id, "u_depth_steps");
    p->u_room_active = glGetUniformLocation(id, "u_room_active");
    p->u_room_probe = glGetUniformLocation(id, "u_room_probe");
    p->u_room_distance = glGetUniformLocation(id, "u_room_distance");
    p->u_room_surface = glGetUniformLocation(id, "u_room_surface");
    p->u_room_centre = glGetUniformLocation(id, "u_room_centre");
    p->u_room_lod = glGetUniformLocation(id, "u_room_lod");
    p->u_group_min = glGetUniformLocation(id, "u_group_min");
    p->u_group_max = glGetUniformLocation(id, "u_group_max");
    p->u_emitter_count = glGetUniformLocation(id, "u_emitter_count");
    p->u_emitter_shape = glGetUniformLocation(id, "u_emitter_shape");
    p->u_emitter_to_local = glGetUniformLocation(id, "u_emitter_to_local");
    p->u_emitter_ambient = glGetUniformLocation(id, "u_emitter_ambient");
    p->u_emitter_diffuse = glGetUniformLocation(id, "u_emitter_diffuse");
    p->u_emitter_specular = glGetUniformLocation(id, "u_emitter_specular");
    p->u_emitter_emissive = glGetUniformLocation(id, "u_emitter_emissive");
    p->u_emitter_shininess = glGetUniformLocation(id, "u_emitter_shininess");
    p->u_emitter_sphere = glGetUniformLocation(id, "u_emitter_sphere");
    p->u_self_nodes = glGetUniformLocation(id, "u_self_nodes");
    p->u_self_tris = glGetUniformLocation(id, "u_self_tris");
    p->u_self_textures = glGetUniformLocation(id, "u_self_textures");
    p->u_self_base = glGetUniformLocation(id, "u_self_base");
    p->u_self_ambient = glGetUniformLocation(id, "u_self_ambient");
    p->u_self_diffuse = glGetUniformLocation(id, "u_self_diffuse");
    p->u_self_specular = glGetUniformLocation(id, "u_self_specular");
    p->u_self_emissive = glGetUniformLocation(id, "u_self_emissive");
    p->u_self_shininess = glGetUniformLocation(id, "u_self_shininess");
    p->u_self_kr = glGetUniformLocation(id, "u_self_kr");
    p->u_self_blend = glGetUniformLocation(id, "u_self_blend");
    p->u_self_slot = glGetUniformLocation(id, "u_self_slot");
    p->u_self_uv_scale = glGetUniformLocation(id, "u_self_uv_scale");
    p->u_self_epsilon = glGetUniformLocation(id, "u_self_epsilon");
    p->u_self_rays = glGetUniformLocation(id, "u_self_rays");
    p->u_self_grid = glGetUniformLocation(id, "u_self_grid");
}

/* Links variant's lit program into *p, with `extra` appended to its defines. */
/* Every sampler on a unit of its own from the start, the units the draws bind (draw.c,
 * shadow.c, self_trace.c): GL refuses a draw whose samplers of two types share a unit, and a
 * new program's samplers all read unit 0 until a draw sets them. */
static void default_sampler_units(const rd_program *p)
{
    const struct {
        int location, unit;
    } units[] = {{p->u_diffuse_texture, 0}, {p->u_probe, 1},         {p->u_sphere_map, 2},
                 {p->u_probe_distance, 3},  {p->u_probe_surface, 4}, {p->u_room_probe, 6},
                 {p->u_room_distance, 7},   {p->u_room_surface, 8},  {p->u_self_nodes, 9},
                 {p->u_self_tris, 10},      {p->u_lightmap, 12},     {p->u_planar, 15}};
    glUseProgram(p->id);
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
        if (units[i].location >= 0)
            glUniform1i(units[i].location, units[i].unit);
    GLint atlas = glGetUniformLocation(p->id, "u_shadow_atlas");
    if (atlas >= 0)
        glUniform1i(atlas, 5);
    if (p->u_self_textures >= 0) {
        static const int self_units[4] = {11, 12, 13, 14};
        glUniform1iv(p->u_self_textures, 4, self_units);
    }
}

static const rd_program *make_lit(rd_program *p, int variant, const char *extra)
{
    int textured = variant & RD_LIT_TEXTURED, reflecting = variant & RD_LIT_REFLECTING;
    int per_vertex = reflecting && (variant & RD_LIT_PER_VERTEX);
    int sphere = reflecting && (variant & RD_LIT_SPHERE_MAP);
    int planar = reflecting && !per_vertex && !sphere && (variant & RD_LIT_PLANAR);
    /* A planar mirror needs none of the full path's refraction, search or highlights; glass
     * through the box keeps the refraction alone. */
    int box = reflecting && !per_vertex && !sphere &&
              (planar || (variant & (RD_LIT_BOX_OPAQUE | RD_LIT_BOX_GLASS)));
    int box_glass = box && !planar && (variant & RD_LIT_BOX_GLASS);
    /* Self-traced lookups are the full path's (not the lean box or planar variants). */
    int self_trace = reflecting && !per_vertex && !sphere && !box && (variant & RD_LIT_SELF_TRACE);
    /* A glaze reads the room probe; an object with a probe of its own reflects through it. */
    int glaze = !reflecting && (variant & RD_LIT_GLAZE);
    char wood[400] = "";
    if (variant & RD_LIT_WOOD) /* wood.glsl, with rd_ref_wood_grain's constants */
        snprintf(
            wood, sizeof wood,
            "#define WOOD_GRAIN 1\n#define WOOD_RING_SPACING float(%.9g)\n"
            "#define WOOD_AXIS_Y float(%.9g)\n#define WOOD_AXIS_Z float(%.9g)\n"
            "#define WOOD_WOBBLE float(%.9g)\n#define WOOD_RING_CONTRAST float(%.9g)\n"
            "#define WOOD_PORE_CONTRAST float(%.9g)\n#define WOOD_FIGURE_CONTRAST float(%.9g)\n"
            "#define WOOD_BAND_CONTRAST float(%.9g)\n",
            (double)RD_WOOD_RING_SPACING, (double)RD_WOOD_AXIS_Y, (double)RD_WOOD_AXIS_Z,
            (double)RD_WOOD_WOBBLE, (double)RD_WOOD_RING_CONTRAST, (double)RD_WOOD_PORE_CONTRAST,
            (double)RD_WOOD_FIGURE_CONTRAST, (double)RD_WOOD_BAND_CONTRAST);
    char defines[1100];
    snprintf(defines, sizeof defines,
             "#define MAX_LIGHTS %d\n#define MAX_EMITTERS %d\n#define MAX_SELF_PARTS %d\n"
             "#define MAX_SELF_TEXTURES %d\n%s%s%s%s%s%s%s%s%s%s%s%s%s%s%s%s",
             RD_MAX_LIGHTS, RD_MAX_EMITTERS, RD_MAX_SELF_PARTS, RD_MAX_SELF_TEXTURES,
             textured ? "#define HAS_DIFFUSE_TEXTURE 1\n" : "",
             reflecting ? "#define HAS_REFLECTION 1\n" : "",
             per_vertex ? "#define PER_VERTEX_REFLECTION 1\n" : "",
             sphere ? "#define SPHERE_MAP 1\n" : "",
             (variant & RD_LIT_SH9) ? "#define SH9_AMBIENT 1\n" : "",
             (variant & RD_LIT_SHADOWS) ? "#define HAS_SHADOWS 1\n" : "",
             box ? "#define BOX_REFLECTION 1\n" : "", box_glass ? "#define BOX_GLASS 1\n" : "",
             (variant & RD_LIT_NO_SPECULAR) ? "#define NO_SPECULAR 1\n" : "",
             planar ? "#define PLANAR_REFLECTION 1\n" : "",
             self_trace ? "#define SELF_TRACE 1\n" : "",
             (variant & RD_LIT_AREA_LIGHTS) ? "#define AREA_LIGHTS 1\n" : "",
             (variant & RD_LIT_BAKED) ? "#define BAKED_LIGHT 1\n" : "",
             glaze ? "#define GLAZE 1\n" : "", wood, extra);
    if (variant == RD_LIT_DEPTH_ONLY)
        p->id = link("lit.vert", "depth_only.frag", defines);
    else
        p->id =
            link(reflecting ? "reflect.glsl lit.vert" : "lit.vert",
                 reflecting ? "reflect.glsl emitters.glsl self_trace.glsl shadow.glsl "
                              "grout.glsl wood.glsl area_light.glsl lit.frag"
                 : glaze ? "reflect.glsl shadow.glsl grout.glsl wood.glsl area_light.glsl lit.frag"
                         : "shadow.glsl grout.glsl wood.glsl area_light.glsl lit.frag",
                 defines);
    if (!p->id)
        return NULL;
    locate_lit(p);
    default_sampler_units(p);
    return p;
}

const rd_program *rd_lit_program(rd_context *ctx, int variant)
{
    rd_program *p = ctx->lit[variant];
    if (p && p->id)
        return p;
    if (!p) {
        p = calloc(1, sizeof *p);
        if (!p) {
            rd_fail(RD_ERR_OUT_OF_MEMORY, "out of memory for a shader program");
            return NULL;
        }
        ctx->lit[variant] = p;
    }
    return make_lit(p, variant, "");
}

const rd_program *rd_lit_program_fixed(rd_context *ctx, int variant, int local_lights,
                                       int other_lights, int lamp_lookups)
{
    struct rd_fixed_lit *slots = ctx->lit_fixed;
    for (int i = 0; i < RD_LIT_FIXED_SLOTS; i++)
        if (slots[i].program.id && slots[i].variant == variant &&
            slots[i].local_lights == local_lights && slots[i].other_lights == other_lights &&
            slots[i].lamp_lookups == lamp_lookups)
            return &slots[i].program;
    /* A free slot, or the next in turn: a scene's live frames use a handful. */
    int slot = 0;
    while (slot < RD_LIT_FIXED_SLOTS && slots[slot].program.id)
        slot++;
    if (slot == RD_LIT_FIXED_SLOTS) {
        slot = ctx->lit_fixed_next;
        ctx->lit_fixed_next = (ctx->lit_fixed_next + 1) % RD_LIT_FIXED_SLOTS;
        glDeleteProgram(slots[slot].program.id);
    }
    memset(&slots[slot], 0, sizeof slots[slot]);
    char extra[128];
    snprintf(extra, sizeof extra,
             "#define FIXED_LOCAL_LIGHTS %d\n#define FIXED_OTHER_LIGHTS %d\n%s", local_lights,
             other_lights, lamp_lookups ? "" : "#define NO_LAMP_LOOKUPS 1\n");
    if (!make_lit(&slots[slot].program, variant, extra))
        return NULL;
    slots[slot].variant = variant;
    slots[slot].local_lights = local_lights;
    slots[slot].other_lights = other_lights;
    slots[slot].lamp_lookups = lamp_lookups;
    return &slots[slot].program;
}

rd_result rd_programs_create(rd_context *ctx)
{
    /* The plain variants are made now, so a broken shader fails context creation; the
     * reflecting ones when a scene first needs them. */
    if (!rd_lit_program(ctx, 0) || !rd_lit_program(ctx, RD_LIT_TEXTURED) ||
        !rd_lit_program(ctx, RD_LIT_REFLECTING))
        return RD_ERR_SHADER;
    return rd_tonemap_program(ctx, 1, 0) ? RD_OK : RD_ERR_SHADER;
}

/* The full-screen programs over a radiance image (tonemap.glsl and one .frag). */
static const struct rd_tonemap_program *make_tonemap(struct rd_tonemap_program *t, const char *frag,
                                                     const char *defines)
{
    t->id = link("fullscreen.vert", frag, defines);
    if (!t->id)
        return NULL;
    t->u_source = glGetUniformLocation(t->id, "u_source");
    t->u_exposure = glGetUniformLocation(t->id, "u_exposure");
    t->u_white = glGetUniformLocation(t->id, "u_white");
    t->u_mode = glGetUniformLocation(t->id, "u_mode");
    t->u_wb = glGetUniformLocation(t->id, "u_wb");
    t->u_refined = glGetUniformLocation(t->id, "u_refined");
    t->u_threshold = glGetUniformLocation(t->id, "u_threshold");
    t->u_samples = glGetUniformLocation(t->id, "u_samples");
    return t;
}

/* A resolve variant (tonemap.frag), made on first use into *t. */
static const struct rd_tonemap_program *resolve_program(struct rd_tonemap_program *t, int samples,
                                                        int linear, int adaptive)
{
    if (t->id)
        return t;
    char defines[96];
    snprintf(defines, sizeof defines,
             "#define SAMPLES %d\n#define LINEAR_OUT %d\n#define ADAPTIVE %d\n", samples,
             linear ? 1 : 0, adaptive);
    return make_tonemap(t, "tonemap.glsl tonemap.frag", defines);
}

const struct rd_tonemap_program *rd_tonemap_program(rd_context *ctx, int samples, int linear)
{
    return resolve_program(&ctx->tonemap[samples - 1][linear ? 1 : 0], samples, linear, 0);
}

const struct rd_tonemap_program *rd_tonemap_adaptive_program(rd_context *ctx, int samples,
                                                             int linear)
{
    return resolve_program(&ctx->tonemap_adaptive[samples - 1][linear ? 1 : 0], samples, linear, 1);
}

const struct rd_tonemap_program *rd_edge_mask_program(rd_context *ctx)
{
    return ctx->edge_mask.id ? &ctx->edge_mask
                             : make_tonemap(&ctx->edge_mask, "tonemap.glsl edge_mask.frag", "");
}

const struct rd_tonemap_program *rd_exposure_meter_program(rd_context *ctx)
{
    return ctx->exposure_meter.id
               ? &ctx->exposure_meter
               : make_tonemap(&ctx->exposure_meter, "tonemap.glsl exposure_meter.frag", "");
}

const struct rd_tonemap_program *rd_mask_stencil_program(rd_context *ctx)
{
    return ctx->mask_stencil.id ? &ctx->mask_stencil
                                : make_tonemap(&ctx->mask_stencil, "mask_stencil.frag", "");
}

rd_result rd_prefilter_program_create(rd_context *ctx)
{
    GLuint p = link("fullscreen.vert", "prefilter.frag", "");
    if (!p)
        return RD_ERR_SHADER;
    ctx->prefilter_program = p;
    ctx->pf_u_source = glGetUniformLocation(p, "u_source");
    ctx->pf_u_face = glGetUniformLocation(p, "u_face");
    ctx->pf_u_size = glGetUniformLocation(p, "u_size");
    ctx->pf_u_exponent = glGetUniformLocation(p, "u_exponent");
    ctx->pf_u_clamp = glGetUniformLocation(p, "u_clamp");
    ctx->pf_u_source_size = glGetUniformLocation(p, "u_source_size");
    ctx->pf_u_samples = glGetUniformLocation(p, "u_samples");
    return RD_OK;
}

rd_result rd_sphere_program_create(rd_context *ctx)
{
    GLuint p = link("fullscreen.vert", "reflect.glsl sphere_map_gen.frag", "");
    if (!p)
        return RD_ERR_SHADER;
    ctx->sphere_program = p;
    ctx->sm_u_source = glGetUniformLocation(p, "u_source");
    ctx->sm_u_view_rot = glGetUniformLocation(p, "u_view_rot");
    ctx->sm_u_size = glGetUniformLocation(p, "u_size");
    return RD_OK;
}

void rd_programs_destroy(rd_context *ctx)
{
    if (ctx->sphere_program) {
        glDeleteProgram(ctx->sphere_program);
        ctx->sphere_program = 0;
    }
    if (ctx->prefilter_program) {
        glDeleteProgram(ctx->prefilter_program);
        ctx->prefilter_program = 0;
    }
    for (int v = 0; v < RD_LIT_VARIANTS; v++)
        if (ctx->lit[v]) {
            if (ctx->lit[v]->id)
                glDeleteProgram(ctx->lit[v]->id);
            free(ctx->lit[v]);
            ctx->lit[v] = NULL;
        }
    for (int i = 0; i < RD_LIT_FIXED_SLOTS; i++)
        if (ctx->lit_fixed[i].program.id) {
            glDeleteProgram(ctx->lit_fixed[i].program.id);
            ctx->lit_fixed[i].program.id = 0;
        }
    for (int s = 0; s < 4; s++)
        for (int l = 0; l < 2; l++)
            if (ctx->tonemap[s][l].id) {
                glDeleteProgram(ctx->tonemap[s][l].id);
                ctx->tonemap[s][l].id = 0;
            }
    for (int k = 0; k < 11; k++) {
        struct rd_tonemap_program *t = k < 8    ? &ctx->tonemap_adaptive[k / 2][k % 2]
                                       : k == 8 ? &ctx->edge_mask
                                       : k == 9 ? &ctx->mask_stencil
                                                : &ctx->exposure_meter;
        if (t->id) {
            glDeleteProgram(t->id);
            t->id = 0;
        }
    }
}
