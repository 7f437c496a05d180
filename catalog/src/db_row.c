/* The checks of one import row: each cell's text, type and range, and the rules that tie cells
 * together (a variant needs a code and a name; a tile's nominal size is its work size plus the
 * grout; its m2 per box matches its pieces per box). Every problem is reported, not just the
 * first. */
#include "db_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

/* Longest text a cell of each column may hold. */
static size_t max_bytes(int c)
{
    switch (c) {
    case COL_MANUFACTURER:
        return CAT_MANUFACTURER_BYTES;
    case COL_ARTICLE:
        return CAT_ARTICLE_BYTES;
    case COL_SERIES:
        return CAT_SERIES_BYTES;
    case COL_NAME:
        return CAT_NAME_BYTES;
    case COL_SHORT_TEXT:
        return CAT_SHORT_TEXT_BYTES;
    case COL_LONG_TEXT:
        return CAT_LONG_TEXT_BYTES;
    case COL_DISCOUNT_GROUP:
        return CAT_DISCOUNT_GROUP_BYTES;
    case COL_MODEL:
    case COL_TEXTURE:
        return CAT_PATH_BYTES;
    case COL_VARIANT_CODE:
        return CAT_VARIANT_CODE_BYTES;
    case COL_VARIANT_NAME:
        return CAT_VARIANT_NAME_BYTES;
    case COL_CALIBRE:
        return CAT_CALIBRE_BYTES;
    case COL_COMPANIONS:
        return CAT_COMPANIONS_BYTES;
    case COL_AMBIENT:
    case COL_DIFFUSE:
    case COL_SPECULAR:
    case COL_EMISSIVE:
        return 128;
    default:
        return 64; /* numbers and names of enumerations */
    }
}

typedef struct checker {
    const char *const *cells;
    catdb_row *row;
    catdb_problem_fn add;
    void *ctx;
    int problems;
    char msg[256];
} checker;

static void problem(checker *k, int col, const char *message)
{
    k->problems++;
    k->add(k->ctx, col, message);
}

static const char *cell(const checker *k, int c)
{
    return k->row->given[c] ? k->cells[c] : NULL;
}

static void copy(char *dst, size_t size, const char *src)
{
    snprintf(dst, size, "%s", src ? src : "");
}

static void real(checker *k, int c, double lo, double hi, int lo_open, double *out)
{
    const char *t = cell(k, c);
    if (t && catdb_parse_real(t, lo, hi, lo_open, out, k->msg, sizeof k->msg)) {
        problem(k, c, k->msg);
        k->row->given[c] = 0;
    }
}

static void rgb(checker *k, int c, double hi, double out[3])
{
    const char *t = cell(k, c);
    if (t && catdb_parse_rgb(t, hi, out, k->msg, sizeof k->msg)) {
        problem(k, c, k->msg);
        k->row->given[c] = 0;
    }
}

/* A column the header has must not be empty in a row. */
static void required(checker *k, int c)
{
    if (k->cells[c] && !k->cells[c][0])
        problem(k, c, "is empty");
}

static void enum_problem(checker *k, int c, const char *what, const char *known)
{
    char b[64];
    snprintf(b, sizeof b, "%s", k->cells[c]);
    snprintf(k->msg, sizeof k->msg, "unknown %s \"%s\" (known: %s)", what, b, known);
    problem(k, c, k->msg);
    k->row->given[c] = 0;
}

static void gtin(checker *k)
{
    const char *t = cell(k, COL_GTIN);
    if (!t)
        return;
    size_t n = strlen(t);
    if (strspn(t, "0123456789") != n || (n != 8 && n != 12 && n != 13 && n != 14)) {
        char b[64];
        snprintf(b, sizeof b, "%s", t);
        snprintf(k->msg, sizeof k->msg, "expected 8, 12, 13 or 14 digits, got \"%s\"", b);
        problem(k, COL_GTIN, k->msg);
        return;
    }
    if (!cat_gtin_valid(t)) {
        int sum = 0;
        for (size_t i = 0; i + 1 < n; i++)
            sum += (t[i] - '0') * ((n - 1 - i) % 2 == 1 ? 3 : 1);
        snprintf(k->msg, sizeof k->msg, "check digit of %s is %c, expected %d", t, t[n - 1],
                 (10 - sum % 10) % 10);
        problem(k, COL_GTIN, k->msg);
        return;
    }
    copy(k->row->product.gtin, sizeof k->row->product.gtin, t);
}

static void product_columns(checker *k)
{
    catdb_row *row = k->row;
    cat_product *p = &row->product;
    required(k, COL_MANUFACTURER);
    required(k, COL_ARTICLE);
    required(k, COL_CATEGORY);
    required(k, COL_NAME);
    required(k, COL_LIST_PRICE);
    copy(p->manufacturer, sizeof p->manufacturer, cell(k, COL_MANUFACTURER));
    copy(p->article, sizeof p->article, cell(k, COL_ARTICLE));
    gtin(k);
    if (cell(k, COL_CATEGORY) && !cat_category_parse(cell(k, COL_CATEGORY), &p->category))
        enum_problem(k, COL_CATEGORY, "category",
                     "taps_mixers, shower_sets, basins, wcs_bidets, baths, shower_trays, "
                     "shower_screens, mirrors, mirror_cabinets, lamps, towel_radiators, "
                     "vanity_units, accessories, tiles");
    copy(p->series, sizeof p->series, cell(k, COL_SERIES));
    copy(p->name, sizeof p->name, cell(k, COL_NAME));
    copy(p->short_text, sizeof p->short_text, cell(k, COL_SHORT_TEXT));
    copy(p->long_text, sizeof p->long_text, cell(k, COL_LONG_TEXT));
    real(k, COL_WIDTH, 0, 20000, 1, &p->width_mm);
    real(k, COL_DEPTH, 0, 20000, 1, &p->depth_mm);
    real(k, COL_HEIGHT, 0, 20000, 1, &p->height_mm);
    const char *price = cell(k, COL_LIST_PRICE);
    if (price && catdb_parse_money(price, 0, &p->price_cents, k->msg, sizeof k->msg)) {
        problem(k, COL_LIST_PRICE, k->msg);
        row->given[COL_LIST_PRICE] = 0;
    }
    const char *cur = cell(k, COL_CURRENCY);
    copy(p->currency, sizeof p->currency, "EUR");
    if (cur) {
        if (strlen(cur) == 3 && strspn(cur, "ABCDEFGHIJKLMNOPQRSTUVWXYZ") == 3) {
            copy(p->currency, sizeof p->currency, cur);
        } else {
            char b[64];
            snprintf(b, sizeof b, "%s", cur);
            snprintf(k->msg, sizeof k->msg,
                     "expected a three-letter ISO 4217 code such as EUR, got \"%s\"", b);
            problem(k, COL_CURRENCY, k->msg);
        }
    }
    p->vat_percent = 19;
    real(k, COL_VAT, 0, 100, 0, &p->vat_percent);
    p->unit = CAT_UNIT_PIECE;
    if (cell(k, COL_UNIT) && !cat_unit_parse(cell(k, COL_UNIT), &p->unit))
        enum_problem(k, COL_UNIT, "unit", "piece, m2, box, m");
    copy(p->discount_group, sizeof p->discount_group, cell(k, COL_DISCOUNT_GROUP));
    if (cell(k, COL_MODEL)) {
        if (catdb_check_asset_path(cell(k, COL_MODEL), k->msg, sizeof k->msg))
            problem(k, COL_MODEL, k->msg);
        else
            copy(p->model, sizeof p->model, cell(k, COL_MODEL));
    }
}

/* Where the product is mounted: a height and what it is measured to come together; the
 * height lies between the floor and CAT_MOUNTING_MAX_MM. */
static void mounting_columns(checker *k)
{
    catdb_row *row = k->row;
    cat_product *p = &row->product;
    const char *h = cell(k, COL_MOUNTING_HEIGHT);
    char inner[160];
    if (h && catdb_parse_real(h, 0, CAT_MOUNTING_MAX_MM, 0, &p->mounting_height_mm, inner,
                              sizeof inner)) {
        snprintf(k->msg, sizeof k->msg,
                 "%.150s (a mounting height is measured from the floor, at most %.0f mm, above "
                 "any room's ceiling)",
                 inner, CAT_MOUNTING_MAX_MM);
        problem(k, COL_MOUNTING_HEIGHT, k->msg);
        row->given[COL_MOUNTING_HEIGHT] = 0;
    }
    const char *to = cell(k, COL_MOUNTING_TO);
    if (to && !cat_mount_to_parse(to, &p->mounting_to))
        enum_problem(k, COL_MOUNTING_TO, "mounting reference", "bottom, top, rim, seat");
    if (row->given[COL_MOUNTING_HEIGHT] && !to)
        problem(k, COL_MOUNTING_TO,
                "is empty, but the row has a mounting height: say what it is measured to "
                "(bottom, top, rim, seat)");
    if (row->given[COL_MOUNTING_TO] &&
        !(k->cells[COL_MOUNTING_HEIGHT] && k->cells[COL_MOUNTING_HEIGHT][0]))
        problem(k, COL_MOUNTING_HEIGHT, "is empty, but the row has a mounting_to");
}

/* Companions: "ARTICLE" or "MANUFACTURER:ARTICLE" separated by ";", at most
 * CAT_MAX_COMPANIONS, none the product itself. Whether each is in the catalog is checked once
 * the whole file is read (db_import.c). */
static void companion_columns(checker *k)
{
    cat_product *p = &k->row->product;
    const char *t = cell(k, COL_COMPANIONS);
    if (!t)
        return;
    char maker[CAT_MANUFACTURER_BYTES + 1], article[CAT_ARTICLE_BYTES + 1];
    int n = 0, r;
    while ((r = cat_companion_get(t, n, maker, sizeof maker, article, sizeof article)) != 0) {
        if (r < 0) {
            snprintf(k->msg, sizeof k->msg,
                     "entry %d is empty or too long (expected ARTICLE or MANUFACTURER:ARTICLE "
                     "separated by \";\")",
                     n + 1);
            problem(k, COL_COMPANIONS, k->msg);
            return;
        }
        if (!strcasecmp(article, p->article) &&
            (!maker[0] || !strcasecmp(maker, p->manufacturer))) {
            problem(k, COL_COMPANIONS, "names the product itself");
            return;
        }
        n++;
    }
    if (n > CAT_MAX_COMPANIONS) {
        snprintf(k->msg, sizeof k->msg, "names %d products, at most %d", n, CAT_MAX_COMPANIONS);
        problem(k, COL_COMPANIONS, k->msg);
        return;
    }
    copy(p->companions, sizeof p->companions, t);
}

/* The material of a variant whose file gives no value: a plain light grey (ambient follows
 * diffuse unless given). */
/* clang-format off */
static const double default_material[CATDB_MATERIAL_VALUES] = {
    0.8, 0.8, 0.8, 0.8, 0.8, 0.8, /* ambient, diffuse */
    0.2, 0.2, 0.2, 0,   0,   0,   /* specular, emissive */
    32,  0,   0.5, 0,   1.5,      /* shininess, k_r, g, transparency, ior */
    CAT_GRAIN_LONG                /* grain: along the longer side */
};
/* clang-format on */

/* The grain's direction: "horizontal" (0), "vertical" (90) or degrees 0-180 from the
 * product's width towards its height; empty: along its longer side. */
static void grain(checker *k)
{
    const char *t = cell(k, COL_GRAIN);
    double *out = k->row->material + CATDB_M_GRAIN;
    if (!t)
        return;
    if (!strcasecmp(t, "horizontal"))
        *out = 0.0;
    else if (!strcasecmp(t, "vertical"))
        *out = 90.0;
    else if (catdb_parse_real(t, 0, 180, 0, out, k->msg, sizeof k->msg)) {
        snprintf(k->msg, sizeof k->msg,
                 "must be horizontal, vertical or an angle of 0 to 180 degrees, got \"%.40s\"", t);
        problem(k, COL_GRAIN, k->msg);
        k->row->given[COL_GRAIN] = 0;
    }
}

static void variant_columns(checker *k)
{
    catdb_row *row = k->row;
    cat_variant *v = &row->variant;
    int any = 0;
    for (int c = COL_FIRST_VARIANT; c < COL_FIRST_TILE; c++)
        any |= row->given[c];
    if (!any)
        return;
    if (!row->given[COL_VARIANT_CODE]) {
        problem(k, COL_VARIANT_CODE, "is empty, but the row has other variant values");
        return;
    }
    row->has_variant = 1;
    copy(v->code, sizeof v->code, cell(k, COL_VARIANT_CODE));
    if (!row->given[COL_VARIANT_NAME])
        problem(k, COL_VARIANT_NAME, "is empty; a variant needs a name");
    copy(v->name, sizeof v->name, cell(k, COL_VARIANT_NAME));
    const char *s = cell(k, COL_VARIANT_SURCHARGE);
    if (s && catdb_parse_money(s, 1, &v->surcharge_cents, k->msg, sizeof k->msg))
        problem(k, COL_VARIANT_SURCHARGE, k->msg);
    double *m = row->material;
    memcpy(m, default_material, sizeof default_material);
    rgb(k, COL_DIFFUSE, 1, m + CATDB_M_DIFFUSE);
    memcpy(m + CATDB_M_AMBIENT, m + CATDB_M_DIFFUSE, 3 * sizeof *m);
    rgb(k, COL_AMBIENT, 1, m + CATDB_M_AMBIENT);
    rgb(k, COL_SPECULAR, 1, m + CATDB_M_SPECULAR);
    rgb(k, COL_EMISSIVE, 1e6, m + CATDB_M_EMISSIVE);
    real(k, COL_SHININESS, 0, 1e6, 0, m + CATDB_M_SHININESS);
    real(k, COL_REFLECTIVITY, 0, 1, 0, m + CATDB_M_REFLECTIVITY);
    real(k, COL_GLOSSINESS, 0, 1, 0, m + CATDB_M_GLOSSINESS);
    v->material.blend = CAT_BLEND_MIX;
    if (cell(k, COL_BLEND) && !cat_blend_parse(cell(k, COL_BLEND), &v->material.blend))
        enum_problem(k, COL_BLEND, "blend mode", "mix, add, fresnel");
    real(k, COL_TRANSPARENCY, 0, 1, 0, m + CATDB_M_TRANSPARENCY);
    real(k, COL_IOR, 1, 3, 0, m + CATDB_M_IOR);
    v->material.pattern = CAT_PATTERN_NONE;
    if (cell(k, COL_PATTERN) && !cat_pattern_parse(cell(k, COL_PATTERN), &v->material.pattern))
        enum_problem(k, COL_PATTERN, "pattern", "none, wood");
    grain(k);
}

static void tile_columns(checker *k)
{
    catdb_row *row = k->row;
    cat_tile *t = &row->tile;
    int any = 0;
    for (int c = COL_FIRST_TILE; c < COL_COUNT; c++)
        any |= k->cells[c] && k->cells[c][0];
    if (!any)
        return;
    row->has_tile = 1;
    static const int needed[] = {COL_TILE_TYPE, COL_NOMINAL_W,  COL_NOMINAL_H,
                                 COL_WORK_W,    COL_WORK_H,     COL_THICKNESS,
                                 COL_SURFACE,   COL_M2_PER_BOX, COL_PIECES_PER_BOX};
    for (size_t i = 0; i < sizeof needed / sizeof needed[0]; i++) {
        if (!k->cells[needed[i]] || !k->cells[needed[i]][0]) {
            problem(k, needed[i], "is empty, but the row has other tile values");
        }
    }
    if (cell(k, COL_TILE_TYPE) && !cat_tile_type_parse(cell(k, COL_TILE_TYPE), &t->type))
        enum_problem(k, COL_TILE_TYPE, "tile type", "UNI, BOR, DEK, EIN");
    real(k, COL_NOMINAL_W, 0, 4000, 1, &t->nominal_w_mm);
    real(k, COL_NOMINAL_H, 0, 4000, 1, &t->nominal_h_mm);
    real(k, COL_WORK_W, 0, 4000, 1, &t->work_w_mm);
    real(k, COL_WORK_H, 0, 4000, 1, &t->work_h_mm);
    real(k, COL_THICKNESS, 0, 50, 1, &t->thickness_mm);
    real(k, COL_M2_PER_BOX, 0, 100, 1, &t->m2_per_box);
    const char *pieces = cell(k, COL_PIECES_PER_BOX);
    long n = 0;
    if (pieces && catdb_parse_int(pieces, 1, 100000, &n, k->msg, sizeof k->msg)) {
        problem(k, COL_PIECES_PER_BOX, k->msg);
        row->given[COL_PIECES_PER_BOX] = 0;
    }
    t->pieces_per_box = (int)n;
    if (cell(k, COL_SURFACE) && !cat_surface_parse(cell(k, COL_SURFACE), &t->surface))
        enum_problem(k, COL_SURFACE, "surface", "glossy, matt, structured");
    copy(t->calibre, sizeof t->calibre, cell(k, COL_CALIBRE));
    if (cell(k, COL_TEXTURE)) {
        if (catdb_check_asset_path(cell(k, COL_TEXTURE), k->msg, sizeof k->msg))
            problem(k, COL_TEXTURE, k->msg);
        else
            copy(t->texture, sizeof t->texture, cell(k, COL_TEXTURE));
    }
    int sizes = row->given[COL_NOMINAL_W] && row->given[COL_NOMINAL_H] && row->given[COL_WORK_W] &&
                row->given[COL_WORK_H];
    if (cell(k, COL_GROUT))
        real(k, COL_GROUT, 0, 20, 0, &t->grout_mm);
    else if (sizes)
        t->grout_mm = t->nominal_w_mm - t->work_w_mm;
    int grout_ok = !cell(k, COL_GROUT) || row->given[COL_GROUT];
    /* DOMAIN.md: nominal = work + grout (597 + 3 = 600), on both sides. */
    if (sizes && grout_ok) {
        const int cols[2][2] = {{COL_NOMINAL_W, COL_WORK_W}, {COL_NOMINAL_H, COL_WORK_H}};
        const double nominal[2] = {t->nominal_w_mm, t->nominal_h_mm};
        const double work[2] = {t->work_w_mm, t->work_h_mm};
        for (int i = 0; i < 2; i++) {
            if (fabs(nominal[i] - (work[i] + t->grout_mm)) > 0.5) {
                snprintf(k->msg, sizeof k->msg,
                         "%g is not the work size %g plus the grout %g (nominal = work + grout)",
                         nominal[i], work[i], t->grout_mm);
                problem(k, cols[i][0], k->msg);
            } else if (work[i] > nominal[i]) {
                problem(k, cols[i][1], "is larger than the nominal size");
            }
        }
    }
    if (sizes && row->given[COL_M2_PER_BOX] && row->given[COL_PIECES_PER_BOX]) {
        double expect = t->pieces_per_box * t->nominal_w_mm * t->nominal_h_mm / 1e6;
        if (fabs(t->m2_per_box - expect) > 0.05 * expect) {
            snprintf(k->msg, sizeof k->msg,
                     "%g m2 does not match %d pieces of %g x %g mm (%.4g m2) within 5 %%",
                     t->m2_per_box, t->pieces_per_box, t->nominal_w_mm, t->nominal_h_mm, expect);
            problem(k, COL_M2_PER_BOX, k->msg);
        }
    }
}

int catdb_row_parse(const char *const cells[COL_COUNT], const size_t lengths[COL_COUNT],
                    catdb_row *row, catdb_problem_fn add, void *ctx)
{
    memset(row, 0, sizeof *row);
    checker k = {.cells = cells, .row = row, .add = add, .ctx = ctx};
    int bad_text[COL_COUNT] = {0};
    for (int c = 0; c < COL_COUNT; c++) {
        if (!cells[c])
            continue;
        if (catdb_check_text(cells[c], lengths[c], max_bytes(c), c == COL_LONG_TEXT, k.msg,
                             sizeof k.msg)) {
            problem(&k, c, k.msg);
            bad_text[c] = 1;
        }
        row->given[c] = lengths[c] > 0 && !bad_text[c];
    }
    product_columns(&k);
    mounting_columns(&k);
    companion_columns(&k);
    variant_columns(&k);
    tile_columns(&k);
    cat_product *p = &row->product;
    int is_tile = row->given[COL_CATEGORY] && p->category == CAT_CATEGORY_TILES;
    if (row->has_tile && row->given[COL_CATEGORY] && !is_tile)
        problem(&k, COL_TILE_TYPE, "tile columns are only for products of category tiles");
    /* A tile's quantities are pieces, m2 and boxes (app_tile_billed_quantity); a price per
     * metre would bill a count of tiles as metres. */
    if (row->given[COL_UNIT] && p->unit == CAT_UNIT_M && (is_tile || row->has_tile))
        problem(&k, COL_UNIT,
                "a tile is priced per piece, m2 or box, not per metre (m is for profiles sold "
                "by the length)");
    /* A tile's box: its work size and thickness, unless the row says otherwise. */
    if (row->has_tile && (is_tile || !cells[COL_CATEGORY])) {
        const cat_tile *t = &row->tile;
        int dims[3] = {COL_WIDTH, COL_DEPTH, COL_HEIGHT};
        double from[3] = {t->work_w_mm, t->thickness_mm, t->work_h_mm};
        double *to[3] = {&p->width_mm, &p->depth_mm, &p->height_mm};
        for (int i = 0; i < 3; i++) {
            if (!row->given[dims[i]] && !bad_text[dims[i]] && from[i] > 0 &&
                (!cells[dims[i]] || !cells[dims[i]][0])) {
                *to[i] = from[i];
                row->dims_from_tile |= 1 << i;
            }
        }
    }
    for (int i = 0; i < 3; i++) {
        int c = i == 0 ? COL_WIDTH : i == 1 ? COL_DEPTH : COL_HEIGHT;
        if (cells[c] && !cells[c][0] && !(row->dims_from_tile & 1 << i))
            problem(&k, c,
                    is_tile ? "is empty (and the row has no tile sizes to take it from)"
                            : "is empty");
    }
    return k.problems;
}

int catdb_row_check_new(const catdb_row *row, const unsigned char *header_has,
                        const catdb_existing *ex, catdb_problem_fn add, void *ctx)
{
    checker k = {.row = (catdb_row *)row, .add = add, .ctx = ctx};
    cat_category category = row->given[COL_CATEGORY] ? row->product.category : ex->category;
    if (!ex->id) {
        static const int needed[] = {COL_CATEGORY, COL_NAME,   COL_WIDTH,
                                     COL_DEPTH,    COL_HEIGHT, COL_LIST_PRICE};
        for (size_t i = 0; i < sizeof needed / sizeof needed[0]; i++) {
            int c = needed[i];
            int dim = c == COL_WIDTH ? 0 : c == COL_DEPTH ? 1 : c == COL_HEIGHT ? 2 : -1;
            if (header_has[c] || (dim >= 0 && (row->dims_from_tile & 1 << dim)))
                continue; /* an empty cell was reported with the row's own checks */
            problem(&k, c,
                    "is missing: the product is not in the catalog yet, and a new product "
                    "needs this column");
        }
    }
    int had_tile = ex->id && ex->category == CAT_CATEGORY_TILES;
    if (category == CAT_CATEGORY_TILES && !row->has_tile && !had_tile)
        problem(&k, COL_TILE_TYPE,
                "a product of category tiles needs the tile columns (tile_type, nominal_w_mm, "
                "nominal_h_mm, work_w_mm, work_h_mm, thickness_mm, surface, m2_per_box, "
                "pieces_per_box)");
    if (category != CAT_CATEGORY_TILES && category != CAT_CATEGORY_ANY && row->has_tile &&
        !row->given[COL_CATEGORY])
        problem(&k, COL_TILE_TYPE, "tile columns are only for products of category tiles");
    return k.problems;
}
