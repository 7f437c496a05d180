/* catalog/catalog.h: the product catalog database: manufacturers, series, products with their
 * finish variants (each with its render material) and tile data, full-text search, and CSV
 * import and export. Everything lives in one SQLite file (schema in docs/catalog.md).
 *
 * The file is created on first use from the shipped CSV files in assets/catalog, so nothing
 * needs setting up; when the shipped data changes, the next open imports it again.
 *
 * Every call that can fail returns a cat_db_result and writes "FILE: what went wrong" into err
 * (when err is not NULL and err_size > 0); a CSV problem also names the line and the column.
 * Nothing here aborts or exits, and no input crashes it. Lengths are millimetres, prices are
 * integer cents of the row's currency.
 */
#ifndef CATALOG_CATALOG_H
#define CATALOG_CATALOG_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The schema version this build writes (PRAGMA user_version). Older files are migrated on
 * open, one step at a time; newer ones are refused with CAT_DB_ERR_VERSION. */
#define CAT_DB_SCHEMA_VERSION 8

typedef enum cat_db_result {
    CAT_DB_OK = 0,
    CAT_DB_ERR_IO,            /* a file or folder could not be read, written, made or renamed */
    CAT_DB_ERR_PARSE,         /* a malformed CSV file: quotes, encoding, field count, header */
    CAT_DB_ERR_INVALID,       /* rows or arguments break a rule; nothing was changed */
    CAT_DB_ERR_NOT_FOUND,     /* no such product */
    CAT_DB_ERR_AMBIGUOUS,     /* the article number exists at more than one manufacturer */
    CAT_DB_ERR_VERSION,       /* the database was written by a newer Tessera */
    CAT_DB_ERR_DATABASE,      /* not a catalog database, a damaged one, or an SQLite failure */
    CAT_DB_ERR_OUT_OF_MEMORY, /* an allocation failed */
    CAT_DB_ERR_TOO_LARGE      /* a file, record or field above one of the limits below */
} cat_db_result;

/* A short English name of a result, e.g. "invalid data"; never NULL. */
const char *cat_db_result_name(cat_db_result r);

/* ---- enumerations, with their names as they appear in CSV files and on the command line ---- */

typedef enum cat_category {
    CAT_CATEGORY_ANY = 0, /* in filters: every category; never a product's category */
    CAT_CATEGORY_TAPS_MIXERS,
    CAT_CATEGORY_SHOWER_SETS,
    CAT_CATEGORY_BASINS,
    CAT_CATEGORY_WCS_BIDETS,
    CAT_CATEGORY_BATHS,
    CAT_CATEGORY_SHOWER_TRAYS,
    CAT_CATEGORY_SHOWER_SCREENS,
    CAT_CATEGORY_MIRRORS,
    CAT_CATEGORY_MIRROR_CABINETS,
    CAT_CATEGORY_LAMPS,
    CAT_CATEGORY_TOWEL_RADIATORS,
    CAT_CATEGORY_VANITY_UNITS,
    CAT_CATEGORY_ACCESSORIES,
    CAT_CATEGORY_TILES,
    CAT_CATEGORY_COUNT
} cat_category;

/* How a product's price is counted: per piece, per m2, per box, or per metre ("m": profiles
 * sold in whole lengths and billed by the metres of the lengths bought). */
typedef enum cat_unit {
    CAT_UNIT_PIECE = 0,
    CAT_UNIT_M2,
    CAT_UNIT_BOX,
    CAT_UNIT_M,
    CAT_UNIT_COUNT
} cat_unit;

/* How a variant's reflection is blended (RENDERING.md section 6). */
typedef enum cat_blend {
    CAT_BLEND_MIX = 0,
    CAT_BLEND_ADD,
    CAT_BLEND_FRESNEL,
    CAT_BLEND_COUNT
} cat_blend;

/* A procedural pattern on a variant's colour (docs/rendering.md "Wood grain"). */
typedef enum cat_pattern { CAT_PATTERN_NONE = 0, CAT_PATTERN_WOOD, CAT_PATTERN_COUNT } cat_pattern;

/* cat_render_material.grain_deg of a variant whose grain runs along the product's longer side
 * (its width or its height); the placement resolves it per product. */
#define CAT_GRAIN_LONG (-1.0f)

typedef enum cat_tile_surface {
    CAT_SURFACE_GLOSSY = 0,
    CAT_SURFACE_MATT,
    CAT_SURFACE_STRUCTURED,
    CAT_SURFACE_COUNT
} cat_tile_surface;

/* UNI field tile, BOR border, DEK decor, EIN insert. */
typedef enum cat_tile_type {
    CAT_TILE_UNI = 0,
    CAT_TILE_BOR,
    CAT_TILE_DEK,
    CAT_TILE_EIN,
    CAT_TILE_TYPE_COUNT
} cat_tile_type;

/* What a product's mounting height is measured to, from the floor (docs/catalog.md "Mounting
 * heights"): its underside (a mirror, a radiator), its top, a basin's rim or a WC's seat (both
 * the top of the product's box, which is where the catalog's boxes have them). NONE: the
 * product gives no height; the placement uses its category's (docs/editing.md). */
typedef enum cat_mount_to {
    CAT_MOUNT_NONE = 0,
    CAT_MOUNT_BOTTOM,
    CAT_MOUNT_TOP,
    CAT_MOUNT_RIM,
    CAT_MOUNT_SEAT,
    CAT_MOUNT_COUNT
} cat_mount_to;

/* Names: "taps_mixers", "piece"/"m2"/"box", "mix"/"add"/"fresnel", "glossy"/"matt"/"structured",
 * "UNI"/"BOR"/"DEK"/"EIN"; "" for a value out of range (CAT_CATEGORY_ANY too). Never NULL. */
const char *cat_category_name(cat_category c);
const char *cat_unit_name(cat_unit u);
const char *cat_blend_name(cat_blend b);
const char *cat_pattern_name(cat_pattern p); /* "none", "wood" */
const char *cat_surface_name(cat_tile_surface s);
const char *cat_tile_type_name(cat_tile_type t);
const char *cat_mount_to_name(cat_mount_to m); /* "bottom", "top", "rim", "seat"; NONE: "" */

/* Parse the names above (categories, units, blends and surfaces ignore case; tile types too).
 * Return 1 and set *out when known, else 0 and leave *out alone. */
int cat_category_parse(const char *text, cat_category *out);
int cat_unit_parse(const char *text, cat_unit *out);
int cat_blend_parse(const char *text, cat_blend *out);
int cat_pattern_parse(const char *text, cat_pattern *out);
int cat_surface_parse(const char *text, cat_tile_surface *out);
int cat_tile_type_parse(const char *text, cat_tile_type *out);
int cat_mount_to_parse(const char *text, cat_mount_to *out); /* not "" */

/* 1 when text is a GTIN-8, -12 (UPC-A), -13 (EAN) or -14: only digits, and the last is the
 * GS1 mod-10 check digit of the others. */
int cat_gtin_valid(const char *text);

/* ---- records -------------------------------------------------------------------------------- */

/* Text limits in bytes of UTF-8 (the arrays below have one more for the terminating zero).
 * Import refuses longer values rather than cutting them. */
#define CAT_MANUFACTURER_BYTES 64
#define CAT_SERIES_BYTES 64
#define CAT_ARTICLE_BYTES 40
#define CAT_GTIN_BYTES 14
#define CAT_NAME_BYTES 160
#define CAT_SHORT_TEXT_BYTES 400
#define CAT_LONG_TEXT_BYTES 4000
#define CAT_DISCOUNT_GROUP_BYTES 16
#define CAT_PATH_BYTES 255 /* model and texture file names, relative to the assets folder */
#define CAT_VARIANT_CODE_BYTES 16
#define CAT_VARIANT_NAME_BYTES 64
#define CAT_CALIBRE_BYTES 16
#define CAT_COMPANIONS_BYTES 400

/* A mounting height above this (mm) is refused on import: no room is that high. The room a
 * product is placed in is checked again at placement. */
#define CAT_MOUNTING_MAX_MM 4000.0
/* Companions one product may name. */
#define CAT_MAX_COMPANIONS 8

/* A variant's material: the renderer's parameters (render.h rd_material, RENDERING.md). */
typedef struct cat_render_material {
    float ambient[3], diffuse[3], specular[3]; /* linear RGB, 0 .. 1 */
    float emissive[3];                         /* linear RGB, 0 .. 1e6 (lamps glow above 1) */
    float shininess;                           /* Blinn-Phong exponent n, 0 .. 1e6 */
    float reflectivity;                        /* k_r, 0 .. 1 */
    float glossiness;                          /* g, 0 .. 1 (1 = mirror) */
    cat_blend blend;
    float transparency;  /* 0 opaque .. 1 invisible */
    float ior;           /* index of refraction, 1 .. 3 */
    cat_pattern pattern; /* a procedural pattern on the colour: the wood grain */
    /* The grain's direction on the product's front, degrees from its width (x) towards its
     * height (z), 0 .. 180: 0 horizontal, 90 vertical; CAT_GRAIN_LONG along the longer side. */
    float grain_deg;
} cat_render_material;

typedef struct cat_variant {
    char code[CAT_VARIANT_CODE_BYTES + 1]; /* unique per product, e.g. "CP" (chrome) */
    char name[CAT_VARIANT_NAME_BYTES + 1]; /* e.g. "Chrome" */
    long long surcharge_cents;             /* added to the product's list price, >= 0 */
    cat_render_material material;
} cat_variant;

typedef struct cat_tile {
    cat_tile_type type;
    double nominal_w_mm, nominal_h_mm; /* the laying grid: work size + grout */
    double work_w_mm, work_h_mm;       /* the tile as made */
    double grout_mm, thickness_mm;
    char calibre[CAT_CALIBRE_BYTES + 1]; /* size class within tolerance, may be "" */
    cat_tile_surface surface;
    double m2_per_box;
    int pieces_per_box;
    char texture[CAT_PATH_BYTES + 1]; /* e.g. "textures/tiles/x.png", may be "" */
} cat_tile;

typedef struct cat_product {
    long long id; /* the database's row id: stable while the product exists, not across files */
    char manufacturer[CAT_MANUFACTURER_BYTES + 1];
    char article[CAT_ARTICLE_BYTES + 1]; /* the manufacturer's article number */
    char gtin[CAT_GTIN_BYTES + 1];       /* "" when the source has none */
    cat_category category;
    char series[CAT_SERIES_BYTES + 1]; /* may be "" */
    char name[CAT_NAME_BYTES + 1];
    char short_text[CAT_SHORT_TEXT_BYTES + 1];
    char long_text[CAT_LONG_TEXT_BYTES + 1];
    double width_mm, depth_mm, height_mm; /* the bounding box: x, y, z (Z up) */
    long long price_cents;                /* list price per unit, without VAT */
    double vat_percent;
    char currency[4]; /* ISO 4217, e.g. "EUR" */
    cat_unit unit;
    char discount_group[CAT_DISCOUNT_GROUP_BYTES + 1];
    char model[CAT_PATH_BYTES + 1]; /* GLB file relative to the assets folder, may be "" */
    /* Where it is mounted: mounting_height_mm above the floor to what mounting_to says
     * (CAT_MOUNT_NONE and 0: not given). */
    double mounting_height_mm;
    cat_mount_to mounting_to;
    /* Products that go with it, placed with it as a group (a vanity's basin, tap and mirror):
     * "ARTICLE" of the same manufacturer or "MANUFACTURER:ARTICLE", separated by ";", in the
     * order they are placed; "" when none. Every one is in the catalog (checked on import). */
    char companions[CAT_COMPANIONS_BYTES + 1];
    int shipped;           /* 1: from the shipped data, 0: from a user's import */
    cat_variant *variants; /* ordered by code; owned, freed by cat_product_free */
    int variant_count;
    int has_tile; /* tile is filled in for category tiles */
    cat_tile tile;
} cat_product;

/* Entry k (from 0) of a companions text (cat_product.companions): its manufacturer ("" when
 * the entry names none: the product's own) and article, blanks around each trimmed. Returns 1,
 * 0 when there is no entry k, -1 when entry k is empty or a part does not fit. */
int cat_companion_get(const char *companions, int k, char *manufacturer, size_t manufacturer_size,
                      char *article, size_t article_size);

/* Frees what *p owns and zeroes it. Safe on a zeroed product and on NULL. */
void cat_product_free(cat_product *p);

/* ---- the database --------------------------------------------------------------------------- */

typedef struct cat_db cat_db;

/* Where the catalog lives unless told: $TESSERA_CATALOG, else $XDG_CACHE_HOME/tessera/
 * catalog.sqlite, else $HOME/.cache/tessera/catalog.sqlite. Returns 0 if none can be made
 * (no HOME, or the buffer is too small). */
int cat_default_path(char *buf, size_t size);

/* Opens the catalog at path (NULL = cat_default_path), creating missing folders.
 * source_dir is the shipped data (assets/catalog: every *.csv in it, in name order, in the
 * import format). When the file does not exist it is built from source_dir into a temporary
 * file that is then renamed into place, so a half-built catalog is never seen. When it exists
 * it is migrated to CAT_DB_SCHEMA_VERSION if older, and if the shipped data differs from the
 * data it was built from (a content hash kept in the file), a copy is brought up to date
 * (shipped products replaced, products of users' imports kept) and renamed over it.
 * source_dir NULL: no shipped data; a missing file becomes an empty catalog. A source_dir
 * without CSV files is an error only when the file has to be built. An existing file that
 * cannot be opened for writing (a read-only folder, a full disk) is opened read-only, as it is
 * (no migration, no update): see cat_db_read_only_reason. */
cat_db_result cat_catalog_open(const char *path, const char *source_dir, cat_db **out, char *err,
                               size_t err_size);

/* cat_catalog_open for a reader (search, show, export, info, bench). A catalog that is current
 * (this schema version, in WAL mode, built from the shipped data in source_dir, its search index
 * made with this build's words) is opened read-only: no lock for writing, no schema work,
 * nothing written. Any other (missing, older, built from other shipped data) goes through
 * cat_catalog_open, which brings it up to date. Imports through a read-only handle fail with
 * SQLite's "readonly database" error. */
cat_db_result cat_catalog_open_read(const char *path, const char *source_dir, cat_db **out,
                                    char *err, size_t err_size);

/* Closes the database; NULL is fine. */
void cat_db_close(cat_db *db);

/* The file the database was opened from. */
const char *cat_db_path(const cat_db *db);

/* NULL when the catalog was opened for writing; else why it could only be read (a read-only
 * folder, a full disk: cat_catalog_open falls back to reading it, and imports are refused with
 * this reason). */
const char *cat_db_read_only_reason(const cat_db *db);

typedef struct cat_db_stats {
    int schema_version;
    long long manufacturers, series, products, variants, tiles;
    long long per_category[CAT_CATEGORY_COUNT]; /* products per category ([0] unused) */
    char source_hash[17];                       /* of the shipped data it holds, "" if none */
} cat_db_stats;

cat_db_result cat_db_get_stats(cat_db *db, cat_db_stats *out, char *err, size_t err_size);

/* ---- products ------------------------------------------------------------------------------- */

/* Finds a product by its article number (any case) or GTIN, at one manufacturer (name, any
 * case) or, when manufacturer is NULL or "", at any: an article number that several
 * manufacturers use gives CAT_DB_ERR_AMBIGUOUS with their names in err. *out is zeroed first
 * and filled on success; free it with cat_product_free. */
cat_db_result cat_product_find(cat_db *db, const char *manufacturer, const char *article,
                               cat_product *out, char *err, size_t err_size);

/* The product with row id `id`, with its variants and tile data. */
cat_db_result cat_product_get(cat_db *db, long long id, cat_product *out, char *err,
                              size_t err_size);

/* ---- search --------------------------------------------------------------------------------- */

/* Zero means "no filter" in every field. */
typedef struct cat_search_filter {
    cat_category category;
    double max_width_mm;      /* products at most this wide (width_mm <= max) */
    const char *manufacturer; /* exact name, any case */
} cat_search_filter;

typedef struct cat_search_hit {
    long long product_id;
    char manufacturer[CAT_MANUFACTURER_BYTES + 1];
    char article[CAT_ARTICLE_BYTES + 1];
    char series[CAT_SERIES_BYTES + 1];
    char name[CAT_NAME_BYTES + 1];
    cat_category category;
    double width_mm, depth_mm, height_mm;
    long long price_cents;
    char currency[4];
    cat_unit unit;
    int exact;    /* 1: the text is this product's article number or GTIN */
    double score; /* FTS5 bm25, lower is better; 0 for exact hits and for an empty text */
} cat_search_hit;

#define CAT_SEARCH_MAX_TEXT 1000 /* bytes of search text; longer is CAT_DB_ERR_INVALID */
#define CAT_SEARCH_MAX_TERMS 16  /* words of search text that count; the rest are ignored */

/* Full-text search over names, series, manufacturers, article numbers, short texts and
 * categories. Words are folded (case, diacritics, "ß" as "ss", "ae" as "ä") and matched by their
 * German and English stems too ("Waschtische" finds "Waschtisch", "basins" finds "basin"). Every
 * word must match, each as itself or as any term of its synonym groups ("Waschtisch" finds
 * basins, "grau" finds grey and grigio); the last word of two or more characters also matches
 * as a prefix ("therm" finds "thermostat"), and when that finds too little every word does. A
 * word that matches nothing gives no hits (cat_search_unmatched tells which). Hits are ranked
 * with the name weighted most. A text that is exactly an article number or GTIN puts that
 * product first. Words are only words: FTS5 query syntax in the text (AND, OR, NOT, quotes, *,
 * column:) has no effect. An empty text lists the products that pass the filter, by category and
 * name. Fills hits[0 .. *count - 1], at most limit (1 .. 10000). filter may be NULL. */
cat_db_result cat_search(cat_db *db, const char *text, const cat_search_filter *filter, int limit,
                         cat_search_hit *hits, int *count, char *err, size_t err_size);

/* After a search found nothing: the first word of text that no product matches at all (with its
 * synonyms, as a prefix, without filters), into word; "" when every word matches some product
 * and only their combination (or the filter) has none. */
cat_db_result cat_search_unmatched(cat_db *db, const char *text, char *word, size_t size, char *err,
                                   size_t err_size);

/* ---- CSV import and export (the column set is in docs/catalog.md) -------------------------- */

#define CAT_IMPORT_MAX_FILE_BYTES (1024u * 1024u * 1024u) /* a whole CSV file */
#define CAT_IMPORT_MAX_RECORD_BYTES (1024u * 1024u)       /* one record (row), quotes included */
#define CAT_IMPORT_MAX_FIELD_BYTES (64u * 1024u)          /* one field */
#define CAT_IMPORT_MAX_COLUMNS 64
#define CAT_IMPORT_MAX_PROBLEMS 1000 /* problems kept in a report; all are counted */

typedef struct cat_import_problem {
    long line;       /* 1-based line of the file where the record (row) starts; 0 = whole file */
    char column[32]; /* the column's header name, "" when the problem is the whole row */
    char message[224];
} cat_import_problem;

typedef struct cat_import_report {
    long rows;                    /* data records read (the header and empty lines not counted) */
    long products_added;          /* new products (0 when anything was wrong: nothing is applied) */
    long products_updated;        /* existing products whose row was applied again */
    long variants_written;        /* variant rows written */
    long problem_count;           /* every problem found */
    cat_import_problem *problems; /* the first CAT_IMPORT_MAX_PROBLEMS, in file order */
    int problems_kept;
} cat_import_report;

/* Frees the problems and zeroes the report. Safe on a zeroed report and on NULL. */
void cat_import_report_free(cat_import_report *r);

typedef struct cat_import_desc {
    int dry_run; /* check everything, change nothing */
    /* Called every few thousand rows and once at the end; total counts the file's records. */
    void (*progress)(void *user, long rows_done, long rows_total);
    void *user;
} cat_import_desc;

/* Imports a CSV file in one transaction: every row is checked (types, ranges, GTIN check
 * digit, known names, positive sizes and prices, no NaN or infinity, consistent tile sizes);
 * if any is wrong nothing is changed and CAT_DB_ERR_INVALID (or CAT_DB_ERR_PARSE for a broken
 * file) is returned with every problem in the report and the first in err. Products are keyed
 * by manufacturer + article number: an existing one is updated in the columns the file has
 * (so a price list with only manufacturer, article and list_price changes prices only); its
 * variants are replaced when the file has variant columns, its tile data when it has tile
 * columns. desc and report may be NULL. */
cat_db_result cat_import_csv(cat_db *db, const char *path, const cat_import_desc *desc,
                             cat_import_report *report, char *err, size_t err_size);

/* The same from memory; `name` stands for the file in messages. */
cat_db_result cat_import_csv_buffer(cat_db *db, const char *name, const void *data, size_t size,
                                    const cat_import_desc *desc, cat_import_report *report,
                                    char *err, size_t err_size);

/* Writes every product in the import format (all columns; one row per variant, or one row for
 * a product without variants), ordered by manufacturer, article and variant code, so that
 * importing the output into an empty catalog and exporting again gives the same bytes.
 * *rows (may be NULL) receives the number of data rows. */
cat_db_result cat_export_csv(cat_db *db, FILE *out, long *rows, char *err, size_t err_size);

/* The same into a file, written to a temporary name and renamed into place. */
cat_db_result cat_export_csv_file(cat_db *db, const char *path, long *rows, char *err,
                                  size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
