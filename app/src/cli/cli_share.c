/* tessera share PROJECT -o DIR [--size WxH] [--panorama-size WxH] [--camera NAME]
 * The "share" export (app/output/share.h): a folder a customer opens in any browser
 * from the file system, with no network: index.html with the renders of every stored viewpoint,
 * the plan and elevations (SVG pages of the print set), an interactive 360-degree panorama, the
 * part list with prices, and the print set as PDF. It composes the commands that make each
 * part (render --all-views, panorama, print), so the folder shows exactly what they make. */
#include "cli_commands.h"
#include "cli_table.h"
#include "app/design/placement.h"
#include "app/project/project.h"
#include "app/design/quantities.h"
#include "app/design/room_surfaces.h"
#include "app/design/trims.h"
#include "app/output/folder_swap.h"
#include "app/output/share.h"
#include "catalog/catalog.h"

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define MAX_FILES 64

/* What a share folder holds: an existing folder with anything else in it is not replaced (a
 * mistyped -o naming a folder of the user's must not be swapped away). */
static const char *const share_entries[] = {
    "index.html", "panorama.jpg", "panorama.js", "pano-viewer.js", "print.pdf", "renders", "plan"};

/* 1 when path is missing, or a folder holding only what a share folder holds; else says why. */
static int replaceable(const char *path)
{
    DIR *d = opendir(path);
    if (!d)
        return 1; /* missing (or a file: the swap names that) */
    struct dirent *e;
    int ok = 1;
    while (ok && (e = readdir(d))) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
            continue;
        ok = 0;
        for (size_t i = 0; i < sizeof share_entries / sizeof share_entries[0]; i++)
            ok |= !strcmp(e->d_name, share_entries[i]);
        if (!ok)
            fprintf(stderr,
                    "tessera share: %s holds %s, which a share folder does not: it is not "
                    "replaced (give a new folder, an empty one or an earlier share folder)\n",
                    path, e->d_name);
    }
    closedir(d);
    return ok;
}

static int make_dir(const char *path)
{
    if (mkdir(path, 0777) == 0 || errno == EEXIST)
        return 0;
    fprintf(stderr, "tessera share: cannot make folder %s: %s\n", path, strerror(errno));
    return 1;
}

static int has_suffix(const char *name, const char *suffix)
{
    size_t n = strlen(name), k = strlen(suffix);
    return n > k && !strcmp(name + n - k, suffix);
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* The files of dir ending in suffix, as "sub/NAME", sorted; *titles get NAME without suffix. */
static int list_files(const char *dir, const char *sub, const char *suffix, char **files,
                      char **titles)
{
    DIR *d = opendir(dir);
    int n = 0;
    if (!d)
        return 0;
    struct dirent *e;
    while ((e = readdir(d)) && n < MAX_FILES) {
        if (e->d_name[0] == '.' || !has_suffix(e->d_name, suffix))
            continue;
        size_t len = strlen(sub) + strlen(e->d_name) + 2;
        files[n] = malloc(len);
        if (!files[n])
            break;
        snprintf(files[n], len, "%s/%s", sub, e->d_name);
        n++;
    }
    closedir(d);
    qsort(files, (size_t)n, sizeof *files, by_name);
    for (int i = 0; i < n; i++) {
        const char *base = strrchr(files[i], '/') + 1;
        titles[i] = strdup(base);
        if (titles[i])
            titles[i][strlen(titles[i]) - strlen(suffix)] = 0;
    }
    return n;
}

static char *money(long long cents, const char *currency)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%lld.%02lld %s", cents / 100, (cents < 0 ? -cents : cents) % 100,
             currency);
    return strdup(buf);
}

/* The part list as table cells: tiles first, then the fixtures, priced from the catalog. */
static int part_list(const app_project *p, char ***cells, int *rows, char *totals[6])
{
    cat_db *db = NULL;
    char err[1024];
    if (app_placement_open_catalog(NULL, &db, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera share: %s (the part list is left out)\n", err);
        return 0;
    }
    app_tile_layout *layouts = NULL;
    int n = 0;
    app_quantities q;
    memset(&q, 0, sizeof q);
    app_bom bom;
    memset(&bom, 0, sizeof bom);
    app_result r = app_room_tile_layouts(p, db, &layouts, &n, err, sizeof err);
    if (r == APP_OK)
        r = app_quantities_compute(layouts, n, NULL, &q, err, sizeof err);
    if (r == APP_OK)
        r = app_bom_build(db, p, &q, &bom, err, sizeof err);
    if (r == APP_OK) /* trims, consumables and labour, as on the quotation */
        r = app_bom_add_project_trims(db, p, &bom, err, sizeof err);
    app_consumables cons;
    if (r == APP_OK)
        r = app_consumables_compute(p, db, layouts, n, NULL, &cons, err, sizeof err);
    if (r == APP_OK)
        r = app_bom_add_consumables(db, &cons, NULL, &bom, err, sizeof err);
    if (r != APP_OK) {
        fprintf(stderr, "tessera share: %s (the part list is left out)\n", err);
    } else {
        static const char *const header[6] = {"Manufacturer", "Article",    "Name",
                                              "Quantity",     "Unit price", "Total"};
        *cells = calloc((size_t)(bom.line_count + 1) * 6, sizeof **cells);
        for (int c = 0; *cells && c < 6; c++)
            (*cells)[c] = strdup(header[c]);
        for (int i = 0; *cells && i < bom.line_count; i++) {
            const app_bom_line *l = &bom.lines[i];
            char **row = &(*cells)[(size_t)(i + 1) * 6], qty[64];
            snprintf(qty, sizeof qty, "%.2f %s", l->quantity, cat_unit_name(l->unit));
            row[0] = strdup(l->product.manufacturer);
            row[1] = strdup(l->product.article);
            row[2] = strdup(l->found ? l->name : "(not in the catalog)");
            row[3] = strdup(qty);
            row[4] = money(l->unit_price_cents, l->currency);
            row[5] = money(l->net_cents, l->currency);
        }
        *rows = *cells ? bom.line_count : 0;
        totals[0] = strdup("Net");
        totals[1] = money(bom.net_cents, bom.currency);
        totals[2] = strdup("VAT");
        totals[3] = money(bom.vat_cents, bom.currency);
        totals[4] = strdup("Total incl. VAT");
        totals[5] = money(bom.gross_cents, bom.currency);
    }
    app_bom_free(&bom);
    app_quantities_free(&q);
    app_tile_layouts_free(layouts, n);
    cat_db_close(db);
    return r == APP_OK && *cells;
}

static int read_file(const char *path, uint8_t **out, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return 1;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    *out = n > 0 ? malloc((size_t)n) : NULL;
    int bad = !*out || fread(*out, 1, (size_t)n, f) != (size_t)n;
    fclose(f);
    *size = (size_t)n;
    return bad;
}

/* A sub-command run as if typed: its options as the table would fill them. */
static int run(int (*command)(const cli_options *), const char *name, cli_options *o)
{
    o->command = cli_command_find(cli_commands, name);
    return command(o);
}

int cli_cmd_share(const cli_options *o)
{
    const char *project = o->project, *out = o->output, *camera = o->camera;
    if (!out)
        return cli_usage_error(o);
    app_project p;
    char err[1024];
    if (app_project_read(project, &p, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return 2;
    }
    /* The folder is written whole beside the old one and swapped in at the end, so a failure
     * midway (a full disk) leaves the old folder as it was and nothing new. */
    app_folder_swap swap;
    if (!replaceable(out)) {
        app_project_free(&p);
        return 2;
    }
    if (app_folder_swap_begin(&swap, out, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera share: %s\n", err);
        app_project_free(&p);
        return 1;
    }
    const char *dir = swap.temp;
    fprintf(stderr, "tessera share: writing %s (it replaces %s when complete)\n", dir, out);
    char renders[4096], plan[4096], pano[4096], pdf[4096];
    snprintf(renders, sizeof renders, "%s/renders", dir);
    snprintf(plan, sizeof plan, "%s/plan", dir);
    snprintf(pano, sizeof pano, "%s/panorama.jpg", dir);
    snprintf(pdf, sizeof pdf, "%s/print.pdf", dir);
    int rc = make_dir(renders) || make_dir(plan) ? 2 : 0;

    /* 1. every stored viewpoint */
    fprintf(stderr, "tessera share: renders of %d viewpoints\n", p.camera_count);
    if (!rc && p.camera_count > 0) {
        cli_options r = {.project = project,
                         .output = renders,
                         .all_views = 1,
                         .width = o->width ? o->width : 1280,
                         .height = o->height ? o->height : 720};
        rc = run(cli_cmd_render, "render", &r);
    }
    /* 2. the panorama from the first (or the named) viewpoint */
    int has_pano = 0;
    if (!rc && p.camera_count > 0) {
        fprintf(stderr, "tessera share: 360-degree panorama\n");
        cli_options r = {.project = project,
                         .output = pano,
                         .camera = camera,
                         .width = o->pano_width ? o->pano_width : 4096,
                         .height = o->pano_height ? o->pano_height : 2048};
        rc = run(cli_cmd_panorama, "panorama", &r);
        uint8_t *jpeg = NULL;
        size_t n = 0;
        /* A panorama that cannot be written fails the share (a full disk must not leave a
         * folder that looks complete without it). */
        snprintf(err, sizeof err, "%.900s: cannot read the panorama back", pano);
        if (!rc && !read_file(pano, &jpeg, &n) &&
            app_share_write_panorama(dir, jpeg, n, "image/jpeg", err, sizeof err) == APP_OK &&
            app_share_copy_viewer(dir, app_placement_assets_dir(), err, sizeof err) == APP_OK)
            has_pano = 1;
        else if (!rc) {
            fprintf(stderr, "tessera share: %s\n", err);
            rc = 1;
        }
        free(jpeg);
    }
    /* 3. the print set, its pages also as SVG for the page */
    if (!rc) {
        fprintf(stderr, "tessera share: print set\n");
        cli_options r = {.project = project, .output = pdf, .svg = plan, .renders = renders};
        rc = run(cli_cmd_print, "print", &r);
    }
    /* 4. the page */
    char *files[MAX_FILES] = {0}, *titles[MAX_FILES] = {0};
    char *pfiles[MAX_FILES] = {0}, *ptitles[MAX_FILES] = {0};
    char **cells = NULL, *totals[6] = {0};
    int rows = 0;
    if (!rc) {
        int nr = list_files(renders, "renders", ".png", files, titles);
        int np = list_files(plan, "plan", ".svg", pfiles, ptitles);
        app_share_image img[MAX_FILES], pimg[MAX_FILES];
        for (int i = 0; i < nr; i++)
            img[i] = (app_share_image){files[i], titles[i]};
        for (int i = 0; i < np; i++)
            pimg[i] = (app_share_image){pfiles[i], ptitles[i]};
        int table = part_list(&p, &cells, &rows, totals);
        app_share_page page = {.title = p.name[0] ? p.name : "Bathroom",
                               .plans = pimg,
                               .plan_count = np,
                               .renders = img,
                               .render_count = nr,
                               .pdf_file = "print.pdf",
                               .has_panorama = has_pano,
                               .table = table ? (const char *const *)cells : NULL,
                               .columns = table ? 6 : 0,
                               .rows = rows,
                               .totals = table ? (const char *const *)totals : NULL,
                               .total_count = table ? 3 : 0};
        if (app_share_write_page(dir, &page, err, sizeof err) != APP_OK ||
            app_folder_swap_commit(&swap, err, sizeof err) != APP_OK) {
            fprintf(stderr, "tessera share: %s\n", err);
            rc = 1;
        } else {
            printf("%s/index.html: %d views, %d drawings, %s, %d part list lines\n", out, nr, np,
                   has_pano ? "a panorama" : "no panorama", rows);
        }
    }
    for (int i = 0; i < MAX_FILES; i++) {
        free(files[i]);
        free(titles[i]);
        free(pfiles[i]);
        free(ptitles[i]);
    }
    for (int i = 0; cells && i < (rows + 1) * 6; i++)
        free(cells[i]);
    free(cells);
    for (int i = 0; i < 6; i++)
        free(totals[i]);
    app_folder_swap_discard(&swap); /* after a failure: the new folder goes, the old stays */
    app_project_free(&p);
    return rc;
}
