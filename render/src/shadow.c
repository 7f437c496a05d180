/* Shadow maps from every light (docs/rendering.md, "Shadows"; Williams 1978, with percentage
 * closer filtering after Reeves et al. 1987). The depths of all lights live in one
 * GL_DEPTH_COMPONENT32F atlas read through a comparison sampler, so the lit program needs one
 * sampler whatever the number of lights (GLSL 3.30 cannot index sampler arrays by a loop
 * variable). The maps hold plain window depth, written by the rasteriser with no fragment
 * work (early depth test: llvmpipe's fastest pass); shadow.glsl turns a point's view depth
 * into the same measure. */
#include "shadow.h"
#include "depth_range.h"

#include "gl_funcs.h"
#include "phase_timer.h"
#include "probe.h"
#include "scene_internal.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdlib.h>

#define ATLAS_UNIT 5 /* texture unit of the atlas; 0-2 are the lit program's own */
#define ATLAS_COLS 6 /* tiles per row: a cube light fills one row */
#define ATLAS_MAX_BYTES (256LL * 1024 * 1024) /* faces are halved until the atlas fits */
#define CUBE_SPOT_COS 0.5f /* spots wider than 60 degrees (half-angle) get a cube */

struct rd_shadow_maps {
    unsigned program, fbo, atlas;
    int u_model, u_view_proj;
    int atlas_w, atlas_h, face;
    long long stamp; /* the scene's change counter the maps were made at */
    int light_count;
    rd_shadow_settings settings;
    /* A remake under way (rd_scene_prepare_shadows): the state it is for and the next face to
     * draw, counting every light's faces in light order (a cube light six, others one). */
    int building, next_face, face_total;
    long long build_stamp;
    int build_lights;
    rd_shadow_settings build_settings;
    int taps_per_sample;    /* this frame's (rd_shadow_frame) */
    float sample_offset[2]; /* this frame's window origin in samples, y from the bottom */
    int tile[RD_MAX_LIGHTS], cube[RD_MAX_LIGHTS];
    float matrix[RD_MAX_LIGHTS][16], texel[RD_MAX_LIGHTS][2];
    float depth[RD_MAX_LIGHTS][3]; /* perspective: A, B of depth = A - B / z; ortho: 0, 0, range */
};

/* The face frames shadow.glsl selects by major axis (k_shadow_fwd, k_shadow_up). */
static const float face_fwd[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                     {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
static const float face_up[6][3] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1},
                                    {0, 0, 1}, {0, 1, 0}, {0, 1, 0}};

static const char *const mode_names[] = {"off", "hard", "soft"};

rd_result rd_shadow_mode_parse(const char *name, rd_shadow_mode *out)
{
    for (int i = 0; name && i < 3; i++)
        if (!strcmp(name, mode_names[i])) {
            *out = (rd_shadow_mode)i;
            return RD_OK;
        }
    return rd_fail(RD_ERR_INVALID_ARGUMENT, "shadows \"%s\": expected off, hard or soft",
                   name ? name : "(null)");
}

const char *rd_shadow_mode_name(rd_shadow_mode m)
{
    return m >= RD_SHADOWS_OFF && m <= RD_SHADOWS_SOFT ? mode_names[m] : "?";
}

int rd_shadow_taps_per_sample(const rd_shadow_settings *s, int supersample)
{
    if (!s || s->mode != RD_SHADOWS_SOFT)
        return 1;
    int ss = supersample > 1 ? supersample * supersample : 1;
    int taps = (s->taps + ss - 1) / ss;
    return taps < 2 ? 2 : taps > 64 ? 64 : taps; /* shadow.glsl holds 64 */
}

void rd_shadow_disk_tap(int i, int n, float rotation, float out[2])
{
    /* Vogel's spiral: radius sqrt((i + 1/2) / n) covers the disk's area evenly, the golden
     * angle spaces the taps; shadow.glsl computes the same. */
    float r = sqrtf(((float)i + 0.5f) / (float)(n > 0 ? n : 1));
    float phi = (float)i * 2.39996323f + rotation;
    out[0] = r * cosf(phi);
    out[1] = r * sinf(phi);
}

rd_shadow_settings rd_shadow_settings_resolve(const rd_shadow_settings *in)
{
    rd_shadow_settings s = *in;
    if (s.mode < RD_SHADOWS_OFF || s.mode > RD_SHADOWS_SOFT)
        s.mode = RD_SHADOWS_OFF;
    if (s.map_size <= 0)
        s.map_size = 1024;
    if (s.map_size > 4096)
        s.map_size = 4096;
    if (s.taps <= 0)
        s.taps = 16;
    if (s.taps > 256)
        s.taps = 256;
    if (!(s.softness_m > 0.0f) || !isfinite(s.softness_m))
        s.softness_m = 0.03f;
    return s;
}

void rd_scene_set_shadows(rd_scene *scene, const rd_shadow_settings *s)
{
    if (scene && s)
        scene->shadows = rd_shadow_settings_resolve(s);
}

rd_shadow_settings rd_scene_shadows(const rd_scene *scene)
{
    rd_shadow_settings none = {0};
    return scene ? scene->shadows : none;
}

int rd_shadows_active(const rd_scene *scene)
{
    return scene->shadows.mode != RD_SHADOWS_OFF && scene->shadow_maps &&
           scene->shadow_maps->atlas && scene->light_count > 0;
}

void rd_shadow_maps_destroy(rd_scene *scene)
{
    rd_shadow_maps *m = scene->shadow_maps;
    if (!m)
        return;
    if (m->program)
        glDeleteProgram(m->program);
    if (m->fbo)
        glDeleteFramebuffers(1, &m->fbo);
    if (m->atlas)
        glDeleteTextures(1, &m->atlas);
    free(m);
    scene->shadow_maps = NULL;
}

static rd_result ensure_gl(rd_shadow_maps *m, int w, int h)
{
    if (!m->program) {
        m->program = rd_link_program("shadow_depth.vert", "shadow_depth.frag", "");
        if (!m->program)
            return RD_ERR_SHADER;
        m->u_model = glGetUniformLocation(m->program, "u_model");
        m->u_view_proj = glGetUniformLocation(m->program, "u_view_proj");
    }
    if (m->atlas && m->atlas_w == w && m->atlas_h == h)
        return RD_OK;
    if (m->atlas)
        glDeleteTextures(1, &m->atlas);
    if (!m->fbo)
        glGenFramebuffers(1, &m->fbo);
    rd_gl_drain_errors();
    glGenTextures(1, &m->atlas);
    glBindTexture(GL_TEXTURE_2D, m->atlas);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, w, h, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 NULL);
    /* Linear filtering of a comparison: four taps weighted bilinearly, a 1-texel soft edge. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, m->fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m->atlas, 0);
    GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glReadBuffer(GL_NONE);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    unsigned err = rd_gl_drain_errors();
    if (status != GL_FRAMEBUFFER_COMPLETE || err != GL_NO_ERROR) {
        glDeleteTextures(1, &m->atlas);
        m->atlas = 0;
        return rd_fail(err == GL_OUT_OF_MEMORY ? RD_ERR_OUT_OF_MEMORY : RD_ERR_GL,
                       "cannot make a %dx%d shadow atlas (status 0x%x, GL error 0x%x)", w, h,
                       status, err);
    }
    m->atlas_w = w;
    m->atlas_h = h;
    return RD_OK;
}

/* Draws every shadow caster into atlas tile `tile` with the view-projection vp. */
static void draw_casters(rd_context *ctx, const rd_scene *s, const rd_shadow_maps *m, int tile,
                         const float vp[16])
{
    int col = tile % ATLAS_COLS, row = tile / ATLAS_COLS;
    glViewport(col * m->face, row * m->face, m->face, m->face);
    glScissor(col * m->face, row * m->face, m->face, m->face);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUniformMatrix4fv(m->u_view_proj, 1, GL_FALSE, vp);
    for (int i = 0; i < s->object_count; i++) {
        const rd_object_desc *o = &s->objects[i];
        const float *e = o->material.emissive;
        if (o->background || o->material.transparency > 0.0f || e[0] > 0.0f || e[1] > 0.0f ||
            e[2] > 0.0f)
            continue; /* the room encloses its lights; glass lets light through; a glowing
                         object is a light's own fixture */
        const rd_mesh_slot *mesh = rd_mesh_lookup(ctx, o->mesh);
        if (!mesh)
            continue;
        glUniformMatrix4fv(m->u_model, 1, GL_FALSE, o->transform);
        glBindVertexArray(mesh->vao);
        glDrawElements(GL_TRIANGLES, mesh->index_count, GL_UNSIGNED_INT, 0);
    }
}

static float reach_from(const float p[3], const float lo[3], const float hi[3])
{
    float r = 0.0f;
    for (int c = 0; c < 8; c++) {
        vec3 corner = {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]};
        r = fmaxf(r, glm_vec3_distance((float *)p, corner));
    }
    return r > 0.0f ? r * 1.01f : 1.0f;
}

/* A perspective map's near plane: 1/1000 of its reach keeps the 32-bit float window depth
 * finer than 0.1 mm at 2 m in a 5 m room (dz = z^2 / near x 2^-24); rd_depth_near caps it by
 * the room's smallest side for tall narrow rooms. */
static float near_of(float far_m, const float lo[3], const float hi[3])
{
    return fmaxf(rd_depth_near(far_m, lo, hi), 1e-4f);
}

/* GL's window depth of view depth z for glm_perspective(near, far): A - B / z. */
static void set_perspective_depth(rd_shadow_maps *m, int i, float near_m, float far_m)
{
    m->depth[i][0] = far_m / (far_m - near_m);
    m->depth[i][1] = far_m * near_m / (far_m - near_m);
    m->depth[i][2] = 0.0f;
}

/* Renders face f of light i's tiles (f = 0 for a one-tile light) and fills its lookup data. */
static void render_light_face(rd_context *ctx, const rd_scene *s, rd_shadow_maps *m, int i, int f,
                              const float lo[3], const float hi[3])
{
    const rd_light *l = &s->lights[i];
    float face = (float)m->face;
    if (m->cube[i]) {
        float far_m = reach_from(l->position, lo, hi), near_m = near_of(far_m, lo, hi);
        set_perspective_depth(m, i, near_m, far_m);
        m->texel[i][0] = 0.0f;
        m->texel[i][1] = 2.0f / face; /* tan 45 = 1: a face spans 2 d over `face` texels */
        mat4 view, proj, vp;
        vec3 target;
        glm_vec3_add((float *)l->position, (float *)face_fwd[f], target);
        glm_lookat((float *)l->position, target, (float *)face_up[f], view);
        glm_perspective(glm_rad(90.0f), 1.0f, near_m, far_m, proj);
        glm_mat4_mul(proj, view, vp);
        draw_casters(ctx, s, m, m->tile[i] + f, (const float *)vp);
        return;
    }
    vec3 dir = {l->direction[0], l->direction[1], l->direction[2]};
    glm_vec3_normalize(dir);
    vec3 up = {0, 0, 1};
    if (fabsf(dir[2]) > 0.99f)
        glm_vec3_copy((vec3){0, 1, 0}, up);
    mat4 view, proj, vp;
    if (l->type == RD_LIGHT_SPOT) {
        float far_m = reach_from(l->position, lo, hi), near_m = near_of(far_m, lo, hi);
        float half = acosf(fminf(fmaxf(l->spot_outer_cos, CUBE_SPOT_COS), 1.0f)) + glm_rad(2.0f);
        vec3 target;
        glm_vec3_add((float *)l->position, dir, target);
        glm_lookat((float *)l->position, target, up, view);
        glm_perspective(2.0f * half, 1.0f, near_m, far_m, proj);
        set_perspective_depth(m, i, near_m, far_m);
        m->texel[i][0] = 0.0f;
        m->texel[i][1] = 2.0f * tanf(half) / face;
    } else {
        /* Directional: an orthographic box around the scene's bounding sphere. */
        vec3 centre, eye, half_diag;
        for (int k = 0; k < 3; k++) {
            centre[k] = 0.5f * (lo[k] + hi[k]);
            half_diag[k] = 0.5f * (hi[k] - lo[k]);
        }
        float r = fmaxf(glm_vec3_norm(half_diag) * 1.01f, 1e-3f);
        glm_vec3_scale(dir, -2.0f * r, eye);
        glm_vec3_add(eye, centre, eye);
        glm_lookat(eye, centre, up, view);
        glm_ortho(-r, r, -r, r, r, 3.0f * r, proj);
        m->depth[i][0] = m->depth[i][1] = 0.0f;
        m->depth[i][2] = 2.0f * r; /* window depth 0..1 spans 2 r */
        m->texel[i][0] = 2.0f * r / face;
        m->texel[i][1] = 0.0f;
    }
    glm_mat4_mul(proj, view, vp);
    memcpy(m->matrix[i], vp, sizeof vp);
    draw_casters(ctx, s, m, m->tile[i], (const float *)vp);
}

/* 1 when the maps were made for the scene as it is now. */
static int maps_current(const rd_shadow_maps *m, const rd_scene *s)
{
    return m->atlas && !m->building && m->stamp == s->change_counter &&
           m->light_count == s->light_count &&
           !memcmp(&m->settings, &s->shadows, sizeof m->settings);
}

/* 1 when the remake under way is for the scene as it is now (else it starts again). */
static int build_current(const rd_shadow_maps *m, const rd_scene *s)
{
    return m->building && m->build_stamp == s->change_counter &&
           m->build_lights == s->light_count &&
           !memcmp(&m->build_settings, &s->shadows, sizeof m->build_settings);
}

/* Lays the atlas out for the scene's lights and settings and starts a remake at face 0. */
static rd_result begin_build(rd_context *ctx, rd_scene *s, rd_shadow_maps *m)
{
    /* Cube lights first, a row each (their six faces side by side: shadow.glsl finds face f
     * at the light's origin plus f tiles), then the one-tile lights, six to a row. */
    int tiles = 0, faces = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < s->light_count; i++) {
            const rd_light *l = &s->lights[i];
            int cube = l->type == RD_LIGHT_POINT || l->type == RD_LIGHT_RECT ||
                       (l->type == RD_LIGHT_SPOT && l->spot_outer_cos < CUBE_SPOT_COS);
            if (cube != (pass == 0))
                continue;
            m->cube[i] = cube;
            m->tile[i] = tiles;
            tiles += cube ? ATLAS_COLS : 1;
            faces += cube ? 6 : 1;
        }
    int rows = (tiles + ATLAS_COLS - 1) / ATLAS_COLS;
    int limit = ctx->max_size;
    int face = s->shadows.map_size;
    while (face > 64 && (ATLAS_COLS * face > limit || rows * face > limit ||
                         4LL * ATLAS_COLS * face * rows * face > ATLAS_MAX_BYTES))
        face /= 2;
    m->face = face;
    m->building = 0;
    rd_result r = ensure_gl(m, ATLAS_COLS * face, rows * face);
    if (r != RD_OK)
        return r;
    m->building = 1;
    m->next_face = 0;
    m->face_total = faces;
    m->build_stamp = s->change_counter;
    m->build_lights = s->light_count;
    m->build_settings = s->shadows;
    return RD_OK;
}

/* Draws up to max_faces (all when <= 0) of the remake's next faces; ends the remake after its
 * last face. The faces are drawn in the same order whatever the slicing, each into its own
 * cleared tile, so the atlas ends up the same as when made at once. */
static rd_result draw_faces(rd_context *ctx, rd_scene *s, rd_shadow_maps *m, int max_faces)
{
    float lo[3], hi[3];
    rd_scene_depth_bounds(s, lo, hi);
    glBindFramebuffer(GL_FRAMEBUFFER, m->fbo);
    glUseProgram(m->program);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_SCISSOR_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE); /* both sides cast: open sheets and closed meshes alike */
    int drawn = 0, first = 0;
    for (int i = 0; i < s->light_count; i++) {
        int n = m->cube[i] ? 6 : 1;
        for (int f = 0; f < n; f++, first++) {
            if (first < m->next_face || (max_faces > 0 && drawn >= max_faces))
                continue;
            render_light_face(ctx, s, m, i, f, lo, hi);
            drawn++;
        }
    }
    m->next_face += drawn;
    glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(0);
    unsigned err = rd_gl_drain_errors();
    if (err != GL_NO_ERROR) {
        m->building = 0;
        return rd_fail(RD_ERR_GL, "OpenGL error 0x%x in the shadow pass", err);
    }
    if (m->next_face >= m->face_total) {
        m->building = 0;
        m->stamp = m->build_stamp;
        m->light_count = m->build_lights;
        m->settings = m->build_settings;
    }
    return RD_OK;
}

/* Makes up to max_faces (all when <= 0) of the faces the scene's maps lack; *left gets how
 * many remain. */
static rd_result shadow_maps_step(rd_context *ctx, rd_scene *s, int max_faces, int *left)
{
    *left = 0;
    if (s->shadows.mode == RD_SHADOWS_OFF || s->light_count == 0)
        return RD_OK;
    if (!s->shadow_maps) {
        s->shadow_maps = calloc(1, sizeof *s->shadow_maps);
        if (!s->shadow_maps)
            return rd_fail(RD_ERR_OUT_OF_MEMORY, "out of memory for shadow maps");
        s->shadow_maps->stamp = -1;
    }
    rd_shadow_maps *m = s->shadow_maps;
    if (maps_current(m, s))
        return RD_OK; /* nothing moved: the maps stand */
    rd_result r = RD_OK;
    if (!build_current(m, s))
        r = begin_build(ctx, s, m);
    if (r == RD_OK)
        r = draw_faces(ctx, s, m, max_faces);
    *left = m->building ? m->face_total - m->next_face : 0;
    return r;
}

rd_result rd_shadow_maps_update(rd_context *ctx, rd_scene *s)
{
    rd_phase_mark("probe captures"); /* TESSERA_PHASES: the probes' tail (phase_timer.h) */
    int left;
    rd_result r = shadow_maps_step(ctx, s, 0, &left);
    rd_phase_mark("shadow maps");
    return r;
}

rd_result rd_scene_prepare_shadows(rd_context *ctx, rd_scene *scene, int max_faces, int *left)
{
    if (left)
        *left = 0;
    if (!ctx || !scene || !left)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_prepare_shadows: missing argument");
    if (ctx->ops)
        ctx->ops->make_current(ctx->backend_state);
    rd_result r = shadow_maps_step(ctx, scene, max_faces > 0 ? max_faces : 1, left);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glFinish(); /* the faces' rasterising falls in this call, not in the caller's next frame */
    return r;
}

void rd_shadow_frame(rd_scene *s, const rd_view *v, int samples)
{
    rd_shadow_maps *m = s->shadow_maps;
    if (!m)
        return;
    m->taps_per_sample = rd_shadow_taps_per_sample(&s->shadows, samples);
    /* The tap rotation hashes the sample's place in the whole image, so a tile turns its taps
     * exactly as the untiled render does (gl_FragCoord counts from the bottom-left). */
    m->sample_offset[0] = v->full_width > 0 ? (float)(v->crop_x * samples) : 0.0f;
    m->sample_offset[1] =
        v->full_width > 0 ? (float)((v->full_height - v->crop_y - v->height) * samples) : 0.0f;
}

void rd_shadow_set_uniforms(const rd_program *p, const rd_scene *s)
{
    const rd_shadow_maps *m = s->shadow_maps;
    GLuint id = p->id;
    int n = s->light_count;
    glActiveTexture(GL_TEXTURE0 + ATLAS_UNIT);
    glBindTexture(GL_TEXTURE_2D, m->atlas);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(id, "u_shadow_atlas"), ATLAS_UNIT);
    float origin[RD_MAX_LIGHTS][2];
    for (int i = 0; i < n; i++) {
        origin[i][0] = (float)(m->tile[i] % ATLAS_COLS * m->face) / (float)m->atlas_w;
        origin[i][1] = (float)(m->tile[i] / ATLAS_COLS * m->face) / (float)m->atlas_h;
    }
    glUniform2fv(glGetUniformLocation(id, "u_shadow_origin"), n, &origin[0][0]);
    glUniform1iv(glGetUniformLocation(id, "u_shadow_cube"), n, m->cube);
    glUniformMatrix4fv(glGetUniformLocation(id, "u_shadow_matrix"), n, GL_FALSE, &m->matrix[0][0]);
    glUniform2fv(glGetUniformLocation(id, "u_shadow_texel"), n, &m->texel[0][0]);
    glUniform3fv(glGetUniformLocation(id, "u_shadow_depth"), n, &m->depth[0][0]);
    glUniform4f(glGetUniformLocation(id, "u_shadow_grid"), (float)m->face / (float)m->atlas_w,
                (float)m->face / (float)m->atlas_h, 1.0f / (float)m->face, 0.0f);
    glUniform1i(glGetUniformLocation(id, "u_shadow_taps"), m->taps_per_sample);
    float disk[64][2];
    int taps = m->taps_per_sample < 64 ? m->taps_per_sample : 64;
    for (int k = 0; k < taps; k++)
        rd_shadow_disk_tap(k, taps, 0.0f, disk[k]);
    glUniform2fv(glGetUniformLocation(id, "u_shadow_disk"), taps, &disk[0][0]);
    glUniform2f(glGetUniformLocation(id, "u_shadow_sample_offset"), m->sample_offset[0],
                m->sample_offset[1]);
    glUniform1f(glGetUniformLocation(id, "u_shadow_softness"), s->shadows.softness_m);
}
