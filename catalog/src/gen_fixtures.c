/* Taps, mixers and shower sets: chrome-like bodies turned on a lathe (gen_cylinder, lofts of
 * circles or, for square series, of rounded squares), spouts and arms swept along arcs, levers
 * and knobs. Shapes follow the product's name (make_catalog_csv.c's product types); sizes come
 * from the row, so the proportions below are fractions of width, depth and height. */
#include "gen_internal.h"

#include <math.h>

static const double AX[3] = {1, 0, 0}, AY[3] = {0, 1, 0}, AZ[3] = {0, 0, 1};

/* A quarter-round bend path from (x, y0, z0) forward along +y to y1 and then down to z1. */
static int spout_path(double *p, double x, double y0, double z0, double y1, double z1)
{
    int n = 0;
    double r = fabs(z0 - z1) < (y1 - y0) * 0.5 ? fabs(z0 - z1) : (y1 - y0) * 0.5;
    double straight_end = y1 - r;
    p[3 * n] = x, p[3 * n + 1] = y0, p[3 * n + 2] = z0, n++;
    p[3 * n] = x, p[3 * n + 1] = straight_end, p[3 * n + 2] = z0, n++;
    for (int i = 1; i <= 6; i++) {
        double a = GEN_PI / 2 * i / 6;
        p[3 * n] = x;
        p[3 * n + 1] = straight_end + r * sin(a);
        p[3 * n + 2] = z0 - r * (1 - cos(a));
        n++;
    }
    if (z0 - r > z1 + 0.5) {
        p[3 * n] = x, p[3 * n + 1] = y1, p[3 * n + 2] = z1, n++;
    }
    return n;
}

/* A vertical body: a cylinder, or a rounded square in square series. */
static void column(gen_ctx *c, int part, double x, double y, double z0, double z1, double r)
{
    if (c->square)
        gen_rbox(c, part, x - r, y - r, z0, x + r, y + r, z1, r * 0.25);
    else
        gen_cylinder(c, part, x, y, z0, AZ, r, z1 - z0, 16);
}

static void spout(gen_ctx *c, int part, const double *path, int n, double r)
{
    if (c->square) {
        double prof[8] = {-r, -r * 0.7, r, -r * 0.7, r, r * 0.7, -r, r * 0.7};
        gen_sweep(c, part, path, n, prof, 4, AX, 1);
    } else {
        gen_tube(c, part, path, n, r, 12, 0);
    }
}

/* Single-lever and pillar taps on a basin or bidet deck. */
static void deck_tap(gen_ctx *c, double w, double d, double h)
{
    int body = gen_part(c, "body", GEN_MAT_FINISH);
    int lever = gen_part(c, "lever", GEN_MAT_FINISH);
    int aer = gen_part(c, "aerator", GEN_MAT_BLACK);
    double rb = w / 2, lever_h = h * 0.14, hb = h - lever_h;
    column(c, body, 0, rb, 0, hb, rb);
    double rs = rb * 0.42, zs = hb * 0.82;
    double path[3 * 10];
    int n = spout_path(path, 0, rb, zs, d - rs, zs - rb * 1.2);
    spout(c, body, path, n, rs);
    gen_cylinder(c, aer, 0, d - rs, zs - rb * 1.2 - 2, AZ, rs * 0.8, 3, 12);
    if (gen_has(c, "cold water")) { /* a knob on top */
        gen_cylinder(c, lever, 0, rb, hb, AZ, rb * 0.8, lever_h * 0.5, 12);
        gen_rbox(c, lever, -rb, rb - rb * 0.25, hb + lever_h * 0.3, rb, rb + rb * 0.25, h,
                 rb * 0.15);
    } else { /* a cartridge cap and a lever pointing back and up */
        gen_cylinder(c, lever, 0, rb, hb, AZ, rb * 0.85, lever_h * 0.45, 16);
        gen_rbox(c, lever, -rb * 0.3, 0, hb + lever_h * 0.4, rb * 0.3, rb * 1.3, h, rb * 0.12);
    }
}

/* A finish set on the wall: a plate, a spout and (for mixers) a lever. */
static void wall_tap(gen_ctx *c, double w, double d, double h)
{
    int plate = gen_part(c, "rosette", GEN_MAT_FINISH);
    int body = gen_part(c, "spout", GEN_MAT_FINISH);
    int aer = gen_part(c, "aerator", GEN_MAT_BLACK);
    double t = 10, rs = h * 0.22 < 14 ? h * 0.22 : 14, zs = h / 2;
    if (c->square || w > h * 1.5)
        gen_rbox(c, plate, -w / 2, 0, 0, w / 2, t, h, 6);
    else
        gen_cylinder(c, plate, 0, 0, h / 2, AY, h / 2, t, 24);
    double path[3 * 10];
    int n = spout_path(path, 0, t / 2, zs, d - rs, zs - rs * 1.5);
    spout(c, body, path, n, rs);
    gen_cylinder(c, aer, 0, d - rs, zs - rs * 1.5 - 2, AZ, rs * 0.8, 3, 12);
    if (gen_has(c, "mixer")) {
        int lever = gen_part(c, "lever", GEN_MAT_FINISH);
        double lx = w / 2 - h * 0.35;
        gen_cylinder(c, lever, lx, t, zs, AY, h * 0.22, h * 0.5, 16);
        gen_rbox(c, lever, lx - 5, t + h * 0.35, zs - 4, lx + 5, t + h * 0.5, h * 0.95, 3);
    }
}

/* Exposed bath and shower mixers: a horizontal body on two S-unions, knobs or a lever. */
static void exposed(gen_ctx *c, double w, double d, double h)
{
    int body = gen_part(c, "body", GEN_MAT_FINISH);
    int knobs = gen_part(c, gen_has(c, "thermostat") ? "handles" : "lever", GEN_MAT_FINISH);
    int ros = gen_part(c, "rosettes", GEN_MAT_FINISH);
    int bath = gen_has(c, "bath");
    double r = h * (bath ? 0.3 : 0.45), zc = h - r, yc = bath ? r + 35 : d - r;
    double knob = w * 0.1;
    if (c->square)
        gen_rbox(c, body, -w / 2 + knob, yc - r, zc - r, w / 2 - knob, yc + r, zc + r, r * 0.3);
    else
        gen_cylinder(c, body, -w / 2 + knob, yc, zc, AX, r, w - 2 * knob, 20);
    /* S-unions at the standard 150 mm centres, closer on a body too short for them. */
    double ux = 75 < w / 2 - knob - r * 0.75 ? 75 : w / 2 - knob - r * 0.75;
    for (int s = -1; s <= 1; s += 2) {
        gen_cylinder(c, ros, s * ux, 0, zc, AY, r * 0.75, 8, 16);
        gen_cylinder(c, ros, s * ux, 0, zc, AY, r * 0.35, yc, 12);
    }
    if (gen_has(c, "thermostat")) {
        gen_cylinder(c, knobs, -w / 2, yc, zc, AX, r * 1.05, knob, 20);
        gen_cylinder(c, knobs, w / 2 - knob, yc, zc, AX, r * 1.05, knob, 20);
    } else {
        gen_cylinder(c, knobs, -w / 2, yc, zc, AX, r * 0.9, knob, 16);
        gen_cylinder(c, knobs, w / 2 - knob, yc, zc, AX, r * 0.9, knob, 16);
        gen_rbox(c, knobs, -6, yc - 5, zc + r * 0.8, 6, yc + r * 1.6, h, 3);
    }
    if (bath) {
        double path[3 * 10], rs = r * 0.45;
        int n = spout_path(path, 0, yc, zc - r * 0.4, d - rs, rs);
        spout(c, body, path, n, rs);
    }
}

static void three_hole(gen_ctx *c, double w, double d, double h)
{
    int body = gen_part(c, "body", GEN_MAT_FINISH);
    int handles = gen_part(c, "handles", GEN_MAT_FINISH);
    double r = w * 0.12, y = r + 5;
    for (int s = -1; s <= 1; s += 2) {
        double x = s * (w / 2 - r);
        column(c, handles, x, y, 0, h * 0.55, r);
        gen_rbox(c, handles, x - r * 0.3, y - r * 1.2, h * 0.55, x + r * 0.3, y + r * 1.2, h * 0.7,
                 r * 0.2);
    }
    column(c, body, 0, y, 0, h * 0.5, r * 1.1);
    double path[3 * 16];
    int n = 0;
    double top = h - r * 0.5, base = h * 0.45;
    for (int i = 0; i <= 12; i++) { /* a swan neck: up, over and forward */
        double a = GEN_PI * i / 12;
        path[3 * n] = 0;
        path[3 * n + 1] = y + (d - y - r * 0.5) * (1 - cos(a)) / 2;
        path[3 * n + 2] = base + (top - base) * sin(a);
        n++;
    }
    spout(c, body, path, n, r * 0.5);
}

static void floor_standing(gen_ctx *c, double w, double d, double h)
{
    int body = gen_part(c, "body", GEN_MAT_FINISH);
    int lever = gen_part(c, "lever", GEN_MAT_FINISH);
    int hs = gen_part(c, "hand shower", GEN_MAT_FINISH);
    double r = 25, y = 70;
    gen_cylinder(c, body, 0, y, 0, AZ, 70, 12, 24); /* floor plate */
    column(c, body, 0, y, 0, h * 0.82, r);
    double path[3 * 16];
    int n = 0;
    for (int i = 0; i <= 12; i++) {
        double a = GEN_PI * i / 12;
        path[3 * n] = 0;
        path[3 * n + 1] = y + (d - y - 15) * (1 - cos(a)) / 2;
        path[3 * n + 2] = h * 0.8 + (h - 15 - h * 0.8) * sin(a);
        n++;
    }
    spout(c, body, path, n, 15);
    gen_cylinder(c, lever, -w / 2, y, h * 0.6, AX, 18, w / 2 - r, 12);
    gen_cylinder(c, hs, w / 2 - 22, y, h * 0.45, AZ, 20, h * 0.3, 16);
    gen_cylinder(c, hs, 0, y, h * 0.5, AX, 8, w / 2 - 22, 8);
}

static void concealed_trim(gen_ctx *c, double w, double d, double h)
{
    int plate = gen_part(c, "plate", GEN_MAT_FINISH);
    int knobs = gen_part(c, "handles", GEN_MAT_FINISH);
    if (c->square)
        gen_rbox(c, plate, -w / 2, 0, 0, w / 2, 10, h, 8);
    else
        gen_cylinder(c, plate, 0, 0, h / 2, AY, w / 2, 10, 32);
    gen_cylinder(c, knobs, -w * 0.22, 10, h / 2, AY, w * 0.14, d - 10, 20);
    gen_cylinder(c, knobs, w * 0.22, 10, h / 2, AY, w * 0.14, (d - 10) * 0.8, 20);
    gen_rbox(c, knobs, w * 0.22 - 5, d * 0.7, h / 2 - 5, w * 0.22 + 5, d, h / 2 + w * 0.25, 3);
}

void gen_tap(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    if (gen_has(c, "floor-standing"))
        floor_standing(c, w, d, h);
    else if (gen_has(c, "concealed"))
        concealed_trim(c, w, d, h);
    else if (gen_has(c, "three-hole"))
        three_hole(c, w, d, h);
    else if (gen_has(c, "wall-mounted"))
        wall_tap(c, w, d, h);
    else if (gen_has(c, "exposed"))
        exposed(c, w, d, h);
    else
        deck_tap(c, w, d, h);
}

/* A round or square shower head of diameter s facing down, top at z. */
static void head(gen_ctx *c, int part, double x, double y, double z, double s, double t)
{
    if (c->square)
        gen_rbox(c, part, x - s / 2, y - s / 2, z - t, x + s / 2, y + s / 2, z, t * 0.4);
    else
        gen_cylinder(c, part, x, y, z - t, AZ, s / 2, t, 32);
}

static void hand_shower(gen_ctx *c, int part, int face, double x, double y, double z0, double len,
                        double s)
{
    /* handle up to the head; the spray face looks forward (+y) */
    gen_cylinder(c, part, x, y, z0, AZ, s * 0.13, len - s * 0.5, 12);
    gen_cylinder(c, part, x, y - s * 0.2, z0 + len - s / 2, AY, s / 2, s * 0.3, 24);
    gen_cylinder(c, face, x, y + s * 0.1, z0 + len - s / 2, AY, s * 0.4, 2, 24);
}

void gen_shower(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    int metal = gen_part(c, "body", GEN_MAT_FINISH);
    int face = gen_part(c, "spray face", GEN_MAT_BLACK);
    if (gen_has(c, "rail set")) {
        double yr = 30;
        gen_cylinder(c, metal, 0, yr, 0, AZ, 12, h, 12);
        for (int e = 0; e < 2; e++) {
            double z = e ? h - 40 : 40;
            gen_cylinder(c, metal, 0, 0, z, AY, 22, 8, 16);
            gen_cylinder(c, metal, 0, 0, z, AY, 9, yr, 12);
        }
        gen_rbox(c, metal, -20, yr - 18, h * 0.72, 20, yr + 35, h * 0.8, 6);
        hand_shower(c, metal, face, 0, d - w * 0.35, h * 0.45, h * 0.45, w);
        int hose = gen_part(c, "hose", GEN_MAT_STEEL);
        double path[3 * 14];
        int n = 0;
        for (int i = 0; i <= 12; i++) { /* hangs in a loose U from the handle to the outlet */
            double a = GEN_PI * i / 12;
            path[3 * n] = -w * 0.3 * sin(a);
            path[3 * n + 1] = d - w * 0.35 - (d - w * 0.35 - 20) * i / 12.0;
            path[3 * n + 2] = 10 + (h * 0.45 - 10) * (0.5 + 0.5 * cos(a));
            n++;
        }
        gen_tube(c, hose, path, n, 7, 8, 0);
    } else if (gen_has(c, "system")) {
        double s = w, yp = 40;
        gen_cylinder(c, metal, 0, yp, h * 0.1, AZ, 14, h * 0.9 - 20, 12);
        gen_cylinder(c, metal, -w / 2 + 10, yp, h * 0.1, AX, 35, w - 20, 20); /* thermostat */
        double arm[6] = {0, yp, h - 20, 0, d - s / 2, h - 20};
        gen_tube(c, metal, arm, 2, 10, 10, 0);
        head(c, metal, 0, d - s / 2, h, s, 14);
        head(c, face, 0, d - s / 2, h - 14, s * 0.92, 1.5);
        gen_cylinder(c, metal, 0, 0, h * 0.85, AY, 25, 8, 16);
    } else if (gen_has(c, "overhead")) {
        double s = w;
        gen_cylinder(c, metal, 0, 0, h / 2, AY, h / 2, 8, 16);
        double arm[9] = {0, 4, h * 0.6, 0, d - s / 2, h * 0.6, 0, d - s / 2, h * 0.35};
        gen_tube(c, metal, arm, 3, 10, 10, 0);
        head(c, metal, 0, d - s / 2, h * 0.4, s, 12);
        head(c, face, 0, d - s / 2, h * 0.4 - 12, s * 0.92, 1.5);
    } else { /* a hand shower on its own */
        hand_shower(c, metal, face, 0, d * 0.55, 0, h, w);
    }
}
