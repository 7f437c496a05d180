/* Internals of the tile layout (app/design/tile_layout.h): convex clipping with edge labels and the
 * trapezoid decomposition of a region. docs/tiling.md "How a layout is computed". */
#ifndef APP_TILE_LAYOUT_INTERNAL_H
#define APP_TILE_LAYOUT_INTERNAL_H

#include "app/design/tile_layout.h"

/* Most points a clipped convex piece can have: a trapezoid side is split at most at
 * TL_MAX_SIDE_BREAKS points, and each of the 4 half-planes of a cell adds at most one. */
#define TL_MAX_SIDE_BREAKS 60
#define TL_MAX_POLY (2 * TL_MAX_SIDE_BREAKS + 16)

/* A convex polygon with a label (app_tile_edge) per edge: lab[i] is the edge from p[i] to
 * p[i + 1]. */
typedef struct tl_poly {
    app_point2 p[TL_MAX_POLY];
    unsigned char lab[TL_MAX_POLY];
    int n;
} tl_poly;

/* Clips convex `in` to the convex quadrilateral q (counter-clockwise); edges made along q's
 * sides get label `label`. Sutherland-Hodgman, one half-plane at a time. */
void tl_clip_convex(const tl_poly *in, const app_point2 q[4], unsigned char label, tl_poly *out);

/* Shoelace area of a tl_poly (positive for counter-clockwise). */
double tl_poly_area(const tl_poly *p);

/* A ring of a region: an outline (+1, made counter-clockwise) or a hole (-1, made clockwise). */
typedef struct tl_ring {
    const app_point2 *p;
    int n;
    int sign;
} tl_ring;

/* One convex piece of the decomposition: a trapezoid between two slab lines x0 < x1 with its
 * vertical sides split where the neighbour slabs' trapezoids end (labels SEAM where the region
 * continues across, CUT where it does not). */
typedef struct tl_trap {
    double x0, x1, y0, y1; /* bounding box */
    int first, count;      /* into the decomposition's points/labels */
} tl_trap;

typedef struct tl_decomp {
    tl_trap *traps;
    int trap_count;
    app_point2 *points;
    unsigned char *labels;
    int point_count;
    double *slab_x;  /* slab_count + 1 boundaries */
    int *slab_first; /* traps of slab k: [slab_first[k], slab_first[k + 1]) */
    int slab_count;
    double area;
    double bbox[4]; /* s0, t0, s1, t1 of the covered area; all 0 when empty */
} tl_decomp;

/* The region inside the rings by the winding rule "inside when the sum of the rings that
 * contain a point is > 0" (an outline +1, each hole -1): holes may overlap each other and stick
 * out of the outline. Returns 0 on success, -1 out of memory, -2 too complex. */
int tl_decompose(const tl_ring *rings, int ring_count, tl_decomp *out);
void tl_decomp_free(tl_decomp *d);

/* The trapezoids whose bounding box meets [s0,s1] x [t0,t1]: calls fn for each. */
void tl_decomp_query(const tl_decomp *d, double s0, double t0, double s1, double t1,
                     void (*fn)(void *user, const tl_trap *t), void *user);

/* The region shrunk by the edge joint e > 0: the outline moved in, every hole grown
 * (tile_edge_joint.c). *out is initialised here; free it with app_surface_region_free. */
app_result tl_region_shrink(const app_surface_region *in, double e, app_surface_region *out,
                            char *err, size_t err_size);

/* The layout of desc on its region as given (no edge joint, align not AUTO): tile_layout.c. */
app_result tl_layout_region(const app_tile_layout_desc *desc, app_tile_layout *out, char *err,
                            size_t err_size);

/* The set-out solver (tile_setout.c): the grid point for desc (its region already shrunk by
 * the edge joint) that keeps the smallest cut largest, then lays the fewest tiles. */
app_result tl_setout_solve(const app_tile_layout_desc *desc, app_point2 *origin, char *err,
                           size_t err_size);

void tl_set_err(char *err, size_t err_size, const char *prefix, const char *fmt, ...);

#endif
