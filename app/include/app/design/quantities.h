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

/* What a bill-of-materials line is: a placed product or tile, a consumable the tiling uses
 * (adhesive, grout, silicone, waterproofing) or a labour line. */
typedef enum app_bom_kind { APP_BOM_PRODUCT = 0, APP_BOM_CONSUMABLE, APP_BOM_LABOUR } app_bom_kind;

typedef struct app_bom_line {
    app_product_ref product;
    app_bom_kind kind;
    char detail[96]; /* consumables and labour: how the amount came about ("21.5 kg") */
    int found;       /* 0: not in the catalog (priced 0, named by its reference) */
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

/* The VAT of b's totalled lines (not those in another currency or out of range) per rate, in
 * order of first appearance: at most max rates; returns how many. */
int app_bom_vat_by_rate(const app_bom *b, double *rates, long long *vat_cents, int max);

/* Writes a VAT rate with the digits it has: 19 -> "19", 8.1 -> "8.1", 7.7 -> "7.7" (at most two
 * decimals, trailing zeros dropped). Returns buf. */
const char *app_format_percent(double percent, char *buf, size_t size);

/* Prices the tiles of q (their amount to order) and every placed product of p (objects with
 * has_product; equal references counted together) from the catalog. Fails with APP_ERR_SCHEMA,
 * naming the line, when an amount does not fit (app_bom_total's out_of_range). */
app_result app_bom_build(cat_db *db, const app_project *p, const app_quantities *q, app_bom *out,
                         char *err, size_t err_size);
void app_bom_free(app_bom *b);

/* ---- consumables and labour ----------------------------------------------------------------- */

/* Which catalog items the consumables and labour lines bill, and the rates that size them.
 * app_consumable_rules_default names the shipped items (assets/catalog/consumables.csv); a
 * showroom with other products fills its own. docs/tiling.md "Consumables and labour". */
typedef struct app_consumable_rules {
    app_product_ref adhesive, grout, silicone, waterproofing;
    app_product_ref labour_floor, labour_wall, labour_fixture;
    double adhesive_bag_kg;       /* 25: the adhesive item is one bag */
    double grout_bag_kg;          /* 5 */
    double grout_density_kg_dm3;  /* 1.6 (DOMAIN.md "Setting out tiles", consumables) */
    double grout_depth_mm;        /* used when the tile's thickness is unknown: 8 */
    double silicone_cartridge_ml; /* 310 */
    double silicone_min_width_mm; /* a bead is at least this wide and as deep as wide: 5 */
    double shower_wall_mm;        /* waterproofing height on the walls of a shower zone: 2000 */
} app_consumable_rules;

app_consumable_rules app_consumable_rules_default(void);

/* The adhesive rate (kg per m2) for a tile of work size w x h (DOMAIN.md: 2.5-5 kg/m2 by tile
 * size and notch): longest side up to 150 mm 2.5 (6 mm notch), up to 300 mm 3.0 (8 mm notch),
 * below 0.25 m2 4.0 (10 mm notch), large format (0.25 m2 and up) 5.0 (12 mm notch with the
 * tile's back buttered as well). */
double app_adhesive_kg_per_m2(double w_mm, double h_mm);

/* The amounts of one project, before prices. */
typedef struct app_consumables {
    double floor_m2, wall_m2; /* tiled regions (tiles and joints, inside the edge joint):
                                 floors, and everything else (walls, pre-walls, ceilings) */
    double adhesive_kg;
    int adhesive_bags;
    double joint_length_m;      /* grouted joints: half the uncut tile edges facing another tile */
    double grout_dm3, grout_kg; /* joint length x joint width x tile thickness, its weight */
    int grout_bags;
    double edge_joint_m; /* boundaries of the tiled regions, a boundary two tiled surfaces
                            share counted once; a wall band's own top and bottom are not
                            edge joints unless they meet the floor or ceiling */
    double silicone_ml;
    int silicone_cartridges;
    double waterproofing_m2; /* shower trays: the floor under them and the walls they stand
                                against, up to shower_wall_mm (DIN 18534 practice) */
    int shower_zones;
    int fixtures; /* placed catalog products to install, pieces */
} app_consumables;

/* Computes the amounts of p whose tilings are laid out as layouts (app_room_tile_layouts, in
 * the order of p->tilings); db supplies tile thicknesses and the placed products' categories
 * and sizes (NULL: default depths, no shower zones). rules NULL = defaults. */
app_result app_consumables_compute(const app_project *p, struct cat_db *db,
                                   const app_tile_layout *layouts, int n,
                                   const app_consumable_rules *rules, app_consumables *out,
                                   char *err, size_t err_size);

/* Fills the catalog part of l from its product (name, series, category, unit, unit price with
 * the variant's surcharge, VAT, currency); found = 0 when the catalog has no such product. */
void app_bom_price_line(cat_db *db, app_bom_line *l);

/* Appends the consumables and labour lines of c to b (priced from db like every line; lines
 * with a zero amount are left out) and totals b again. */
app_result app_bom_add_consumables(cat_db *db, const app_consumables *c,
                                   const app_consumable_rules *rules, app_bom *b, char *err,
                                   size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
