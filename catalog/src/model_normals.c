/* Vertex normals for primitives that have none: the area-weighted average of the faces around
 * each vertex (the cross product of two edges is the face normal scaled by twice its area). */
#include "model_internal.h"

#include <math.h>
#include <stdlib.h>

int cat_normals_generate(const float *positions, int vertex_count, const unsigned *indices,
                         int index_count, const unsigned char *replace, float *normals)
{
    double *acc = calloc((size_t)vertex_count * 3 + 1, sizeof *acc);
    if (!acc)
        return 0;
    {
        for (int t = 0; t + 2 < index_count; t += 3) {
            const float *a = positions + 3 * (size_t)indices[t];
            const float *b = positions + 3 * (size_t)indices[t + 1];
            const float *c = positions + 3 * (size_t)indices[t + 2];
            double e1[3] = {(double)b[0] - a[0], (double)b[1] - a[1], (double)b[2] - a[2]};
            double e2[3] = {(double)c[0] - a[0], (double)c[1] - a[1], (double)c[2] - a[2]};
            double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                           e1[0] * e2[1] - e1[1] * e2[0]};
            for (int k = 0; k < 3; k++)
                for (int j = 0; j < 3; j++)
                    acc[3 * (size_t)indices[t + k] + (size_t)j] += n[j];
        }
    }
    for (int v = 0; v < vertex_count; v++) {
        if (replace && !replace[v])
            continue;
        float *out = normals + 3 * (size_t)v;
        double x = acc[3 * (size_t)v], y = acc[3 * (size_t)v + 1], z = acc[3 * (size_t)v + 2];
        double len = sqrt(x * x + y * y + z * z);
        if (len > 0.0 && isfinite(len)) {
            out[0] = (float)(x / len);
            out[1] = (float)(y / len);
            out[2] = (float)(z / len);
        } else {
            out[0] = 0.0f;
            out[1] = 0.0f;
            out[2] = 1.0f;
        }
    }
    free(acc);
    return 1;
}
