/* Path tracing with indirect light (docs/reference.md, "Indirect light"): the physical ground
 * truth behind `tessera reference --bounces N`.
 *
 * Radiance leaving a surface is its emission plus what it reflects (the rendering equation,
 * Kajiya 1986), estimated by paths from the eye. At every vertex:
 * - the renderer's lights (point, spot, directional) give section 1's direct terms exactly as
 *   rd_ref_shade computes them, shadowed by a ray (the GPU's soft taps at the first vertex when
 *   the scene asks for soft shadows), and no ambient term: the paths carry the indirect light
 *   the constant I_a stands in for;
 * - emitting triangles are area lights that emit from their front (counter-clockwise) side only,
 *   as area lights in PBRT and Mitsuba do (a window pane or a ceiling panel shines into the room,
 *   not into the wall behind it), sampled by area x power (next-event estimation) and
 *   combined with the paths that hit them by multiple importance sampling with the power
 *   heuristic (Veach and Guibas 1995), so no light is counted twice;
 * - the path continues through one part of the surface, picked by its weight: the diffuse and
 *   glossy lobes, or on a surface the GPU gives a probe, the reflection or the transmission of
 *   lit.frag's blend (RENDERING.md sections 5, 6, 9);
 * - a bounce is what a bake pass is (ref_bake_gather.c): a lobe sample, or a mirror reflection
 *   after one; a pass through glass never counts (the bake sees through glass), nor does a
 *   reflection or a pass on the way from the eye to the first lobe (the GPU shows the baked
 *   surface in a mirror and behind a screen with all its bounces), at most MAX_FREE_EVENTS
 *   of those a path;
 * - after RR_START vertices Russian roulette ends the path with probability 1 - q and divides
 *   the survivors by q (unbiased; Arvo and Kirk 1990).
 * The BSDF for bounced and area light is a diffuse lobe C_d / pi (the renderer's light I
 * stands for irradiance pi I, so section 1's C_d I N.L is exactly this lobe's response) and a
 * normalised Blinn-Phong lobe C_s (n + 8) / (8 pi) (N.H)^n (the normalisation of
 * Akenine-Moeller, Haines and Hoffman, Real-Time Rendering, 3rd ed., chapter 7), sampled by
 * importance: cosine-weighted for the diffuse lobe, H from ((n + 1) / 2 pi) (N.H)^n for the glossy
 * one (Walter et al. 2007: pdf_L = pdf_H / (4 V.H)). */
#include "ref_internal.h"

#include "render/reflect_ref.h"
#include "render/shade_ref.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI_F 3.14159265358979f
/* Russian roulette from the fourth vertex on: short paths keep their full weight. */
#define RR_START 3
/* Mirror and glass events that spend no bounce, a path: two facing mirrors end. */
#define MAX_FREE_EVENTS 8

void ref_emitters_free(ref_emitters *e)
{
    if (!e)
        return;
    free(e->mesh);
    free(e->prim);
    free(e->cdf);
    memset(e, 0, sizeof *e);
}

/* An emitter's power per unit area and solid angle, up to a constant: the mean of its radiance. */
static float emitted_power(const ref_mesh *m)
{
    return (m->emission[0] + m->emission[1] + m->emission[2]) / 3.0f;
}

/* Emitting triangles are area lights, except a surface whose light the scene's lights carry: a
 * window's exterior panel is stood in for by the rectangle light and the sun the render list
 * gives it (docs/rendering.md, "Daylight"), which next-event estimation samples with the
 * renderer's lights, so counting the panel too would let the sky in twice. */
static int is_area_light(const ref_mesh *m)
{
    return emitted_power(m) > 0.0f && !m->light_stand_in;
}

static float triangle_area(const ref_mesh *m, unsigned prim)
{
    const float *n = m->tri_normals + 3 * (size_t)prim;
    return 0.5f * sqrtf(ref_dot(n, n));
}

ref_result ref_emitters_prepare(ref_scene *s)
{
    ref_emitters *e = &s->emitters;
    ref_emitters_free(e);
    int count = 0;
    for (int i = 0; i < s->mesh_count; i++)
        if (is_area_light(&s->meshes[i]))
            count += s->meshes[i].triangle_count;
    if (count == 0)
        return REF_OK;
    e->mesh = malloc((size_t)count * sizeof *e->mesh);
    e->prim = malloc((size_t)count * sizeof *e->prim);
    e->cdf = malloc((size_t)count * sizeof *e->cdf);
    if (!e->mesh || !e->prim || !e->cdf) {
        ref_emitters_free(e);
        return ref_fail(REF_ERR_OUT_OF_MEMORY, "area lights: out of memory");
    }
    double total = 0.0;
    for (int i = 0; i < s->mesh_count; i++) {
        const ref_mesh *m = &s->meshes[i];
        float power = emitted_power(m);
        if (!is_area_light(m))
            continue;
        for (int t = 0; t < m->triangle_count; t++) {
            double w = (double)triangle_area(m, (unsigned)t) * power;
            if (!(w > 0.0) || !isfinite(w))
                continue;
            total += w;
            e->mesh[e->count] = i;
            e->prim[e->count] = t;
            e->cdf[e->count] = total;
            e->count++;
        }
    }
    e->total = e->count > 0 ? total : 0.0;
    return REF_OK;
}

/* The emitter whose share of the running sum holds u in [0, 1). */
static int pick_emitter(const ref_emitters *e, float u)
{
    double x = (double)u * e->total;
    int lo = 0, hi = e->count - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (e->cdf[mid] > x)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

/* The solid-angle density with which next-event estimation picks the point at distance t along
 * unit dir on an emitter of mesh m whose unit geometric normal makes cosine cos_l with dir:
 * (power / total) (its area density) x t^2 / cos_l. */
static float light_pdf(const ref_scene *s, const ref_mesh *m, float t, float cos_l)
{
    if (!(s->emitters.total > 0.0) || !(cos_l > 0.0f))
        return 0.0f;
    return (float)((double)emitted_power(m) / s->emitters.total) * t * t / cos_l;
}

/* The power heuristic with exponent 2 (Veach and Guibas 1995). */
static float mis_weight(float pdf_a, float pdf_b)
{
    float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    return a + b > 0.0f && isfinite(a + b) ? a / (a + b) : (pdf_a >= pdf_b ? 1.0f : 0.0f);
}

static float mean3(const float c[3])
{
    return (fmaxf(c[0], 0.0f) + fmaxf(c[1], 0.0f) + fmaxf(c[2], 0.0f)) / 3.0f;
}

/* The diffuse and glossy lobes of one surface point and the chance of sampling the glossy one. */
typedef struct lobes {
    float diffuse[3];  /* C_d x texture */
    float specular[3]; /* C_s */
    float shininess;
    float p_glossy;
} lobes;

/* f(V, L) without the cosine, and the density with which lobes_sample picks L. */
static void lobes_eval(const lobes *b, const float n[3], const float v[3], const float l[3],
                       float f[3], float *pdf)
{
    float nl = ref_dot(n, l), nv = ref_dot(n, v);
    f[0] = f[1] = f[2] = 0.0f;
    *pdf = 0.0f;
    if (!(nl > 0.0f) || !(nv > 0.0f))
        return;
    float h[3] = {l[0] + v[0], l[1] + v[1], l[2] + v[2]};
    float h_len = sqrtf(ref_dot(h, h));
    if (!(h_len > 0.0f))
        return;
    for (int k = 0; k < 3; k++)
        h[k] /= h_len;
    float n_exp = fmaxf(b->shininess, 0.0f);
    float lobe = rd_ref_blinn_phong_power(ref_dot(n, h), n_exp);
    float vh = ref_dot(v, h);
    float norm = (n_exp + 8.0f) / (8.0f * PI_F);
    for (int k = 0; k < 3; k++)
        f[k] = b->diffuse[k] / PI_F + b->specular[k] * norm * lobe;
    float pdf_glossy = vh > 0.0f ? (n_exp + 1.0f) / (2.0f * PI_F) * lobe / (4.0f * vh) : 0.0f;
    *pdf = (1.0f - b->p_glossy) * nl / PI_F + b->p_glossy * pdf_glossy;
}

/* Picks L for view V from the lobes with numbers u0 (which lobe), u1, u2 (where). 0 when the
 * sample falls below the surface. */
static int lobes_sample(const lobes *b, const float n[3], const float v[3], float u0, float u1,
                        float u2, float l[3])
{
    float t[3], bt[3];
    ref_basis(n, t, bt);
    float phi = 2.0f * PI_F * u2;
    if (u0 < b->p_glossy) {
        float cos_h = powf(fmaxf(1.0f - u1, 1e-30f), 1.0f / (fmaxf(b->shininess, 0.0f) + 1.0f));
        float sin_h = sqrtf(fmaxf(0.0f, 1.0f - cos_h * cos_h));
        float h[3];
        for (int k = 0; k < 3; k++)
            h[k] = cos_h * n[k] + sin_h * (cosf(phi) * t[k] + sinf(phi) * bt[k]);
        float vh = ref_dot(v, h);
        for (int k = 0; k < 3; k++)
            l[k] = 2.0f * vh * h[k] - v[k];
    } else {
        float r = sqrtf(u1), z = sqrtf(fmaxf(0.0f, 1.0f - u1));
        for (int k = 0; k < 3; k++)
            l[k] = z * n[k] + r * (cosf(phi) * t[k] + sinf(phi) * bt[k]);
    }
    return ref_dot(n, l) > 0.0f;
}

/* A direction from the normalised Phong lobe of glossiness g around unit axis (one sample of
 * what ref_trace.c's lobe_radiance averages); the axis itself for a mirror. */
static void gloss_direction(const float axis[3], float g, float u1, float u2, float out[3])
{
    if (g >= 1.0f) {
        memcpy(out, axis, 3 * sizeof(float));
        return;
    }
    float t[3], b[3];
    ref_basis(axis, t, b);
    float cos_t = powf(fmaxf(1.0f - u1, 1e-30f), 1.0f / (rd_ref_gloss_exponent(g) + 1.0f));
    float sin_t = sqrtf(fmaxf(0.0f, 1.0f - cos_t * cos_t));
    float phi = 2.0f * PI_F * u2;
    for (int k = 0; k < 3; k++)
        out[k] = cos_t * axis[k] + sin_t * (cosf(phi) * t[k] + sinf(phi) * b[k]);
}

static float clamp01(float x)
{
    return fminf(fmaxf(x, 0.0f), 1.0f); /* NaN -> 0, as draw.c sets the GPU's uniforms */
}

/* The unit geometric normal of the hit triangle on the side the ray came from (n where the
 * triangle is degenerate). */
static void side_normal(const ref_surface *sf, float ng[3])
{
    const float *tri_n = sf->mesh->tri_normals + 3 * (size_t)sf->prim;
    float len = sqrtf(ref_dot(tri_n, tri_n));
    for (int k = 0; k < 3; k++)
        ng[k] = len > 1e-30f ? (sf->front ? tri_n[k] : -tri_n[k]) / len : sf->n[k];
}

/* Section 1's direct terms of the renderer's lights at the hit, shadowed, without ambient and
 * emission. */
static void renderer_lights(const ref_scene *s, const ref_surface *sf, const float eye[3],
                            const float albedo[3], int first, float turn, ref_trace_stats *stats,
                            float out[3])
{
    out[0] = out[1] = out[2] = 0.0f;
    if (s->light_count == 0)
        return;
    float ng[3], vis[RD_MAX_LIGHTS];
    side_normal(sf, ng);
    /* Physical light casts shadows: hard ones where the scene has none, the GPU's soft taps at
     * the first vertex where it asks for them, one ray deeper down (the blur of bounced light
     * hides the difference). */
    rd_shadow_mode mode =
        first && s->shadows.mode == RD_SHADOWS_SOFT ? RD_SHADOWS_SOFT : RD_SHADOWS_HARD;
    ref_shadow_visibility_mode(s, mode, s->shadow_taps, sf->p, sf->n, ng, turn, vis, stats);
    rd_light lights[RD_MAX_LIGHTS];
    for (int i = 0; i < s->light_count; i++) {
        lights[i] = s->lights[i];
        for (int k = 0; k < 3; k++) {
            lights[i].diffuse[k] *= vis[i];
            lights[i].specular[k] *= vis[i];
        }
    }
    rd_material mat = sf->mesh->material;
    for (int k = 0; k < 3; k++)
        mat.emissive[k] = -FLT_MAX; /* max(-FLT_MAX, lit) = lit */
    static const float no_ambient[3] = {0.0f, 0.0f, 0.0f};
    rd_ref_shade(&mat, sf->mesh->texture || sf->mesh->object_positions ? albedo : NULL, sf->p,
                 sf->n, eye, lights, s->light_count, no_ambient, out);
}

/* Next-event estimation of the area lights through the lobes, MIS-weighted against the lobes'
 * own samples (unweighted at the `last` vertex, after which no lobe sample is traced). */
static void area_lights(const ref_scene *s, const ref_surface *sf, const lobes *b, const float v[3],
                        float u0, float u1, float u2, int last, ref_trace_stats *stats,
                        float out[3])
{
    out[0] = out[1] = out[2] = 0.0f;
    const ref_emitters *e = &s->emitters;
    if (!(e->total > 0.0))
        return;
    int i = pick_emitter(e, u0);
    const ref_mesh *m = &s->meshes[e->mesh[i]];
    const uint32_t *tri = m->indices + 3 * (size_t)e->prim[i];
    const float *p0 = m->positions + 3 * tri[0], *p1 = m->positions + 3 * tri[1],
                *p2 = m->positions + 3 * tri[2];
    /* A uniform point on the triangle (Shirley's square-root warp). */
    float su = sqrtf(u1), b0 = 1.0f - su, b1 = u2 * su;
    float q[3], d[3];
    for (int k = 0; k < 3; k++) {
        q[k] = b0 * p0[k] + b1 * p1[k] + (1.0f - b0 - b1) * p2[k];
        d[k] = q[k] - sf->p[k];
    }
    float dist = sqrtf(ref_dot(d, d));
    if (!(dist > 0.0f))
        return;
    float l[3] = {d[0] / dist, d[1] / dist, d[2] / dist};
    const float *tri_n = m->tri_normals + 3 * (size_t)e->prim[i];
    float cos_l = -ref_dot(tri_n, l) / sqrtf(ref_dot(tri_n, tri_n)); /* front side only */
    float f[3], pdf_lobes;
    lobes_eval(b, sf->n, v, l, f, &pdf_lobes);
    float nl = ref_dot(sf->n, l);
    float pdf_light = light_pdf(s, m, dist, cos_l);
    if (!(pdf_light > 0.0f) || !(nl > 0.0f) || !(f[0] + f[1] + f[2] > 0.0f))
        return;
    float ng[3], from[3];
    side_normal(sf, ng);
    for (int k = 0; k < 3; k++)
        from[k] = sf->p[k] + ng[k] * s->epsilon;
    if (!ref_segment_clear(s, from, q, stats))
        return;
    /* At the path's last vertex no lobe sample follows to count its share: all of it here. */
    float w = (last ? 1.0f : mis_weight(pdf_light, pdf_lobes)) * nl / pdf_light;
    for (int k = 0; k < 3; k++)
        out[k] = f[k] * m->emission[k] * w;
}

/* One path from (origin, dir) into out. */
static void trace_path(const ref_scene *s, const float origin[3], const float dir_in[3],
                       const ref_ray_diff *diff, int bounces, uint64_t key, float out[3],
                       int *reflective, ref_trace_stats *stats)
{
    float beta[3] = {1.0f, 1.0f, 1.0f}, sum[3] = {0.0f, 0.0f, 0.0f};
    float org[3], dir[3];
    memcpy(org, origin, sizeof org);
    memcpy(dir, dir_in, sizeof dir);
    unsigned skip_geom = RTC_INVALID_GEOMETRY_ID, skip_prim = RTC_INVALID_GEOMETRY_ID;
    int after_lobes = 0;   /* the last bounce sampled the lobes (not a reflection lookup) */
    int lobes_seen = 0;    /* a lobe was sampled on the way here: reflections now count */
    int used = 0;          /* bounces spent (the header's rule) */
    int free_events = 0;   /* mirror and glass events that spent none */
    float pdf_prev = 0.0f; /* its density, for the MIS weight of an emitter it hits */
    uint64_t dim = 0;      /* the next random number's index */
    for (int depth = 0;; depth++) {
        ref_surface sf;
        if (!ref_intersect(s, org, dir, depth ? s->epsilon : 0.0f, skip_geom, skip_prim, 0, &sf,
                           stats))
            break; /* the GPU clears to black: nothing outside the scene shines */
        const ref_mesh *m = sf.mesh;
        if (depth == 0)
            *reflective = m->reflective;
        /* A stand-in is seen by the camera and through mirrors and glass; after a lobe sample
         * its light came in already through the lights that carry it (is_area_light). */
        if (emitted_power(m) > 0.0f && sf.front && (is_area_light(m) || !after_lobes)) {
            float w = 1.0f;
            if (after_lobes) {
                const float *tri_n = m->tri_normals + 3 * (size_t)sf.prim;
                float cos_l = fabsf(ref_dot(tri_n, dir)) / sqrtf(ref_dot(tri_n, tri_n));
                w = mis_weight(pdf_prev, light_pdf(s, m, sf.t, cos_l));
            }
            for (int k = 0; k < 3; k++)
                sum[k] += beta[k] * m->emission[k] * w;
        }
        float v[3] = {-dir[0], -dir[1], -dir[2]};
        float albedo[3];
        ref_surface_albedo(s, &sf, org, dir, depth == 0 ? diff : NULL, albedo);

        /* lit.frag's blend is linear in the lit colour and the lookups: its weights per channel. */
        const rd_material *mat = &m->material;
        float w_lit[3] = {1.0f, 1.0f, 1.0f}, w_refl[3] = {0.0f, 0.0f, 0.0f};
        float tr = 0.0f;
        if (m->reflective) {
            static const float one[3] = {1.0f, 1.0f, 1.0f}, zero[3] = {0.0f, 0.0f, 0.0f};
            const float none[3] = {-FLT_MAX, -FLT_MAX, -FLT_MAX};
            float nv = ref_dot(sf.n, v), kr = clamp01(mat->reflectivity);
            rd_ref_blend((rd_blend_mode)mat->blend, kr, mat->specular, one, zero, nv, none, w_lit);
            rd_ref_blend((rd_blend_mode)mat->blend, kr, mat->specular, zero, one, nv, none, w_refl);
            tr = clamp01(mat->transparency);
        }
        float w_surface[3], w_trans[3];
        for (int k = 0; k < 3; k++) {
            w_surface[k] = w_lit[k] * (1.0f - tr);
            w_trans[k] = w_lit[k] * tr;
        }

        lobes b;
        for (int k = 0; k < 3; k++) {
            b.diffuse[k] = fmaxf(mat->diffuse[k] * albedo[k], 0.0f);
            b.specular[k] = fmaxf(mat->specular[k], 0.0f);
        }
        b.shininess = mat->shininess;
        float md = mean3(b.diffuse), ms = mean3(b.specular);
        b.p_glossy = md + ms > 0.0f ? ms / (md + ms) : 0.0f;

        /* Direct light on the surface's own lobes. */
        float direct[3], area[3];
        float turn = 2.0f * PI_F * ref_uniform01(key, dim++);
        renderer_lights(s, &sf, org, albedo, depth == 0, turn, stats, direct);
        float e0 = ref_uniform01(key, dim++), e1 = ref_uniform01(key, dim++),
              e2 = ref_uniform01(key, dim++);
        int last = used >= bounces || free_events >= MAX_FREE_EVENTS;
        area_lights(s, &sf, &b, v, e0, e1, e2, last, stats, area);
        for (int k = 0; k < 3; k++)
            sum[k] += beta[k] * w_surface[k] * (direct[k] + area[k]);
        if (last)
            break;

        /* The next bounce: one part of the surface, picked by its share of the weight. */
        float a_lobes = mean3(w_surface) * fminf(md + ms, 1.0f);
        float a_refl = mean3(w_refl), a_trans = mean3(w_trans);
        float a_total = a_lobes + a_refl + a_trans;
        if (!(a_total > 0.0f))
            break;
        float pick = ref_uniform01(key, dim++) * a_total;
        float u1 = ref_uniform01(key, dim++), u2 = ref_uniform01(key, dim++),
              u3 = ref_uniform01(key, dim++);
        float next[3];
        if (pick < a_lobes) {
            float p_part = a_lobes / a_total, f[3], pdf;
            if (!lobes_sample(&b, sf.n, v, u1, u2, u3, next))
                break;
            lobes_eval(&b, sf.n, v, next, f, &pdf);
            if (!(pdf > 0.0f))
                break;
            float nl = ref_dot(sf.n, next);
            for (int k = 0; k < 3; k++)
                beta[k] *= w_surface[k] * f[k] * nl / (pdf * p_part);
            after_lobes = 1;
            lobes_seen = 1;
            used++;
            pdf_prev = pdf;
        } else {
            int reflect = pick < a_lobes + a_refl;
            float p_part = (reflect ? a_refl : a_trans) / a_total;
            float axis[3], minus_v[3] = {dir[0], dir[1], dir[2]};
            const float *w = reflect ? w_refl : w_trans;
            float chosen[3] = {1.0f, 1.0f, 1.0f};
            if (reflect) {
                rd_ref_reflect(minus_v, sf.n, axis);
            } else if (m->double_sided) {
                memcpy(axis, minus_v, sizeof axis); /* a thin pane: straight through */
            } else {
                /* Dispersion: one channel's IOR a path, that channel weighted by 3. */
                float ior = mat->ior > 0.0f ? mat->ior : 1.5f;
                float disp = fmaxf(mat->dispersion, 0.0f);
                int ch = 1;
                if (disp > 0.0f) {
                    ch = (int)(u3 * 3.0f) % 3;
                    for (int k = 0; k < 3; k++)
                        chosen[k] = k == ch ? 3.0f : 0.0f;
                }
                float eta = 1.0f / (ior + ((float)ch - 1.0f) * 0.5f * disp);
                if (!rd_ref_refract(minus_v, sf.n, eta, axis))
                    rd_ref_reflect(minus_v, sf.n, axis); /* total internal reflection */
            }
            float len = sqrtf(ref_dot(axis, axis));
            if (!(len > 0.0f) || !isfinite(len))
                break;
            for (int k = 0; k < 3; k++)
                axis[k] /= len;
            gloss_direction(axis, mat->glossiness, u1, u2, next);
            for (int k = 0; k < 3; k++)
                beta[k] *= w[k] * chosen[k] / p_part;
            after_lobes = 0;
            if (reflect && lobes_seen)
                used++;
            else
                free_events++;
        }
        if (depth + 1 >= RR_START) {
            float q = fminf(fmaxf(beta[0], fmaxf(beta[1], beta[2])), 0.95f);
            if (!(ref_uniform01(key, dim++) < q))
                break;
            for (int k = 0; k < 3; k++)
                beta[k] /= q;
        }
        float len = sqrtf(ref_dot(next, next));
        if (!(len > 0.0f) || !isfinite(len))
            break;
        for (int k = 0; k < 3; k++) {
            org[k] = sf.p[k];
            dir[k] = next[k] / len;
        }
        skip_geom = sf.geom;
        skip_prim = sf.prim;
    }
    int finite = isfinite(sum[0]) && isfinite(sum[1]) && isfinite(sum[2]);
    for (int k = 0; k < 3; k++)
        out[k] = finite ? sum[k] : 0.0f; /* a NaN path is dropped, not spread over the image */
}

void ref_path_primary(const ref_scene *s, const float origin[3], const float dir[3],
                      const ref_ray_diff *diff, int bounces, int paths, uint64_t rng_key,
                      float out[3], int *reflective, ref_trace_stats *stats)
{
    double sum[3] = {0.0, 0.0, 0.0};
    *reflective = 0;
    for (int i = 0; i < paths; i++) {
        float c[3];
        int refl = 0;
        trace_path(s, origin, dir, diff, bounces,
                   ref_mix64(rng_key + 0x9E3779B97F4A7C15ull * (uint64_t)(i + 1)), c, &refl, stats);
        if (i == 0)
            *reflective = refl;
        for (int k = 0; k < 3; k++)
            sum[k] += c[k];
    }
    for (int k = 0; k < 3; k++)
        out[k] = (float)(sum[k] / (double)(paths > 0 ? paths : 1));
}
