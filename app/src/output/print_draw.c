/* Drawing helpers for the printed pages: text with anchors, dimension lines in the
 * architectural style (ticks at 45 degrees, value above the line; ISO 129-1 allows ticks for
 * building drawings), hatching, level marks, money. Units: paper mm. */
#include "print_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void pr_set_font(cairo_t *cr, double size_mm, int bold)
{
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size_mm);
}

double pr_text_width(cairo_t *cr, const char *text)
{
    cairo_text_extents_t e;
    cairo_text_extents(cr, text, &e);
    return e.x_advance;
}

void pr_text_rotated(cairo_t *cr, double x, double y, double angle, double ax, double ay,
                     const char *text)
{
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    double w = pr_text_width(cr, text);
    /* ay: 0 top (ascent below y), 0.5 middle of the capitals, 1 baseline at y. */
    double cap = fe.ascent * 0.72;
    double dy = ay >= 1.0 ? 0.0 : (ay <= 0.0 ? cap : cap * (1.0 - ay) + 0.0);
    if (text[0])
        pr_box_record(cr, pr_text_measure(cr, x, y, angle, ax, ay, text), text);
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_rotate(cr, -angle);
    cairo_move_to(cr, -w * ax, dy);
    cairo_show_text(cr, text);
    cairo_new_path(cr);
    cairo_restore(cr);
}

void pr_text(cairo_t *cr, double x, double y, double ax, double ay, const char *text)
{
    pr_text_rotated(cr, x, y, 0.0, ax, ay, text);
}

/* Where a dimension's value goes: variant 0 centred above the line (when it fits between the
 * ticks), 1 beyond the b end, 2 beyond the a end, 3 centred a line further out. */
static void dimension_text_at(cairo_t *cr, const double a2[2], const double b2[2], double ux,
                              double uy, double sgn, int variant, const char *text, double *x,
                              double *y, double *angle)
{
    double len = hypot(b2[0] - a2[0], b2[1] - a2[1]);
    double an = atan2(-uy, ux); /* counter-clockwise on paper */
    if (an > PR_PI / 2 + 1e-6)
        an -= PR_PI;
    else if (an <= -PR_PI / 2 + 1e-6)
        an += PR_PI;
    /* "Above" the line as read: the text's up direction. */
    double upx = -sin(an), upy = -cos(an);
    double w = pr_text_width(cr, text);
    double mx = (a2[0] + b2[0]) / 2, my = (a2[1] + b2[1]) / 2;
    if (variant == 0 && w + 2.0 > len)
        variant = 1; /* no room between the ticks */
    if (variant == 1) {
        mx = b2[0] + ux * (w / 2 + 3.0);
        my = b2[1] + uy * (w / 2 + 3.0);
    } else if (variant == 2) {
        mx = a2[0] - ux * (w / 2 + 3.0);
        my = a2[1] - uy * (w / 2 + 3.0);
    }
    double lift = 0.8;
    if (variant == 3) {
        /* Away from the object: "up" as read may point either way. */
        double nx = uy, ny = -ux; /* left of a->b */
        double out = (upx * nx + upy * ny) * sgn >= 0 ? 1.0 : -1.0;
        lift = out > 0 ? 3.6 : -1.2 - 2.6;
    }
    *x = mx + upx * lift;
    *y = my + upy * lift;
    *angle = an;
}

int pr_dimension_placed(cairo_t *cr, double ax, double ay, double bx, double by, double offset,
                        double value_mm, int draw)
{
    double dx = bx - ax, dy = by - ay, len = hypot(dx, dy);
    if (len < 1e-6)
        return 1;
    double ux = dx / len, uy = dy / len;
    /* Left of a->b on paper (y down): (uy, -ux). */
    double nx = uy, ny = -ux;
    double a2x = ax + nx * offset, a2y = ay + ny * offset;
    double b2x = bx + nx * offset, b2y = by + ny * offset;
    double sgn = offset >= 0 ? 1.0 : -1.0;
    char text[32];
    snprintf(text, sizeof text, "%.0f", value_mm);
    cairo_save(cr);
    pr_set_font(cr, PR_TEXT_NORMAL, 0);
    const double a2[2] = {a2x, a2y}, b2[2] = {b2x, b2y};
    /* The value takes the first place free of the texts already on the page. */
    int placed = 0, variant = 0;
    double tx = 0, ty = 0, angle = 0;
    for (int k = 0; k < 4 && !placed; k++) {
        dimension_text_at(cr, a2, b2, ux, uy, sgn, k, text, &tx, &ty, &angle);
        placed = pr_box_is_free(cr, pr_text_measure(cr, tx, ty, angle, 0.5, 1.0, text), 0.3);
        variant = k;
    }
    if (!placed)
        dimension_text_at(cr, a2, b2, ux, uy, sgn, variant = 0, text, &tx, &ty, &angle);
    if (!draw) {
        if (placed)
            pr_box_record(cr, pr_text_measure(cr, tx, ty, angle, 0.5, 1.0, text), text);
        cairo_restore(cr);
        return placed;
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, PR_LINE_THIN);
    /* Extension lines: from 1 mm off the object to 1.5 mm past the dimension line. */
    if (fabs(offset) > 1.0) {
        cairo_move_to(cr, ax + nx * sgn * 1.0, ay + ny * sgn * 1.0);
        cairo_line_to(cr, a2x + nx * sgn * 1.5, a2y + ny * sgn * 1.5);
        cairo_move_to(cr, bx + nx * sgn * 1.0, by + ny * sgn * 1.0);
        cairo_line_to(cr, b2x + nx * sgn * 1.5, b2y + ny * sgn * 1.5);
    }
    /* The dimension line, running 1.5 mm past the extension lines. */
    cairo_move_to(cr, a2x - ux * 1.5, a2y - uy * 1.5);
    cairo_line_to(cr, b2x + ux * 1.5, b2y + uy * 1.5);
    cairo_stroke(cr);
    /* Ticks: short heavy strokes at 45 degrees through each end. */
    cairo_set_line_width(cr, PR_LINE_WIDE);
    double kx = (ux + nx) * 0.7071 * 1.3, ky = (uy + ny) * 0.7071 * 1.3;
    cairo_move_to(cr, a2x - kx, a2y - ky);
    cairo_line_to(cr, a2x + kx, a2y + ky);
    cairo_move_to(cr, b2x - kx, b2y - ky);
    cairo_line_to(cr, b2x + kx, b2y + ky);
    cairo_stroke(cr);
    /* The value (readable from the bottom or the right, ISO 129-1 method 1). */
    pr_text_rotated(cr, tx, ty, angle, 0.5, 1.0, text);
    cairo_restore(cr);
    return placed;
}

void pr_dimension(cairo_t *cr, double ax, double ay, double bx, double by, double offset,
                  double value_mm)
{
    pr_dimension_placed(cr, ax, ay, bx, by, offset, value_mm, 1);
}

int pr_text_boxes_mark(cairo_t *cr)
{
    pr_text_boxes *r = pr_text_boxes_of(cr);
    return r ? r->count : 0;
}

void pr_text_boxes_rollback(cairo_t *cr, int mark)
{
    pr_text_boxes *r = pr_text_boxes_of(cr);
    if (r && mark <= r->count)
        r->count = mark;
}

void pr_hatch_path(cairo_t *cr, double spacing, double angle_deg)
{
    double x0, y0, x1, y1;
    cairo_save(cr);
    cairo_path_t *path = cairo_copy_path(cr);
    cairo_fill_extents(cr, &x0, &y0, &x1, &y1);
    cairo_clip(cr);
    double a = angle_deg * PR_PI / 180.0;
    double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2, r = hypot(x1 - x0, y1 - y0) / 2 + spacing;
    double ux = cos(a), uy = -sin(a), nx = -uy, ny = ux;
    for (double k = -r; k <= r; k += spacing) {
        cairo_move_to(cr, cx + nx * k - ux * r, cy + ny * k - uy * r);
        cairo_line_to(cr, cx + nx * k + ux * r, cy + ny * k + uy * r);
    }
    cairo_stroke(cr);
    cairo_restore(cr);
    cairo_new_path(cr);
    cairo_append_path(cr, path);
    cairo_path_destroy(path);
}

void pr_level_mark(cairo_t *cr, double x, double y, const char *text, int text_left)
{
    /* An open triangle standing on the level line, point down (building drawings' level),
     * the value on a short leader to the right (or to the left). */
    cairo_save(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, PR_LINE_FINE);
    pr_set_font(cr, PR_TEXT_SMALL, 0);
    double w = pr_text_width(cr, text);
    if (text_left) {
        cairo_move_to(cr, x + 3.0, y);
        cairo_line_to(cr, x - 6.0 - w, y);
    } else {
        cairo_move_to(cr, x - 3.0, y);
        cairo_line_to(cr, x + 6.0 + w, y);
    }
    cairo_stroke(cr);
    cairo_move_to(cr, x, y);
    cairo_line_to(cr, x - 1.3, y - 2.0);
    cairo_line_to(cr, x + 1.3, y - 2.0);
    cairo_close_path(cr);
    cairo_fill(cr);
    if (text_left)
        pr_text(cr, x - 2.0, y - 0.7, 1.0, 1.0, text);
    else
        pr_text(cr, x + 2.0, y - 0.7, 0.0, 1.0, text);
    cairo_restore(cr);
}

void pr_scale_bar(cairo_t *cr, double x, double y, int scale)
{
    /* A graphic scale, so a copy printed at another size can still be measured: 1 m (2 m at
     * 1:100 and smaller) in five alternating blocks, ending at (x, y). */
    if (scale <= 0)
        return;
    double metres = scale >= 100 ? 2.0 : (scale <= 10 ? 0.5 : 1.0);
    double len = metres * 1000.0 / scale, x0 = x - len;
    cairo_save(cr);
    cairo_set_line_width(cr, PR_LINE_THIN);
    for (int i = 0; i < 5; i++) {
        cairo_rectangle(cr, x0 + len * i / 5, y - 1.2, len / 5, 1.2);
        if (i % 2 == 0) {
            cairo_set_source_rgb(cr, 0, 0, 0);
            cairo_fill_preserve(cr);
        }
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_stroke(cr);
    }
    pr_set_font(cr, 1.8, 0);
    char text[32];
    pr_text(cr, x0, y - 2.0, 0.5, 1.0, "0");
    snprintf(text, sizeof text, "%g m", metres);
    pr_text(cr, x, y - 2.0, 0.5, 1.0, text);
    snprintf(text, sizeof text, "1:%d", scale);
    pr_text(cr, x0 - 2.5, y, 1.0, 1.0, text);
    cairo_restore(cr);
}

void pr_format_money(long long cents, char *out, size_t size)
{
    int neg = cents < 0;
    unsigned long long v =
        neg ? (unsigned long long)(-(cents + 1)) + 1u : (unsigned long long)cents;
    unsigned long long units = v / 100, frac = v % 100;
    char digits[32], grouped[48];
    snprintf(digits, sizeof digits, "%llu", units);
    size_t n = strlen(digits), j = 0;
    for (size_t i = 0; i < n; i++) {
        if (i > 0 && (n - i) % 3 == 0)
            grouped[j++] = ',';
        grouped[j++] = digits[i];
    }
    grouped[j] = 0;
    snprintf(out, size, "%s%s.%02llu", neg ? "-" : "", grouped, frac);
}

void pr_balloon(cairo_t *cr, double x, double y, int number)
{
    char text[16];
    snprintf(text, sizeof text, "%d", number);
    const double r = PR_BALLOON_RADIUS;
    cairo_save(cr);
    cairo_new_path(cr);
    cairo_arc(cr, x, y, r, 0, 2 * PR_PI);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, PR_LINE_FINE);
    cairo_stroke(cr);
    pr_set_font(cr, number >= 100 ? 1.5 : (number >= 10 ? 1.8 : 2.0), 1);
    /* The circle is the text's box: the digits inside are not recorded again. */
    pr_box_record(cr, pr_box_to_paper(cr, x - r, y - r, x + r, y + r), text);
    pr_text_boxes *reg = pr_text_boxes_of(cr);
    if (reg)
        reg->suspended++;
    pr_text(cr, x, y, 0.5, 0.5, text);
    if (reg)
        reg->suspended--;
    cairo_restore(cr);
}

int pr_place_balloon(cairo_t *cr, double x, double y, int number, pr_box within)
{
    const double r = PR_BALLOON_RADIUS;
    /* The anchor first, then along leaders in eight directions at growing lengths: the
     * shortest free leader wins. */
    static const double dirs[8][2] = {
        {0, -1},          {0, 1},           {1, 0}, {-1, 0}, {0.7071, -0.7071}, {-0.7071, -0.7071},
        {0.7071, 0.7071}, {-0.7071, 0.7071}};
    static const double lengths[] = {0, 4.5, 7, 10, 14, 19, 25};
    for (size_t li = 0; li < sizeof lengths / sizeof lengths[0]; li++)
        for (int k = 0; k < (li == 0 ? 1 : 8); k++) {
            double bx = x + dirs[k][0] * lengths[li], by = y + dirs[k][1] * lengths[li];
            pr_box b = pr_box_to_paper(cr, bx - r, by - r, bx + r, by + r);
            if (b.x0 < within.x0 || b.y0 < within.y0 || b.x1 > within.x1 || b.y1 > within.y1 ||
                !pr_box_is_free(cr, b, 0.4))
                continue;
            if (li > 0) {
                cairo_save(cr);
                cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
                cairo_set_line_width(cr, PR_LINE_THIN);
                cairo_move_to(cr, x, y);
                cairo_line_to(cr, bx - dirs[k][0] * r, by - dirs[k][1] * r);
                cairo_stroke(cr);
                cairo_arc(cr, x, y, 0.4, 0, 2 * PR_PI);
                cairo_fill(cr);
                cairo_restore(cr);
            }
            pr_balloon(cr, bx, by, number);
            return 1;
        }
    return 0;
}
