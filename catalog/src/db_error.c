/* Error messages of the catalog database: every message starts with the file it is about. */
#include "db_internal.h"

#include <stdarg.h>
#include <stdio.h>

cat_db_result catdb_fail(char *err, size_t err_size, cat_db_result code, const char *fmt, ...)
{
    if (!err || err_size == 0)
        return code;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, err_size, fmt, ap);
    va_end(ap);
    return code;
}

cat_db_result catdb_result_of(int sqlite_code)
{
    switch (sqlite_code & 0xff) {
    case SQLITE_OK:
    case SQLITE_DONE:
    case SQLITE_ROW:
        return CAT_DB_OK;
    case SQLITE_NOMEM:
        return CAT_DB_ERR_OUT_OF_MEMORY;
    case SQLITE_IOERR:
    case SQLITE_CANTOPEN:
    case SQLITE_READONLY:
    case SQLITE_FULL:
    case SQLITE_PERM:
        return CAT_DB_ERR_IO;
    case SQLITE_TOOBIG:
        return CAT_DB_ERR_TOO_LARGE;
    case SQLITE_CONSTRAINT:
    case SQLITE_MISMATCH:
    case SQLITE_RANGE:
        return CAT_DB_ERR_INVALID;
    default:
        return CAT_DB_ERR_DATABASE;
    }
}

cat_db_result catdb_sql_fail(sqlite3 *sql, const char *path, char *err, size_t err_size,
                             const char *what)
{
    int code = sql ? sqlite3_extended_errcode(sql) : SQLITE_NOMEM;
    const char *text = sql ? sqlite3_errmsg(sql) : "out of memory";
    cat_db_result r = catdb_result_of(code);
    if (r == CAT_DB_OK)
        r = CAT_DB_ERR_DATABASE;
    return catdb_fail(err, err_size, r, "%s: %s: %s", path ? path : "(catalog)", what, text);
}

const char *cat_db_result_name(cat_db_result r)
{
    switch (r) {
    case CAT_DB_OK:
        return "ok";
    case CAT_DB_ERR_IO:
        return "input/output error";
    case CAT_DB_ERR_PARSE:
        return "malformed CSV";
    case CAT_DB_ERR_INVALID:
        return "invalid data";
    case CAT_DB_ERR_NOT_FOUND:
        return "not found";
    case CAT_DB_ERR_AMBIGUOUS:
        return "ambiguous";
    case CAT_DB_ERR_VERSION:
        return "newer schema version";
    case CAT_DB_ERR_DATABASE:
        return "database error";
    case CAT_DB_ERR_OUT_OF_MEMORY:
        return "out of memory";
    case CAT_DB_ERR_TOO_LARGE:
        return "too large";
    }
    return "unknown result";
}
