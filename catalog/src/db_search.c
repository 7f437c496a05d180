/* Search: an exact article number or GTIN first, then FTS5 full-text hits ranked by bm25, each
 * passed through the filters (category, width, manufacturer). The user's words are quoted
 * before they reach FTS5, so its query syntax (AND, OR, NEAR, *, ", :, ^, parentheses) is never
 * interpreted: a search text cannot cause a syntax error. */
#include "db_internal.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HIT_COLUMNS                                                                                \
    "p.id, m.name, p.article, coalesce(s.name, ''), p.name, p.category, p.width_mm, p.depth_mm, "  \
    "p.height_mm, p.price_cents, p.currency, p.unit"
#define HIT_FROM                                                                                   \
    " FROM products p JOIN manufacturers m ON m.id = p.manufacturer_id"                            \
    " LEFT JOIN series s ON s.id = p.series_id"
/* Parameters shared by every statement: ?1 text, ?2 category, ?3 width, ?4 manufacturer id,
 * ?5 limit, ?6 how many matches to rank. */
#define HIT_FILTERS                                                                                \
    " AND (?2 IS NULL OR p.category = ?2) AND (?3 IS NULL OR p.width_mm <= ?3)"                    \
    " AND (?4 IS NULL OR p.manufacturer_id = ?4)"

/* At most this many matches are ranked, the first in catalog (row id) order: a word found in
 * tens of thousands of products still costs a millisecond or two. Below the cap the ranking is
 * complete. */
#define RANK_CAP 1000

/* Room for an FTS5 query: every word with its synonyms, and the filters. */
#define MATCH_BYTES 32768

/* Column weights: name, series, manufacturer, article, article_compact, short_text, category,
 * finishes (db_rank.c). A word in the name counts most; the short text only breaks ties. The
 * ranking runs over row ids alone (the category filter is part of the FTS5 query); products are
 * read for a width or manufacturer filter, and for the few hits at the end. */
#define RANK "catdb_rank(product_fts, 10.0, 5.0, 3.0, 8.0, 8.0, 1.0, 2.0, 2.0)"
#define RANKED_HITS(candidates)                                                                    \
    "SELECT " HIT_COLUMNS ", h.score FROM"                                                         \
    " (SELECT id, score FROM (" candidates ") ORDER BY score, id LIMIT ?5) h"                      \
    " JOIN products p ON p.id = h.id JOIN manufacturers m ON m.id = p.manufacturer_id"             \
    " LEFT JOIN series s ON s.id = p.series_id ORDER BY h.score, h.id"

static const char rank_sql[] =
    RANKED_HITS("SELECT product_fts.rowid AS id, " RANK " AS score FROM product_fts"
                " WHERE product_fts MATCH ?1 ORDER BY product_fts.rowid LIMIT ?6");

static const char rank_filtered_sql[] =
    RANKED_HITS("SELECT product_fts.rowid AS id, " RANK " AS score FROM product_fts"
                " JOIN products p ON p.id = product_fts.rowid"
                " WHERE product_fts MATCH ?1" HIT_FILTERS " ORDER BY product_fts.rowid LIMIT ?6");

static const char exact_sql[] =
    "SELECT " HIT_COLUMNS ", 0" HIT_FROM " WHERE (p.article = ?1 OR p.gtin = ?1)" HIT_FILTERS
    " ORDER BY m.name, p.article LIMIT ?5";

static const char all_sql[] = "SELECT " HIT_COLUMNS ", 0" HIT_FROM " WHERE 1" HIT_FILTERS
                              " ORDER BY p.category, p.name, p.id LIMIT ?5";

typedef struct filter_values {
    const char *category;   /* name, or NULL */
    double max_width;       /* > 0, or 0 */
    long long manufacturer; /* id, or 0 */
} filter_values;

static void bind_filter(sqlite3_stmt *st, const filter_values *f, int limit)
{
    if (f->category)
        sqlite3_bind_text(st, 2, f->category, -1, SQLITE_STATIC);
    if (f->max_width > 0)
        sqlite3_bind_double(st, 3, f->max_width);
    if (f->manufacturer)
        sqlite3_bind_int64(st, 4, f->manufacturer);
    sqlite3_bind_int(st, 5, limit);
}

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

/* Appends `text` to out as one FTS5 string ("" for a quote inside), so that nothing in it is
 * query syntax. Returns 0 when there is no room. */
static int put_string(char *out, size_t size, size_t *o, const char *text, size_t n)
{
    if (*o + 2 * n + 3 >= size)
        return 0;
    out[(*o)++] = '"';
    for (size_t i = 0; i < n; i++) {
        if (text[i] == '"')
            out[(*o)++] = '"';
        out[(*o)++] = text[i];
    }
    out[(*o)++] = '"';
    out[*o] = 0;
    return 1;
}

static int put_raw(char *out, size_t size, size_t *o, const char *text)
{
    size_t n = strlen(text);
    if (*o + n + 1 >= size)
        return 0;
    memcpy(out + *o, text, n + 1);
    *o += n;
    return 1;
}

static int has_word(const char *s, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)s[i];
        if ((c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c >= 0x80)
            return 1;
    }
    return 0;
}

static int prepare(cat_db *db, sqlite3_stmt **st, const char *text)
{
    if (*st)
        return 1;
    return sqlite3_prepare_v3(db->sql, text, -1, SQLITE_PREPARE_PERSISTENT, st, NULL) == SQLITE_OK;
}

/* The terms of the synonym groups of a word (db_synonyms.c), appended to out as FTS5
 * alternatives (" OR "term""). Returns 0 when there is no room or the lookup fails. */
static const char synonyms_sql[] = "SELECT DISTINCT t.term FROM search_synonyms k"
                                   " JOIN search_synonyms t ON t.group_id = k.group_id"
                                   " WHERE k.form IN (?1, ?2, ?3) ORDER BY t.term LIMIT 32";

static int put_synonyms(cat_db *db, const char *word, size_t n, char *out, size_t size, size_t *o)
{
    catdb_word_form forms[3];
    int count = catdb_query_forms(db->sql, &db->words, word, n, forms, 3);
    if (count <= 0)
        return 1; /* not one word (or no tokenizer): the word alone */
    if (!prepare(db, &db->search_synonyms, synonyms_sql))
        return 0;
    sqlite3_stmt *st = db->search_synonyms;
    for (int k = 0; k < 3; k++)
        sqlite3_bind_text(st, k + 1, forms[k < count ? k : 0].text, -1, SQLITE_STATIC);
    int ok = 1, rc;
    while (ok && (rc = sqlite3_step(st)) == SQLITE_ROW) {
        const char *term = (const char *)sqlite3_column_text(st, 0);
        ok = term && put_raw(out, size, o, " OR ") && put_string(out, size, o, term, strlen(term));
    }
    sqlite3_reset(st);
    sqlite3_clear_bindings(st);
    return ok;
}

/* A compound word's parts (db_compound.c), both required, appended as one more alternative:
 * "Bodenfliese" also matches "boden" AND ("fliese" OR "tile" ...). The last part, which says
 * what the thing is, brings its synonyms; the first only says what kind, and through its
 * synonyms would match far too much ("Duschwanne" is no "shower" AND "bath" mixer). Returns 0
 * when there is no room. */
static int put_compound(cat_db *db, const char *word, size_t n, char *out, size_t size, size_t *o)
{
    catdb_word_form head, tail;
    if (!catdb_compound_split_query(db, word, n, &head, &tail))
        return 1;
    return put_raw(out, size, o, " OR (") && put_string(out, size, o, head.text, head.len) &&
           put_raw(out, size, o, " AND (") && put_string(out, size, o, tail.text, tail.len) &&
           put_synonyms(db, tail.text, tail.len, out, size, o) && put_raw(out, size, o, "))");
}

/* Builds the FTS5 query: every word of text must match (AND), each as itself or any term of its
 * synonym groups (OR): "(\"tile\" OR \"fliese\" ...) (\"grey\"* OR \"grau\" ...)". The word
 * itself is a prefix when it has two or more bytes (MATCH_TYPING: only the last word, as one
 * types; the others must be whole words, which FTS5 reads far faster than prefixes); synonyms
 * are whole words. Words without a letter or digit are left out. The category and manufacturer
 * filters join as column phrases, which FTS5 intersects far faster than a scan could
 * ("{category} : "wcs bidets""; the manufacturer is checked exactly afterwards). `only` >= 0
 * keeps that word alone (and no filters). Returns the number of words used. */
enum { MATCH_TYPING, MATCH_ALL_PREFIX };

static int build_match(cat_db *db, const char *text, int mode, int only, const filter_values *fv,
                       const cat_search_filter *filter, char *out, size_t size)
{
    size_t o = 0;
    int terms = 0, index = 0;
    out[0] = 0;
    for (const char *p = text; *p && index < CAT_SEARCH_MAX_TERMS;) {
        while (is_space(*p))
            p++;
        const char *start = p;
        while (*p && !is_space(*p))
            p++;
        size_t n = (size_t)(p - start);
        if (!n || !has_word(start, n))
            continue;
        while (is_space(*p))
            p++;
        int last = !*p;
        int prefix = n >= 2 && (mode != MATCH_TYPING || last);
        if (only >= 0 && index++ != only)
            continue;
        if ((terms && !put_raw(out, size, &o, " AND ")) || !put_raw(out, size, &o, "(") ||
            !put_string(out, size, &o, start, n) || (prefix && !put_raw(out, size, &o, "*")) ||
            !put_synonyms(db, start, n, out, size, &o) ||
            !put_compound(db, start, n, out, size, &o) || !put_raw(out, size, &o, ")"))
            return 0;
        terms++;
    }
    if (!terms || only >= 0)
        return terms;
    if (fv->category) {
        char words[64];
        snprintf(words, sizeof words, "%s", fv->category);
        for (char *c = words; *c; c++)
            if (*c == '_')
                *c = ' ';
        if (!put_raw(out, size, &o, " AND {category} : ") ||
            !put_string(out, size, &o, words, strlen(words)))
            return 0;
    }
    if (fv->manufacturer && has_word(filter->manufacturer, strlen(filter->manufacturer))) {
        if (!put_raw(out, size, &o, " AND {manufacturer} : ") ||
            !put_string(out, size, &o, filter->manufacturer, strlen(filter->manufacturer)))
            return 0;
    }
    return terms;
}

static void read_hit(sqlite3_stmt *st, cat_search_hit *h)
{
    memset(h, 0, sizeof *h);
    h->product_id = sqlite3_column_int64(st, 0);
    catdb_copy_text(h->manufacturer, sizeof h->manufacturer, sqlite3_column_text(st, 1));
    catdb_copy_text(h->article, sizeof h->article, sqlite3_column_text(st, 2));
    catdb_copy_text(h->series, sizeof h->series, sqlite3_column_text(st, 3));
    catdb_copy_text(h->name, sizeof h->name, sqlite3_column_text(st, 4));
    const char *cat = (const char *)sqlite3_column_text(st, 5);
    if (!cat || !cat_category_parse(cat, &h->category))
        h->category = CAT_CATEGORY_ANY;
    h->width_mm = sqlite3_column_double(st, 6);
    h->depth_mm = sqlite3_column_double(st, 7);
    h->height_mm = sqlite3_column_double(st, 8);
    h->price_cents = sqlite3_column_int64(st, 9);
    catdb_copy_text(h->currency, sizeof h->currency, sqlite3_column_text(st, 10));
    const char *unit = (const char *)sqlite3_column_text(st, 11);
    if (!unit || !cat_unit_parse(unit, &h->unit))
        h->unit = CAT_UNIT_PIECE;
    h->score = sqlite3_column_double(st, 12);
}

/* Appends the statement's rows to hits (skipping ids already there) up to limit. */
static int collect(sqlite3_stmt *st, cat_search_hit *hits, int *n, int limit, int exact)
{
    int rc = SQLITE_DONE;
    int already = *n;
    while (*n < limit && (rc = sqlite3_step(st)) == SQLITE_ROW) {
        long long id = sqlite3_column_int64(st, 0);
        int dup = 0;
        for (int i = 0; i < already && !dup; i++)
            dup = hits[i].product_id == id;
        if (dup)
            continue;
        read_hit(st, &hits[*n]);
        hits[*n].exact = exact;
        if (exact)
            hits[*n].score = 0;
        (*n)++;
    }
    if (*n >= limit)
        rc = SQLITE_DONE;
    sqlite3_reset(st);
    sqlite3_clear_bindings(st);
    return rc == SQLITE_DONE;
}

/* Ranks the matches of `match` (at most RANK_CAP of them) and appends the best to hits. */
static int ranked(cat_db *db, const char *match, const filter_values *fv, int limit,
                  cat_search_hit *hits, int *n)
{
    sqlite3_stmt *st =
        fv->max_width > 0 || fv->manufacturer ? db->search_fts_filtered : db->search_fts;
    sqlite3_bind_text(st, 1, match, -1, SQLITE_STATIC);
    bind_filter(st, fv, limit + *n); /* room for hits already there, which are skipped */
    sqlite3_bind_int(st, 6, RANK_CAP);
    return collect(st, hits, n, limit, 0);
}

static cat_db_result manufacturer_id(cat_db *db, const char *name, long long *id, char *err,
                                     size_t err_size)
{
    *id = 0;
    sqlite3_stmt *st = NULL;
    int rc =
        sqlite3_prepare_v2(db->sql, "SELECT id FROM manufacturers WHERE name = ?1", -1, &st, NULL);
    if (rc == SQLITE_OK) {
        sqlite3_bind_text(st, 1, name, -1, SQLITE_STATIC);
        rc = sqlite3_step(st);
    }
    if (rc == SQLITE_ROW)
        *id = sqlite3_column_int64(st, 0);
    sqlite3_finalize(st);
    if (rc != SQLITE_ROW && rc != SQLITE_DONE)
        return catdb_sql_fail(db->sql, db->path, err, err_size, "search failed");
    return CAT_DB_OK;
}

/* The connection's buffer for FTS5 queries, made on first use. */
static char *query_buffer(cat_db *db)
{
    if (!db->match)
        db->match = malloc(MATCH_BYTES);
    return db->match;
}

static cat_db_result search_in_snapshot(cat_db *db, const char *text,
                                        const cat_search_filter *filter, int limit,
                                        cat_search_hit *hits, int *count, char *err,
                                        size_t err_size);

/* One read transaction around the search's statements (the exact match, one or two ranked
 * queries): in WAL mode they all read the same snapshot, so a search while another process
 * imports finds the catalog from before the import or after it, never a mix. */
cat_db_result cat_search(cat_db *db, const char *text, const cat_search_filter *filter, int limit,
                         cat_search_hit *hits, int *count, char *err, size_t err_size)
{
    if (count)
        *count = 0;
    if (!db || !hits || !count)
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID, "cat_search: no catalog or no hits");
    catdb_recover(db);
    if (sqlite3_exec(db->sql, "BEGIN", NULL, NULL, NULL) != SQLITE_OK)
        return catdb_sql_fail(db->sql, db->path, err, err_size, "cannot start the search");
    cat_db_result r = search_in_snapshot(db, text, filter, limit, hits, count, err, err_size);
    /* A read transaction has nothing to write: COMMIT only ends it; if it cannot, the next call's
     * catdb_recover rolls it back. */
    sqlite3_exec(db->sql, "COMMIT", NULL, NULL, NULL);
    return r;
}

static cat_db_result search_in_snapshot(cat_db *db, const char *text,
                                        const cat_search_filter *filter, int limit,
                                        cat_search_hit *hits, int *count, char *err,
                                        size_t err_size)
{
    if (count)
        *count = 0;
    if (!db || !hits || !count)
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID, "cat_search: no catalog or no hits");
    catdb_recover(db);
    if (limit < 1 || limit > 10000)
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID,
                          "%s: search limit %d is not between 1 and 10000", db->path, limit);
    if (!text)
        text = "";
    size_t len = strlen(text);
    char msg[160];
    if (len > CAT_SEARCH_MAX_TEXT)
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID,
                          "%s: the search text has %zu bytes, the limit is %d", db->path, len,
                          CAT_SEARCH_MAX_TEXT);
    if (catdb_check_text(text, len, CAT_SEARCH_MAX_TEXT, 1, msg, sizeof msg))
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID, "%s: the search text %s", db->path,
                          msg);
    while (is_space(*text))
        text++;
    char trimmed[CAT_SEARCH_MAX_TEXT + 1];
    snprintf(trimmed, sizeof trimmed, "%s", text);
    for (size_t n = strlen(trimmed); n > 0 && is_space(trimmed[n - 1]); n--)
        trimmed[n - 1] = 0;

    filter_values fv = {0};
    if (filter && filter->category > CAT_CATEGORY_ANY && filter->category < CAT_CATEGORY_COUNT)
        fv.category = cat_category_name(filter->category);
    if (filter && filter->max_width_mm > 0)
        fv.max_width = filter->max_width_mm;
    if (filter && filter->manufacturer && *filter->manufacturer) {
        cat_db_result r =
            manufacturer_id(db, filter->manufacturer, &fv.manufacturer, err, err_size);
        if (r != CAT_DB_OK || fv.manufacturer == 0)
            return r; /* an unknown manufacturer has no products */
    }

    int n = 0;
    if (!trimmed[0]) {
        if (!prepare(db, &db->search_all, all_sql))
            return catdb_sql_fail(db->sql, db->path, err, err_size, "cannot prepare the search");
        bind_filter(db->search_all, &fv, limit);
        if (!collect(db->search_all, hits, &n, limit, 0))
            return catdb_sql_fail(db->sql, db->path, err, err_size, "search failed");
        *count = n;
        return CAT_DB_OK;
    }
    if (!prepare(db, &db->search_exact, exact_sql) || !prepare(db, &db->search_fts, rank_sql) ||
        !prepare(db, &db->search_fts_filtered, rank_filtered_sql))
        return catdb_sql_fail(db->sql, db->path, err, err_size, "cannot prepare the search");
    sqlite3_bind_text(db->search_exact, 1, trimmed, -1, SQLITE_STATIC);
    bind_filter(db->search_exact, &fv, limit);
    if (!collect(db->search_exact, hits, &n, limit, 1))
        return catdb_sql_fail(db->sql, db->path, err, err_size, "search failed");
    char *match = query_buffer(db);
    if (!match)
        return catdb_fail(err, err_size, CAT_DB_ERR_OUT_OF_MEMORY, "%s: out of memory", db->path);
    /* Whole words and a last prefix first; then every word as a prefix ("therm bath" finds
     * thermostatic bath mixers). A word that matches nothing gives no hits, never fewer words:
     * cat_search_unmatched names it. */
    int terms = build_match(db, trimmed, MATCH_TYPING, -1, &fv, filter, match, MATCH_BYTES);
    if (n < limit && terms > 0 && !ranked(db, match, &fv, limit, hits, &n))
        return catdb_sql_fail(db->sql, db->path, err, err_size, "search failed");
    if (n < limit && terms > 1 &&
        build_match(db, trimmed, MATCH_ALL_PREFIX, -1, &fv, filter, match, MATCH_BYTES) > 0 &&
        !ranked(db, match, &fv, limit, hits, &n))
        return catdb_sql_fail(db->sql, db->path, err, err_size, "search failed");
    *count = n;
    return CAT_DB_OK;
}

cat_db_result cat_search_unmatched(cat_db *db, const char *text, char *word, size_t size, char *err,
                                   size_t err_size)
{
    if (word && size)
        word[0] = 0;
    if (!db || !text || !word || !size)
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID,
                          "cat_search_unmatched: no catalog, text or room for the word");
    catdb_recover(db);
    if (!prepare(db, &db->search_any,
                 "SELECT 1 FROM product_fts WHERE product_fts MATCH ?1 LIMIT 1"))
        return catdb_sql_fail(db->sql, db->path, err, err_size, "cannot prepare the search");
    char *match = query_buffer(db);
    if (!match)
        return catdb_fail(err, err_size, CAT_DB_ERR_OUT_OF_MEMORY, "%s: out of memory", db->path);
    filter_values none = {0};
    for (int i = 0; i < CAT_SEARCH_MAX_TERMS; i++) {
        if (build_match(db, text, MATCH_ALL_PREFIX, i, &none, NULL, match, MATCH_BYTES) < 1)
            break;
        sqlite3_bind_text(db->search_any, 1, match, -1, SQLITE_STATIC);
        int rc = sqlite3_step(db->search_any);
        sqlite3_reset(db->search_any);
        sqlite3_clear_bindings(db->search_any);
        if (rc == SQLITE_ROW)
            continue;
        if (rc != SQLITE_DONE)
            return catdb_sql_fail(db->sql, db->path, err, err_size, "search failed");
        /* the i-th word: the one whose quoted string opens the query */
        size_t o = 0;
        for (const char *p = match + 2; *p && o + 1 < size; p++) {
            if (*p == '"' && p[1] == '"')
                p++;
            else if (*p == '"')
                break;
            word[o++] = *p;
        }
        word[o] = 0;
        return CAT_DB_OK;
    }
    return CAT_DB_OK;
}
