/* Quantities of a tiled project: per tile product the whole and cut tiles, m2 / running metres /
 * pieces, the amount to order with a surplus (default 10 %, DOMAIN.md "Typical sizes"), offcut
 * reuse (DOMAIN.md "What the best planners print": which cut pieces' remainders serve another
 * cut; decor tiles never; others may be turned), and a priced bill of materials for every
 * placed product. docs/tiling.md describes the rules; `tessera quantities PROJECT` prints it.
 *
 * Every call that can fail returns an app_result and writes "quantities: what went wrong". */
#ifndef APP_QUANTITIES_H
#define APP_QUANTITIES_H

#include "app/project/project.h"
#include "app/design/tile_layout.h"
#include "catalog/catalog.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- catalog look-up ------------------------------------------------------------------------ */

/* Fills *spec from the catalog's tile record of ref (work size, grout, type, m2 and pieces per
 * box, texture; offcuts reusable and rotatable unless DEK). product (may be NULL) receives the
 * whole catalog record; free it with cat_product_free. APP_ERR_NOT_FOUND: no such product, or
 * not a tile. */
app_result app_tile_spec_from_catalog(cat_db *db, const app_product_ref *ref, app_tile_spec *spec,
                                      cat_product *product, char *err, size_t err_size);

/* 1 when two references name the same product (manufacturer and article any case, variant
 * exactly; an empty variant matches only an empty one). */
int app_product_ref_equal(const app_product_ref *a, const app_product_ref *b);

/* ---- the layouts of a project --------------------------------------------------------------- */

/* Gives the region of a surface ("wall:0", "floor", ...) of project p. Lets the room model
 * supply its regions (with niches, slopes, covered areas of fixtures); NULL = the fallback
 * app_surface_region_from_plan. */
typedef app_result (*app_region_provider)(void *user, const app_project *p, const char *surface,
                                          app_surface_region *out, char *err, size_t err_size);

/* Lays out every tiling of p (specs from the catalog). *layouts is an array of p->tiling_count
 * layouts, in the order of p->tilings; free it with app_tile_layouts_free. */
app_result app_project_tile_layouts(const app_project *p, cat_db *db, app_region_provider regions,
                                    void *regions_user, app_tile_layout **layouts, int *count,
                                    char *err, size_t err_size);
void app_tile_layouts_free(app_tile_layout *layouts, int count);

/* ---- quantities ----------------------------------------------------------------------------- */

typedef struct app_quantity_options {
    double surplus_percent; /* added for cutting and breakage; default 10 (DOMAIN.md) */
    double kerf_mm;         /* lost in each cut (saw blade / score and snap); default 3 */
    double min_offcut_mm;   /* a remainder narrower than this is waste; default 50 */
    int reuse_offcuts;      /* 1 (default): match remainders to cuts */
} app_quantity_options;

/* The defaults above. */
app_quantity_options app_quantity_options_default(void);

/* One cut served by another cut's remainder. */
typedef struct app_offcut_use {
    int product;                    /* index into app_quantities.lines */
    int source_layout, source_tile; /* the tile whose remainder is used */
    int target_layout, target_tile; /* the cut it serves (no new tile bought for it) */
    double piece_w_mm, piece_h_mm;  /* the piece needed, tile axes */
    double rest_w_mm, rest_h_mm;    /* the remainder it is cut from, tile axes */
    int rotated;                    /* 1: the remainder is turned 90 degrees */
    int piece_triangle;             /* 1: the piece is a corner triangle, piece_w/h its legs */
    int rest_triangle; /* 1: the rest is the opposite half of a tile cut on a corner triangle
                          (diagonal layouts), rest_w/h its legs less the kerf; the piece is
                          turned (rotated = 1) */
} app_offcut_use;

/* The tile part list's line for one tile product (DOMAIN.md: type, article and size, count with
 * the cut tiles, m2 / m / pieces, amount to order with the surplus). */
typedef struct app_tile_quantity {
    app_tile_spec spec;
    int whole, cut;    /* placed tiles */
    int reused;        /* cuts served by an offcut: no new tile */
    int pieces_needed; /* whole + cut - reused */
    double area_m2;    /* laid area (the clipped tiles) */
    double length_m;   /* BOR/DEK/EIN rows: running metres laid; else 0 */
    double surplus_percent;
    int pieces_with_surplus; /* ceil(pieces_needed x (1 + surplus)) */
    int boxes;               /* to order: ceil(pieces_with_surplus / pieces_per_box), or by m2
                                when pieces per box is unknown; 0 when neither is known */
    int pieces_to_order;     /* boxes x pieces per box (pieces_with_surplus without boxes) */
    double order_m2;         /* pieces_to_order x work area, or boxes x m2 per box */
} app_tile_quantity;

typedef struct app_quantities {
    app_tile_quantity *lines; /* one per tile product, in order of first appearance */
    int line_count;
    app_offcut_use *offcuts;
    int offcut_count;
    double region_area_m2, tiled_area_m2, grout_area_m2; /* over all layouts */
} app_quantities;

/* Counts the tiles of n layouts (several layouts may use the same product: they add up, and
 * offcuts travel between them). opts NULL = defaults. */
app_result app_quantities_compute(const app_tile_layout *layouts, int n,
                                  const app_quantity_options *opts, app_quantities *out, char *err,
                                  size_t err_size);
void app_quantities_free(app_quantities *q);

/* ---- bill of materials ---------------------------------------------------------------------- */

typedef struct app_bom_line {
    app_product_ref product;
    int found; /* 0: not in the catalog (priced 0, named by its reference) */
    char name[CAT_NAME_BYTES + 1];
    char series[CAT_SERIES_BYTES + 1];
    cat_category category;
    int is_tile;
    app_tile_type tile_type;
    double quantity; /* in unit: pieces; tiles as the catalog prices them (piece, m2, box) */
    cat_unit unit;
    long long unit_price_cents; /* list price + the variant's surcharge, without VAT */
    double vat_percent;
    long long net_cents, vat_cents, gross_cents; /* net = round(quantity x unit price) */
    char currency[4];
    int foreign_currency; /* 1: priced in another currency than the project: left out of the
                             totals, reported as an error (docs/tiling.md "Bill of materials") */
    int out_of_range;     /* 1: quantity x unit price or its VAT does not fit in cents: net, VAT
                             and gross are 0 and the line is left out of the totals */
} app_bom_line;

typedef struct app_bom {
    app_bom_line *lines; /* tiles first (in the order of q's lines), then fixtures by name */
    int line_count;
    long long net_cents, vat_cents, gross_cents; /* over the lines in the project's currency */
    char currency[4]; /* the project's: the one most priced lines use (ties: the first) */
    int missing;      /* lines whose product the catalog does not have */
    int foreign;      /* lines in another currency, left out of the totals */
    int out_of_range; /* lines whose amounts do not fit, plus 1 when a sum does not: then the
                         totals are 0, never a wrapped number */
} app_bom;

/* The amount billed for tile line t in the unit the catalog prices it by (DOMAIN.md "Products
 * and catalog records": unit piece, m2 or box): pieces -> the pieces needed with the order
 * surplus, without box rounding; box -> whole boxes; m2 -> the m2 of the boxes ordered. */
double app_tile_billed_quantity(const app_tile_quantity *t, cat_unit unit);

/* Totals the lines of b (their quantity, unit price, VAT and currency filled): each line's net,
 * VAT and gross, the project's currency, and the sums over the lines in that currency. Lines in
 * another currency are marked foreign_currency and counted in b->foreign, never summed. A line
 * or sum that does not fit in cents is counted in b->out_of_range (see app_bom_build). */
void app_bom_total(app_bom *b);

/* Writes a VAT rate with the digits it has: 19 -> "19", 8.1 -> "8.1", 7.7 -> "7.7" (at most two
 * decimals, trailing zeros dropped). Returns buf. */
const char *app_format_percent(double percent, char *buf, size_t size);

/* Prices the tiles of q (their amount to order) and every placed product of p (objects with
 * has_product; equal references counted together) from the catalog. Fails with APP_ERR_SCHEMA,
 * naming the line, when an amount does not fit (app_bom_total's out_of_range). */
app_result app_bom_build(cat_db *db, const app_project *p, const app_quantities *q, app_bom *out,
                         char *err, size_t err_size);
void app_bom_free(app_bom *b);

#ifdef __cplusplus
}
#endif
#endif
