/* Plain mesh data for the project file's primitives, each filling the unit box
 * [-0.5, 0.5]^3 (a plane: the unit square at z = 0 facing +Z), so that an object's size is
 * its scale. Counter-clockwise winding seen from outside; unit normals; UVs in [0, 1]. */
#ifndef RENDER_PRIMITIVES_H
#define RENDER_PRIMITIVES_H

#include "render/render.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rd_mesh_data {
    float *positions; /* 3 per vertex */
    float *normals;   /* 3 per vertex */
    float *uvs;       /* 2 per vertex */
    uint32_t *indices;
    int vertex_count, index_count;
} rd_mesh_data;

rd_result rd_mesh_data_box(rd_mesh_data *out);
rd_result rd_mesh_data_plane(rd_mesh_data *out);
rd_result rd_mesh_data_sphere(int segments, int rings, rd_mesh_data *out);
/* Axis Z, with caps. */
rd_result rd_mesh_data_cylinder(int segments, rd_mesh_data *out);
/* Axis Z; outer diameter 1; tube diameter = minor_ratio (0 < minor_ratio <= 0.5). */
rd_result rd_mesh_data_torus(float minor_ratio, int segments, int sides, rd_mesh_data *out);
void rd_mesh_data_free(rd_mesh_data *m);

/* The rd_mesh_desc that uploads this data. */
rd_mesh_desc rd_mesh_data_desc(const rd_mesh_data *m);

#ifdef __cplusplus
}
#endif
#endif
