/* tessera catalog thumbs [--size N] [--out DIR] [--category C] [--limit N] [--db PATH]
 *                        [--backend egl|osmesa] [--supersample N]
 * Headless thumbnails of every product through the renderer (thumb_scene.c): one GL context
 * for all, one PNG per product named MANUFACTURER-ARTICLE.png (lower case, runs of other
 * characters as '-'), a progress bar on stderr, and at the end the time per product. */
#include "catalog/catalog.h"
#include "cli_commands.h"
#include "cli_print_render.h"
#include "render/image_io.h"
#include "app/scene/thumb_scene.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

typedef struct thumbs_options {
    int size, limit, supersample;
    const char *out, *db, *variant;
    rd_backend backend;
    cat_category category;
} thumbs_options;

/* The table's options with this command's defaults filled in. */
static void thumbs_from(const cli_options *c, thumbs_options *o)
{
    memset(o, 0, sizeof *o);
    o->size = c->thumb_size ? c->thumb_size : 256;
    o->limit = c->limit ? c->limit : 10000; /* cat_search's most; --category splits a larger one */
    o->supersample = c->supersample ? c->supersample : 2;
    o->out = c->out_dir ? c->out_dir : "thumbs";
    o->db = c->db;
    o->backend = c->backend;
    o->variant = c->variant;
    if (c->category)
        cat_category_parse(c->category, &o->category);
}

/* "Nordkeram", "NK-51244.00" -> "nordkeram-nk-51244-00" */
static void file_stem(const cat_product *p, char *out, size_t size)
{
    char raw[CAT_MANUFACTURER_BYTES + CAT_ARTICLE_BYTES + 2];
    snprintf(raw, sizeof raw, "%s %s", p->manufacturer, p->article);
    size_t o = 0;
    for (const char *c = raw; *c && o + 1 < size; c++) {
        char ch = *c >= 'A' && *c <= 'Z' ? (char)(*c - 'A' + 'a') : *c;
        if ((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9'))
            out[o++] = ch;
        else if (o > 0 && out[o - 1] != '-')
            out[o++] = '-';
    }
    while (o > 0 && out[o - 1] == '-')
        o--;
    out[o] = '\0';
}

/* mkdir -p: 1 when the folder exists afterwards. */
static int make_folders(const char *path)
{
    char buf[4096];
    if (snprintf(buf, sizeof buf, "%s", path) >= (int)sizeof buf)
        return 0;
    for (char *c = buf + 1; *c; c++)
        if (*c == '/') {
            *c = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                return 0;
            *c = '/';
        }
    struct stat st;
    return (mkdir(buf, 0777) == 0 || errno == EEXIST) && stat(buf, &st) == 0 && S_ISDIR(st.st_mode);
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int cli_cmd_catalog_thumbs(const cli_options *args)
{
    thumbs_options o;
    thumbs_from(args, &o);
    if (!make_folders(o.out)) {
        fprintf(stderr, "tessera catalog thumbs: cannot make folder %s: %s\n", o.out,
                strerror(errno));
        return CLI_FAILED;
    }

    char path[4096], assets[4096], src[4200], err[4096];
    if (o.db)
        snprintf(path, sizeof path, "%s", o.db);
    else if (!cat_default_path(path, sizeof path)) {
        fprintf(stderr, "tessera catalog thumbs: no place for the catalog: set TESSERA_CATALOG "
                        "or HOME, or give --db PATH\n");
        return CLI_FAILED;
    }
    const char *env = getenv("TESSERA_ASSETS");
    snprintf(assets, sizeof assets, "%s", env && *env ? env : TESSERA_SOURCE_DIR "/assets");
    snprintf(src, sizeof src, "%s/catalog", assets);
    cat_db *db = NULL;
    if (cat_catalog_open(path, src, &db, err, sizeof err) != CAT_DB_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_FAILED;
    }
    cat_search_hit *hits = malloc(sizeof *hits * (size_t)o.limit);
    int count = 0;
    cat_search_filter filter = {o.category, 0, NULL};
    if (!hits || cat_search(db, "", &filter, o.limit, hits, &count, err, sizeof err) != CAT_DB_OK) {
        fprintf(stderr, "tessera: %s\n", hits ? err : "out of memory");
        free(hits);
        cat_db_close(db);
        return CLI_FAILED;
    }

    rd_context_desc cd = {.backend = o.backend};
    rd_context *ctx = NULL;
    thumb_studio st;
    memset(&st, 0, sizeof st);
    if (rd_context_create(&cd, &ctx) != RD_OK ||
        !thumb_studio_init(&st, ctx, assets, err, sizeof err)) {
        fprintf(stderr, "tessera catalog thumbs: %s\n", ctx ? err : rd_last_error());
        rd_context_destroy(ctx);
        free(hits);
        cat_db_close(db);
        return CLI_FAILED;
    }
    st.supersample = o.supersample;
    st.variant = o.variant;

    uint8_t *rgba = malloc((size_t)o.size * (size_t)o.size * 4);
    double *ms = malloc(sizeof *ms * (size_t)(count + 1));
    int failures = 0, sources[3] = {0, 0, 0}, done = 0;
    char first_note[1400] = "";
    cli_progress bar;
    cli_progress_init(&bar, "tessera catalog thumbs");
    double t_all = cli_now_ms();
    for (int i = 0; rgba && ms && i < count; i++) {
        cat_product p;
        if (cat_product_get(db, hits[i].product_id, &p, err, sizeof err) != CAT_DB_OK) {
            fprintf(stderr, "\ntessera: %s\n", err);
            failures++;
            continue;
        }
        char stem[128], file[4400], note[1024];
        file_stem(&p, stem, sizeof stem);
        snprintf(file, sizeof file, "%s/%s.png", o.out, stem);
        thumb_source source = THUMB_BOX;
        double t0 = cli_now_ms();
        int ok = thumb_render(&st, &p, o.size, rgba, &source, note, sizeof note, err, sizeof err);
        if (ok && rd_image_write_rgba8(file, o.size, o.size, rgba, err, sizeof err) != RD_IMAGE_OK)
            ok = 0;
        ms[done++] = cli_now_ms() - t0;
        if (!ok) {
            fprintf(stderr, "\ntessera catalog thumbs: %s %s: %s\n", p.manufacturer, p.article,
                    err);
            failures++;
        } else {
            sources[source]++;
            if (source == THUMB_BOX && p.model[0] && !first_note[0])
                snprintf(first_note, sizeof first_note, "%s %s: %s", p.manufacturer, p.article,
                         note);
        }
        cat_product_free(&p);
        cli_progress_update(&bar, i + 1, count);
    }
    double total_s = (cli_now_ms() - t_all) / 1000;
    if (done > 0) {
        qsort(ms, (size_t)done, sizeof *ms, by_value);
        printf("%d thumbnails of %d x %d px in %s (%d from models, %d boxes without a model, %d "
               "tiles) in %.1f s: median %.1f ms per product, slowest %.1f ms; %s\n",
               done - failures, o.size, o.size, o.out, sources[THUMB_MODEL], sources[THUMB_BOX],
               sources[THUMB_TILE], total_s, ms[done / 2], ms[done - 1],
               rd_context_description(ctx));
    }
    if (first_note[0])
        fprintf(stderr, "tessera catalog thumbs: some models could not be used (first: %s)\n",
                first_note);
    if (!rgba || !ms) {
        fprintf(stderr, "tessera catalog thumbs: out of memory\n");
        failures++;
    }
    free(rgba);
    free(ms);
    thumb_studio_free(&st);
    rd_context_destroy(ctx);
    free(hits);
    cat_db_close(db);
    return failures ? CLI_FAILED : CLI_OK;
}
