/* Diffuse textures sampled the way the GPU samples them (render/src/resources.c): a mip chain
 * made by halving with a box filter (glGenerateMipmap), GL_REPEAT, GL_LINEAR for magnification
 * and GL_LINEAR_MIPMAP_LINEAR for minification, and an anisotropic footprint as
 * EXT_texture_filter_anisotropic defines it. */
#include "ref_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void ref_texture_free(ref_texture *t)
{
    if (!t)
        return;
    for (int l = 0; l < t->levels; l++)
        free(t->mips[l].rgb);
    free(t->mips);
    memset(t, 0, sizeof *t);
}

/* Level l + 1 from level l: each texel averages the (up to) 2 x 2 texels it covers. */
static void halve(const ref_mip *src, ref_mip *dst)
{
    for (int y = 0; y < dst->height; y++)
        for (int x = 0; x < dst->width; x++) {
            int x0 = 2 * x < src->width ? 2 * x : src->width - 1;
            int y0 = 2 * y < src->height ? 2 * y : src->height - 1;
            int x1 = x0 + 1 < src->width ? x0 + 1 : x0;
            int y1 = y0 + 1 < src->height ? y0 + 1 : y0;
            const float *a = src->rgb + 3 * ((size_t)y0 * (size_t)src->width + (size_t)x0);
            const float *b = src->rgb + 3 * ((size_t)y0 * (size_t)src->width + (size_t)x1);
            const float *c = src->rgb + 3 * ((size_t)y1 * (size_t)src->width + (size_t)x0);
            const float *d = src->rgb + 3 * ((size_t)y1 * (size_t)src->width + (size_t)x1);
            float *o = dst->rgb + 3 * ((size_t)y * (size_t)dst->width + (size_t)x);
            for (int k = 0; k < 3; k++)
                o[k] = 0.25f * (a[k] + b[k] + c[k] + d[k]);
        }
}

ref_result ref_texture_build(const ref_texture_desc *d, ref_texture *out)
{
    memset(out, 0, sizeof *out);
    if (!d || !d->rgba || d->width <= 0 || d->height <= 0)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "texture: no pixels or a size below 1x1");
    if (d->width > 65536 || d->height > 65536 || (long long)d->width * d->height > (1LL << 28))
        return ref_fail(REF_ERR_TOO_LARGE, "texture: %dx%d is too large", d->width, d->height);
    int levels = 1;
    while ((d->width >> levels) > 0 || (d->height >> levels) > 0)
        levels++;
    out->mips = calloc((size_t)levels, sizeof *out->mips);
    if (!out->mips)
        return ref_fail(REF_ERR_OUT_OF_MEMORY, "texture: out of memory");
    out->levels = levels;
    for (int l = 0; l < levels; l++) {
        ref_mip *m = &out->mips[l];
        m->width = d->width >> l > 0 ? d->width >> l : 1;
        m->height = d->height >> l > 0 ? d->height >> l : 1;
        m->rgb = malloc((size_t)m->width * (size_t)m->height * 3 * sizeof *m->rgb);
        if (!m->rgb) {
            ref_texture_free(out);
            return ref_fail(REF_ERR_OUT_OF_MEMORY, "texture: out of memory");
        }
        if (l == 0) {
            size_t n = (size_t)m->width * (size_t)m->height;
            for (size_t i = 0; i < n; i++)
                for (int k = 0; k < 3; k++) {
                    float x = d->rgba[4 * i + (size_t)k];
                    m->rgb[3 * i + (size_t)k] = isfinite(x) ? x : 0.0f;
                }
        } else {
            halve(&out->mips[l - 1], m);
        }
    }
    return REF_OK;
}

static int wrap(int i, int n)
{
    int r = i % n;
    return r < 0 ? r + n : r;
}

/* GL_LINEAR with GL_REPEAT: texel centres at (i + 0.5) / size. */
static void bilinear(const ref_mip *m, float u, float v, float out[3])
{
    if (!isfinite(u))
        u = 0.0f;
    if (!isfinite(v))
        v = 0.0f;
    u -= floorf(u); /* the repeat, done first so that large coordinates keep their fraction */
    v -= floorf(v);
    float x = u * (float)m->width - 0.5f, y = v * (float)m->height - 0.5f;
    float fx0 = floorf(x), fy0 = floorf(y);
    float fx = x - fx0, fy = y - fy0;
    int x0 = wrap((int)fx0, m->width), x1 = wrap((int)fx0 + 1, m->width);
    int y0 = wrap((int)fy0, m->height), y1 = wrap((int)fy0 + 1, m->height);
    size_t w = (size_t)m->width;
    const float *a = m->rgb + 3 * ((size_t)y0 * w + (size_t)x0);
    const float *b = m->rgb + 3 * ((size_t)y0 * w + (size_t)x1);
    const float *c = m->rgb + 3 * ((size_t)y1 * w + (size_t)x0);
    const float *d = m->rgb + 3 * ((size_t)y1 * w + (size_t)x1);
    for (int k = 0; k < 3; k++) {
        float top = a[k] + fx * (b[k] - a[k]);
        float bottom = c[k] + fx * (d[k] - c[k]);
        out[k] = top + fy * (bottom - top);
    }
}

void ref_texture_sample(const ref_texture *t, float u, float v, float lod, float out[3])
{
    /* GL 4.6 section 8.14: lambda <= 0 magnifies from level 0; above, levels floor(lambda) and
     * floor(lambda) + 1 are mixed by the fraction, both clamped to the last level. */
    if (!(lod > 0.0f) || t->levels == 1) {
        bilinear(&t->mips[0], u, v, out);
        return;
    }
    float q = (float)(t->levels - 1);
    if (lod >= q) {
        bilinear(&t->mips[t->levels - 1], u, v, out);
        return;
    }
    int d1 = (int)floorf(lod);
    float f = lod - (float)d1;
    float a[3], b[3];
    bilinear(&t->mips[d1], u, v, a);
    bilinear(&t->mips[d1 + 1], u, v, b);
    for (int k = 0; k < 3; k++)
        out[k] = (1.0f - f) * a[k] + f * b[k];
}

void ref_texture_sample_footprint(const ref_texture *t, const float uv[2], const float duv_dx[2],
                                  const float duv_dy[2], int max_aniso, float out[3])
{
    float w = (float)t->mips[0].width, h = (float)t->mips[0].height;
    float px = hypotf(duv_dx[0] * w, duv_dx[1] * h);
    float py = hypotf(duv_dy[0] * w, duv_dy[1] * h);
    float pmax = fmaxf(px, py), pmin = fminf(px, py);
    if (!(pmax > 0.0f) || !isfinite(pmax)) {
        ref_texture_sample(t, uv[0], uv[1], 0.0f, out);
        return;
    }
    /* EXT_texture_filter_anisotropic: N = min(ceil(Pmax / Pmin), maxAniso) probes along the
     * major axis at offsets -1/2 + i / (N + 1), each at lambda = log2(Pmax / N). */
    int n = 1;
    if (max_aniso > 1) {
        float ratio = pmin > 0.0f ? ceilf(pmax / pmin) : (float)max_aniso;
        n = ratio < (float)max_aniso ? (int)ratio : max_aniso;
        if (n < 1)
            n = 1;
    }
    float lod = log2f(pmax / (float)n);
    if (n == 1) {
        ref_texture_sample(t, uv[0], uv[1], lod, out);
        return;
    }
    const float *axis = px >= py ? duv_dx : duv_dy;
    float sum[3] = {0, 0, 0};
    for (int i = 1; i <= n; i++) {
        float o = -0.5f + (float)i / (float)(n + 1), c[3];
        ref_texture_sample(t, uv[0] + o * axis[0], uv[1] + o * axis[1], lod, c);
        for (int k = 0; k < 3; k++)
            sum[k] += c[k];
    }
    for (int k = 0; k < 3; k++)
        out[k] = sum[k] / (float)n;
}
