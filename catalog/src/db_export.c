/* Export in the import format: every column, one row per variant, numbers in the shortest
 * text that reads back as the same value, so export -> import -> export gives the same bytes. */
#include "db_internal.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static const char export_sql[] =
    "SELECT m.name, p.article, p.gtin, p.category, coalesce(s.name, ''), p.name, p.short_text, "
    "p.long_text, p.width_mm, p.depth_mm, p.height_mm, p.price_cents, p.currency, "
    "p.vat_percent, p.unit, p.discount_group, p.model, p.mounting_height_mm, p.mounting_to, "
    "p.companions, v.code, v.name, v.surcharge_cents, v.ambient_r, v.ambient_g, v.ambient_b, "
    "v.diffuse_r, "
    "v.diffuse_g, v.diffuse_b, v.specular_r, v.specular_g, v.specular_b, v.emissive_r, "
    "v.emissive_g, v.emissive_b, v.shininess, v.reflectivity, v.glossiness, v.blend, "
    "v.transparency, v.ior, v.pattern, v.grain_deg, "
    "t.type, t.nominal_w_mm, t.nominal_h_mm, t.work_w_mm, t.work_h_mm, t.grout_mm, "
    "t.thickness_mm, t.calibre, t.surface, t.m2_per_box, t.pieces_per_box, t.texture "
    "FROM products p JOIN manufacturers m ON m.id = p.manufacturer_id "
    "LEFT JOIN series s ON s.id = p.series_id "
    "LEFT JOIN variants v ON v.product_id = p.id "
    "LEFT JOIN tiles t ON t.product_id = p.id "
    "ORDER BY m.name, p.article, v.code";

/* The select's columns follow the import format's, except that each colour takes three. */
#define Q_AMBIENT 23

static int query_column(int c)
{
    return c < COL_AMBIENT ? c : c + 8; /* (ambient .. emissive: 4 columns, 12 values) */
}

static void put_text(FILE *f, const char *s)
{
    size_t n = strlen(s);
    int quote = n > 0 && (strpbrk(s, ",\"\n\r") || s[0] == ' ' || s[0] == '\t' || s[n - 1] == ' ' ||
                          s[n - 1] == '\t');
    if (!quote) {
        fwrite(s, 1, n, f);
        return;
    }
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"')
            fputc('"', f);
        fputc(*s, f);
    }
    fputc('"', f);
}

static void put_real(FILE *f, sqlite3_stmt *st, int i)
{
    if (sqlite3_column_type(st, i) == SQLITE_NULL)
        return;
    char buf[40];
    catdb_format_real(sqlite3_column_double(st, i), buf, sizeof buf);
    fputs(buf, f);
}

static void put_rgb(FILE *f, sqlite3_stmt *st, int i)
{
    if (sqlite3_column_type(st, i) == SQLITE_NULL)
        return;
    for (int k = 0; k < 3; k++) {
        if (k)
            fputc(' ', f);
        put_real(f, st, i + k);
    }
}

static void put_money(FILE *f, sqlite3_stmt *st, int i)
{
    if (sqlite3_column_type(st, i) == SQLITE_NULL)
        return;
    char buf[40];
    catdb_format_money(sqlite3_column_int64(st, i), buf, sizeof buf);
    fputs(buf, f);
}

static void put_column(FILE *f, sqlite3_stmt *st, int i)
{
    const unsigned char *t = sqlite3_column_text(st, i);
    put_text(f, t ? (const char *)t : "");
}

/* "none" is written as an empty cell (the import's default), so plain rows stay plain. */
static void put_pattern(FILE *f, sqlite3_stmt *st, int i)
{
    const unsigned char *t = sqlite3_column_text(st, i);
    if (t && strcmp((const char *)t, "none"))
        put_text(f, (const char *)t);
}

/* The grain by its word where it has one; NULL (along the longer side) as an empty cell. */
static void put_grain(FILE *f, sqlite3_stmt *st, int i)
{
    if (sqlite3_column_type(st, i) == SQLITE_NULL)
        return;
    double deg = sqlite3_column_double(st, i);
    if (deg == 0.0 || deg == 90.0)
        fputs(deg == 0.0 ? "horizontal" : "vertical", f);
    else
        put_real(f, st, i);
}

static void put_row(FILE *f, sqlite3_stmt *st)
{
    for (int c = 0; c < COL_COUNT; c++) {
        if (c)
            fputc(',', f);
        switch (c) {
        case COL_WIDTH:
        case COL_DEPTH:
        case COL_HEIGHT:
        case COL_MOUNTING_HEIGHT:
        case COL_VAT:
        case COL_SHININESS:
        case COL_REFLECTIVITY:
        case COL_GLOSSINESS:
        case COL_TRANSPARENCY:
        case COL_IOR:
        case COL_NOMINAL_W:
        case COL_NOMINAL_H:
        case COL_WORK_W:
        case COL_WORK_H:
        case COL_GROUT:
        case COL_THICKNESS:
        case COL_M2_PER_BOX:
            put_real(f, st, query_column(c));
            break;
        case COL_PATTERN:
            put_pattern(f, st, query_column(c));
            break;
        case COL_GRAIN:
            put_grain(f, st, query_column(c));
            break;
        case COL_LIST_PRICE:
        case COL_VARIANT_SURCHARGE:
            put_money(f, st, query_column(c));
            break;
        case COL_AMBIENT:
        case COL_DIFFUSE:
        case COL_SPECULAR:
        case COL_EMISSIVE:
            put_rgb(f, st, Q_AMBIENT + 3 * (c - COL_AMBIENT));
            break;
        default:
            put_column(f, st, query_column(c));
            break;
        }
    }
    fputc('\n', f);
}

cat_db_result cat_export_csv(cat_db *db, FILE *out, long *rows, char *err, size_t err_size)
{
    if (rows)
        *rows = 0;
    if (!db || !out)
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID, "cat_export_csv: no catalog or file");
    catdb_recover(db);
    sqlite3_stmt *st = NULL;
    if (sqlite3_prepare_v2(db->sql, export_sql, -1, &st, NULL) != SQLITE_OK) {
        sqlite3_finalize(st);
        return catdb_sql_fail(db->sql, db->path, err, err_size, "cannot export");
    }
    for (int c = 0; c < COL_COUNT; c++) {
        if (c)
            fputc(',', out);
        fputs(catdb_col_name((catdb_col)c), out);
    }
    fputc('\n', out);
    long n = 0;
    int rc;
    while ((rc = sqlite3_step(st)) == SQLITE_ROW) {
        put_row(out, st);
        n++;
    }
    sqlite3_finalize(st);
    if (rc != SQLITE_DONE)
        return catdb_sql_fail(db->sql, db->path, err, err_size, "cannot export");
    if (fflush(out) != 0 || ferror(out))
        return catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot write the export: %s", db->path,
                          strerror(errno));
    if (rows)
        *rows = n;
    return CAT_DB_OK;
}

cat_db_result cat_export_csv_file(cat_db *db, const char *path, long *rows, char *err,
                                  size_t err_size)
{
    if (rows)
        *rows = 0;
    if (!db || !path)
        return catdb_fail(err, err_size, CAT_DB_ERR_INVALID, "cat_export_csv_file: no path");
    char tmp[4200];
    catdb_temp_name(path, tmp, sizeof tmp);
    FILE *f = fopen(tmp, "wb");
    if (!f)
        return catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot write: %s", path,
                          strerror(errno));
    cat_db_result r = cat_export_csv(db, f, rows, err, err_size);
    if (r == CAT_DB_OK && fsync(fileno(f)) != 0)
        r = catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
    if (fclose(f) != 0 && r == CAT_DB_OK)
        r = catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot write: %s", path, strerror(errno));
    if (r == CAT_DB_OK)
        r = catdb_rename_into_place(tmp, path, err, err_size);
    if (r != CAT_DB_OK) {
        remove(tmp);
        if (rows)
            *rows = 0;
    }
    return r;
}
