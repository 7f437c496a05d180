/* The search's synonym table: the shipped list (db_synonyms.inc) loaded into search_synonyms as
 * one row per form of each one-word term (folded and both stems, db_words.c) and one row for a
 * term of several words (its folded text), so that a query word's forms find its groups with one
 * indexed lookup. */
#include "db_internal.h"

#include <stdio.h>
#include <string.h>

static const char synonym_list[] =
#include "db_synonyms.inc"
    ;

const char *catdb_synonym_list(void)
{
    return synonym_list;
}

uint64_t catdb_synonyms_hash(uint64_t h)
{
    return catdb_hash64(h, synonym_list, sizeof synonym_list);
}

static int is_space(char c)
{
    return c == ' ' || c == '\t';
}

/* Inserts the rows of one term (text[0 .. n)) of group `group`. */
static int insert_term(sqlite3_stmt *st, catdb_stemmers *stemmers, int group, const char *text,
                       size_t n)
{
    char term[CATDB_WORD_BYTES + 1];
    if (n > CATDB_WORD_BYTES)
        n = CATDB_WORD_BYTES;
    memcpy(term, text, n);
    term[n] = 0;
    catdb_word_form forms[3];
    int count = 0;
    if (strpbrk(term, " -")) {
        forms[0].len = catdb_word_fold(term, n, forms[0].text, sizeof forms[0].text);
        count = 1;
    } else {
        count = catdb_word_forms(stemmers, term, n, forms);
    }
    for (int k = 0; k < count; k++) {
        sqlite3_bind_int(st, 1, group);
        sqlite3_bind_text(st, 2, term, (int)n, SQLITE_TRANSIENT);
        sqlite3_bind_text(st, 3, forms[k].text, (int)forms[k].len, SQLITE_TRANSIENT);
        int rc = sqlite3_step(st);
        sqlite3_reset(st);
        if (rc != SQLITE_DONE)
            return 0;
    }
    return 1;
}

cat_db_result catdb_synonyms_load(sqlite3 *sql, const char *path, char *err, size_t err_size)
{
    cat_db_result r = catdb_exec(sql, path, "cannot clear the synonym table",
                                 "DELETE FROM search_synonyms", err, err_size);
    if (r != CAT_DB_OK)
        return r;
    catdb_stemmers *stemmers = catdb_stemmers_new();
    if (!stemmers)
        return catdb_fail(err, err_size, CAT_DB_ERR_OUT_OF_MEMORY, "%s: out of memory", path);
    sqlite3_stmt *st = NULL;
    int ok = sqlite3_prepare_v2(sql,
                                "INSERT OR IGNORE INTO search_synonyms (group_id, term, form)"
                                " VALUES (?1, ?2, ?3)",
                                -1, &st, NULL) == SQLITE_OK;
    int group = 0;
    for (const char *line = synonym_list; ok && *line;) {
        const char *end = strchr(line, '\n');
        if (!end)
            end = line + strlen(line);
        group++;
        for (const char *p = line; ok && p < end;) {
            while (p < end && (is_space(*p) || *p == ','))
                p++;
            const char *start = p;
            while (p < end && *p != ',')
                p++;
            const char *stop = p;
            while (stop > start && is_space(stop[-1]))
                stop--;
            if (stop > start)
                ok = insert_term(st, stemmers, group, start, (size_t)(stop - start));
        }
        line = *end ? end + 1 : end;
    }
    sqlite3_finalize(st);
    catdb_stemmers_free(stemmers);
    if (!ok)
        return catdb_sql_fail(sql, path, err, err_size, "cannot fill the synonym table");
    return CAT_DB_OK;
}
