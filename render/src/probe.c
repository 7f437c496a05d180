/* Per-object reflection probes (RENDERING.md sections 3, 5, 8): which objects get one, when
 * each is captured, at what resolution, and which texture the main pass samples. */
#include "probe.h"
#include "glaze.h"
#include "depth_range.h"
#include "probe_planar.h"
#include "draw.h"
#include "emitters.h"
#include "self_trace.h"
#include "gl_funcs.h"
#include "phase_timer.h"
#include "capture_clock.h"
#include "prefilter.h"

#include "render/cube_data.h"
#include "render/reflect_ref.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int rd_object_key(const rd_scene *s, int i)
{
    const rd_object_desc *o = &s->objects[i];
    /* Glass in a group (a screen's panes beside its profiles) takes a probe of its own, which
     * leaves only the glass out of its capture: what the panes show through them includes
     * their own product's profiles, as the traced reference sees them. */
    int own = rd_planar_candidate(s, o) || o->material.transparency > 0.0f;
    return o->group > 0 && !own ? o->group : -(i + 1);
}

static void free_probe_textures(rd_probe *p)
{
    if (p->capture)
        glDeleteTextures(1, &p->capture);
    if (p->filtered)
        glDeleteTextures(1, &p->filtered);
    if (p->sphere_map)
        glDeleteTextures(1, &p->sphere_map);
    if (p->surface)
        glDeleteTextures(1, &p->surface);
    if (p->planar_texture)
        glDeleteTextures(1, &p->planar_texture);
    p->capture = p->filtered = p->sphere_map = p->surface = p->planar_texture = 0;
    p->planar_width = p->planar_height = 0;
}

void rd_probes_destroy(rd_scene *s)
{
    for (int i = 0; i < s->probe_count; i++) {
        free_probe_textures(&s->probes[i]);
        rd_self_trace_free(&s->probes[i].self);
    }
    free_probe_textures(&s->room_probe);
    s->room_probe = (rd_probe){.captured_frame = -1, .filtered_level = -1};
    free(s->probes);
    s->probes = NULL;
    s->probe_count = 0;
}

rd_result rd_probes_sync(rd_scene *s)
{
    if (!s->probes_dirty)
        return RD_OK;
    int *map =
        realloc(s->object_probe, (size_t)(s->object_count ? s->object_count : 1) * sizeof *map);
    if (!map)
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "out of memory for probes");
    s->object_probe = map;
    /* Probes are rebuilt from scratch: adding objects is rare (loading), capturing is not. */
    rd_probes_destroy(s);
    rd_probe *list = calloc((size_t)(s->object_count ? s->object_count : 1), sizeof *list);
    if (!list)
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "out of memory for probes");
    s->probes = list;
    for (int i = 0; i < s->object_count; i++) {
        map[i] = -1;
        const rd_material *mat = &s->objects[i].material;
        if (!(mat->reflectivity > 0.0f) && !(mat->transparency > 0.0f))
            continue; /* k_r = 0 and opaque: no probe (section 3) */
        int key = rd_object_key(s, i), found = -1;
        for (int j = 0; j < s->probe_count; j++)
            if (s->probes[j].key == key)
                found = j;
        float g = fminf(fmaxf(mat->glossiness, 0.0f), 1.0f);
        if (found < 0) {
            found = s->probe_count++;
            s->probes[found] = (rd_probe){.key = key,
                                          .owner = i,
                                          .captured_frame = -1,
                                          .filtered_level = -1,
                                          .gloss_min = g,
                                          .gloss_max = g};
        }
        s->probes[found].gloss_min = fminf(s->probes[found].gloss_min, g);
        s->probes[found].gloss_max = fmaxf(s->probes[found].gloss_max, g);
        map[i] = found;
    }
    s->probes_dirty = 0;
    return RD_OK;
}

void rd_object_world_bounds(rd_context *ctx, const rd_object_desc *o, float lo[3], float hi[3])
{
    const rd_mesh_slot *m = rd_mesh_lookup(ctx, o->mesh);
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    if (!m)
        return;
    for (int c = 0; c < 8; c++) {
        vec4 p = {c & 1 ? m->bounds_max[0] : m->bounds_min[0],
                  c & 2 ? m->bounds_max[1] : m->bounds_min[1],
                  c & 4 ? m->bounds_max[2] : m->bounds_min[2], 1.0f};
        vec4 w;
        glm_mat4_mulv((vec4 *)o->transform, p, w);
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], w[k]);
            hi[k] = fmaxf(hi[k], w[k]);
        }
    }
}

/* The probe sits at the centre of its objects' joint bounding box (section 3: the geometric
 * centre, not the model's origin). */
static void place_probe(rd_context *ctx, const rd_scene *s, rd_probe *p)
{
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < s->object_count; i++) {
        if (rd_object_key(s, i) != p->key)
            continue;
        float a[3], b[3];
        rd_object_world_bounds(ctx, &s->objects[i], a, b);
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], a[k]);
            hi[k] = fmaxf(hi[k], b[k]);
        }
    }
    float r2 = 0.0f, e[3];
    memcpy(p->box_min, lo, sizeof lo);
    memcpy(p->box_max, hi, sizeof hi);
    for (int k = 0; k < 3; k++) {
        p->centre[k] = lo[k] <= hi[k] ? 0.5f * (lo[k] + hi[k]) : 0.0f;
        e[k] = lo[k] <= hi[k] ? hi[k] - lo[k] : 0.0f;
        r2 += 0.25f * e[k] * e[k];
    }
    p->radius = sqrtf(r2);
    /* The size its reflection shows at: the geometric mean of the two largest extents, so a
     * thin rail is not sized like a panel as long as it (its bounding sphere would be). */
    float big = fmaxf(e[0], fmaxf(e[1], e[2])), small = fminf(e[0], fminf(e[1], e[2]));
    float mid = e[0] + e[1] + e[2] - big - small;
    p->detail_size = sqrtf(big * mid);
}

/* A material that does not name its correction, under a scene-wide "depth" (the print preset),
 * whose reflection is faint and blurred (k_r and g below RD_DEPTH_MIN_*), not glass: a glaze,
 * whose probe is sized by its lobe (probe_resolution). */
static int faint_under_depth(const rd_scene *s, const rd_material *m)
{
    return m->correction == RD_CORRECTION_DEFAULT &&
           s->reflection.correction == RD_CORRECTION_DEPTH && m->transparency <= 0.0f &&
           m->reflectivity < RD_DEPTH_MIN_REFLECTIVITY && m->glossiness < RD_DEPTH_MIN_GLOSSINESS;
}

rd_correction rd_effective_correction(const rd_scene *s, const rd_material *m)
{
    if (m->correction != RD_CORRECTION_DEFAULT)
        return m->correction;
    rd_correction c = s->reflection.correction != RD_CORRECTION_DEFAULT ? s->reflection.correction
                                                                        : RD_CORRECTION_BOX;
    /* Faint, blurred glazes keep a scene-wide "depth" (the print preset) too: their probe
     * leaves their own product out, and the room probe's search brings it back (a WC's seat
     * reflects its cistern). The box would be faster but misplaces exactly those
     * reflections. */
    return c;
}

rd_blur_method rd_effective_blur(const rd_scene *s)
{
    return s->reflection.blur != RD_BLUR_DEFAULT ? s->reflection.blur : RD_BLUR_PREFILTERED;
}

/* The reference blur of one level (section 5, "reference"): the capture read back at the mip
 * level nearest 32 texels (the brute force is O(N^4)), convolved on the CPU with the level's
 * lobe, and uploaded. Level 0 (the mirror) is the capture itself. */
rd_result rd_reference_blur_level(rd_probe *p, unsigned source, int source_size, int level)
{
    int src_level = 0;
    while ((source_size >> src_level) > 32)
        src_level++;
    int n = source_size >> src_level, dst = p->size >> level;
    if (dst < 1)
        dst = 1;
    rd_cube_data src = {0}, out = {0};
    rd_result r = rd_cube_data_alloc(n, &src);
    if (r != RD_OK)
        return r;
    glBindTexture(GL_TEXTURE_CUBE_MAP, source);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int f = 0; f < 6; f++)
        glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, src_level, GL_RGBA, GL_FLOAT,
                      src.faces[f]);
    float exponent = level == 0 ? 1e9f : rd_level_exponent(level, p->size);
    r = level == 0 ? rd_cube_data_alloc(dst, &out)
                   : rd_ref_cube_convolve(&src, exponent, 0.0f, dst, &out);
    if (r == RD_OK && level == 0)
        for (int f = 0; f < 6; f++) /* the mirror level: the capture at full size */
            glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGBA, GL_FLOAT,
                          out.faces[f]);
    glBindTexture(GL_TEXTURE_CUBE_MAP, p->filtered);
    for (int f = 0; r == RD_OK && f < 6; f++)
        glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, level, 0, 0, dst, dst, GL_RGBA,
                        GL_FLOAT, out.faces[f]); /* the storage is rd_alloc_cube's */
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    rd_cube_data_free(&src);
    rd_cube_data_free(&out);
    unsigned e = rd_gl_drain_errors();
    return r != RD_OK ? r : e == GL_NO_ERROR ? RD_OK : rd_fail(RD_ERR_GL, "reference blur failed");
}

/* The box proxy: the scene's (the room's interior), else the bounds of everything. */
void rd_effective_proxy(const rd_scene *s, float bmin[3], float bmax[3])
{
    const rd_reflection_defaults *d = &s->reflection;
    int given = 0;
    for (int k = 0; k < 3; k++)
        given |= d->proxy_min[k] != 0.0f || d->proxy_max[k] != 0.0f;
    if (given) {
        memcpy(bmin, d->proxy_min, 3 * sizeof(float));
        memcpy(bmax, d->proxy_max, 3 * sizeof(float));
        return;
    }
    for (int k = 0; k < 3; k++) {
        bmin[k] = INFINITY;
        bmax[k] = -INFINITY;
    }
    for (int i = 0; i < s->object_count; i++) {
        float a[3], b[3];
        rd_object_world_bounds(s->ctx, &s->objects[i], a, b);
        for (int k = 0; k < 3; k++) {
            bmin[k] = fminf(bmin[k], a[k]);
            bmax[k] = fmaxf(bmax[k], b[k]);
        }
    }
}

static rd_probe_update effective_update(const rd_scene *s, const rd_probe_desc *pd, int *every)
{
    rd_probe_update u = pd->update != RD_PROBE_DEFAULT ? pd->update : s->reflection.update;
    int n = pd->update != RD_PROBE_DEFAULT ? pd->every_n : s->reflection.every_n;
    *every = n > 1 ? n : 1; /* N = 0 or 1: every frame (section 11) */
    return u != RD_PROBE_DEFAULT ? u : RD_PROBE_EVERY_FRAME;
}

static int next_pow2(float x)
{
    int n = 1;
    while ((float)n < x && n < 8192)
        n *= 2;
    return n;
}

/* Section 8: resolution follows the object's size on screen (seed 001 picks 8x8 ... 64x64 by
 * distance); supersampled stills raise it for print. */
static int probe_resolution(const rd_scene *s, const rd_probe *p, const float eye[3],
                            float pixels_per_tan, int supersample, int max_size)
{
    const rd_probe_desc *pd = &s->objects[p->owner].probe;
    int fixed = pd->resolution > 0 ? pd->resolution : s->reflection.resolution;
    int cap = s->reflection.max_resolution > 0 ? s->reflection.max_resolution
                                               : (supersample > 1 ? 512 : 256);
    if (cap > max_size)
        cap = max_size;
    /* A fixed size (the print preset's 512) is kept, but for the faint glazes under the print
     * preset's scene-wide "depth" (faint_under_depth): their colour is only ever read through
     * their lobe, so the gloss cap below holds for them as in auto sizing (a glaze of g = 0.6
     * is read at the 64-texel level of a 512 capture, which a 128 capture makes as well;
     * designed demo, 4K print: six such probes). */
    int glaze = faint_under_depth(s, &s->objects[p->owner].material);
    if (fixed > 0 && !glaze)
        return fixed < max_size ? fixed : max_size;
    float d = glm_vec3_distance((float *)eye, (float *)p->centre);
    float diameter_px = p->detail_size / fmaxf(d, 1e-3f) * pixels_per_tan * (float)supersample;
    float wanted = 0.5f * diameter_px;
    int n = next_pow2(wanted);
    /* Hysteresis: a live view moves the eye and adapts its render scale every
     * frame, and a new size means a new, complete capture. A probe keeps its size until the
     * wanted texels leave (size / 3, 1.5 size], 1.5 times beyond the rounding's own
     * (size / 2, size]; a first capture (a still) takes the plain rounding. */
    if (p->size > 0 && wanted > (float)p->size / 3.0f && wanted <= 1.5f * (float)p->size)
        n = p->size;
    if (fixed > 0) /* a glaze's fixed size: only the gloss cap applies */
        n = fixed < max_size ? fixed : max_size;
    /* A blurred reflection needs no more texels than its lobe can show: about two texels
     * across the lobe's half-width sqrt(2 ln 2 / n(g)) (a face spans pi/2). */
    float g = p->gloss_max; /* the sharpest of the objects that look it up */
    if (g < 1.0f && s->objects[p->owner].material.transparency <= 0.0f) {
        float half_width = sqrtf(2.0f * 0.6931472f / exp2f(13.0f * fmaxf(g, 0.0f)));
        /* Twice that, so the lookup lands on level 1 or above (rd_lobe_level), never between
         * the unblurred capture and the first blurred level. */
        int gloss_cap = next_pow2(2.0f * RD_LOBE_TEXELS * 1.5707963f / half_width);
        /* A glaze's "depth" search reads the capture's distances unblurred, at the texels'
         * own size: twice the texels place its hits closer. */
        if (glaze)
            gloss_cap *= 2;
        if (n > gloss_cap)
            n = gloss_cap;
    }
    /* Below 64 texels a face costs about the same (the capture is its fixed overhead:
     * tessera probe-bench), while bright surroundings bleed across its coarse texels: 64 is
     * the floor (docs/accuracy.md). */
    if (fixed > 0)
        return n < 64 && fixed >= 64 ? 64 : n;
    return n < 64 ? (cap < 64 ? cap : 64) : n > cap ? cap : n;
}

int rd_level_count(int size)
{
    int n = 1;
    while ((size >> n) > 0)
        n++;
    return n;
}

rd_result rd_alloc_cube(unsigned *name, int size, int levels)
{
    glGenTextures(1, name);
    glBindTexture(GL_TEXTURE_CUBE_MAP, *name);
    /* One allocation for every face and level where GL 4.2's immutable storage exists: level
     * by level, Mesa re-creates the texture as each image is specified, which makes a print's
     * probe set-up (many large cubes with their mips) take seconds. */
    if (rd_gl_has_tex_storage())
        rd_glTexStorage2D(GL_TEXTURE_CUBE_MAP, levels, GL_RGBA16F, size, size);
    else
        for (int f = 0; f < 6; f++)
            for (int l = 0; l < levels; l++) {
                int n = size >> l;
                glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, l, GL_RGBA16F, n, n, 0,
                             GL_RGBA, GL_FLOAT, NULL);
            }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum w = GL_TEXTURE_WRAP_S; w <= GL_TEXTURE_WRAP_R; w++)
        if (w == GL_TEXTURE_WRAP_S || w == GL_TEXTURE_WRAP_T || w == GL_TEXTURE_WRAP_R)
            glTexParameteri(GL_TEXTURE_CUBE_MAP, w, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    unsigned e = rd_gl_drain_errors();
    return e == GL_NO_ERROR
               ? RD_OK
               : rd_fail(e == GL_OUT_OF_MEMORY ? RD_ERR_OUT_OF_MEMORY : RD_ERR_GL,
                         "cannot make a %dx%d cube map (GL error 0x%x)", size, size, e);
}

/* GL's cube-face cameras in CMCS (the orientation that makes window rows the faces' t). */
static const float face_dir[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                     {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
static const float face_up[6][3] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                                    {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};

/* CMCS -> world: the inverse of seed 000's M_rot, (x, y, z) -> (x, z, -y). */
static void cmcs_to_world(const float c[3], float w[3])
{
    w[0] = c[0];
    w[1] = c[2];
    w[2] = -c[1];
}

rd_result rd_probe_capture_face(rd_context *ctx, rd_scene *s, rd_probe *p, int face, float far_m)
{
    glBindFramebuffer(GL_FRAMEBUFFER, ctx->probe_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                           GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face, p->capture, 0);
    /* "depth" probes also keep what their highlights need (lit.frag's frag_surface). */
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1,
                           GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face, p->surface, 0);
    static const GLenum two[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(p->surface ? 2 : 1, two);
    rd_result r = rd_probe_depth_ensure(ctx, p->size);
    if (r != RD_OK)
        return r;
    glViewport(0, 0, p->size, p->size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    /* Alpha holds the distance to what the face sees ("depth" correction); where it sees
     * nothing, farther than any room (about the largest half float). */
    glClearColor(0, 0, 0, 65000.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    vec3 dir, up, target;
    cmcs_to_world(face_dir[face], dir);
    cmcs_to_world(face_up[face], up);
    glm_vec3_add(p->centre, dir, target);
    mat4 view, proj, vp;
    glm_lookat(p->centre, target, up, view);
    /* A probe often sits millimetres in front of a wall (a mirror's centre is on its
     * surface): the near plane must not cut that wall away, nor, in a tall narrow room, the
     * walls beside it (rd_depth_near's cap by the room's smallest side). */
    float room_lo[3], room_hi[3];
    rd_effective_proxy(s, room_lo, room_hi);
    float near_m = 0.1f * rd_depth_near(far_m, room_lo, room_hi);
    glm_perspective(glm_rad(90.0f), 1.0f, fmaxf(near_m, 1e-5f), far_m, proj);
    glm_mat4_mul(proj, view, vp);
    if (p->surface) {
        /* No surface (the clear) has no highlight: shininess -1. */
        static const float none[4] = {0.0f, 0.0f, 0.0f, -1.0f};
        glClearBufferfv(GL_COLOR, 1, none);
    }
    /* The owner is left out of its own capture; reflective objects appear plain (one
     * bounce). */
    /* An object under half a texel across (a face spans 90 degrees over `size` texels) is
     * left out (section 8). A "depth" probe leaves highlights to the lookup, which sees them
     * from the reflecting point (lit.frag). */
    r = rd_draw_objects(ctx, s,
                        &(rd_pass){.view_proj = &vp[0][0],
                                   .eye = p->centre,
                                   .exclude_key = p->key,
                                   .exclude_emitters = p->leaves_emitters,
                                   .exclude_traced = rd_self_traced(s, p) ? &p->self : NULL,
                                   .reflections = 0,
                                   .min_solid_radius = 0.25f / (float)p->size,
                                   .specular_off = s->reflection.probe_no_specular || p->surface,
                                   .store_distance = 1,
                                   .isotropic_textures = 1});
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0,
                           0);
    glDrawBuffers(1, two);
    return r;
}

/* What a probe's blur costs a split capture's budget, in faces: the prefilter of a 256-texel
 * map takes about as long as two of its faces' captures on llvmpipe. */
#define SPLIT_BLUR_FACES 2

/* Which faces this frame's policy captures (a bit each). */
static int faces_to_capture(const rd_scene *s, rd_probe *p, rd_probe_update u, int every)
{
    int all = 0x3f;
    if (p->faces_valid != all)
        return all; /* the first frame (and every still) gets a complete map */
    if (u == RD_PROBE_TIME_SLICED)
        return 1 << p->next_face;
    switch (u) {
    case RD_PROBE_ONCE:
        return 0;
    case RD_PROBE_ON_CHANGE:
        if (s->reflection.max_faces_per_frame <= 0)
            return s->change_counter > p->captured_stamp ? all : 0;
        /* Within a frame budget: a face is refreshed only when the scene changed
         * after it was captured (the camera moving changes nothing), one face a frame and
         * probe, the faces taking turns, so a dragged fixture costs at most the budget. */
        for (int k = 0; k < 6; k++) {
            int f = (p->next_face + k) % 6;
            if (p->face_stamp[f] < s->change_counter)
                return 1 << f;
        }
        return 0;
    default:
        return s->frame - p->captured_frame >= every ? all : 0;
    }
}

float rd_probe_lod(const rd_probe *p, float glossiness)
{
    float g = fminf(fmaxf(glossiness, 0.0f), 1.0f);
    return rd_lobe_level(g, p->size, p->levels); /* section 5 */
}

unsigned rd_probe_texture(const rd_scene *s, const rd_probe *p)
{
    if (p->planar) /* a 2D texture (probe_planar.c), of this frame's eye or none */
        return p->planar_frame == s->frame ? p->planar_texture : 0;
    const rd_object_desc *o = &s->objects[p->owner];
    if (o->probe.update == RD_PROBE_STATIC) {
        const rd_texture_slot *t = rd_cubemap_lookup(s->ctx, o->probe.static_map);
        return t ? (p->filtered && p->filtered_level >= 0 ? p->filtered : t->name) : 0;
    }
    if (p->faces_valid != 0x3f)
        return 0;
    if (p->gloss_min < 1.0f && rd_effective_blur(s) == RD_BLUR_PREFILTERED)
        return p->filtered_level >= 0 ? p->filtered : 0;
    return p->capture;
}

/* After a complete capture: the blur its objects' glossiness needs (from the sharpest's
 * level to the roughest's), and nothing when they are all mirrors. Objects sharing a probe
 * may differ (a mirror and its frame, g = 1 and 0.9, with planar mirrors off; glass and planar
 * mirrors take probes of their own, rd_object_key): a level nobody made reads black, so every
 * level any of them looks up is made. */
static rd_result blur_probe(rd_context *ctx, rd_scene *s, rd_probe *p, unsigned source,
                            int source_size, rd_frame_stats *stats)
{
    p->filtered_level = -1;
    if (!(p->gloss_min < 1.0f))
        return RD_OK; /* mirrors only: no blur work at all (section 5) */
    float lod_sharp = rd_probe_lod(p, p->gloss_max), lod_rough = rd_probe_lod(p, p->gloss_min);
    int lo = (int)floorf(lod_sharp), hi = (int)floorf(lod_rough) + 1;
    if (hi > p->levels - 1)
        hi = p->levels - 1;
    if (lo > hi)
        lo = hi;
    if (source == p->capture) {
        /* Box mips: the fast method's lookup and the prefilter's source. Only the levels the
         * lookup or the filtered samples can reach are made: mipmapping a cube map is a pass
         * per face and level, and the small levels of a mirror-like lobe are never read. */
        int needed = hi + 2 < p->levels ? hi + 2 : p->levels - 1;
        glBindTexture(GL_TEXTURE_CUBE_MAP, source);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, needed);
        glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
        glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
        rd_phase_mark("probe box mips");
    }
    rd_blur_method method = rd_effective_blur(s);
    if (method == RD_BLUR_BOX_MIPS)
        return RD_OK;
    if (!p->filtered) {
        rd_result r = rd_alloc_cube(&p->filtered, p->size, p->levels);
        if (r != RD_OK)
            return r;
    }
    if (method == RD_BLUR_REFERENCE) {
        for (int level = lo; level <= hi; level++) {
            rd_result r = rd_reference_blur_level(p, source, source_size, level);
            if (r != RD_OK)
                return r;
            stats->prefiltered++;
        }
        p->filtered_level = lo;
        return RD_OK;
    }
    /* Only the two levels the lookup blends between are computed (section 8: compute only what
     * the scene needs). */
    float clamp = s->reflection.hdr_clamp > 0.0f ? s->reflection.hdr_clamp : 64.0f;
    for (int level = lo; level <= hi; level++) {
        rd_result r = rd_prefilter_level(ctx, source, source_size, p->filtered, p->size, level,
                                         p->levels, clamp);
        if (r != RD_OK)
            return r;
        stats->prefiltered++;
    }
    p->filtered_level = lo;
    return RD_OK;
}

rd_result rd_scene_update_spheres(rd_context *ctx, rd_scene *s)
{
    float(*sp)[4] =
        realloc(s->object_spheres, (size_t)(s->object_count ? s->object_count : 1) * sizeof *sp);
    if (!sp)
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "out of memory");
    s->object_spheres = sp;
    for (int i = 0; i < s->object_count; i++) {
        float lo[3], hi[3], r2 = 0.0f;
        rd_object_world_bounds(ctx, &s->objects[i], lo, hi);
        for (int k = 0; k < 3; k++) {
            int valid = lo[k] <= hi[k];
            sp[i][k] = valid ? 0.5f * (lo[k] + hi[k]) : 0.0f;
            float h = valid ? 0.5f * (hi[k] - lo[k]) : 0.0f;
            r2 += h * h;
        }
        sp[i][3] = sqrtf(r2);
    }
    return RD_OK;
}

/* A capture's far plane: far enough to see the whole scene (the proxy) from `centre`. */
static float capture_far(const float centre[3], const float bmin[3], const float bmax[3])
{
    float reach = 0.0f;
    for (int c = 0; c < 8; c++) {
        vec3 corner = {c & 1 ? bmax[0] : bmin[0], c & 2 ? bmax[1] : bmin[1],
                       c & 4 ? bmax[2] : bmin[2]};
        reach = fmaxf(reach, glm_vec3_distance((float *)centre, corner));
    }
    return isfinite(reach) && reach > 0.0f ? reach * 2.0f : 100.0f;
}

/* Whether any object of the probe's key is inside the main view's frustum. */
static int probe_visible(const rd_scene *s, const rd_probe *p, vec4 planes[6])
{
    for (int i = 0; i < s->object_count; i++) {
        if (rd_object_key(s, i) != p->key)
            continue;
        const float *sp = s->object_spheres[i];
        int inside = 1;
        for (int k = 0; k < 6 && inside; k++)
            inside = glm_vec3_dot(planes[k], (float *)sp) + planes[k][3] >= -sp[3];
        if (inside)
            return 1;
    }
    return 0;
}

/* Whether an object of the probe's key shows in a planar mirror the view sees (rd_planar_pyramid):
 * the mirror's capture draws it with its probe, which must then be fresh as if it were in view. */
static int probe_seen_in_mirror(const rd_scene *s, const rd_probe *p, vec4 planes[6])
{
    for (int m = 0; m < s->probe_count; m++) {
        const rd_probe *q = &s->probes[m];
        if (q == p || !q->planar || !probe_visible(s, q, planes))
            continue;
        float pyramid[5][4];
        rd_planar_pyramid(q, pyramid);
        for (int i = 0; i < s->object_count; i++) {
            if (rd_object_key(s, i) != p->key)
                continue;
            const float *sp = s->object_spheres[i];
            int inside = 1;
            for (int k = 0; k < 5 && inside; k++)
                inside = glm_vec3_dot(pyramid[k], (float *)sp) + pyramid[k][3] >= -sp[3];
            if (inside)
                return 1;
        }
    }
    return 0;
}

/* The room probe (lit.frag, pick_depth_hit): a cube of everything, the owners of the other
 * probes included, captured at the proxy's centre with distances and surfaces as a "depth"
 * probe is, and blurred for the glossiness of every object that searches it. It is made on the
 * frames that capture a "depth" probe completely, so the two always show the same scene. */
/* Captures the room probe: all six faces and its blur at once when *faces_left < 0, else (a
 * split capture, split_captures 2) at most *faces_left faces this frame, the faces already
 * made for the scene as it is kept, the blur after the last face in a frame with room for it
 * (SPLIT_BLUR_FACES) or that captured nothing else (frame_idle); until then the probe is held.
 * *faces_left is charged what was spent. */
static rd_result room_probe_update(rd_context *ctx, rd_scene *s, const float bmin[3],
                                   const float bmax[3], float g_min, float g_max, int *faces_left,
                                   rd_capture_clock *clock, rd_frame_stats *stats)
{
    rd_probe *p = &s->room_probe;
    for (int i = 0; i < s->object_count; i++) {
        const rd_material *m = &s->objects[i].material;
        if (s->object_probe[i] < 0 || s->probes[s->object_probe[i]].planar ||
            rd_effective_correction(s, m) != RD_CORRECTION_DEPTH)
            continue;
        float g = fminf(fmaxf(m->glossiness, 0.0f), 1.0f);
        g_min = fminf(g_min, g);
        g_max = fmaxf(g_max, g);
    }
    int fixed = s->reflection.resolution > 0 ? s->reflection.resolution : 256;
    int size = fixed < ctx->max_size ? fixed : ctx->max_size;
    if (size != p->size) {
        free_probe_textures(p);
        p->size = size;
        p->levels = rd_level_count(size);
        p->faces_valid = 0;
        rd_result r = rd_alloc_cube(&p->capture, size, p->levels);
        if (r == RD_OK)
            r = rd_alloc_cube(&p->surface, size, 1);
        if (r != RD_OK)
            return r;
    }
    p->key = 0;
    p->gloss_min = g_min;
    p->gloss_max = g_max > g_min ? g_max : g_min;
    for (int k = 0; k < 3; k++)
        p->centre[k] = 0.5f * (bmin[k] + bmax[k]);
    float far_m = capture_far(p->centre, bmin, bmax);
    int split = *faces_left >= 0, fresh = 0, made = 0;
    for (int f = 0; f < 6 && split; f++)
        if ((p->faces_valid & (1 << f)) && p->face_stamp[f] == s->change_counter)
            fresh |= 1 << f;
    p->faces_valid = fresh;
    int frame_idle = clock->steps == 0;
    rd_phase_mark("probe set-up");
    for (int f = 0; f < 6; f++) {
        if ((fresh & (1 << f)) ||
            (split && (*faces_left <= 0 || !rd_capture_clock_allows(clock, s, p->size, 1.0))))
            continue;
        double t0 = rd_capture_clock_now();
        rd_result r = rd_probe_capture_face(ctx, s, p, f, far_m);
        if (r != RD_OK)
            return r;
        rd_capture_clock_done(clock, s, p->size, t0);
        p->faces_valid |= 1 << f;
        p->face_stamp[f] = s->change_counter;
        stats->faces_captured++;
        made++;
        if (split)
            --*faces_left;
    }
    rd_phase_mark("probe captures");
    /* The blur where the budget leaves room for it, or in a frame that captured nothing else. */
    if (p->faces_valid != 0x3f ||
        (split &&
         (*faces_left < SPLIT_BLUR_FACES ||
          !rd_capture_clock_allows(clock, s, p->size, SPLIT_BLUR_FACES)) &&
         (made || !frame_idle))) {
        stats->probes_held++; /* the rest, or the blur, in a later frame */
        return RD_OK;
    }
    if (split)
        *faces_left -= SPLIT_BLUR_FACES;
    p->captured_frame = s->frame;
    p->captured_stamp = s->change_counter;
    stats->room_probe = 1;
    if (rd_phase_enabled())
        fprintf(stderr, "room probe: %d texels a face\n", p->size);
    return blur_probe(ctx, s, p, p->capture, p->size, stats);
}

/* The planar mirrors in view, each captured from the eye's image. They come after every cube
 * probe of the frame: a mirror's capture draws the objects in front of it with their own
 * probes (glass, chrome: what the mirror shows of them is what the eye would see from its
 * image, probe_planar.c), so those probes must be this frame's. */
static rd_result planar_captures(rd_context *ctx, rd_scene *s, const rd_planar_view *planar,
                                 vec4 planes[6], const float bmin[3], const float bmax[3],
                                 rd_frame_stats *stats)
{
    for (int i = 0; i < s->probe_count; i++) {
        rd_probe *p = &s->probes[i];
        if (!p->planar || !probe_visible(s, p, planes))
            continue;
        rd_phase_mark("probe set-up");
        rd_result r = rd_planar_capture(ctx, s, p, planar, capture_far(p->centre, bmin, bmax));
        rd_phase_mark("probe captures");
        if (r != RD_OK)
            return r;
        if (p->planar_frame != s->frame)
            continue; /* none of it in view */
        stats->planar_mirrors++;
        if (rd_phase_enabled())
            fprintf(stderr, "planar mirror: %d x %d texels\n", p->planar_width, p->planar_height);
    }
    return RD_OK;
}

rd_result rd_probes_update(rd_context *ctx, rd_scene *s, const float view_proj[16],
                           const float capture_view_proj[16], const float eye[3],
                           float pixels_per_tan, int supersample, const rd_planar_view *planar,
                           int hold_sizes, rd_frame_stats *stats)
{
    rd_result r = rd_probes_sync(s);
    if (r == RD_OK)
        r = rd_scene_update_spheres(ctx, s);
    if (r == RD_OK)
        r = rd_emitters_update(s);
    if (r == RD_OK)
        r = rd_self_trace_update(ctx, s);
    if (r != RD_OK)
        return r;
    s->frame++;
    stats->probes = s->probe_count;
    stats->emitters = s->emitter_count;
    for (int i = 0; i < s->probe_count; i++)
        if (rd_self_traced(s, &s->probes[i])) {
            stats->self_traced_probes++;
            stats->self_triangles += s->probes[i].self.tri_count;
        }
    if (!s->probe_count && s->reflection.glaze != RD_SWITCH_ON)
        return RD_OK; /* nothing reflects */
    float bmin[3], bmax[3];
    rd_effective_proxy(s, bmin, bmax);
    mat4 vp;
    vec4 planes[6], whole[6];
    memcpy(vp, view_proj, sizeof vp);
    glm_frustum_planes(vp, planes);
    memcpy(vp, capture_view_proj ? capture_view_proj : view_proj, sizeof vp);
    glm_frustum_planes(vp, whole);
    /* The frame budget for refreshing probes:
     * at most max_faces_per_frame faces re-captured a frame, the probes taking turns from a
     * start that moves every frame. A probe's first, complete capture is held back only when
     * the caller asked to split them (split_captures). */
    int budget = s->reflection.max_faces_per_frame, spent = 0, depth_fresh = 0;
    rd_capture_clock clock; /* the frame's capture time (rd_scene_set_capture_time) */
    rd_capture_clock_start(&clock);
    int start = s->probe_count ? (int)(s->frame % s->probe_count) : 0;
    /* Every probe placed and every planar mirror planned first: what a mirror in view shows
     * counts as in view (probe_seen_in_mirror). */
    for (int i = 0; i < s->probe_count; i++) {
        place_probe(ctx, s, &s->probes[i]);
        rd_probe_plan_planar(ctx, s, &s->probes[i], eye);
    }
    for (int k = 0; k < s->probe_count; k++) {
        int i = (start + k) % s->probe_count;
        rd_probe *p = &s->probes[i];
        const rd_object_desc *owner = &s->objects[p->owner];
        /* Sharp probes leave the lamps to their lookups (emitters.c); a change of mind needs
         * a new capture. */
        int leave = rd_probe_wants_leave_emitters(s, p);
        if (leave != p->leaves_emitters) {
            p->leaves_emitters = leave;
            p->faces_valid = 0;
            p->next_face = 0;
        }
        stats->emitter_probes += leave;
        if (owner->probe.update == RD_PROBE_STATIC) {
            const rd_texture_slot *t = rd_cubemap_lookup(ctx, owner->probe.static_map);
            if (!t)
                return rd_fail(RD_ERR_STALE_HANDLE, "a static probe's cube map is not live");
            if (p->captured_frame < 0) {
                p->size = t->size;
                p->levels = rd_level_count(t->size);
                r = blur_probe(ctx, s, p, t->name, t->size, stats);
                if (r != RD_OK)
                    return r;
                p->captured_frame = s->frame;
            }
            continue;
        }
        /* A planar mirror's capture follows the eye: made afresh every frame it is seen (a
         * cube it may have kept is stale by the time it is used again), after the cubes
         * (planar_captures). */
        if (p->planar) {
            p->faces_valid = 0;
            continue;
        }
        /* A moving live view changes its eye and its render scale every frame, and a new size
         * is a new, complete capture in one frame, for a reflection that motion blurs anyway:
         * its probes keep their sizes until the view stands still. */
        int size = hold_sizes && p->size > 0
                       ? p->size
                       : probe_resolution(s, p, eye, pixels_per_tan, supersample, ctx->max_size);
        if (size != p->size) {
            free_probe_textures(p);
            p->size = size;
            p->levels = rd_level_count(size);
            p->faces_valid = 0;
            p->next_face = 0;
            r = rd_alloc_cube(&p->capture, size, p->levels);
            if (r != RD_OK)
                return r;
        }
        /* The surface map comes and goes with the "depth" correction; a new one needs a new
         * capture. */
        int depth = rd_effective_correction(s, &owner->material) == RD_CORRECTION_DEPTH;
        if (depth != (p->surface != 0)) {
            if (p->surface)
                glDeleteTextures(1, &p->surface);
            p->surface = 0;
            p->faces_valid = 0;
            p->next_face = 0;
            if (depth && (r = rd_alloc_cube(&p->surface, size, 1)) != RD_OK)
                return r;
        }
        int every;
        rd_probe_update u = effective_update(s, &owner->probe, &every);
        /* An object out of view, and out of every mirror in view, needs no fresh reflection
         * this frame (section 8: compute only what the scene needs); its policy resumes when
         * it comes into view. */
        if (!probe_visible(s, p, whole) && !probe_seen_in_mirror(s, p, whole))
            continue;
        if (p->blur_waits) {
            /* A split first capture's blur: in the frame of its last face when the budget
             * leaves room for it, else in a frame of its own; the faces stay as they were. */
            p->blur_waits = 0;
            if (p->faces_valid == 0x3f && p->captured_stamp == s->change_counter) {
                if ((budget > 0 && spent + SPLIT_BLUR_FACES > budget && spent > 0) ||
                    !rd_capture_clock_allows(&clock, s, p->size, SPLIT_BLUR_FACES)) {
                    p->blur_waits = 1;
                    stats->probes_held++;
                    continue;
                }
                spent += SPLIT_BLUR_FACES;
                p->captured_frame = s->frame;
                r = blur_probe(ctx, s, p, p->capture, p->size, stats);
                if (r != RD_OK)
                    return r;
                rd_capture_clock_done(&clock, s, 0, 0.0);
                depth_fresh |= depth;
                continue;
            }
        }
        int faces = faces_to_capture(s, p, u, every);
        if (!faces)
            continue;
        int complete = faces == 0x3f; /* this frame ends with all six faces fresh */
        int split = 0;
        if (budget > 0 && faces == 0x3f && s->reflection.split_captures >= 2) {
            /* A first capture split by faces: the faces still missing, as many as the budget
             * leaves, in face order; the probe is held until its last face, then blurred. The
             * faces are what one capture would make (the scene has not changed since the
             * first of them: their stamps say so). */
            int fresh = 0;
            for (int f = 0; f < 6; f++)
                if ((p->faces_valid & (1 << f)) && p->face_stamp[f] == s->change_counter)
                    fresh |= 1 << f;
            p->faces_valid = fresh; /* a face of an older scene is made again */
            int missing = 0x3f & ~fresh, take = 0;
            for (int f = 0; f < 6 && spent < budget; f++)
                if (missing & (1 << f)) {
                    take |= 1 << f;
                    spent++;
                }
            if (take != missing)
                stats->probes_held++;
            if (!take)
                continue; /* its turn comes in a later frame */
            faces = take;
            complete = take == missing;
            split = 1;
        } else if (budget > 0 && (faces != 0x3f || s->reflection.split_captures)) {
            int n = __builtin_popcount((unsigned)faces);
            if (spent + n > budget && (faces != 0x3f || spent > 0)) {
                stats->probes_held++;
                continue; /* its turn comes in a later frame */
            }
            spent += n;
        }
        float far_m = capture_far(p->centre, bmin, bmax);
        rd_phase_mark("probe set-up"); /* TESSERA_PHASES (phase_timer.h) */
        /* Split captures and refreshes of a few faces keep to the frame's time as well: the
         * faces it leaves wait for a later frame, as the face budget's do. */
        int timed = split || faces != 0x3f, made = 0;
        for (int f = 0; f < 6; f++) {
            if (!(faces & (1 << f)))
                continue;
            if (timed && !rd_capture_clock_allows(&clock, s, p->size, 1.0))
                break;
            double t0 = rd_capture_clock_now();
            r = rd_probe_capture_face(ctx, s, p, f, far_m);
            if (r != RD_OK)
                return r;
            rd_capture_clock_done(&clock, s, p->size, t0);
            p->faces_valid |= 1 << f;
            p->face_stamp[f] = s->change_counter;
            stats->faces_captured++;
            made |= 1 << f;
        }
        rd_phase_mark("probe captures");
        if (made != faces) {
            if (complete || !split)
                stats->probes_held++; /* else held already: the budget left faces too */
            complete = 0;
            faces = made;
            if (!made)
                continue;
        }
        if (complete) {
            p->captured_stamp = s->change_counter;
            /* Time-sliced probes end their first round after 1 to 6 faces, by index, so that
             * their blurs (one per round) fall on different frames. */
            p->faces_since_blur = u == RD_PROBE_TIME_SLICED ? 5 - i % 6 : 0;
        }
        int round_done = 0;
        if (complete && split &&
            (spent + SPLIT_BLUR_FACES > budget ||
             !rd_capture_clock_allows(&clock, s, p->size, SPLIT_BLUR_FACES))) {
            p->blur_waits = 1; /* no room left for the blur: the next frame's */
            stats->probes_held++;
            continue;
        } else if (complete) {
            /* a first capture's last face, split or not: the blur below */
        } else if (faces != 0x3f && p->faces_valid != 0x3f) {
            continue; /* a split first capture under way: no blur before its last face */
        } else if (u == RD_PROBE_TIME_SLICED && faces != 0x3f) {
            p->next_face = (p->next_face + 1) % 6;
            round_done = ++p->faces_since_blur >= 6;
            if (round_done)
                p->faces_since_blur = 0;
        } else if (u == RD_PROBE_ON_CHANGE && faces != 0x3f) {
            /* Blur when no face is stale any more, or after six faces while the scene keeps
             * changing (a drag), so the reflection follows. */
            p->next_face = (__builtin_ctz((unsigned)faces) + 1) % 6;
            round_done = ++p->faces_since_blur >= 6 || !faces_to_capture(s, p, u, every);
            if (round_done)
                p->faces_since_blur = 0;
        }
        /* Blur when a full set of faces is fresh: every full capture, or at the end of each
         * time-sliced round. */
        if (complete && split)
            spent += SPLIT_BLUR_FACES;
        if (complete || round_done) {
            p->captured_frame = s->frame;
            r = blur_probe(ctx, s, p, p->capture, p->size, stats);
            if (r != RD_OK)
                return r;
            rd_capture_clock_done(&clock, s, 0, 0.0);
            depth_fresh |= depth;
        }
    }
    if (rd_phase_enabled() && stats->emitter_probes)
        fprintf(stderr, "lamps reflected exactly: %d, in %d probes captured without them\n",
                s->emitter_count, stats->emitter_probes);
    if (rd_phase_enabled() && stats->self_traced_probes)
        fprintf(stderr, "self-reflections traced: %d probes, %d triangles\n",
                stats->self_traced_probes, stats->self_triangles);
    /* Glazes read the room probe too: it is made when one is in view and the scene changed
     * since its last capture (compute only what the scene needs), blurred for both kinds of
     * reader. */
    float glaze_min, glaze_max;
    stats->glazed = rd_glazes_in_view(s, whole, &glaze_min, &glaze_max);
    const rd_probe *room = &s->room_probe;
    int room_for_depth = depth_fresh && s->reflection.room_probe != RD_SWITCH_OFF;
    int room_for_glazes = stats->glazed > 0 &&
                          (room->faces_valid != 0x3f || room->captured_stamp != s->change_counter ||
                           !(room->gloss_min <= glaze_min));
    /* A room probe for the glazes alone splits as the cube probes do; one for the "depth"
     * lookups follows their blur in the same frame. */
    int room_faces = budget > 0 && s->reflection.split_captures >= 2 && !room_for_depth
                         ? (budget > spent ? budget - spent : 0)
                         : -1;
    if ((room_for_depth || room_for_glazes) &&
        (r = room_probe_update(ctx, s, bmin, bmax, glaze_min, glaze_max, &room_faces, &clock,
                               stats)) != RD_OK)
        return r;
    if ((r = planar_captures(ctx, s, planar, planes, bmin, bmax, stats)) != RD_OK)
        return r;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    unsigned e = rd_gl_drain_errors();
    return e == GL_NO_ERROR ? RD_OK : rd_fail(RD_ERR_GL, "OpenGL error 0x%x in a probe", e);
}

rd_result rd_scene_read_probe(rd_scene *s, int index, int face, int level, float *rgba,
                              size_t count, int *size)
{
    if (!s || index < 0 || index >= s->probe_count || face < 0 || face > 5 || level < 0)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_read_probe: no probe %d face %d", index,
                       face);
    const rd_probe *p = &s->probes[index];
    unsigned tex = rd_probe_texture(s, p);
    int n = p->size >> level;
    if (!tex || level >= p->levels || n < 1)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_read_probe: probe %d has no level %d",
                       index, level);
    if (!rgba || count < (size_t)n * (size_t)n * 4)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_read_probe: buffer too small");
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face, level, GL_RGBA, GL_FLOAT, rgba);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    if (size)
        *size = n;
    return rd_gl_drain_errors() == GL_NO_ERROR ? RD_OK
                                               : rd_fail(RD_ERR_GL, "rd_scene_read_probe failed");
}
