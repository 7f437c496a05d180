/* tessera catalog search|show|import|export|info|bench: the product catalog from the command
 * line. Every sub-command takes --db PATH (default: $TESSERA_CATALOG, else the user's cache
 * folder); the catalog is built from the shipped CSV files on first use. */
#include "catalog/catalog.h"
#include "app/output/safe_file.h"
#include "cli_commands.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* The shipped catalog data: $TESSERA_ASSETS/catalog, else the source tree's. */
static void source_dir(char *buf, size_t size)
{
    const char *env = getenv("TESSERA_ASSETS");
    snprintf(buf, size, "%s/catalog", env && *env ? env : TESSERA_SOURCE_DIR "/assets");
}

static int exit_code(cat_db_result r)
{
    switch (r) {
    case CAT_DB_OK:
        return CLI_OK;
    case CAT_DB_ERR_PARSE:
    case CAT_DB_ERR_INVALID:
    case CAT_DB_ERR_NOT_FOUND:
    case CAT_DB_ERR_AMBIGUOUS:
    case CAT_DB_ERR_TOO_LARGE:
        return CLI_USAGE;
    default:
        return CLI_FAILED;
    }
}

/* Search, show, export, info and bench only read: a current catalog is opened read-only,
 * without schema work (cat_catalog_open_read); import writes. */
enum catalog_use { CATALOG_READ, CATALOG_WRITE };

static int open_catalog(const cli_options *o, cat_db **db, enum catalog_use use)
{
    char path[4096], src[4096], err[4096];
    if (o->db)
        snprintf(path, sizeof path, "%s", o->db);
    else if (!cat_default_path(path, sizeof path)) {
        fprintf(stderr, "tessera catalog: no place for the catalog: set TESSERA_CATALOG or HOME, "
                        "or give --db PATH\n");
        return CLI_FAILED;
    }
    source_dir(src, sizeof src);
    struct stat st;
    if (stat(path, &st) != 0 && errno == ENOENT)
        fprintf(stderr, "tessera catalog: building %s from %s (first use)\n", path, src);
    double t0 = cli_now_ms();
    cat_db_result r = use == CATALOG_READ ? cat_catalog_open_read(path, src, db, err, sizeof err)
                                          : cat_catalog_open(path, src, db, err, sizeof err);
    if (r != CAT_DB_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_FAILED;
    }
    if (cat_db_read_only_reason(*db))
        fprintf(stderr, "tessera catalog: opened read-only (%s)\n", cat_db_read_only_reason(*db));
    double ms = cli_now_ms() - t0;
    if (ms > 1000)
        fprintf(stderr, "tessera catalog: opened %s in %.1f s\n", path, ms / 1000);
    return CLI_OK;
}

/* Prints text in a column of `width` characters (UTF-8 aware), cut with "~" when longer. */
static void cell(const char *text, int width)
{
    int chars = 0;
    const unsigned char *s = (const unsigned char *)text;
    size_t i = 0;
    for (; s[i]; i++) {
        if ((s[i] & 0xC0) == 0x80)
            continue;
        if (chars == width - 1) {
            size_t rest = 0;
            for (size_t k = i; s[k]; k++)
                rest += (s[k] & 0xC0) != 0x80;
            if (rest > 1) {
                fwrite(text, 1, i, stdout);
                fputs("~", stdout);
                chars++;
                goto pad;
            }
        }
        chars++;
    }
    fputs(text, stdout);
pad:
    for (; chars < width; chars++)
        fputc(' ', stdout);
}

static void money(long long cents, char *buf, size_t size)
{
    snprintf(buf, size, "%lld.%02lld", cents / 100, cents % 100);
}

/* Why a search found nothing: the word that matches no product, or that only the combination
 * (or a filter) has none. A word is never dropped from a search silently. */
static void say_unmatched(cat_db *db, const char *text)
{
    char word[CAT_SEARCH_MAX_TEXT + 1], err[1024];
    if (cat_search_unmatched(db, text, word, sizeof word, err, sizeof err) != CAT_DB_OK)
        fprintf(stderr, "tessera: %s\n", err);
    else if (word[0])
        fprintf(stderr, "no match for '%s'\n", word);
    else
        fprintf(stderr, "no product matches every word of '%s' (with the filters)\n", text);
}

int cli_cmd_catalog_search(const cli_options *o)
{
    if (o->arg_count == 0)
        return cli_usage_error(o);
    char text[CAT_SEARCH_MAX_TEXT + 1] = "";
    for (int i = 0; i < o->arg_count; i++) {
        size_t n = strlen(text);
        if (n + strlen(o->args[i]) + 2 > sizeof text) {
            fprintf(stderr, "tessera catalog search: the search text is longer than %d bytes\n",
                    CAT_SEARCH_MAX_TEXT);
            return CLI_USAGE;
        }
        snprintf(text + n, sizeof text - n, "%s%s", n ? " " : "", o->args[i]);
    }
    cat_db *db;
    int rc = open_catalog(o, &db, CATALOG_READ);
    if (rc != CLI_OK)
        return rc;
    cat_search_filter f = {.max_width_mm = o->max_width, .manufacturer = o->manufacturer};
    if (o->category)
        cat_category_parse(o->category, &f.category);
    int limit = o->limit ? o->limit : 20;
    cat_search_hit *hits = calloc((size_t)limit, sizeof *hits);
    if (!hits) {
        cat_db_close(db);
        fprintf(stderr, "tessera: out of memory\n");
        return CLI_FAILED;
    }
    int n = 0;
    char err[1024];
    double t0 = cli_now_ms();
    cat_db_result r = cat_search(db, text, &f, limit, hits, &n, err, sizeof err);
    double ms = cli_now_ms() - t0;
    if (r != CAT_DB_OK) {
        fprintf(stderr, "tessera: %s\n", err);
    } else if (n > 0) {
        printf("%-16s %-20s %-46s %-16s %-20s %s\n", "article", "manufacturer", "name", "category",
               "W x D x H mm", "list price");
        for (int i = 0; i < n; i++) {
            const cat_search_hit *h = &hits[i];
            char size[64], price[32], price_text[48];
            snprintf(size, sizeof size, "%g x %g x %g", h->width_mm, h->depth_mm, h->height_mm);
            money(h->price_cents, price, sizeof price);
            snprintf(price_text, sizeof price_text, "%s %s/%s", price, h->currency,
                     h->unit == CAT_UNIT_PIECE ? "pc" : cat_unit_name(h->unit));
            cell(h->article, 16);
            fputc(' ', stdout);
            cell(h->manufacturer, 20);
            fputc(' ', stdout);
            cell(h->name, 46);
            fputc(' ', stdout);
            cell(cat_category_name(h->category), 16);
            fputc(' ', stdout);
            cell(size, 20);
            printf(" %s\n", price_text);
        }
    }
    if (r == CAT_DB_OK)
        fprintf(stderr, "%d product%s (%.2f ms)\n", n, n == 1 ? "" : "s", ms);
    if (r == CAT_DB_OK && n == 0 && text[0])
        say_unmatched(db, text);
    free(hits);
    cat_db_close(db);
    return exit_code(r);
}

static void print_rgb(const char *label, const float c[3])
{
    printf(" %s %g %g %g", label, c[0], c[1], c[2]);
}

int cli_cmd_catalog_show(const cli_options *o)
{
    if (o->arg_count != 1)
        return cli_usage_error(o);
    cat_db *db;
    int rc = open_catalog(o, &db, CATALOG_READ);
    if (rc != CLI_OK)
        return rc;
    cat_product p;
    char err[1024];
    cat_db_result r = cat_product_find(db, o->manufacturer, o->args[0], &p, err, sizeof err);
    cat_db_close(db);
    if (r != CAT_DB_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return exit_code(r);
    }
    char price[32], gross[32], surcharge[32];
    money(p.price_cents, price, sizeof price);
    money((long long)llround(p.price_cents * (1 + p.vat_percent / 100)), gross, sizeof gross);
    printf("%s %s: %s\n", p.manufacturer, p.article, p.name);
    printf("  %-15s %s\n", "GTIN", p.gtin[0] ? p.gtin : "(none)");
    printf("  %-15s %s\n", "category", cat_category_name(p.category));
    printf("  %-15s %s\n", "series", p.series[0] ? p.series : "(none)");
    printf("  %-15s %s\n", "short text", p.short_text);
    printf("  %-15s %s\n", "long text", p.long_text);
    printf("  %-15s %g x %g x %g mm (width x depth x height)\n", "size", p.width_mm, p.depth_mm,
           p.height_mm);
    printf("  %-15s %s %s per %s, VAT %g %% (%s %s with VAT)\n", "list price", price, p.currency,
           cat_unit_name(p.unit), p.vat_percent, gross, p.currency);
    printf("  %-15s %s\n", "discount group", p.discount_group[0] ? p.discount_group : "(none)");
    printf("  %-15s %s\n", "model", p.model[0] ? p.model : "(none yet)");
    if (p.mounting_to != CAT_MOUNT_NONE)
        printf("  %-15s %g mm to its %s\n", "mounting", p.mounting_height_mm,
               cat_mount_to_name(p.mounting_to));
    else
        printf("  %-15s %s\n", "mounting",
               "(its category's, docs/editing.md \"Mounting heights\")");
    printf("  %-15s %s\n", "companions", p.companions[0] ? p.companions : "(none)");
    printf("  %-15s %s\n", "source", p.shipped ? "shipped catalog" : "imported");
    if (p.has_tile) {
        const cat_tile *t = &p.tile;
        printf("tile: %s, nominal %g x %g mm, work %g x %g mm, grout %g mm, thickness %g mm\n",
               cat_tile_type_name(t->type), t->nominal_w_mm, t->nominal_h_mm, t->work_w_mm,
               t->work_h_mm, t->grout_mm, t->thickness_mm);
        printf("      surface %s, calibre %s, %g m2 per box (%d pieces), texture %s\n",
               cat_surface_name(t->surface), t->calibre[0] ? t->calibre : "-", t->m2_per_box,
               t->pieces_per_box, t->texture[0] ? t->texture : "(none)");
    }
    printf("variants (%d):\n", p.variant_count);
    for (int i = 0; i < p.variant_count; i++) {
        const cat_variant *v = &p.variants[i];
        const cat_render_material *m = &v->material;
        money(v->surcharge_cents, surcharge, sizeof surcharge);
        printf("  %-6s %-32s +%s %s\n", v->code, v->name, surcharge, p.currency);
        printf("        ");
        print_rgb("ambient", m->ambient);
        print_rgb(" diffuse", m->diffuse);
        print_rgb(" specular", m->specular);
        print_rgb(" emissive", m->emissive);
        printf("\n         shininess %g  k_r %g  g %g  blend %s  transparency %g  IOR %g\n",
               m->shininess, m->reflectivity, m->glossiness, cat_blend_name(m->blend),
               m->transparency, m->ior);
        if (m->pattern != CAT_PATTERN_NONE) {
            char grain[32];
            if (m->grain_deg < 0.0f)
                snprintf(grain, sizeof grain, "along the longer side");
            else if (m->grain_deg == 0.0f || m->grain_deg == 90.0f)
                snprintf(grain, sizeof grain, m->grain_deg == 0.0f ? "horizontal" : "vertical");
            else
                snprintf(grain, sizeof grain, "%g degrees", (double)m->grain_deg);
            printf("         pattern %s, grain %s\n", cat_pattern_name(m->pattern), grain);
        }
    }
    cat_product_free(&p);
    return CLI_OK;
}

typedef struct progress_state {
    int tty;
    long last_tenth, last_done;
} progress_state;

static void progress(void *user, long done, long total)
{
    progress_state *s = user;
    if (total < 5000 || done == s->last_done)
        return; /* small files finish before a progress line would help */
    s->last_done = done;
    if (s->tty) {
        fprintf(stderr, "\rtessera catalog import: %ld / %ld rows", done, total);
        if (done >= total)
            fputc('\n', stderr);
        return;
    }
    long tenth = done * 10 / total;
    if (tenth != s->last_tenth || done >= total) {
        fprintf(stderr, "tessera catalog import: %ld / %ld rows\n", done, total);
        s->last_tenth = tenth;
    }
}

int cli_cmd_catalog_import(const cli_options *o)
{
    if (o->arg_count != 1)
        return cli_usage_error(o);
    cat_db *db;
    int rc = open_catalog(o, &db, CATALOG_WRITE);
    if (rc != CLI_OK)
        return rc;
    const char *file = o->args[0];
    progress_state ps = {.tty = isatty(2), .last_tenth = -1, .last_done = -1};
    cat_import_desc desc = {.dry_run = o->dry_run, .progress = progress, .user = &ps};
    cat_import_report rep;
    char err[2048];
    double t0 = cli_now_ms();
    cat_db_result r = cat_import_csv(db, file, &desc, &rep, err, sizeof err);
    double s = (cli_now_ms() - t0) / 1000;
    cat_db_close(db);
    if (r != CAT_DB_OK && rep.problem_count == 0) {
        fprintf(stderr, "tessera: %s\n", err);
    } else if (r != CAT_DB_OK) {
        for (int i = 0; i < rep.problems_kept; i++) {
            const cat_import_problem *p = &rep.problems[i];
            if (p->column[0])
                fprintf(stderr, "tessera: %s:%ld: column %s: %s\n", file, p->line, p->column,
                        p->message);
            else
                fprintf(stderr, "tessera: %s:%ld: %s\n", file, p->line, p->message);
        }
        if (rep.problem_count > rep.problems_kept)
            fprintf(stderr, "tessera: ... and %ld more problems\n",
                    rep.problem_count - rep.problems_kept);
        fprintf(stderr, "tessera: %s: %ld problem%s in %ld rows; nothing was imported\n", file,
                rep.problem_count, rep.problem_count == 1 ? "" : "s", rep.rows);
    } else {
        fprintf(stderr,
                "tessera catalog import: %s: %ld rows, %ld products added, %ld updated, %ld "
                "variants%s (%.2f s)\n",
                file, rep.rows, rep.products_added, rep.products_updated, rep.variants_written,
                o->dry_run ? "; dry run, nothing written" : "", s);
    }
    cat_import_report_free(&rep);
    return exit_code(r);
}

int cli_cmd_catalog_export(const cli_options *o)
{
    if (o->arg_count != 0)
        return cli_usage_error(o);
    cat_db *db;
    int rc = open_catalog(o, &db, CATALOG_READ);
    if (rc != CLI_OK)
        return rc;
    long rows = 0;
    char err[1024];
    cat_db_result r = o->output ? cat_export_csv_file(db, o->output, &rows, err, sizeof err)
                                : cat_export_csv(db, stdout, &rows, err, sizeof err);
    cat_db_close(db);
    if (r != CAT_DB_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_FAILED;
    }
    fprintf(stderr, "tessera catalog export: %ld rows%s%s\n", rows, o->output ? " to " : "",
            o->output ? o->output : "");
    return CLI_OK;
}

int cli_cmd_catalog_info(const cli_options *o)
{
    if (o->arg_count != 0)
        return cli_usage_error(o);
    cat_db *db;
    int rc = open_catalog(o, &db, CATALOG_READ);
    if (rc != CLI_OK)
        return rc;
    cat_db_stats s;
    char err[1024];
    cat_db_result r = cat_db_get_stats(db, &s, err, sizeof err);
    if (r == CAT_DB_OK) {
        printf("catalog        %s\n", cat_db_path(db));
        printf("schema         version %d\n", s.schema_version);
        printf("shipped data   %s\n", s.source_hash[0] ? s.source_hash : "(none)");
        printf("manufacturers  %lld\nseries         %lld\nproducts       %lld\n"
               "variants       %lld\ntiles          %lld\n",
               s.manufacturers, s.series, s.products, s.variants, s.tiles);
        for (int c = 1; c < CAT_CATEGORY_COUNT; c++)
            printf("  %-16s %lld\n", cat_category_name((cat_category)c), s.per_category[c]);
    } else {
        fprintf(stderr, "tessera: %s\n", err);
    }
    cat_db_close(db);
    return exit_code(r);
}

/* ---- bench: search latency over the catalog's own products ------------------------------- */

enum { Q_WORD, Q_PREFIX, Q_TWO_WORDS, Q_ARTICLE, Q_FILTERED, Q_KINDS };
static const char *const kind_names[Q_KINDS] = {"word", "prefix", "two words", "article",
                                                "word + filters"};

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The calling thread's CPU time in ms: on a machine shared with other work, a query's wall time
 * includes the time it waited for a core; its CPU time is what the search itself costs. */
static double thread_cpu_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

static double quantile(double *v, int n, double q)
{
    if (n == 0)
        return 0;
    qsort(v, (size_t)n, sizeof *v, by_value);
    int i = (int)floor(q * (n - 1) + 0.5);
    return v[i];
}

/* The k-th word of at least min_len letters of text into out; 0 if there is none. */
static int pick_word(const char *text, unsigned k, size_t min_len, char *out, size_t size)
{
    char words[16][64];
    int n = 0;
    for (const char *p = text; *p && n < 16;) {
        while (*p && !((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z')))
            p++;
        const char *s = p;
        while ((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z'))
            p++;
        size_t len = (size_t)(p - s);
        if (len >= min_len && len < sizeof words[0]) {
            memcpy(words[n], s, len);
            words[n++][len] = 0;
        }
    }
    if (!n)
        return 0;
    snprintf(out, size, "%s", words[k % (unsigned)n]);
    return 1;
}

int cli_cmd_catalog_bench(const cli_options *o)
{
    cat_db *db;
    int rc = open_catalog(o, &db, CATALOG_READ);
    if (rc != CLI_OK)
        return rc;
    char err[1024];
    cat_db_stats st;
    cat_db_result r = cat_db_get_stats(db, &st, err, sizeof err);
    if (r != CAT_DB_OK || st.products == 0) {
        fprintf(stderr, "tessera: %s\n", r != CAT_DB_OK ? err : "the catalog is empty");
        cat_db_close(db);
        return CLI_FAILED;
    }
    int per_kind = o->queries ? o->queries : 400;
    double *ms[Q_KINDS];
    double *cpu = calloc((size_t)Q_KINDS * (size_t)per_kind, sizeof *cpu);
    int cpu_n = 0;
    int counts[Q_KINDS] = {0};
    long hits_total = 0;
    for (int k = 0; k < Q_KINDS; k++)
        ms[k] = calloc((size_t)per_kind, sizeof *ms[k]);
    cat_search_hit *hits = calloc(20, sizeof *hits);
    unsigned seed = 12345;
    /* Queries come from products picked at random (by row id; gaps are skipped). */
    for (int round = 0; round < per_kind * 4 && hits && ms[Q_KINDS - 1]; round++) {
        seed = seed * 1103515245u + 12345u;
        long long id = 1 + (long long)(seed >> 4) % (st.products + st.products / 10 + 1);
        cat_product p;
        if (cat_product_get(db, id, &p, NULL, 0) != CAT_DB_OK)
            continue;
        for (int k = 0; k < Q_KINDS; k++) {
            if (counts[k] >= per_kind)
                continue;
            char text[200], w1[64], w2[64];
            cat_search_filter f = {0};
            int ok = 1;
            switch (k) {
            case Q_WORD:
                ok = pick_word(p.name, seed >> 8, 4, text, sizeof text);
                break;
            case Q_PREFIX:
                ok = pick_word(p.name, seed >> 9, 6, w1, sizeof w1);
                w1[4] = 0;
                snprintf(text, sizeof text, "%s", w1);
                break;
            case Q_TWO_WORDS:
                ok = pick_word(p.name, seed >> 8, 4, w1, sizeof w1) &&
                     pick_word(p.name, (seed >> 8) + 1, 4, w2, sizeof w2);
                snprintf(text, sizeof text, "%s %s", w1, w2);
                break;
            case Q_ARTICLE:
                snprintf(text, sizeof text, "%s", p.article);
                break;
            case Q_FILTERED:
                ok = pick_word(p.name, seed >> 10, 4, text, sizeof text);
                f.category = p.category;
                f.max_width_mm = p.width_mm + 100;
                break;
            }
            if (!ok)
                continue;
            int n = 0;
            double t0 = cli_now_ms(), c0 = thread_cpu_ms();
            r = cat_search(db, text, &f, 20, hits, &n, err, sizeof err);
            double t = cli_now_ms() - t0;
            if (cpu)
                cpu[cpu_n++] = thread_cpu_ms() - c0;
            if (r != CAT_DB_OK) {
                fprintf(stderr, "tessera: %s\n", err);
                break;
            }
            hits_total += n;
            ms[k][counts[k]++] = t;
        }
        cat_product_free(&p);
        if (r != CAT_DB_OK)
            break;
    }
    FILE *csv = NULL;
    app_safe_stream csv_out = {.f = NULL};
    char csv_err[4200];
    if (r == CAT_DB_OK && o->csv) {
        csv = app_safe_stream_open(&csv_out, o->csv, csv_err, sizeof csv_err);
        if (!csv)
            fprintf(stderr, "tessera catalog bench: %s\n", csv_err);
        else
            fprintf(csv, "kind,queries,median_ms,p90_ms,p95_ms,max_ms\n");
    }
    if (r == CAT_DB_OK) {
        printf("search latency over %s (%lld products), limit 20, ms per query:\n", cat_db_path(db),
               st.products);
        printf("%-16s %8s %8s %8s %8s %8s\n", "query", "count", "median", "p90", "p95", "max");
        double *all = calloc((size_t)Q_KINDS * (size_t)per_kind, sizeof *all);
        int all_n = 0;
        for (int k = 0; k < Q_KINDS; k++) {
            for (int i = 0; all && i < counts[k]; i++)
                all[all_n++] = ms[k][i];
            double med = quantile(ms[k], counts[k], 0.5), p90 = quantile(ms[k], counts[k], 0.9),
                   p95 = quantile(ms[k], counts[k], 0.95), max = quantile(ms[k], counts[k], 1.0);
            printf("%-16s %8d %8.3f %8.3f %8.3f %8.3f\n", kind_names[k], counts[k], med, p90, p95,
                   max);
            if (csv)
                fprintf(csv, "%s,%d,%.4f,%.4f,%.4f,%.4f\n", kind_names[k], counts[k], med, p90, p95,
                        max);
        }
        double med = quantile(all, all_n, 0.5), p90 = quantile(all, all_n, 0.9),
               p95 = quantile(all, all_n, 0.95);
        printf("%-16s %8d %8.3f %8.3f %8.3f\n", "all", all_n, med, p90, p95);
        double cmed = quantile(cpu, cpu_n, 0.5), cp90 = quantile(cpu, cpu_n, 0.9),
               cp95 = quantile(cpu, cpu_n, 0.95), cmax = quantile(cpu, cpu_n, 1.0);
        printf("%-16s %8d %8.3f %8.3f %8.3f %8.3f\n", "all, CPU time", cpu_n, cmed, cp90, cp95,
               cmax);
        printf("(%.1f hits per query on average)\n", all_n ? (double)hits_total / all_n : 0.0);
        if (csv)
            fprintf(csv, "all,%d,%.4f,%.4f,%.4f,\nall cpu,%d,%.4f,%.4f,%.4f,%.4f\n", all_n, med,
                    p90, p95, cpu_n, cmed, cp90, cp95, cmax);
        free(all);
    }
    int csv_failed = (o->csv && !csv && r == CAT_DB_OK) ||
                     (csv && app_safe_stream_commit(&csv_out, csv_err, sizeof csv_err) != APP_OK);
    if (csv && csv_failed)
        fprintf(stderr, "tessera catalog bench: %s\n", csv_err);
    for (int k = 0; k < Q_KINDS; k++)
        free(ms[k]);
    free(cpu);
    free(hits);
    cat_db_close(db);
    return csv_failed && r == CAT_DB_OK ? CLI_FAILED : exit_code(r);
}
