/* catdb_rank(product_fts, w1, .., w7): the search's ranking, an FTS5 auxiliary function.
 *
 * bm25 does real work for every matching row in this index (a docsize lookup per
 * row, and a pass over every phrase's matches for its IDF), too slow for search as you type
 * over a common word in a few thousand products. This ranking reads only the current row's phrase
 * instances, which FTS5 already holds in memory: for each phrase and column, the column's weight
 * times tf / (tf + 0.5), summed and negated (lower is better, as with bm25); ties go to the shorter
 * name, which stands in for bm25's length normalisation.
 * The FTS5 API (Fts5ExtensionApi, fts5_api) is declared in sqlite3.h. */
#include "db_internal.h"

#include <string.h>

enum { MAX_PHRASES = 40, MAX_COLUMNS = 8 };

static void rank(const Fts5ExtensionApi *api, Fts5Context *fts, sqlite3_context *ctx, int n_val,
                 sqlite3_value **val)
{
    int columns = api->xColumnCount(fts);
    int phrases = api->xPhraseCount(fts);
    int inst = 0;
    if (api->xInstCount(fts, &inst) != SQLITE_OK) {
        sqlite3_result_error(ctx, "catdb_rank: cannot read the matches", -1);
        return;
    }
    if (columns > MAX_COLUMNS)
        columns = MAX_COLUMNS;
    if (phrases > MAX_PHRASES)
        phrases = MAX_PHRASES;
    unsigned short tf[MAX_PHRASES][MAX_COLUMNS];
    memset(tf, 0, sizeof tf);
    for (int i = 0; i < inst; i++) {
        int phrase, col, off;
        if (api->xInst(fts, i, &phrase, &col, &off) != SQLITE_OK)
            break;
        if (phrase >= 0 && phrase < phrases && col >= 0 && col < columns && tf[phrase][col] < 60000)
            tf[phrase][col]++;
    }
    double score = 0;
    for (int c = 0; c < columns; c++) {
        double w = c < n_val ? sqlite3_value_double(val[c]) : 1.0;
        for (int p = 0; p < phrases; p++)
            if (tf[p][c])
                score += w * tf[p][c] / (tf[p][c] + 0.5);
    }
    /* Of two equal matches, the shorter name first: "Mirror 600" before "Mirror cabinet 600,
     * 2 doors" for "mirror 600". Its token count comes from FTS5's small docsize table. */
    int name_tokens = 0;
    if (api->xColumnSize(fts, 0, &name_tokens) != SQLITE_OK)
        name_tokens = 0;
    sqlite3_result_double(ctx, -score + 0.001 * (name_tokens < 1000 ? name_tokens : 1000));
}

int catdb_register_rank(sqlite3 *sql)
{
    fts5_api *api = NULL;
    sqlite3_stmt *st = NULL;
    if (sqlite3_prepare_v2(sql, "SELECT fts5(?1)", -1, &st, NULL) != SQLITE_OK)
        return 0;
    sqlite3_bind_pointer(st, 1, (void *)&api, "fts5_api_ptr", NULL);
    sqlite3_step(st);
    sqlite3_finalize(st);
    return api && api->iVersion >= 2 &&
           api->xCreateFunction(api, "catdb_rank", NULL, rank, NULL) == SQLITE_OK;
}
