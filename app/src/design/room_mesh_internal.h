/* Shared by room_mesh*.c: the mesh builder and the plan's geometry in millimetres. */
#ifndef APP_ROOM_MESH_INTERNAL_H
#define APP_ROOM_MESH_INTERNAL_H

#include "app/design/room_mesh.h"

typedef struct rm_build {
    const app_project *p;
    const app_room_plan *plan; /* p->plan, or a 4-corner plan made from p->room */
    app_room_geometry *g;
    int oom; /* sticky: an allocation failed */
} rm_build;

/* A wall's frame: point(s, t) = a + s * d + t * z; n = d turned 90 degrees counter-clockwise
 * (into the room). */
typedef struct rm_wall {
    double a[2], d[2], n[2];
    double length;
} rm_wall;

void rm_wall_frame(const app_room_plan *plan, int i, rm_wall *w);
/* The ceiling height (mm) above plan point (x, y): the flat height, or on the sloped section
 * knee + (height - knee) * distance / run, clamped to [knee, height]. */
double rm_ceiling_height(const app_room_plan *plan, double x, double y);

app_room_mesh *rm_mesh(rm_build *b, const char *surface, int material);
/* Texture size (mm) of a mesh's material. */
void rm_texture_size(const rm_build *b, const app_room_mesh *m, double out[2]);
/* Adds a vertex (position mm, unit normal, uv in repeats); its index, or -1 out of memory. */
int rm_vertex(rm_build *b, app_room_mesh *m, const double pos_mm[3], const double n[3],
              const double uv[2]);
/* A triangle of three added vertices, wound so that its face normal agrees with n. */
void rm_triangle(rm_build *b, app_room_mesh *m, int i0, int i1, int i2, const double n[3]);
/* A planar quad p0 p1 p2 p3 (in order around it) with its uvs, facing n. */
void rm_quad(rm_build *b, app_room_mesh *m, const double p[4][3], const double uv[4][2],
             const double n[3]);
/* Version 1's rectangle: origin + su * ulen * u + sv * vlen * v, normal u x v, uv =
 * (u0 + su * ulen) / tex_u, -(v0 + sv * vlen) / tex_v; indices 0 1 3, 0 3 2. */
void rm_rect(rm_build *b, app_room_mesh *m, const double origin[3], const double u[3], double ulen,
             const double v[3], double vlen, double u0, double v0);

void rm_add_floor_ceiling(rm_build *b);
void rm_add_walls(rm_build *b);
void rm_add_prewalls(rm_build *b);
/* The point s along wall w, t above the floor, off in front of its inside face (negative:
 * into the wall), mm. */
void rm_wall_point(const rm_wall *w, double s, double t, double off, double out[3]);
/* A flat panel in the plane `off` from the inside face, facing into the room. */
void rm_panel(rm_build *b, app_room_mesh *m, const rm_wall *w, double s0, double s1, double t0,
              double t1, double off);
/* A window's exterior behind the opening (surface `name`, bands of it `name:N`) and the
 * daylight it lets in (room_mesh_window.c); T the wall's thickness. */
void rm_add_window(rm_build *b, const app_opening *o, const rm_wall *w, double T, const char *name);

#endif
