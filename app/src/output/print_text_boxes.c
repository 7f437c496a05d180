/* The texts drawn on a page, as boxes in paper mm: every pr_text call records the ink box of
 * what it drew, so labels and dimension values placed later can look for a free spot instead of
 * landing on an earlier text, and `tessera print --text-boxes FILE` can list them for the test
 * that no two texts of a page overlap. The registry hangs on the cairo context (user data), so
 * the drawing helpers that only see the context record into it too. */
#include "print_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const cairo_user_data_key_t boxes_key;

void pr_text_boxes_attach(cairo_t *cr, pr_text_boxes *b)
{
    cairo_set_user_data(cr, &boxes_key, b, NULL);
}

pr_text_boxes *pr_text_boxes_of(cairo_t *cr)
{
    return cr ? cairo_get_user_data(cr, &boxes_key) : NULL;
}

void pr_text_boxes_clear(pr_text_boxes *b)
{
    b->count = 0;
    b->obstacle_count = 0;
}

void pr_text_boxes_free(pr_text_boxes *b)
{
    free(b->items);
    free(b->obstacles);
    memset(b, 0, sizeof *b);
}

/* Device units are PDF/SVG points; the page's user unit is the millimetre (print_page.c). */
static void to_paper(cairo_t *cr, double *x, double *y)
{
    cairo_user_to_device(cr, x, y);
    *x *= 25.4 / 72.0;
    *y *= 25.4 / 72.0;
}

pr_box pr_text_measure(cairo_t *cr, double x, double y, double angle, double ax, double ay,
                       const char *text)
{
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    cairo_text_extents_t te;
    cairo_text_extents(cr, text, &te);
    double w = te.x_advance;
    double cap = fe.ascent * 0.72;
    double dy = ay >= 1.0 ? 0.0 : (ay <= 0.0 ? cap : cap * (1.0 - ay));
    double lx = -w * ax + te.x_bearing, ly = dy + te.y_bearing;
    double cx[4] = {lx, lx + te.width, lx + te.width, lx};
    double cy[4] = {ly, ly, ly + te.height, ly + te.height};
    pr_box b = {1e300, 1e300, -1e300, -1e300};
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_rotate(cr, -angle);
    for (int k = 0; k < 4; k++) {
        double px = cx[k], py = cy[k];
        to_paper(cr, &px, &py);
        b.x0 = fmin(b.x0, px);
        b.y0 = fmin(b.y0, py);
        b.x1 = fmax(b.x1, px);
        b.y1 = fmax(b.y1, py);
    }
    cairo_restore(cr);
    return b;
}

pr_box pr_box_to_paper(cairo_t *cr, double x0, double y0, double x1, double y1)
{
    double xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
    pr_box b = {1e300, 1e300, -1e300, -1e300};
    for (int k = 0; k < 4; k++) {
        to_paper(cr, &xs[k], &ys[k]);
        b.x0 = fmin(b.x0, xs[k]);
        b.y0 = fmin(b.y0, ys[k]);
        b.x1 = fmax(b.x1, xs[k]);
        b.y1 = fmax(b.y1, ys[k]);
    }
    return b;
}

int pr_boxes_overlap(pr_box a, pr_box b, double margin)
{
    return a.x0 - margin < b.x1 && a.x1 + margin > b.x0 && a.y0 - margin < b.y1 &&
           a.y1 + margin > b.y0;
}

int pr_box_is_free(cairo_t *cr, pr_box b, double margin)
{
    const pr_text_boxes *r = pr_text_boxes_of(cr);
    for (int i = 0; r && i < r->count; i++)
        if (pr_boxes_overlap(b, r->items[i].box, margin))
            return 0;
    for (int i = 0; r && i < r->obstacle_count; i++)
        if (pr_boxes_overlap(b, r->obstacles[i], margin))
            return 0;
    return 1;
}

void pr_box_reserve(cairo_t *cr, pr_box b)
{
    pr_text_boxes *r = pr_text_boxes_of(cr);
    if (!r)
        return;
    if (r->obstacle_count == r->obstacle_cap) {
        int cap = r->obstacle_cap ? r->obstacle_cap * 2 : 16;
        pr_box *o = realloc(r->obstacles, (size_t)cap * sizeof *o);
        if (!o)
            return;
        r->obstacles = o;
        r->obstacle_cap = cap;
    }
    r->obstacles[r->obstacle_count++] = b;
}

void pr_box_record(cairo_t *cr, pr_box b, const char *text)
{
    pr_text_boxes *r = pr_text_boxes_of(cr);
    if (!r || r->suspended || b.x1 < b.x0 || b.y1 < b.y0)
        return;
    if (r->count == r->cap) {
        int cap = r->cap ? r->cap * 2 : 256;
        pr_text_box *items = realloc(r->items, (size_t)cap * sizeof *items);
        if (!items)
            return; /* only the overlap checks lose this box */
        r->items = items;
        r->cap = cap;
    }
    pr_text_box *t = &r->items[r->count++];
    t->box = b;
    snprintf(t->text, sizeof t->text, "%s", text);
}

void pr_text_boxes_write(const pr_text_boxes *b, FILE *out, int page, const char *drawing)
{
    for (int i = 0; i < b->count; i++) {
        const pr_text_box *t = &b->items[i];
        /* Tabs and newlines would break the columns: the text is only for reading. */
        char text[sizeof t->text];
        snprintf(text, sizeof text, "%s", t->text);
        for (char *c = text; *c; c++)
            if (*c == '\t' || *c == '\n')
                *c = ' ';
        fprintf(out, "%d\t%.3f\t%.3f\t%.3f\t%.3f\t%s\t%s\n", page, t->box.x0, t->box.y0, t->box.x1,
                t->box.y1, drawing, text);
    }
}
