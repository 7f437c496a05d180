/* Render pages: two PNG images a page (the last may hold one), side by side or one above the
 * other, whichever shows them larger, filling the drawing area, each captioned with its view's
 * name. Renders are pictures, not drawings: the title block shows no scale. */
#include "print_internal.h"

#include <stdio.h>

#define CAPTION_H 7.0 /* under each image */
#define GAP 6.0       /* between the two */

static cairo_surface_t *load(pr_doc *d, int index)
{
    const char *path = d->o->images[index];
    cairo_surface_t *img = cairo_image_surface_create_from_png(path);
    if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) {
        snprintf(d->err, d->err_size, "%s: cannot read the PNG image: %s", path,
                 cairo_status_to_string(cairo_surface_status(img)));
        cairo_surface_destroy(img);
        return NULL;
    }
    return img;
}

static const char *title_of(const pr_doc *d, int index)
{
    return d->o->image_titles && d->o->image_titles[index] ? d->o->image_titles[index] : "Render";
}

/* The scale factor fitting an iw x ih image into w x h (caption below included). */
static double fit(int iw, int ih, double w, double h)
{
    double k = w / iw, kh = (h - CAPTION_H) / ih;
    return kh < k ? kh : k;
}

/* The image fitted into the cell, centred, framed, its caption under it. */
static void draw_cell(pr_doc *d, cairo_surface_t *img, const char *title, double cx, double cy,
                      double cw, double ch)
{
    cairo_t *cr = d->cr;
    int iw = cairo_image_surface_get_width(img), ih = cairo_image_surface_get_height(img);
    double k = fit(iw, ih, cw, ch), w = iw * k, h = ih * k;
    double x = cx + (cw - w) / 2, y = cy + (ch - CAPTION_H - h) / 2;
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_scale(cr, k, k);
    cairo_set_source_surface(cr, img, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_rectangle(cr, x, y, w, h);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, PR_LINE_FINE);
    cairo_stroke(cr);
    pr_set_font(cr, PR_TEXT_LARGE, 0);
    char text[200];
    snprintf(text, sizeof text, "View: %.120s", title);
    pr_text(cr, x, y + h + 5.0, 0.0, 1.0, text);
}

int pr_image_page_count(const pr_doc *d)
{
    return (d->o->image_count + 1) / 2;
}

app_result pr_draw_image(pr_doc *d, int index, int second)
{
    cairo_surface_t *img[2] = {load(d, index), NULL};
    if (img[0] && second >= 0)
        img[1] = load(d, second);
    if (!img[0] || (second >= 0 && !img[1])) {
        for (int k = 0; k < 2; k++)
            if (img[k])
                cairo_surface_destroy(img[k]);
        return APP_ERR_IO;
    }
    char caption[300];
    if (second >= 0)
        snprintf(caption, sizeof caption, "Views: %.120s, %.120s", title_of(d, index),
                 title_of(d, second));
    else
        snprintf(caption, sizeof caption, "Views: %.120s", title_of(d, index));
    app_result r = pr_page_begin(d, caption, 0);
    if (r == APP_OK) {
        double ax = d->area_x, ay = d->area_y, aw = d->area_w, ah = d->area_h;
        if (second < 0) {
            draw_cell(d, img[0], title_of(d, index), ax, ay, aw, ah);
        } else {
            /* Side by side or stacked: the arrangement whose smaller image is larger. */
            int w0 = cairo_image_surface_get_width(img[0]),
                h0 = cairo_image_surface_get_height(img[0]);
            int w1 = cairo_image_surface_get_width(img[1]),
                h1 = cairo_image_surface_get_height(img[1]);
            double side = (aw - GAP) / 2, stack = (ah - GAP) / 2;
            double ks0 = fit(w0, h0, side, ah) * w0, ks1 = fit(w1, h1, side, ah) * w1;
            double kt0 = fit(w0, h0, aw, stack) * w0, kt1 = fit(w1, h1, aw, stack) * w1;
            double by_side = ks0 < ks1 ? ks0 : ks1, stacked = kt0 < kt1 ? kt0 : kt1;
            if (by_side >= stacked) {
                draw_cell(d, img[0], title_of(d, index), ax, ay, side, ah);
                draw_cell(d, img[1], title_of(d, second), ax + side + GAP, ay, side, ah);
            } else {
                draw_cell(d, img[0], title_of(d, index), ax, ay, aw, stack);
                draw_cell(d, img[1], title_of(d, second), ax, ay + stack + GAP, aw, stack);
            }
        }
        if (d->report)
            d->report->render_pages++;
        r = pr_page_end(d);
    }
    for (int k = 0; k < 2; k++)
        if (img[k])
            cairo_surface_destroy(img[k]);
    return r;
}
