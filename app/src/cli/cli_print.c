/* tessera print PROJECT -o plan.pdf [--paper A4|A3] [--landscape] [--scale 1:20|fit]
 *               [--svg DIR] [--renders DIR|none] [--render-size WxH] [--customer NAME]
 *               [--date TEXT] [--no-clearances] [--backend egl|osmesa] [--text-boxes FILE]
 * The print set (app/output/print.h, docs/printing.md): plan, elevations, renders, part list. */
#include "app/cli/cli.h"
#include "app/output/print.h"
#include "app/project/flat.h"
#include "app/scene/quality.h"
#include "cli_commands.h"
#include "cli_quantities.h"

#include <dirent.h>
#include <errno.h>
#include <libgen.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *assets_dir(void)
{
    const char *env = getenv("TESSERA_ASSETS");
    return env && *env ? env : TESSERA_SOURCE_DIR "/assets";
}

typedef struct image_list {
    char **paths;
    char **titles;
    int count;
} image_list;

static void images_free(image_list *l)
{
    for (int i = 0; i < l->count; i++) {
        free(l->paths[i]);
        free(l->titles[i]);
    }
    free(l->paths);
    free(l->titles);
    memset(l, 0, sizeof *l);
}

static int images_add(image_list *l, const char *path, const char *title)
{
    char **p = realloc(l->paths, (size_t)(l->count + 1) * sizeof *p);
    if (!p)
        return 0;
    l->paths = p;
    char **t = realloc(l->titles, (size_t)(l->count + 1) * sizeof *t);
    if (!t)
        return 0;
    l->titles = t;
    l->paths[l->count] = strdup(path);
    l->titles[l->count] = strdup(title);
    if (!l->paths[l->count] || !l->titles[l->count]) {
        free(l->paths[l->count]);
        free(l->titles[l->count]);
        return 0;
    }
    l->count++;
    return 1;
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Every *.png in dir, by name. */
static int images_from_dir(const char *dir, image_list *l)
{
    DIR *dp = opendir(dir);
    if (!dp) {
        fprintf(stderr, "tessera print: --renders %s: %s\n", dir, strerror(errno));
        return CLI_USAGE;
    }
    char *names[256];
    int n = 0;
    struct dirent *e;
    while ((e = readdir(dp)) != NULL && n < 256) {
        size_t len = strlen(e->d_name);
        if (len > 4 && !strcmp(e->d_name + len - 4, ".png"))
            names[n++] = strdup(e->d_name);
    }
    closedir(dp);
    qsort(names, (size_t)n, sizeof *names, cmp_str);
    int rc = CLI_OK;
    for (int i = 0; i < n; i++) {
        char path[4096], title[256];
        if (!names[i]) {
            rc = CLI_FAILED;
            continue;
        }
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        snprintf(title, sizeof title, "%.*s", (int)strlen(names[i]) - 4, names[i]);
        if (rc == CLI_OK && !images_add(l, path, title))
            rc = CLI_FAILED;
        free(names[i]);
    }
    return rc;
}

/* Renders every camera of the project at a modest size into tmp_dir (the renderer of
 * `tessera render`); a progress line per view. */
static int render_cameras(const char *project, const app_project *room, int room_number,
                          rd_backend backend, const app_quality *quality, int w, int h,
                          const char *tmp_dir, image_list *l)
{
    cli_options o = {0};
    o.project = project;
    o.backend = backend;
    o.quality = quality;
    cli_session s;
    /* A flat's room is handed over, not read again: reading the whole file for each room
     * would make the renders of N rooms cost N file reads of N rooms each. */
    int rc = room ? cli_session_open_room(&o, room, &s) : cli_session_open(&o, &s);
    if (rc != CLI_OK)
        return rc;
    for (int i = 0; rc == CLI_OK && i < s.project.camera_count; i++) {
        const char *cam = s.project.cameras[i].name;
        fprintf(stderr, "tessera print: [%d/%d] rendering view \"%s\"\n", i + 1,
                s.project.camera_count, cam);
        rd_view view;
        rc = cli_session_view(&s, &o, cam, w, h, &view);
        char path[4096];
        snprintf(path, sizeof path, "%s/view-%02d-%02d.png", tmp_dir, room_number, i + 1);
        if (rc == CLI_OK)
            rc = cli_render_to_file(&s, &view, path);
        if (rc == CLI_OK && !images_add(l, path, cam))
            rc = CLI_FAILED;
    }
    cli_session_close(&s);
    return rc;
}

/* -o gets a PDF whatever its name, so x.txt would silently hold one: refuse any other extension
 * (the SVG pages go to --svg DIR). Returns CLI_OK, or CLI_USAGE after saying why. */
static int check_pdf_name(const char *path)
{
    const char *base = strrchr(path, '/');
    const char *dot = strrchr(base ? base + 1 : path, '.');
    if (dot && !strcasecmp(dot, ".pdf"))
        return CLI_OK;
    fprintf(stderr,
            "tessera print: %s: not a .pdf file name; -o writes a PDF (SVG pages: --svg DIR)\n",
            path);
    return CLI_USAGE;
}

/* The PDF is written last, after the renders; checking its folder first fails fast and names the
 * file and the reason, where the writer can only say its stream failed. Returns CLI_OK, or
 * CLI_FAILED after saying why. */
static int check_pdf_folder(const char *path)
{
    char copy[4096];
    snprintf(copy, sizeof copy, "%s", path);
    const char *dir = dirname(copy);
    struct stat st;
    int e = 0;
    if (stat(dir, &st) != 0)
        e = errno;
    else if (!S_ISDIR(st.st_mode))
        e = ENOTDIR;
    else if (access(dir, W_OK | X_OK) != 0)
        e = errno;
    else if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        e = EISDIR;
    if (!e)
        return CLI_OK;
    fprintf(stderr, "tessera print: cannot write %s: %s\n", path, strerror(e));
    return CLI_FAILED;
}

/* A flat: each room's renders (its cameras; the other rooms are not built), then one PDF with
 * a section a room. --renders DIR is not taken for a flat (its images belong to no room). */
static int print_flat(const cli_options *o, const app_flat *f, const app_print_options *base,
                      const app_quality *quality, int render_w, int render_h)
{
    if (o->svg || (o->renders && strcmp(o->renders, "none") != 0)) {
        fprintf(stderr,
                "tessera print: %s: a flat takes neither --svg nor --renders DIR (only "
                "--renders none)\n",
                o->project);
        return CLI_USAGE;
    }
    image_list *images = calloc((size_t)f->room_count, sizeof *images);
    app_print_options *opts = calloc((size_t)f->room_count, sizeof *opts);
    char tmp_dir[] = "/tmp/tessera-print-XXXXXX";
    int made_tmp = 0, rc = images && opts ? CLI_OK : CLI_FAILED;
    if (rc == CLI_OK && !o->renders) {
        if (mkdtemp(tmp_dir)) {
            made_tmp = 1;
        } else {
            fprintf(stderr, "tessera print: cannot make a temporary folder: %s\n", strerror(errno));
            rc = CLI_FAILED;
        }
    }
    char catalog_src[4200], assets[4096];
    snprintf(assets, sizeof assets, "%s", assets_dir());
    snprintf(catalog_src, sizeof catalog_src, "%s/catalog", assets);
    double t0 = cli_now_ms();
    for (int i = 0; rc == CLI_OK && i < f->room_count; i++) {
        if (made_tmp) {
            fprintf(stderr, "tessera print: room %d of %d, \"%s\"\n", i + 1, f->room_count,
                    f->rooms[i].name);
            rc = render_cameras(o->project, &f->rooms[i], i + 1, o->backend, quality, render_w,
                                render_h, tmp_dir, &images[i]);
        }
        opts[i] = *base;
        /* as for a single room: --customer, else the file's customer; the company block */
        opts[i].customer = o->customer
                               ? o->customer
                               : (f->rooms[i].customer.name[0] ? f->rooms[i].customer.name : NULL);
        opts[i].company = o->company;
        opts[i].date = o->date;
        opts[i].catalog_source = catalog_src;
        opts[i].assets_dir = assets;
        opts[i].images = (const char *const *)images[i].paths;
        opts[i].image_titles = (const char *const *)images[i].titles;
        opts[i].image_count = images[i].count;
        opts[i].verbose = 1;
    }
    double t1 = cli_now_ms();
    app_print_report rep = {0};
    char err[2048];
    if (rc == CLI_OK) {
        app_result r = app_print_flat_pdf(f->rooms, opts, f->room_count, f->name, o->output, &rep,
                                          err, sizeof err);
        if (r != APP_OK) {
            fprintf(stderr, "tessera: %s\n", err);
            rc = r == APP_ERR_SCHEMA ? CLI_USAGE : CLI_FAILED;
        }
    }
    /* The flat's one quotation over every room, as `tessera quantities FLAT --xlsx` writes it. */
    if (rc == CLI_OK && o->xlsx)
        rc = cli_flat_quotation_xlsx(o, f, o->xlsx);
    if (rc == CLI_OK)
        fprintf(stderr,
                "tessera print: %s: %d rooms, %d pages (%d elevations with %d whole and %d cut "
                "tiles, %d renders, %d part-list pages); renders %.0f ms, pages %.0f ms\n",
                o->output, f->room_count, rep.pages, rep.elevation_pages, rep.tiles_whole,
                rep.tiles_cut, rep.render_pages, rep.partlist_pages, t1 - t0, cli_now_ms() - t1);
    for (int i = 0; images && i < f->room_count; i++) {
        for (int k = 0; made_tmp && k < images[i].count; k++)
            unlink(images[i].paths[k]);
        images_free(&images[i]);
    }
    if (made_tmp)
        rmdir(tmp_dir);
    free(images);
    free(opts);
    return rc;
}

int cli_cmd_print(const cli_options *o)
{
    const char *project = o->project, *output = o->output, *svg = o->svg, *renders = o->renders;
    const char *customer = o->customer, *date = o->date;
    const app_quality *quality = o->quality ? o->quality : app_quality_find("final");
    int render_w = o->render_width ? o->render_width : 960;
    int render_h = o->render_height ? o->render_height : 540;
    rd_backend backend = o->backend;
    app_print_options po = {.paper = (app_paper)o->paper,
                            .landscape = o->landscape,
                            .scale = o->scale,
                            .no_clearances = o->no_clearances};
    if (!output)
        return cli_usage_error(o);
    int checked = check_pdf_name(output);
    if (checked == CLI_OK)
        checked = check_pdf_folder(output);
    if (checked != CLI_OK)
        return checked;
    if (svg) {
        struct stat st;
        if (stat(svg, &st) != 0 && mkdir(svg, 0777) != 0) {
            fprintf(stderr, "tessera print: --svg %s: %s\n", svg, strerror(errno));
            return CLI_USAGE;
        }
    }
    app_project p;
    char err[2048];
    app_flat flat;
    app_result r = app_flat_read(project, &flat, err, sizeof err);
    if (r != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return r == APP_ERR_OUT_OF_MEMORY ? CLI_FAILED : CLI_USAGE;
    }
    if (flat.is_flat) {
        int frc = print_flat(o, &flat, &po, quality, render_w, render_h);
        app_flat_free(&flat);
        return frc;
    }
    app_flat_take_room(&flat, 0, &p);
    image_list images = {0};
    char tmp_dir[] = "/tmp/tessera-print-XXXXXX";
    int made_tmp = 0, rc = CLI_OK;
    if (renders && strcmp(renders, "none") != 0) {
        rc = images_from_dir(renders, &images);
    } else if (!renders && p.camera_count > 0) {
        if (mkdtemp(tmp_dir)) {
            made_tmp = 1;
            rc = render_cameras(project, NULL, 0, backend, quality, render_w, render_h, tmp_dir,
                                &images);
        } else {
            fprintf(stderr, "tessera print: cannot make a temporary folder: %s\n", strerror(errno));
            rc = CLI_FAILED;
        }
    }
    char catalog_src[4200], assets[4096];
    snprintf(assets, sizeof assets, "%s", assets_dir());
    snprintf(catalog_src, sizeof catalog_src, "%s/catalog", assets);
    po.customer = customer ? customer : (p.customer.name[0] ? p.customer.name : NULL);
    po.date = date;
    po.company = o->company;
    po.xlsx = o->xlsx;
    po.catalog_source = catalog_src;
    po.assets_dir = assets;
    po.images = (const char *const *)images.paths;
    po.image_titles = (const char *const *)images.titles;
    po.image_count = images.count;
    po.verbose = 1;
    app_print_report rep = {0};
    double t0 = cli_now_ms();
    if (rc == CLI_OK) {
        po.text_boxes_path = o->text_boxes;
        r = app_print_pdf(&p, &po, output, &rep, err, sizeof err);
        po.text_boxes_path = NULL; /* the SVG pages are the same pages */
        if (r == APP_OK && svg)
            r = app_print_svg(&p, &po, svg, &rep, err, sizeof err);
        if (r != APP_OK) {
            fprintf(stderr, "tessera: %s\n", err);
            rc = r == APP_ERR_SCHEMA ? CLI_USAGE : CLI_FAILED;
        }
    }
    if (rc == CLI_OK)
        fprintf(
            stderr,
            "tessera print: %s: %d pages (plan 1:%d, %d elevations on %d pages, 1:%d and larger, "
            "with %d whole and %d cut tiles, %d render pages, %d part-list pages) in %.0f ms\n",
            output, rep.pages, rep.plan_scale, rep.elevations, rep.elevation_pages,
            rep.elevation_scale, rep.tiles_whole, rep.tiles_cut, rep.render_pages,
            rep.partlist_pages, cli_now_ms() - t0);
    if (made_tmp) {
        for (int i = 0; i < images.count; i++)
            unlink(images.paths[i]);
        rmdir(tmp_dir);
    }
    images_free(&images);
    app_project_free(&p);
    return rc;
}

int app_cli_print_demo(const struct app_project *p, const char *out_dir)
{
    image_list images = {0};
    int rc = CLI_OK;
    for (int i = 0; rc == CLI_OK && i < p->camera_count; i++) {
        char path[4200];
        snprintf(path, sizeof path, "%s/demo-%s.png", out_dir, p->cameras[i].name);
        if (access(path, R_OK) == 0 && !images_add(&images, path, p->cameras[i].name))
            rc = CLI_FAILED;
    }
    char pdf[4200], catalog_src[4200], assets[4096], err[2048];
    snprintf(pdf, sizeof pdf, "%s/plan.pdf", out_dir);
    snprintf(assets, sizeof assets, "%s", assets_dir());
    snprintf(catalog_src, sizeof catalog_src, "%s/catalog", assets);
    app_print_options po = {.paper = APP_PAPER_A4,
                            .landscape = 1,
                            .catalog_source = catalog_src,
                            .assets_dir = assets,
                            .images = (const char *const *)images.paths,
                            .image_titles = (const char *const *)images.titles,
                            .image_count = images.count};
    app_print_report rep = {0};
    double t0 = cli_now_ms();
    if (rc == CLI_OK) {
        app_result r = app_print_pdf(p, &po, pdf, &rep, err, sizeof err);
        if (r != APP_OK) {
            fprintf(stderr, "tessera demo: %s\n", err);
            rc = CLI_FAILED;
        } else {
            fprintf(stderr, "tessera demo: %s: %d pages in %.0f ms\n", pdf, rep.pages,
                    cli_now_ms() - t0);
        }
    }
    images_free(&images);
    return rc;
}
