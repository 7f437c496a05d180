/* One primary ray: first hit, direct light (RENDERING.md section 1, rd_ref_shade) and, on a
 * surface the GPU gives a probe, reflection and transmission traced into the real geometry and
 * blended as render/shaders/lit.frag blends its probe lookups (sections 2, 5, 6, 9). */
#include "ref_internal.h"

#include "render/cube_data.h"
#include "render/reflect_ref.h"
#include "render/shade_ref.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* The GPU asks for 8x anisotropic filtering of its textures (render/src/resources.c). */
#define REF_MAX_ANISO 8

/* An Embree intersect context that carries the tracer's rules to the filter below. */
typedef struct trace_ctx {
    struct RTCIntersectContext rtc; /* first: Embree hands the filter a pointer to it */
    const ref_scene *scene;
    unsigned skip_geom, skip_prim; /* the triangle a secondary ray leaves from */
    int secondary;                 /* reflected and transmitted rays do not see glass */
} trace_ctx;

/* Rejects what the GPU would not draw: back faces of closed meshes (culled), and for secondary
 * rays glass (probes skip it, draw.c) and the triangle the ray starts on. */
static void hit_filter(const struct RTCFilterFunctionNArguments *a)
{
    const trace_ctx *c = (const trace_ctx *)a->context;
    const float *ray = (const float *)a->ray;
    const unsigned *hit = (const unsigned *)a->hit;
    unsigned n = a->N;
    for (unsigned i = 0; i < n; i++) {
        if (a->valid[i] == 0)
            continue;
        unsigned prim = hit[5 * n + i], geom = hit[6 * n + i];
        const ref_mesh *m = &c->scene->meshes[geom];
        int reject = geom == c->skip_geom && prim == c->skip_prim;
        if (c->secondary && m->glass)
            reject = 1;
        if (!reject && !m->double_sided) {
            const float *ng = m->tri_normals + 3 * (size_t)prim;
            float d = ng[0] * ray[4 * n + i] + ng[1] * ray[5 * n + i] + ng[2] * ray[6 * n + i];
            reject = !(d < 0.0f); /* back-facing or edge-on: not rasterised */
        }
        if (reject)
            a->valid[i] = 0;
    }
}

typedef ref_surface surface;

int ref_intersect(const ref_scene *s, const float org[3], const float dir[3], float tnear,
                  unsigned skip_geom, unsigned skip_prim, int secondary, surface *out,
                  ref_trace_stats *stats)
{
    trace_ctx c;
    rtcInitIntersectContext(&c.rtc);
    c.rtc.filter = hit_filter;
    c.scene = s;
    c.skip_geom = skip_geom;
    c.skip_prim = skip_prim;
    c.secondary = secondary;
    struct RTCRayHit rh;
    memset(&rh, 0, sizeof rh);
    rh.ray.org_x = org[0];
    rh.ray.org_y = org[1];
    rh.ray.org_z = org[2];
    rh.ray.dir_x = dir[0];
    rh.ray.dir_y = dir[1];
    rh.ray.dir_z = dir[2];
    rh.ray.tnear = tnear;
    rh.ray.tfar = INFINITY;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(s->rtc, &c.rtc, &rh);
    if (stats)
        stats->rays++;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
        return 0;
    const ref_mesh *m = &s->meshes[rh.hit.geomID];
    const uint32_t *tri = m->indices + 3 * (size_t)rh.hit.primID;
    float b1 = rh.hit.u, b2 = rh.hit.v, b0 = 1.0f - b1 - b2;
    float n[3];
    for (int k = 0; k < 3; k++) {
        out->p[k] = b0 * m->positions[3 * tri[0] + (unsigned)k] +
                    b1 * m->positions[3 * tri[1] + (unsigned)k] +
                    b2 * m->positions[3 * tri[2] + (unsigned)k];
        n[k] = b0 * m->normals[3 * tri[0] + (unsigned)k] +
               b1 * m->normals[3 * tri[1] + (unsigned)k] +
               b2 * m->normals[3 * tri[2] + (unsigned)k];
    }
    for (int k = 0; k < 2; k++)
        out->uv[k] = b0 * m->uvs[2 * tri[0] + (unsigned)k] + b1 * m->uvs[2 * tri[1] + (unsigned)k] +
                     b2 * m->uvs[2 * tri[2] + (unsigned)k];
    if (m->object_positions)
        for (int k = 0; k < 3; k++)
            out->object_p[k] = b0 * m->object_positions[3 * tri[0] + (unsigned)k] +
                               b1 * m->object_positions[3 * tri[1] + (unsigned)k] +
                               b2 * m->object_positions[3 * tri[2] + (unsigned)k];
    out->mesh = m;
    out->geom = rh.hit.geomID;
    out->prim = rh.hit.primID;
    out->t = rh.ray.tfar;
    out->front = ref_dot(m->tri_normals + 3 * (size_t)rh.hit.primID, dir) < 0.0f;
    /* lit.frag: V = normalize(eye - P) (or +Z); N = normalize(n) (or V), negated on back faces. */
    float v[3] = {org[0] - out->p[0], org[1] - out->p[1], org[2] - out->p[2]};
    float v_len = sqrtf(ref_dot(v, v));
    float n_len = sqrtf(ref_dot(n, n));
    for (int k = 0; k < 3; k++) {
        v[k] = v_len > 0.0f ? v[k] / v_len : (k == 2 ? 1.0f : 0.0f);
        out->n[k] = n_len > 1e-20f ? n[k] / n_len : v[k];
        if (!out->front)
            out->n[k] = -out->n[k];
    }
    return 1;
}

/* A ray's two neighbours, one subpixel to the right and one below, carried as whole rays so that
 * a footprint survives a bounce (a ray differential, Igehy 1999, in finite form): on a mirror
 * they reflect about the normals interpolated where they meet the mirror's plane, as a probe
 * looked up with screen-space derivatives would be filtered. */
typedef struct ray_fan {
    int valid;
    float org_x[3], dir_x[3], org_y[3], dir_y[3];
} ray_fan;

/* Where the ray meets the plane of triangle `prim` ahead of its origin: the point and its
 * barycentric coordinates (it need not lie inside). 0 when it does not (parallel, behind). */
static int bary_on_plane(const ref_mesh *m, unsigned prim, const float org[3], const float dir[3],
                         float b[3], float p[3])
{
    const uint32_t *tri = m->indices + 3 * (size_t)prim;
    const float *p0 = m->positions + 3 * tri[0], *p1 = m->positions + 3 * tri[1],
                *p2 = m->positions + 3 * tri[2];
    const float *ng = m->tri_normals + 3 * (size_t)prim;
    float denom = ref_dot(dir, ng);
    if (!(fabsf(denom) > 0.0f))
        return 0;
    float w0[3] = {p0[0] - org[0], p0[1] - org[1], p0[2] - org[2]};
    float t = ref_dot(w0, ng) / denom;
    if (!(t > 0.0f) || !isfinite(t))
        return 0;
    float e1[3], e2[3], w[3];
    for (int k = 0; k < 3; k++) {
        p[k] = org[k] + t * dir[k];
        e1[k] = p1[k] - p0[k];
        e2[k] = p2[k] - p0[k];
        w[k] = p[k] - p0[k];
    }
    float d00 = ref_dot(e1, e1), d01 = ref_dot(e1, e2), d11 = ref_dot(e2, e2);
    float d20 = ref_dot(w, e1), d21 = ref_dot(w, e2);
    float det = d00 * d11 - d01 * d01;
    if (!(fabsf(det) > 0.0f))
        return 0;
    b[1] = (d11 * d20 - d01 * d21) / det;
    b[2] = (d00 * d21 - d01 * d20) / det;
    b[0] = 1.0f - b[1] - b[2];
    return isfinite(b[1]) && isfinite(b[2]);
}

/* Attribute `attr` (dim floats per vertex) of triangle `prim` at barycentrics b. */
static void interpolate(const ref_mesh *m, unsigned prim, const float *attr, int dim,
                        const float b[3], float *out)
{
    const uint32_t *tri = m->indices + 3 * (size_t)prim;
    for (int k = 0; k < dim; k++)
        out[k] = b[0] * attr[(size_t)dim * tri[0] + (size_t)k] +
                 b[1] * attr[(size_t)dim * tri[1] + (size_t)k] +
                 b[2] * attr[(size_t)dim * tri[2] + (size_t)k];
}

static int uv_on_plane(const ref_mesh *m, unsigned prim, const float org[3], const float dir[3],
                       float uv[2])
{
    float b[3], p[3];
    if (!bary_on_plane(m, prim, org, dir, b, p))
        return 0;
    interpolate(m, prim, m->uvs, 2, b, uv);
    return isfinite(uv[0]) && isfinite(uv[1]);
}

/* The ambient intensity at a surface of shading normal n: I_a, or with SH9 (section 7)
 * max(E(n), 0) / pi as lit.frag's SH9_AMBIENT variant; 0 while the SH capture itself is traced
 * (the GPU's first capture sees no coefficients yet). */
static void ambient_at(const ref_scene *s, const float n[3], float out[3])
{
    if (s->sh9_state == 0) {
        memcpy(out, s->ambient, 3 * sizeof(float));
        return;
    }
    out[0] = out[1] = out[2] = 0.0f;
    if (s->sh9_state != 3)
        return;
    rd_ref_sh9_irradiance(&s->sh9, n, out);
    for (int k = 0; k < 3; k++)
        out[k] = fmaxf(out[k], 0.0f) / 3.14159265f;
}

/* The diffuse texture at the hit (albedo 1 without one): over the footprint the ray's
 * neighbours span (the GPU's derivatives), else level 0. On tiles with joints (grout.glsl) the
 * texture is read clear of the joint band and *joint gets the band's share of the footprint. */
static void image_albedo(const ref_scene *s, const surface *sf, const float org[3],
                         const float dir[3], const ray_fan *fan, float albedo[3], float *joint)
{
    const ref_mesh *m = sf->mesh;
    albedo[0] = albedo[1] = albedo[2] = 1.0f;
    *joint = 0.0f;
    if (!m->texture)
        return;
    const float *jw = m->material.joint_width;
    int joints = jw[0] > 0.0f || jw[1] > 0.0f;
    const ref_texture *t = &s->textures[m->texture - 1];
    float uv[2] = {sf->uv[0] * m->uv_scale[0], sf->uv[1] * m->uv_scale[1]}, st[2];
    float base[2], ux[2], uy[2];
    int tw = t->mips[0].width, th = t->mips[0].height;
    if (fan && fan->valid && uv_on_plane(m, sf->prim, org, dir, base) &&
        uv_on_plane(m, sf->prim, fan->org_x, fan->dir_x, ux) &&
        uv_on_plane(m, sf->prim, fan->org_y, fan->dir_y, uy)) {
        float dx[2] = {(ux[0] - base[0]) * m->uv_scale[0], (ux[1] - base[1]) * m->uv_scale[1]};
        float dy[2] = {(uy[0] - base[0]) * m->uv_scale[0], (uy[1] - base[1]) * m->uv_scale[1]};
        float rho = fmaxf(hypotf(dx[0] * (float)tw, dx[1] * (float)th),
                          hypotf(dy[0] * (float)tw, dy[1] * (float)th));
        rd_ref_joint_texcoord(uv, jw, tw, th, rho, st);
        if (joints) /* grout.glsl: isotropic, at the footprint's larger axis */
            ref_texture_sample(t, st[0], st[1], log2f(fmaxf(rho, 1e-6f)), albedo);
        else
            ref_texture_sample_footprint(t, uv, dx, dy, REF_MAX_ANISO, albedo);
        float fw[2] = {fabsf(dx[0]) + fabsf(dy[0]), fabsf(dx[1]) + fabsf(dy[1])};
        *joint = joints ? rd_ref_joint_coverage(uv, jw, fw) : 0.0f;
    } else {
        rd_ref_joint_texcoord(uv, jw, tw, th, 0.0f, st);
        const float *at = joints ? st : uv;
        ref_texture_sample(t, at[0], at[1], 0.0f, albedo);
        *joint = joints ? rd_ref_joint_coverage(uv, jw, (const float[2]){0.0f, 0.0f}) : 0.0f;
    }
}

/* The texture times the wood grain (wood.glsl), sampled at the point: a pixel's many paths
 * average it, as the GPU's footprint fade does. */
static void texture_albedo(const ref_scene *s, const surface *sf, const float org[3],
                           const float dir[3], const ray_fan *fan, float albedo[3], float *joint)
{
    image_albedo(s, sf, org, dir, fan, albedo, joint);
    if (sf->mesh->material.pattern == RD_PATTERN_WOOD && sf->mesh->object_positions) {
        float dir[2], q[3];
        rd_ref_wood_grain_dir(sf->mesh->material.grain_angle_deg, dir);
        rd_ref_wood_grain_point(sf->object_p, dir, q);
        float grain = rd_ref_wood_grain(q, 0.0f);
        for (int k = 0; k < 3; k++)
            albedo[k] *= grain;
    }
}

void ref_surface_albedo(const ref_scene *s, const ref_surface *sf, const float org[3],
                        const float dir[3], const ref_ray_diff *diff, float out[3])
{
    ray_fan fan = {.valid = diff != NULL};
    if (diff)
        for (int k = 0; k < 3; k++) {
            fan.org_x[k] = fan.org_y[k] = org[k];
            fan.dir_x[k] = diff->dir_dx[k];
            fan.dir_y[k] = diff->dir_dy[k];
        }
    float joint;
    texture_albedo(s, sf, org, dir, &fan, out, &joint);
    /* lit.frag's c_d = mix(C_d x texture, joint colour, joint), as a factor on C_d. */
    const rd_material *mat = &sf->mesh->material;
    if (joint > 0.0f)
        for (int k = 0; k < 3; k++)
            out[k] =
                out[k] * (1.0f - joint) +
                (mat->diffuse[k] > 0.0f ? mat->joint_color[k] / mat->diffuse[k] : 0.0f) * joint;
}

/* Section 1 at a hit of the ray (org, dir), seen from `eye`. With the ray's neighbours the
 * texture is filtered over the footprint they span (the GPU's derivatives); without, level 0.
 * raw_lit = 1 leaves out the emissive max, which lit.frag applies only after the blend. */
static void shade_direct(const ref_scene *s, const surface *sf, const float eye[3],
                         const float org[3], const float dir[3], const ray_fan *fan, int raw_lit,
                         int shadowed, float shadow_turn, ref_trace_stats *stats, float out[3])
{
    const ref_mesh *m = sf->mesh;
    float albedo[3], joint = 0.0f;
    texture_albedo(s, sf, org, dir, fan, albedo, &joint);
    rd_material mat = m->material;
    if (joint > 0.0f) { /* lit.frag: c_a, c_d = mix(C x texture, joint colour, joint) */
        for (int k = 0; k < 3; k++) {
            mat.ambient[k] =
                mat.ambient[k] * albedo[k] * (1.0f - joint) + mat.joint_color[k] * joint;
            mat.diffuse[k] =
                mat.diffuse[k] * albedo[k] * (1.0f - joint) + mat.joint_color[k] * joint;
            albedo[k] = 1.0f;
        }
    }
    if (raw_lit)
        for (int k = 0; k < 3; k++)
            mat.emissive[k] = -FLT_MAX; /* max(-FLT_MAX, lit) = lit */
    const rd_light *lights = s->lights;
    rd_light dimmed[RD_MAX_LIGHTS];
    if (shadowed && s->shadows.mode != RD_SHADOWS_OFF) {
        /* Shadows scale each light's direct terms by the fraction of it that arrives. */
        /* The triangle's unit normal on the viewer's side, as n is (n where it is degenerate). */
        float vis[RD_MAX_LIGHTS], ng[3];
        const float *tri_n = m->tri_normals + 3 * (size_t)sf->prim;
        float len = sqrtf(ref_dot(tri_n, tri_n));
        for (int k = 0; k < 3; k++)
            ng[k] = len > 1e-30f ? (sf->front ? tri_n[k] : -tri_n[k]) / len : sf->n[k];
        ref_shadow_visibility(s, sf->p, sf->n, ng, shadow_turn, vis, stats);
        for (int i = 0; i < s->light_count; i++) {
            dimmed[i] = s->lights[i];
            for (int k = 0; k < 3; k++) {
                dimmed[i].diffuse[k] *= vis[i];
                dimmed[i].specular[k] *= vis[i];
            }
        }
        lights = dimmed;
    }
    float ambient[3];
    ambient_at(s, sf->n, ambient);
    rd_ref_shade(&mat, m->texture || m->object_positions ? albedo : NULL, sf->p, sf->n, eye, lights,
                 s->light_count, ambient, out);
}

typedef enum bounce { BOUNCE_REFLECT, BOUNCE_STRAIGHT, BOUNCE_REFRACT } bounce;

/* The direction a ray leaves `sf` in, by lit.frag's rules: from the view vector V (toward the
 * ray's origin) and the shading normal N, R = reflect(-V, N), T = -V through a thin sheet or
 * refract(-V, N, eta). 0 on total internal reflection. */
static int bounce_dir(bounce kind, const float v[3], const float n[3], float eta, float out[3])
{
    float minus_v[3] = {-v[0], -v[1], -v[2]};
    if (kind == BOUNCE_REFLECT) {
        rd_ref_reflect(minus_v, n, out);
        return 1;
    }
    if (kind == BOUNCE_STRAIGHT) {
        memcpy(out, minus_v, sizeof minus_v);
        return 1;
    }
    return rd_ref_refract(minus_v, n, eta, out);
}

/* One neighbour through the bounce: where it meets the surface's plane, the normal there
 * (lit.frag's rules: interpolated, normalised or V, flipped on a back face), its new ray. */
static int bounce_neighbour(const surface *sf, const float org[3], const float dir[3], bounce kind,
                            float eta, float new_org[3], float new_dir[3])
{
    float b[3], n[3], v[3];
    if (!bary_on_plane(sf->mesh, sf->prim, org, dir, b, new_org))
        return 0;
    interpolate(sf->mesh, sf->prim, sf->mesh->normals, 3, b, n);
    for (int k = 0; k < 3; k++)
        v[k] = org[k] - new_org[k];
    float v_len = sqrtf(ref_dot(v, v)), n_len = sqrtf(ref_dot(n, n));
    if (!(v_len > 0.0f))
        return 0;
    for (int k = 0; k < 3; k++) {
        v[k] /= v_len;
        n[k] = n_len > 1e-20f ? n[k] / n_len : v[k];
        if (!sf->front)
            n[k] = -n[k];
    }
    return bounce_dir(kind, v, n, eta, new_dir);
}

static void bounce_fan(const surface *sf, const ray_fan *in, bounce kind, float eta, ray_fan *out)
{
    out->valid = in && in->valid &&
                 bounce_neighbour(sf, in->org_x, in->dir_x, kind, eta, out->org_x, out->dir_x) &&
                 bounce_neighbour(sf, in->org_y, in->dir_y, kind, eta, out->org_y, out->dir_y);
}

/* What a probe would show in direction dir from the surface: the first non-glass surface, lit
 * by direct light only (one bounce: reflective objects appear plain in reflections), black on a
 * miss. fan: the ray's neighbours for texture filtering, or NULL. */
static void secondary_radiance(const ref_scene *s, const surface *from, const float dir[3],
                               const ray_fan *fan, float out[3], ref_trace_stats *stats)
{
    surface sf;
    if (!ref_intersect(s, from->p, dir, s->epsilon, from->geom, from->prim, 1, &sf, stats)) {
        out[0] = out[1] = out[2] = 0.0f;
        return;
    }
    shade_direct(s, &sf, from->p, from->p, dir, fan, 0, 0, 0.0f, stats, out);
}

/* splitmix64's finaliser: a well-mixed 64-bit hash. */
uint64_t ref_mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

float ref_uniform01(uint64_t key, uint64_t index)
{
    return (float)(ref_mix64(key + 0x9E3779B97F4A7C15ull * (index + 1)) >> 40) *
           (1.0f / 16777216.0f);
}

/* An orthonormal basis around unit a (Duff et al. 2017, "Building an orthonormal basis,
 * revisited"). */
void ref_basis(const float a[3], float t[3], float b[3])
{
    float sign = copysignf(1.0f, a[2]);
    float p = -1.0f / (sign + a[2]);
    float q = a[0] * a[1] * p;
    t[0] = 1.0f + sign * a[0] * a[0] * p;
    t[1] = sign * q;
    t[2] = -sign * a[0];
    b[0] = q;
    b[1] = sign + a[1] * a[1] * p;
    b[2] = -a[1];
}

/* The reflection (or transmission) along `axis` through the gloss lobe: one ray for a mirror;
 * else the mean of `samples` rays drawn from the normalised Phong lobe
 * ((n + 1) / 2 pi) cos^n around the axis, n = rd_ref_gloss_exponent(g) -- importance sampled,
 * so the estimate is a plain mean: cos = u^(1 / (n + 1)), phi = 2 pi v. u is stratified
 * ((k + jitter) / samples) and v a randomly shifted golden-ratio sequence, both keyed by `key`
 * alone, so a pixel's samples never depend on the thread that traces it. */
static void lobe_radiance(const ref_scene *s, const surface *from, const float axis_in[3],
                          const ray_fan *fan, float glossiness, int samples, uint64_t key,
                          float out[3], ref_trace_stats *stats)
{
    float axis[3] = {axis_in[0], axis_in[1], axis_in[2]};
    float len = sqrtf(ref_dot(axis, axis));
    if (!(len > 0.0f) || !isfinite(len)) {
        out[0] = out[1] = out[2] = 0.0f;
        return;
    }
    for (int k = 0; k < 3; k++)
        axis[k] /= len;
    if (glossiness >= 1.0f) {
        secondary_radiance(s, from, axis, fan, out, stats);
        return;
    }
    float n = rd_ref_gloss_exponent(glossiness);
    float inv = 1.0f / (n + 1.0f);
    float t[3], b[3];
    ref_basis(axis, t, b);
    float shift = ref_uniform01(key, 0xFFFFFFFFull);
    double sum[3] = {0, 0, 0};
    for (int i = 0; i < samples; i++) {
        float u = ((float)i + ref_uniform01(key, (uint64_t)i)) / (float)samples;
        double vd = (double)shift + (double)i * 0.6180339887498949; /* exact for large i */
        float v = (float)(vd - floor(vd));
        float cos_t = powf(fmaxf(1.0f - u, 1e-30f), inv);
        float sin_t = sqrtf(fmaxf(0.0f, 1.0f - cos_t * cos_t));
        float phi = 6.28318530718f * v;
        float cp = cosf(phi) * sin_t, sp = sinf(phi) * sin_t;
        float d[3];
        for (int k = 0; k < 3; k++)
            d[k] = cos_t * axis[k] + cp * t[k] + sp * b[k];
        float c[3];
        secondary_radiance(s, from, d, NULL, c, stats); /* the lobe blurs more than a pixel */
        for (int k = 0; k < 3; k++)
            sum[k] += c[k];
    }
    for (int k = 0; k < 3; k++)
        out[k] = (float)(sum[k] / samples);
}

static float clamp01(float x)
{
    return fminf(fmaxf(x, 0.0f), 1.0f); /* NaN -> 0, as the GPU's uniforms are set (draw.c) */
}

/* lit.frag's HAS_REFLECTION block, line for line, with every probe lookup replaced by a traced
 * lobe: reflection along R = reflect(-V, N); glass mixes in what lies behind (straight through a
 * double-sided sheet, refracted otherwise, per channel with dispersion, the reflected lookup on
 * total internal reflection) by its transparency; then the blend and the emissive max. `fan`:
 * the primary ray's neighbours (or NULL), bounced along for mirror and clear lookups. */
static void shade_reflective(const ref_scene *s, const surface *sf, const float eye[3],
                             const ray_fan *fan, const float lit_in[3], int samples, uint64_t key,
                             float out[3], ref_trace_stats *stats)
{
    const rd_material *m = &sf->mesh->material;
    float v[3] = {eye[0] - sf->p[0], eye[1] - sf->p[1], eye[2] - sf->p[2]};
    float v_len = sqrtf(ref_dot(v, v));
    for (int k = 0; k < 3; k++)
        v[k] = v_len > 0.0f ? v[k] / v_len : (k == 2 ? 1.0f : 0.0f);
    const float *n = sf->n;
    float g = m->glossiness, r[3], refl[3];
    bounce_dir(BOUNCE_REFLECT, v, n, 1.0f, r);
    ray_fan bounced = {0};
    if (g >= 1.0f)
        bounce_fan(sf, fan, BOUNCE_REFLECT, 1.0f, &bounced);
    lobe_radiance(s, sf, r, &bounced, g, samples, ref_mix64(key ^ 0x5EF1ull), refl, stats);
    float lit[3] = {lit_in[0], lit_in[1], lit_in[2]};
    float tr = clamp01(m->transparency);
    if (tr > 0.0f) {
        float ior = m->ior > 0.0f ? m->ior : 1.5f;
        float disp = fmaxf(m->dispersion, 0.0f);
        bounce kind = sf->mesh->double_sided ? BOUNCE_STRAIGHT : BOUNCE_REFRACT;
        float refr[3];
        for (int ch = 0; ch < 3; ch++) {
            float eta = 1.0f / (ior + ((float)ch - 1.0f) * 0.5f * disp);
            float t[3], c[3];
            if (!bounce_dir(kind, v, n, eta, t)) {
                memcpy(c, refl, sizeof c); /* total internal reflection: the reflected lookup */
            } else {
                bounced.valid = 0;
                if (g >= 1.0f)
                    bounce_fan(sf, fan, kind, eta, &bounced);
                lobe_radiance(s, sf, t, &bounced, g, samples,
                              ref_mix64(key ^ (0x7A11ull + (uint64_t)ch)), c, stats);
            }
            refr[ch] = c[ch];
            if (disp <= 0.0f) {
                memcpy(refr, c, sizeof refr);
                break;
            }
        }
        for (int k = 0; k < 3; k++)
            lit[k] = lit[k] * (1.0f - tr) + refr[k] * tr; /* GLSL mix */
    }
    rd_ref_blend((rd_blend_mode)m->blend, clamp01(m->reflectivity), m->specular, lit, refl,
                 ref_dot(n, v), m->emissive, out);
}

void ref_trace_primary(const ref_scene *s, const float origin[3], const float dir[3],
                       const ref_ray_diff *diff, int samples, uint64_t rng_key, float out[3],
                       int *reflective, ref_trace_stats *stats)
{
    surface sf;
    *reflective = 0;
    if (!ref_intersect(s, origin, dir, 0.0f, RTC_INVALID_GEOMETRY_ID, RTC_INVALID_GEOMETRY_ID, 0,
                       &sf, stats)) {
        out[0] = out[1] = out[2] = 0.0f; /* the GPU clears to black */
        return;
    }
    ray_fan fan = {.valid = diff != NULL};
    if (diff)
        for (int k = 0; k < 3; k++) {
            fan.org_x[k] = fan.org_y[k] = origin[k];
            fan.dir_x[k] = diff->dir_dx[k];
            fan.dir_y[k] = diff->dir_dy[k];
        }
    /* The soft-shadow disk's turn for this sample: uniform in [0, 2 pi) (ref_shadow.c). */
    float turn = 6.28318530718f * ref_uniform01(rng_key, 0x5AD0ull);
    if (!sf.mesh->reflective) {
        shade_direct(s, &sf, origin, origin, dir, &fan, 0, 1, turn, stats, out);
        return;
    }
    *reflective = 1;
    float lit[3];
    shade_direct(s, &sf, origin, origin, dir, &fan, 1, 1, turn, stats, lit);
    shade_reflective(s, &sf, origin, &fan, lit, samples, rng_key, out, stats);
}

int ref_scene_intersect(ref_scene *s, const float origin[3], const float dir[3], ref_hit *hit)
{
    if (!s || !origin || !dir || !hit) {
        ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_scene_intersect: missing argument");
        return 0;
    }
    if (ref_scene_commit(s) != REF_OK)
        return 0;
    float d[3] = {dir[0], dir[1], dir[2]};
    float len = sqrtf(ref_dot(d, d));
    if (!(len > 0.0f) || !isfinite(len))
        return 0;
    for (int k = 0; k < 3; k++)
        d[k] /= len;
    surface sf;
    if (!ref_intersect(s, origin, d, 0.0f, RTC_INVALID_GEOMETRY_ID, RTC_INVALID_GEOMETRY_ID, 0, &sf,
                       NULL))
        return 0;
    hit->t = sf.t;
    memcpy(hit->position, sf.p, sizeof hit->position);
    memcpy(hit->normal, sf.n, sizeof hit->normal);
    memcpy(hit->uv, sf.uv, sizeof hit->uv);
    hit->mesh = (int)sf.geom;
    hit->triangle = (int)sf.prim;
    hit->front = sf.front;
    return 1;
}

ref_result ref_trace_ray(ref_scene *s, const float origin[3], const float dir[3], int samples,
                         uint32_t seed, float out[3])
{
    if (!s || !origin || !dir || !out)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_trace_ray: missing argument");
    if (samples < 0)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_trace_ray: samples %d < 0", samples);
    ref_result r = ref_scene_commit(s);
    if (r == REF_OK)
        r = ref_ambient_prepare(s);
    if (r != REF_OK)
        return r;
    float d[3] = {dir[0], dir[1], dir[2]};
    float len = sqrtf(ref_dot(d, d));
    if (!(len > 0.0f) || !isfinite(len))
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_trace_ray: direction is zero");
    for (int k = 0; k < 3; k++)
        d[k] /= len;
    int reflective;
    ref_trace_primary(s, origin, d, NULL, samples ? samples : 64, ref_mix64(seed), out, &reflective,
                      NULL);
    return REF_OK;
}

/* The GPU's SH9 ambient (render/src/ambient_sh.c): a 32-texel cube capture at the proxy's
 * centre, box-filtered to 8 texels (two 2 x 2 mip steps = the mean of 4 x 4 texels), projected
 * on nine coefficients. Each texel is what the capture's rasteriser shows at its centre: the
 * first non-glass surface (secondary rays' rules), lit by direct light with ambient 0, its
 * emissive max, highlights seen from the centre; black where nothing is hit (the clear). */
enum { SH_CAPTURE = 32, SH_READ = 8 };

ref_result ref_ambient_prepare(ref_scene *s)
{
    if (s->sh9_state == 0 || s->sh9_state == 3)
        return REF_OK;
    rd_cube_data cube;
    if (rd_cube_data_alloc(SH_READ, &cube) != RD_OK)
        return ref_fail(REF_ERR_OUT_OF_MEMORY, "SH9 ambient: out of memory");
    s->sh9_state = 2;
    surface centre = {.geom = RTC_INVALID_GEOMETRY_ID, .prim = RTC_INVALID_GEOMETRY_ID};
    memcpy(centre.p, s->sh9_centre, sizeof centre.p);
    const int block = SH_CAPTURE / SH_READ;
    for (int f = 0; f < 6; f++)
        for (int j = 0; j < SH_CAPTURE; j++)
            for (int i = 0; i < SH_CAPTURE; i++) {
                float cmcs[3], dir[3], c[3];
                rd_ref_cube_face_direction(f, ((float)i + 0.5f) / SH_CAPTURE,
                                           ((float)j + 0.5f) / SH_CAPTURE, cmcs);
                rd_ref_cmcs_to_world(cmcs, dir);
                float len = sqrtf(ref_dot(dir, dir));
                for (int k = 0; k < 3; k++)
                    dir[k] /= len;
                secondary_radiance(s, &centre, dir, NULL, c, NULL);
                float *texel =
                    cube.faces[f] + 4 * ((size_t)(j / block) * SH_READ + (size_t)(i / block));
                for (int k = 0; k < 3; k++)
                    texel[k] += c[k] / (float)(block * block);
                texel[3] = 1.0f;
            }
    rd_ref_sh9_project(&cube, &s->sh9);
    rd_cube_data_free(&cube);
    s->sh9_state = 3;
    return REF_OK;
}
