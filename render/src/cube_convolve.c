/* The "reference" gloss blur of RENDERING.md section 5: brute-force convolution of a cube map
 * with the normalised Phong lobe, by direction over all faces, weighted by exact texel solid
 * angles. Slow on purpose; the GPU prefilter is measured against it. */
#include "render/reflect_ref.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The integral of the area element of the face plane at distance 1 (the solid angle of the
 * rectangle [0, x] x [0, y]): atan2(x y, sqrt(x^2 + y^2 + 1)). */
static double area_element(double x, double y)
{
    return atan2(x * y, sqrt(x * x + y * y + 1.0));
}

float rd_ref_texel_solid_angle(int i, int j, int size)
{
    if (size < 1 || i < 0 || j < 0 || i >= size || j >= size)
        return 0.0f;
    double step = 2.0 / (double)size;
    double x0 = i * step - 1.0, x1 = (i + 1) * step - 1.0;
    double y0 = j * step - 1.0, y1 = (j + 1) * step - 1.0;
    return (float)(area_element(x0, y0) - area_element(x0, y1) - area_element(x1, y0) +
                   area_element(x1, y1));
}

static int cube_usable(const rd_cube_data *c)
{
    if (c == NULL || c->size < 1 || c->size > RD_CUBE_MAX_SIZE)
        return 0;
    for (int f = 0; f < 6; f++)
        if (c->faces[f] == NULL)
            return 0;
    return 1;
}

/* The unit CMCS direction through the centre of texel (i, j) of a face. */
static void texel_direction(int face, int i, int j, int size, float d[3])
{
    rd_ref_cube_face_direction(face, ((float)i + 0.5f) / (float)size,
                               ((float)j + 0.5f) / (float)size, d);
    float len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    d[0] /= len;
    d[1] /= len;
    d[2] /= len;
}

rd_result rd_ref_cube_convolve(const rd_cube_data *src, float n, float clamp, int dst_size,
                               rd_cube_data *dst)
{
    if (dst == NULL)
        return RD_ERR_INVALID_ARGUMENT;
    memset(dst, 0, sizeof *dst);
    if (!cube_usable(src) || dst_size < 1)
        return RD_ERR_INVALID_ARGUMENT;
    rd_result r = rd_cube_data_alloc(dst_size, dst);
    if (r != RD_OK)
        return r;

    int ns = src->size;
    size_t per_face = (size_t)ns * (size_t)ns, count = 6 * per_face;
    /* Per source texel: unit direction, solid angle, and the (clamped, finite) RGBA. */
    float *dir = malloc(count * 3 * sizeof(float));
    float *sa = malloc(count * sizeof(float));
    float *val = malloc(count * 4 * sizeof(float));
    if (dir == NULL || sa == NULL || val == NULL) {
        free(dir);
        free(sa);
        free(val);
        rd_cube_data_free(dst);
        return RD_ERR_OUT_OF_MEMORY;
    }
    int use_clamp = clamp > 0.0f; /* NaN -> no clamp */
    for (int f = 0; f < 6; f++) {
        for (int j = 0; j < ns; j++) {
            for (int i = 0; i < ns; i++) {
                size_t k = (size_t)f * per_face + (size_t)j * ns + (size_t)i;
                texel_direction(f, i, j, ns, dir + k * 3);
                sa[k] = rd_ref_texel_solid_angle(i, j, ns);
                const float *texel = src->faces[f] + ((size_t)j * ns + (size_t)i) * 4;
                for (int ch = 0; ch < 4; ch++) {
                    float v = isfinite(texel[ch]) ? texel[ch] : 0.0f;
                    if (use_clamp && ch < 3)
                        v = fminf(v, clamp);
                    val[k * 4 + ch] = v;
                }
            }
        }
    }

    for (int f = 0; f < 6; f++) {
        for (int j = 0; j < dst_size; j++) {
            for (int i = 0; i < dst_size; i++) {
                float d[3];
                texel_direction(f, i, j, dst_size, d);
                double sum[4] = {0, 0, 0, 0}, wsum = 0.0;
                for (size_t k = 0; k < count; k++) {
                    const float *l = dir + k * 3;
                    float cosine = d[0] * l[0] + d[1] * l[1] + d[2] * l[2];
                    if (!(cosine > 0.0f))
                        continue;
                    double w = (double)rd_ref_lobe(cosine, n) * sa[k];
                    if (w == 0.0)
                        continue;
                    wsum += w;
                    for (int ch = 0; ch < 4; ch++)
                        sum[ch] += w * val[k * 4 + ch];
                }
                float *out = dst->faces[f] + ((size_t)j * dst_size + (size_t)i) * 4;
                if (wsum > 0.0) {
                    for (int ch = 0; ch < 4; ch++)
                        out[ch] = (float)(sum[ch] / wsum);
                } else {
                    /* Every weight underflowed: the nearest source texel (clamped as above). */
                    float s, t;
                    int sf = rd_ref_cube_face_st(d, &s, &t);
                    int si = (int)fminf(fmaxf(floorf(s * (float)ns), 0.0f), (float)(ns - 1));
                    int sj = (int)fminf(fmaxf(floorf(t * (float)ns), 0.0f), (float)(ns - 1));
                    size_t k = (size_t)(sf < 0 ? 0 : sf) * per_face + (size_t)sj * ns + si;
                    memcpy(out, val + k * 4, 4 * sizeof(float));
                }
            }
        }
    }
    free(dir);
    free(sa);
    free(val);
    return RD_OK;
}
