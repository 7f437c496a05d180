/* app_room_geometry_build: the mesh builder, the plan's frames, the floor and the ceiling
 * (ear clipping; the sloped section by splitting triangles along its break lines). Walls,
 * openings, niches and pre-walls are in room_mesh_walls.c. */
#include "room_mesh_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void rm_wall_frame(const app_room_plan *plan, int i, rm_wall *w)
{
    app_point2 a = plan->corners[i], e = plan->corners[(i + 1) % plan->corner_count];
    double dx = e.x - a.x, dy = e.y - a.y, len = hypot(dx, dy);
    w->a[0] = a.x;
    w->a[1] = a.y;
    w->length = len;
    w->d[0] = len > 0 ? dx / len : 1;
    w->d[1] = len > 0 ? dy / len : 0;
    w->n[0] = -w->d[1];
    w->n[1] = w->d[0];
}

double rm_ceiling_height(const app_room_plan *plan, double x, double y)
{
    const app_ceiling_slope *s = &plan->slope;
    if (!s->present || s->wall < 0 || s->wall >= plan->corner_count || s->run_mm <= 0)
        return plan->height_mm;
    rm_wall w;
    rm_wall_frame(plan, s->wall, &w);
    double dist = (x - w.a[0]) * w.n[0] + (y - w.a[1]) * w.n[1];
    double h = s->knee_mm + (plan->height_mm - s->knee_mm) * dist / s->run_mm;
    return fmin(plan->height_mm, fmax(s->knee_mm, h));
}

app_room_mesh *rm_mesh(rm_build *b, const char *surface, int material)
{
    app_room_geometry *g = b->g;
    for (int i = 0; i < g->mesh_count; i++)
        if (!strcmp(g->meshes[i].surface, surface) && g->meshes[i].material == material &&
            material >= 0)
            return &g->meshes[i];
    if (g->mesh_count == g->mesh_capacity) {
        int cap = g->mesh_capacity ? 2 * g->mesh_capacity : 16;
        app_room_mesh *m = realloc(g->meshes, (size_t)cap * sizeof *m);
        if (!m) {
            b->oom = 1;
            return NULL;
        }
        g->meshes = m;
        g->mesh_capacity = cap;
    }
    app_room_mesh *m = &g->meshes[g->mesh_count++];
    memset(m, 0, sizeof *m);
    snprintf(m->surface, sizeof m->surface, "%s", surface);
    m->material = material;
    return m;
}

void rm_texture_size(const rm_build *b, const app_room_mesh *m, double out[2])
{
    const app_material *am = m->material >= 0 && m->material < b->p->material_count
                                 ? &b->p->materials[m->material]
                                 : &m->inline_material;
    out[0] = am->texture_size_mm[0] > 0 ? am->texture_size_mm[0] : 1000.0;
    out[1] = am->texture_size_mm[1] > 0 ? am->texture_size_mm[1] : 1000.0;
}

static int grow(rm_build *b, void **ptr, int *cap, int need, size_t elem)
{
    if (need <= *cap)
        return 1;
    int c = *cap ? *cap : 64;
    while (c < need)
        c *= 2;
    void *q = realloc(*ptr, (size_t)c * elem);
    if (!q) {
        b->oom = 1;
        return 0;
    }
    *ptr = q;
    *cap = c;
    return 1;
}

int rm_vertex(rm_build *b, app_room_mesh *m, const double pos_mm[3], const double n[3],
              const double uv[2])
{
    if (!m || b->oom)
        return -1;
    int cap = m->vertex_capacity;
    int cap_n = cap, cap_uv = cap;
    if (!grow(b, (void **)&m->positions, &cap, m->vertex_count + 1, 3 * sizeof(float)) ||
        !grow(b, (void **)&m->normals, &cap_n, m->vertex_count + 1, 3 * sizeof(float)) ||
        !grow(b, (void **)&m->uvs, &cap_uv, m->vertex_count + 1, 2 * sizeof(float)))
        return -1;
    m->vertex_capacity = cap;
    int i = m->vertex_count++;
    for (int k = 0; k < 3; k++) {
        m->positions[3 * i + k] = (float)(pos_mm[k] * 1e-3);
        m->normals[3 * i + k] = (float)n[k];
    }
    m->uvs[2 * i] = (float)uv[0];
    m->uvs[2 * i + 1] = (float)uv[1];
    return i;
}

static void push_index(rm_build *b, app_room_mesh *m, int a, int c, int d)
{
    if (!grow(b, (void **)&m->indices, &m->index_capacity, m->index_count + 3, sizeof(uint32_t)))
        return;
    m->indices[m->index_count++] = (uint32_t)a;
    m->indices[m->index_count++] = (uint32_t)c;
    m->indices[m->index_count++] = (uint32_t)d;
}

void rm_triangle(rm_build *b, app_room_mesh *m, int i0, int i1, int i2, const double n[3])
{
    if (!m || b->oom || i0 < 0 || i1 < 0 || i2 < 0)
        return;
    const float *p = m->positions;
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = (double)p[3 * i1 + k] - p[3 * i0 + k];
        e2[k] = (double)p[3 * i2 + k] - p[3 * i0 + k];
    }
    double c[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    if (c[0] * n[0] + c[1] * n[1] + c[2] * n[2] < 0)
        push_index(b, m, i0, i2, i1);
    else
        push_index(b, m, i0, i1, i2);
}

void rm_quad(rm_build *b, app_room_mesh *m, const double p[4][3], const double uv[4][2],
             const double n[3])
{
    int v[4];
    for (int k = 0; k < 4; k++)
        v[k] = rm_vertex(b, m, p[k], n, uv[k]);
    rm_triangle(b, m, v[0], v[1], v[2], n);
    rm_triangle(b, m, v[0], v[2], v[3], n);
}

void rm_rect(rm_build *b, app_room_mesh *m, const double origin[3], const double u[3], double ulen,
             const double v[3], double vlen, double u0, double v0)
{
    double tex[2];
    if (!m)
        return;
    rm_texture_size(b, m, tex);
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    int idx[4];
    for (int c = 0; c < 4; c++) {
        double su = c & 1, sv = c >> 1, pos[3];
        for (int k = 0; k < 3; k++)
            pos[k] = origin[k] + su * ulen * u[k] + sv * vlen * v[k];
        double uv[2] = {(u0 + su * ulen) / tex[0], -(v0 + sv * vlen) / tex[1]};
        idx[c] = rm_vertex(b, m, pos, n, uv);
    }
    if (b->oom)
        return;
    push_index(b, m, idx[0], idx[1], idx[3]);
    push_index(b, m, idx[0], idx[3], idx[2]);
}

/* ---- ear clipping --------------------------------------------------------------------------- */

static double cross3(const double *xy, int a, int b, int c)
{
    return (xy[2 * b] - xy[2 * a]) * (xy[2 * c + 1] - xy[2 * a + 1]) -
           (xy[2 * b + 1] - xy[2 * a + 1]) * (xy[2 * c] - xy[2 * a]);
}

/* p inside or on triangle abc (counter-clockwise). */
static int in_triangle(const double *xy, int a, int b, int c, int p)
{
    return cross3(xy, a, b, p) >= 0 && cross3(xy, b, c, p) >= 0 && cross3(xy, c, a, p) >= 0;
}

int app_triangulate_polygon(const double *xy, int n, uint32_t *tri)
{
    if (n < 3)
        return -1;
    int *v = malloc((size_t)n * sizeof *v);
    if (!v)
        return -1;
    for (int i = 0; i < n; i++)
        v[i] = i;
    int m = n, t = 0, guard = 0, ok = 1;
    /* Ears are looked for from the second vertex on, so a convex quad is cut along its
     * 0-2 diagonal like version 1's rectangles. */
    int i = 1;
    while (m > 3) {
        int a = v[(i + m - 1) % m], c = v[i % m], d = v[(i + 1) % m];
        int ear = cross3(xy, a, c, d) > 0;
        for (int k = 0; ear && k < m; k++) {
            int q = v[k];
            if (q == a || q == c || q == d)
                continue;
            /* A reflex corner touching the ear blocks it; coincident points do not. */
            if (in_triangle(xy, a, c, d, q) &&
                !((xy[2 * q] == xy[2 * a] && xy[2 * q + 1] == xy[2 * a + 1]) ||
                  (xy[2 * q] == xy[2 * d] && xy[2 * q + 1] == xy[2 * d + 1])))
                ear = 0;
        }
        if (ear) {
            tri[3 * t] = (uint32_t)a;
            tri[3 * t + 1] = (uint32_t)c;
            tri[3 * t + 2] = (uint32_t)d;
            t++;
            memmove(&v[i % m], &v[i % m + 1], (size_t)(m - i % m - 1) * sizeof *v);
            m--;
            guard = 0;
            i = i % m;
            if (i == 0)
                i = 1 % m;
        } else {
            i = (i + 1) % m;
            if (++guard > m) { /* no ear: degenerate input; finish with a fan */
                ok = 0;
                break;
            }
        }
    }
    for (int k = 1; k + 1 < m; k++) {
        tri[3 * t] = (uint32_t)v[0];
        tri[3 * t + 1] = (uint32_t)v[k];
        tri[3 * t + 2] = (uint32_t)v[k + 1];
        t++;
    }
    free(v);
    return ok ? t : -1;
}

/* ---- floor and ceiling ---------------------------------------------------------------------- */

/* One ceiling triangle (plan points), cut along the slope's break lines so the piecewise
 * linear height is exact, each piece lifted to rm_ceiling_height and facing down. */
static void ceiling_triangle(rm_build *b, app_room_mesh *m, const double tri[3][2], double y_max,
                             int cut)
{
    const app_room_plan *plan = b->plan;
    const app_ceiling_slope *s = &plan->slope;
    if (cut < 2 && s->present) {
        rm_wall w;
        rm_wall_frame(plan, s->wall, &w);
        double at = cut == 0 ? 0.0 : s->run_mm; /* the line dist = at */
        double dist[3];
        int above = 0;
        for (int k = 0; k < 3; k++) {
            dist[k] = (tri[k][0] - w.a[0]) * w.n[0] + (tri[k][1] - w.a[1]) * w.n[1] - at;
            above += dist[k] > 1e-9;
        }
        int below = 0;
        for (int k = 0; k < 3; k++)
            below += dist[k] < -1e-9;
        if (above && below) {
            /* Clip the triangle against both half-planes (Sutherland-Hodgman); each side is
             * a convex polygon of 3 or 4 points, fanned. */
            for (int side = 0; side < 2; side++) {
                double poly[4][2];
                int np = 0;
                for (int k = 0; k < 3; k++) {
                    int k1 = (k + 1) % 3;
                    double dk = side ? -dist[k] : dist[k], dk1 = side ? -dist[k1] : dist[k1];
                    if (dk >= 0 && np < 4) {
                        poly[np][0] = tri[k][0];
                        poly[np][1] = tri[k][1];
                        np++;
                    }
                    if ((dk > 0 && dk1 < 0) || (dk < 0 && dk1 > 0)) {
                        double f = dk / (dk - dk1);
                        if (np < 4) {
                            poly[np][0] = tri[k][0] + f * (tri[k1][0] - tri[k][0]);
                            poly[np][1] = tri[k][1] + f * (tri[k1][1] - tri[k][1]);
                            np++;
                        }
                    }
                }
                for (int k = 1; k + 1 < np; k++) {
                    const double piece[3][2] = {{poly[0][0], poly[0][1]},
                                                {poly[k][0], poly[k][1]},
                                                {poly[k + 1][0], poly[k + 1][1]}};
                    ceiling_triangle(b, m, piece, y_max, cut + 1);
                }
            }
            return;
        }
        ceiling_triangle(b, m, tri, y_max, cut + 1);
        return;
    }
    double p[3][3], tex[2];
    rm_texture_size(b, m, tex);
    for (int k = 0; k < 3; k++) {
        p[k][0] = tri[k][0];
        p[k][1] = tri[k][1];
        p[k][2] = rm_ceiling_height(plan, tri[k][0], tri[k][1]);
    }
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = p[1][k] - p[0][k];
        e2[k] = p[2][k] - p[0][k];
    }
    double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len == 0)
        return;
    double sign = n[2] > 0 ? -1.0 : 1.0; /* facing down, into the room */
    for (int k = 0; k < 3; k++)
        n[k] *= sign / len;
    int v[3];
    for (int k = 0; k < 3; k++) {
        double uv[2] = {p[k][0] / tex[0], -(y_max - p[k][1]) / tex[1]};
        v[k] = rm_vertex(b, m, p[k], n, uv);
    }
    rm_triangle(b, m, v[0], v[1], v[2], n);
}

void rm_add_floor_ceiling(rm_build *b)
{
    const app_room_plan *plan = b->plan;
    int n = plan->corner_count;
    if (n < 3)
        return;
    double *xy = calloc((size_t)n * 2, sizeof *xy);
    uint32_t *tri = malloc((size_t)(n - 2) * 3 * sizeof *tri);
    if (!xy || !tri) {
        b->oom = 1;
        free(xy);
        free(tri);
        return;
    }
    double y_max = plan->corners[0].y;
    for (int i = 0; i < n; i++)
        y_max = fmax(y_max, plan->corners[i].y);

    /* Floor: u = x, v = -y (version 1's floor rectangle). */
    app_room_mesh *floor = rm_mesh(b, "floor", b->p->room.floor_material);
    double tex[2] = {1000, 1000};
    if (floor)
        rm_texture_size(b, floor, tex);
    for (int i = 0; i < n; i++) {
        xy[2 * i] = plan->corners[i].x;
        xy[2 * i + 1] = plan->corners[i].y;
    }
    int count = app_triangulate_polygon(xy, n, tri);
    if (count < 0)
        count = n - 2;
    const double up[3] = {0, 0, 1};
    int base = floor ? floor->vertex_count : 0;
    for (int i = 0; i < n && floor; i++) {
        double pos[3] = {xy[2 * i], xy[2 * i + 1], 0}, uv[2] = {pos[0] / tex[0], -pos[1] / tex[1]};
        rm_vertex(b, floor, pos, up, uv);
    }
    for (int t = 0; t < count && floor && !b->oom; t++)
        rm_triangle(b, floor, base + (int)tri[3 * t], base + (int)tri[3 * t + 1],
                    base + (int)tri[3 * t + 2], up);

    /* Ceiling: the polygon in reverse order (counter-clockwise seen from below), so a
     * rectangle is cut along the same diagonal as version 1's ceiling. */
    app_room_mesh *ceiling = rm_mesh(b, "ceiling", b->p->room.ceiling_material);
    for (int i = 0; i < n; i++) {
        xy[2 * i] = plan->corners[n - 1 - i].x;
        xy[2 * i + 1] = -plan->corners[n - 1 - i].y; /* mirrored: reversed order stays CCW */
    }
    count = app_triangulate_polygon(xy, n, tri);
    if (count < 0)
        count = n - 2;
    if (!plan->slope.present && ceiling) {
        /* flat: shared corners, as the floor */
        const double down[3] = {0, 0, -1};
        rm_texture_size(b, ceiling, tex);
        base = ceiling->vertex_count;
        for (int i = 0; i < n; i++) {
            double pos[3] = {xy[2 * i], -xy[2 * i + 1], plan->height_mm};
            double uv[2] = {pos[0] / tex[0], -(y_max - pos[1]) / tex[1]};
            rm_vertex(b, ceiling, pos, down, uv);
        }
        for (int t = 0; t < count && !b->oom; t++)
            rm_triangle(b, ceiling, base + (int)tri[3 * t], base + (int)tri[3 * t + 1],
                        base + (int)tri[3 * t + 2], down);
        count = 0;
    }
    for (int t = 0; t < count && ceiling && !b->oom; t++) {
        double pts[3][2];
        for (int k = 0; k < 3; k++) {
            pts[k][0] = xy[2 * tri[3 * t + k]];
            pts[k][1] = -xy[2 * tri[3 * t + k] + 1];
        }
        ceiling_triangle(b, ceiling, pts, y_max, 0);
    }
    free(xy);
    free(tri);
}

/* ---- the whole room ------------------------------------------------------------------------- */

void app_room_geometry_free(app_room_geometry *g)
{
    if (!g)
        return;
    for (int i = 0; i < g->mesh_count; i++) {
        free(g->meshes[i].positions);
        free(g->meshes[i].normals);
        free(g->meshes[i].uvs);
        free(g->meshes[i].indices);
    }
    free(g->meshes);
    free(g->lights);
    memset(g, 0, sizeof *g);
}

app_result app_room_geometry_build(const app_project *p, app_room_geometry *out, char *err,
                                   size_t err_size)
{
    memset(out, 0, sizeof *out);
    app_room_plan box;
    app_point2 box_corners[4];
    const app_room_plan *plan = &p->plan;
    if (plan->corner_count < 3 || !plan->corners) {
        /* A project built in memory by version 1 code: its room box. */
        memset(&box, 0, sizeof box);
        double w = p->room.width_mm, d = p->room.depth_mm;
        box_corners[0] = (app_point2){0, 0};
        box_corners[1] = (app_point2){w, 0};
        box_corners[2] = (app_point2){w, d};
        box_corners[3] = (app_point2){0, d};
        box.corners = box_corners;
        box.corner_count = 4;
        box.height_mm = p->room.height_mm;
        box.wall_thickness_mm = APP_ROOM_DEFAULT_WALL_THICKNESS_MM;
        plan = &box;
    }
    rm_build b = {p, plan, out, 0};
    out->bounds_min[0] = out->bounds_max[0] = plan->corners[0].x * 1e-3;
    out->bounds_min[1] = out->bounds_max[1] = plan->corners[0].y * 1e-3;
    for (int i = 1; i < plan->corner_count; i++) {
        out->bounds_min[0] = fmin(out->bounds_min[0], plan->corners[i].x * 1e-3);
        out->bounds_max[0] = fmax(out->bounds_max[0], plan->corners[i].x * 1e-3);
        out->bounds_min[1] = fmin(out->bounds_min[1], plan->corners[i].y * 1e-3);
        out->bounds_max[1] = fmax(out->bounds_max[1], plan->corners[i].y * 1e-3);
    }
    out->bounds_min[2] = 0;
    out->bounds_max[2] = plan->height_mm * 1e-3;
    rm_add_floor_ceiling(&b);
    if (!b.oom)
        rm_add_walls(&b);
    if (!b.oom)
        rm_add_prewalls(&b);
    if (b.oom) {
        app_room_geometry_free(out);
        snprintf(err, err_size, "%s: out of memory building the room's geometry",
                 p->path[0] ? p->path : "<project>");
        return APP_ERR_OUT_OF_MEMORY;
    }
    return APP_OK;
}

double app_room_mesh_area(const app_room_mesh *m)
{
    double area = 0;
    for (int t = 0; t + 2 < m->index_count; t += 3) {
        const float *a = &m->positions[3 * m->indices[t]],
                    *c = &m->positions[3 * m->indices[t + 1]],
                    *d = &m->positions[3 * m->indices[t + 2]];
        double e1[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]},
               e2[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        double x = e1[1] * e2[2] - e1[2] * e2[1], y = e1[2] * e2[0] - e1[0] * e2[2],
               z = e1[0] * e2[1] - e1[1] * e2[0];
        area += 0.5 * sqrt(x * x + y * y + z * z);
    }
    return area;
}

const app_room_mesh *app_room_geometry_find(const app_room_geometry *g, const char *surface)
{
    for (int i = 0; i < g->mesh_count; i++)
        if (!strcmp(g->meshes[i].surface, surface))
            return &g->meshes[i];
    return NULL;
}
