/* Internals of the catalog database (db_*.c): the handle, error messages, the schema chain, the
 * CSV reader, the import's column set and row checks, and the small helpers they share.
 * Internal names start with catdb_ so that they never meet the model loader's cat_*. */
#ifndef CATALOG_DB_INTERNAL_H
#define CATALOG_DB_INTERNAL_H

#include "catalog/catalog.h"

#include <sqlite3.h>
#include <stddef.h>
#include <stdint.h>

#if defined(__GNUC__)
#define CATDB_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define CATDB_PRINTF(a, b)
#endif

/* ---- the handle ----------------------------------------------------------------------------- */

typedef struct catdb_stemmers catdb_stemmers;       /* libstemmer's German and English stemmers */
typedef struct catdb_query_words catdb_query_words; /* the tokenizer, for query words */

struct cat_db {
    sqlite3 *sql;
    char *path;
    sqlite3_stmt *search_fts, *search_fts_filtered, *search_exact, *search_all; /* reused */
    sqlite3_stmt *search_synonyms, *search_any;                                 /* reused */
    sqlite3_stmt *known_synonym, *known_word; /* compound splitting (db_compound.c) */
    catdb_query_words *words;                 /* made on first use */
    char *match;                              /* the FTS5 query, made on first use */
    char *read_only;                          /* why it was opened read-only; NULL: writable */
};

/* 'TESS': PRAGMA application_id of a Tessera catalog. */
#define CATDB_APPLICATION_ID 0x54455353

/* Products from the shipped data and from users' imports (products.origin). */
#define CATDB_ORIGIN_SHIPPED "shipped"
#define CATDB_ORIGIN_IMPORT "import"

/* ---- messages ------------------------------------------------------------------------------- */

/* Writes "<formatted>" into err (when there is room) and returns code. */
cat_db_result catdb_fail(char *err, size_t err_size, cat_db_result code, const char *fmt, ...)
    CATDB_PRINTF(4, 5);

/* "PATH: what: SQLite's message", with a result that fits SQLite's error code. */
cat_db_result catdb_sql_fail(sqlite3 *sql, const char *path, char *err, size_t err_size,
                             const char *what);

/* The cat_db_result for an SQLite result code. */
cat_db_result catdb_result_of(int sqlite_code);

/* ---- connection and schema (db_connect.c, db_schema.c) ------------------------------------ */

/* Opens a connection with Tessera's settings (foreign keys, busy timeout). flags as for
 * sqlite3_open_v2. On failure *out is NULL. */
cat_db_result catdb_connect(const char *path, int flags, sqlite3 **out, char *err, size_t err_size);

/* Registers catdb_rank(), the search's FTS5 ranking function (db_rank.c), on a connection.
 * Returns 0 when this SQLite has no FTS5. */
int catdb_register_rank(sqlite3 *sql);

/* ---- words (db_words.c) --------------------------------------------------------------------- */

#define CATDB_WORD_BYTES                                                                           \
    64 /* longer tokens are indexed as they are, neither folded nor stemmed                        \
        */

/* Folds a lower-cased, diacritic-free word (unicode61's output): "ß" to "ss", "ae", "oe", "ue"
 * to "a", "o", "u". Returns the folded length; out is terminated. */
size_t catdb_word_fold(const char *in, size_t n, char *out, size_t size);

catdb_stemmers *catdb_stemmers_new(void); /* NULL when out of memory */
void catdb_stemmers_free(catdb_stemmers *s);

typedef struct catdb_word_form {
    char text[CATDB_WORD_BYTES + 1];
    size_t len;
} catdb_word_form;

/* The forms under which a lower-cased word is indexed: folded, then its German and English
 * stems where they differ. Returns how many (0 for an empty word). */
int catdb_word_forms(catdb_stemmers *s, const char *word, size_t n, catdb_word_form forms[3]);

/* Registers the "tessera" FTS5 tokenizer (unicode61, folding, stems) on a connection; every
 * connection that reads or writes product_fts needs it. Returns 0 on failure. */
int catdb_register_words(sqlite3 *sql);

/* The forms of one query word as the index knows them (the tokenizer's output in query mode),
 * at most max; 0 when the word is not one token. *words is made on the first call and freed by
 * catdb_query_words_free. */
int catdb_query_forms(sqlite3 *sql, catdb_query_words **words, const char *word, size_t n,
                      catdb_word_form *forms, int max);
void catdb_query_words_free(catdb_query_words *words);

/* ---- compound words (db_compound.c) ---------------------------------------------------------- */

/* The fixed lexicon of the index side: the synonym list's single words, folded. */
typedef struct catdb_compounds catdb_compounds;
catdb_compounds *catdb_compounds_new(void); /* NULL when out of memory */
void catdb_compounds_free(catdb_compounds *c);

/* Splits a folded word of letters into two words of the lexicon (head with its linking element
 * resolved, tail without a plural ending). Returns 1 when it is such a compound. */
int catdb_compound_split(const catdb_compounds *c, const char *word, size_t n,
                         catdb_word_form *head, catdb_word_form *tail);

/* The same for a query word (any case, unfolded) against the synonym table and the words in the
 * catalog's index. */
int catdb_compound_split_query(cat_db *db, const char *word, size_t n, catdb_word_form *head,
                               catdb_word_form *tail);

/* The index's compound parts depend on the synonym list (the lexicon): a catalog whose index was
 * made with another list (meta "index_words", the list's hash) has it rebuilt, in one
 * transaction. */
cat_db_result catdb_words_check(sqlite3 *sql, const char *path, char *err, size_t err_size);
/* What meta "index_words" holds once the index is made with this build's list. */
void catdb_words_stamp(char *buf, size_t size);

/* The shipped synonym list's text (db_synonyms.inc). */
const char *catdb_synonym_list(void);

/* Fills search_synonyms from the shipped synonym list (db_synonyms.c), replacing its rows. */
cat_db_result catdb_synonyms_load(sqlite3 *sql, const char *path, char *err, size_t err_size);

/* A hash of the synonym list, so that a changed list makes the catalog refresh. */
uint64_t catdb_synonyms_hash(uint64_t h);

/* Rolls back a transaction that a failed call could not roll back itself (its ROLLBACK can
 * fail too when memory runs out). Every public call on a cat_db starts with it: no call leaves a
 * transaction open on purpose, so one that is open is such a leftover. */
void catdb_recover(cat_db *db);

/* Closes the handle's connection and opens a new one on the same file, keeping the old one if
 * that fails. Called after a failed write: in WAL mode a transaction that ran out of memory and
 * was rolled back can leave the connection's cached full-text index structure out of step with
 * the file (the file itself is intact; catalog.db_faults finds it), and a new connection reads
 * the file afresh. */
void catdb_reconnect(cat_db *db);

/* Runs SQL without results; on failure a message naming path and what. */
cat_db_result catdb_exec(sqlite3 *sql, const char *path, const char *what, const char *text,
                         char *err, size_t err_size);

/* Reads PRAGMA user_version and application_id and checks this is a Tessera catalog (or an
 * empty database, version 0) that this build can read. */
cat_db_result catdb_schema_check(sqlite3 *sql, const char *path, int *version, char *err,
                                 size_t err_size);

/* Brings the schema from `from` to CAT_DB_SCHEMA_VERSION, one step per migration, all in one
 * transaction. */
cat_db_result catdb_migrate(sqlite3 *sql, const char *path, int from, char *err, size_t err_size);

/* Bulk changes: the full-text triggers stand still until resume rebuilds the index (both in the
 * caller's transaction, so a rollback undoes them too). */
cat_db_result catdb_fts_defer(sqlite3 *sql, const char *path, char *err, size_t err_size);
cat_db_result catdb_fts_resume(sqlite3 *sql, const char *path, char *err, size_t err_size);

/* meta table: value of key into buf ("" when absent); set. */
cat_db_result catdb_meta_get(sqlite3 *sql, const char *path, const char *key, char *buf,
                             size_t size, char *err, size_t err_size);
cat_db_result catdb_meta_set(sqlite3 *sql, const char *path, const char *key, const char *value,
                             char *err, size_t err_size);

/* ---- shipped data (db_source.c, db_sync.c) --------------------------------------------------- */

typedef struct catdb_source {
    char **files; /* absolute or source_dir-relative paths of the *.csv files, in name order */
    int count;
    char hash[17]; /* FNV-1a 64 of the names and contents, with the schema version, in hex */
} catdb_source;

cat_db_result catdb_source_read(const char *dir, catdb_source *out, char *err, size_t err_size);
void catdb_source_free(catdb_source *s);

/* Replaces the shipped products in an open connection by the source's, keeping products of
 * users' imports, and records the source's hash; one transaction. */
cat_db_result catdb_sync_shipped(sqlite3 *sql, const char *path, const catdb_source *src, char *err,
                                 size_t err_size);

/* ---- files (db_file.c) ------------------------------------------------------------------------
 */

/* Reads a whole regular file of at most max_bytes. */
cat_db_result catdb_read_file(const char *path, size_t max_bytes, unsigned char **data,
                              size_t *size, char *err, size_t err_size);

/* mkdir -p of the folder that holds path (not path itself). */
cat_db_result catdb_make_parent_dirs(const char *path, char *err, size_t err_size);

/* A fresh name next to path for a temporary file: "path.tmp-PID-N". */
void catdb_temp_name(const char *path, char *buf, size_t size);

/* Renames tmp to path and syncs the folder so that the rename survives a crash. */
cat_db_result catdb_rename_into_place(const char *tmp, const char *path, char *err,
                                      size_t err_size);

/* Puts tmp at path unless a file is there already (another process built it first: that one
 * stays, and may be open in WAL mode), and syncs the folder; tmp itself stays. */
cat_db_result catdb_link_into_place(const char *tmp, const char *path, char *err, size_t err_size);

/* Removes an SQLite file and its journal, ignoring errors. */
void catdb_remove_db_file(const char *path);

/* ---- CSV reading (db_csv.c) -------------------------------------------------------------------
 */

typedef struct catdb_csv {
    const unsigned char *data;
    size_t size, pos;
    long line; /* line of the file at pos, 1-based */
    /* the current record */
    long record_line;
    int field_count;
    char *text; /* the fields' text, each zero-terminated */
    size_t text_cap;
    size_t *start;  /* offset of each field in text */
    size_t *length; /* its length in bytes (it may contain zero bytes) */
    int *quoted;    /* 1 when the field was in quotes */
    int field_cap;
    /* the first structural error */
    long error_line;
    cat_db_result error_code;
    char error[160];
} catdb_csv;

/* Starts reading data (a leading UTF-8 byte order mark is skipped). */
void catdb_csv_init(catdb_csv *c, const void *data, size_t size);
void catdb_csv_free(catdb_csv *c);

/* Reads the next record: 1 = a record (fields in c), 0 = end of data, -1 = a structural error
 * (c->error, c->error_line, c->error_code); reading cannot go on after an error. Lines that
 * are completely empty are skipped. */
int catdb_csv_next(catdb_csv *c);

static inline const char *catdb_csv_field(const catdb_csv *c, int i)
{
    return c->text + c->start[i];
}

/* Records in data, counted quickly (for progress reports); stops counting at a broken quote. */
long catdb_csv_count_records(const void *data, size_t size);

/* ---- the import format's columns (db_columns.c) ---------------------------------------------- */

typedef enum catdb_col {
    /* product */
    COL_MANUFACTURER,
    COL_ARTICLE,
    COL_GTIN,
    COL_CATEGORY,
    COL_SERIES,
    COL_NAME,
    COL_SHORT_TEXT,
    COL_LONG_TEXT,
    COL_WIDTH,
    COL_DEPTH,
    COL_HEIGHT,
    COL_LIST_PRICE,
    COL_CURRENCY,
    COL_VAT,
    COL_UNIT,
    COL_DISCOUNT_GROUP,
    COL_MODEL,
    COL_MOUNTING_HEIGHT,
    COL_MOUNTING_TO,
    COL_COMPANIONS,
    /* variant */
    COL_VARIANT_CODE,
    COL_VARIANT_NAME,
    COL_VARIANT_SURCHARGE,
    COL_AMBIENT,
    COL_DIFFUSE,
    COL_SPECULAR,
    COL_EMISSIVE,
    COL_SHININESS,
    COL_REFLECTIVITY,
    COL_GLOSSINESS,
    COL_BLEND,
    COL_TRANSPARENCY,
    COL_IOR,
    COL_PATTERN,
    COL_GRAIN,
    /* tile */
    COL_TILE_TYPE,
    COL_NOMINAL_W,
    COL_NOMINAL_H,
    COL_WORK_W,
    COL_WORK_H,
    COL_GROUT,
    COL_THICKNESS,
    COL_CALIBRE,
    COL_SURFACE,
    COL_M2_PER_BOX,
    COL_PIECES_PER_BOX,
    COL_TEXTURE,
    COL_COUNT
} catdb_col;

#define COL_FIRST_VARIANT COL_VARIANT_CODE
#define COL_FIRST_TILE COL_TILE_TYPE
#define COL_PRODUCT_COUNT COL_FIRST_VARIANT

/* The column's header name, e.g. "list_price". */
const char *catdb_col_name(catdb_col c);

/* The column named text (any case, surrounding blanks ignored), or -1. */
int catdb_col_find(const char *text);

/* ---- values (db_values.c) ------------------------------------------------------------------- */

/* Each returns NULL when text is good (and stores the value), else a message fragment such as
 * "expected a number, got \"abc\"". */
const char *catdb_parse_real(const char *text, double lo, double hi, int lo_open, double *out,
                             char *msg, size_t msg_size);
const char *catdb_parse_int(const char *text, long lo, long hi, long *out, char *msg,
                            size_t msg_size);
const char *catdb_parse_money(const char *text, int allow_zero, long long *cents, char *msg,
                              size_t msg_size);
const char *catdb_parse_rgb(const char *text, double hi, double out[3], char *msg, size_t msg_size);

/* Checks text of `length` bytes: no zero byte, valid UTF-8, at most max_bytes, no control
 * characters (multi_line: tab, line feed and carriage return are allowed). */
const char *catdb_check_text(const char *text, size_t length, size_t max_bytes, int multi_line,
                             char *msg, size_t msg_size);

/* A relative path inside the assets folder: no "..", not absolute, no backslash. */
const char *catdb_check_asset_path(const char *text, char *msg, size_t msg_size);

/* Shortest text that reads back as the same double ("%.15g" when that is exact, else %.17g). */
void catdb_format_real(double v, char *buf, size_t size);

/* "123.45" from 12345 cents. */
void catdb_format_money(long long cents, char *buf, size_t size);

/* ---- a string-keyed table of the import's products and variants (db_keymap.c) --------------- */

typedef struct catdb_keymap_entry {
    char *key;
    long line;     /* the first line with this key */
    uint32_t *aux; /* per-key data owned by the map (product column hashes), or NULL */
    int flags;
} catdb_keymap_entry;

typedef struct catdb_keymap {
    catdb_keymap_entry *slots;
    size_t cap, count;
} catdb_keymap;

/* Finds key; when absent and create is set, inserts it (*created = 1). NULL: out of memory,
 * or absent and !create. aux_count > 0 allocates that many zeroed uint32_t on creation. */
catdb_keymap_entry *catdb_keymap_get(catdb_keymap *m, const char *key, int create, int aux_count,
                                     int *created);
void catdb_keymap_free(catdb_keymap *m);

uint32_t catdb_hash32(const void *data, size_t size);
uint64_t catdb_hash64(uint64_t h, const void *data, size_t size); /* FNV-1a, chainable */
#define CATDB_HASH64_INIT 0xcbf29ce484222325ull

/* ---- import (db_import.c, db_row.c, db_apply.c) --------------------------------------------- */

enum {
    CATDB_M_AMBIENT = 0,
    CATDB_M_DIFFUSE = 3,
    CATDB_M_SPECULAR = 6,
    CATDB_M_EMISSIVE = 9,
    CATDB_M_SHININESS = 12,
    CATDB_M_REFLECTIVITY,
    CATDB_M_GLOSSINESS,
    CATDB_M_TRANSPARENCY,
    CATDB_M_IOR,
    CATDB_M_GRAIN, /* degrees, or CAT_GRAIN_LONG when the cell is empty */
    CATDB_MATERIAL_VALUES
};

/* One row of the import after its checks. */
typedef struct catdb_row {
    unsigned char given[COL_COUNT]; /* 1: the header has the column and the cell is not empty */
    cat_product product;            /* product columns (variants/tile unused) */
    cat_variant variant;            /* when has_variant (its material: see below) */
    /* The variant's material as the file's decimals (the float copy in variant.material would
     * not export back to the same text): ambient, diffuse, specular, emissive (3 each), then
     * shininess, reflectivity, glossiness, transparency, ior, grain. */
    double material[CATDB_MATERIAL_VALUES];
    cat_tile tile; /* when has_tile */
    int has_variant, has_tile;
    int dims_from_tile; /* a tile's width, depth, height taken from its sizes */
} catdb_row;

typedef struct catdb_import catdb_import;

/* Imports a buffer with origin CATDB_ORIGIN_SHIPPED or CATDB_ORIGIN_IMPORT inside the
 * current transaction, if there is one (else in its own). */
cat_db_result catdb_import_buffer(sqlite3 *sql, const char *db_path, const char *origin,
                                  const char *name, const void *data, size_t size,
                                  const cat_import_desc *desc, cat_import_report *report, char *err,
                                  size_t err_size);

/* Statements of one import, prepared for the header's columns. */
typedef struct catdb_apply {
    sqlite3 *sql;
    const char *origin;
    sqlite3_stmt *find_product, *find_manufacturer, *add_manufacturer, *find_series, *add_series;
    sqlite3_stmt *insert_product, *update_product, *delete_variants, *insert_variant;
    sqlite3_stmt *upsert_tile, *delete_tile;
    const unsigned char *header_has; /* [COL_COUNT] */
    long long last_manufacturer_id;
    char last_manufacturer[CAT_MANUFACTURER_BYTES + 1];
} catdb_apply;

cat_db_result catdb_apply_prepare(catdb_apply *a, sqlite3 *sql, const char *origin,
                                  const unsigned char *header_has, char *msg, size_t msg_size);
void catdb_apply_finish(catdb_apply *a);

typedef struct catdb_existing {
    long long id; /* 0: no such product */
    cat_category category;
    int from_import; /* origin is a user's import */
} catdb_existing;

/* Looks up manufacturer + article. */
cat_db_result catdb_apply_lookup(catdb_apply *a, const char *manufacturer, const char *article,
                                 catdb_existing *out, char *msg, size_t msg_size);

/* Writes one checked row. first_of_product: this file's first row of the product (variants
 * are then replaced). *added / *updated say what happened to the product. */
cat_db_result catdb_apply_row(catdb_apply *a, const catdb_row *row, const catdb_existing *ex,
                              int first_of_product, long long *product_id, char *msg,
                              size_t msg_size);

/* Row checks: fills row from the record's cells (cells[col] or NULL when the header lacks it),
 * reporting each problem through add(ctx, col, message). Returns the number of problems. */
typedef void (*catdb_problem_fn)(void *ctx, int col, const char *message);
int catdb_row_parse(const char *const cells[COL_COUNT], const size_t lengths[COL_COUNT],
                    catdb_row *row, catdb_problem_fn add, void *ctx);

/* The checks that need to know whether the product exists (and its category). */
int catdb_row_check_new(const catdb_row *row, const unsigned char *header_has,
                        const catdb_existing *ex, catdb_problem_fn add, void *ctx);

/* ---- reading products (db_product.c) -------------------------------------------------------- */

cat_db_result catdb_product_load(sqlite3 *sql, const char *path, long long id, cat_product *out,
                                 char *err, size_t err_size);

/* Copies at most size-1 bytes of a column's text. */
void catdb_copy_text(char *dst, size_t size, const unsigned char *src);

#endif
