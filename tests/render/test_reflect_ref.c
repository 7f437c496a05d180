/* The CPU reference of the reflection formulas (RENDERING.md sections 2, 4-6, 9, 11) against
 * hand-computed values, their invariants (lobe normalisation, brightness conservation, Snell's
 * law, inverse sphere-map mappings) and the numerical extremes of section 11. */
#include "../common/check.h"
#include "render/reflect_ref.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#define PI 3.14159265358979323846

static int near(float a, float b, float tol)
{
    return fabsf(a - b) <= tol;
}

static int near3(const float a[3], float x, float y, float z, float tol)
{
    return near(a[0], x, tol) && near(a[1], y, tol) && near(a[2], z, tol);
}

static int finite3(const float v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

static unsigned rng_state = 2024u;
static float rnd(void) /* [0, 1) */
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (float)(rng_state >> 8) / (float)(1u << 24);
}

/* ---- section 2 ------------------------------------------------------------------------ */

static void test_reflect(void)
{
    const float h = 0.70710678f;
    float i[3] = {h, -h, 0}, n[3] = {0, 1, 0}, r[3];
    rd_ref_reflect(i, n, r);
    CHECK(near3(r, h, h, 0, 1e-7f));
    float i2[3] = {0.3f, 0.4f, -0.8660254f}, n2[3] = {0, 0, 1};
    rd_ref_reflect(i2, n2, r);
    CHECK(near3(r, 0.3f, 0.4f, 0.8660254f, 1e-7f));
    /* Generic: R.N = -I.N, |R| = |I|; in place. */
    float n3[3] = {0.48f, 0.6f, 0.64f}, i3[3] = {-0.2f, 0.9f, -0.3f};
    rd_ref_reflect(i3, n3, r);
    float in = i3[0] * n3[0] + i3[1] * n3[1] + i3[2] * n3[2];
    CHECK(near(r[0] * n3[0] + r[1] * n3[1] + r[2] * n3[2], -in, 1e-6f));
    CHECK(near(r[0] * r[0] + r[1] * r[1] + r[2] * r[2],
               i3[0] * i3[0] + i3[1] * i3[1] + i3[2] * i3[2], 1e-6f));
    float same[3] = {i3[0], i3[1], i3[2]};
    rd_ref_reflect(same, n3, same);
    CHECK(memcmp(same, r, sizeof r) == 0);
}

/* ---- section 4 ------------------------------------------------------------------------ */

static void test_correct_box(void)
{
    /* A 2 x 3 x 2.5 room with its capture centre in the middle. */
    const float bmin[3] = {0, 0, 0}, bmax[3] = {2, 3, 2.5f}, c[3] = {1, 1.5f, 1.25f};
    const float p[3] = {0.5f, 1, 1};
    float d[3];

    /* Axis-aligned: the hit is on the x = 2 wall at (2, 1, 1). Zero components of R are
     * nudged, no NaN. */
    float rx[3] = {1, 0, 0};
    CHECK(rd_ref_correct_box(p, rx, bmin, bmax, c, d) == 1);
    CHECK_MSG(near3(d, 1, -0.5f, -0.25f, 1e-5f), "+x: %g %g %g", d[0], d[1], d[2]);
    float rnx[3] = {-1, -0.0f, 0}; /* -0: nudged to -1e-8 */
    CHECK(rd_ref_correct_box(p, rnx, bmin, bmax, c, d) == 1);
    CHECK_MSG(near3(d, -1, -0.5f, -0.25f, 1e-5f), "-x: %g %g %g", d[0], d[1], d[2]);
    float ry[3] = {0, 1, 0};
    CHECK(rd_ref_correct_box(p, ry, bmin, bmax, c, d) == 1);
    CHECK(near3(d, -0.5f, 1.5f, -0.25f, 1e-5f));
    float rz[3] = {0, 0, -2}; /* not unit: t scales, D does not */
    CHECK(rd_ref_correct_box(p, rz, bmin, bmax, c, d) == 1);
    CHECK(near3(d, -0.5f, -0.5f, -1.25f, 1e-5f));

    /* Oblique: R = (1, 2, 2)/3: t = min(4.5, 3, 2.25) = 2.25, hit (1.25, 2.5, 2.5). */
    float ro[3] = {1.0f / 3, 2.0f / 3, 2.0f / 3};
    CHECK(rd_ref_correct_box(p, ro, bmin, bmax, c, d) == 1);
    CHECK_MSG(near3(d, 0.25f, 1.0f, 1.25f, 1e-5f), "oblique: %g %g %g", d[0], d[1], d[2]);
    /* R = (-2, 1, -2)/3: t = min(0.75, 6, 1.5) = 0.75, hit (0, 1.25, 0.5). */
    float ro2[3] = {-2.0f / 3, 1.0f / 3, -2.0f / 3};
    CHECK(rd_ref_correct_box(p, ro2, bmin, bmax, c, d) == 1);
    CHECK_MSG(near3(d, -1, -0.25f, -0.75f, 1e-5f), "oblique 2: %g %g %g", d[0], d[1], d[2]);

    /* R with zero components, R = 0, R parallel to a face with P right next to it: finite. */
    float zero[3] = {0, 0, 0};
    /* R = 0: nudged in the divisions only (t = 1.5e8), so D = P + t 0 - c = P - c. */
    CHECK(rd_ref_correct_box(p, zero, bmin, bmax, c, d) == 1);
    CHECK_MSG(finite3(d) && near3(d, -0.5f, -0.5f, -0.25f, 0), "R = 0: %g %g %g", d[0], d[1], d[2]);
    /* ... and with P at c that is no direction: the fallback. */
    CHECK(rd_ref_correct_box(c, zero, bmin, bmax, c, d) == 0 && near3(d, 0, 0, 0, 0));
    float near_wall[3] = {1.99999f, 1, 1}, along[3] = {0, 0, 1};
    CHECK(rd_ref_correct_box(near_wall, along, bmin, bmax, c, d) == 1);
    CHECK(finite3(d) && near(d[2], 1.25f, 1e-5f) && near(d[0], 0.99999f, 1e-5f));

    /* P at the centre: D = t R. */
    float up[3] = {0, 0, 1};
    CHECK(rd_ref_correct_box(c, up, bmin, bmax, c, d) == 1);
    CHECK(near3(d, 0, 0, 1.25f, 1e-6f));

    /* Fallbacks: outside, on the surface, degenerate or inverted box, non-finite input. */
    float outside[3] = {5, 1, 1}, surface[3] = {0, 1, 1};
    CHECK(rd_ref_correct_box(outside, ro, bmin, bmax, c, d) == 0 && memcmp(d, ro, sizeof d) == 0);
    CHECK(rd_ref_correct_box(surface, ro, bmin, bmax, c, d) == 0 && memcmp(d, ro, sizeof d) == 0);
    float flat_max[3] = {2, 3, 0}, inv_min[3] = {0, 4, 0};
    CHECK(rd_ref_correct_box(p, ro, bmin, flat_max, c, d) == 0 && memcmp(d, ro, sizeof d) == 0);
    CHECK(rd_ref_correct_box(p, ro, inv_min, bmax, c, d) == 0);
    float nanp[3] = {NAN, 1, 1}, infr[3] = {INFINITY, 0, 0};
    CHECK(rd_ref_correct_box(nanp, ro, bmin, bmax, c, d) == 0 && memcmp(d, ro, sizeof d) == 0);
    CHECK(rd_ref_correct_box(p, infr, bmin, bmax, c, d) == 0);

    /* Scenes from 1 mm to 10 km. */
    float kmin[3] = {-5000, -5000, 0}, kmax[3] = {5000, 5000, 10000}, kc[3] = {0, 0, 5000};
    float kp[3] = {0.001f, -0.001f, 1}, kr[3] = {0.3f, 0, 0.9f};
    CHECK(rd_ref_correct_box(kp, kr, kmin, kmax, kc, d) == 1 && finite3(d));
    float mmin[3] = {0, 0, 0}, mmax[3] = {0.001f, 0.001f, 0.001f},
          mc[3] = {0.0005f, 0.0005f, 0.0005f};
    float mp[3] = {0.0002f, 0.0007f, 0.0005f};
    CHECK(rd_ref_correct_box(mp, kr, mmin, mmax, mc, d) == 1 && finite3(d));

    /* In place (d aliases r). */
    float alias[3] = {1, 0, 0};
    CHECK(rd_ref_correct_box(p, alias, bmin, bmax, c, alias) == 1);
    CHECK(near3(alias, 1, -0.5f, -0.25f, 1e-5f));
}

static void test_correct_sphere(void)
{
    const float c[3] = {0, 0, 0}, p[3] = {1, 0, 0};
    float d[3];
    float rx[3] = {1, 0, 0}, rnx[3] = {-1, 0, 0}, ry[3] = {0, 2, 0};
    CHECK(rd_ref_correct_sphere(p, rx, c, 2, d) == 1 && near3(d, 2, 0, 0, 1e-6f));
    CHECK(rd_ref_correct_sphere(p, rnx, c, 2, d) == 1 && near3(d, -2, 0, 0, 1e-6f));
    /* |(1, t, 0)| = 2 -> the hit is (1, sqrt 3, 0), whatever the length of R. */
    CHECK(rd_ref_correct_sphere(p, ry, c, 2, d) == 1 && near3(d, 1, 1.7320508f, 0, 1e-6f));
    /* Off-centre sphere, P at its centre: D = rad R / |R|. */
    float c2[3] = {10, 20, 30}, r3[3] = {0, 0, 3};
    CHECK(rd_ref_correct_sphere(c2, r3, c2, 1.5f, d) == 1 && near3(d, 0, 0, 1.5f, 1e-6f));
    /* |D| = rad for random inside points and directions. */
    for (int k = 0; k < 200; k++) {
        float q[3] = {rnd() - 0.5f, rnd() - 0.5f, rnd() - 0.5f};
        float r[3] = {rnd() - 0.5f, rnd() - 0.5f, rnd() - 0.5f};
        CHECK(rd_ref_correct_sphere(q, r, c, 1.0f, d) == 1);
        CHECK(near(sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), 1.0f, 1e-5f));
        /* D - (P - c) is along R, forwards. */
        float e[3] = {d[0] - q[0], d[1] - q[1], d[2] - q[2]};
        CHECK(e[0] * r[0] + e[1] * r[1] + e[2] * r[2] > 0.0f);
    }
    /* Fallbacks. */
    float out[3] = {3, 0, 0}, on[3] = {2, 0, 0}, zero[3] = {0, 0, 0}, nan3[3] = {0, NAN, 0};
    CHECK(rd_ref_correct_sphere(out, rx, c, 2, d) == 0 && memcmp(d, rx, sizeof d) == 0);
    CHECK(rd_ref_correct_sphere(on, rnx, c, 2, d) == 0 && memcmp(d, rnx, sizeof d) == 0);
    CHECK(rd_ref_correct_sphere(p, rx, c, 0, d) == 0);
    CHECK(rd_ref_correct_sphere(p, rx, c, -1, d) == 0);
    CHECK(rd_ref_correct_sphere(p, rx, c, NAN, d) == 0);
    CHECK(rd_ref_correct_sphere(p, zero, c, 2, d) == 0 && finite3(d));
    CHECK(rd_ref_correct_sphere(p, nan3, c, 2, d) == 0);
    CHECK(rd_ref_correct_sphere(nan3, rx, c, 2, d) == 0 && memcmp(d, rx, sizeof d) == 0);
}

/* ---- section 5 ------------------------------------------------------------------------ */

static void test_gloss(void)
{
    CHECK(rd_ref_gloss_exponent(0.0f) == 1.0f);
    CHECK(rd_ref_gloss_exponent(1.0f) == 8192.0f);
    CHECK(near(rd_ref_gloss_exponent(0.5f), 90.50967f, 1e-3f));
    float lo = rd_ref_gloss_exponent(1e-6f), hi = rd_ref_gloss_exponent(1.0f - 1e-6f);
    CHECK(isfinite(lo) && lo >= 1.0f && lo < 1.001f);
    CHECK(isfinite(hi) && hi <= 8192.0f && hi > 8190.0f);
    CHECK(rd_ref_gloss_exponent(-1.0f) == 1.0f && rd_ref_gloss_exponent(2.0f) == 8192.0f);
    CHECK(rd_ref_gloss_exponent(NAN) == 1.0f);

    /* A level's lobe spans two of its texels (reflect_ref.c): at 128 texels (8 levels) the
     * half-width of level k is 2 (pi / 2) 2^k / 128, so g = 0 (n = 1, half-width 1.1774)
     * lands on log2(1.1774 / (pi / 128)) = 5.584 and g = 0.5 (n = 90.5) on 2.334. */
    CHECK(rd_ref_gloss_lod(1.0f, 8) == 0.0f && near(rd_ref_gloss_lod(0.0f, 8), 5.584f, 1e-3f));
    CHECK(near(rd_ref_gloss_lod(0.5f, 8), 2.334f, 1e-3f));
    CHECK(isfinite(rd_ref_gloss_lod(1e-6f, 8)) && isfinite(rd_ref_gloss_lod(1 - 1e-6f, 8)));
    CHECK(rd_ref_gloss_lod(0.3f, 0) == 0.0f && rd_ref_gloss_lod(0.3f, 1) == 0.0f);
    CHECK(rd_ref_gloss_lod(NAN, 8) == rd_ref_gloss_lod(0.0f, 8));
    for (int i = 1; i <= 100; i++) /* blurrier lobes, coarser levels */
        CHECK(rd_ref_gloss_lod((i - 1) / 100.0f, 8) >= rd_ref_gloss_lod(i / 100.0f, 8));
    CHECK(rd_ref_gloss_lod(0.2f, 12) > rd_ref_gloss_lod(0.2f, 8)); /* finer probes: more levels */

    /* Level k of the chain is the lobe of the g whose LOD is k (where n is not clamped). */
    CHECK(rd_ref_level_exponent(0, 8) == 8192.0f && rd_ref_level_exponent(7, 8) == 1.0f);
    for (int k = 1; k < 8; k++) {
        float n = rd_ref_level_exponent(k, 8);
        float w = 2.0f * 1.5707963f * exp2f((float)k) / 128.0f;
        CHECK(near(n, fminf(fmaxf(2.0f * 0.6931472f / (w * w), 1.0f), 8192.0f), 1e-3f * n));
        CHECK(n <= rd_ref_level_exponent(k - 1, 8));
        if (n > 1.0f && n < 8192.0f)
            CHECK(near(rd_ref_gloss_lod(log2f(n) / 13.0f, 8), (float)k, 1e-3f));
    }
    CHECK(rd_ref_level_exponent(-2, 8) == 8192.0f && rd_ref_level_exponent(99, 8) == 1.0f);
    CHECK(rd_ref_level_exponent(0, 1) == 8192.0f && rd_ref_level_exponent(3, 0) == 8192.0f);
}

/* The depth search's steps (rd_depth_search_steps): 32 for a mirror and the sharp chrome whose
 * lobe is narrower than a mirror's step, fewer as the lobe widens, never below 8, monotone. */
static void test_depth_steps(void)
{
    CHECK(rd_depth_search_steps(1.0f) == 32 && rd_depth_search_steps(0.9f) == 32);
    CHECK(rd_depth_search_steps(0.8f) == 23); /* half-width 0.0313 rad: ceil(32 * 0.0227 / it) */
    CHECK(rd_depth_search_steps(0.6f) == 10);
    CHECK(rd_depth_search_steps(0.0f) == 8 && rd_depth_search_steps(0.35f) == 8);
    CHECK(rd_depth_search_steps(NAN) == 8 && rd_depth_search_steps(2.0f) == 32);
    for (int i = 1; i <= 100; i++)
        CHECK(rd_depth_search_steps((i - 1) / 100.0f) <= rd_depth_search_steps(i / 100.0f));
}

static void test_lobe(void)
{
    CHECK(rd_ref_lobe(0.0f, 8) == 0.0f && rd_ref_lobe(-0.5f, 8) == 0.0f);
    CHECK(rd_ref_lobe(NAN, 8) == 0.0f);
    CHECK(near(rd_ref_lobe(1.0f, 8), 9.0f / (2.0f * (float)PI), 1e-6f));
    CHECK(near(rd_ref_lobe(0.5f, 2), 3.0f / (2.0f * (float)PI) * 0.25f, 1e-6f));
    CHECK(near(rd_ref_lobe(1.5f, 8), rd_ref_lobe(1.0f, 8), 0)); /* cos above 1 */
    CHECK(isfinite(rd_ref_lobe(0.999f, 1e6f)) && isfinite(rd_ref_lobe(1.0f, 1e9f)));
    CHECK(isfinite(rd_ref_lobe(0.5f, NAN)) && isfinite(rd_ref_lobe(0.5f, -3)));

    /* The lobe integrates to 1 over the hemisphere: 2 pi int_0^{pi/2} lobe(cos th) sin th. */
    const float ns[4] = {1, 8, 64, 1024};
    for (int k = 0; k < 4; k++) {
        const int steps = 200000;
        double sum = 0.0, h = (PI / 2) / steps;
        for (int q = 0; q < steps; q++) {
            double th = (q + 0.5) * h;
            sum += rd_ref_lobe((float)cos(th), ns[k]) * sin(th) * h;
        }
        sum *= 2 * PI;
        CHECK_MSG(fabs(sum - 1.0) < 0.01, "n = %g: integral %g", ns[k], sum);
    }
    /* The same over the texels of a cube map (exact solid angles), lobe on a face centre. */
    const float ns_cube[3] = {1, 8, 64};
    for (int k = 0; k < 3; k++) {
        const int size = 64;
        double sum = 0.0;
        for (int f = 0; f < 6; f++)
            for (int j = 0; j < size; j++)
                for (int i = 0; i < size; i++) {
                    float d[3];
                    rd_ref_cube_face_direction(f, (i + 0.5f) / size, (j + 0.5f) / size, d);
                    float len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                    sum +=
                        rd_ref_lobe(d[2] / len, ns_cube[k]) * rd_ref_texel_solid_angle(i, j, size);
                }
        CHECK_MSG(fabs(sum - 1.0) < 0.01, "n = %g over a cube: integral %g", ns_cube[k], sum);
    }
}

static void test_solid_angle(void)
{
    const int sizes[5] = {1, 2, 7, 64, 512};
    for (int k = 0; k < 5; k++) {
        int n = sizes[k];
        double sum = 0.0;
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++)
                sum += rd_ref_texel_solid_angle(i, j, n);
        CHECK_MSG(fabs(6 * sum - 4 * PI) < 1e-4, "size %d: total %g", n, 6 * sum);
    }
    CHECK(near(rd_ref_texel_solid_angle(0, 0, 1), (float)(4 * PI / 6), 1e-6f));
    /* A centre texel of a fine face is nearly (2/n)^2; a corner one is smaller by ~3^(3/2). */
    float centre = rd_ref_texel_solid_angle(256, 256, 512),
          corner = rd_ref_texel_solid_angle(0, 0, 512);
    CHECK(near(centre, (2.0f / 512) * (2.0f / 512), 1e-9f));
    CHECK(near(centre / corner, 5.196f, 0.05f));
    CHECK(rd_ref_texel_solid_angle(-1, 0, 4) == 0 && rd_ref_texel_solid_angle(0, 4, 4) == 0);
    CHECK(rd_ref_texel_solid_angle(0, 0, 0) == 0);
}

/* Solid-angle weighted mean and variance of channel 0. */
static void cube_stats(const rd_cube_data *c, double *mean, double *var)
{
    double s = 0, s2 = 0, w = 0;
    for (int f = 0; f < 6; f++)
        for (int j = 0; j < c->size; j++)
            for (int i = 0; i < c->size; i++) {
                double sa = rd_ref_texel_solid_angle(i, j, c->size);
                double v = c->faces[f][(j * c->size + i) * 4];
                s += sa * v;
                s2 += sa * v * v;
                w += sa;
            }
    *mean = s / w;
    *var = s2 / w - *mean * *mean;
}

static float cube_max(const rd_cube_data *c)
{
    float m = -INFINITY;
    for (int f = 0; f < 6; f++)
        for (int p = 0; p < c->size * c->size; p++)
            m = fmaxf(m, c->faces[f][p * 4]);
    return m;
}

static int cube_finite(const rd_cube_data *c)
{
    for (int f = 0; f < 6; f++)
        for (int p = 0; p < c->size * c->size * 4; p++)
            if (!isfinite(c->faces[f][p]))
                return 0;
    return 1;
}

static void test_convolve(void)
{
    rd_cube_data src, dst;
    CHECK(rd_cube_data_alloc(16, &src) == RD_OK);
    for (int f = 0; f < 6; f++)
        for (int p = 0; p < 16 * 16; p++) {
            src.faces[f][p * 4 + 0] = rnd();
            src.faces[f][p * 4 + 1] = 0.5f;
            src.faces[f][p * 4 + 2] = 0.0f;
            src.faces[f][p * 4 + 3] = 1.0f;
        }
    double src_mean, src_var;
    cube_stats(&src, &src_mean, &src_var);

    /* Brightness is conserved and the blur grows as n falls. */
    const float ns[3] = {64, 8, 1};
    double prev_var = src_var;
    for (int k = 0; k < 3; k++) {
        /* At the source's resolution the symmetric kernel moves no energy in or out. */
        CHECK(rd_ref_cube_convolve(&src, ns[k], 0, 16, &dst) == RD_OK && dst.size == 16);
        double mean, var;
        cube_stats(&dst, &mean, &var);
        CHECK_MSG(fabs(mean - src_mean) < 0.01 * src_mean, "n = %g: mean %g, source %g", ns[k],
                  mean, src_mean);
        CHECK_MSG(var < prev_var, "n = %g: variance %g, not below %g", ns[k], var, prev_var);
        prev_var = var;
        /* A constant channel stays constant. */
        float g = dst.faces[3][5 * 4 + 1], a = dst.faces[0][0 + 3];
        CHECK(near(g, 0.5f, 1e-5f) && near(a, 1.0f, 1e-5f));
        rd_cube_data_free(&dst);
    }

    /* Against a closed form: the normalised lobe maps a linear environment 1 + a.l to
     * 1 + (n + 1) / (n + 2) a.d (int over the hemisphere of lobe(mu) mu = (n + 1) / (n + 2)). */
    rd_cube_data lin;
    CHECK(rd_cube_data_alloc(32, &lin) == RD_OK);
    const float grad[3] = {0.5f, -0.3f, 0.2f}; /* world */
    for (int f = 0; f < 6; f++)
        for (int j = 0; j < 32; j++)
            for (int i = 0; i < 32; i++) {
                float cm[3], w[3];
                rd_ref_cube_face_direction(f, (i + 0.5f) / 32, (j + 0.5f) / 32, cm);
                rd_ref_cmcs_to_world(cm, w);
                float len = sqrtf(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
                lin.faces[f][(j * 32 + i) * 4] =
                    1.0f + (grad[0] * w[0] + grad[1] * w[1] + grad[2] * w[2]) / len;
            }
    const float lin_ns[2] = {1, 8};
    for (int k = 0; k < 2; k++) {
        CHECK(rd_ref_cube_convolve(&lin, lin_ns[k], 0, 6, &dst) == RD_OK);
        float worst = 0.0f, scale = (lin_ns[k] + 1) / (lin_ns[k] + 2);
        for (int f = 0; f < 6; f++)
            for (int j = 0; j < 6; j++)
                for (int i = 0; i < 6; i++) {
                    float cm[3], w[3];
                    rd_ref_cube_face_direction(f, (i + 0.5f) / 6, (j + 0.5f) / 6, cm);
                    rd_ref_cmcs_to_world(cm, w);
                    float len = sqrtf(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
                    float want =
                        1.0f + scale * (grad[0] * w[0] + grad[1] * w[1] + grad[2] * w[2]) / len;
                    worst = fmaxf(worst, fabsf(dst.faces[f][(j * 6 + i) * 4] - want));
                }
        CHECK_MSG(worst < 5e-4f, "n = %g: linear environment off by %g", lin_ns[k], worst);
        rd_cube_data_free(&dst);
    }
    rd_cube_data_free(&lin);

    /* A 1e6 lamp texel: with clamp 10 the result is that of a 10 texel; without, huge. */
    rd_cube_data lamp, ten, a, b;
    CHECK(rd_cube_data_alloc(8, &lamp) == RD_OK && rd_cube_data_alloc(8, &ten) == RD_OK);
    lamp.faces[2][(3 * 8 + 4) * 4] = 1e6f;
    ten.faces[2][(3 * 8 + 4) * 4] = 10.0f;
    lamp.faces[4][0] = NAN; /* a non-finite texel counts as 0 */
    lamp.faces[4][4] = INFINITY;
    CHECK(rd_ref_cube_convolve(&lamp, 8, 10.0f, 4, &a) == RD_OK);
    CHECK(rd_ref_cube_convolve(&ten, 8, 0, 4, &b) == RD_OK);
    CHECK(cube_finite(&a) && cube_max(&a) <= 10.0f && cube_max(&a) > 0.0f);
    int same = 1;
    for (int f = 0; f < 6; f++)
        for (int p = 0; p < 16; p++)
            same &= near(a.faces[f][p * 4], b.faces[f][p * 4], 1e-5f);
    CHECK_MSG(same, "clamped lamp differs from a 10 texel");
    rd_cube_data_free(&a);
    CHECK(rd_ref_cube_convolve(&lamp, 8, 0, 4, &a) == RD_OK);
    CHECK(cube_finite(&a) && cube_max(&a) > 1000.0f);
    rd_cube_data_free(&a);
    CHECK(rd_ref_cube_convolve(&lamp, 8, NAN, 4, &a) == RD_OK && cube_max(&a) > 1000.0f);
    rd_cube_data_free(&a);

    /* n = 8192 (g = 1) on a coarse source: weights underflow far from texel centres; finite. */
    CHECK(rd_ref_cube_convolve(&ten, 8192, 0, 5, &a) == RD_OK && cube_finite(&a));
    rd_cube_data_free(&a);
    rd_cube_data_free(&b);
    rd_cube_data_free(&ten);
    rd_cube_data_free(&lamp);

    /* Bad arguments. */
    CHECK(rd_ref_cube_convolve(NULL, 8, 0, 4, &dst) == RD_ERR_INVALID_ARGUMENT && !dst.faces[0]);
    CHECK(rd_ref_cube_convolve(&src, 8, 0, 0, &dst) == RD_ERR_INVALID_ARGUMENT);
    CHECK(rd_ref_cube_convolve(&src, 8, 0, 4, NULL) == RD_ERR_INVALID_ARGUMENT);
    rd_cube_data empty = {0};
    CHECK(rd_ref_cube_convolve(&empty, 8, 0, 4, &dst) == RD_ERR_INVALID_ARGUMENT);
    rd_cube_data_free(&src);
}

/* ---- section 6 ------------------------------------------------------------------------ */

static void test_blend(void)
{
    const float lit[3] = {0.2f, 0.4f, 0.6f}, refl[3] = {1.0f, 0.5f, 0.0f};
    const float spec[3] = {0.5f, 1.0f, 0.25f}, emis[3] = {0, 0, 0.7f};
    float out[3];
    rd_ref_blend(RD_BLEND_MIX, 0.25f, spec, lit, refl, 0.5f, emis, out);
    CHECK_MSG(near3(out, 0.4f, 0.425f, 0.7f, 1e-6f), "mix %g %g %g", out[0], out[1], out[2]);
    rd_ref_blend(RD_BLEND_ADD, 0.25f, spec, lit, refl, 0.5f, emis, out);
    CHECK_MSG(near3(out, 0.325f, 0.525f, 0.7f, 1e-6f), "add %g %g %g", out[0], out[1], out[2]);
    /* F = 0.25 + 0.75 * 0.5^5 = 0.2734375. */
    rd_ref_blend(RD_BLEND_FRESNEL, 0.25f, spec, lit, refl, 0.5f, emis, out);
    CHECK_MSG(near3(out, 0.41875f, 0.42734375f, 0.7f, 1e-6f), "fresnel %g %g %g", out[0], out[1],
              out[2]);
    /* kr = 1: mix is the reflection; kr clamped. */
    const float none[3] = {0, 0, 0};
    rd_ref_blend(RD_BLEND_MIX, 1.0f, spec, lit, refl, 0.5f, none, out);
    CHECK(near3(out, 1.0f, 0.5f, 0.0f, 0));
    rd_ref_blend(RD_BLEND_MIX, 7.0f, spec, lit, refl, 0.5f, none, out);
    CHECK(near3(out, 1.0f, 0.5f, 0.0f, 0));
    rd_ref_blend(RD_BLEND_ADD, 1.0f, spec, lit, refl, 0.5f, none, out);
    CHECK(near3(out, 0.7f, 0.9f, 0.6f, 1e-6f));

    /* kr = 0 (and anything below, and NaN): exactly section 1, bit for bit, whatever refl. */
    const float lits[3][3] = {{0.2f, 0.4f, 0.6f}, {1e-30f, -0.0f, 123456.7f}, {0, 3, 1e6f}};
    const float refls[3][3] = {{1, 0.5f, 0}, {INFINITY, NAN, -1e30f}, {1e6f, 1e6f, 1e6f}};
    const float emits[2][3] = {{0, 0, 0.7f}, {0.1f, 5, 0}};
    const float krs[3] = {0.0f, -1.0f, NAN};
    for (int m = 0; m < 2; m++)
        for (int l = 0; l < 3; l++)
            for (int e = 0; e < 2; e++)
                for (int k = 0; k < 3; k++) {
                    float want[3];
                    /* max as GLSL defines it: lit if emissive < lit, else emissive (fmaxf
                     * may give either zero for +0 vs -0). */
                    for (int ch = 0; ch < 3; ch++)
                        want[ch] = emits[e][ch] < lits[l][ch] ? lits[l][ch] : emits[e][ch];
                    rd_ref_blend(m == 0 ? RD_BLEND_MIX : RD_BLEND_ADD, krs[k], spec, lits[l],
                                 refls[l], 0.3f, emits[e], out);
                    /* Equal as numbers: +0 and -0 are one colour, and an optimising build may
                     * pick either for max(+0, -0). */
                    int same = 1;
                    for (int ch = 0; ch < 3; ch++)
                        same &= out[ch] == want[ch] || (isnan(out[ch]) && isnan(want[ch]));
                    CHECK_MSG(same, "mode %d lit %d emissive %d kr %g: not max(emissive, lit)", m,
                              l, e, krs[k]);
                }

    /* Fresnel: f0 at N.V = 1, 1 at N.V = 0 and below, finite everywhere. */
    const float f0s[4] = {0.0f, 0.04f, 0.5f, 1.0f};
    for (int k = 0; k < 4; k++) {
        CHECK(rd_ref_fresnel(f0s[k], 1.0f) == f0s[k]);
        CHECK(rd_ref_fresnel(f0s[k], 0.0f) == 1.0f);
        CHECK(rd_ref_fresnel(f0s[k], -0.7f) == 1.0f);
        float f = rd_ref_fresnel(f0s[k], NAN);
        CHECK(isfinite(f) && f >= f0s[k] && f <= 1.0f);
        CHECK(rd_ref_fresnel(f0s[k], 1.5f) == f0s[k]);
    }
    CHECK(near(rd_ref_fresnel(0.04f, 0.5f), 0.04f + 0.96f / 32.0f, 1e-7f));
    rd_ref_blend(RD_BLEND_FRESNEL, 0.04f, spec, lit, refl, -0.5f, none, out);
    CHECK(finite3(out) && near3(out, 1.0f, 0.5f, 0.0f, 1e-6f)); /* back-facing: F = 1 */
    rd_ref_blend(RD_BLEND_FRESNEL, 0.0f, spec, lit, refl, 1.0f, emis, out);
    CHECK(near3(out, 0.2f, 0.4f, 0.7f, 1e-7f)); /* F = f0 = 0 head-on */
}

/* ---- section 9 ------------------------------------------------------------------------ */

static void test_refract(void)
{
    float t[3];
    float down[3] = {0, 0, -1}, n[3] = {0, 0, 1};
    CHECK(rd_ref_refract(down, n, 1.0f / 1.5f, t) == 1 && near3(t, 0, 0, -1, 1e-7f));
    CHECK(rd_ref_refract(down, n, 1.5f, t) == 1 && near3(t, 0, 0, -1, 1e-7f));

    /* Snell: n1 sin th1 = n2 sin th2, air into water at 40 degrees. */
    const float th1 = 40.0f * (float)PI / 180.0f, eta = 1.0f / 1.33f;
    float in[3] = {sinf(th1), 0, -cosf(th1)};
    CHECK(rd_ref_refract(in, n, eta, t) == 1);
    CHECK(near(sqrtf(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]), 1.0f, 1e-6f));
    CHECK_MSG(near(t[0], eta * sinf(th1), 1e-6f) && t[2] < 0 && t[1] == 0, "Snell: %g %g %g", t[0],
              t[1], t[2]);

    /* Glass to air: critical angle asin(1/1.5) = 41.81 degrees. */
    const float below = 41.0f * (float)PI / 180.0f, above = 42.5f * (float)PI / 180.0f;
    float in_below[3] = {sinf(below), 0, -cosf(below)},
          in_above[3] = {sinf(above), 0, -cosf(above)};
    CHECK(rd_ref_refract(in_below, n, 1.5f, t) == 1 && near(t[0], 1.5f * sinf(below), 1e-5f));
    t[0] = t[1] = t[2] = 9;
    CHECK(rd_ref_refract(in_above, n, 1.5f, t) == 0 && t[0] == 0 && t[1] == 0 && t[2] == 0);
    float grazing[3] = {1, 0, 0};
    CHECK(rd_ref_refract(grazing, n, 1.5f, t) == 0);
    float nan3[3] = {NAN, 0, -1};
    CHECK(rd_ref_refract(nan3, n, 0.7f, t) == 0 && finite3(t));
    CHECK(rd_ref_refract(down, n, INFINITY, t) == 0 && finite3(t));
}

static void test_sphere_map(void)
{
    float s, t, r[3];
    const float a = 0.35355339f; /* 1 / (4 sqrt(1/2)) */
    const float cases[6][5] = {
        {0, 0, 1, 0.5f, 0.5f},      {1, 0, 0, 0.5f + a, 0.5f},  {0, 1, 0, 0.5f, 0.5f + a},
        {-1, 0, 0, 0.5f - a, 0.5f}, {0, -2, 0, 0.5f, 0.5f - a}, {0, 0, -1, 1.0f, 0.5f},
    };
    for (int k = 0; k < 6; k++) {
        rd_ref_sphere_map_st(cases[k], &s, &t);
        CHECK_MSG(near(s, cases[k][3], 1e-6f) && near(t, cases[k][4], 1e-6f),
                  "(%g, %g, %g) -> (%g, %g)", cases[k][0], cases[k][1], cases[k][2], s, t);
    }
    /* The rim, A_z -> 0: the rim point in the direction of (R_x, R_y). */
    float rim1[3] = {1e-4f, 0, -1}, rim2[3] = {0, -1e-4f, -1}, rim3[3] = {-3e-20f, 3e-20f, -1};
    rd_ref_sphere_map_st(rim1, &s, &t);
    CHECK(near(s, 1.0f, 1e-6f) && near(t, 0.5f, 1e-6f));
    rd_ref_sphere_map_st(rim2, &s, &t);
    CHECK(near(s, 0.5f, 1e-6f) && near(t, 0.0f, 1e-6f));
    rd_ref_sphere_map_st(rim3, &s, &t);
    CHECK(near(s, 0.5f - 0.35355339f, 1e-6f) && near(t, 0.5f + 0.35355339f, 1e-6f));
    float zero[3] = {0, 0, 0}, nan3[3] = {NAN, 0, 0}, huge[3] = {3e38f, 3e38f, 0};
    rd_ref_sphere_map_st(zero, &s, &t);
    CHECK(s == 0.5f && t == 0.5f);
    rd_ref_sphere_map_st(nan3, &s, &t);
    CHECK(s == 0.5f && t == 0.5f);
    rd_ref_sphere_map_st(huge, &s, &t);
    CHECK(isfinite(s) && isfinite(t) && near(s, 0.75f, 1e-5f) && near(t, 0.75f, 1e-5f));

    /* direction is unit and st(direction(s, t)) = (s, t) inside the disc. */
    for (int j = 0; j < 40; j++)
        for (int i = 0; i < 40; i++) {
            float s0 = (i + 0.5f) / 40, t0 = (j + 0.5f) / 40;
            float dx = s0 - 0.5f, dy = t0 - 0.5f;
            if (dx * dx + dy * dy > 0.49f * 0.49f)
                continue;
            rd_ref_sphere_map_direction(s0, t0, r);
            CHECK(near(r[0] * r[0] + r[1] * r[1] + r[2] * r[2], 1.0f, 1e-5f));
            rd_ref_sphere_map_st(r, &s, &t);
            CHECK_MSG(near(s, s0, 2e-5f) && near(t, t0, 2e-5f), "(%g, %g) -> (%g, %g)", s0, t0, s,
                      t);
        }
    /* and direction(st(R)) = R away from the rim. */
    for (int k = 0; k < 500; k++) {
        float d[3] = {2 * rnd() - 1, 2 * rnd() - 1, 2 * rnd() - 1};
        float len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (len < 0.1f || d[2] / len < -0.95f)
            continue;
        for (int q = 0; q < 3; q++)
            d[q] /= len;
        rd_ref_sphere_map_st(d, &s, &t);
        rd_ref_sphere_map_direction(s, t, r);
        CHECK_MSG(near3(r, d[0], d[1], d[2], 1e-4f), "(%g, %g, %g) -> (%g, %g, %g)", d[0], d[1],
                  d[2], r[0], r[1], r[2]);
    }
    /* Outside the disc: the rim; non-finite (s, t): finite. */
    rd_ref_sphere_map_direction(1.0f, 1.0f, r);
    CHECK(near3(r, 0, 0, -1, 0));
    rd_ref_sphere_map_direction(NAN, INFINITY, r);
    CHECK(finite3(r));

    /* The generator: world up in the centre, world down outside the disc, all finite. */
    rd_cube_data c;
    CHECK(rd_cube_data_alloc(4, &c) == RD_OK);
    for (int f = 0; f < 6; f++)
        for (int p = 0; p < 16; p++) {
            c.faces[f][p * 4] = (float)f;
            c.faces[f][p * 4 + 3] = 1.0f;
        }
    float map[17 * 17 * 4];
    for (size_t k = 0; k < sizeof map / sizeof map[0]; k++)
        map[k] = NAN;
    CHECK(rd_sphere_map_from_cube(&c, 17, map) == RD_OK);
    int finite = 1;
    for (size_t k = 0; k < sizeof map / sizeof map[0]; k++)
        finite &= isfinite(map[k]) != 0;
    CHECK(finite);
    CHECK(map[(8 * 17 + 8) * 4] == (float)RD_CUBE_NEG_Y); /* world +Z is CMCS -Y (Fig. 8) */
    CHECK(map[0] == (float)RD_CUBE_POS_Y);                /* world -Z */
    CHECK(map[3] == 1.0f);
    float one[4] = {NAN, NAN, NAN, NAN};
    CHECK(rd_sphere_map_from_cube(&c, 1, one) == RD_OK && one[0] == (float)RD_CUBE_NEG_Y);
    CHECK(rd_sphere_map_from_cube(&c, 0, one) == RD_ERR_INVALID_ARGUMENT);
    CHECK(rd_sphere_map_from_cube(NULL, 4, map) == RD_ERR_INVALID_ARGUMENT);
    CHECK(rd_sphere_map_from_cube(&c, 4, NULL) == RD_ERR_INVALID_ARGUMENT);
    rd_cube_data_free(&c);
}

/* ---- section 11: a 1x1 cube map everywhere ------------------------------------------- */

static void test_one_texel_cube(void)
{
    rd_cube_data c, blurred;
    CHECK(rd_cube_data_alloc(1, &c) == RD_OK);
    for (int f = 0; f < 6; f++) {
        c.faces[f][0] = (float)(f + 1);
        c.faces[f][1] = 1e6f;
        c.faces[f][3] = 1.0f;
    }
    int ok = 1;
    for (int k = 0; k < 2000; k++) {
        float d[3] = {2 * rnd() - 1, 2 * rnd() - 1, 2 * rnd() - 1}, a[4], b[4];
        rd_cube_sample_nearest(&c, d, a);
        rd_cube_sample_bilinear(&c, d, b);
        ok &= finite3(a) && finite3(b) && a[0] >= 1 && a[0] <= 6 && b[0] >= 1 && b[0] <= 6;
    }
    CHECK_MSG(ok, "1x1 sampling");
    CHECK(rd_ref_cube_convolve(&c, 1, 0, 1, &blurred) == RD_OK && cube_finite(&blurred));
    rd_cube_data_free(&blurred);
    CHECK(rd_ref_cube_convolve(&c, 8192, 100, 2, &blurred) == RD_OK && cube_finite(&blurred));
    CHECK(blurred.faces[0][1] <= 100.0f);
    rd_cube_data_free(&blurred);
    rd_sh9 sh;
    rd_ref_sh9_project(&c, &sh);
    float n[3] = {0.3f, -0.2f, 0.9f}, e[3];
    rd_ref_sh9_irradiance(&sh, n, e);
    CHECK(finite3(e) && e[0] > 0);
    float map[3 * 3 * 4];
    CHECK(rd_sphere_map_from_cube(&c, 3, map) == RD_OK);
    for (int k = 0; k < 36; k++)
        CHECK(isfinite(map[k]));
    rd_cube_data_free(&c);
}

int main(void)
{
    test_reflect();
    test_correct_box();
    test_correct_sphere();
    test_gloss();
    test_depth_steps();
    test_lobe();
    test_solid_angle();
    test_convolve();
    test_blend();
    test_refract();
    test_sphere_map();
    test_one_texel_cube();
    return check_report("test_reflect_ref");
}
