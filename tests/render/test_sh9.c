/* SH9 irradiance (RENDERING.md section 7; Ramamoorthi and Hanrahan 2001): projection of
 * analytic environments against coefficients derived by hand, irradiance against closed forms
 * and against brute-force cosine integration, and a lamp texel. */
#include "../common/check.h"
#include "render/reflect_ref.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

/* Fills every texel with env(world direction of its centre) per channel. */
typedef void (*env_fn)(const float w[3], float rgb[3]);

static void fill(rd_cube_data *c, env_fn env)
{
    int n = c->size;
    for (int f = 0; f < 6; f++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                float cm[3], w[3], rgb[3];
                rd_ref_cube_face_direction(f, (i + 0.5f) / n, (j + 0.5f) / n, cm);
                float len = sqrtf(cm[0] * cm[0] + cm[1] * cm[1] + cm[2] * cm[2]);
                for (int k = 0; k < 3; k++)
                    cm[k] /= len;
                rd_ref_cmcs_to_world(cm, w);
                env(w, rgb);
                float *p = c->faces[f] + ((size_t)j * n + i) * 4;
                p[0] = rgb[0];
                p[1] = rgb[1];
                p[2] = rgb[2];
                p[3] = 1.0f;
            }
}

/* Red: 0.7 + 0.3 z (world z, up). Green: constant 1. Blue: 0.5 x. */
static void env_linear(const float w[3], float rgb[3])
{
    rgb[0] = 0.7f + 0.3f * w[2];
    rgb[1] = 1.0f;
    rgb[2] = 0.5f * w[0];
}

/* Every channel z^2 (exercises L00 and L20, hence c3, c4 and c5). */
static void env_z2(const float w[3], float rgb[3])
{
    rgb[0] = rgb[1] = rgb[2] = w[2] * w[2];
}

/* A band-limited (order <= 2) environment using every coefficient, different per channel. */
static void env_mixed(const float w[3], float rgb[3])
{
    float x = w[0], y = w[1], z = w[2];
    rgb[0] = 1.0f + 0.5f * x - 0.3f * y + 0.2f * z + 0.4f * x * y - 0.25f * y * z + 0.3f * x * z +
             0.2f * (x * x - y * y) + 0.35f * z * z;
    rgb[1] = 2.0f - 0.6f * y + 0.5f * x * z;
    rgb[2] = 0.5f + 0.4f * z - 0.3f * (x * x - y * y) - 0.45f * x * y;
}

static int rel_near(double got, double want, double rel)
{
    return fabs(got - want) <= rel * fabs(want) + 1e-12;
}

static void test_basis_order(void)
{
    /* A unit direction with distinct components: the order L00, L1-1, L10, L11, L2-2, L2-1,
     * L20, L21, L22 and the constants of R&H. */
    const float d[3] = {0.48f, 0.6f, 0.64f};
    const float x = d[0], y = d[1], z = d[2];
    const float want[9] = {0.282095f,
                           0.488603f * y,
                           0.488603f * z,
                           0.488603f * x,
                           1.092548f * x * y,
                           1.092548f * y * z,
                           0.315392f * (3 * z * z - 1),
                           1.092548f * x * z,
                           0.546274f * (x * x - y * y)};
    float got[9];
    rd_ref_sh9_basis(d, got);
    for (int k = 0; k < 9; k++)
        CHECK_MSG(fabsf(got[k] - want[k]) < 1e-6f, "Y[%d] = %g, expected %g", k, got[k], want[k]);
}

static void test_projection(void)
{
    /* Expected coefficients, L_lm = int L Y_lm dw over the sphere, using
     *   int 1 dw = 4 pi,  int x dw = int xy dw = ... = 0,  int x^2 dw = int z^2 dw = 4 pi / 3:
     *   constant a:    L00 = a 0.282095 4 pi (= a 2 sqrt(pi)), all others 0;
     *   b z:           L10 = b 0.488603 4 pi / 3, all others 0 (Y20 has int z (3z^2-1) = 0);
     *   b x:           L11 = b 0.488603 4 pi / 3. */
    rd_cube_data c;
    CHECK(rd_cube_data_alloc(64, &c) == RD_OK);
    fill(&c, env_linear);
    rd_sh9 sh;
    rd_ref_sh9_project(&c, &sh);
    double want[9][3] = {{0}};
    want[RD_SH_00][0] = 0.7 * 0.282095 * 4 * PI;
    want[RD_SH_10][0] = 0.3 * 0.488603 * 4 * PI / 3;
    want[RD_SH_00][1] = 1.0 * 0.282095 * 4 * PI;
    want[RD_SH_11][2] = 0.5 * 0.488603 * 4 * PI / 3;
    for (int k = 0; k < 9; k++)
        for (int ch = 0; ch < 3; ch++)
            CHECK_MSG(fabs(sh.coeff[k][ch] - want[k][ch]) < 1e-3,
                      "coefficient %d channel %d: %g, expected %g", k, ch, sh.coeff[k][ch],
                      want[k][ch]);
    /* L00 of a = 0.7 is 0.7 * 2 sqrt(pi). */
    CHECK(fabs(sh.coeff[RD_SH_00][0] - 0.7 * 2 * sqrt(PI)) < 1e-3);

    /* z^2: L00 = 0.282095 4 pi / 3, L20 = 0.315392 (3 int z^4 - int z^2) = 0.315392 (3 4 pi / 5
     * - 4 pi / 3) = 0.315392 16 pi / 15. */
    fill(&c, env_z2);
    rd_ref_sh9_project(&c, &sh);
    CHECK(fabs(sh.coeff[RD_SH_00][0] - 0.282095 * 4 * PI / 3) < 1e-3);
    CHECK(fabs(sh.coeff[RD_SH_20][0] - 0.315392 * 16 * PI / 15) < 1e-3);
    CHECK(fabs(sh.coeff[RD_SH_22][0]) < 1e-3 && fabs(sh.coeff[RD_SH_10][0]) < 1e-3);
    rd_cube_data_free(&c);
}

/* int L(w) max(n.w, 0) dw over the cube's texels (brute force). */
static void brute_irradiance(const rd_cube_data *c, const float n[3], double out[3])
{
    int size = c->size;
    out[0] = out[1] = out[2] = 0;
    for (int f = 0; f < 6; f++)
        for (int j = 0; j < size; j++)
            for (int i = 0; i < size; i++) {
                float cm[3], w[3];
                rd_ref_cube_face_direction(f, (i + 0.5f) / size, (j + 0.5f) / size, cm);
                float len = sqrtf(cm[0] * cm[0] + cm[1] * cm[1] + cm[2] * cm[2]);
                for (int k = 0; k < 3; k++)
                    cm[k] /= len;
                rd_ref_cmcs_to_world(cm, w);
                double cosine = n[0] * w[0] + n[1] * w[1] + n[2] * w[2];
                if (cosine <= 0)
                    continue;
                double sa = rd_ref_texel_solid_angle(i, j, size);
                const float *p = c->faces[f] + ((size_t)j * size + i) * 4;
                for (int ch = 0; ch < 3; ch++)
                    out[ch] += p[ch] * cosine * sa;
            }
}

static unsigned rng_state = 99u;
static float rnd(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (float)(rng_state >> 8) / (float)(1u << 24);
}

static void random_normal(float n[3])
{
    for (;;) {
        n[0] = 2 * rnd() - 1, n[1] = 2 * rnd() - 1, n[2] = 2 * rnd() - 1;
        float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len > 0.1f && len <= 1.0f) {
            for (int k = 0; k < 3; k++)
                n[k] /= len;
            return;
        }
    }
}

static void test_irradiance(void)
{
    rd_cube_data c;
    CHECK(rd_cube_data_alloc(64, &c) == RD_OK);
    rd_sh9 sh;
    float e[3];

    /* A constant environment L gives E = pi L for every normal. */
    for (int f = 0; f < 6; f++)
        for (int p = 0; p < 64 * 64; p++) {
            c.faces[f][p * 4 + 0] = 0.8f;
            c.faces[f][p * 4 + 1] = 2.0f;
            c.faces[f][p * 4 + 2] = 1e-3f;
        }
    rd_ref_sh9_project(&c, &sh);
    const float axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    int ok = 1;
    for (int k = 0; k < 506; k++) {
        float n[3];
        if (k < 6)
            memcpy(n, axes[k], sizeof n);
        else
            random_normal(n);
        rd_ref_sh9_irradiance(&sh, n, e);
        ok &= rel_near(e[0], PI * 0.8, 1e-3) && rel_near(e[1], PI * 2.0, 1e-3) &&
              rel_near(e[2], PI * 1e-3, 1e-3);
    }
    CHECK_MSG(ok, "constant environment: E != pi L");

    /* 0.7 + 0.3 z: E(n) = 0.7 pi + 0.3 (2 pi / 3) n_z exactly (A0 = pi, A1 = 2 pi / 3). */
    fill(&c, env_linear);
    rd_ref_sh9_project(&c, &sh);
    ok = 1;
    for (int k = 0; k < 200; k++) {
        float n[3];
        random_normal(n);
        rd_ref_sh9_irradiance(&sh, n, e);
        ok &= rel_near(e[0], 0.7 * PI + 0.3 * 2 * PI / 3 * n[2], 1e-3);
        ok &= fabs(e[2] - 0.5 * 2 * PI / 3 * n[0]) < 1e-3;
    }
    CHECK_MSG(ok, "linear environment");

    /* z^2 = 1/3 + (2/3) P2(z): E(n) = pi / 3 + (pi / 4)(2 / 3) P2(n_z) (A2 = pi / 4), so pi / 2
     * straight up and pi / 4 sideways. Fails with seed 001's c5 = 0.429043. */
    fill(&c, env_z2);
    rd_ref_sh9_project(&c, &sh);
    float up[3] = {0, 0, 1}, side[3] = {0.6f, 0.8f, 0};
    rd_ref_sh9_irradiance(&sh, up, e);
    CHECK_MSG(rel_near(e[0], PI / 2, 1e-3), "z^2 up: %g, expected %g", e[0], PI / 2);
    rd_ref_sh9_irradiance(&sh, side, e);
    CHECK_MSG(rel_near(e[0], PI / 4, 1e-3), "z^2 sideways: %g, expected %g", e[0], PI / 4);

    /* Every coefficient and sign: SH9 is exact for an order-2 environment, so E(n) matches
     * brute-force cosine integration over the texels. */
    rd_cube_data_free(&c);
    CHECK(rd_cube_data_alloc(48, &c) == RD_OK);
    fill(&c, env_mixed);
    rd_ref_sh9_project(&c, &sh);
    for (int k = 0; k < 14; k++) {
        float n[3];
        if (k < 6)
            memcpy(n, axes[k], sizeof n);
        else
            random_normal(n);
        double want[3];
        brute_irradiance(&c, n, want);
        rd_ref_sh9_irradiance(&sh, n, e);
        for (int ch = 0; ch < 3; ch++)
            CHECK_MSG(rel_near(e[ch], want[ch], 2e-3),
                      "order-2 environment, n (%g, %g, %g) channel %d: %g, brute force %g", n[0],
                      n[1], n[2], ch, e[ch], want[ch]);
    }
    /* An unnormalised normal is normalised; a zero or non-finite one gives a finite value. */
    float n_long[3] = {0, 0, 5}, n_unit[3] = {0, 0, 1}, e2[3];
    rd_ref_sh9_irradiance(&sh, n_long, e);
    rd_ref_sh9_irradiance(&sh, n_unit, e2);
    CHECK(fabsf(e[0] - e2[0]) < 1e-5f * fabsf(e2[0]));
    float n_zero[3] = {0, 0, 0}, n_nan[3] = {NAN, 0, 1}, n_huge[3] = {3e38f, 3e38f, 0};
    rd_ref_sh9_irradiance(&sh, n_zero, e);
    CHECK(isfinite(e[0]) && isfinite(e[1]) && isfinite(e[2]));
    rd_ref_sh9_irradiance(&sh, n_nan, e);
    CHECK(isfinite(e[0]) && isfinite(e[1]) && isfinite(e[2]));
    rd_ref_sh9_irradiance(&sh, n_huge, e);
    CHECK(isfinite(e[0]) && isfinite(e[1]) && isfinite(e[2]));
    rd_cube_data_free(&c);
}

static void test_lamp(void)
{
    /* A lamp-like single bright texel (plus a NaN and an Inf texel, counted as 0). */
    rd_cube_data c;
    CHECK(rd_cube_data_alloc(16, &c) == RD_OK);
    c.faces[RD_CUBE_NEG_Y][(7 * 16 + 8) * 4 + 0] = 1e6f;
    c.faces[RD_CUBE_NEG_Y][(7 * 16 + 8) * 4 + 1] = 1e6f;
    c.faces[RD_CUBE_POS_X][0] = NAN;
    c.faces[RD_CUBE_POS_X][5] = INFINITY;
    rd_sh9 sh;
    rd_ref_sh9_project(&c, &sh);
    int ok = 1;
    for (int k = 0; k < 9; k++)
        for (int ch = 0; ch < 3; ch++)
            ok &= isfinite(sh.coeff[k][ch]) != 0;
    CHECK_MSG(ok, "lamp coefficients not finite");
    CHECK(sh.coeff[RD_SH_00][0] > 0 && sh.coeff[RD_SH_00][2] == 0);
    /* The lamp sits near world up (CMCS -Y): brightest facing up. */
    CHECK(sh.coeff[RD_SH_10][0] > 0);
    ok = 1;
    for (int k = 0; k < 300; k++) {
        float n[3], e[3];
        random_normal(n);
        rd_ref_sh9_irradiance(&sh, n, e);
        ok &= isfinite(e[0]) && isfinite(e[1]) && isfinite(e[2]);
    }
    CHECK_MSG(ok, "lamp irradiance not finite");
    rd_cube_data_free(&c);

    /* An empty cube gives zeros. */
    rd_cube_data empty = {0};
    rd_sh9 sh0;
    memset(&sh0, 0x7f, sizeof sh0);
    rd_ref_sh9_project(&empty, &sh0);
    CHECK(sh0.coeff[0][0] == 0 && sh0.coeff[8][2] == 0);
}

int main(void)
{
    test_basis_order();
    test_projection();
    test_irradiance();
    test_lamp();
    return check_report("test_sh9");
}
