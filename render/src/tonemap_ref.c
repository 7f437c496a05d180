/* CPU twin of shaders/tonemap.glsl: white balance, exposure, the tone curves and sRGB
 * encoding, line for line, so the reference tracer's images are resolved as the GPU's. */
#include "render/shade_ref.h"

#include <math.h>
#include <string.h>

static const struct {
    const char *name;
    rd_tonemap mode;
} tone_names[] = {
    {"reinhard", RD_TONEMAP_PHOTOGRAPHIC},
    {"photographic", RD_TONEMAP_PHOTOGRAPHIC},
    {"clamp", RD_TONEMAP_CLAMP},
    {"neutral", RD_TONEMAP_NEUTRAL},
    {"agx", RD_TONEMAP_AGX},
};

rd_result rd_tonemap_parse(const char *name, rd_tonemap *out)
{
    for (size_t i = 0; name && i < sizeof tone_names / sizeof tone_names[0]; i++)
        if (!strcmp(name, tone_names[i].name)) {
            *out = tone_names[i].mode;
            return RD_OK;
        }
    return RD_ERR_INVALID_ARGUMENT;
}

const char *rd_tonemap_name(rd_tonemap t)
{
    switch (t) {
    case RD_TONEMAP_CLAMP:
        return "clamp";
    case RD_TONEMAP_NEUTRAL:
        return "neutral";
    case RD_TONEMAP_AGX:
        return "agx";
    default:
        return "reinhard";
    }
}

float rd_auto_exposure_ev(double sum_log, long long count, float compensation_ev)
{
    if (count <= 0 || !isfinite(sum_log))
        return compensation_ev;
    double log_avg = sum_log / (double)count; /* log(L_avg), eq. 1 */
    double ev = log2(RD_EXPOSURE_KEY) - log_avg / log(2.0) + compensation_ev;
    /* rd_view's exposure range, with room for the compensation */
    return (float)fmin(fmax(ev, -60.0), 60.0);
}

/* ---- white balance ------------------------------------------------------------------------ */

static void mat3_mul(const float a[9], const float b[9], float out[9])
{
    float r[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
    memcpy(out, r, sizeof r);
}

static void mat3_apply(const float m[9], const float v[3], float out[3])
{
    float r[3];
    for (int i = 0; i < 3; i++)
        r[i] = m[3 * i] * v[0] + m[3 * i + 1] * v[1] + m[3 * i + 2] * v[2];
    memcpy(out, r, sizeof r);
}

/* CIE xy of a black body at t kelvin: the cubic spline of Kim et al. 2002 (US patent 7024034,
 * "Color temperature conversion"), valid over 1667 to 25000 K. */
static void planckian_xy(double t, double *x, double *y)
{
    t = fmin(fmax(t, 1667.0), 25000.0);
    double t1 = 1e3 / t, t2 = t1 * t1, t3 = t2 * t1;
    double xc = t <= 4000.0 ? -0.2661239 * t3 - 0.2343589 * t2 + 0.8776956 * t1 + 0.179910
                            : -3.0258469 * t3 + 2.1070379 * t2 + 0.2226347 * t1 + 0.240390;
    double x2 = xc * xc, x3 = x2 * xc;
    double yc = t <= 2222.0   ? -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * xc - 0.20219683
                : t <= 4000.0 ? -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * xc - 0.16748867
                              : 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * xc - 0.37001483;
    *x = xc;
    *y = yc;
}

void rd_white_balance_matrix(float kelvin, float m[9])
{
    static const float identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    memcpy(m, identity, sizeof identity);
    if (!(kelvin > 0.0f))
        return;
    /* Linear Rec. 709 / sRGB primaries with the D65 white (IEC 61966-2-1) and the Bradford
     * cone response (Lam 1985; as in ICC v4 and CIECAM97s). */
    static const float rgb_to_xyz[9] = {0.4124564f, 0.3575761f, 0.1804375f, 0.2126729f, 0.7151522f,
                                        0.0721750f, 0.0193339f, 0.1191920f, 0.9503041f};
    static const float xyz_to_rgb[9] = {3.2404542f,  -1.5371385f, -0.4985314f,
                                        -0.9692660f, 1.8760108f,  0.0415560f,
                                        0.0556434f,  -0.2040259f, 1.0572252f};
    static const float bradford[9] = {0.8951f, 0.2664f, -0.1614f, -0.7502f, 1.7135f,
                                      0.0367f, 0.0389f, -0.0685f, 1.0296f};
    static const float bradford_inv[9] = {0.9869929f,  -0.1470543f, 0.1599627f,
                                          0.4323053f,  0.5183603f,  0.0492912f,
                                          -0.0085287f, 0.0400428f,  0.9684867f};
    double x, y;
    planckian_xy(kelvin, &x, &y);
    float src_xyz[3] = {(float)(x / y), 1.0f, (float)((1.0 - x - y) / y)};
    float d65_xyz[3] = {0.95047f, 1.0f, 1.08883f};
    float src_lms[3], d65_lms[3];
    mat3_apply(bradford, src_xyz, src_lms);
    mat3_apply(bradford, d65_xyz, d65_lms);
    float gain[9] = {d65_lms[0] / src_lms[0], 0, 0, 0, d65_lms[1] / src_lms[1], 0, 0, 0,
                     d65_lms[2] / src_lms[2]};
    /* xyz_to_rgb . bradford_inv . gain . bradford . rgb_to_xyz */
    float t[9];
    mat3_mul(gain, bradford, t);
    mat3_mul(bradford_inv, t, t);
    mat3_mul(xyz_to_rgb, t, t);
    mat3_mul(t, rgb_to_xyz, m);
}

/* ---- exposure and the tone curves --------------------------------------------------------- */

void rd_ref_expose(const float radiance[3], float exposure_ev, const float wb[9], float out[3])
{
    float scale = exp2f(exposure_ev), c[3];
    if (wb)
        mat3_apply(wb, radiance, c);
    else
        memcpy(c, radiance, sizeof c);
    for (int k = 0; k < 3; k++) {
        float x = c[k] * scale;
        out[k] = isnan(x) ? 0.0f : fminf(fmaxf(x, 0.0f), 1e30f);
    }
}

/* Khronos PBR Neutral (Khronos 3D Commerce, "PBR Neutral" tone mapper specification, 2024):
 * colours below 0.76 pass unchanged but for a small black offset; above, the peak channel is
 * compressed toward 1 and the colour desaturated in proportion to the compression. */
static void neutral(const float in[3], float out[3])
{
    const float start = 0.8f - 0.04f, desaturation = 0.15f;
    float c[3] = {in[0], in[1], in[2]};
    float x = fminf(c[0], fminf(c[1], c[2]));
    float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
    for (int k = 0; k < 3; k++)
        c[k] -= offset;
    float peak = fmaxf(c[0], fmaxf(c[1], c[2]));
    if (peak >= start) {
        const float d = 1.0f - start;
        float new_peak = 1.0f - d * d / (peak + d - start);
        float g = 1.0f - 1.0f / (desaturation * (peak - new_peak) + 1.0f);
        for (int k = 0; k < 3; k++)
            c[k] = c[k] * (new_peak / peak) * (1.0f - g) + new_peak * g;
    }
    for (int k = 0; k < 3; k++)
        out[k] = fminf(fmaxf(c[k], 0.0f), 1.0f);
}

/* AgX (Troy Sobotka), as the minimal version of Benjamin Wrensch ("Minimal AgX
 * implementation", iolite engine, 2023): inset matrix, log2 encoding over [-12.47, 4.03] EV,
 * a sixth-order polynomial fit of the default contrast sigmoid, outset matrix, then the 2.2
 * display power back to linear (the output is sRGB-encoded after). */
static void agx(const float in[3], float out[3])
{
    static const float inset[9] = {0.842479062253094f,  0.0784335999999992f, 0.0792237451477643f,
                                   0.0423282422610123f, 0.878468636469772f,  0.0791661274605434f,
                                   0.0423756549057051f, 0.0784336f,          0.879142973793104f};
    static const float outset[9] = {
        1.19687900512017f,    -0.0980208811401368f, -0.0990297440797205f,
        -0.0528968517574562f, 1.15190312990417f,    -0.0989611768448433f,
        -0.0529716355144438f, -0.0980434501171241f, 1.15107367264116f};
    const float min_ev = -12.47393f, max_ev = 4.026069f;
    float v[3];
    mat3_apply(inset, in, v);
    for (int k = 0; k < 3; k++) {
        float e = v[k] > 0.0f ? log2f(v[k]) : min_ev;
        float x = (fminf(fmaxf(e, min_ev), max_ev) - min_ev) / (max_ev - min_ev);
        float x2 = x * x, x4 = x2 * x2;
        v[k] = 15.5f * x4 * x2 - 40.14f * x4 * x + 31.96f * x4 - 6.868f * x2 * x + 0.4298f * x2 +
               0.1191f * x - 0.00232f;
    }
    mat3_apply(outset, v, v);
    for (int k = 0; k < 3; k++)
        out[k] = powf(fminf(fmaxf(v[k], 0.0f), 1.0f), 2.2f);
}

void rd_ref_tone_curve(const float in[3], rd_tonemap mode, float white, float out[3])
{
    float c[3];
    for (int k = 0; k < 3; k++)
        c[k] = isnan(in[k]) ? 0.0f : fminf(fmaxf(in[k], 0.0f), 1e30f);
    if (mode == RD_TONEMAP_CLAMP) {
        for (int k = 0; k < 3; k++)
            out[k] = fminf(c[k], 1.0f);
        return;
    }
    if (mode == RD_TONEMAP_NEUTRAL) {
        neutral(c, out);
        return;
    }
    if (mode == RD_TONEMAP_AGX) {
        agx(c, out);
        return;
    }
    /* Reinhard et al. 2002, eq. 4, on luminance (Rec. 709 weights) so hue is kept. */
    float w = white > 0.0f ? white : 4.0f;
    float y = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
    if (!(y > 0.0f)) {
        out[0] = out[1] = out[2] = 0.0f;
        return;
    }
    float ratio = (1.0f + y / (w * w)) / (1.0f + y);
    for (int k = 0; k < 3; k++)
        out[k] = fminf(fmaxf(c[k] * ratio, 0.0f), 1.0f);
}

void rd_ref_tonemap(const float radiance[3], float exposure_ev, rd_tonemap mode, float white,
                    float out[3])
{
    float c[3];
    rd_ref_expose(radiance, exposure_ev, NULL, c);
    rd_ref_tone_curve(c, mode, white, out);
}

float rd_ref_srgb_encode(float x)
{
    return x < 0.0031308f ? 12.92f * x : 1.055f * powf(x, 1.0f / 2.4f) - 0.055f;
}

void rd_ref_display_rgb8(const float radiance[3], float exposure_ev, rd_tonemap mode, float white,
                         unsigned char out[3])
{
    float d[3];
    rd_ref_tonemap(radiance, exposure_ev, mode, white, d);
    for (int k = 0; k < 3; k++)
        out[k] = (unsigned char)(rd_ref_srgb_encode(d[k]) * 255.0f + 0.5f);
}
