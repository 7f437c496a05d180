/* The floor plan's geometric rules (docs/project-format.md "Plan"): the polygon is simple and
 * counter-clockwise, and every opening, pre-wall, niche and the slope fits its wall. Clockwise
 * plans are refused rather than silently reversed, because reversing renumbers the walls the
 * openings refer to. */
#include "project_internal.h"

#include <math.h>
#include <string.h>

#define MIN_WALL_MM 1.0 /* shorter walls are input mistakes (a corner typed twice) */
#define FIT_EPS_MM 1e-6 /* an opening may end exactly at the wall's end */

static double wall_length(const app_room_plan *plan, int i)
{
    app_point2 a = plan->corners[i], b = plan->corners[(i + 1) % plan->corner_count];
    return hypot(b.x - a.x, b.y - a.y);
}

static double cross(app_point2 o, app_point2 a, app_point2 b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

static int on_segment(app_point2 a, app_point2 b, app_point2 p)
{
    return fmin(a.x, b.x) <= p.x && p.x <= fmax(a.x, b.x) && fmin(a.y, b.y) <= p.y &&
           p.y <= fmax(a.y, b.y);
}

/* Closed segments ab and cd share a point (touching counts). */
static int segments_meet(app_point2 a, app_point2 b, app_point2 c, app_point2 d)
{
    double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return 1;
    return (d1 == 0 && on_segment(c, d, a)) || (d2 == 0 && on_segment(c, d, b)) ||
           (d3 == 0 && on_segment(a, b, c)) || (d4 == 0 && on_segment(a, b, d));
}

static app_result check_polygon(pj_ctx *c, const app_room_plan *plan)
{
    int n = plan->corner_count;
    size_t mark = pj_path_key(c, "corners");
    for (int i = 0; i < n; i++) {
        if (wall_length(plan, i) < MIN_WALL_MM) {
            pj_path_index(c, (i + 1) % n);
            return pj_fail(c, APP_ERR_SCHEMA,
                           "wall %d is shorter than %g mm (corner %d repeats corner %d)", i,
                           MIN_WALL_MM, (i + 1) % n, i);
        }
    }
    for (int i = 0; i < n; i++) {
        /* Adjacent walls share a corner; they overlap only when the second folds back. */
        app_point2 a = plan->corners[i], b = plan->corners[(i + 1) % n],
                   d = plan->corners[(i + 2) % n];
        double dot = (b.x - a.x) * (d.x - b.x) + (b.y - a.y) * (d.y - b.y);
        if (cross(a, b, d) == 0 && dot < 0) {
            pj_path_index(c, (i + 1) % n);
            return pj_fail(c, APP_ERR_SCHEMA, "walls %d and %d fold back onto each other", i,
                           (i + 1) % n);
        }
        for (int j = i + 2; j < n; j++) {
            if (i == 0 && j == n - 1)
                continue; /* adjacent through the closing corner */
            if (segments_meet(a, b, plan->corners[j], plan->corners[(j + 1) % n]))
                return pj_fail(c, APP_ERR_SCHEMA,
                               "the floor plan is not a simple polygon: wall %d (corners %d-%d) "
                               "crosses or touches wall %d (corners %d-%d)",
                               i, i, (i + 1) % n, j, j, (j + 1) % n);
        }
    }
    double area2 = 0;
    for (int i = 0; i < n; i++) {
        app_point2 a = plan->corners[i], b = plan->corners[(i + 1) % n];
        area2 += a.x * b.y - b.x * a.y;
    }
    if (area2 < 0)
        return pj_fail(c, APP_ERR_SCHEMA,
                       "the corners run clockwise seen from above; list them counter-clockwise "
                       "(the room's interior on the left of each wall)");
    if (area2 == 0)
        return pj_fail(c, APP_ERR_SCHEMA, "the floor plan has no area");
    pj_path_restore(c, mark);
    return APP_OK;
}

/* wall index, along-wall span and vertical span of one item at path $.plan.LIST[i]. */
static app_result check_on_wall(pj_ctx *c, const app_room_plan *plan, const char *what, int wall,
                                double offset, double width, double bottom, double height)
{
    if (wall >= plan->corner_count) {
        pj_path_key(c, "wall");
        return pj_fail(c, APP_ERR_SCHEMA, "wall %d does not exist (the plan has %d walls, 0..%d)",
                       wall, plan->corner_count, plan->corner_count - 1);
    }
    double len = wall_length(plan, wall);
    if (offset + width > len + FIT_EPS_MM)
        return pj_fail(c, APP_ERR_SCHEMA,
                       "the %s reaches %g mm along wall %d (offset + width), beyond its length of "
                       "%g mm",
                       what, offset + width, wall, len);
    if (bottom + height > plan->height_mm + FIT_EPS_MM)
        return pj_fail(c, APP_ERR_SCHEMA,
                       "the %s's top is at %g mm, above the wall height of %g mm", what,
                       bottom + height, plan->height_mm);
    return APP_OK;
}

static app_result check_openings(pj_ctx *c, const app_room_plan *plan)
{
    size_t mark = pj_path_key(c, "openings");
    for (int i = 0; i < plan->opening_count; i++) {
        const app_opening *o = &plan->openings[i];
        size_t i_mark = pj_path_index(c, i);
        app_result r = check_on_wall(c, plan, pj_opening_type_names[o->type], o->wall, o->offset_mm,
                                     o->width_mm, o->sill_mm, o->height_mm);
        if (r != APP_OK)
            return r;
        for (int j = 0; j < i; j++) {
            const app_opening *q = &plan->openings[j];
            if (q->wall == o->wall && o->offset_mm < q->offset_mm + q->width_mm &&
                q->offset_mm < o->offset_mm + o->width_mm &&
                o->sill_mm < q->sill_mm + q->height_mm && q->sill_mm < o->sill_mm + o->height_mm)
                return pj_fail(c, APP_ERR_SCHEMA, "overlaps opening %d (\"%s\") on wall %d", j,
                               q->name, o->wall);
        }
        pj_path_restore(c, i_mark);
    }
    pj_path_restore(c, mark);
    return APP_OK;
}

static app_result check_prewalls_and_niches(pj_ctx *c, const app_room_plan *plan)
{
    size_t mark = pj_path_key(c, "prewalls");
    for (int i = 0; i < plan->prewall_count; i++) {
        const app_prewall *w = &plan->prewalls[i];
        size_t i_mark = pj_path_index(c, i);
        app_result r =
            check_on_wall(c, plan, "pre-wall", w->wall, w->offset_mm, w->width_mm, 0, w->height_mm);
        if (r != APP_OK)
            return r;
        for (int j = 0; j < i; j++) {
            if (strcmp(plan->prewalls[j].name, w->name) == 0) {
                pj_path_key(c, "name");
                return pj_fail(c, APP_ERR_SCHEMA,
                               "\"%s\" is already the name of pre-wall %d (names must be unique)",
                               w->name, j);
            }
        }
        pj_path_restore(c, i_mark);
    }
    pj_path_restore(c, mark);
    mark = pj_path_key(c, "niches");
    for (int i = 0; i < plan->niche_count; i++) {
        const app_niche *n = &plan->niches[i];
        size_t i_mark = pj_path_index(c, i);
        app_result r = check_on_wall(c, plan, "niche", n->wall, n->offset_mm, n->width_mm,
                                     n->sill_mm, n->height_mm);
        if (r != APP_OK)
            return r;
        if (n->depth_mm >= plan->wall_thickness_mm) {
            pj_path_key(c, "depth");
            return pj_fail(c, APP_ERR_SCHEMA,
                           "must be less than the wall thickness (%g mm), got %g",
                           plan->wall_thickness_mm, n->depth_mm);
        }
        pj_path_restore(c, i_mark);
    }
    pj_path_restore(c, mark);
    return APP_OK;
}

static app_result check_slope(pj_ctx *c, const app_room_plan *plan)
{
    const app_ceiling_slope *s = &plan->slope;
    if (!s->present)
        return APP_OK;
    size_t mark = pj_path_key(c, "slope");
    if (s->wall >= plan->corner_count) {
        pj_path_key(c, "wall");
        return pj_fail(c, APP_ERR_SCHEMA, "wall %d does not exist (the plan has %d walls, 0..%d)",
                       s->wall, plan->corner_count, plan->corner_count - 1);
    }
    if (s->knee_mm >= plan->height_mm) {
        pj_path_key(c, "knee");
        return pj_fail(c, APP_ERR_SCHEMA, "must be below the wall height (%g mm), got %g",
                       plan->height_mm, s->knee_mm);
    }
    pj_path_restore(c, mark);
    return APP_OK;
}

app_result pj_check_plan(pj_ctx *c, const app_room_plan *plan)
{
    app_result r;
    if ((r = check_polygon(c, plan)) != APP_OK || (r = check_openings(c, plan)) != APP_OK ||
        (r = check_prewalls_and_niches(c, plan)) != APP_OK || (r = check_slope(c, plan)) != APP_OK)
        return r;
    return APP_OK;
}
