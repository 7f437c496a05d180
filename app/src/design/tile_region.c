/* Surface regions (app/design/tile_layout.h): an outline and holes, owned by the region. */
#include "tile_layout_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define REGION_MAX_POINTS 100000

void app_surface_region_init(app_surface_region *r, const char *surface, app_surface_kind kind)
{
    memset(r, 0, sizeof *r);
    snprintf(r->surface, sizeof r->surface, "%s", surface ? surface : "");
    r->kind = kind;
}

static app_result copy_points(const app_point2 *points, int count, app_polygon *out,
                              const char *what, char *err, size_t err_size)
{
    if (!points || count < 3 || count > REGION_MAX_POINTS) {
        tl_set_err(err, err_size, "tile_layout", "%s: needs 3..%d points, got %d", what,
                   REGION_MAX_POINTS, count);
        return APP_ERR_SCHEMA;
    }
    for (int i = 0; i < count; i++)
        if (!isfinite(points[i].x) || !isfinite(points[i].y) || fabs(points[i].x) > 1e8 ||
            fabs(points[i].y) > 1e8) {
            tl_set_err(err, err_size, "tile_layout", "%s: point %d is not a finite coordinate",
                       what, i);
            return APP_ERR_SCHEMA;
        }
    if (fabs(app_polygon_signed_area(points, count)) < 1e-6) {
        tl_set_err(err, err_size, "tile_layout", "%s: has no area", what);
        return APP_ERR_SCHEMA;
    }
    app_point2 *p = malloc(sizeof *p * (size_t)count);
    if (!p) {
        tl_set_err(err, err_size, "tile_layout", "%s: out of memory", what);
        return APP_ERR_OUT_OF_MEMORY;
    }
    memcpy(p, points, sizeof *p * (size_t)count);
    out->points = p;
    out->count = count;
    return APP_OK;
}

app_result app_region_set_outer(app_surface_region *r, const app_point2 *points, int count,
                                char *err, size_t err_size)
{
    app_polygon poly = {0};
    app_result res = copy_points(points, count, &poly, "outline", err, err_size);
    if (res != APP_OK)
        return res;
    if (app_polygon_signed_area(poly.points, poly.count) < 0)
        for (int i = 0, j = count - 1; i < j; i++, j--) {
            app_point2 t = poly.points[i];
            poly.points[i] = poly.points[j];
            poly.points[j] = t;
        }
    free(r->outer.points);
    r->outer = poly;
    return APP_OK;
}

app_result app_region_add_hole(app_surface_region *r, const app_point2 *points, int count,
                               app_hole_kind kind, const char *name, char *err, size_t err_size)
{
    if (r->hole_count == r->hole_capacity) {
        int cap = r->hole_capacity ? 2 * r->hole_capacity : 8;
        if (cap > REGION_MAX_POINTS) {
            tl_set_err(err, err_size, "tile_layout", "too many holes");
            return APP_ERR_SCHEMA;
        }
        app_region_hole *h = realloc(r->holes, sizeof *h * (size_t)cap);
        if (!h) {
            tl_set_err(err, err_size, "tile_layout", "out of memory");
            return APP_ERR_OUT_OF_MEMORY;
        }
        r->holes = h;
        r->hole_capacity = cap;
    }
    app_region_hole *h = &r->holes[r->hole_count];
    memset(h, 0, sizeof *h);
    char what[96];
    snprintf(what, sizeof what, "hole %d", r->hole_count);
    app_result res = copy_points(points, count, &h->polygon, what, err, err_size);
    if (res != APP_OK)
        return res;
    h->kind = kind;
    snprintf(h->name, sizeof h->name, "%s", name ? name : "");
    r->hole_count++;
    return APP_OK;
}

static void rect_points(double s0, double t0, double s1, double t1, app_point2 p[4])
{
    double a = fmin(s0, s1), b = fmax(s0, s1), c = fmin(t0, t1), d = fmax(t0, t1);
    p[0] = (app_point2){a, c};
    p[1] = (app_point2){b, c};
    p[2] = (app_point2){b, d};
    p[3] = (app_point2){a, d};
}

app_result app_region_set_outer_rect(app_surface_region *r, double s0, double t0, double s1,
                                     double t1, char *err, size_t err_size)
{
    app_point2 p[4];
    rect_points(s0, t0, s1, t1, p);
    return app_region_set_outer(r, p, 4, err, err_size);
}

app_result app_region_add_hole_rect(app_surface_region *r, double s0, double t0, double s1,
                                    double t1, app_hole_kind kind, const char *name, char *err,
                                    size_t err_size)
{
    app_point2 p[4];
    rect_points(s0, t0, s1, t1, p);
    return app_region_add_hole(r, p, 4, kind, name, err, err_size);
}

void app_surface_region_free(app_surface_region *r)
{
    if (!r)
        return;
    free(r->outer.points);
    for (int i = 0; i < r->hole_count; i++)
        free(r->holes[i].polygon.points);
    free(r->holes);
    memset(r, 0, sizeof *r);
}

double app_surface_region_area(const app_surface_region *r)
{
    if (!r || r->outer.count < 3)
        return 0.0;
    /* Holes may overlap and stick out, so the union is taken by the winding rule of the
     * decomposition; without holes it is the shoelace formula. */
    if (r->hole_count == 0)
        return fabs(app_polygon_signed_area(r->outer.points, r->outer.count));
    tl_ring *rings = malloc(sizeof *rings * (size_t)(r->hole_count + 1));
    if (!rings)
        return NAN;
    rings[0] = (tl_ring){r->outer.points, r->outer.count, 1};
    for (int i = 0; i < r->hole_count; i++)
        rings[i + 1] = (tl_ring){r->holes[i].polygon.points, r->holes[i].polygon.count, -1};
    tl_decomp d;
    double area = NAN;
    if (tl_decompose(rings, r->hole_count + 1, &d) == 0)
        area = d.area;
    tl_decomp_free(&d);
    free(rings);
    return area;
}
