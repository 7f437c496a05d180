/* Paper, scales and the page frame: the border, the title block (project, customer, drawing,
 * scale, date, page n of m; DOMAIN.md "What the best planners print": header and footer with
 * page number, scale, date, project name) and the drawing area above it. */
#include "print_internal.h"

#include <cairo-svg.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

const int app_print_scales[APP_PRINT_SCALE_COUNT] = {10, 20, 25, 50, 100, 200};

#define PR_MARGIN 10.0       /* paper mm around the frame */
#define PR_TITLE_HEIGHT 16.0 /* the title block's height */

void app_paper_size_mm(app_paper paper, int landscape, double *width_mm, double *height_mm)
{
    double w = paper == APP_PAPER_A3 ? 297.0 : 210.0;
    double h = paper == APP_PAPER_A3 ? 420.0 : 297.0;
    *width_mm = landscape ? h : w;
    *height_mm = landscape ? w : h;
}

int app_paper_parse(const char *text, app_paper *out)
{
    if (!text)
        return 0;
    if (!strcasecmp(text, "A4")) {
        *out = APP_PAPER_A4;
        return 1;
    }
    if (!strcasecmp(text, "A3")) {
        *out = APP_PAPER_A3;
        return 1;
    }
    return 0;
}

int app_print_fit_scale(double extent_w_mm, double extent_h_mm, double border_mm, double avail_w_mm,
                        double avail_h_mm)
{
    for (int i = 0; i < APP_PRINT_SCALE_COUNT; i++) {
        double n = app_print_scales[i];
        if (extent_w_mm / n + 2 * border_mm <= avail_w_mm &&
            extent_h_mm / n + 2 * border_mm <= avail_h_mm)
            return app_print_scales[i];
    }
    return app_print_scales[APP_PRINT_SCALE_COUNT - 1];
}

int app_print_scale_parse(const char *text, int *denominator)
{
    if (!text || !*text)
        return 0;
    if (!strcasecmp(text, "fit")) {
        *denominator = 0;
        return 1;
    }
    const char *s = text;
    if (!strncmp(s, "1:", 2))
        s += 2;
    int n = 0, digits = 0;
    for (; *s >= '0' && *s <= '9' && digits < 6; s++, digits++)
        n = n * 10 + (*s - '0');
    if (*s || digits == 0 || n < 1 || n > 10000)
        return 0;
    *denominator = n;
    return 1;
}

static void title_cell(cairo_t *cr, double x, double y, double w, double h, const char *caption,
                       const char *value, int large)
{
    cairo_set_line_width(cr, PR_LINE_MEDIUM);
    cairo_rectangle(cr, x, y, w, h);
    cairo_stroke(cr);
    pr_set_font(cr, 1.8, 0);
    cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
    pr_text(cr, x + 1.5, y + 1.5, 0.0, 0.0, caption);
    cairo_set_source_rgb(cr, 0, 0, 0);
    pr_set_font(cr, large ? PR_TEXT_TITLE : PR_TEXT_LARGE, large);
    /* Shrink a value that does not fit its cell rather than run into the next one. */
    double tw = pr_text_width(cr, value);
    if (tw > w - 3.0)
        pr_set_font(cr, (large ? PR_TEXT_TITLE : PR_TEXT_LARGE) * (w - 3.0) / tw, large);
    pr_text(cr, x + 1.5, y + h - 2.5, 0.0, 1.0, value);
}

static void draw_frame(pr_doc *d, const char *title, int scale)
{
    cairo_t *cr = d->cr;
    double x0 = PR_MARGIN, y0 = PR_MARGIN;
    double w = d->page_w - 2 * PR_MARGIN, h = d->page_h - 2 * PR_MARGIN;
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, PR_LINE_HEAVY);
    cairo_rectangle(cr, x0, y0, w, h);
    cairo_stroke(cr);

    double ty = y0 + h - PR_TITLE_HEIGHT;
    char scale_text[32], page_text[48], project[160];
    if (scale > 0)
        snprintf(scale_text, sizeof scale_text, "1:%d", scale);
    else
        snprintf(scale_text, sizeof scale_text, "-");
    snprintf(page_text, sizeof page_text, "%d of %d", d->page + 1, d->page_count);
    snprintf(project, sizeof project, "%s", d->p->name[0] ? d->p->name : "Untitled project");
    const char *customer = d->o->customer && d->o->customer[0] ? d->o->customer : "";
    /* Column widths as fractions of the frame: project | customer | drawing | scale | date |
     * page. */
    const double frac[6] = {0.27, 0.17, 0.24, 0.09, 0.12, 0.11};
    const char *caps[6] = {"Project", "Customer", "Drawing", "Scale", "Date", "Page"};
    const char *vals[6] = {project, customer, title, scale_text, d->date, page_text};
    double x = x0;
    for (int i = 0; i < 6; i++) {
        double cw = w * frac[i];
        title_cell(cr, x, ty, cw, PR_TITLE_HEIGHT, caps[i], vals[i], i == 0);
        x += cw;
    }
    pr_set_font(cr, 1.6, 0);
    cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
    pr_text(cr, x0 + w - 1.5, ty - 1.2, 1.0, 1.0,
            "Tessera - dimensions in mm - check all dimensions on site");
    cairo_set_source_rgb(cr, 0, 0, 0);

    d->area_x = x0 + 4.0;
    d->area_y = y0 + 4.0;
    d->area_w = w - 8.0;
    d->area_h = h - PR_TITLE_HEIGHT - 8.0;
}

app_result pr_page_begin(pr_doc *d, const char *title, int scale)
{
    if (d->svg_dir) {
        char path[4096];
        snprintf(path, sizeof path, "%s/page-%02d.svg", d->svg_dir, d->page + 1);
        /* Each page whole or not at all (app/output/safe_file.h). */
        app_result r = app_safe_file_open(&d->svg_file, path, d->err, d->err_size);
        if (r != APP_OK)
            return r;
        d->surface =
            cairo_svg_surface_create_for_stream(app_safe_file_cairo_write, &d->svg_file,
                                                d->page_w * 72.0 / 25.4, d->page_h * 72.0 / 25.4);
        if (cairo_surface_status(d->surface) != CAIRO_STATUS_SUCCESS) {
            snprintf(d->err, d->err_size, "%s: cannot write: %s", path,
                     cairo_status_to_string(cairo_surface_status(d->surface)));
            cairo_surface_destroy(d->surface);
            d->surface = NULL;
            app_safe_file_discard(&d->svg_file);
            return APP_ERR_IO;
        }
        cairo_svg_surface_restrict_to_version(d->surface, CAIRO_SVG_VERSION_1_1);
        d->cr = cairo_create(d->surface);
    }
    pr_text_boxes_clear(&d->text_boxes);
    pr_text_boxes_attach(d->cr, &d->text_boxes);
    snprintf(d->page_title, sizeof d->page_title, "%s", title);
    cairo_save(d->cr);
    cairo_identity_matrix(d->cr);
    cairo_scale(d->cr, 72.0 / 25.4, 72.0 / 25.4); /* user unit: the paper millimetre */
    /* White paper: an SVG page is transparent otherwise (viewers show it on black). */
    cairo_set_source_rgb(d->cr, 1, 1, 1);
    cairo_paint(d->cr);
    cairo_set_line_join(d->cr, CAIRO_LINE_JOIN_MITER);
    cairo_set_line_cap(d->cr, CAIRO_LINE_CAP_BUTT);
    draw_frame(d, title, scale);
    return APP_OK;
}

app_result pr_page_end(pr_doc *d)
{
    if (d->text_boxes_out)
        pr_text_boxes_write(&d->text_boxes, d->text_boxes_out, d->page + 1, d->page_title);
    pr_text_boxes_clear(&d->text_boxes);
    cairo_restore(d->cr);
    cairo_status_t st = cairo_status(d->cr);
    if (st == CAIRO_STATUS_SUCCESS)
        cairo_show_page(d->cr);
    if (d->svg_dir) {
        cairo_destroy(d->cr);
        d->cr = NULL;
        cairo_surface_finish(d->surface);
        if (st == CAIRO_STATUS_SUCCESS)
            st = cairo_surface_status(d->surface);
        cairo_surface_destroy(d->surface);
        d->surface = NULL;
        if (st == CAIRO_STATUS_SUCCESS || d->svg_file.error) {
            /* A failed write shows as a cairo error: the file's own reason says more. */
            if (app_safe_file_commit(&d->svg_file, d->err, d->err_size) != APP_OK)
                return APP_ERR_IO;
        } else {
            app_safe_file_discard(&d->svg_file);
        }
    }
    if (st != CAIRO_STATUS_SUCCESS) {
        snprintf(d->err, d->err_size, "%s: page %d: %s", d->svg_dir ? d->svg_dir : d->pdf_path,
                 d->page + 1, cairo_status_to_string(st));
        return APP_ERR_IO;
    }
    d->page++;
    return APP_OK;
}
