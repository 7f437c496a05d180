/* The room's geometry from its floor plan (app/design/room.h): the meshes both renderers draw
 * (through the render list, app/scene/render_list.h), so they see the same triangles, normals and
 * texture coordinates.
 *
 *  - floor and ceiling: the plan polygon, ear-clipped (any simple polygon: L-shapes, ...); the
 *    ceiling follows the sloped section where there is one;
 *  - each wall: its inside face with openings and niches cut out (split into rectangles around
 *    them; the top edge follows the slope), the reveals of openings through the wall
 *    thickness, the recess of each niche;
 *  - pre-walls: boxes (front, top, left, right faces) standing on the floor against a wall;
 *  - windows: a bright exterior panel behind the opening (emissive in the window's light
 *    colour) and a spot light just inside it shining into the room (RENDERING.md section 1
 *    lights, so both renderers light the same way); doors: a closed door leaf in the opening.
 *
 * Positions in metres (the renderers' unit), texture coordinates in repeats of the material's
 * real-world texture size, as in version 1: on a wall u grows to the right seen from inside
 * the room (from the wall's end corner), v up (-t); floors u = x, v = -y.
 * A version 1 room (4 corners, nothing else) gives the same six rectangles as version 1 did. */
#ifndef APP_ROOM_MESH_H
#define APP_ROOM_MESH_H

#include "app/project/project.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct app_room_mesh {
    char surface[96]; /* "floor", "ceiling", "wall:2", "prewall:wc-box", "window:0", ... */
    int material;     /* index into app_project.materials, or -1: use inline_material */
    app_material inline_material; /* window panels and door leaves */
    int light_stand_in; /* a window's exterior: its light comes in as the window's lights */
    float *positions, *normals, *uvs; /* 3, 3, 2 per vertex */
    uint32_t *indices;
    int vertex_count, index_count;
    int vertex_capacity, index_capacity;
} app_room_mesh;

typedef struct app_room_geometry {
    app_room_mesh *meshes;
    int mesh_count, mesh_capacity;
    app_light *lights; /* daylight through the windows; added after the project's lights */
    int light_count;
    double bounds_min[3], bounds_max[3]; /* the room's interior, metres */
} app_room_geometry;

/* Builds the geometry of p's plan (a project without a plan uses its room box). On failure
 * (out of memory) nothing stays allocated and err says so. */
app_result app_room_geometry_build(const app_project *p, app_room_geometry *out, char *err,
                                   size_t err_size);
void app_room_geometry_free(app_room_geometry *g);

/* Sum of the triangle areas of a mesh, m^2 (for tests and quantities). */
double app_room_mesh_area(const app_room_mesh *m);
/* The mesh named surface, NULL if none. */
const app_room_mesh *app_room_geometry_find(const app_room_geometry *g, const char *surface);

/* Ear clipping of a simple counter-clockwise polygon (n >= 3 points, x/y pairs): writes
 * 3 * (n - 2) indices into tri. Returns the number of triangles (n - 2), or -1 when the
 * polygon is degenerate (then a fan is written, so callers still get something drawable). */
int app_triangulate_polygon(const double *xy, int n, uint32_t *tri);

#ifdef __cplusplus
}
#endif
#endif
