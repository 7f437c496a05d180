/* CSV import: the header is mapped to the import format's columns, every row is checked and
 * written inside one transaction (or savepoint), and the transaction is rolled back if any row
 * is wrong, so a file imports completely or not at all. Every problem is reported with its
 * line and column. */
#include "db_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PROGRESS_EVERY 2000

typedef struct importer {
    const char *name;
    cat_import_report *report;
    long line;
    char first[512]; /* the first problem, as "NAME:LINE: column C: message" */
} importer;

static void add_problem(void *ctx, int col, const char *message)
{
    importer *im = ctx;
    cat_import_report *rep = im->report;
    const char *column = col >= 0 ? catdb_col_name((catdb_col)col) : "";
    if (rep->problem_count == 0) {
        if (*column)
            snprintf(im->first, sizeof im->first, "%s:%ld: column %s: %s", im->name, im->line,
                     column, message);
        else
            snprintf(im->first, sizeof im->first, "%s:%ld: %s", im->name, im->line, message);
    }
    rep->problem_count++;
    if (rep->problems_kept >= CAT_IMPORT_MAX_PROBLEMS)
        return;
    if (!rep->problems) {
        rep->problems = calloc(CAT_IMPORT_MAX_PROBLEMS, sizeof *rep->problems);
        if (!rep->problems)
            return;
    }
    cat_import_problem *p = &rep->problems[rep->problems_kept++];
    p->line = im->line;
    snprintf(p->column, sizeof p->column, "%s", column);
    snprintf(p->message, sizeof p->message, "%s", message);
}

/* Maps header fields to columns; reports unknown, repeated and missing columns. */
static void read_header(importer *im, const catdb_csv *c, int *map, unsigned char *has)
{
    char msg[256];
    for (int i = 0; i < c->field_count; i++) {
        map[i] = -1;
        const char *text = catdb_csv_field(c, i);
        if (catdb_check_text(text, c->length[i], 64, 0, msg, sizeof msg)) {
            char m2[300];
            snprintf(m2, sizeof m2, "header field %d %s", i + 1, msg);
            add_problem(im, -1, m2);
            continue;
        }
        int col = catdb_col_find(text);
        if (col < 0) {
            if (c->field_count == 1 && strchr(text, ';'))
                snprintf(msg, sizeof msg,
                         "the header has no commas but semicolons: Tessera reads comma-separated "
                         "files (save as \"CSV UTF-8 (comma delimited)\")");
            else if (!*text)
                snprintf(msg, sizeof msg, "header field %d is empty", i + 1);
            else
                snprintf(msg, sizeof msg,
                         "unknown column \"%.64s\" in the header (docs/catalog.md lists the "
                         "columns)",
                         text);
            add_problem(im, -1, msg);
            continue;
        }
        if (has[col]) {
            snprintf(msg, sizeof msg, "column %s appears twice in the header",
                     catdb_col_name((catdb_col)col));
            add_problem(im, -1, msg);
            continue;
        }
        has[col] = 1;
        map[i] = col;
    }
    int any_variant = 0, any_tile = 0;
    for (int col = COL_FIRST_VARIANT; col < COL_FIRST_TILE; col++)
        any_variant |= has[col];
    for (int col = COL_FIRST_TILE; col < COL_COUNT; col++)
        any_tile |= has[col];
    static const int always[] = {COL_MANUFACTURER, COL_ARTICLE};
    static const int variant[] = {COL_VARIANT_CODE, COL_VARIANT_NAME};
    static const int tile[] = {COL_TILE_TYPE, COL_NOMINAL_W,  COL_NOMINAL_H,
                               COL_WORK_W,    COL_WORK_H,     COL_THICKNESS,
                               COL_SURFACE,   COL_M2_PER_BOX, COL_PIECES_PER_BOX};
    struct {
        const int *cols;
        size_t n;
        int needed;
        const char *why;
    } groups[] = {{always, 2, 1, "every file needs it"},
                  {variant, 2, any_variant, "the file has variant columns"},
                  {tile, sizeof tile / sizeof tile[0], any_tile, "the file has tile columns"}};
    for (size_t g = 0; g < sizeof groups / sizeof groups[0]; g++) {
        if (!groups[g].needed)
            continue;
        for (size_t k = 0; k < groups[g].n; k++) {
            int col = groups[g].cols[k];
            if (has[col])
                continue;
            snprintf(msg, sizeof msg, "the header lacks the column %s (%s)",
                     catdb_col_name((catdb_col)col), groups[g].why);
            add_problem(im, -1, msg);
        }
    }
}

static void trim(char **text, size_t *length, int keep)
{
    if (keep)
        return;
    char *s = *text;
    size_t n = *length;
    while (n > 0 && (s[0] == ' ' || s[0] == '\t'))
        s++, n--;
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t'))
        n--;
    s[n] = 0;
    *text = s;
    *length = n;
}

/* "manufacturer\x1farticle" in ASCII lower case: the key SQLite's NOCASE compares by. */
static void product_key(const cat_product *p, char *key, size_t size)
{
    snprintf(key, size, "%s\x1f%s", p->manufacturer, p->article);
    for (char *k = key; *k; k++)
        if (*k >= 'A' && *k <= 'Z')
            *k = (char)(*k - 'A' + 'a');
}

enum { KEY_WITHOUT_VARIANT = 1, KEY_WITH_VARIANT = 2 };

/* Rows of one product must agree in the product columns, and may not mix a row without a
 * variant with rows with variants; a variant code may appear once per product. */
static void check_repeats(importer *im, catdb_keymap *products, catdb_keymap *variants,
                          const char *key, char **cells, const size_t *lengths,
                          const catdb_row *row, const unsigned char *has, int *first, int *oom)
{
    int created = 0;
    catdb_keymap_entry *e = catdb_keymap_get(products, key, 1, COL_PRODUCT_COUNT, &created);
    if (!e) {
        *oom = 1;
        return;
    }
    char msg[256];
    *first = created;
    if (created) {
        e->line = im->line;
        for (int c = 0; c < COL_PRODUCT_COUNT; c++)
            if (cells[c])
                e->aux[c] = catdb_hash32(cells[c], lengths[c]);
    } else {
        for (int c = 0; c < COL_PRODUCT_COUNT; c++) {
            if (!cells[c] || c == COL_MANUFACTURER || c == COL_ARTICLE ||
                e->aux[c] == catdb_hash32(cells[c], lengths[c]))
                continue;
            snprintf(msg, sizeof msg,
                     "differs from line %ld, the first row of this product (rows of one product "
                     "must agree in the product columns)",
                     e->line);
            add_problem(im, c, msg);
        }
    }
    if (!has[COL_VARIANT_CODE])
        return;
    int kind = row->has_variant ? KEY_WITH_VARIANT : KEY_WITHOUT_VARIANT;
    if (!created && (e->flags & KEY_WITHOUT_VARIANT || kind == KEY_WITHOUT_VARIANT)) {
        snprintf(msg, sizeof msg,
                 "this product already has a row on line %ld; a product has either one row "
                 "without a variant or one row per variant",
                 e->line);
        add_problem(im, COL_VARIANT_CODE, msg);
    }
    e->flags |= kind;
    if (!row->has_variant)
        return;
    char vkey[256];
    snprintf(vkey, sizeof vkey, "%s\x1f%s", key, row->variant.code);
    catdb_keymap_entry *v = catdb_keymap_get(variants, vkey, 1, 0, &created);
    if (!v) {
        *oom = 1;
        return;
    }
    if (created) {
        v->line = im->line;
    } else {
        snprintf(msg, sizeof msg, "variant \"%s\" of this product is already on line %ld",
                 row->variant.code, v->line);
        add_problem(im, COL_VARIANT_CODE, msg);
    }
}

/* A row that names companions, kept until the whole file is read: a companion may come later
 * in the same file. */
typedef struct companion_row {
    long line;
    char manufacturer[CAT_MANUFACTURER_BYTES + 1];
    char article[CAT_ARTICLE_BYTES + 1];
    char companions[CAT_COMPANIONS_BYTES + 1];
} companion_row;

typedef struct companion_rows {
    companion_row *rows;
    size_t count, cap;
} companion_rows;

static int keep_companions(companion_rows *c, long line, const cat_product *p)
{
    if (c->count == c->cap) {
        size_t cap = c->cap ? c->cap * 2 : 16;
        companion_row *r = realloc(c->rows, cap * sizeof *r);
        if (!r)
            return 0;
        c->rows = r;
        c->cap = cap;
    }
    companion_row *r = &c->rows[c->count++];
    r->line = line;
    snprintf(r->manufacturer, sizeof r->manufacturer, "%s", p->manufacturer);
    snprintf(r->article, sizeof r->article, "%s", p->article);
    snprintf(r->companions, sizeof r->companions, "%s", p->companions);
    return 1;
}

/* Every companion is a product of this file or of the catalog. */
static cat_db_result check_companions(importer *im, catdb_apply *apply, catdb_keymap *products,
                                      const companion_rows *c, char *msg, size_t msg_size)
{
    for (size_t i = 0; i < c->count; i++) {
        const companion_row *r = &c->rows[i];
        char maker[CAT_MANUFACTURER_BYTES + 1], article[CAT_ARTICLE_BYTES + 1];
        for (int k = 0;
             cat_companion_get(r->companions, k, maker, sizeof maker, article, sizeof article) == 1;
             k++) {
            cat_product key_of = {0};
            snprintf(key_of.manufacturer, sizeof key_of.manufacturer, "%s",
                     maker[0] ? maker : r->manufacturer);
            snprintf(key_of.article, sizeof key_of.article, "%s", article);
            char key[CAT_MANUFACTURER_BYTES + CAT_ARTICLE_BYTES + 8];
            product_key(&key_of, key, sizeof key);
            if (catdb_keymap_get(products, key, 0, 0, NULL))
                continue;
            catdb_existing ex;
            cat_db_result res =
                catdb_apply_lookup(apply, key_of.manufacturer, article, &ex, msg, msg_size);
            if (res != CAT_DB_OK)
                return res;
            if (ex.id)
                continue;
            char m[256];
            snprintf(m, sizeof m, "companion %d, %s %s, is neither in this file nor in the catalog",
                     k + 1, key_of.manufacturer, article);
            im->line = r->line;
            add_problem(im, COL_COMPANIONS, m);
        }
    }
    return CAT_DB_OK;
}

/* A big import (against the catalog's size) leaves the full-text index alone and rebuilds it
 * once at the end: FTS5 takes a row from a trigger several times slower than in a rebuild.
 * Nothing to do when the caller has deferred it already (the shipped data's sync). */
static cat_db_result defer_index(sqlite3 *sql, const char *db_path, long records, int *deferred,
                                 char *msg, size_t msg_size)
{
    *deferred = 0;
    char now[8];
    cat_db_result r = catdb_meta_get(sql, db_path, "fts_deferred", now, sizeof now, msg, msg_size);
    if (r != CAT_DB_OK || now[0])
        return r;
    long long existing = 0;
    sqlite3_stmt *st = NULL;
    if (sqlite3_prepare_v2(sql, "SELECT coalesce(max(id), 0) FROM products", -1, &st, NULL) ==
            SQLITE_OK &&
        sqlite3_step(st) == SQLITE_ROW)
        existing = sqlite3_column_int64(st, 0);
    sqlite3_finalize(st);
    /* A rebuild reads every catalog row, so it pays only when the import is large against
     * what is there already. */
    if (records <= 500 || (long long)records * 4 <= existing)
        return CAT_DB_OK;
    r = catdb_fts_defer(sql, db_path, msg, msg_size);
    *deferred = r == CAT_DB_OK;
    return r;
}

cat_db_result catdb_import_buffer(sqlite3 *sql, const char *db_path, const char *origin,
                                  const char *name, const void *data, size_t size,
                                  const cat_import_desc *desc, cat_import_report *report, char *err,
                                  size_t err_size)
{
    cat_import_report local = {0};
    cat_import_report *rep = report ? report : &local;
    memset(rep, 0, sizeof *rep);
    importer im = {.name = name, .report = rep, .line = 1};
    if (err && err_size)
        err[0] = 0;
    long total = catdb_csv_count_records(data, size);

    catdb_csv csv;
    catdb_csv_init(&csv, data, size);
    int map[CAT_IMPORT_MAX_COLUMNS];
    unsigned char has[COL_COUNT] = {0};
    cat_db_result fatal = CAT_DB_OK; /* a failure that is not a row's fault */
    cat_db_result file_code = CAT_DB_OK;
    char fatal_msg[512] = "";

    int rc = catdb_csv_next(&csv);
    if (rc == 0) {
        im.line = 1;
        add_problem(&im, -1, "the file is empty: it needs a header line naming the columns");
        file_code = CAT_DB_ERR_PARSE;
    } else if (rc < 0) {
        im.line = csv.error_line;
        add_problem(&im, -1, csv.error);
        file_code = csv.error_code;
    } else {
        im.line = csv.record_line;
        read_header(&im, &csv, map, has);
        if (rep->problem_count)
            file_code = CAT_DB_ERR_PARSE;
        if (total > 0)
            total--; /* the header */
    }
    int header_fields = csv.field_count;

    int own_tx = sqlite3_get_autocommit(sql);
    int in_tx = 0, deferred = 0;
    catdb_apply apply;
    memset(&apply, 0, sizeof apply);
    catdb_keymap products = {0}, variants = {0};
    companion_rows companions = {0};
    catdb_row *row = NULL;
    if (file_code == CAT_DB_OK) {
        fatal = catdb_exec(sql, db_path, "cannot start the import",
                           own_tx ? "BEGIN IMMEDIATE" : "SAVEPOINT catdb_import", fatal_msg,
                           sizeof fatal_msg);
        in_tx = fatal == CAT_DB_OK;
        if (fatal == CAT_DB_OK)
            fatal = catdb_apply_prepare(&apply, sql, origin, has, fatal_msg, sizeof fatal_msg);
        if (fatal == CAT_DB_OK)
            fatal = defer_index(sql, db_path, total, &deferred, fatal_msg, sizeof fatal_msg);
        row = malloc(sizeof *row);
        if (fatal == CAT_DB_OK && !row)
            fatal =
                catdb_fail(fatal_msg, sizeof fatal_msg, CAT_DB_ERR_OUT_OF_MEMORY, "out of memory");
    }

    while (file_code == CAT_DB_OK && fatal == CAT_DB_OK) {
        rc = catdb_csv_next(&csv);
        if (rc == 0)
            break;
        if (rc < 0) {
            im.line = csv.error_line;
            add_problem(&im, -1, csv.error);
            file_code = csv.error_code;
            break;
        }
        im.line = csv.record_line;
        rep->rows++;
        if (desc && desc->progress && rep->rows % PROGRESS_EVERY == 0)
            desc->progress(desc->user, rep->rows, total);
        if (csv.field_count != header_fields) {
            char msg[128];
            snprintf(msg, sizeof msg, "the row has %d fields, the header has %d", csv.field_count,
                     header_fields);
            add_problem(&im, -1, msg);
            continue;
        }
        char *cells[COL_COUNT] = {0};
        size_t lengths[COL_COUNT] = {0};
        for (int i = 0; i < csv.field_count; i++) {
            if (map[i] < 0)
                continue;
            cells[map[i]] = csv.text + csv.start[i];
            lengths[map[i]] = csv.length[i];
            trim(&cells[map[i]], &lengths[map[i]], map[i] == COL_LONG_TEXT);
        }
        long before = rep->problem_count;
        catdb_row_parse((const char *const *)cells, lengths, row, add_problem, &im);
        if (!row->given[COL_MANUFACTURER] || !row->given[COL_ARTICLE])
            continue;
        char key[CAT_MANUFACTURER_BYTES + CAT_ARTICLE_BYTES + 8];
        product_key(&row->product, key, sizeof key);
        int first = 0, oom = 0;
        check_repeats(&im, &products, &variants, key, cells, lengths, row, has, &first, &oom);
        if (oom) {
            fatal =
                catdb_fail(fatal_msg, sizeof fatal_msg, CAT_DB_ERR_OUT_OF_MEMORY, "out of memory");
            break;
        }
        catdb_existing ex;
        char msg[256];
        if (catdb_apply_lookup(&apply, row->product.manufacturer, row->product.article, &ex, msg,
                               sizeof msg) != CAT_DB_OK) {
            fatal = catdb_fail(fatal_msg, sizeof fatal_msg, CAT_DB_ERR_DATABASE, "%s", msg);
            break;
        }
        catdb_row_check_new(row, has, &ex, add_problem, &im);
        if (first && row->product.companions[0] &&
            !keep_companions(&companions, im.line, &row->product)) {
            fatal =
                catdb_fail(fatal_msg, sizeof fatal_msg, CAT_DB_ERR_OUT_OF_MEMORY, "out of memory");
            break;
        }
        if (rep->problem_count > before || rep->problem_count > 0)
            continue; /* nothing more is written once anything is wrong: it is rolled back */
        if (!strcmp(origin, CATDB_ORIGIN_SHIPPED) && ex.from_import)
            continue; /* a user's import of this product wins over the shipped data */
        long long id;
        cat_db_result r = catdb_apply_row(&apply, row, &ex, first, &id, msg, sizeof msg);
        if (r == CAT_DB_ERR_INVALID) {
            add_problem(&im, -1, msg); /* a constraint the checks above did not foresee */
        } else if (r != CAT_DB_OK) {
            fatal = catdb_fail(fatal_msg, sizeof fatal_msg, r, "%s", msg);
            break;
        } else {
            if (!ex.id)
                rep->products_added++;
            else if (first)
                rep->products_updated++;
            rep->variants_written += row->has_variant;
        }
    }
    if (fatal == CAT_DB_OK && file_code == CAT_DB_OK && companions.count) {
        char msg[256];
        if (check_companions(&im, &apply, &products, &companions, msg, sizeof msg) != CAT_DB_OK)
            fatal = catdb_fail(fatal_msg, sizeof fatal_msg, CAT_DB_ERR_DATABASE, "%s", msg);
    }
    free(companions.rows);
    if (desc && desc->progress)
        desc->progress(desc->user, rep->rows, total > rep->rows ? total : rep->rows);
    free(row);
    catdb_apply_finish(&apply);
    catdb_keymap_free(&products);
    catdb_keymap_free(&variants);
    catdb_csv_free(&csv);

    int keep = fatal == CAT_DB_OK && rep->problem_count == 0 && !(desc && desc->dry_run);
    if (in_tx && keep && deferred) {
        fatal = catdb_fts_resume(sql, db_path, fatal_msg, sizeof fatal_msg);
        keep = fatal == CAT_DB_OK;
    }
    if (in_tx && keep) {
        fatal = catdb_exec(sql, db_path, "cannot commit the import",
                           own_tx ? "COMMIT" : "RELEASE catdb_import", fatal_msg, sizeof fatal_msg);
        keep = fatal == CAT_DB_OK;
    }
    if (in_tx && !keep) {
        if (own_tx)
            sqlite3_exec(sql, "ROLLBACK", NULL, NULL, NULL);
        else
            sqlite3_exec(sql, "ROLLBACK TO catdb_import; RELEASE catdb_import", NULL, NULL, NULL);
    }

    cat_db_result result = CAT_DB_OK;
    if (fatal != CAT_DB_OK) {
        result = catdb_fail(err, err_size, fatal, "%s: import into %s failed: %s", name, db_path,
                            fatal_msg);
    } else if (rep->problem_count) {
        result = file_code != CAT_DB_OK ? file_code : CAT_DB_ERR_INVALID;
        if (rep->problem_count == 1)
            catdb_fail(err, err_size, result, "%s (nothing was imported)", im.first);
        else
            catdb_fail(err, err_size, result, "%s (and %ld more problems; nothing was imported)",
                       im.first, rep->problem_count - 1);
    }
    if (result != CAT_DB_OK || (desc && desc->dry_run)) {
        if (result != CAT_DB_OK)
            rep->products_added = rep->products_updated = rep->variants_written = 0;
    }
    if (rep == &local)
        cat_import_report_free(&local);
    return result;
}

void cat_import_report_free(cat_import_report *r)
{
    if (!r)
        return;
    free(r->problems);
    memset(r, 0, sizeof *r);
}

/* An import into a catalog opened read-only (cat_catalog_open's fallback) is refused up
 * front, with the reason the catalog could not be written. */
static cat_db_result read_only_fail(const cat_db *db, char *err, size_t err_size)
{
    return catdb_fail(err, err_size, CAT_DB_ERR_IO,
                      "%s: cannot import: the catalog could only be opened read-only (%s)",
                      db->path, db->read_only);
}

cat_db_result cat_import_csv_buffer(cat_db *db, const char *name, const void *data, size_t size,
                                    const cat_import_desc *desc, cat_import_report *report,
                                    char *err, size_t err_size)
{
    if (report)
        memset(report, 0, sizeof *report);
    if (!db || (!data && size))
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID, "%s: no catalog or no data",
                          name ? name : "(import)");
    if (db->read_only)
        return read_only_fail(db, err, err_size);
    catdb_recover(db);
    cat_db_result r =
        catdb_import_buffer(db->sql, db->path, CATDB_ORIGIN_IMPORT, name ? name : "(import)",
                            data ? data : "", size, desc, report, err, err_size);
    if (r != CAT_DB_OK)
        catdb_reconnect(db);
    return r;
}

cat_db_result cat_import_csv(cat_db *db, const char *path, const cat_import_desc *desc,
                             cat_import_report *report, char *err, size_t err_size)
{
    if (report)
        memset(report, 0, sizeof *report);
    if (!db || !path)
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID, "cat_import_csv: no catalog or path");
    if (db->read_only)
        return read_only_fail(db, err, err_size);
    catdb_recover(db);
    unsigned char *data;
    size_t size;
    cat_db_result r = catdb_read_file(path, CAT_IMPORT_MAX_FILE_BYTES, &data, &size, err, err_size);
    if (r != CAT_DB_OK)
        return r;
    r = catdb_import_buffer(db->sql, db->path, CATDB_ORIGIN_IMPORT, path, data, size, desc, report,
                            err, err_size);
    free(data);
    if (r != CAT_DB_OK)
        catdb_reconnect(db);
    return r;
}
