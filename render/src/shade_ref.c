/* CPU twin of shaders/lit.frag: line for line the same formulas (seed 002 eqs. 1-7). */
#include "render/shade_ref.h"

#include <math.h>

static float dot3(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void normalize_or(const float v[3], const float fallback[3], float out[3])
{
    float len = sqrtf(dot3(v, v));
    for (int k = 0; k < 3; k++)
        out[k] = len > 1e-20f ? v[k] / len : fallback[k];
}

float rd_ref_blinn_phong_power(float n_dot_h, float n)
{
    if (!(n > 0.0f))
        return 1.0f; /* pow(x, 0) = 1, including pow(0, 0) */
    if (!(n_dot_h > 0.0f))
        return 0.0f;
    /* exp2(n log2 x): for x <= 1 the exponent is <= 0, so the result is in [0, 1]. */
    return exp2f(n * log2f(fminf(n_dot_h, 1.0f)));
}

static float spot_factor(float cos_angle, float inner_cos, float outer_cos)
{
    float t = (cos_angle - outer_cos) / fmaxf(inner_cos - outer_cos, 1e-6f);
    t = fminf(fmaxf(t, 0.0f), 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

void rd_ref_light_incidence(const rd_light *light, const float p[3], const float n[3], float l[3],
                            float *factor)
{
    if (light->type == RD_LIGHT_DIRECTIONAL) {
        for (int k = 0; k < 3; k++)
            l[k] = -light->direction[k];
        *factor = rd_ref_portal_factor(p, l, light);
        return;
    }
    float d[3] = {light->position[0] - p[0], light->position[1] - p[1], light->position[2] - p[2]};
    float dist = sqrtf(dot3(d, d));
    for (int k = 0; k < 3; k++)
        l[k] = dist > 0.0f ? d[k] / dist : n[k];
    if (light->type == RD_LIGHT_RECT) {
        /* As a point light at its centre of the same power: what probe captures draw. */
        *factor = rd_ref_rect_solid_angle(p, light) / 3.14159265f;
        return;
    }
    const float *a = light->attenuation;
    float k = 1.0f / fmaxf(a[0] + a[1] * dist + a[2] * dist * dist, 1e-4f);
    if (light->type == RD_LIGHT_SPOT) {
        float minus_l[3] = {-l[0], -l[1], -l[2]};
        k *= spot_factor(dot3(minus_l, light->direction), light->spot_inner_cos,
                         light->spot_outer_cos);
    }
    *factor = k;
}

/* A rectangle light's diffuse and specular terms (area_light_ref.c, docs/rendering.md). */
static void shade_rect(const rd_light *l, const rd_material *m, const float c_d[3],
                       const float p[3], const float n[3], const float v[3], float lit[3])
{
    float ff = rd_ref_rect_form_factor(p, n, l);
    if (!(ff > 0.0f))
        return;
    float n_dot_v = dot3(n, v), r[3], q[3];
    for (int k = 0; k < 3; k++)
        r[k] = 2.0f * n_dot_v * n[k] - v[k];
    rd_ref_rect_representative_point(p, r, l, q);
    float d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, lq[3], h_raw[3], h[3];
    normalize_or(d, n, lq);
    float spec = 0.0f;
    if (dot3(n, lq) > 0.0f) {
        for (int k = 0; k < 3; k++)
            h_raw[k] = lq[k] + v[k];
        normalize_or(h_raw, n, h);
        spec = rd_ref_blinn_phong_power(dot3(n, h), m->shininess) *
               rd_ref_rect_specular_solid_angle(rd_ref_rect_solid_angle(p, l), m->shininess) /
               3.14159265f;
    }
    for (int k = 0; k < 3; k++) {
        lit[k] += c_d[k] * l->diffuse[k] * ff;
        lit[k] += m->specular[k] * l->specular[k] * spec;
    }
}

void rd_ref_shade(const rd_material *m, const float albedo_scale[3], const float p[3],
                  const float n_in[3], const float eye[3], const rd_light *lights, int light_count,
                  const float ambient_light[3], float out[3])
{
    static const float up[3] = {0.0f, 0.0f, 1.0f};
    float v_raw[3] = {eye[0] - p[0], eye[1] - p[1], eye[2] - p[2]};
    float v[3], n[3];
    normalize_or(v_raw, up, v);
    normalize_or(n_in, v, n);

    float lit[3], c_d[3];
    for (int k = 0; k < 3; k++) {
        float s = albedo_scale ? albedo_scale[k] : 1.0f;
        lit[k] = m->ambient[k] * s * ambient_light[k]; /* eq. 1 */
        c_d[k] = m->diffuse[k] * s;
    }
    for (int i = 0; i < light_count; i++) {
        if (lights[i].type == RD_LIGHT_RECT) {
            shade_rect(&lights[i], m, c_d, p, n, v, lit);
            continue;
        }
        float l[3], factor;
        rd_ref_light_incidence(&lights[i], p, n, l, &factor);
        float n_dot_l = dot3(n, l);
        if (n_dot_l <= 0.0f)
            continue;
        float h_raw[3] = {l[0] + v[0], l[1] + v[1], l[2] + v[2]}, h[3];
        normalize_or(h_raw, n, h);
        float spec = rd_ref_blinn_phong_power(dot3(n, h), m->shininess);
        for (int k = 0; k < 3; k++) {
            lit[k] += factor * c_d[k] * lights[i].diffuse[k] * n_dot_l;       /* eq. 2 */
            lit[k] += factor * m->specular[k] * lights[i].specular[k] * spec; /* eqs. 3-5 */
        }
    }
    for (int k = 0; k < 3; k++)
        out[k] = fmaxf(m->emissive[k], lit[k]); /* eq. 7 */
}
