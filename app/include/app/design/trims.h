/* Trim profiles: the metal edge a tiler sets along a tiled surface's outside edges, where a cut
 * tile edge would show (DOMAIN.md "Setting out tiles": reveals are tiled with the cut edge
 * hidden by a trim profile, aluminium, stainless or chrome, L, quarter-circle or square, sold in
 * 2.5 m lengths). A tiling names its profile (app_tiling.trim, a catalog product); its edges
 * are the outside edges of its surface (docs/tiling.md "Trim profiles"):
 *  - a reveal's or a niche's left, right, top or bottom face: its edge on the wall's face
 *    (the side faces' edges clipped to the tiling's band); a niche's back has none;
 *  - a pre-wall's top: its front edge and the depth of each free side; its front: the height
 *    (in the band) of each free side. A side is free unless it stands in the wall's end corner
 *    (within 1 mm).
 * Other surfaces meet the room at internal corners (an elastic joint, no trim). */
#ifndef APP_TRIMS_H
#define APP_TRIMS_H

#include "app/design/quantities.h"
#include "app/project/project.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The length a profile is sold in (DOMAIN.md). */
#define APP_TRIM_PIECE_MM 2500.0
#define APP_TRIM_MAX_EDGES 8

/* The outside edges (mm) of tiling t's surface on plan: up to max lengths written, returns
 * how many there are (0 for a surface without outside edges). */
int app_tiling_trim_edges(const app_room_plan *plan, const app_tiling *t, double *lengths_mm,
                          int max);

/* The pieces of piece_mm needed to cut every edge from: first-fit decreasing (the longest edge
 * first, each into the first piece with enough left); an edge longer than a piece takes whole
 * pieces and its rest is cut like any edge. Joints between pieces along one edge are butt
 * joints; no allowance for the saw. */
int app_trim_pieces(const double *lengths_mm, int n, double piece_mm);

/* One trim product of a project: its edges over every tiling that names it. */
typedef struct app_trim_quantity {
    app_product_ref product;
    int edges;     /* edges trimmed */
    double metres; /* their total length */
    int pieces;    /* pieces of APP_TRIM_PIECE_MM to buy (app_trim_pieces over all its edges) */
} app_trim_quantity;

/* The trims of every tiling of p, one line per product in order of first appearance. *out is
 * malloc'ed (free it; NULL when there are none). */
app_result app_trim_quantities(const app_project *p, app_trim_quantity **out, int *count, char *err,
                               size_t err_size);

/* The metres of the whole lengths bought: pieces x APP_TRIM_PIECE_MM (a tiler buys whole
 * lengths, so these, not t->metres, are what a price per metre bills). */
double app_trim_billed_metres(const app_trim_quantity *t);

/* Appends a priced line per trim to b and totals b again (app_bom_total). A profile priced per
 * metre (catalog unit m) is billed app_trim_billed_metres at that price; one priced per piece
 * (unit piece, the price of one length) is billed its pieces. The line's detail says the metres
 * needed, the pieces and the metres billed. A profile the catalog lacks is listed at 0, by the
 * piece, and counted in missing. */
app_result app_bom_add_trims(cat_db *db, const app_trim_quantity *trims, int count, app_bom *b,
                             char *err, size_t err_size);

/* app_trim_quantities and app_bom_add_trims in one: the bill's lines for p's trims, as the
 * quotation, the share page and the window's quantities panel list them. */
app_result app_bom_add_project_trims(cat_db *db, const app_project *p, app_bom *b, char *err,
                                     size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
