/* Mounting heights of the trade (the fallback for products whose catalog row gives none) and the
 * check that a basin is carried by something: the heights a dropped product lands at (DOMAIN.md
 * "Typical sizes": basin rim 850-900, WC seat 400-420, mirror above the basin) and the
 * floating-basin finding (docs/editing.md). */
#include "placement_internal.h"

#include "catalog/catalog.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* How close (mm) a basin's underside must be to the top of what carries it, and its back to
 * a wall face for a wall-hung basin. */
#define SUPPORT_GAP_MM 30.0
/* A wall-hung or floor-standing basin's rim between these heights is plausible: DOMAIN.md
 * gives 850-900 for adults; 750 covers a lowered (accessible, DIN 18040-2: 800 max.) and
 * children's basins, 950 a tall user's. */
#define RIM_MIN_MM 750.0
#define RIM_MAX_MM 950.0

static const app_mounting mountings[] = {
    /* category, height_mm, of: what the height measures, onto: carried by */
    {CAT_CATEGORY_BASINS, 850, APP_MOUNT_TOP, CAT_CATEGORY_VANITY_UNITS},
    {CAT_CATEGORY_WCS_BIDETS, 420, APP_MOUNT_TOP, 0},
    {CAT_CATEGORY_VANITY_UNITS, 680, APP_MOUNT_TOP, 0},
    {CAT_CATEGORY_MIRRORS, 1150, APP_MOUNT_BOTTOM, CAT_CATEGORY_BASINS},
    {CAT_CATEGORY_MIRROR_CABINETS, 1150, APP_MOUNT_BOTTOM, CAT_CATEGORY_BASINS},
    {CAT_CATEGORY_TAPS_MIXERS, 850, APP_MOUNT_BOTTOM, CAT_CATEGORY_BASINS},
    {CAT_CATEGORY_TOWEL_RADIATORS, 150, APP_MOUNT_BOTTOM, 0},
    {CAT_CATEGORY_SHOWER_SETS, 1000, APP_MOUNT_BOTTOM, 0},
    {CAT_CATEGORY_ACCESSORIES, 1000, APP_MOUNT_BOTTOM, 0},
};

const app_mounting *app_mounting_of(int category)
{
    for (size_t i = 0; i < sizeof mountings / sizeof mountings[0]; i++)
        if (mountings[i].category == category)
            return &mountings[i];
    return NULL;
}

double app_mounting_z(int category, double height_mm)
{
    const app_mounting *m = app_mounting_of(category);
    if (!m)
        return 0;
    double z = m->of == APP_MOUNT_TOP ? m->height_mm - height_mm : m->height_mm;
    /* A product taller than its mounting height stands on the floor (a floor-standing WC, a
     * column basin). */
    return z > 0 ? z : 0;
}

double app_product_mounting_z(const app_product_info *info)
{
    if (!info->has_mounting)
        return app_mounting_z(info->category, info->height_mm);
    double z = info->mounting_of == APP_MOUNT_TOP ? info->mounting_height_mm - info->height_mm
                                                  : info->mounting_height_mm;
    /* As for the categories: taller than its mounting height, it stands on the floor. */
    return z > 0 ? z : 0;
}

int app_mounting_support(const app_fixture *fx, int count, int category, const double at[2],
                         double max_distance_mm)
{
    const app_mounting *m = app_mounting_of(category);
    if (!m || !m->onto)
        return -1;
    int best = -1;
    double best_d = max_distance_mm;
    for (int i = 0; i < count; i++) {
        if (fx[i].category != m->onto)
            continue;
        pl_rect r = pl_rect_of_fixture(&fx[i]);
        pl_rect dot = pl_rect_make(at[0], at[1], 0, 0.5, 0.5);
        double p[2], d = pl_rect_distance(&r, &dot, p);
        if (d <= best_d) {
            best_d = d;
            best = i;
        }
    }
    return best;
}

/* 1 when some part of f is within SUPPORT_GAP_MM of a wall face or a pre-wall. */
static int against_wall(const app_project *p, const app_fixture *f)
{
    const app_room_plan *plan = &p->plan;
    pl_rect r = pl_rect_of_fixture(f);
    double at[2];
    for (int w = 0; w < plan->corner_count && plan->corner_count >= 3; w++) {
        double o[2], dir[2], nrm[2], len;
        pl_wall_frame(plan, w, o, dir, nrm, &len);
        double e[2] = {o[0] + dir[0] * len, o[1] + dir[1] * len};
        if (pl_segment_rect_distance(o, e, &r, at) <= SUPPORT_GAP_MM)
            return 1;
    }
    for (int k = 0; k < plan->prewall_count && plan->corner_count >= 3; k++) {
        pl_rect pw = pl_prewall_rect(plan, k);
        if (pl_rect_distance(&pw, &r, at) <= SUPPORT_GAP_MM && f->z0 <= plan->prewalls[k].height_mm)
            return 1;
    }
    return 0;
}

/* 1 when another fixture's footprint lies under f and its top is at f's underside (or f is
 * set into it, a countertop basin). */
static int carried(const app_fixture *fx, int count, int self)
{
    const app_fixture *f = &fx[self];
    pl_rect r = pl_rect_of_fixture(f);
    for (int i = 0; i < count; i++) {
        const app_fixture *g = &fx[i];
        if (i == self || g->role != APP_ROLE_FIXTURE || g->z1 - g->z0 < 1)
            continue;
        if (f->z0 < g->z0 || f->z0 > g->z1 + SUPPORT_GAP_MM)
            continue;
        pl_rect rg = pl_rect_of_fixture(g);
        if (pl_rect_penetration(&r, &rg) > PL_TOLERANCE_MM)
            return 1;
    }
    return 0;
}

app_result pl_check_mounting(const app_project *p, const app_fixture *fx, int count,
                             app_findings *out)
{
    for (int i = 0; i < count; i++) {
        const app_fixture *f = &fx[i];
        if (!f->has_product || f->category != CAT_CATEGORY_BASINS)
            continue;
        int floor_standing = f->z0 <= SUPPORT_GAP_MM && f->z1 >= RIM_MIN_MM;
        int wall_hung = f->z1 >= RIM_MIN_MM && f->z1 <= RIM_MAX_MM && against_wall(p, f);
        if (floor_standing || wall_hung || carried(fx, count, i))
            continue;
        app_result r = pl_add_finding(
            out, APP_FINDING_FLOATING, APP_SEVERITY_ERROR, f->object, -1, f->centre,
            "\"%s\" floats: its underside at %.0f mm rests on no vanity unit, and with the rim "
            "at %.0f mm it is not wall-hung (rim %.0f-%.0f mm against a wall)",
            f->name, f->z0, f->z1, RIM_MIN_MM, RIM_MAX_MM);
        if (r != APP_OK)
            return r;
    }
    return APP_OK;
}
