/* Consumables and labour of a tiled project (app/design/quantities.h, docs/tiling.md
 * "Consumables and labour"): tile adhesive from the tiled area and a rate by tile size, grout from
 * the joint volume, silicone from the edge-joint metres, waterproofing of the shower zones, and
 * the areas and pieces the labour lines bill. The rates are DOMAIN.md's ("Setting out tiles",
 * consumables); the sources of each are named where they are used. */
#include "app/design/placement.h"
#include "app/design/quantities.h"
#include "app/design/room_surfaces.h"
#include "quantities_internal.h"
#include "tile_layout_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static app_product_ref ref(const char *manufacturer, const char *article)
{
    app_product_ref r;
    memset(&r, 0, sizeof r);
    snprintf(r.manufacturer, sizeof r.manufacturer, "%s", manufacturer);
    snprintf(r.article, sizeof r.article, "%s", article);
    return r;
}

app_consumable_rules app_consumable_rules_default(void)
{
    app_consumable_rules r;
    memset(&r, 0, sizeof r);
    /* The shipped items: assets/catalog/consumables.csv. */
    r.adhesive = ref("Fugenwerk", "FW-C2-25");
    r.grout = ref("Fugenwerk", "FW-CG2-5");
    r.silicone = ref("Fugenwerk", "FW-SIL-310");
    r.waterproofing = ref("Fugenwerk", "FW-DS-M2");
    r.labour_floor = ref("Tessera Services", "LAB-TILE-FLOOR");
    r.labour_wall = ref("Tessera Services", "LAB-TILE-WALL");
    r.labour_fixture = ref("Tessera Services", "LAB-FIXTURE");
    r.adhesive_bag_kg = 25.0;
    r.grout_bag_kg = 5.0;
    /* DOMAIN.md: grout kg = joint volume (dm3) x 1.6 kg/dm3. */
    r.grout_density_kg_dm3 = 1.6;
    r.grout_depth_mm = 8.0;
    r.silicone_cartridge_ml = 310.0;
    /* IVD leaflet 3 (elastic joints): a joint up to about 10 mm wide is filled about as deep as
     * it is wide; a bead narrower than 5 mm does not hold, so a 2-3 mm edge gap is sealed as a
     * 5 x 5 mm bead: 25 mm2, 12.4 m per 310 ml cartridge (DOMAIN.md: 8-12 m a cartridge). */
    r.silicone_min_width_mm = 5.0;
    /* DIN 18534-1 practice: the walls of a shower area are sealed to at least 200 mm above the
     * shower outlet, in practice to 2.0 m. */
    r.shower_wall_mm = 2000.0;
    return r;
}

double app_adhesive_kg_per_m2(double w_mm, double h_mm)
{
    double longest = fmax(w_mm, h_mm), area_m2 = w_mm * h_mm * 1e-6;
    if (longest <= 150.0)
        return 2.5;
    if (longest <= 300.0)
        return 3.0;
    if (area_m2 < 0.25) /* DOMAIN.md "Typical sizes": large format is 0.25 m2 and up */
        return 4.0;
    return 5.0;
}

static int is_floor(const char *surface)
{
    return !strncmp(surface, "floor", 5);
}

/* ---- joints between tiles ------------------------------------------------------------------- */

static int inside_convex(const app_tile_layout *L, const app_tile_piece *pc, double x, double y)
{
    for (int i = 0; i < pc->count; i++) {
        app_point2 a = L->points[pc->first + i], b = L->points[pc->first + (i + 1) % pc->count];
        if ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x) < 0)
            return 0;
    }
    return 1;
}

/* The length of the grouted joints of a layout: half the length of the uncut tile edges that
 * another tile faces across one joint width (each joint has a tile on either side). Edges that
 * face the region's boundary border the edge joint (silicone), and cut edges lie on it. Tiles
 * are found through a grid of their centres (cells as large as the largest tile). */
static double joint_length_mm(const app_tile_layout *L)
{
    if (L->tile_count == 0 || !(L->grout_mm > 0))
        return 0;
    double cell = 0, x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (int i = 0; i < L->tile_count; i++) {
        const app_placed_tile *t = &L->tiles[i];
        for (int k = 0; k < 4; k++)
            cell = fmax(cell, hypot(t->cell[k].x - t->centre.x, t->cell[k].y - t->centre.y));
        x0 = fmin(x0, t->centre.x), y0 = fmin(y0, t->centre.y);
        x1 = fmax(x1, t->centre.x), y1 = fmax(y1, t->centre.y);
    }
    cell = 2 * cell + L->grout_mm;
    long nx = (long)((x1 - x0) / cell) + 1, ny = (long)((y1 - y0) / cell) + 1;
    if (nx * ny > 4L * L->tile_count + 64)
        return 0; /* a degenerate spread: no sensible grid */
    int *head = malloc(sizeof *head * (size_t)(nx * ny)),
        *next = malloc(sizeof *next * (size_t)L->tile_count);
    if (!head || !next) {
        free(head);
        free(next);
        return 0;
    }
    for (long i = 0; i < nx * ny; i++)
        head[i] = -1;
    for (int i = 0; i < L->tile_count; i++) {
        long cx = (long)((L->tiles[i].centre.x - x0) / cell);
        long cy = (long)((L->tiles[i].centre.y - y0) / cell);
        next[i] = head[cy * nx + cx];
        head[cy * nx + cx] = i;
    }
    double facing = 0, step = L->grout_mm + 0.25;
    for (int i = 0; i < L->tile_count; i++) {
        const app_placed_tile *t = &L->tiles[i];
        long cx = (long)((t->centre.x - x0) / cell), cy = (long)((t->centre.y - y0) / cell);
        for (int p = t->first_piece; p < t->first_piece + t->piece_count; p++) {
            const app_tile_piece *pc = &L->pieces[p];
            for (int e = 0; e < pc->count; e++) {
                if (L->edges[pc->first + e] != APP_EDGE_TILE)
                    continue;
                app_point2 a = L->points[pc->first + e];
                app_point2 b = L->points[pc->first + (e + 1) % pc->count];
                double len = hypot(b.x - a.x, b.y - a.y);
                if (len < 1e-9)
                    continue;
                /* across the joint: the outward normal of a counter-clockwise piece */
                double mx = 0.5 * (a.x + b.x) + step * (b.y - a.y) / len;
                double my = 0.5 * (a.y + b.y) - step * (b.x - a.x) / len;
                int found = 0;
                for (long gy = cy - 1; gy <= cy + 1 && !found; gy++)
                    for (long gx = cx - 1; gx <= cx + 1 && !found; gx++) {
                        if (gx < 0 || gy < 0 || gx >= nx || gy >= ny)
                            continue;
                        for (int j = head[gy * nx + gx]; j >= 0 && !found; j = next[j]) {
                            if (j == i)
                                continue;
                            const app_placed_tile *u = &L->tiles[j];
                            for (int q = u->first_piece;
                                 q < u->first_piece + u->piece_count && !found; q++)
                                found = inside_convex(L, &L->pieces[q], mx, my);
                        }
                    }
                if (found)
                    facing += len;
            }
        }
    }
    free(head);
    free(next);
    return 0.5 * facing;
}

/* ---- edge joints ---------------------------------------------------------------------------- */

typedef struct seg3 {
    double a[3], b[3];
    int layout;
} seg3;

typedef struct seg_list {
    seg3 *s;
    int n, cap;
} seg_list;

static int push_seg(seg_list *l, const double a[3], const double b[3], int layout)
{
    if (l->n == l->cap) {
        int nc = l->cap ? 2 * l->cap : 64;
        seg3 *g = realloc(l->s, sizeof *g * (size_t)nc);
        if (!g)
            return 0;
        l->s = g;
        l->cap = nc;
    }
    seg3 *s = &l->s[l->n++];
    memcpy(s->a, a, sizeof s->a);
    memcpy(s->b, b, sizeof s->b);
    s->layout = layout;
    return 1;
}

/* The part of edge p-q (surface coordinates) inside the band t0 <= t <= t1, into world space. */
static int add_ring(seg_list *l, const app_surface_frame *f, const app_polygon *ring, double t0,
                    double t1, int layout)
{
    for (int i = 0; i < ring->count; i++) {
        app_point2 p = ring->points[i], q = ring->points[(i + 1) % ring->count];
        double u0 = 0, u1 = 1, dt = q.y - p.y;
        if (fabs(dt) < 1e-12) {
            if (p.y < t0 - 1e-6 || p.y > t1 + 1e-6)
                continue;
        } else {
            double a = (t0 - p.y) / dt, b = (t1 - p.y) / dt;
            u0 = fmax(u0, fmin(a, b));
            u1 = fmin(u1, fmax(a, b));
            if (u1 <= u0)
                continue;
        }
        double a3[3], b3[3];
        app_surface_frame_point(f, p.x + u0 * (q.x - p.x), p.y + u0 * dt, a3);
        app_surface_frame_point(f, p.x + u1 * (q.x - p.x), p.y + u1 * dt, b3);
        if (!push_seg(l, a3, b3, layout))
            return 0;
    }
    return 1;
}

/* Whether segment s runs through point m (within 0.5 mm) in direction d (unit). */
static int covers(const seg3 *s, const double m[3], const double d[3])
{
    double e[3], w[3], len2 = 0, t = 0;
    for (int k = 0; k < 3; k++) {
        e[k] = s->b[k] - s->a[k];
        w[k] = m[k] - s->a[k];
        len2 += e[k] * e[k];
        t += w[k] * e[k];
    }
    if (len2 <= 0)
        return 0;
    double len = sqrt(len2), dot = 0, dist2 = 0;
    for (int k = 0; k < 3; k++)
        dot += d[k] * e[k] / len;
    if (fabs(dot) < 0.999)
        return 0;
    t /= len2;
    if (t < -1e-9 || t > 1 + 1e-9)
        return 0;
    for (int k = 0; k < 3; k++) {
        double x = w[k] - t * e[k];
        dist2 += x * x;
    }
    return dist2 < 0.25;
}

/* Whether segment i is a boundary of its region at m: no other segment of the same region runs
 * there too (a hole touching the outline). */
static int boundary_at(const seg_list *l, int i, const double m[3], const double d[3])
{
    for (int k = 0; k < l->n; k++)
        if (k != i && l->s[k].layout == l->s[i].layout && covers(&l->s[k], m, d))
            return 0;
    return 1;
}

/* The length of the union of the boundaries: each segment is split where collinear segments
 * start or end; a piece that an outline and a hole of the same region both run along (a hole
 * touching the outline: a fixture standing against the wall) is no boundary of that region, and
 * a piece counted for one surface is not counted again for another (the floor-wall junction). */
static double union_length(const seg_list *l)
{
    double total = 0;
    /* The pairwise splitting is cubic in the worst case: a region traced with thousands of
     * points (a curved outline) is summed without merging shared stretches. */
    if (l->n > 4000) {
        for (int i = 0; i < l->n; i++)
            total += hypot(hypot(l->s[i].b[0] - l->s[i].a[0], l->s[i].b[1] - l->s[i].a[1]),
                           l->s[i].b[2] - l->s[i].a[2]);
        return total;
    }
    double *cuts = malloc(sizeof *cuts * (size_t)(2 * l->n + 2));
    if (!cuts)
        return 0;
    for (int i = 0; i < l->n; i++) {
        const seg3 *s = &l->s[i];
        double d[3], len = 0;
        for (int k = 0; k < 3; k++) {
            d[k] = s->b[k] - s->a[k];
            len += d[k] * d[k];
        }
        len = sqrt(len);
        if (len < 1e-6)
            continue;
        for (int k = 0; k < 3; k++)
            d[k] /= len;
        int nc = 0;
        cuts[nc++] = 0;
        cuts[nc++] = len;
        for (int j = 0; j < l->n; j++) {
            if (j == i)
                continue;
            const double *ends[2] = {l->s[j].a, l->s[j].b};
            for (int e = 0; e < 2; e++) {
                if (!covers(s, ends[e], d))
                    continue;
                double u = 0;
                for (int k = 0; k < 3; k++)
                    u += (ends[e][k] - s->a[k]) * d[k];
                if (u > 1e-6 && u < len - 1e-6)
                    cuts[nc++] = u;
            }
        }
        /* insertion sort: a handful of cuts */
        for (int a = 1; a < nc; a++)
            for (int b = a; b > 0 && cuts[b - 1] > cuts[b]; b--) {
                double t = cuts[b];
                cuts[b] = cuts[b - 1];
                cuts[b - 1] = t;
            }
        for (int c = 0; c + 1 < nc; c++) {
            double u0 = cuts[c], u1 = cuts[c + 1];
            if (u1 - u0 < 1e-6)
                continue;
            double m[3];
            for (int k = 0; k < 3; k++)
                m[k] = s->a[k] + 0.5 * (u0 + u1) * d[k];
            if (!boundary_at(l, i, m, d))
                continue;
            int counted = 0;
            for (int j = 0; j < i && !counted; j++)
                counted = covers(&l->s[j], m, d) && boundary_at(l, j, m, d);
            if (counted)
                continue;
            total += u1 - u0;
        }
    }
    free(cuts);
    return total;
}

static app_result edge_joints(const app_project *p, const app_fixture_box *boxes, int nbox,
                              const app_tile_layout *layouts, int n, double *metres, char *err,
                              size_t err_size)
{
    seg_list l = {0};
    app_result r = APP_OK;
    for (int i = 0; i < n && i < p->tiling_count && r == APP_OK; i++) {
        const app_tiling *t = &p->tilings[i];
        app_surface_region reg;
        app_surface_frame f;
        memset(&reg, 0, sizeof reg);
        r = app_room_surface_region(p, layouts[i].surface, boxes, nbox, &reg, &f, err, err_size);
        if (r != APP_OK)
            break;
        /* room.h: a wall tiling may cover a band from_mm..to_mm (to 0 = up to the ceiling). */
        double t0 = -1e300, t1 = 1e300;
        if (!strncmp(t->surface, "wall:", 5)) {
            t0 = t->from_mm > 0 ? t->from_mm : -1e300;
            t1 = t->to_mm > 0 ? t->to_mm : 1e300;
        }
        int ok = add_ring(&l, &f, &reg.outer, t0, t1, i);
        for (int h = 0; ok && h < reg.hole_count; h++)
            ok = add_ring(&l, &f, &reg.holes[h].polygon, t0, t1, i);
        app_surface_region_free(&reg);
        if (!ok) {
            tl_set_err(err, err_size, "quantities", "out of memory");
            r = APP_ERR_OUT_OF_MEMORY;
        }
    }
    *metres = r == APP_OK ? union_length(&l) * 1e-3 : 0;
    free(l.s);
    return r;
}

/* ---- shower zones --------------------------------------------------------------------------- */

/* The walls a tray stands against (its box within APP_FIXTURE_WALL_GAP_MM of the wall's face)
 * get the overlap along the wall times the sealed height. */
static app_result shower_walls(const app_project *p, const app_fixture_box *b, double height_mm,
                               double *m2, char *err, size_t err_size)
{
    app_surface_frame *frames = NULL;
    int nf = 0;
    app_result r = app_room_surface_list(p, &frames, &nf, err, err_size);
    for (int i = 0; r == APP_OK && i < nf; i++) {
        if (strncmp(frames[i].surface, "wall:", 5))
            continue;
        app_surface_region reg;
        app_surface_frame f;
        memset(&reg, 0, sizeof reg);
        r = app_room_surface_region(p, frames[i].surface, NULL, 0, &reg, &f, err, err_size);
        if (r != APP_OK)
            break;
        double s_lo = 1e300, s_hi = -1e300, t_hi = 0;
        for (int k = 0; k < reg.outer.count; k++) {
            s_lo = fmin(s_lo, reg.outer.points[k].x);
            s_hi = fmax(s_hi, reg.outer.points[k].x);
            t_hi = fmax(t_hi, reg.outer.points[k].y);
        }
        app_surface_region_free(&reg);
        double d_min = 1e300, bs_lo = 1e300, bs_hi = -1e300;
        for (int c = 0; c < 4; c++) {
            double x = (c & 1) ? b->max_mm[0] : b->min_mm[0];
            double y = (c & 2) ? b->max_mm[1] : b->min_mm[1];
            double w[3] = {x - f.origin_mm[0], y - f.origin_mm[1], b->min_mm[2] - f.origin_mm[2]};
            double d = w[0] * f.normal[0] + w[1] * f.normal[1] + w[2] * f.normal[2];
            double s = w[0] * f.s_axis[0] + w[1] * f.s_axis[1] + w[2] * f.s_axis[2];
            d_min = fmin(d_min, d);
            bs_lo = fmin(bs_lo, s);
            bs_hi = fmax(bs_hi, s);
        }
        double along = fmin(bs_hi, s_hi) - fmax(bs_lo, s_lo);
        if (d_min > APP_FIXTURE_WALL_GAP_MM || d_min < -APP_FIXTURE_WALL_GAP_MM || along <= 0)
            continue;
        *m2 += along * fmin(height_mm, t_hi) * 1e-6;
    }
    free(frames);
    return r;
}

/* ---- the amounts ---------------------------------------------------------------------------- */

static double tile_thickness(cat_db *db, const app_product_ref *r, double fallback)
{
    cat_product prod;
    char cerr[256];
    if (!db ||
        cat_product_find(db, r->manufacturer, r->article, &prod, cerr, sizeof cerr) != CAT_DB_OK)
        return fallback;
    double t = prod.has_tile && prod.tile.thickness_mm > 0 ? prod.tile.thickness_mm : fallback;
    cat_product_free(&prod);
    return t;
}

static int whole_units(double amount, double unit)
{
    return unit > 0 && amount > 0 ? (int)ceil(amount / unit - 1e-9) : 0;
}

app_result app_consumables_compute(const app_project *p, cat_db *db, const app_tile_layout *layouts,
                                   int n, const app_consumable_rules *rules, app_consumables *out,
                                   char *err, size_t err_size)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!p || !out || n < 0 || (n > 0 && !layouts)) {
        tl_set_err(err, err_size, "quantities", "no project or layouts");
        return APP_ERR_SCHEMA;
    }
    app_consumable_rules r = rules ? *rules : app_consumable_rules_default();
    for (int i = 0; i < n; i++) {
        const app_tile_layout *L = &layouts[i];
        double region_m2 = L->region_area_mm2 * 1e-6;
        if (is_floor(L->surface))
            out->floor_m2 += region_m2;
        else
            out->wall_m2 += region_m2;
        const app_tile_spec *field = L->spec_count > 0 ? &L->specs[0] : NULL;
        if (field)
            out->adhesive_kg +=
                region_m2 * app_adhesive_kg_per_m2(field->work_w_mm, field->work_h_mm);
        /* DOMAIN.md: joint volume = length x width x depth, the joint filled over the tile's
         * thickness; 1e6 mm3 a dm3. */
        double depth =
            field ? tile_thickness(db, &field->product, r.grout_depth_mm) : r.grout_depth_mm;
        double joint_mm = joint_length_mm(L);
        out->joint_length_m += joint_mm * 1e-3;
        out->grout_dm3 += joint_mm * L->grout_mm * depth * 1e-6;
    }
    out->grout_kg = out->grout_dm3 * r.grout_density_kg_dm3;
    out->adhesive_bags = whole_units(out->adhesive_kg, r.adhesive_bag_kg);
    out->grout_bags = whole_units(out->grout_kg, r.grout_bag_kg);

    app_fixture_box *boxes = NULL;
    int nbox = 0;
    app_result res = APP_OK;
    if (db && p->object_count > 0)
        res = app_room_fixture_boxes(p, app_placement_catalog_lookup, db, &boxes, &nbox, err,
                                     err_size);
    if (res == APP_OK && n > 0)
        res = edge_joints(p, boxes, nbox, layouts, n, &out->edge_joint_m, err, err_size);
    if (res == APP_OK) {
        double w = fmax(r.silicone_min_width_mm, 0.0);
        for (int i = 0; i < n && i < p->tiling_count; i++)
            w = fmax(w, app_tile_edge_joint_mm(&p->tilings[i], layouts[i].grout_mm));
        /* metres x mm2 = 1e3 mm3 = 1 ml */
        out->silicone_ml = out->edge_joint_m * w * w;
        out->silicone_cartridges = whole_units(out->silicone_ml, r.silicone_cartridge_ml);
    }
    for (int i = 0; res == APP_OK && i < p->object_count; i++) {
        const app_object *o = &p->objects[i];
        if (!o->has_product)
            continue;
        out->fixtures++;
        app_product_info info;
        char lerr[256];
        if (!db ||
            app_placement_catalog_lookup(db, &o->product, &info, lerr, sizeof lerr) != APP_OK ||
            info.category != CAT_CATEGORY_SHOWER_TRAYS)
            continue;
        app_fixture_box b;
        if (!app_room_fixture_box(o, &info, &b))
            continue;
        out->shower_zones++;
        out->waterproofing_m2 += (b.max_mm[0] - b.min_mm[0]) * (b.max_mm[1] - b.min_mm[1]) * 1e-6;
        res = shower_walls(p, &b, r.shower_wall_mm, &out->waterproofing_m2, err, err_size);
    }
    free(boxes);
    if (res != APP_OK)
        memset(out, 0, sizeof *out);
    return res;
}

/* ---- the bill's lines ------------------------------------------------------------------------ */

/* Areas billed to the next 0.01 m2 up. */
static double billed_m2(double m2)
{
    return ceil(m2 * 100.0 - 1e-6) / 100.0;
}

app_result app_bom_add_consumables(cat_db *db, const app_consumables *c,
                                   const app_consumable_rules *rules, app_bom *b, char *err,
                                   size_t err_size)
{
    if (!c || !b) {
        tl_set_err(err, err_size, "quantities", "no consumables or bill of materials");
        return APP_ERR_SCHEMA;
    }
    app_consumable_rules r = rules ? *rules : app_consumable_rules_default();
    int cap = b->line_count; /* the array holds exactly line_count lines or more */
    char d[96];
    app_result res = APP_OK;
    snprintf(d, sizeof d, "%.1f kg for %.2f m2 = %d bag%s of %g kg", c->adhesive_kg,
             c->floor_m2 + c->wall_m2, c->adhesive_bags, c->adhesive_bags == 1 ? "" : "s",
             r.adhesive_bag_kg);
    res = qty_bom_add_priced(db, b, &cap, &r.adhesive, APP_BOM_CONSUMABLE, c->adhesive_bags, d, err,
                             err_size);
    if (res == APP_OK) {
        snprintf(d, sizeof d, "%.2f kg (%.2f dm3 of joint, %.1f m) = %d bag%s of %g kg",
                 c->grout_kg, c->grout_dm3, c->joint_length_m, c->grout_bags,
                 c->grout_bags == 1 ? "" : "s", r.grout_bag_kg);
        res = qty_bom_add_priced(db, b, &cap, &r.grout, APP_BOM_CONSUMABLE, c->grout_bags, d, err,
                                 err_size);
    }
    if (res == APP_OK) {
        snprintf(d, sizeof d, "%.1f m of edge joint, %.0f ml = %d x %g ml", c->edge_joint_m,
                 c->silicone_ml, c->silicone_cartridges, r.silicone_cartridge_ml);
        res = qty_bom_add_priced(db, b, &cap, &r.silicone, APP_BOM_CONSUMABLE,
                                 c->silicone_cartridges, d, err, err_size);
    }
    if (res == APP_OK) {
        snprintf(d, sizeof d, "%d shower zone%s: floor and walls to %g mm", c->shower_zones,
                 c->shower_zones == 1 ? "" : "s", r.shower_wall_mm);
        res = qty_bom_add_priced(db, b, &cap, &r.waterproofing, APP_BOM_CONSUMABLE,
                                 billed_m2(c->waterproofing_m2), d, err, err_size);
    }
    if (res == APP_OK)
        res = qty_bom_add_priced(db, b, &cap, &r.labour_floor, APP_BOM_LABOUR,
                                 billed_m2(c->floor_m2), "tiled floor area", err, err_size);
    if (res == APP_OK)
        res = qty_bom_add_priced(db, b, &cap, &r.labour_wall, APP_BOM_LABOUR, billed_m2(c->wall_m2),
                                 "tiled wall area", err, err_size);
    if (res == APP_OK)
        res = qty_bom_add_priced(db, b, &cap, &r.labour_fixture, APP_BOM_LABOUR, c->fixtures,
                                 "placed products", err, err_size);
    if (res != APP_OK)
        return res;
    app_bom_total(b);
    if (b->out_of_range) {
        tl_set_err(err, err_size, "quantities",
                   "the total with consumables and labour does not fit in an amount");
        return APP_ERR_SCHEMA;
    }
    return APP_OK;
}
