/* Door swings: the square an inward-opening leaf sweeps (the `opening` check's), and sliding a
 * dropped fixture along its wall out of it (docs/editing.md "Mounting heights"). */
#include "placement_internal.h"

#include <math.h>
#include <stdlib.h>

/* Free areas are for standing and moving: anything reaching below this height blocks them
 * (the checks' FREE_AREA_HEADROOM_MM). */
#define HEADROOM_MM 2000.0

int pl_door_swing_rect(const app_room_plan *plan, int k, pl_rect *out)
{
    const app_opening *op = &plan->openings[k];
    if (op->type != APP_OPENING_DOOR ||
        (op->swing != APP_SWING_IN_LEFT && op->swing != APP_SWING_IN_RIGHT) || op->wall < 0 ||
        op->wall >= plan->corner_count)
        return 0;
    double o[2], d[2], n[2], len;
    pl_wall_frame(plan, op->wall, o, d, n, &len);
    /* A leaf opening into the room sweeps a quarter circle; its square is kept free. */
    out->ax[0] = d[0];
    out->ax[1] = d[1];
    out->ay[0] = n[0];
    out->ay[1] = n[1];
    out->h[0] = out->h[1] = 0.5 * op->width_mm;
    double s = op->offset_mm + 0.5 * op->width_mm;
    out->c[0] = o[0] + d[0] * s + n[0] * out->h[1];
    out->c[1] = o[1] + d[1] * s + n[1] * out->h[1];
    return 1;
}

/* The centres along the face (s) at which a fixture of the given width and depth, its back on
 * the face, overlaps obstacle r: the open interval (*lo, *hi). 0 when r is not within the
 * band the fixture's depth sweeps. The obstacle is bounded by its box in the face's frame,
 * exact for the walls' and doors' axis-aligned rectangles. */
static int blocked_interval(const pl_face *f, const pl_rect *r, double width_mm, double depth_mm,
                            double *lo, double *hi)
{
    double c[4][2], s0 = INFINITY, s1 = -INFINITY, t0 = INFINITY, t1 = -INFINITY;
    pl_rect_corners(r, c);
    for (int q = 0; q < 4; q++) {
        double rx = c[q][0] - f->o[0], ry = c[q][1] - f->o[1];
        double s = rx * f->d[0] + ry * f->d[1], t = rx * f->n[0] + ry * f->n[1] - f->offset;
        s0 = fmin(s0, s);
        s1 = fmax(s1, s);
        t0 = fmin(t0, t);
        t1 = fmax(t1, t);
    }
    if (t1 <= PL_TOLERANCE_MM || t0 >= depth_mm - PL_TOLERANCE_MM)
        return 0;
    *lo = s0 - 0.5 * width_mm + PL_TOLERANCE_MM;
    *hi = s1 + 0.5 * width_mm - PL_TOLERANCE_MM;
    return *hi > *lo;
}

typedef struct interval {
    double lo, hi;
} interval;

/* The obstacles a fixture on face f must keep clear of, as blocked centre intervals: door
 * swings, doorways and windows in front of it, pre-walls, other fixtures' footprints (widened
 * by the side distance where the distance check asks for one) and free areas. *swings = how many of
 * them (the first ones) are door swings. */
static int blocked_intervals(const app_room_plan *plan, const pl_face *f, const app_fixture *fx,
                             int count, int category, double width_mm, double depth_mm, double z0,
                             double z1, interval *out, int *swings)
{
    int n = 0;
    pl_rect r;
    for (int k = 0; k < plan->opening_count; k++)
        if (pl_door_swing_rect(plan, k, &r) && z0 < plan->openings[k].height_mm &&
            blocked_interval(f, &r, width_mm, depth_mm, &out[n].lo, &out[n].hi))
            n++;
    *swings = n;
    for (int k = 0; k < plan->opening_count; k++) {
        const app_opening *op = &plan->openings[k];
        if (op->wall < 0 || op->wall >= plan->corner_count || z1 <= op->sill_mm ||
            z0 >= op->sill_mm + op->height_mm)
            continue;
        double o[2], d[2], nrm[2], len;
        pl_wall_frame(plan, op->wall, o, d, nrm, &len);
        double s = op->offset_mm + 0.5 * op->width_mm, h = 0.5 * PL_OPENING_REACH_MM;
        r = pl_rect_make(o[0] + d[0] * s + nrm[0] * h, o[1] + d[1] * s + nrm[1] * h,
                         atan2(d[1], d[0]) * 180.0 / 3.14159265358979323846, 0.5 * op->width_mm, h);
        if (blocked_interval(f, &r, width_mm, depth_mm, &out[n].lo, &out[n].hi))
            n++;
    }
    for (int k = 0; k < plan->prewall_count; k++) {
        r = pl_prewall_rect(plan, k);
        if (k != f->prewall && z0 < plan->prewalls[k].height_mm &&
            blocked_interval(f, &r, width_mm, depth_mm, &out[n].lo, &out[n].hi))
            n++;
    }
    for (int i = 0; i < count; i++) {
        const app_fixture *g = &fx[i];
        if (g->role != APP_ROLE_FIXTURE)
            continue;
        r = pl_rect_of_fixture(g);
        if (z0 < g->z1 && g->z0 < z1 &&
            blocked_interval(f, &r, width_mm, depth_mm, &out[n].lo, &out[n].hi)) {
            if (g->has_product && pl_side_distance_applies(category, g->category)) {
                out[n].lo -= PL_SIDE_DISTANCE_MM;
                out[n].hi += PL_SIDE_DISTANCE_MM;
            }
            n++;
        }
        double aw, ad;
        if (z0 < HEADROOM_MM && app_free_area_size(g, APP_BARRIER_FREE_OFF, &aw, &ad)) {
            double fd = 2 * g->half[1];
            r = pl_rect_local(g, -0.5 * aw, 0.5 * aw, fd, fd + ad);
            if (blocked_interval(f, &r, width_mm, depth_mm, &out[n].lo, &out[n].hi))
                n++;
        }
    }
    return n;
}

static int is_free(const interval *b, int n, double s)
{
    for (int i = 0; i < n; i++)
        if (s > b[i].lo && s < b[i].hi)
            return 0;
    return 1;
}

int app_slide_out_of_swing(const app_room_plan *plan, const app_fixture *fx, int count,
                           int category, double width_mm, double depth_mm, double z0, double z1,
                           app_pose in, app_pose *out)
{
    *out = in;
    pl_face f;
    if (!plan || plan->corner_count < 3 || !plan->corners || pl_face_of_pose(plan, in, &f) < 0)
        return 0;
    int cap = plan->opening_count * 2 + plan->prewall_count + count * 2 + 1, swings = 0;
    interval *b = malloc((size_t)cap * sizeof *b);
    if (!b)
        return -1;
    int n =
        blocked_intervals(plan, &f, fx, count, category, width_mm, depth_mm, z0, z1, b, &swings);
    double s = (in.x - f.o[0]) * f.d[0] + (in.y - f.o[1]) * f.d[1];
    if (is_free(b, swings, s)) {
        free(b);
        return 0;
    }
    /* Candidates: the ends of every blocked interval, within the face; the nearest free one. */
    double lo = f.s0 + 0.5 * width_mm, hi = f.s1 - 0.5 * width_mm, best = NAN;
    for (int i = 0; i < n && lo <= hi; i++) {
        double cand[2] = {b[i].lo - PL_TOLERANCE_MM, b[i].hi + PL_TOLERANCE_MM};
        for (int e = 0; e < 2; e++) {
            double c = cand[e];
            if (c < lo - 1e-9 || c > hi + 1e-9 || !is_free(b, n, c))
                continue;
            if (isnan(best) || fabs(c - s) < fabs(best - s))
                best = c;
        }
    }
    free(b);
    if (isnan(best))
        return -1;
    out->x = in.x + f.d[0] * (best - s);
    out->y = in.y + f.d[1] * (best - s);
    return 1;
}
