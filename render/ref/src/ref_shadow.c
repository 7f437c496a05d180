/* Shadow rays: the tracer's side of rd_scene_set_shadows (docs/reference.md, "Shadows"). Where
 * the GPU compares a tap's distance to the light with the nearest caster in the shadow map
 * (render/shaders/shadow.glsl), this file traces a ray from the same tap toward the light. The
 * taps are the same: a normal offset, then the Vogel disk (rd_shadow_disk_tap) of softness_m
 * in the receiver's plane, as many per sample, turned by a random angle per sample (the
 * GPU hashes the sample's position, this tracer its random key: the same kernel in
 * expectation); they differ otherwise only by the map's resolution and bias. */
#include "ref_internal.h"

#include <math.h>
#include <string.h>

typedef struct occlusion_ctx {
    struct RTCIntersectContext rtc; /* first: Embree hands the filter a pointer to it */
    const ref_scene *scene;
} occlusion_ctx;

/* What casts: everything the GPU's shadow pass draws -- not the room's enclosing surfaces, not
 * glass, not glowing (emissive) fixtures; both sides of a triangle. */
static void occlusion_filter(const struct RTCFilterFunctionNArguments *a)
{
    const occlusion_ctx *c = (const occlusion_ctx *)a->context;
    const unsigned *hit = (const unsigned *)a->hit;
    unsigned n = a->N;
    for (unsigned i = 0; i < n; i++) {
        if (a->valid[i] == 0)
            continue;
        const ref_mesh *m = &c->scene->meshes[hit[6 * n + i]];
        const float *e = m->material.emissive;
        if (m->background || m->glass || e[0] > 0.0f || e[1] > 0.0f || e[2] > 0.0f)
            a->valid[i] = 0;
    }
}

void ref_scene_set_shadows(ref_scene *s, const rd_shadow_settings *settings)
{
    if (s && settings) {
        s->shadows = rd_shadow_settings_resolve(settings);
        s->shadow_taps = rd_shadow_taps_per_sample(&s->shadows, 1);
    }
}

static int occluded(const ref_scene *s, const float org[3], const float dir[3], float tfar,
                    ref_trace_stats *stats)
{
    occlusion_ctx c;
    rtcInitIntersectContext(&c.rtc);
    c.rtc.filter = occlusion_filter;
    c.scene = s;
    struct RTCRay ray;
    memset(&ray, 0, sizeof ray);
    ray.org_x = org[0];
    ray.org_y = org[1];
    ray.org_z = org[2];
    ray.dir_x = dir[0];
    ray.dir_y = dir[1];
    ray.dir_z = dir[2];
    ray.tnear = s->epsilon;
    ray.tfar = tfar;
    ray.mask = 0xFFFFFFFFu;
    rtcOccluded1(s->rtc, &c.rtc, &ray);
    if (stats)
        stats->rays++;
    return ray.tfar < 0.0f; /* Embree sets tfar to -inf on a hit */
}

/* How far shadow-ray origins leave the triangle along its geometric normal, in the scene's ray
 * epsilons (ref_scene.c: 1e-5 of its diagonal), so 1e-3 of the diagonal: 4 mm in a 4 m room. */
#define SHADOW_LIFT_EPSILONS 100.0f

/* An orthonormal basis around unit a (Duff et al. 2017), as shadow.glsl builds it. */
static void basis(const float a[3], float t[3], float b[3])
{
    float sign = a[2] >= 0.0f ? 1.0f : -1.0f;
    float p = -1.0f / (sign + a[2]);
    float q = a[0] * a[1] * p;
    t[0] = 1.0f + sign * a[0] * a[0] * p;
    t[1] = sign * q;
    t[2] = -sign * a[0];
    b[0] = q;
    b[1] = sign + a[1] * a[1] * p;
    b[2] = -a[1];
}

/* Whether tap q sees light l. */
static float tap_visible(const ref_scene *s, const rd_light *l, const float q[3],
                         ref_trace_stats *stats)
{
    float d[3], tfar;
    if (l->type == RD_LIGHT_DIRECTIONAL) {
        for (int k = 0; k < 3; k++)
            d[k] = -l->direction[k];
        tfar = INFINITY;
    } else {
        for (int k = 0; k < 3; k++)
            d[k] = l->position[k] - q[k];
        float len = sqrtf(ref_dot(d, d));
        if (!(len > 0.0f))
            return 1.0f;
        for (int k = 0; k < 3; k++)
            d[k] /= len;
        tfar = len * (1.0f - 1e-4f); /* the light's own fixture surface does not count */
    }
    return occluded(s, q, d, tfar, stats) ? 0.0f : 1.0f;
}

void ref_shadow_visibility(const ref_scene *s, const float p[3], const float n[3],
                           const float ng[3], float rotation, float vis[RD_MAX_LIGHTS],
                           ref_trace_stats *stats)
{
    ref_shadow_visibility_mode(s, s->shadows.mode, s->shadow_taps, p, n, ng, rotation, vis, stats);
}

void ref_shadow_visibility_mode(const ref_scene *s, rd_shadow_mode mode, int soft_taps,
                                const float p[3], const float n[3], const float ng[3],
                                float rotation, float vis[RD_MAX_LIGHTS], ref_trace_stats *stats)
{
    for (int i = 0; i < RD_MAX_LIGHTS; i++)
        vis[i] = 1.0f;
    if (mode == RD_SHADOWS_OFF)
        return;
    int taps = mode == RD_SHADOWS_SOFT && soft_taps > 1 ? soft_taps : 1;
    /* The taps leave from the plane of the triangle that was hit, lifted off it along its
     * geometric normal, not from the tangent plane of the interpolated normal 4 ray epsilons
     * out. On a faceted curved surface (a basin's rim, a seat's torus) the interpolated normal
     * tilts by up to half a facet's angle from the triangle's, so a tap a few centimetres out
     * in its tangent plane lies up to softness * sin(tilt), millimetres, below the triangle,
     * inside the solid, and its ray meets the neighbouring facets; and a receiver beside a part
     * a millimetre or two proud of it (a wall round a mirror, a basin's rim round its bowl)
     * has taps under that part. Both are shadow acne: speckle and bands the GPU never shows,
     * because its lookups sit a texel off the surface and compare with a bias of 1.5 to 6
     * texels (shadow.glsl), 2 to 4 mm for a 1024-texel map a metre or two from its light. The
     * lift is of that scale, 1e-3 of the scene's diagonal (SHADOW_LIFT_EPSILONS ray epsilons,
     * ref_scene.c), and along the geometric normal, the one direction that leaves the
     * triangle's plane (Wächter and Binder 2019, "A fast and robust method for avoiding
     * self-intersection", Ray Tracing Gems ch. 6: offset a ray's origin along the geometric,
     * not the shading, normal). The disk keeps its radius and turn; only its plane follows the
     * triangle, a few degrees from the GPU's. */
    float t[3], b[3];
    basis(ng, t, b);
    float base[3];
    for (int k = 0; k < 3; k++)
        base[k] = p[k] + ng[k] * SHADOW_LIFT_EPSILONS * s->epsilon;
    for (int i = 0; i < s->light_count; i++) {
        const rd_light *l = &s->lights[i];
        float to_light[3];
        for (int k = 0; k < 3; k++)
            to_light[k] =
                l->type == RD_LIGHT_DIRECTIONAL ? -l->direction[k] : l->position[k] - p[k];
        if (!(ref_dot(to_light, n) > 0.0f))
            continue; /* unlit from behind anyway */
        float sum = 0.0f;
        for (int k = 0; k < taps; k++) {
            float q[3], disk[2] = {0.0f, 0.0f};
            if (taps > 1)
                rd_shadow_disk_tap(k, taps, rotation, disk);
            for (int c = 0; c < 3; c++)
                q[c] = base[c] + s->shadows.softness_m * (disk[0] * t[c] + disk[1] * b[c]);
            sum += tap_visible(s, l, q, stats);
        }
        vis[i] = sum / (float)taps;
    }
}

int ref_segment_clear(const ref_scene *s, const float p[3], const float q[3],
                      ref_trace_stats *stats)
{
    /* Every surface blocks an area light, glass and the room's walls included: the path's own
     * rays see them too, so the two halves of multiple importance sampling agree. */
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    float d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    float len = sqrtf(ref_dot(d, d));
    if (!(len > 2.0f * s->epsilon))
        return 1;
    struct RTCRay ray;
    memset(&ray, 0, sizeof ray);
    ray.org_x = p[0];
    ray.org_y = p[1];
    ray.org_z = p[2];
    ray.dir_x = d[0] / len;
    ray.dir_y = d[1] / len;
    ray.dir_z = d[2] / len;
    ray.tnear = s->epsilon;
    ray.tfar = len - s->epsilon;
    ray.mask = 0xFFFFFFFFu;
    rtcOccluded1(s->rtc, &ctx, &ray);
    if (stats)
        stats->rays++;
    return !(ray.tfar < 0.0f);
}
