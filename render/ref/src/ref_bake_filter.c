/* Noise filters of the bake. The lightmap: an edge-avoiding a-trous wavelet filter (Dammertz,
 * Sewtz, Hanika and Lensch 2010, "Edge-Avoiding A-Trous Wavelet Transform for fast Global
 * Illumination Filtering"): a 5x5 B3-spline kernel at steps 1, 2, 4, 8, confined to the texels of
 * one chart (one plane: the normal guide is the chart, the position guide the kernel's reach),
 * and stopped by the occlusion, so a contact shadow's edge stays sharp while flat light is
 * smoothed. Then the gutter, the texels off the polygon and those buried in a fixture take their
 * covered neighbours' mean,
 * so bilinear lookups at a polygon's edge see no black. The vertices: a few rounds of averaging
 * with the neighbours across each edge, weighted by how alike the normals are. */
#include "ref_bake_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const float B3[5] = {1.0f / 16, 1.0f / 4, 3.0f / 8, 1.0f / 4, 1.0f / 16};

#define SIGMA_OCCLUSION 0.08f
#define SIGMA_RELATIVE_LIGHT 0.6f

/* Whether texel i holds light of its surface: covered by the chart's polygon and not buried
 * in a fixture (ref_bake_gather.c); the others are filled from their neighbours. */
static int holds_light(const ref_bake *b, const unsigned char *buried, size_t i)
{
    return b->cover[i] && !(buried && buried[i]);
}

static void atrous_chart(const ref_bake *b, const unsigned char *buried, const ref_bake_chart *c,
                         const float *in, float *out, int step)
{
    int W = b->atlas_width;
    for (int y = c->y; y < c->y + c->height; y++)
        for (int x = c->x; x < c->x + c->width; x++) {
            size_t i = (size_t)y * (size_t)W + (size_t)x;
            const float *centre = in + 4 * i;
            if (!holds_light(b, buried, i)) {
                memcpy(out + 4 * i, centre, 4 * sizeof(float));
                continue;
            }
            float lum = 0.2126f * centre[0] + 0.7152f * centre[1] + 0.0722f * centre[2];
            float sum[4] = {0, 0, 0, 0}, wsum = 0.0f;
            for (int dy = -2; dy <= 2; dy++)
                for (int dx = -2; dx <= 2; dx++) {
                    int xx = x + dx * step, yy = y + dy * step;
                    if (xx < c->x || yy < c->y || xx >= c->x + c->width || yy >= c->y + c->height)
                        continue;
                    size_t j = (size_t)yy * (size_t)W + (size_t)xx;
                    if (!holds_light(b, buried, j))
                        continue;
                    const float *q = in + 4 * j;
                    float ql = 0.2126f * q[0] + 0.7152f * q[1] + 0.0722f * q[2];
                    float dao = fabsf(q[3] - centre[3]) / SIGMA_OCCLUSION;
                    float dl = fabsf(ql - lum) / (SIGMA_RELATIVE_LIGHT * (lum + ql) + 1e-6f);
                    float w = B3[dx + 2] * B3[dy + 2] * expf(-dao * dao - dl * dl);
                    for (int k = 0; k < 4; k++)
                        sum[k] += w * q[k];
                    wsum += w;
                }
            for (int k = 0; k < 4; k++)
                out[4 * i + (size_t)k] = wsum > 0.0f ? sum[k] / wsum : centre[k];
        }
}

/* Texels off the polygon (and the gutter) take the mean of their filled 8-neighbours, ring by
 * ring; what no ring reaches takes the chart's mean. */
static void dilate_chart(const ref_bake *b, const unsigned char *buried, const ref_bake_chart *c,
                         float *v, unsigned char *fill)
{
    int W = b->atlas_width;
    double mean[4] = {0, 0, 0, 0};
    int covered = 0;
    for (int y = c->y; y < c->y + c->height; y++)
        for (int x = c->x; x < c->x + c->width; x++) {
            size_t i = (size_t)y * (size_t)W + (size_t)x;
            fill[i] = (unsigned char)holds_light(b, buried, i);
            if (fill[i]) {
                covered++;
                for (int k = 0; k < 4; k++)
                    mean[k] += v[4 * i + (size_t)k];
            }
        }
    for (int ring = 0; ring < 4; ring++) {
        for (int y = c->y; y < c->y + c->height; y++)
            for (int x = c->x; x < c->x + c->width; x++) {
                size_t i = (size_t)y * (size_t)W + (size_t)x;
                if (fill[i])
                    continue;
                float sum[4] = {0, 0, 0, 0};
                int n = 0;
                for (int dy = -1; dy <= 1; dy++)
                    for (int dx = -1; dx <= 1; dx++) {
                        int xx = x + dx, yy = y + dy;
                        if (xx < c->x || yy < c->y || xx >= c->x + c->width ||
                            yy >= c->y + c->height)
                            continue;
                        size_t j = (size_t)yy * (size_t)W + (size_t)xx;
                        if (fill[j] == 0 || fill[j] > ring + 1)
                            continue;
                        for (int k = 0; k < 4; k++)
                            sum[k] += v[4 * j + (size_t)k];
                        n++;
                    }
                if (n) {
                    for (int k = 0; k < 4; k++)
                        v[4 * i + (size_t)k] = sum[k] / (float)n;
                    fill[i] = (unsigned char)(ring + 2);
                }
            }
    }
    for (int y = c->y; y < c->y + c->height; y++)
        for (int x = c->x; x < c->x + c->width; x++) {
            size_t i = (size_t)y * (size_t)W + (size_t)x;
            if (!fill[i])
                for (int k = 0; k < 4; k++)
                    v[4 * i + (size_t)k] = covered ? (float)(mean[k] / covered) : 0.0f;
        }
}

void ref_bake_filter_atlas(ref_bake *b, float *values, const unsigned char *buried)
{
    size_t texels = (size_t)b->atlas_width * (size_t)b->atlas_height;
    if (!texels || !b->chart_count)
        return;
    float *tmp = malloc(4 * texels * sizeof *tmp);
    unsigned char *fill = calloc(texels, 1);
    if (!tmp || !fill) {
        free(tmp);
        free(fill);
        return; /* unfiltered is still right, only noisier */
    }
    for (int ci = 0; ci < b->chart_count; ci++) {
        const ref_bake_chart *c = &b->charts[ci];
        float *src = values, *dst = tmp;
        for (int step = 1; step <= 8; step *= 2) {
            atrous_chart(b, buried, c, src, dst, step);
            float *t = src;
            src = dst;
            dst = t;
        }
        /* Four steps: the result is back in values. */
        dilate_chart(b, buried, c, values, fill);
    }
    free(tmp);
    free(fill);
}

void ref_bake_filter_vertices(const ref_scene *s, const ref_bake *b, const bake_layout *layout,
                              float *values, const unsigned char *changed)
{
    for (int m = 0; m < b->mesh_count; m++) {
        if (b->meshes[m].kind != REF_BAKE_VERTEX || (changed && !changed[m]))
            continue;
        const ref_mesh *mesh = &s->meshes[m];
        size_t nv = (size_t)mesh->vertex_count;
        float *acc = calloc(5 * nv + 1, sizeof *acc);
        float *unit = malloc(3 * nv * sizeof *unit + 1);
        if (!acc || !unit) {
            free(acc);
            free(unit);
            continue;
        }
        for (size_t v = 0; v < nv; v++) {
            const float *n = mesh->normals + 3 * v;
            float len = sqrtf(ref_dot(n, n));
            for (int k = 0; k < 3; k++)
                unit[3 * v + (size_t)k] = len > 0.0f ? n[k] / len : 0.0f;
        }
        float *val = values + 4 * (size_t)layout->vertex_base[m];
        for (int round = 0; round < 2; round++) {
            memset(acc, 0, 5 * nv * sizeof *acc);
            for (size_t v = 0; v < nv; v++) {
                for (int k = 0; k < 4; k++)
                    acc[5 * v + (size_t)k] = val[4 * v + (size_t)k];
                acc[5 * v + 4] = 1.0f;
            }
            for (int t = 0; t < mesh->triangle_count; t++)
                for (int e = 0; e < 3; e++) {
                    uint32_t i = mesh->indices[3 * t + (unsigned)e];
                    uint32_t j = mesh->indices[3 * t + (unsigned)(e + 1) % 3];
                    float c = ref_dot(unit + 3 * (size_t)i, unit + 3 * (size_t)j);
                    if (!(c > 0.5f))
                        continue;
                    float w = powf(c, 16.0f) * 0.5f;
                    for (int k = 0; k < 4; k++) {
                        acc[5 * i + (unsigned)k] += w * val[4 * j + (unsigned)k];
                        acc[5 * j + (unsigned)k] += w * val[4 * i + (unsigned)k];
                    }
                    acc[5 * i + 4] += w;
                    acc[5 * j + 4] += w;
                }
            for (size_t v = 0; v < nv; v++)
                for (int k = 0; k < 4; k++)
                    val[4 * v + (size_t)k] = acc[5 * v + (size_t)k] / acc[5 * v + 4];
        }
        free(acc);
        free(unit);
    }
}
