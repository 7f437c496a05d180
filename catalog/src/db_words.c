/* The search's words: the "tessera" FTS5 tokenizer and the folding it shares with the synonym
 * lookup.
 *
 * A word is cut and lower-cased by FTS5's unicode61 tokenizer with remove_diacritics 2 (so
 * "Wäsche" is "wasche"); then "ß" becomes "ss" (unicode61 keeps it: it is a letter, not a letter
 * with a diacritic) and the German transcriptions "ae", "oe", "ue" become "a", "o", "u", so that
 * "Weiß", "weiss", "Wäsche" and "Waesche" all reach the index as one word. The rule also folds
 * English words ("blue" is "blu"), harmlessly: documents and queries are folded alike.
 *
 * Each folded word is indexed together with its Snowball stems (libstemmer, the "german" and
 * "english" algorithms, https://snowballstem.org/algorithms/) as colocated tokens, the way the
 * FTS5 documentation adds synonyms (https://sqlite.org/fts5.html#synonym_support, method 3).
 * A query word is looked up as the alternatives word, German stem, English stem, so "Waschtische"
 * finds "Waschtisch" and "basins" finds "basin". A prefix query ("therm"*) looks up the folded
 * word alone: a stem of a half-typed word means nothing. */
#include "db_internal.h"

#include <libstemmer.h>
#include <stdlib.h>
#include <string.h>

size_t catdb_word_fold(const char *in, size_t n, char *out, size_t size)
{
    size_t o = 0;
    if (!size)
        return 0;
    for (size_t i = 0; i < n && o + 2 < size; i++) {
        unsigned char c = (unsigned char)in[i];
        if (c == 0xC3 && i + 1 < n && (unsigned char)in[i + 1] == 0x9F) { /* ß */
            out[o++] = 's';
            out[o++] = 's';
            i++;
        } else if (c == 'e' && o > 0 &&
                   (out[o - 1] == 'a' || out[o - 1] == 'o' || out[o - 1] == 'u')) {
            /* ae, oe, ue: the transcribed umlaut, folded like the umlaut itself */
        } else {
            out[o++] = (char)c;
        }
    }
    out[o] = 0;
    return o;
}

struct catdb_stemmers {
    struct sb_stemmer *german, *english;
};

catdb_stemmers *catdb_stemmers_new(void)
{
    catdb_stemmers *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->german = sb_stemmer_new("german", "UTF_8");
    s->english = sb_stemmer_new("english", "UTF_8");
    if (!s->german || !s->english) {
        catdb_stemmers_free(s);
        return NULL;
    }
    return s;
}

void catdb_stemmers_free(catdb_stemmers *s)
{
    if (!s)
        return;
    if (s->german)
        sb_stemmer_delete(s->german);
    if (s->english)
        sb_stemmer_delete(s->english);
    free(s);
}

/* The stem of a folded word in one language, into out; 0 when it cannot be made. */
static size_t stem_with(struct sb_stemmer *st, const char *word, size_t n, char *out, size_t size)
{
    const sb_symbol *s = sb_stemmer_stem(st, (const sb_symbol *)word, (int)n);
    if (!s)
        return 0;
    size_t len = (size_t)sb_stemmer_length(st);
    if (len == 0 || len >= size)
        return 0;
    memcpy(out, s, len);
    out[len] = 0;
    return len;
}

int catdb_word_forms(catdb_stemmers *s, const char *word, size_t n, catdb_word_form forms[3])
{
    int count = 0;
    size_t len = catdb_word_fold(word, n, forms[0].text, sizeof forms[0].text);
    if (!len)
        return 0;
    forms[0].len = len;
    count = 1;
    struct sb_stemmer *langs[2] = {s->german, s->english};
    for (int l = 0; l < 2; l++) {
        catdb_word_form *f = &forms[count];
        f->len = stem_with(langs[l], forms[0].text, len, f->text, sizeof f->text);
        int seen = f->len == 0;
        for (int k = 0; k < count && !seen; k++)
            seen = forms[k].len == f->len && !memcmp(forms[k].text, f->text, f->len);
        if (!seen)
            count++;
    }
    return count;
}

/* ---- the FTS5 tokenizer ---------------------------------------------------------------------- */

typedef struct words_tokenizer {
    fts5_tokenizer base; /* unicode61's methods */
    Fts5Tokenizer *base_instance;
    catdb_stemmers *stemmers;
    catdb_compounds *compounds;
} words_tokenizer;

typedef struct words_call {
    words_tokenizer *tok;
    int flags;
    void *ctx;
    int (*emit)(void *ctx, int flags, const char *token, int n, int start, int end);
} words_call;

static int words_token(void *p, int tflags, const char *token, int n, int start, int end)
{
    words_call *c = p;
    if (n <= 0 || n >= CATDB_WORD_BYTES)
        return c->emit(c->ctx, tflags, token, n, start, end);
    catdb_word_form forms[3];
    int count;
    if (c->flags & FTS5_TOKENIZE_PREFIX) {
        forms[0].len = catdb_word_fold(token, (size_t)n, forms[0].text, sizeof forms[0].text);
        count = forms[0].len ? 1 : 0;
    } else {
        count = catdb_word_forms(c->tok->stemmers, token, (size_t)n, forms);
    }
    if (!count)
        return SQLITE_OK;
    int rc = c->emit(c->ctx, tflags, forms[0].text, (int)forms[0].len, start, end);
    for (int k = 1; k < count && rc == SQLITE_OK; k++)
        rc = c->emit(c->ctx, FTS5_TOKEN_COLOCATED, forms[k].text, (int)forms[k].len, start, end);
    /* A compound in a document is also indexed under its last part, with that part's stems, at
     * its own place: "Eckbadewanne" is found by "Badewanne". Only the last part: German compounds
     * are right-headed, a "Waschtischmischer" is a mixer, not a Waschtisch. Queries are not
     * split here: a query compound needs its parts ANDed, which db_search.c does. */
    catdb_word_form parts[2];
    if (rc == SQLITE_OK && (c->flags & FTS5_TOKENIZE_DOCUMENT) &&
        catdb_compound_split(c->tok->compounds, forms[0].text, forms[0].len, &parts[0],
                             &parts[1])) {
        catdb_word_form tail[3];
        int tc = catdb_word_forms(c->tok->stemmers, parts[1].text, parts[1].len, tail);
        for (int k = 0; k < tc && rc == SQLITE_OK; k++)
            rc = c->emit(c->ctx, FTS5_TOKEN_COLOCATED, tail[k].text, (int)tail[k].len, start, end);
    }
    return rc;
}

static int words_tokenize(Fts5Tokenizer *t, void *ctx, int flags, const char *text, int n,
                          int (*emit)(void *, int, const char *, int, int, int))
{
    words_tokenizer *tok = (words_tokenizer *)t;
    words_call call = {tok, flags, ctx, emit};
    return tok->base.xTokenize(tok->base_instance, &call, flags, text, n, words_token);
}

static void words_delete(Fts5Tokenizer *t)
{
    words_tokenizer *tok = (words_tokenizer *)t;
    if (!tok)
        return;
    if (tok->base_instance)
        tok->base.xDelete(tok->base_instance);
    catdb_stemmers_free(tok->stemmers);
    catdb_compounds_free(tok->compounds);
    free(tok);
}

static int words_create(void *api_ptr, const char **args, int n_args, Fts5Tokenizer **out)
{
    (void)args;
    (void)n_args;
    fts5_api *api = api_ptr;
    *out = NULL;
    words_tokenizer *tok = calloc(1, sizeof *tok);
    if (!tok)
        return SQLITE_NOMEM;
    void *base_ctx = NULL;
    static const char *base_args[] = {"remove_diacritics", "2"};
    int rc = api->xFindTokenizer(api, "unicode61", &base_ctx, &tok->base);
    if (rc == SQLITE_OK)
        rc = tok->base.xCreate(base_ctx, base_args, 2, &tok->base_instance);
    if (rc == SQLITE_OK && !(tok->stemmers = catdb_stemmers_new()))
        rc = SQLITE_NOMEM;
    if (rc == SQLITE_OK && !(tok->compounds = catdb_compounds_new()))
        rc = SQLITE_NOMEM;
    if (rc != SQLITE_OK) {
        words_delete((Fts5Tokenizer *)tok);
        return rc;
    }
    *out = (Fts5Tokenizer *)tok;
    return SQLITE_OK;
}

int catdb_register_words(sqlite3 *sql)
{
    fts5_api *api = NULL;
    sqlite3_stmt *st = NULL;
    if (sqlite3_prepare_v2(sql, "SELECT fts5(?1)", -1, &st, NULL) != SQLITE_OK)
        return 0;
    sqlite3_bind_pointer(st, 1, (void *)&api, "fts5_api_ptr", NULL);
    sqlite3_step(st);
    sqlite3_finalize(st);
    fts5_tokenizer methods = {words_create, words_delete, words_tokenize};
    return api && api->xCreateTokenizer(api, "tessera", api, &methods, NULL) == SQLITE_OK;
}

/* ---- query words ----------------------------------------------------------------------------- */

struct catdb_query_words {
    fts5_tokenizer methods;
    Fts5Tokenizer *instance;
};

typedef struct forms_out {
    catdb_word_form *forms;
    int max, count, tokens;
} forms_out;

static int collect_form(void *p, int tflags, const char *token, int n, int start, int end)
{
    (void)start;
    (void)end;
    forms_out *o = p;
    if (!(tflags & FTS5_TOKEN_COLOCATED))
        o->tokens++;
    if (o->tokens == 1 && o->count < o->max && n > 0 && n <= CATDB_WORD_BYTES) {
        memcpy(o->forms[o->count].text, token, (size_t)n);
        o->forms[o->count].text[n] = 0;
        o->forms[o->count].len = (size_t)n;
        o->count++;
    }
    return SQLITE_OK;
}

void catdb_query_words_free(catdb_query_words *words)
{
    if (!words)
        return;
    if (words->instance)
        words->methods.xDelete(words->instance);
    free(words);
}

int catdb_query_forms(sqlite3 *sql, catdb_query_words **words, const char *word, size_t n,
                      catdb_word_form *forms, int max)
{
    if (!*words) {
        fts5_api *api = NULL;
        sqlite3_stmt *st = NULL;
        if (sqlite3_prepare_v2(sql, "SELECT fts5(?1)", -1, &st, NULL) != SQLITE_OK)
            return 0;
        sqlite3_bind_pointer(st, 1, (void *)&api, "fts5_api_ptr", NULL);
        sqlite3_step(st);
        sqlite3_finalize(st);
        catdb_query_words *w = calloc(1, sizeof *w);
        void *ctx = NULL;
        if (!w || !api || api->xFindTokenizer(api, "tessera", &ctx, &w->methods) != SQLITE_OK ||
            w->methods.xCreate(ctx, NULL, 0, &w->instance) != SQLITE_OK) {
            free(w);
            return 0;
        }
        *words = w;
    }
    forms_out o = {forms, max, 0, 0};
    if ((*words)->methods.xTokenize((*words)->instance, &o, FTS5_TOKENIZE_QUERY, word, (int)n,
                                    collect_form) != SQLITE_OK ||
        o.tokens != 1)
        return 0;
    return o.count;
}
