/* Irradiance from 9 spherical-harmonic coefficients (RENDERING.md section 7): Ramamoorthi and
 * Hanrahan 2001, eqs. 10-13, the method of seed 001 eqs. 8-12 (with R&H's c5, not the seed's
 * misprint). The basis is evaluated in WORLD coordinates, z up. */
#include "render/reflect_ref.h"

#include <math.h>
#include <string.h>

void rd_ref_sh9_basis(const float d[3], float y[9])
{
    float x = d[0], yy = d[1], z = d[2];
    y[RD_SH_00] = 0.282095f;
    y[RD_SH_1M1] = 0.488603f * yy;
    y[RD_SH_10] = 0.488603f * z;
    y[RD_SH_11] = 0.488603f * x;
    y[RD_SH_2M2] = 1.092548f * x * yy;
    y[RD_SH_2M1] = 1.092548f * yy * z;
    y[RD_SH_20] = 0.315392f * (3.0f * z * z - 1.0f);
    y[RD_SH_21] = 1.092548f * x * z;
    y[RD_SH_22] = 0.546274f * (x * x - yy * yy);
}

/* R&H eq. 10 as a quadrature: L_lm = sum of L(texel) Y_lm(texel direction) dOmega(texel). */
void rd_ref_sh9_project(const rd_cube_data *c, rd_sh9 *out)
{
    memset(out, 0, sizeof *out);
    if (c == NULL || c->size < 1 || c->size > RD_CUBE_MAX_SIZE)
        return;
    for (int f = 0; f < 6; f++)
        if (c->faces[f] == NULL)
            return;
    int n = c->size;
    double acc[9][3] = {{0}};
    for (int f = 0; f < 6; f++) {
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                float cm[3], w[3], y[9];
                rd_ref_cube_face_direction(f, ((float)i + 0.5f) / (float)n,
                                           ((float)j + 0.5f) / (float)n, cm);
                float len = sqrtf(cm[0] * cm[0] + cm[1] * cm[1] + cm[2] * cm[2]);
                cm[0] /= len;
                cm[1] /= len;
                cm[2] /= len;
                rd_ref_cmcs_to_world(cm, w);
                rd_ref_sh9_basis(w, y);
                double sa = rd_ref_texel_solid_angle(i, j, n);
                const float *texel = c->faces[f] + ((size_t)j * n + (size_t)i) * 4;
                for (int ch = 0; ch < 3; ch++) {
                    double v = isfinite(texel[ch]) ? texel[ch] : 0.0;
                    for (int k = 0; k < 9; k++)
                        acc[k][ch] += v * y[k] * sa;
                }
            }
        }
    }
    for (int k = 0; k < 9; k++)
        for (int ch = 0; ch < 3; ch++)
            out->coeff[k][ch] = (float)acc[k][ch];
}

/* R&H eq. 13. */
void rd_ref_sh9_irradiance(const rd_sh9 *sh, const float n_world[3], float out[3])
{
    const float c1 = 0.429043f, c2 = 0.511664f, c3 = 0.743125f, c4 = 0.886227f, c5 = 0.247708f;
    float x = n_world[0], y = n_world[1], z = n_world[2];
    /* Scaled by the largest component first, so huge finite normals do not overflow. */
    float m = fmaxf(fabsf(x), fmaxf(fabsf(y), fabsf(z)));
    if (isfinite(m) && m > 0.0f && isfinite(x) && isfinite(y) && isfinite(z)) {
        x /= m;
        y /= m;
        z /= m;
        float len = sqrtf(x * x + y * y + z * z);
        x /= len;
        y /= len;
        z /= len;
    } else {
        x = y = z = 0.0f;
    }
    float res[3];
    for (int ch = 0; ch < 3; ch++) {
        const float L00 = sh->coeff[RD_SH_00][ch], L1m1 = sh->coeff[RD_SH_1M1][ch],
                    L10 = sh->coeff[RD_SH_10][ch], L11 = sh->coeff[RD_SH_11][ch],
                    L2m2 = sh->coeff[RD_SH_2M2][ch], L2m1 = sh->coeff[RD_SH_2M1][ch],
                    L20 = sh->coeff[RD_SH_20][ch], L21 = sh->coeff[RD_SH_21][ch],
                    L22 = sh->coeff[RD_SH_22][ch];
        res[ch] = c1 * L22 * (x * x - y * y) + c3 * L20 * z * z + c4 * L00 - c5 * L20 +
                  2.0f * c1 * (L2m2 * x * y + L21 * x * z + L2m1 * y * z) +
                  2.0f * c2 * (L11 * x + L1m1 * y + L10 * z);
    }
    memcpy(out, res, sizeof res);
}
