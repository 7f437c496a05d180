/* A CSV reader (RFC 4180, with the usual leniencies): comma-separated fields, fields in double
 * quotes may hold commas, quotes ("") and line breaks; records end with LF, CRLF or CR; a UTF-8
 * byte order mark is skipped; completely empty lines are skipped. A quote inside an unquoted
 * field is taken literally. Line breaks inside quoted fields become LF. Reading stops at the
 * first structural error (an unclosed quote, a stray character after a closing quote, a
 * record, field or field count above the limits), which names its line. */
#include "db_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void catdb_csv_init(catdb_csv *c, const void *data, size_t size)
{
    memset(c, 0, sizeof *c);
    c->data = data;
    c->size = size;
    c->line = 1;
    if (size >= 3 && c->data[0] == 0xEF && c->data[1] == 0xBB && c->data[2] == 0xBF)
        c->pos = 3;
}

void catdb_csv_free(catdb_csv *c)
{
    free(c->text);
    free(c->start);
    free(c->length);
    free(c->quoted);
    c->text = NULL;
    c->start = c->length = NULL;
    c->quoted = NULL;
    c->text_cap = 0;
    c->field_cap = 0;
}

static int fail(catdb_csv *c, long line, cat_db_result code, const char *fmt, long a, long b)
{
    c->error_line = line;
    c->error_code = code;
    snprintf(c->error, sizeof c->error, fmt, a, b);
    return -1;
}

/* Room for `more` bytes of text plus a terminating zero. */
static int reserve_text(catdb_csv *c, size_t used, size_t more)
{
    if (used + more + 1 <= c->text_cap)
        return 1;
    size_t cap = c->text_cap ? c->text_cap : 1024;
    while (cap < used + more + 1)
        cap *= 2;
    char *t = realloc(c->text, cap);
    if (!t)
        return 0;
    c->text = t;
    c->text_cap = cap;
    return 1;
}

static int reserve_field(catdb_csv *c)
{
    if (c->field_count < c->field_cap)
        return 1;
    int cap = c->field_cap ? c->field_cap * 2 : 16;
    size_t *s = realloc(c->start, (size_t)cap * sizeof *s);
    if (s)
        c->start = s;
    size_t *l = realloc(c->length, (size_t)cap * sizeof *l);
    if (l)
        c->length = l;
    int *q = realloc(c->quoted, (size_t)cap * sizeof *q);
    if (q)
        c->quoted = q;
    if (!s || !l || !q)
        return 0;
    c->field_cap = cap;
    return 1;
}

int catdb_csv_next(catdb_csv *c)
{
    if (c->error_code != CAT_DB_OK)
        return -1;
    const unsigned char *d = c->data;
    size_t n = c->size;
    /* Skip empty lines. */
    while (c->pos < n && (d[c->pos] == '\n' || d[c->pos] == '\r')) {
        if (d[c->pos] == '\r' && c->pos + 1 < n && d[c->pos + 1] == '\n')
            c->pos++;
        c->pos++;
        c->line++;
    }
    if (c->pos >= n)
        return 0;
    c->record_line = c->line;
    c->field_count = 0;
    size_t record_start = c->pos, used = 0;
    for (;;) {
        if (c->field_count >= (int)CAT_IMPORT_MAX_COLUMNS)
            return fail(c, c->record_line, CAT_DB_ERR_TOO_LARGE,
                        "the record has more than %ld fields", (long)CAT_IMPORT_MAX_COLUMNS, 0);
        if (!reserve_field(c))
            return fail(c, c->record_line, CAT_DB_ERR_OUT_OF_MEMORY, "out of memory", 0, 0);
        int f = c->field_count++;
        c->start[f] = used;
        c->quoted[f] = 0;
        if (c->pos < n && d[c->pos] == '"') {
            long quote_line = c->line;
            c->quoted[f] = 1;
            c->pos++;
            for (;;) {
                if (c->pos >= n)
                    return fail(c, quote_line, CAT_DB_ERR_PARSE,
                                "field %ld: the quote opened here is never closed", f + 1L, 0);
                if (used - c->start[f] >= CAT_IMPORT_MAX_FIELD_BYTES)
                    return fail(c, c->record_line, CAT_DB_ERR_TOO_LARGE,
                                "field %ld is longer than %ld bytes", f + 1L,
                                (long)CAT_IMPORT_MAX_FIELD_BYTES);
                /* Copy the run up to the next quote or line break in one go. */
                size_t run = c->pos;
                while (run < n && d[run] != '"' && d[run] != '\n' && d[run] != '\r' &&
                       run - c->pos < CAT_IMPORT_MAX_FIELD_BYTES)
                    run++;
                if (run > c->pos) {
                    if (!reserve_text(c, used, run - c->pos))
                        return fail(c, c->record_line, CAT_DB_ERR_OUT_OF_MEMORY, "out of memory", 0,
                                    0);
                    memcpy(c->text + used, d + c->pos, run - c->pos);
                    used += run - c->pos;
                    c->pos = run;
                    continue;
                }
                if (!reserve_text(c, used, 1))
                    return fail(c, c->record_line, CAT_DB_ERR_OUT_OF_MEMORY, "out of memory", 0, 0);
                unsigned char ch = d[c->pos];
                if (ch == '"') {
                    if (c->pos + 1 < n && d[c->pos + 1] == '"') {
                        c->text[used++] = '"';
                        c->pos += 2;
                        continue;
                    }
                    c->pos++;
                    break;
                }
                /* A line break inside the quotes: CRLF, CR and LF all become LF. */
                if (ch == '\r' && c->pos + 1 < n && d[c->pos + 1] == '\n')
                    c->pos++;
                c->pos++;
                c->line++;
                c->text[used++] = '\n';
            }
            while (c->pos < n && (d[c->pos] == ' ' || d[c->pos] == '\t'))
                c->pos++;
            if (c->pos < n && d[c->pos] != ',' && d[c->pos] != '\n' && d[c->pos] != '\r')
                return fail(c, c->line, CAT_DB_ERR_PARSE,
                            "field %ld: unexpected character after the closing quote (a quote "
                            "inside a quoted field is written \"\")",
                            f + 1L, 0);
        } else {
            size_t end = c->pos;
            while (end < n && d[end] != ',' && d[end] != '\n' && d[end] != '\r' &&
                   end - c->pos <= CAT_IMPORT_MAX_FIELD_BYTES)
                end++;
            if (end - c->pos > CAT_IMPORT_MAX_FIELD_BYTES)
                return fail(c, c->record_line, CAT_DB_ERR_TOO_LARGE,
                            "field %ld is longer than %ld bytes", f + 1L,
                            (long)CAT_IMPORT_MAX_FIELD_BYTES);
            if (!reserve_text(c, used, end - c->pos))
                return fail(c, c->record_line, CAT_DB_ERR_OUT_OF_MEMORY, "out of memory", 0, 0);
            memcpy(c->text + used, d + c->pos, end - c->pos);
            used += end - c->pos;
            c->pos = end;
        }
        c->length[f] = used - c->start[f];
        c->text[used++] = 0;
        if (c->pos - record_start > CAT_IMPORT_MAX_RECORD_BYTES)
            return fail(c, c->record_line, CAT_DB_ERR_TOO_LARGE,
                        "the record is longer than %ld bytes", (long)CAT_IMPORT_MAX_RECORD_BYTES,
                        0);
        if (c->pos >= n)
            return 1;
        if (d[c->pos] == ',') {
            c->pos++;
            continue;
        }
        /* End of the record. */
        if (d[c->pos] == '\r' && c->pos + 1 < n && d[c->pos + 1] == '\n')
            c->pos++;
        c->pos++;
        c->line++;
        return 1;
    }
}

long catdb_csv_count_records(const void *data, size_t size)
{
    const unsigned char *d = data;
    long records = 0;
    int in_quotes = 0, content = 0;
    for (size_t i = 0; i < size; i++) {
        unsigned char ch = d[i];
        if (ch == '"') {
            in_quotes = !in_quotes;
            content = 1;
        } else if ((ch == '\n' || ch == '\r') && !in_quotes) {
            records += content;
            content = 0;
        } else {
            content = 1;
        }
    }
    return records + content;
}
