/* The elastic edge joint (docs/tiling.md "Edge joint"): the tiled region is the surface shrunk
 * by the joint along every boundary (walls, floor and ceiling junctions, openings, covered
 * areas, niches), so the gap a tiler leaves open for silicone is never counted as a cut. */
#include "tile_layout_internal.h"

#include <math.h>
#include <stdlib.h>

/* Ring p moved by d along each edge's left normal (inward for a counter-clockwise ring), the
 * corners at the intersection of the moved edges (a mitre, capped at 4 d for sharp corners). */
static void offset_ring(const app_point2 *p, int n, double d, app_point2 *out)
{
    for (int i = 0; i < n; i++) {
        app_point2 a = p[(i + n - 1) % n], b = p[i], c = p[(i + 1) % n];
        double ax = b.x - a.x, ay = b.y - a.y, cx = c.x - b.x, cy = c.y - b.y;
        double la = hypot(ax, ay), lc = hypot(cx, cy);
        if (la == 0 || lc == 0) {
            out[i] = b;
            continue;
        }
        ax /= la, ay /= la, cx /= lc, cy /= lc;
        /* left normals (-dy, dx); the mitre direction is their sum over 1 + cos */
        double nx = -ay - cy, ny = ax + cx, k = 1.0 + (ax * cx + ay * cy);
        if (k < 1.0 / 16) { /* a spike: cap the mitre */
            double len = hypot(nx, ny);
            out[i] = len > 0 ? (app_point2){b.x + 4 * d * nx / len, b.y + 4 * d * ny / len} : b;
            continue;
        }
        out[i] = (app_point2){b.x + d * nx / k, b.y + d * ny / k};
    }
}

app_result tl_region_shrink(const app_surface_region *in, double e, app_surface_region *out,
                            char *err, size_t err_size)
{
    app_surface_region_init(out, in->surface, in->kind);
    int n = in->outer.count;
    app_point2 *buf = malloc((size_t)(n > 0 ? n : 1) * sizeof *buf);
    if (!buf) {
        tl_set_err(err, err_size, "tile_layout", "out of memory");
        return APP_ERR_OUT_OF_MEMORY;
    }
    offset_ring(in->outer.points, n, e, buf); /* the outline is counter-clockwise: inward */
    app_result r = APP_OK;
    if (app_polygon_signed_area(buf, n) <= 0) {
        tl_set_err(err, err_size, "tile_layout", "%s: narrower than twice the edge joint %g mm",
                   in->surface, e);
        r = APP_ERR_SCHEMA;
    } else
        r = app_region_set_outer(out, buf, n, err, err_size);
    for (int h = 0; h < in->hole_count && r == APP_OK; h++) {
        const app_polygon *q = &in->holes[h].polygon;
        app_point2 *grown = realloc(buf, (size_t)q->count * sizeof *buf);
        if (!grown) {
            tl_set_err(err, err_size, "tile_layout", "out of memory");
            r = APP_ERR_OUT_OF_MEMORY;
            break;
        }
        buf = grown;
        /* a hole grows: outward is to the right of a counter-clockwise ring */
        double sign = app_polygon_signed_area(q->points, q->count) >= 0 ? -1.0 : 1.0;
        offset_ring(q->points, q->count, sign * e, buf);
        r = app_region_add_hole(out, buf, q->count, in->holes[h].kind, in->holes[h].name, err,
                                err_size);
    }
    free(buf);
    if (r != APP_OK)
        app_surface_region_free(out);
    return r;
}
