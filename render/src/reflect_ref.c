/* CPU reference of the reflection formulas (RENDERING.md sections 2, 4, 5, 6, 9): the
 * definitions and their sources are in render/reflect_ref.h; the shaders compute the same. */
#include "render/reflect_ref.h"

#include <math.h>

#define PI_F 3.14159265358979f

static float dot3(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static int finite3(const float v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

static void copy3(const float a[3], float out[3])
{
    out[0] = a[0];
    out[1] = a[1];
    out[2] = a[2];
}

static float clamp01(float x)
{
    return fminf(fmaxf(x, 0.0f), 1.0f); /* fmaxf(NaN, 0) = 0 */
}

/* Section 2, seed 000 eq. 1. */
void rd_ref_reflect(const float i[3], const float n[3], float r[3])
{
    float k = 2.0f * dot3(n, i);
    float out[3] = {i[0] - k * n[0], i[1] - k * n[1], i[2] - k * n[2]};
    copy3(out, r);
}

/* Section 4, seed 002 eq. 10 in its exact form: intersect the reflected ray with a box proxy
 * and look up from the capture centre (box projection). */
int rd_ref_correct_box(const float p[3], const float r[3], const float bmin[3], const float bmax[3],
                       const float c[3], float d[3])
{
    float rr[3];
    copy3(r, rr);
    if (!finite3(p) || !finite3(r) || !finite3(bmin) || !finite3(bmax) || !finite3(c)) {
        copy3(rr, d);
        return 0;
    }
    for (int k = 0; k < 3; k++) {
        /* Degenerate box, or P outside the box or on its surface: no correction. */
        if (!(bmin[k] < bmax[k]) || !(bmin[k] < p[k] && p[k] < bmax[k])) {
            copy3(rr, d);
            return 0;
        }
    }
    /* The nudge keeps 0/0 out; x/1e-8 is large but harmless (the min picks another axis).
     * It only enters the divisions: D = P + t R - c uses the caller's R, as reflect.glsl does
     * (they differ by t * 1e-8 at most, except for R = 0, where D = P - c). */
    float rn[3], t = INFINITY;
    for (int k = 0; k < 3; k++) {
        rn[k] = fabsf(rr[k]) < 1e-8f ? copysignf(1e-8f, rr[k]) : rr[k];
        float t_max = (bmax[k] - p[k]) / rn[k], t_min = (bmin[k] - p[k]) / rn[k];
        t = fminf(t, fmaxf(t_max, t_min));
    }
    float out[3];
    for (int k = 0; k < 3; k++)
        out[k] = p[k] + t * rr[k] - c[k];
    /* D = 0 (R = 0 with P at c) is no direction: fall back, as reflect.glsl does. */
    if (!(t > 0.0f) || !finite3(out) || (out[0] == 0.0f && out[1] == 0.0f && out[2] == 0.0f)) {
        copy3(rr, d);
        return 0;
    }
    copy3(out, d);
    return 1;
}

/* Section 4, sphere proxy: |o + t R| = rad with o = P - c, i.e. a t^2 + 2 b t + q = 0 with
 * a = R.R, b = o.R, q = o.o - rad^2 < 0 (P inside), so the roots have opposite signs and the
 * positive one is (-b + sqrt(b^2 - a q)) / a, computed as -q / (b + sqrt(...)) when b > 0 to
 * avoid cancellation. */
int rd_ref_correct_sphere(const float p[3], const float r[3], const float c[3], float rad,
                          float d[3])
{
    float rr[3];
    copy3(r, rr);
    if (!finite3(p) || !finite3(r) || !finite3(c) || !isfinite(rad) || !(rad > 0.0f)) {
        copy3(rr, d);
        return 0;
    }
    double o[3] = {(double)p[0] - c[0], (double)p[1] - c[1], (double)p[2] - c[2]};
    double a = (double)rr[0] * rr[0] + (double)rr[1] * rr[1] + (double)rr[2] * rr[2];
    double b = o[0] * rr[0] + o[1] * rr[1] + o[2] * rr[2];
    double q = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - (double)rad * rad;
    if (!(q < 0.0) || !(a > 0.0)) {
        copy3(rr, d);
        return 0;
    }
    double root = sqrt(b * b - a * q);
    double t = b > 0.0 ? -q / (b + root) : (root - b) / a;
    float out[3];
    for (int k = 0; k < 3; k++)
        out[k] = (float)(o[k] + t * rr[k]);
    if (!(t > 0.0) || !finite3(out)) {
        copy3(rr, d);
        return 0;
    }
    copy3(out, d);
    return 1;
}

/* Section 5: the gloss -> Phong exponent mapping n = 2^(13 g) (RENDERING.md's example). */
float rd_ref_gloss_exponent(float g)
{
    return exp2f(13.0f * clamp01(g));
}

int rd_depth_search_steps(float g)
{
    const int mirror_steps = 32, fewest = 8;
    const float mirror_step = 0.0227f; /* radians: 1.3 degrees */
    g = clamp01(g);
    if (g >= 1.0f)
        return mirror_steps;
    float half_width = sqrtf(2.0f * 0.6931472f / rd_ref_gloss_exponent(g));
    float steps = ceilf((float)mirror_steps * mirror_step / half_width);
    return steps >= (float)mirror_steps ? mirror_steps
           : steps <= (float)fewest     ? fewest
                                        : (int)steps;
}

/* Section 5: the blur chain's levels are matched to their resolution (docs/history.md,
 * "Reflections"): level k >= 1 of a chain of `levels` levels (a probe of 2^(levels - 1) texels)
 * holds the Phong lobe whose half-width sqrt(2 ln 2 / n) spans LOBE_TEXELS texels of that level (a
 * face spans pi/2), n clamped to [1, n(1) = 8192]; level 0 is the capture (the mirror). A
 * lobe narrower than its level's texels is widened by the bilinear lookup, which let a bright
 * window bleed far beyond the lobe of a small probe's coarse levels. */
#define LOBE_TEXELS 2.0f

static float level_half_width(float level, int levels)
{
    return LOBE_TEXELS * 0.5f * PI_F * exp2f(level - (float)(levels - 1));
}

float rd_ref_gloss_lod(float g, int levels)
{
    if (levels < 1)
        levels = 1;
    g = clamp01(g);
    if (g >= 1.0f)
        return 0.0f;
    float half_width = sqrtf(2.0f * 0.6931472f / rd_ref_gloss_exponent(g));
    float lod = log2f(half_width / level_half_width(0.0f, levels));
    return fminf(fmaxf(lod, 0.0f), (float)(levels - 1));
}

/* Section 5, seed 001 eq. 6 with the normalisation of the Phong lobe. */
float rd_ref_lobe(float cos_angle, float n)
{
    if (!(cos_angle > 0.0f))
        return 0.0f;
    n = fminf(fmaxf(n, 0.0f), 1e6f);
    float c = fminf(cos_angle, 1.0f);
    /* exp2(n log2 c): the exponent is <= 0, so the power is in [0, 1]. */
    return (n + 1.0f) / (2.0f * PI_F) * exp2f(n * log2f(c));
}

float rd_ref_level_exponent(int level, int levels)
{
    if (levels <= 1 || level <= 0)
        return rd_ref_gloss_exponent(1.0f);
    if (level > levels - 1)
        level = levels - 1;
    float w = level_half_width((float)level, levels);
    return fminf(fmaxf(2.0f * 0.6931472f / (w * w), 1.0f), rd_ref_gloss_exponent(1.0f));
}

/* Section 6, seed 001 eq. 15 (Schlick 1994 with N.V in place of H.V). */
float rd_ref_fresnel(float f0, float n_dot_v)
{
    float f = clamp01(f0);
    float m = 1.0f - clamp01(n_dot_v);
    float m2 = m * m;
    return f + (1.0f - f) * (m2 * m2 * m);
}

/* GLSL's max(e, c) ("y if x < y, otherwise x"), which fixes what fmaxf leaves open: a tie of
 * +0 and -0 gives e. A NaN on one side gives the other side. */
static float max_emissive(float e, float c)
{
    if (isnan(e))
        return c;
    return e < c ? c : e;
}

/* Section 6: mix (seed 002), add (seed 000 eq. 3), fresnel (seed 001 eq. 7), then the
 * emissive max of seed 002 eq. 7. */
void rd_ref_blend(rd_blend_mode mode, float kr, const float specular[3], const float lit[3],
                  const float refl[3], float n_dot_v, const float emissive[3], float out[3])
{
    float k = clamp01(kr);
    float f = mode == RD_BLEND_FRESNEL ? rd_ref_fresnel(k, n_dot_v) : 0.0f;
    float res[3];
    for (int ch = 0; ch < 3; ch++) {
        float c;
        if (mode == RD_BLEND_FRESNEL)
            c = (1.0f - f) * lit[ch] + f * refl[ch];
        else if (k == 0.0f)
            c = lit[ch]; /* the formulas' value at kr = 0, exactly section 1 */
        else if (mode == RD_BLEND_ADD)
            c = lit[ch] + k * specular[ch] * refl[ch];
        else
            c = (1.0f - k) * lit[ch] + k * refl[ch];
        res[ch] = max_emissive(emissive[ch], c);
    }
    copy3(res, out);
}

/* Section 9, seed 003: GLSL's refract. */
int rd_ref_refract(const float i[3], const float n[3], float eta, float t[3])
{
    float ni = dot3(n, i);
    float k = 1.0f - eta * eta * (1.0f - ni * ni);
    if (!finite3(i) || !finite3(n) || !isfinite(eta) || !(k >= 0.0f)) {
        t[0] = t[1] = t[2] = 0.0f;
        return 0;
    }
    float m = eta * ni + sqrtf(k);
    float out[3] = {eta * i[0] - m * n[0], eta * i[1] - m * n[1], eta * i[2] - m * n[2]};
    if (!finite3(out)) {
        t[0] = t[1] = t[2] = 0.0f;
        return 0;
    }
    copy3(out, t);
    return 1;
}
