#include "app/measure/sweep_plot.h"

#include "app/measure/label_place.h"

#include <cairo.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

void app_sweep_mark_front(app_sweep_point *p, int n)
{
    for (int i = 0; i < n; i++) {
        p[i].on_front = isfinite(p[i].ms) && !isnan(p[i].psnr);
        for (int j = 0; j < n && p[i].on_front; j++)
            if (j != i && p[j].ms <= p[i].ms && p[j].psnr >= p[i].psnr &&
                (p[j].ms < p[i].ms || p[j].psnr > p[i].psnr))
                p[i].on_front = 0;
    }
}

/* A colour a factor; anything else (the baseline) the last. */
static const char *const factors[] = {"resolution", "correction",       "blur",       "update",
                                      "per-vertex", "ambient",          "highlights", "mirrors",
                                      "lamps",      "self-reflections", "preset",     "baseline"};
enum { FACTORS = sizeof factors / sizeof factors[0] };
static const double colours[FACTORS][3] = {
    {0.12, 0.47, 0.71}, {0.84, 0.15, 0.16}, {0.17, 0.63, 0.17}, {1.0, 0.5, 0.05},
    {0.58, 0.4, 0.74},  {0.55, 0.34, 0.29}, {0.5, 0.5, 0.5},    {0.09, 0.75, 0.81},
    {0.74, 0.74, 0.13}, {0.55, 0.35, 0.0},  {0.89, 0.47, 0.76}, {0.1, 0.1, 0.1}};

static int factor_index(const char *f)
{
    for (int i = 0; i < FACTORS; i++)
        if (!strcmp(f, factors[i]))
            return i;
    return FACTORS - 1;
}

static int compare_ms(const void *a, const void *b)
{
    const app_sweep_point *x = *(const app_sweep_point *const *)a,
                          *y = *(const app_sweep_point *const *)b;
    return (x->ms > y->ms) - (x->ms < y->ms);
}

int app_sweep_plot(const char *path, const app_sweep_point *p, int n, const char *title, char *err,
                   int err_size)
{
    const int W = 1100, H = 700, L = 90, R = 230, T = 60, B = 70;
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int i = 0; i < n; i++) {
        if (!isfinite(p[i].ms) || !isfinite(p[i].psnr))
            continue;
        x0 = fmin(x0, p[i].ms), x1 = fmax(x1, p[i].ms);
        y0 = fmin(y0, p[i].psnr), y1 = fmax(y1, p[i].psnr);
    }
    if (!(x0 <= x1)) {
        snprintf(err, (size_t)err_size, "%s: nothing to plot", path);
        return -1;
    }
    /* Milliseconds on a log scale: the settings span two decades. */
    double lx0 = log10(fmax(x0, 1e-3) * 0.9), lx1 = log10(x1 * 1.8); /* room for labels */
    double py0 = floor(y0 - 1.0), py1 = ceil(y1 + 1.0);
    if (lx1 - lx0 < 0.2)
        lx1 = lx0 + 0.2;
    cairo_surface_t *surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, W, H);
    cairo_t *cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
#define PX(ms) (L + (log10(ms) - lx0) / (lx1 - lx0) * (W - L - R))
#define PY(db) (H - B - ((db)-py0) / (py1 - py0) * (H - T - B))
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_line_width(cr, 1.0);
    /* grid and ticks */
    cairo_set_font_size(cr, 12);
    for (double e = floor(lx0); e <= lx1; e += 1.0)
        for (int m = 1; m < 10; m++) {
            double v = pow(10.0, e) * m;
            if (log10(v) < lx0 || log10(v) > lx1)
                continue;
            double x = PX(v);
            cairo_set_source_rgb(cr, m == 1 ? 0.75 : 0.9, m == 1 ? 0.75 : 0.9, m == 1 ? 0.75 : 0.9);
            cairo_move_to(cr, x, T);
            cairo_line_to(cr, x, H - B);
            cairo_stroke(cr);
            if (m == 1 || m == 2 || m == 5) {
                char t[32];
                snprintf(t, sizeof t, "%g", v);
                cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
                cairo_move_to(cr, x - 8, H - B + 18);
                cairo_show_text(cr, t);
            }
        }
    for (double db = py0; db <= py1; db += (py1 - py0 > 20 ? 5 : 1)) {
        double y = PY(db);
        cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
        cairo_move_to(cr, L, y);
        cairo_line_to(cr, W - R, y);
        cairo_stroke(cr);
        char t[32];
        snprintf(t, sizeof t, "%.0f", db);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        cairo_move_to(cr, L - 30, y + 4);
        cairo_show_text(cr, t);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_rectangle(cr, L, T, W - L - R, H - T - B);
    cairo_stroke(cr);
    cairo_set_font_size(cr, 14);
    cairo_move_to(cr, L + (W - L - R) / 2 - 120, H - 20);
    cairo_show_text(cr, "milliseconds per frame (log scale; less is faster)");
    cairo_save(cr);
    cairo_move_to(cr, 24, T + (H - T - B) / 2 + 120);
    cairo_rotate(cr, -PI / 2);
    cairo_show_text(cr, "PSNR of reflective pixels, dB (more is better)");
    cairo_restore(cr);
    cairo_set_font_size(cr, 16);
    cairo_move_to(cr, L, 32);
    cairo_show_text(cr, title);
    /* the front */
    const app_sweep_point **front = malloc((size_t)n * sizeof *front);
    int nf = 0;
    for (int i = 0; front && i < n; i++)
        if (p[i].on_front)
            front[nf++] = &p[i];
    if (front && nf > 1) {
        qsort(front, (size_t)nf, sizeof *front, compare_ms);
        cairo_set_source_rgba(cr, 0, 0, 0, 0.5);
        cairo_set_line_width(cr, 2.0);
        for (int i = 0; i < nf; i++) {
            if (i == 0)
                cairo_move_to(cr, PX(front[i]->ms), PY(front[i]->psnr));
            else
                cairo_line_to(cr, PX(front[i]->ms), PY(front[i]->psnr));
        }
        cairo_stroke(cr);
    }
    free(front);
    /* Points, then their labels, placed so that none covers another label or a point
     * (label_place.c): the front's first, then the presets', then the rest; a label moved
     * away from its point is joined to it by a leader line. */
    cairo_set_font_size(cr, 11);
    app_label *labels = calloc((size_t)n, sizeof *labels);
    int *order = calloc((size_t)n, sizeof *order);
    int nl = 0;
    for (int pass = 0; labels && order && pass < 3; pass++)
        for (int i = 0; i < n; i++) {
            if (!isfinite(p[i].ms) || !isfinite(p[i].psnr))
                continue;
            int preset = !strcmp(p[i].factor, "preset");
            if ((pass == 0) != (p[i].on_front != 0) || (pass > 0 && (pass == 1) != preset))
                continue;
            cairo_text_extents_t te;
            cairo_text_extents(cr, p[i].label, &te);
            order[nl] = i;
            labels[nl++] = (app_label){
                .px = PX(p[i].ms), .py = PY(p[i].psnr), .w = ceil(te.x_advance) + 2, .h = 13};
        }
    for (int i = 0; i < n; i++) {
        if (!isfinite(p[i].ms) || !isfinite(p[i].psnr))
            continue;
        const double *c = colours[factor_index(p[i].factor)];
        cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        cairo_arc(cr, PX(p[i].ms), PY(p[i].psnr), p[i].on_front ? 6 : 4, 0, 2 * PI);
        cairo_fill(cr);
    }
    const app_label_box area = {L + 1, T + 1, W - L - R - 2, H - T - B - 2};
    app_labels_place(labels, nl, 6.0, &area);
    for (int k = 0; k < nl; k++) {
        const app_label *l = &labels[k];
        if (!l->placed)
            continue;
        const double *c = colours[factor_index(p[order[k]].factor)];
        if (l->moved) {
            /* From the point to the nearest spot of the label's box. */
            double qx = fmin(fmax(l->px, l->box.x), l->box.x + l->box.w);
            double qy = fmin(fmax(l->py, l->box.y), l->box.y + l->box.h);
            cairo_set_source_rgba(cr, c[0], c[1], c[2], 0.6);
            cairo_set_line_width(cr, 0.8);
            cairo_move_to(cr, l->px, l->py);
            cairo_line_to(cr, qx, qy);
            cairo_stroke(cr);
        }
        cairo_set_source_rgb(cr, c[0] * 0.8, c[1] * 0.8, c[2] * 0.8);
        cairo_move_to(cr, l->box.x + 1, l->box.y + 10);
        cairo_show_text(cr, p[order[k]].label);
    }
    free(labels);
    free(order);
    /* legend */
    cairo_set_font_size(cr, 13);
    for (int k = 0; k < FACTORS; k++) {
        double y = T + 20 + 24 * k;
        cairo_set_source_rgb(cr, colours[k][0], colours[k][1], colours[k][2]);
        cairo_arc(cr, W - R + 24, y - 4, 5, 0, 2 * PI);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        cairo_move_to(cr, W - R + 36, y);
        cairo_show_text(cr, factors[k]);
    }
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_move_to(cr, W - R + 16, T + 20 + 24 * FACTORS + 10);
    cairo_show_text(cr, "line: the Pareto front");
#undef PX
#undef PY
    cairo_destroy(cr);
    /* Atomic like every other write: a temporary file renamed over the target. */
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    cairo_status_t st = cairo_surface_write_to_png(surface, tmp);
    cairo_surface_destroy(surface);
    if (st != CAIRO_STATUS_SUCCESS || rename(tmp, path) != 0) {
        remove(tmp);
        snprintf(err, (size_t)err_size, "%s: cannot write the plot (%s)", path,
                 cairo_status_to_string(st));
        return -1;
    }
    return 0;
}
