/* Planar mirrors (rd_reflection_defaults.planar_mirrors; the print preset).
 *
 * Every ray the view reflects off a flat mirror leaves the mirror as if it came from one
 * point: the eye's image in the mirror's plane (the law of reflection; why a mirror shows a
 * second room behind it). A probe centred there sees, in each lookup direction R, exactly what
 * the reflected ray from the mirror's point sees, once it draws only what lies in front of the
 * mirror's plane: its capture holds the planar reflection of the classic mirrored-camera
 * technique, and no proxy or search is needed. Nothing is hidden from the centre that the
 * mirror's points see, which a probe at the mirror's own centre cannot promise even with its
 * stored distances (thin rails in front of a wall; docs/history.md).
 *
 * The capture depends on the eye, so it is made every frame the probe is used. It is a 2D
 * texture, not a cube: from the eye's image the mirror is one window, and the capture is the
 * view through it at the view's own sample density, so its cost follows the mirror's share of
 * the image. The lookup projects the reflecting point into it (lit.frag, PLANAR_REFLECTION). */
#include "probe_planar.h"

#include "draw.h"
#include "gl_funcs.h"

#include <cglm/cglm.h>
#include <math.h>
#include <string.h>

/* Thinner than this, and than a tenth of its other extents, an object is a flat pane. */
#define PLANAR_MAX_THICKNESS_M 0.06f
#define PLANAR_MAX_ASPECT 0.1f
/* The front face is enlarged by this fraction on each side for the capture's footprint: the
 * mirror's edges and bilinear lookups at its border read a little beyond it. */
#define PLANAR_MARGIN 0.03f
/* Bilinear look-ups at one texel a sample blur by about a texel: 1.5 texels a sample keep the
 * edges, and more texels than that buy nothing measurable on the demo's reflective pixels. */
#define PLANAR_TEXELS_PER_SAMPLE 1.5f
/* The largest capture side (4096 x 4096 RGBA16F: 128 MB). */
#define PLANAR_MAX_SIZE 4096

static void transform_point(const float m[16], const float p[3], float out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = m[k] * p[0] + m[4 + k] * p[1] + m[8 + k] * p[2] + m[12 + k];
}

static float dot3(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

int rd_planar_candidate(const rd_scene *s, const rd_object_desc *o)
{
    const rd_material *m = &o->material;
    return s->reflection.planar_mirrors == RD_SWITCH_ON && m->reflectivity > 0.0f &&
           m->glossiness >= 1.0f && !(m->transparency > 0.0f) &&
           m->correction == RD_CORRECTION_DEFAULT && !m->sphere_map && !m->per_vertex_reflection &&
           !s->reflection.per_vertex && o->probe.update != RD_PROBE_STATIC;
}

int rd_probe_plan_planar(rd_context *ctx, const rd_scene *s, rd_probe *p, const float eye[3])
{
    p->planar = 0;
    const rd_object_desc *o = &s->objects[p->owner];
    if (!rd_planar_candidate(s, o) || p->gloss_min < 1.0f)
        return 0;
    for (int i = 0; i < s->object_count; i++)
        if (i != p->owner && rd_object_key(s, i) == p->key)
            return 0; /* a group: its objects need not share a plane */
    const rd_mesh_slot *mesh = rd_mesh_lookup(ctx, o->mesh);
    if (!mesh)
        return 0;
    const float *mt = o->transform, *lo = mesh->bounds_min, *hi = mesh->bounds_max;
    float extent[3];
    for (int k = 0; k < 3; k++) {
        const float *col = mt + 4 * k;
        extent[k] = (hi[k] - lo[k]) * sqrtf(dot3(col, col));
        if (!(extent[k] >= 0.0f) || !isfinite(extent[k]))
            return 0;
    }
    int k = extent[0] <= extent[1] && extent[0] <= extent[2] ? 0 : extent[1] <= extent[2] ? 1 : 2;
    int a = (k + 1) % 3, b = (k + 2) % 3;
    float other = fminf(extent[a], extent[b]);
    if (!(other > 0.0f) || extent[k] > PLANAR_MAX_THICKNESS_M ||
        extent[k] > PLANAR_MAX_ASPECT * other)
        return 0;
    /* The pane's normal: perpendicular to its two long edges (right under any affine
     * transform), turned along the thin axis. */
    const float *ca = mt + 4 * a, *cb = mt + 4 * b, *ck = mt + 4 * k;
    float n[3] = {ca[1] * cb[2] - ca[2] * cb[1], ca[2] * cb[0] - ca[0] * cb[2],
                  ca[0] * cb[1] - ca[1] * cb[0]};
    float len = sqrtf(dot3(n, n));
    if (!(len > 0.0f))
        return 0;
    float sign = dot3(n, ck) < 0.0f ? -1.0f : 1.0f;
    for (int j = 0; j < 3; j++)
        n[j] *= sign / len;
    /* The face the eye looks at: the +k face when the eye is in front of it, else the -k. */
    for (int side = 0; side < 2; side++) {
        float face_n[3] = {side ? -n[0] : n[0], side ? -n[1] : n[1], side ? -n[2] : n[2]};
        float local[3], q[3];
        for (int j = 0; j < 3; j++)
            local[j] = 0.5f * (lo[j] + hi[j]);
        local[k] = side ? lo[k] : hi[k];
        transform_point(mt, local, q);
        float d = -dot3(face_n, q);
        float h = dot3(face_n, eye) + d; /* the eye's height over the face's plane */
        if (!(h > 1e-3f))
            continue;
        for (int c = 0; c < 4; c++) {
            float corner[3] = {local[0], local[1], local[2]};
            float grow = 0.5f + PLANAR_MARGIN;
            corner[a] += (c & 1 ? grow : -grow) * (hi[a] - lo[a]);
            corner[b] += (c & 2 ? grow : -grow) * (hi[b] - lo[b]);
            transform_point(mt, corner, p->quad[c]);
        }
        for (int j = 0; j < 3; j++) {
            p->plane[j] = face_n[j];
            p->centre[j] = eye[j] - 2.0f * h * face_n[j];
        }
        p->plane[3] = d;
        p->planar = 1;
        return 1;
    }
    return 0; /* the eye in the pane's slab or behind it: the ordinary probe */
}

void rd_planar_pyramid(const rd_probe *p, float planes[5][4])
{
    static const int cycle[4] = {0, 1, 3, 2}; /* quad corners by bits -> around the rim */
    float mid[3] = {0.0f, 0.0f, 0.0f};
    for (int c = 0; c < 4; c++)
        for (int k = 0; k < 3; k++)
            mid[k] += 0.25f * p->quad[c][k];
    for (int e = 0; e < 4; e++) {
        const float *a = p->quad[cycle[e]], *b = p->quad[cycle[(e + 1) % 4]];
        float u[3], v[3];
        for (int k = 0; k < 3; k++) {
            u[k] = a[k] - p->centre[k];
            v[k] = b[k] - p->centre[k];
        }
        float n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                      u[0] * v[1] - u[1] * v[0]};
        float len = sqrtf(dot3(n, n));
        float d = -dot3(n, p->centre);
        /* The quad's middle is inside: the side it lies on is the inside. */
        float sign = dot3(n, mid) + d < 0.0f ? -1.0f : 1.0f;
        for (int k = 0; k < 3; k++)
            planes[e][k] = len > 0.0f ? sign * n[k] / len : 0.0f;
        planes[e][3] = len > 0.0f ? sign * d / len : 0.0f;
    }
    memcpy(planes[4], p->plane, sizeof planes[4]); /* in front of the mirror */
}

#define PLANAR_MAX_POLY 16 /* a quad clipped by six planes has at most ten corners */

/* Clips the convex polygon `in` (n world points) to the half-space plane.xyz . x + plane.w >= 0
 * (Sutherland-Hodgman, one plane). */
static int clip_polygon(const float (*in)[3], int n, const float plane[4], float (*out)[3])
{
    int m = 0;
    for (int i = 0; i < n && m < PLANAR_MAX_POLY - 1; i++) {
        const float *a = in[i], *b = in[(i + 1) % n];
        float da = dot3(plane, a) + plane[3], db = dot3(plane, b) + plane[3];
        if (da >= 0.0f) {
            memcpy(out[m++], a, sizeof out[0]);
        }
        if ((da >= 0.0f) != (db >= 0.0f)) {
            float t = da / (da - db);
            for (int k = 0; k < 3; k++)
                out[m][k] = a[k] + t * (b[k] - a[k]);
            m++;
        }
    }
    return m;
}

/* The part of the (enlarged) mirror the view sees: its quad clipped by the view's frustum. */
static int visible_polygon(const rd_probe *p, const float view_proj[16], float (*poly)[3])
{
    vec4 planes[6];
    mat4 vp;
    memcpy(vp, view_proj, sizeof vp);
    glm_frustum_planes(vp, planes);
    float tmp[PLANAR_MAX_POLY][3];
    static const int cycle[4] = {0, 1, 3, 2}; /* quad corners by bits -> around the rim */
    int n = 4;
    for (int c = 0; c < 4; c++)
        memcpy(poly[c], p->quad[cycle[c]], sizeof poly[0]);
    for (int k = 0; k < 6 && n >= 3; k++) {
        n = clip_polygon((const float(*)[3])poly, n, planes[k], tmp);
        memcpy(poly, tmp, (size_t)n * sizeof tmp[0]);
    }
    return n >= 3 ? n : 0;
}

/* The capture's camera: at the eye's image, looking along the mirror's normal, its frustum
 * cut to what the view sees of the mirror (poly, with a margin of 1 % each way for bilinear
 * look-ups at the border), the near plane on the mirror's plane (what lies behind the mirror,
 * the wall it hangs on above all, is cut away). tan_w, tan_h: that window's extent in units of
 * tan as seen from there. */
static void planar_camera(const rd_probe *p, const float (*poly)[3], int n, float far_m, mat4 vp,
                          float *tan_w, float *tan_h)
{
    vec3 eye = {p->centre[0], p->centre[1], p->centre[2]};
    vec3 normal = {p->plane[0], p->plane[1], p->plane[2]}, target, up = {0.0f, 0.0f, 1.0f};
    if (fabsf(normal[2]) > 0.99f) { /* a mirror on the floor or the ceiling */
        up[1] = 1.0f;
        up[2] = 0.0f;
    }
    glm_vec3_add(eye, normal, target);
    mat4 view, proj;
    glm_lookat(eye, target, up, view);
    float h = -(dot3(normal, eye) + p->plane[3]); /* the image's depth behind the plane */
    float l = INFINITY, r = -INFINITY, b = INFINITY, t = -INFINITY;
    for (int c = 0; c < n; c++) {
        vec3 v;
        glm_mat4_mulv3(view, (float *)poly[c], 1.0f, v);
        l = fminf(l, v[0]);
        r = fmaxf(r, v[0]);
        b = fminf(b, v[1]);
        t = fmaxf(t, v[1]);
    }
    float mx = 0.01f * (r - l), my = 0.01f * (t - b);
    l -= mx;
    r += mx;
    b -= my;
    t += my;
    glm_frustum(l, r, b, t, h, fmaxf(far_m, 2.0f * h), proj);
    glm_mat4_mul(proj, view, vp);
    *tan_w = (r - l) / h;
    *tan_h = (t - b) / h;
}

/* The texels across and down the capture that give each of the view's samples on the mirror
 * one texel: for every edge of the visible polygon, its length in samples on screen spread
 * over the capture's x and y as the edge lies there (a mirror seen at a slant needs fewer
 * texels across than a frontal one). 0 when the eye looks along the mirror's plane. */
static int screen_texels(const float (*poly)[3], int n, const rd_planar_view *v,
                         const mat4 capture_vp, float out[2])
{
    float scr[PLANAR_MAX_POLY][2], cap[PLANAR_MAX_POLY][2];
    for (int c = 0; c < n; c++) {
        vec4 q = {poly[c][0], poly[c][1], poly[c][2], 1.0f}, a, b;
        glm_mat4_mulv((vec4 *)v->view_proj, q, a);
        glm_mat4_mulv((vec4 *)capture_vp, q, b);
        if (!(a[3] > 0.0f) || !(b[3] > 0.0f))
            return 0;
        scr[c][0] = 0.5f * a[0] / a[3] * v->samples[0];
        scr[c][1] = 0.5f * a[1] / a[3] * v->samples[1];
        cap[c][0] = b[0] / b[3]; /* the capture's NDC: 2 units across */
        cap[c][1] = b[1] / b[3];
    }
    out[0] = out[1] = 0.0f;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        float len = hypotf(scr[j][0] - scr[i][0], scr[j][1] - scr[i][1]);
        float dx = fabsf(cap[j][0] - cap[i][0]), dy = fabsf(cap[j][1] - cap[i][1]);
        float d = hypotf(dx, dy);
        if (!(d > 1e-6f))
            continue;
        /* samples per capture NDC unit along the edge, times 2 NDC units, by component */
        out[0] = fmaxf(out[0], 2.0f * len / d * (dx / d));
        out[1] = fmaxf(out[1], 2.0f * len / d * (dy / d));
    }
    return isfinite(out[0]) && isfinite(out[1]) && out[0] > 0.0f && out[1] > 0.0f;
}

/* Texels for `tan` units of tan at the view's density, or for the mirror's samples on screen
 * where that is less, texels_per_sample a sample, within [16, the cap]. */
static int planar_texels(float tan, float samples_per_tan, int have_screen, float screen,
                         float texels_per_sample, int max_size)
{
    float wanted = tan * samples_per_tan;
    if (have_screen && screen < wanted)
        wanted = screen;
    wanted *= texels_per_sample > 0.0f ? texels_per_sample : PLANAR_TEXELS_PER_SAMPLE;
    int cap = max_size < PLANAR_MAX_SIZE ? max_size : PLANAR_MAX_SIZE;
    if (!(wanted > 16.0f))
        return 16;
    return wanted >= (float)cap ? cap : (int)ceilf(wanted);
}

rd_result rd_planar_capture(rd_context *ctx, rd_scene *s, rd_probe *p, const rd_planar_view *v,
                            float far_m)
{
    float poly[PLANAR_MAX_POLY][3];
    int n = visible_polygon(p, v->view_proj, poly);
    if (!n)
        return RD_OK; /* the view sees none of the mirror: nothing to capture */
    mat4 vp;
    float tan_w, tan_h, screen[2] = {0.0f, 0.0f};
    planar_camera(p, (const float(*)[3])poly, n, far_m, vp, &tan_w, &tan_h);
    int have_screen = screen_texels((const float(*)[3])poly, n, v, vp, screen);
    int w = planar_texels(tan_w, v->samples_per_tan, have_screen, screen[0], v->texels_per_sample,
                          ctx->max_size);
    int h = planar_texels(tan_h, v->samples_per_tan, have_screen, screen[1], v->texels_per_sample,
                          ctx->max_size);
    if (w != p->planar_width || h != p->planar_height || !p->planar_texture) {
        rd_float_texture_2d(&p->planar_texture, w, h, 0);
        p->planar_width = w;
        p->planar_height = h;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, ctx->probe_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, p->planar_texture,
                           0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, 0, 0);
    static const GLenum one = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &one);
    rd_result r = rd_planar_depth_ensure(ctx, w, h);
    if (r != RD_OK)
        return r;
    glViewport(0, 0, w, h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    memcpy(p->planar_view_proj, vp, sizeof p->planar_view_proj);
    /* The eye's image is where the reflected rays come from: highlights are seen from there,
     * and texture footprints are the mirror's own, so neither is left out or simplified as in
     * a cube capture; full meshes, since the capture is as sharp as the view. Objects under
     * half a sample across are left out (section 8). What reflects or is glass is drawn with
     * its own probe, as the eye would see it from there: chrome in a mirror is chrome and a
     * shower screen in front of it is glass (a second bounce, as a real mirror and the path
     * tracer show them; rd_reflection_defaults.mirror_bounce OFF draws them plain and leaves
     * glass out, as every other capture). With rd_reflection_defaults.mirror_panes ON a thin
     * pane is blended over what the capture drew behind it, last (rd_pass.panes_over): a
     * straight ray through it from the eye's image sees exactly that, where the pane's probe
     * shows it from the pane's centre; it costs the shading of what lies behind the pane, so
     * it is a switch. Another planar
     * mirror's capture belongs to the view's eye, not this one: such a mirror is drawn plain.
     * A depth prepass, as the main view's, shades each texel once: sorted from the mirror's centre,
     * the fixtures seen in it are not always drawn before the walls behind them, and chrome drawn
     * with its probe is the dearest fragment the capture has. */
    float sample_tan = 1.0f / fmaxf(v->samples_per_tan, 1.0f);
    r = rd_draw_objects(ctx, s,
                        &(rd_pass){.view_proj = &vp[0][0],
                                   .eye = p->centre,
                                   .exclude_key = p->key,
                                   .reflections = s->reflection.mirror_bounce != RD_SWITCH_OFF,
                                   .planar_off = 1,
                                   .min_solid_radius = 0.25f * sample_tan,
                                   .full_meshes = 1,
                                   .depth_prepass = 1,
                                   .panes_over = s->reflection.mirror_panes == RD_SWITCH_ON});
    unsigned e = rd_gl_drain_errors();
    if (r == RD_OK && e != GL_NO_ERROR)
        r = rd_fail(e == GL_OUT_OF_MEMORY ? RD_ERR_OUT_OF_MEMORY : RD_ERR_GL,
                    "cannot capture a %dx%d planar mirror (GL error 0x%x)", w, h, e);
    if (r == RD_OK)
        p->planar_frame = s->frame;
    return r;
}
