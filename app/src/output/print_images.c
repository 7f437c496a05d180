/* A render page: one PNG image fitted into the drawing area (aspect kept), with its caption.
 * Renders are pictures, not drawings: the title block shows no scale. */
#include "print_internal.h"

#include <stdio.h>

app_result pr_draw_image(pr_doc *d, int index)
{
    const char *path = d->o->images[index];
    const char *title =
        d->o->image_titles && d->o->image_titles[index] ? d->o->image_titles[index] : "Render";
    cairo_surface_t *img = cairo_image_surface_create_from_png(path);
    if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) {
        snprintf(d->err, d->err_size, "%s: cannot read the PNG image: %s", path,
                 cairo_status_to_string(cairo_surface_status(img)));
        cairo_surface_destroy(img);
        return APP_ERR_IO;
    }
    char caption[160];
    snprintf(caption, sizeof caption, "View: %.120s", title);
    app_result r = pr_page_begin(d, caption, 0);
    if (r != APP_OK) {
        cairo_surface_destroy(img);
        return r;
    }
    cairo_t *cr = d->cr;
    int iw = cairo_image_surface_get_width(img), ih = cairo_image_surface_get_height(img);
    double aw = d->area_w, ah = d->area_h - 8.0;
    double k = aw / iw < ah / ih ? aw / iw : ah / ih;
    double w = iw * k, h = ih * k;
    double x = d->area_x + (d->area_w - w) / 2, y = d->area_y + (ah - h) / 2;
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
    pr_set_font(cr, PR_TEXT_NORMAL, 0);
    char text[200];
    snprintf(text, sizeof text, "%s (%d x %d pixels)", title, iw, ih);
    pr_text(cr, x, y + h + 5.0, 0.0, 1.0, text);
    cairo_surface_destroy(img);
    if (d->report)
        d->report->render_pages++;
    return pr_page_end(d);
}
