/* Welding by position: glTF meshes split a vertex wherever its normal or UV changes (hard
 * edges, UV seams), which looks like an open edge to anything that follows the topology. */
#include "mesh_internal.h"

#include <stdlib.h>
#include <string.h>

typedef struct keyed {
    float p[3];
    int index;
} keyed;

static int by_position(const void *a, const void *b)
{
    const keyed *x = a, *y = b;
    for (int k = 0; k < 3; k++)
        if (x->p[k] != y->p[k])
            return x->p[k] < y->p[k] ? -1 : 1;
    return x->index < y->index ? -1 : x->index > y->index;
}

int cat_mesh_weld(const float *positions, int vertex_count, int *map, int **first,
                  int *welded_count)
{
    *first = NULL;
    *welded_count = 0;
    keyed *k = malloc(((size_t)vertex_count + 1) * sizeof *k);
    int *firsts = malloc(((size_t)vertex_count + 1) * sizeof *firsts);
    if (!k || !firsts) {
        free(k);
        free(firsts);
        return 0;
    }
    for (int v = 0; v < vertex_count; v++) {
        memcpy(k[v].p, positions + 3 * (size_t)v, sizeof k[v].p);
        /* -0 and +0 are one place (they compare equal, but keep the sort strict) */
        for (int j = 0; j < 3; j++)
            if (k[v].p[j] == 0.0f)
                k[v].p[j] = 0.0f;
        k[v].index = v;
    }
    qsort(k, (size_t)vertex_count, sizeof *k, by_position);
    int n = 0;
    for (int i = 0; i < vertex_count; i++) {
        if (i == 0 || memcmp(k[i].p, k[i - 1].p, sizeof k[i].p) != 0)
            firsts[n++] = k[i].index; /* sorted by index within a position: the first */
        map[k[i].index] = n - 1;
    }
    free(k);
    *first = firsts;
    *welded_count = n;
    return 1;
}
