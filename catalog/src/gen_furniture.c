/* Lamps, towel radiators, vanity units and accessories: mostly boxes and tubes. A lamp's
 * diffuser takes the variant (its light colour); a radiator's tubes and a unit's carcass and
 * fronts take the finish; fittings are chrome or brushed steel. */
#include "gen_internal.h"

#include <math.h>

static const double AX[3] = {1, 0, 0}, AY[3] = {0, 1, 0}, AZ[3] = {0, 0, 1};

void gen_lamp(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    int light = gen_part(c, "diffuser", GEN_MAT_FINISH);
    int metal = gen_part(c, "housing", GEN_MAT_CHROME);
    gen_frame f = gen_frame_at(0, d / 2, 0);
    if (gen_has(c, "mirror light")) {
        gen_rbox(c, metal, -w / 2, d * 0.3, h * 0.35, w / 2, d, h, 6);
        gen_box(c, light, -w / 2 + 10, d * 0.4, 0, w / 2 - 10, d * 0.95, h * 0.35);
        gen_box(c, metal, -w * 0.08, 0, h * 0.4, w * 0.08, d * 0.3, h * 0.95);
    } else if (gen_has(c, "ceiling")) {
        double r = w / 2;
        gen_ring g[] = {gen_ring_round(0, 0, 0, 0), gen_ring_round(r * 0.6, r * 0.6, h * 0.08, r),
                        gen_ring_round(r * 0.93, r * 0.93, h * 0.45, r),
                        gen_ring_round(r * 0.97, r * 0.97, h * 0.75, r),
                        gen_ring_round(0, 0, h * 0.75, 0)};
        gen_loft(c, light, &f, g, 5, 6, 0);
        gen_cylinder(c, metal, 0, d / 2, h * 0.75, AZ, r, h * 0.25, 48);
    } else if (gen_has(c, "pendant")) {
        double r = w / 2;
        gen_ellipsoid(c, light, 0, d / 2, r, r, r, r);
        gen_cylinder(c, metal, 0, d / 2, 2 * r - 5, AZ, 2, h - 2 * r - 15, 6);
        gen_cylinder(c, metal, 0, d / 2, h - 25, AZ, r * 0.45, 25, 24);
    } else if (gen_has(c, "downlight")) {
        gen_cylinder(c, light, 0, d / 2, 0, AZ, w * 0.32, 2, 24);
        gen_cylinder(c, metal, 0, d / 2, 1, AZ, w / 2, 4, 32);
        gen_cylinder(c, metal, 0, d / 2, 5, AZ, w * 0.38, h - 5, 24);
    } else if (gen_has(c, "cylinder")) {
        double r = w / 2, y = d - r;
        gen_cylinder(c, metal, 0, y, 3, AZ, r, h - 6, 24);
        gen_cylinder(c, light, 0, y, 0, AZ, r * 0.8, 3, 24);
        gen_cylinder(c, light, 0, y, h - 3, AZ, r * 0.8, 3, 24);
        gen_box(c, metal, -r * 0.5, 0, h * 0.4, r * 0.5, y, h * 0.6);
    } else { /* a wall light with two shades on arms */
        gen_rbox(c, metal, -w / 2, 0, h * 0.3, w / 2, 14, h * 0.7, 4);
        for (int s = -1; s <= 1; s += 2) {
            double x = s * (w / 2 - d * 0.35), r = d * 0.33;
            gen_cylinder(c, metal, x, 10, h / 2, AY, 6, d - r - 10, 8);
            gen_cylinder(c, light, x, d - r, 0, AZ, r, h, 24);
        }
    }
}

void gen_radiator(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    int body = gen_part(c, "radiator", GEN_MAT_FINISH);
    int fix = gen_part(c, "brackets", GEN_MAT_CHROME);
    double rt = 15, y = d - rt;
    for (int s = -1; s <= 1; s += 2) /* wall brackets, top and bottom, on each side */
        for (int e = 0; e < 2; e++)
            gen_cylinder(c, fix, s * (w / 2 - rt), 0, e ? h - 80 : 80, AY, 8, y, 8);
    if (gen_has(c, "flat panel")) {
        gen_rbox(c, body, -w / 2, d * 0.45, 0, w / 2, d, h, 6);
        for (double z = h * 0.1; z < h * 0.95; z += h * 0.1) /* grooves in relief */
            gen_box(c, body, -w / 2 + 20, d - 1, z, w / 2 - 20, d + 1, z + 4);
    } else if (gen_has(c, "designer")) {
        int n = (int)(w / 60);
        n = n < 4 ? 4 : n;
        for (int i = 0; i < n; i++) {
            double x = -w / 2 + rt + (w - 2 * rt) * i / (n - 1);
            gen_cylinder(c, body, x, y, 0, AZ, rt, h, 12);
        }
        gen_cylinder(c, body, -w / 2, y, 40, AX, 12, w, 12);
        gen_cylinder(c, body, -w / 2, y, h - 40, AX, 12, w, 12);
    } else { /* a ladder: two side tubes, rungs in groups with gaps for towels */
        for (int s = -1; s <= 1; s += 2)
            gen_cylinder(c, body, s * (w / 2 - rt), y, 0, AZ, rt, h, 12);
        double step = 32;
        int in_group = 0;
        for (double z = 40; z < h - 30; z += step) {
            gen_cylinder(c, body, -w / 2 + rt, y, z, AX, 10, w - 2 * rt, 10);
            if (++in_group == 6) { /* a gap between groups */
                z += step * 3;
                in_group = 0;
            }
        }
        if (gen_has(c, "electric")) {
            int box = gen_part(c, "heating element", GEN_MAT_BLACK);
            gen_rbox(c, box, w / 2 - rt - 40, y - 30, 0, w / 2 - rt + 5, y + 10, 60, 6);
        }
    }
}

void gen_vanity(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    int carcass = gen_part(c, "carcass", GEN_MAT_FINISH);
    int fronts = gen_part(c, "fronts", GEN_MAT_FINISH);
    int handles = gen_part(c, "handles", GEN_MAT_STEEL);
    if (gen_has(c, "washstand")) { /* a top on a metal frame with a shelf */
        gen_rbox(c, carcass, -w / 2, 0, h - 40, w / 2, d, h, 3);
        gen_box(c, fronts, -w / 2 + 25, 20, 150, w / 2 - 25, d - 20, 175);
        for (int sx = -1; sx <= 1; sx += 2)
            for (int sy = 0; sy < 2; sy++) {
                double x = sx * (w / 2 - 20), yy = sy ? d - 20 : 20;
                gen_box(c, handles, x - 10, yy - 10, 0, x + 10, yy + 10, h - 40);
            }
        gen_cylinder(c, handles, -w / 2 + 10, d - 10, h - 80, AX, 8, w - 20, 12);
        return;
    }
    double ft = 18, hd = 20, body_d = d - ft - hd;
    gen_rbox(c, carcass, -w / 2, 0, 0, w / 2, body_d, h, 2);
    int doors = gen_has(c, "cabinet");
    int n = doors ? 1 : gen_count(c);
    double gap = 3, fh = (h - gap * (n + 1)) / n;
    for (int i = 0; i < n; i++) {
        double z0 = gap + i * (fh + gap);
        gen_rbox(c, fronts, -w / 2 + gap, body_d, z0, w / 2 - gap, body_d + ft, z0 + fh, 2);
        if (doors) { /* a vertical bar on the door's opening side */
            gen_box(c, handles, w / 2 - 50, body_d + ft, z0 + fh * 0.4, w / 2 - 38, d,
                    z0 + fh * 0.4 + (fh * 0.2 < 200 ? fh * 0.2 : 200));
        } else {
            double hw = w * 0.3 < 300 ? w * 0.3 : 300, zt = z0 + fh - 40;
            gen_box(c, handles, -hw / 2, body_d + ft, zt, hw / 2, d, zt + 12);
        }
    }
}

/* A round wall rosette (disc on the wall) at (x, z) and a rod forward to y. */
static void rosette(gen_ctx *c, int part, double x, double z, double r, double y)
{
    gen_cylinder(c, part, x, 0, z, AY, r, 8, 20);
    if (y > 8)
        gen_cylinder(c, part, x, 0, z, AY, r * 0.35, y, 12);
}

void gen_accessory(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    int metal = gen_part(c, "body", GEN_MAT_FINISH);
    if (gen_has(c, "tile trim")) { /* a profile length: the flange under the tile, the edge leg */
        gen_box(c, metal, -w / 2, 0, 0, w / 2, d, 1.0);
        gen_box(c, metal, -w / 2, 0, 0, w / 2, 1.5, h);
        return;
    }
    if (gen_has(c, "seat")) { /* a WC seat with its lid closed: an egg-shaped slab */
        gen_frame f = gen_frame_at(0, 0, 0);
        gen_ring g[] = {{0, 0, 0, {0, 0, 0, 0}, 0, d / 2},
                        {w / 2 - 4, d / 2 - 4, 0, {w / 2, w / 2, 40, 40}, 0, d / 2},
                        {w / 2, d / 2, h * 0.3, {w / 2, w / 2, 40, 40}, 0, d / 2},
                        {w / 2, d / 2, h * 0.75, {w / 2, w / 2, 40, 40}, 0, d / 2},
                        {w / 2 - 8, d / 2 - 8, h, {w / 2, w / 2, 40, 40}, 0, d / 2},
                        {0, 0, h, {0, 0, 0, 0}, 0, d / 2}};
        gen_loft(c, metal, &f, g, 6, 8, 0);
        int hinge = gen_part(c, "hinges", GEN_MAT_CHROME);
        gen_box(c, hinge, -w * 0.3, 0, 0, -w * 0.2, 30, h * 0.6);
        gen_box(c, hinge, w * 0.2, 0, 0, w * 0.3, 30, h * 0.6);
        return;
    }
    if (gen_has(c, "towel bar") || gen_has(c, "grab bar")) {
        double r = h * (gen_has(c, "grab") ? 0.2 : 0.15), z = h / 2, y = d - r;
        for (int s = -1; s <= 1; s += 2)
            rosette(c, metal, s * (w / 2 - h / 2), z, h / 2, y);
        gen_cylinder(c, metal, -w / 2, y, z, AX, r, w, 12);
        return;
    }
    if (gen_has(c, "ring")) {
        double r = 6, R = w / 2 - r, y = d - r, zc = h - 20 - R;
        rosette(c, metal, 0, h - 20, 20, y);
        double path[3 * 40];
        for (int i = 0; i < 40; i++) {
            double a = 2 * GEN_PI * i / 40;
            path[3 * i] = R * cos(a);
            path[3 * i + 1] = y;
            path[3 * i + 2] = zc + R * sin(a);
        }
        gen_tube(c, metal, path, 40, r, 10, 1);
        return;
    }
    if (gen_has(c, "hook")) {
        rosette(c, metal, 0, h / 2, w / 2, 0);
        double path[3 * 10];
        int n = 0;
        for (int i = 0; i <= 8; i++) {
            double a = GEN_PI / 2 * i / 8;
            path[3 * n] = 0;
            path[3 * n + 1] = 8 + (d - 8 - 6) * sin(a);
            path[3 * n + 2] = h / 2 + (h / 2 - 6) * (1 - cos(a));
            n++;
        }
        gen_tube(c, metal, path, n, 6, 10, 0);
        return;
    }
    if (gen_has(c, "spare")) {
        rosette(c, metal, 0, h - w / 2, w / 2, d * 0.5);
        gen_cylinder(c, metal, 0, d * 0.5, 0, AZ, 8, h - w / 2, 10);
        return;
    }
    if (gen_has(c, "roll holder")) {
        double r = h / 2;
        rosette(c, metal, -w / 2 + r, r, r, 0);
        double path[3 * 12];
        int n = 0;
        for (int i = 0; i <= 8; i++) {
            double a = GEN_PI / 2 * i / 8;
            path[3 * n] = -w / 2 + r + (d * 0.6) * (1 - cos(a));
            path[3 * n + 1] = 8 + (d * 0.6) * sin(a);
            path[3 * n + 2] = r;
            n++;
        }
        path[3 * n] = w / 2 - 6, path[3 * n + 1] = 8 + d * 0.6, path[3 * n + 2] = r, n++;
        gen_tube(c, metal, path, n, 6, 10, 0);
        return;
    }
    if (gen_has(c, "basket")) { /* a corner basket: a quarter-round tray of glass on metal */
        gen_frame f = gen_frame_at(0, 0, 0);
        double hx = w / 2, hy = d / 2, R = w * 0.9;
        gen_ring g[] = {{0, 0, 0, {0}, 0, hy},
                        {hx, hy, 0, {R, 2, 2, 2}, 0, hy},
                        {hx, hy, h, {R, 2, 2, 2}, 0, hy},
                        {hx - 6, hy - 6, h, {R - 6, 2, 2, 2}, 0, hy},
                        {hx - 6, hy - 6, 6, {R - 6, 2, 2, 2}, 0, hy},
                        {0, 0, 6, {0}, 0, hy}};
        gen_loft(c, metal, &f, g, 6, 6, 0);
        return;
    }
    int glass = gen_part(c, "glass", GEN_MAT_GLASS);
    if (gen_has(c, "shelf")) {
        gen_box(c, glass, -w / 2, 10, h - 10, w / 2, d, h);
        for (int s = -1; s <= 1; s += 2)
            gen_box(c, metal, s * (w / 2 - 60) - 12, 0, 0, s * (w / 2 - 60) + 12, d * 0.6, h - 10);
        return;
    }
    /* Holders with a glass or a brush: soap dispenser, tumbler, WC brush set. */
    double r = w / 2, y = d - r;
    int brush = gen_has(c, "WC brush");
    double cup = brush ? h * 0.4 : gen_has(c, "dispenser") ? h * 0.8 : h;
    gen_rbox(c, metal, -r * 0.5, 0, cup * 0.4, r * 0.5, 8, cup * 0.9, 3);
    gen_cylinder(c, metal, 0, 4, cup * 0.6, AY, 8, y - r * 0.9, 8);
    gen_cylinder(c, metal, 0, y, cup * 0.2, AZ, r, cup * 0.1, 20); /* the ring holding it */
    if (gen_has(c, "tumbler")) { /* an open cup: out, up, over the lip and down inside */
        gen_frame f = gen_frame_at(0, y, 0);
        double ro = r * 0.92, ri = ro - 3;
        gen_ring g[] = {gen_ring_round(0, 0, 0, 0),      gen_ring_round(ro, ro, 0, ro),
                        gen_ring_round(ro, ro, cup, ro), gen_ring_round(ri, ri, cup, ri),
                        gen_ring_round(ri, ri, 6, ri),   gen_ring_round(0, 0, 6, 0)};
        gen_loft(c, glass, &f, g, 6, 6, 0);
    } else {
        gen_cylinder(c, glass, 0, y, 0, AZ, r * 0.92, cup, 24);
    }
    if (brush) {
        gen_cylinder(c, metal, 0, y, cup, AZ, r * 0.95, 6, 20); /* the lid */
        gen_cylinder(c, metal, 0, y, cup, AZ, 7, h - cup, 10);
    } else if (gen_has(c, "dispenser")) {
        gen_cylinder(c, metal, 0, y, cup, AZ, r * 0.3, h - cup - 8, 12);
        gen_rbox(c, metal, -8, y - 8, h - 14, 8, d, h, 3);
    }
}
