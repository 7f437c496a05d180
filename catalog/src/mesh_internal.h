/* Internals of catalog/mesh_lod.h: the C side (mesh_lod.c, mesh_validate.c) and the thin
 * OpenMesh adapter (mesh_openmesh.cpp), which only decimates index lists. */
#ifndef CATALOG_MESH_INTERNAL_H
#define CATALOG_MESH_INTERNAL_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cat_decimate_result {
    unsigned *triangles; /* 3 per triangle, indices into the input positions; malloc'ed */
    int triangle_count;
    int refused; /* input triangles OpenMesh could not add (non-manifold): passed through */
} cat_decimate_result;

/* Decimates the welded mesh (positions: 3 floats per vertex; triangles: 3 indices each, all in
 * range, no repeated corner) to about target_triangles with OpenMesh's quadric decimater.
 * Triangles OpenMesh refuses (a complex edge or vertex) are appended unchanged. Returns 0 on
 * success, else nonzero with a message in what (out of memory, an exception's text). */
int cat_openmesh_decimate(const float *positions, int vertex_count, const unsigned *triangles,
                          int triangle_count, int target_triangles, cat_decimate_result *out,
                          char *what, size_t what_size);

/* Welds vertices at exactly the same position: map[v] (vertex_count ints, caller's) gets each
 * vertex's welded number, *first (malloc'ed, *welded_count ints) the first input vertex of
 * each welded one. Returns 0 when out of memory. */
int cat_mesh_weld(const float *positions, int vertex_count, int *map, int **first,
                  int *welded_count);

/* 1 when triangle (a, b, c) has a repeated corner or (near) zero area: the sine of its angle
 * at a is below 1e-7, relative, so the test does not depend on the model's scale. */
int cat_triangle_degenerate(const float *positions, unsigned a, unsigned b, unsigned c);

#ifdef __cplusplus
}
#endif

#endif
