/* German compound words in the search: "Bodenfliese" is "Boden" + "Fliese", "Duschwand" is
 * "Dusche" + "Wand". A compound is split into two words that are known, the first allowed a
 * linking element (Fugenelement: "Arbeit-s-platte", "Badewanne-n-armatur", "Dusch(e)-wand"), the
 * second a plural ending ("Bodenfliese-n"): the simple longest-match splitting of Koehn and
 * Knight, "Empirical Methods for Compound Splitting" (EACL 2003), with the known words as its
 * lexicon.
 *
 * Two lexicons, for the two sides of the index:
 * - indexing (the tokenizer, db_words.c) knows the single words of the synonym list
 *   (db_synonyms.inc), fixed at build time, so that a product named "Eckbadewanne" is also
 *   indexed under its last part "badewanne" and found by "Badewanne" or "bath" (only the last
 *   part: a "Waschtischmischer" is a mixer and must not be found by "Waschtisch");
 * - a query word (db_search.c) is split against the synonym table and the catalog's own
 *   vocabulary (any word in the index), so that "Bodenfliese" finds products that say "Boden"
 *   and "Fliese" (or, through the synonyms, "floor" and "tile"). */
#include "db_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MIN_PART = 3, MIN_COMPOUND = 7 };

/* ---- the fixed lexicon: the synonym list's single words ---------------------------------- */

struct catdb_compounds {
    char **slots; /* open addressing, NULL = empty */
    size_t cap;
};

static size_t hash_of(const char *s, size_t n)
{
    uint32_t h = catdb_hash32(s, n);
    return (size_t)h;
}

static int lexicon_has(const catdb_compounds *c, const char *s, size_t n)
{
    if (n < MIN_PART || n > CATDB_WORD_BYTES)
        return 0;
    for (size_t i = hash_of(s, n) & (c->cap - 1);; i = (i + 1) & (c->cap - 1)) {
        const char *w = c->slots[i];
        if (!w)
            return 0;
        if (strlen(w) == n && !memcmp(w, s, n))
            return 1;
    }
}

static int lexicon_add(catdb_compounds *c, const char *s, size_t n)
{
    if (n < MIN_PART || lexicon_has(c, s, n))
        return 1;
    size_t i = hash_of(s, n) & (c->cap - 1);
    while (c->slots[i])
        i = (i + 1) & (c->cap - 1);
    c->slots[i] = malloc(n + 1);
    if (!c->slots[i])
        return 0;
    memcpy(c->slots[i], s, n);
    c->slots[i][n] = 0;
    return 1;
}

void catdb_compounds_free(catdb_compounds *c)
{
    if (!c)
        return;
    for (size_t i = 0; c->slots && i < c->cap; i++)
        free(c->slots[i]);
    free(c->slots);
    free(c);
}

catdb_compounds *catdb_compounds_new(void)
{
    catdb_compounds *c = calloc(1, sizeof *c);
    if (!c)
        return NULL;
    c->cap = 1024; /* a power of two, well above the list's few hundred words */
    c->slots = calloc(c->cap, sizeof *c->slots);
    if (!c->slots) {
        catdb_compounds_free(c);
        return NULL;
    }
    /* Terms are separated by commas and line ends; a term with a blank or hyphen is a phrase,
     * not a word. The list is lower case ASCII (umlauts written folded: "grun", "heizkorper"). */
    const char *list = catdb_synonym_list();
    for (const char *p = list; *p;) {
        while (*p == ' ' || *p == ',' || *p == '\n')
            p++;
        const char *start = p;
        while (*p && *p != ',' && *p != '\n')
            p++;
        size_t n = (size_t)(p - start);
        while (n && start[n - 1] == ' ')
            n--;
        if (!n || memchr(start, ' ', n) || memchr(start, '-', n))
            continue;
        char folded[CATDB_WORD_BYTES + 1];
        size_t f = catdb_word_fold(start, n < CATDB_WORD_BYTES ? n : CATDB_WORD_BYTES, folded,
                                   sizeof folded);
        if (!lexicon_add(c, folded, f)) {
            catdb_compounds_free(c);
            return NULL;
        }
    }
    return c;
}

/* ---- splitting ------------------------------------------------------------------------------ */

typedef int (*known_fn)(void *ctx, const char *s, size_t n);

/* The second part with a plural or case ending taken off: the word itself first. */
static int tail_known(known_fn known, void *ctx, const char *s, size_t n, size_t *len)
{
    static const char *const endings[] = {"", "n", "en", "s", "e"};
    for (size_t k = 0; k < sizeof endings / sizeof endings[0]; k++) {
        size_t e = strlen(endings[k]);
        if (n < e + MIN_PART || memcmp(s + n - e, endings[k], e))
            continue;
        if (known(ctx, s, n - e)) {
            *len = n - e;
            return 1;
        }
    }
    return 0;
}

/* The first part as a known word: itself, with a linking "s", "n" or "en" dropped, or with the
 * "e" a linking element dropped added back ("Dusch-wand": "Dusche"). */
static int head_known(known_fn known, void *ctx, const char *s, size_t n, char *out, size_t *len)
{
    if (known(ctx, s, n)) {
        memcpy(out, s, n);
        *len = n;
        return 1;
    }
    static const char *const links[] = {"s", "n", "en"};
    for (size_t k = 0; k < sizeof links / sizeof links[0]; k++) {
        size_t e = strlen(links[k]);
        if (n >= e + MIN_PART && !memcmp(s + n - e, links[k], e) && known(ctx, s, n - e)) {
            memcpy(out, s, n - e);
            *len = n - e;
            return 1;
        }
    }
    memcpy(out, s, n);
    out[n] = 'e';
    if (known(ctx, out, n + 1)) {
        *len = n + 1;
        return 1;
    }
    return 0;
}

/* The split with the longest known second part (German compounds are right-headed: the last
 * part says what the thing is). */
static int split_with(known_fn known, void *ctx, const char *word, size_t n, catdb_word_form *head,
                      catdb_word_form *tail)
{
    if (n < MIN_COMPOUND || n >= CATDB_WORD_BYTES)
        return 0;
    for (size_t i = MIN_PART; i + MIN_PART <= n; i++) {
        size_t tail_len;
        if (!tail_known(known, ctx, word + i, n - i, &tail_len))
            continue;
        if (!head_known(known, ctx, word, i, head->text, &head->len))
            continue;
        head->text[head->len] = 0;
        memcpy(tail->text, word + i, tail_len);
        tail->text[tail_len] = 0;
        tail->len = tail_len;
        return 1;
    }
    return 0;
}

static int in_lexicon(void *ctx, const char *s, size_t n)
{
    return lexicon_has(ctx, s, n);
}

int catdb_compound_split(const catdb_compounds *c, const char *word, size_t n,
                         catdb_word_form *head, catdb_word_form *tail)
{
    return c && split_with(in_lexicon, (void *)c, word, n, head, tail);
}

/* ---- query words -------------------------------------------------------------------------- */

/* Known to the catalog: a synonym form, or a word of any product (one index look-up). */
static int in_catalog(void *ctx, const char *s, size_t n)
{
    cat_db *db = ctx;
    if (!db->known_synonym &&
        sqlite3_prepare_v3(db->sql, "SELECT 1 FROM search_synonyms WHERE form = ?1 LIMIT 1", -1,
                           SQLITE_PREPARE_PERSISTENT, &db->known_synonym, NULL) != SQLITE_OK)
        return 0;
    if (!db->known_word &&
        sqlite3_prepare_v3(db->sql, "SELECT 1 FROM product_fts WHERE product_fts MATCH ?1 LIMIT 1",
                           -1, SQLITE_PREPARE_PERSISTENT, &db->known_word, NULL) != SQLITE_OK)
        return 0;
    sqlite3_bind_text(db->known_synonym, 1, s, (int)n, SQLITE_STATIC);
    int found = sqlite3_step(db->known_synonym) == SQLITE_ROW;
    sqlite3_reset(db->known_synonym);
    sqlite3_clear_bindings(db->known_synonym);
    if (found)
        return 1;
    char quoted[CATDB_WORD_BYTES + 3];
    if (n + 3 > sizeof quoted || memchr(s, '"', n))
        return 0;
    quoted[0] = '"';
    memcpy(quoted + 1, s, n);
    quoted[n + 1] = '"';
    quoted[n + 2] = 0;
    sqlite3_bind_text(db->known_word, 1, quoted, -1, SQLITE_STATIC);
    found = sqlite3_step(db->known_word) == SQLITE_ROW;
    sqlite3_reset(db->known_word);
    sqlite3_clear_bindings(db->known_word);
    return found;
}

int catdb_compound_split_query(cat_db *db, const char *word, size_t n, catdb_word_form *head,
                               catdb_word_form *tail)
{
    catdb_word_form forms[3];
    if (catdb_query_forms(db->sql, &db->words, word, n, forms, 3) <= 0)
        return 0;
    for (size_t i = 0; i < forms[0].len; i++)
        if (!((forms[0].text[i] >= 'a' && forms[0].text[i] <= 'z')))
            return 0; /* letters only: "600x600" or "nk-5124" is no compound */
    return split_with(in_catalog, db, forms[0].text, forms[0].len, head, tail);
}

/* ---- keeping the index in step with the lexicon ------------------------------------------- */

void catdb_words_stamp(char *buf, size_t size)
{
    snprintf(buf, size, "%016llx", (unsigned long long)catdb_synonyms_hash(CATDB_HASH64_INIT));
}

cat_db_result catdb_words_check(sqlite3 *sql, const char *path, char *err, size_t err_size)
{
    char want[32], have[32];
    catdb_words_stamp(want, sizeof want);
    cat_db_result r = catdb_meta_get(sql, path, "index_words", have, sizeof have, err, err_size);
    if (r != CAT_DB_OK || !strcmp(have, want))
        return r;
    /* FTS5 removes a row by tokenizing its old text again: a row indexed with another lexicon
     * would leave its compound parts behind, so the whole index is made again, once. */
    r = catdb_exec(sql, path, "cannot start rebuilding the search index", "BEGIN IMMEDIATE", err,
                   err_size);
    if (r != CAT_DB_OK)
        return r;
    r = catdb_meta_get(sql, path, "index_words", have, sizeof have, err, err_size);
    if (r == CAT_DB_OK && strcmp(have, want) != 0) {
        r = catdb_exec(sql, path, "cannot rebuild the search index",
                       "INSERT INTO product_fts (product_fts) VALUES ('rebuild')", err, err_size);
        if (r == CAT_DB_OK)
            r = catdb_meta_set(sql, path, "index_words", want, err, err_size);
    }
    if (r == CAT_DB_OK)
        r = catdb_exec(sql, path, "cannot commit the rebuilt search index", "COMMIT", err,
                       err_size);
    if (r != CAT_DB_OK)
        sqlite3_exec(sql, "ROLLBACK", NULL, NULL, NULL);
    return r;
}
