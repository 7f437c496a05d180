/* The print set: gathers what the pages need (the plan, the fixtures with their catalog
 * products, the tile layouts, quantities and the bill of materials), lists the pages (plan,
 * elevations, renders, part list) so each can say "page n of m", and draws them into one PDF
 * or one SVG per page. */
#include "print_internal.h"

#include "app/output/safe_file.h"

#include "app/design/room_surfaces.h"
#include "app/design/trims.h"

#include <cairo-pdf.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static void warn(const pr_doc *d, const char *what, const char *msg)
{
    if (d->o->verbose)
        fprintf(stderr, "tessera print: %s: %s\n", what, msg);
}

static void prepare_quantities(pr_doc *d)
{
    char err[1024];
    if (!d->db)
        return;
    if (d->p->tiling_count > 0) {
        /* The layouts the renderer draws and `tessera quantities` counts (baths and trays
         * cover what is behind and under them), so elevations, part list and renders agree. */
        if (app_room_tile_layouts(d->p, d->db, &d->layouts, &d->layout_count, err, sizeof err) !=
            APP_OK) {
            warn(d, "tile layouts", err);
            d->layouts = NULL;
            d->layout_count = 0;
        } else if (app_quantities_compute(d->layouts, d->layout_count, NULL, &d->q, err,
                                          sizeof err) == APP_OK) {
            d->have_quantities = 1;
        } else {
            warn(d, "quantities", err);
        }
    }
    int products = 0;
    for (int i = 0; i < d->p->object_count; i++)
        products += d->p->objects[i].has_product;
    if (products == 0 && (!d->have_quantities || d->q.line_count == 0)) {
        d->have_bom = 1; /* nothing to price: an empty bill (quantities_catalog.c would hand
                            qsort a NULL array) */
        return;
    }
    app_quantities none = {0};
    if (app_bom_build(d->db, d->p, d->have_quantities ? &d->q : &none, &d->bom, err, sizeof err) ==
        APP_OK)
        d->have_bom = 1;
    else {
        warn(d, "bill of materials", err);
        return;
    }
    /* Trim profiles, consumables and labour (docs/tiling.md "Trim profiles", "Consumables and
     * labour"): the quotation's positions after the products. */
    if (app_bom_add_project_trims(d->db, d->p, &d->bom, err, sizeof err) != APP_OK)
        warn(d, "trim profiles", err);
    if (app_consumables_compute(d->p, d->db, d->layouts, d->layout_count, NULL, &d->cons, err,
                                sizeof err) != APP_OK ||
        app_bom_add_consumables(d->db, &d->cons, NULL, &d->bom, err, sizeof err) != APP_OK)
        warn(d, "consumables", err);
}

/* The title block's date when it is a date (YYYY-MM-DD), else NULL (today). */
static const char *iso_date(const char *text)
{
    int y, m, dd, n = 0;
    return text && sscanf(text, "%4d-%2d-%2d%n", &y, &m, &dd, &n) == 3 && !text[n] ? text : NULL;
}

static app_result prepare(pr_doc *d, const app_project *p, const app_print_options *o,
                          app_print_report *report, char *err, size_t err_size)
{
    memset(d, 0, sizeof *d);
    d->p = p;
    d->o = o;
    d->err = err;
    d->err_size = err_size;
    d->report = report;
    if (report)
        memset(report, 0, sizeof *report);
    app_paper_size_mm(o->paper, o->landscape, &d->page_w, &d->page_h);
    /* The drawing area as pr_page_begin's frame sets it, for the page counts made before any
     * page is drawn (print_page.c: 10 mm margin, 4 mm inside the frame, 16 mm title block). */
    d->area_x = d->area_y = 14.0;
    d->area_w = d->page_w - 28.0;
    d->area_h = d->page_h - 44.0;
    d->plan = p->plan;
    if (d->plan.corner_count < 3) {
        /* A project built in memory by version 1 code: its room box as four corners. */
        d->box_corners[0] = (app_point2){0, 0};
        d->box_corners[1] = (app_point2){p->room.width_mm, 0};
        d->box_corners[2] = (app_point2){p->room.width_mm, p->room.depth_mm};
        d->box_corners[3] = (app_point2){0, p->room.depth_mm};
        d->plan.corners = d->box_corners;
        d->plan.corner_count = 4;
        d->plan.height_mm = p->room.height_mm;
        if (d->plan.wall_thickness_mm <= 0)
            d->plan.wall_thickness_mm = APP_ROOM_DEFAULT_WALL_THICKNESS_MM;
    }
    if (d->plan.height_mm <= 0)
        d->plan.height_mm = p->room.height_mm > 0 ? p->room.height_mm : 2500.0;
    if (o->date)
        snprintf(d->date, sizeof d->date, "%s", o->date);
    else {
        time_t now = time(NULL);
        struct tm tm;
        gmtime_r(&now, &tm);
        strftime(d->date, sizeof d->date, "%Y-%m-%d", &tm);
    }
    char path[4096], cerr[1024];
    int have_path = o->catalog_db ? (snprintf(path, sizeof path, "%s", o->catalog_db), 1)
                                  : cat_default_path(path, sizeof path);
    if (!have_path ||
        cat_catalog_open(path, o->catalog_source, &d->db, cerr, sizeof cerr) != CAT_DB_OK) {
        warn(d, "catalog", have_path ? cerr : "no place for the catalog (set TESSERA_CATALOG)");
        d->db = NULL;
    }
    app_result r = pr_fixtures_collect(d);
    if (r != APP_OK)
        return r;
    prepare_quantities(d);
    r = app_quote_make(p, o->company, iso_date(o->date), &d->quote, err, err_size);
    if (r != APP_OK)
        return r;
    pr_fixtures_number(d);

    if (o->text_boxes_path) {
        d->text_boxes_out = fopen(o->text_boxes_path, "w");
        if (!d->text_boxes_out) {
            snprintf(err, err_size, "%s: cannot write: %s", o->text_boxes_path, strerror(errno));
            return APP_ERR_IO;
        }
    }
    int elevations = pr_elevation_count(d);
    int parts = pr_parts_page_count(d);
    int total = 1 + elevations + o->image_count + parts;
    d->pages = calloc((size_t)total + 1, sizeof *d->pages);
    if (!d->pages) {
        snprintf(err, err_size, "print: out of memory");
        return APP_ERR_OUT_OF_MEMORY;
    }
    int n = 0;
    d->pages[n++] = (pr_page){PR_PAGE_PLAN, 0, -1};
    int elevation_pages = pr_elevation_pages(d, d->pages + n);
    n += elevation_pages;
    for (int i = 0; i < o->image_count; i += 2)
        d->pages[n++] = (pr_page){PR_PAGE_IMAGE, i, i + 1 < o->image_count ? i + 1 : -1};
    for (int i = 0; i < parts; i++)
        d->pages[n++] = (pr_page){PR_PAGE_PARTS, i, -1};
    d->page_count = n;
    if (report) {
        report->pages = n;
        report->elevation_pages = elevation_pages;
        report->elevations = elevations;
    }
    return APP_OK;
}

static void release(pr_doc *d)
{
    pr_fixtures_free(d);
    if (d->layouts)
        app_tile_layouts_free(d->layouts, d->layout_count);
    if (d->have_quantities)
        app_quantities_free(&d->q);
    if (d->have_bom)
        app_bom_free(&d->bom);
    cat_db_close(d->db);
    free(d->pages);
    pr_text_boxes_free(&d->text_boxes);
    free(d->cut_labels);
    if (d->text_boxes_out)
        fclose(d->text_boxes_out);
    if (d->cr)
        cairo_destroy(d->cr);
    if (d->surface)
        cairo_surface_destroy(d->surface);
    if (d->svg_file.temp) /* a page left unfinished by a failure */
        app_safe_file_discard(&d->svg_file);
    memset(d, 0, sizeof *d);
}

static app_result draw_pages(pr_doc *d)
{
    app_result r = APP_OK;
    for (int i = 0; r == APP_OK && i < d->page_count; i++) {
        const pr_page *pg = &d->pages[i];
        switch (pg->kind) {
        case PR_PAGE_PLAN:
            r = pr_draw_plan(d);
            break;
        case PR_PAGE_ELEVATION:
            r = pr_draw_elevation(d, pg->index, pg->second);
            break;
        case PR_PAGE_IMAGE:
            r = pr_draw_image(d, pg->index, pg->second);
            break;
        case PR_PAGE_PARTS:
            r = pr_draw_parts(d, pg->index);
            break;
        }
    }
    return r;
}

static app_result check_args(const app_project *p, const app_print_options *o, const char *out,
                             char *err, size_t err_size)
{
    if (!p || !o || !out || !*out) {
        snprintf(err, err_size, "print: no project, options or output path");
        return APP_ERR_SCHEMA;
    }
    if (o->image_count < 0 || (o->image_count > 0 && !o->images)) {
        snprintf(err, err_size, "print: bad image list");
        return APP_ERR_SCHEMA;
    }
    if (o->scale < 0 || o->scale > 10000) {
        snprintf(err, err_size, "print: scale 1:%d out of range", o->scale);
        return APP_ERR_SCHEMA;
    }
    return APP_OK;
}

app_result app_print_pdf(const app_project *p, const app_print_options *o, const char *pdf_path,
                         app_print_report *report, char *err, size_t err_size)
{
    app_result r = check_args(p, o, pdf_path, err, err_size);
    if (r != APP_OK)
        return r;
    /* Written beside the target and renamed over it when complete, every write checked, so
     * a failure never leaves a half-written PDF (or destroys the previous one) and its
     * message keeps the system's reason (app/output/safe_file.h). */
    pr_doc d;
    r = prepare(&d, p, o, report, err, err_size);
    app_safe_file out;
    if (r == APP_OK)
        r = app_safe_file_open(&out, pdf_path, err, err_size);
    if (r == APP_OK) {
        d.pdf_path = pdf_path;
        d.surface = cairo_pdf_surface_create_for_stream(
            app_safe_file_cairo_write, &out, d.page_w * 72.0 / 25.4, d.page_h * 72.0 / 25.4);
        if (cairo_surface_status(d.surface) != CAIRO_STATUS_SUCCESS) {
            snprintf(err, err_size, "%s: cannot write: %s", pdf_path,
                     cairo_status_to_string(cairo_surface_status(d.surface)));
            r = APP_ERR_IO;
        } else {
            cairo_pdf_surface_set_metadata(d.surface, CAIRO_PDF_METADATA_TITLE,
                                           p->name[0] ? p->name : "Tessera print set");
            cairo_pdf_surface_set_metadata(d.surface, CAIRO_PDF_METADATA_CREATOR, "Tessera");
            d.cr = cairo_create(d.surface);
            r = draw_pages(&d);
            cairo_destroy(d.cr);
            d.cr = NULL;
            cairo_surface_finish(d.surface);
            if (r == APP_OK && !out.error &&
                cairo_surface_status(d.surface) != CAIRO_STATUS_SUCCESS) {
                snprintf(err, err_size, "%s: cannot write: %s", pdf_path,
                         cairo_status_to_string(cairo_surface_status(d.surface)));
                r = APP_ERR_IO;
            }
        }
        if (r == APP_OK && o->xlsx && d.have_bom)
            r = app_quote_write_xlsx(o->xlsx, p, &d.quote, &d.bom, err, err_size);
        if (r == APP_OK || out.error) {
            /* A failed write shows as a cairo error on a page: the file's reason says more. */
            app_result w = app_safe_file_commit(&out, err, err_size);
            if (r == APP_OK || w != APP_OK)
                r = w;
        } else {
            app_safe_file_discard(&out);
        }
    }
    release(&d);
    return r;
}

/* The rooms of a flat into one PDF: each room's print set in turn (its own plan, elevations,
 * renders and part list, numbered within the room), on one surface. */
app_result app_print_flat_pdf(const app_project *rooms, const app_print_options *opts, int n,
                              const char *title, const char *pdf_path, app_print_report *report,
                              char *err, size_t err_size)
{
    if (n < 1 || !rooms || !opts) {
        snprintf(err, err_size, "print: no rooms to print");
        return APP_ERR_SCHEMA;
    }
    app_result r = APP_OK;
    for (int i = 0; r == APP_OK && i < n; i++)
        r = check_args(&rooms[i], &opts[i], pdf_path, err, err_size);
    if (r != APP_OK)
        return r;
    char tmp[4200];
    if ((size_t)snprintf(tmp, sizeof tmp, "%s.part-%ld", pdf_path, (long)getpid()) >= sizeof tmp) {
        snprintf(err, err_size, "%s: path too long", pdf_path);
        return APP_ERR_IO;
    }
    if (report)
        memset(report, 0, sizeof *report);
    double w, h;
    app_paper_size_mm(opts[0].paper, opts[0].landscape, &w, &h);
    cairo_surface_t *surface = cairo_pdf_surface_create(tmp, w * 72.0 / 25.4, h * 72.0 / 25.4);
    cairo_t *cr = NULL;
    if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
        snprintf(err, err_size, "%s: cannot write: %s", pdf_path,
                 cairo_status_to_string(cairo_surface_status(surface)));
        r = APP_ERR_IO;
    } else {
        cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE,
                                       title && *title ? title : "Tessera print set");
        cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "Tessera");
        cr = cairo_create(surface);
    }
    for (int i = 0; r == APP_OK && i < n; i++) {
        app_print_report rep;
        pr_doc d;
        r = prepare(&d, &rooms[i], &opts[i], &rep, err, err_size);
        if (r == APP_OK) {
            d.pdf_path = pdf_path;
            d.surface = surface;
            d.cr = cr;
            r = draw_pages(&d);
            d.surface = NULL; /* shared: not the room's to destroy */
            d.cr = NULL;
        }
        release(&d);
        if (r == APP_OK && report) {
            report->pages += rep.pages;
            report->elevation_pages += rep.elevation_pages;
            report->tiles_whole += rep.tiles_whole;
            report->tiles_cut += rep.tiles_cut;
            report->fixtures += rep.fixtures;
            report->render_pages += rep.render_pages;
            report->partlist_pages += rep.partlist_pages;
            report->plan_scale =
                rep.plan_scale > report->plan_scale ? rep.plan_scale : report->plan_scale;
            report->elevation_scale = rep.elevation_scale > report->elevation_scale
                                          ? rep.elevation_scale
                                          : report->elevation_scale;
        }
        if (opts[i].verbose)
            fprintf(stderr, "tessera print: [%d/%d] room \"%s\" drawn\n", i + 1, n, rooms[i].name);
    }
    if (cr)
        cairo_destroy(cr);
    cairo_surface_finish(surface);
    if (r == APP_OK && cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
        snprintf(err, err_size, "%s: cannot write: %s", pdf_path,
                 cairo_status_to_string(cairo_surface_status(surface)));
        r = APP_ERR_IO;
    }
    cairo_surface_destroy(surface);
    if (r == APP_OK && rename(tmp, pdf_path) != 0) {
        snprintf(err, err_size, "%s: cannot write: %s", pdf_path, strerror(errno));
        r = APP_ERR_IO;
    }
    if (r != APP_OK)
        unlink(tmp);
    return r;
}

app_result app_print_svg(const app_project *p, const app_print_options *o, const char *dir,
                         app_print_report *report, char *err, size_t err_size)
{
    app_result r = check_args(p, o, dir, err, err_size);
    if (r != APP_OK)
        return r;
    pr_doc d;
    r = prepare(&d, p, o, report, err, err_size);
    if (r == APP_OK) {
        d.svg_dir = dir;
        r = draw_pages(&d);
    }
    release(&d);
    return r;
}
