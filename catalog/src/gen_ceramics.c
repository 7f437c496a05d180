/* Ceramic and acrylic shapes: basins, WCs and bidets, baths, shower trays. Each is a coarse
 * cage of rounded-rectangle rings (a profile that runs up the outside, over the rim and down
 * into the bowl, so one closed surface) smoothed by two Catmull-Clark steps (OpenMesh,
 * mesh_subdivide.cpp). Subdivision pulls the surface inside its cage; gen_finish() then scales
 * the result to the row's exact size. Back corners get small radii: the back face goes against
 * the wall (y = 0). */
#include "gen_internal.h"

#include <math.h>

static const double AZ[3] = {0, 0, 1};

/* A ring centred at (0, cy) with back corners (2, 3) of radius rb and front ones of rf. */
static gen_ring ring(double hx, double hy, double cy, double z, double rf, double rb)
{
    gen_ring g = {hx, hy, z, {rf, rf, rb, rb}, 0, cy};
    return g;
}

static gen_ring pole(double cy, double z)
{
    gen_ring g = {0, 0, z, {0, 0, 0, 0}, 0, cy};
    return g;
}

void gen_basin(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    int part = gen_part(c, "ceramic", GEN_MAT_FINISH);
    int waste = gen_part(c, "waste", GEN_MAT_CHROME);
    gen_frame f = gen_frame_at(0, 0, 0);
    double hx = w / 2, hy = d / 2, rim = d * 0.09 > 25 ? d * 0.09 : 25;
    double inner_bottom = h * 0.28;
    if (gen_has(c, "bowl")) { /* a countertop bowl: round or oval, thin walls all round */
        double r = hx < hy ? hx : hy, t = 12;
        gen_ring g[] = {pole(hy, 0),
                        ring(hx * 0.55, hy * 0.55, hy, 0, r * 0.55, r * 0.55),
                        ring(hx * 0.9, hy * 0.9, hy, h * 0.45, r * 0.9, r * 0.9),
                        ring(hx, hy, hy, h, r, r),
                        ring(hx - t, hy - t, hy, h, r - t, r - t),
                        ring(hx * 0.85 - t, hy * 0.85 - t, hy, h * 0.5, r * 0.85 - t, r * 0.85 - t),
                        ring(hx * 0.4, hy * 0.4, hy, inner_bottom * 0.5, r * 0.4, r * 0.4),
                        pole(hy, inner_bottom * 0.5)};
        gen_loft(c, part, &f, g, (int)(sizeof g / sizeof g[0]), 2, 2);
        gen_cylinder(c, waste, 0, hy, inner_bottom * 0.5 + 1, AZ, 20, 2, 16);
        return;
    }
    /* A wall or furniture basin: a slab with a rim and a bowl underneath. */
    double rf = gen_has(c, "hand") || gen_has(c, "semi") ? hx * 0.45 : 40;
    double bx = hx - rim * 1.6, by = hy - rim * 1.3, bcy = hy + rim * 0.2;
    gen_ring g[] = {pole(bcy, h * 0.05),
                    ring(bx * 0.6, by * 0.55, bcy, h * 0.05, bx * 0.4, bx * 0.3),
                    ring(bx * 0.95, by * 0.9, bcy, h * 0.45, rf, 30),
                    ring(hx, hy, hy, h * 0.62, rf, 8),
                    ring(hx, hy, hy, h, rf, 8),
                    ring(hx - rim * 0.5, hy - rim * 0.5, hy, h, rf - rim * 0.5, 6),
                    ring(bx, by, bcy, h * 0.98, rf * 0.9, 25),
                    ring(bx * 0.9, by * 0.85, bcy, h * 0.55, rf * 0.8, 40),
                    ring(bx * 0.45, by * 0.4, bcy, inner_bottom, bx * 0.3, bx * 0.3),
                    pole(bcy, inner_bottom)};
    gen_loft(c, part, &f, g, (int)(sizeof g / sizeof g[0]), 2, 2);
    if (gen_has(c, "double")) { /* a trough with two wastes and two tap holes */
        gen_cylinder(c, waste, -w / 4, bcy, inner_bottom + 4, AZ, 20, 2, 16);
        gen_cylinder(c, waste, w / 4, bcy, inner_bottom + 4, AZ, 20, 2, 16);
    } else {
        gen_cylinder(c, waste, 0, bcy, inner_bottom + 4, AZ, 20, 2, 16);
    }
}

void gen_wc(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    int part = gen_part(c, "ceramic", GEN_MAT_FINISH);
    int bidet = gen_has(c, "bidet");
    int coupled = gen_has(c, "close-coupled");
    int floor = coupled || gen_has(c, "back-to-wall") || gen_has(c, "floor");
    double hb = coupled ? h * 0.52 : h; /* the bowl's height */
    double hx = w / 2, hy = d / 2;
    gen_frame f = gen_frame_at(0, 0, 0);
    /* Every ring touches the wall (cy = hy'), so the back is flat and flush; the front corners
     * are round (an egg seen from above). */
    double inner = hb * (bidet ? 0.55 : 0.35);
    gen_ring g[] = {pole(hy * 0.8, 0),
                    floor ? ring(hx * 0.7, hy * 0.8, hy * 0.8, 0, hx * 0.7, 30)
                          : ring(hx * 0.55, hy * 0.55, hy * 0.55, 0, hx * 0.5, 20),
                    floor ? ring(hx * 0.6, hy * 0.8, hy * 0.8, hb * 0.3, hx * 0.6, 30)
                          : ring(hx * 0.8, hy * 0.8, hy * 0.8, hb * 0.35, hx * 0.75, 25),
                    ring(hx, hy, hy, hb * 0.85, hx, 25),
                    ring(hx, hy, hy, hb, hx, 20),
                    ring(hx * 0.72, hy * 0.72, hy * 1.1, hb, hx * 0.72, 40),
                    ring(hx * 0.6, hy * 0.55, hy * 1.15, hb * 0.75, hx * 0.6, 50),
                    ring(hx * 0.2, hy * 0.18, hy * 1.2, inner, hx * 0.2, hx * 0.2),
                    pole(hy * 1.2, inner)};
    gen_loft(c, part, &f, g, (int)(sizeof g / sizeof g[0]), 2, 2);
    if (!bidet) { /* the seat and lid, closed, in white */
        int seat = gen_part(c, "seat", GEN_MAT_CERAMIC);
        double t = hb * 0.06;
        gen_ring s[] = {pole(hy * 1.02, hb),
                        ring(hx * 0.95, hy * 0.93, hy * 1.02, hb, hx * 0.95, 25),
                        ring(hx * 0.98, hy * 0.96, hy * 1.02, hb + t * 0.3, hx * 0.98, 25),
                        ring(hx * 0.98, hy * 0.96, hy * 1.02, hb + t * 0.7, hx * 0.98, 25),
                        ring(hx * 0.95, hy * 0.93, hy * 1.02, hb + t, hx * 0.95, 25),
                        pole(hy * 1.02, hb + t)};
        gen_loft(c, seat, &f, s, 6, 8, 0);
    }
    if (coupled) { /* the cistern on the bowl's back, with a chrome flush button */
        int button = gen_part(c, "flush button", GEN_MAT_CHROME);
        double top = h - 6;
        gen_rbox(c, part, -hx * 0.98, 0, hb * 0.98, hx * 0.98, d * 0.3, top, 25);
        gen_cylinder(c, button, 0, d * 0.15, top, AZ, 22, 6, 16);
    }
}

void gen_bath(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    int part = gen_part(c, "bath", GEN_MAT_FINISH);
    int waste = gen_part(c, "overflow", GEN_MAT_CHROME);
    gen_frame f = gen_frame_at(0, 0, 0);
    double hx = w / 2, hy = d / 2, rim = gen_has(c, "steel") ? 35 : 60;
    int free = gen_has(c, "freestanding");
    double ro = free ? (gen_has(c, "oval") ? hy : hy * 0.6) : 20; /* outer corner radius */
    double ri = free ? ro - rim : 160;                            /* inner */
    /* corner baths: the front corner (+x, +y) is a big quarter arc, the others square */
    int corner = gen_has(c, "corner");
    double big = corner ? (hx < hy ? hx : hy) * 1.3 : ro;
    gen_ring o_low = {hx * (free ? 0.8 : 1), hy * (free ? 0.75 : 1), 0, {big, ro, ro, ro}, 0, hy};
    gen_ring o_top = {hx, hy, h, {big, ro, ro, ro}, 0, hy};
    gen_ring o_rim = {hx - rim * 0.4, hy - rim * 0.4, h, {big, ro, ro, ro}, 0, hy};
    double ib = corner ? big - rim : ri;
    gen_ring i_top = {hx - rim, hy - rim, h * 0.98, {ib, ri, ri, ri}, 0, hy};
    gen_ring i_mid = {
        hx - rim - 60, hy - rim - 30, h * 0.45, {ib, ri + 40, ri + 40, ri + 40}, 0, hy};
    gen_ring i_low = {hx * 0.6, hy * 0.45, h * 0.1, {ib * 0.6, ri, ri, ri}, 0, hy};
    gen_ring g[] = {pole(hy, 0), o_low, {o_low.hx, o_low.hy, h * 0.5, {big, ro, ro, ro}, 0, hy},
                    o_top,       o_rim, i_top,
                    i_mid,       i_low, pole(hy, h * 0.1)};
    if (free) { /* the freestanding shell bulges out toward the rim */
        g[2].hx = hx * 0.97;
        g[2].hy = hy * 0.95;
    }
    gen_loft(c, part, &f, g, (int)(sizeof g / sizeof g[0]), 2, 2);
    double ex = corner ? -hx * 0.3 : -hx + rim + 60;
    gen_cylinder(c, waste, ex, hy, h * 0.13, AZ, 25, 3, 16);
}

void gen_tray(gen_ctx *c)
{
    double w = c->req->width_mm, d = c->req->depth_mm, h = c->req->height_mm;
    int part = gen_part(c, "tray", GEN_MAT_FINISH);
    int drain = gen_part(c, "drain cover", GEN_MAT_CHROME);
    gen_frame f = gen_frame_at(0, 0, 0);
    double hx = w / 2, hy = d / 2;
    double rq = gen_has(c, "quadrant") ? 550 : 4;
    double rf = rq > 4 ? rq : 4;
    double dy = d / 2, dz = h * 0.75;
    gen_ring g[] = {
        pole(hy, 0),
        {hx, hy, 0, {rf, 4, 4, 4}, 0, hy},
        {hx, hy, h - 2, {rf, 4, 4, 4}, 0, hy},
        {hx - 2, hy - 2, h, {rf - 2, 2, 2, 2}, 0, hy},
        {hx - 30, hy - 30, h, {rf > 30 ? rf - 30 : 2, 2, 2, 2}, 0, hy},
        {hx - 40, hy - 40, h * 0.92, {rf > 40 ? rf - 40 : 8, 8, 8, 8}, 0, hy},
        gen_ring_round(60, 60, dz, 60),
        gen_ring_round(0, 0, dz, 0),
    };
    g[6].cy = g[7].cy = dy;
    gen_loft(c, part, &f, g, 8, rq > 4 ? 10 : 3, 0);
    gen_cylinder(c, drain, 0, dy, dz, AZ, 55, 1.5, 24);
}
