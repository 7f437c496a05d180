/* The plan's legend: each fixture's number (as on the plan and the elevations) with its product's
 * name, article number and position in the quotation, the notes the drawing needs (free areas,
 * room height, walls) and the graphic scale under it. Measured before the plan is laid out, so
 * the plan's scale is chosen with the legend beside or below it. */
#include "print_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define ROW_H 4.1 /* a balloon (3.6 mm) and a little air */
#define HEAD_H 6.0
#define NOTE_H 3.4
#define GAP 2.5
#define NAME_MAX_W 46.0
#define BAR_H 9.0 /* the scale bar under the notes */

static const char *fixture_name(const pr_fixture *f)
{
    return f->found && f->product.name[0] ? f->product.name : f->name;
}

/* The columns' widths: number, name (up to NAME_MAX_W), article, position. */
static void columns(pr_doc *d, cairo_t *cr, double w[4])
{
    pr_set_font(cr, PR_TEXT_SMALL, 0);
    w[0] = 2 * PR_BALLOON_RADIUS + GAP;
    w[1] = pr_text_width(cr, "Product");
    w[2] = pr_text_width(cr, "Article");
    w[3] = pr_text_width(cr, "Pos.");
    for (int i = 0; i < d->fixture_count; i++) {
        const pr_fixture *f = &d->fixtures[i];
        if (!f->number)
            continue;
        w[1] = fmax(w[1], pr_text_width(cr, fixture_name(f)) + 1.0);
        if (f->has_product)
            w[2] = fmax(w[2], pr_text_width(cr, f->ref.article));
    }
    w[1] = fmin(w[1], NAME_MAX_W) + GAP;
    w[2] += GAP;
}

/* The notes under the list; all = 1 counts every note that may be needed (for measuring). */
static int note_lines(const pr_doc *d, int all, const char **lines, char buf[][160])
{
    int n = 0;
    int unplaced = 0, products = 0;
    for (int i = 0; i < d->fixture_count; i++) {
        unplaced += d->fixtures[i].number && !d->fixtures[i].number_placed;
        products += d->fixtures[i].number && d->fixtures[i].has_product;
    }
    if (unplaced || all)
        lines[n++] = "* no room for its number on the plan";
    if (products || all)
        lines[n++] = "Pos.: the line of the quotation";
    if (d->clearances_drawn || all)
        lines[n++] = "Hatched: free area in front (VDI 6000)";
    snprintf(buf[0], 160, "Room height %.0f mm, walls %.0f mm", d->plan.height_mm,
             d->plan.wall_thickness_mm);
    lines[n++] = buf[0];
    return n;
}

static void heading_text(const pr_doc *d, char *out, size_t size)
{
    snprintf(out, size, "Fixtures, clockwise from %s", pr_numbering_start(d));
}

void pr_legend_size(pr_doc *d, cairo_t *cr, double *width, double *height)
{
    double w[4];
    columns(d, cr, w);
    char heading[96];
    heading_text(d, heading, sizeof heading);
    pr_set_font(cr, PR_TEXT_NORMAL, 1);
    double hw = pr_text_width(cr, heading);
    int rows = 0;
    for (int i = 0; i < d->fixture_count; i++)
        rows += d->fixtures[i].number > 0;
    const char *lines[8];
    char buf[1][160];
    /* Every note that may be needed: which are is known only once the plan is drawn. */
    int notes = note_lines(d, 1, lines, buf);
    pr_set_font(cr, PR_TEXT_SMALL, 0);
    double nw = 0;
    for (int i = 0; i < notes; i++)
        nw = fmax(nw, pr_text_width(cr, lines[i]));
    *width = fmax(fmax(w[0] + w[1] + w[2] + w[3], nw), hw);
    *height = HEAD_H + (rows ? ROW_H * (rows + 1) : 0) + NOTE_H * notes + BAR_H;
}

/* Cuts text to fit max_w, ending it in "..". */
static void fit_text(cairo_t *cr, const char *text, double max_w, char *out, size_t size)
{
    snprintf(out, size, "%s", text);
    while (strlen(out) > 2 && pr_text_width(cr, out) > max_w) {
        size_t l = strlen(out);
        out[l - 1] = 0;
        if (l >= 4)
            memcpy(out + l - 3, "..", 2);
    }
}

void pr_legend_draw(pr_doc *d, double x, double y, int scale)
{
    cairo_t *cr = d->cr;
    double w[4];
    columns(d, cr, w);
    cairo_save(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    char heading[96];
    heading_text(d, heading, sizeof heading);
    pr_set_font(cr, PR_TEXT_NORMAL, 1);
    pr_text(cr, x, y + 3.5, 0.0, 1.0, heading);
    double yy = y + HEAD_H;
    int rows = 0;
    for (int i = 0; i < d->fixture_count; i++)
        rows += d->fixtures[i].number > 0;
    if (rows) {
        pr_set_font(cr, 1.8, 0);
        cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
        const char *heads[4] = {"No.", "Product", "Article", "Pos."};
        double cx = x;
        for (int k = 0; k < 4; k++) {
            pr_text(cr, cx, yy + ROW_H - 1.2, 0.0, 1.0, heads[k]);
            cx += w[k];
        }
        cairo_set_source_rgb(cr, 0, 0, 0);
        yy += ROW_H;
    }
    for (int number = 1; number <= d->fixture_count; number++)
        for (int i = 0; i < d->fixture_count; i++) {
            const pr_fixture *f = &d->fixtures[i];
            if (f->number != number)
                continue;
            double mid = yy + ROW_H / 2;
            pr_balloon(cr, x + PR_BALLOON_RADIUS, mid, number);
            pr_set_font(cr, PR_TEXT_SMALL, 0);
            char name[200], pos[16];
            snprintf(name, sizeof name, "%s%.160s", f->number_placed ? "" : "* ", fixture_name(f));
            char cut[200];
            fit_text(cr, name, w[1] - GAP, cut, sizeof cut);
            double cx = x + w[0];
            pr_text(cr, cx, mid, 0.0, 0.5, cut);
            cx += w[1];
            pr_text(cr, cx, mid, 0.0, 0.5, f->has_product ? f->ref.article : "-");
            cx += w[2];
            int p = f->has_product ? pr_quotation_position(d, &f->ref) : 0;
            snprintf(pos, sizeof pos, "%d", p);
            pr_text(cr, cx, mid, 0.0, 0.5, p ? pos : "-");
            yy += ROW_H;
        }
    const char *lines[8];
    char buf[1][160];
    int notes = note_lines(d, 0, lines, buf);
    pr_set_font(cr, PR_TEXT_SMALL, 0);
    cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
    yy += 1.0;
    for (int i = 0; i < notes; i++) {
        pr_text(cr, x, yy + NOTE_H - 0.9, 0.0, 1.0, lines[i]);
        yy += NOTE_H;
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    /* The graphic scale: its right end under the legend's, its "1:N" left of the bar. */
    double lw, lh;
    pr_legend_size(d, cr, &lw, &lh);
    pr_scale_bar(cr, x + lw - 3.0, yy + BAR_H - 2.0, scale);
    cairo_restore(cr);
}
