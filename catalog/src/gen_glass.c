/* Glass and mirrors: shower screens (glass panels with metal profiles), mirrors (a mirror pane
 * on a back panel, a glowing rim when illuminated, a frame when framed) and mirror cabinets (a
 * body with mirror doors). Flat parts are boxes with flat faces; the quadrant enclosure's glass
 * is a rectangle swept along its curved plan. */
#include "gen_internal.h"

#include <math.h>
#include <stdlib.h>

static const double AY[3] = {0, 1, 0}, AZ[3] = {0, 0, 1};

#define GLASS_T 8.0

/* A glass panel in the x-z plane from x0 to x1, centred at y. */
static void panel_x(gen_ctx *c, int glass, double x0, double x1, double y, double z0, double z1)
{
    gen_box(c, glass, x0, y - GLASS_T / 2, z0, x1, y + GLASS_T / 2, z1);
}

static void panel_y(gen_ctx *c, int glass, double y0, double y1, double x, double z0, double z1)
{
    gen_box(c, glass, x - GLASS_T / 2, y0, z0, x + GLASS_T / 2, y1, z1);
}

void gen_screen(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    int glass = gen_part(c, "glass", GEN_MAT_FINISH);
    int metal = gen_part(c, "profiles", GEN_MAT_CHROME);
    double p = 20; /* profile width */
    if (gen_has(c, "quadrant")) {
        double r = 550 < w - 100 ? 550 : w - 100, yf = d - GLASS_T, xr = w / 2 - GLASS_T;
        double cx = xr - r, cy = yf - r, path[3 * 20];
        int n = 0;
        path[3 * n] = -w / 2 + p, path[3 * n + 1] = yf, path[3 * n + 2] = 0, n++;
        for (int i = 0; i <= 16; i++) {
            double a = GEN_PI / 2 * (1 - i / 16.0);
            path[3 * n] = cx + r * cos(a);
            path[3 * n + 1] = cy + r * sin(a);
            path[3 * n + 2] = 0;
            n++;
        }
        path[3 * n] = xr, path[3 * n + 1] = p, path[3 * n + 2] = 0, n++;
        double prof[8] = {0,      -GLASS_T / 2, h - 10, -GLASS_T / 2,
                          h - 10, GLASS_T / 2,  0,      GLASS_T / 2};
        gen_sweep(c, glass, path, n, prof, 4, AZ, 1);
        gen_box(c, metal, -w / 2, yf - p / 2, 0, -w / 2 + p, yf + GLASS_T, h);
        gen_box(c, metal, xr - p / 2, 0, 0, w / 2, p, h);
        for (int i = 0; i < n; i++) /* the top profile follows the glass */
            path[3 * i + 2] = h - 10;
        gen_tube(c, metal, path, n, 6, 8, 0);
        return;
    }
    if (gen_has(c, "corner")) {
        double yf = d - GLASS_T / 2, xr = w / 2 - GLASS_T / 2;
        panel_x(c, glass, -w / 2 + p, xr - GLASS_T, yf, 0, h);
        panel_y(c, glass, p, yf - GLASS_T, xr, 0, h);
        gen_box(c, metal, -w / 2, d - p, 0, -w / 2 + p, d, h); /* against the left wall */
        gen_box(c, metal, w / 2 - p, 0, 0, w / 2, p, h);       /* against the back wall */
        gen_box(c, metal, xr - 12, yf - 12, 0, w / 2, d, h);   /* the corner post */
        gen_box(c, metal, -w / 2 * 0.2 - 4, yf + GLASS_T / 2, h * 0.45, -w / 2 * 0.2 + 4, d,
                h * 0.6); /* a handle */
        return;
    }
    if (gen_has(c, "sliding")) {
        double a = d * 0.3, b = d * 0.7;
        panel_x(c, glass, -w / 2 + p, w * 0.08, a, 0, h - 50);
        panel_x(c, glass, -w * 0.08, w / 2 - p, b, 0, h - 50);
        gen_box(c, metal, -w / 2, 0, h - 50, w / 2, d, h); /* the top rail */
        gen_box(c, metal, -w / 2, 0, 0, -w / 2 + p, d, h - 50);
        gen_box(c, metal, w / 2 - p, 0, 0, w / 2, d, h - 50);
        gen_box(c, metal, -w * 0.05, b + GLASS_T / 2, h * 0.4, -w * 0.05 + 10, d, h * 0.6);
        return;
    }
    double y = d / 2;
    if (gen_has(c, "bath screen")) { /* a fixed panel and a hinged one, slightly open */
        panel_x(c, glass, -w / 2 + p, -2, y - 6, 0, h);
        panel_x(c, glass, 2, w / 2, y + 6, 0, h * 0.97);
        gen_box(c, metal, -w / 2, 0, 0, -w / 2 + p, d, h);
        gen_box(c, metal, -8, y - 10, h * 0.2, 8, y + 14, h * 0.26);
        gen_box(c, metal, -8, y - 10, h * 0.75, 8, y + 14, h * 0.81);
        return;
    }
    panel_x(c, glass, -w / 2 + p * 0.5, w / 2 - (gen_has(c, "door") ? p * 0.5 : 0), y, 0, h);
    gen_box(c, metal, -w / 2, 0, 0, -w / 2 + p, d, h);
    if (gen_has(c, "door")) { /* a niche door: profiles both sides, a handle */
        gen_box(c, metal, w / 2 - p, 0, 0, w / 2, d, h);
        gen_box(c, metal, w / 2 - p - 60, 0, h * 0.4, w / 2 - p - 48, d, h * 0.6);
    } else { /* a walk-in screen: a foot profile on the floor */
        gen_box(c, metal, -w / 2, y - GLASS_T, 0, w / 2, y + GLASS_T, 12);
    }
}

void gen_mirror(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    int mirror = gen_part(c, "mirror", GEN_MAT_FINISH);
    int back = gen_part(c, "back panel", GEN_MAT_BLACK);
    int lit = gen_has(c, "illuminated"), framed = gen_has(c, "frame");
    int round = gen_has(c, "round");
    double t = 5;
    if (round) {
        double r = w / 2, fw = 12 < r * 0.1 ? 12 : r * 0.1, rm = framed ? r - fw : r;
        gen_cylinder(c, mirror, 0, d - t, h / 2, AY, rm, t, 64);
        gen_cylinder(c, back, 0, 0, h / 2, AY, rm * 0.8, d - t, 32);
        if (lit) {
            int light = gen_part(c, "light ring", GEN_MAT_LIGHT);
            gen_cylinder(c, light, 0, d - t - 8, h / 2, AY, r, 8, 64);
        }
        if (framed) {
            int frame = gen_part(c, "frame", GEN_MAT_BLACK);
            double path[3 * 48];
            for (int i = 0; i < 48; i++) {
                double a = 2 * GEN_PI * i / 48;
                path[3 * i] = (r - fw / 2) * cos(a);
                path[3 * i + 1] = d - fw / 2;
                path[3 * i + 2] = h / 2 + (r - fw / 2) * sin(a);
            }
            gen_tube(c, frame, path, 48, fw / 2, 8, 1);
        }
        return;
    }
    gen_box(c, mirror, -w / 2, d - t, 0, w / 2, d, h);
    gen_box(c, back, -w / 2 + 40, 0, 40, w / 2 - 40, d - t, h - 40);
    if (lit) { /* a glowing strip behind the edge of the mirror, lighting the wall */
        int light = gen_part(c, "light strip", GEN_MAT_LIGHT);
        gen_box(c, light, -w / 2 + 20, d - t - 6, 20, w / 2 - 20, d - t, 30);
        gen_box(c, light, -w / 2 + 20, d - t - 6, h - 30, w / 2 - 20, d - t, h - 20);
    }
}

void gen_cabinet(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    int doors = gen_part(c, "mirror doors", GEN_MAT_FINISH);
    int body = gen_part(c, "body", GEN_MAT_CERAMIC);
    double front = 20, z0 = 0;
    if (gen_has(c, "LED")) {
        int light = gen_part(c, "light", GEN_MAT_LIGHT);
        z0 = 6;
        gen_box(c, light, -w / 2 + 30, d * 0.3, 0, w / 2 - 30, d * 0.7, z0);
    }
    gen_rbox(c, body, -w / 2, 0, z0, w / 2, d - front, h, 4);
    int n = gen_count(c);
    double gap = 3, dw = (w - gap * (n - 1)) / n;
    for (int i = 0; i < n; i++) {
        double x0 = -w / 2 + i * (dw + gap);
        gen_box(c, doors, x0, d - front, z0, x0 + dw, d, h);
    }
}
