/* Orbit and walk-through navigation. See ui/navigation.h. */
#include "ui/navigation.h"

#include <math.h>

#define DEG (3.14159265358979323846 / 180.0)

static double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

static void plan_bounds(const app_room_plan *plan, double lo[2], double hi[2])
{
    lo[0] = lo[1] = 0;
    hi[0] = hi[1] = 0;
    for (int i = 0; i < plan->corner_count; i++) {
        const app_point2 *c = &plan->corners[i];
        if (i == 0 || c->x < lo[0])
            lo[0] = c->x;
        if (i == 0 || c->y < lo[1])
            lo[1] = c->y;
        if (i == 0 || c->x > hi[0])
            hi[0] = c->x;
        if (i == 0 || c->y > hi[1])
            hi[1] = c->y;
    }
}

ui_orbit ui_orbit_framing(const app_room_plan *plan)
{
    double lo[2], hi[2];
    plan_bounds(plan, lo, hi);
    double h = plan->height_mm > 0 ? plan->height_mm : 2500;
    double size = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    ui_orbit o = {{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, h * 0.4}, 0, 35, 35};
    o.distance_mm = clampd(1.6 * fmax(size, h), 200, 50000);
    return o;
}

void ui_orbit_eye(const ui_orbit *o, double eye[3])
{
    double cp = cos(o->pitch_deg * DEG), sp = sin(o->pitch_deg * DEG);
    double sy = sin(o->yaw_deg * DEG), cy = cos(o->yaw_deg * DEG);
    /* The view direction is (sy cp, cy cp, -sp); the eye sits behind the target along it. */
    eye[0] = o->target[0] - o->distance_mm * sy * cp;
    eye[1] = o->target[1] - o->distance_mm * cy * cp;
    eye[2] = o->target[2] + o->distance_mm * sp;
}

void ui_orbit_drag(ui_orbit *o, double dx_px, double dy_px)
{
    o->yaw_deg = fmod(o->yaw_deg + 0.3 * dx_px, 360.0);
    o->pitch_deg = clampd(o->pitch_deg + 0.3 * dy_px, -85, 85);
}

void ui_orbit_zoom(ui_orbit *o, double steps)
{
    o->distance_mm = clampd(o->distance_mm * pow(0.9, steps), 200, 50000);
}

ui_orbit ui_orbit_from_view(const double eye[3], const double target[3])
{
    double d[3] = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    ui_orbit o = {{target[0], target[1], target[2]}, clampd(len, 200, 50000), 0, 0};
    if (len > 0) {
        o.yaw_deg = atan2(d[0], d[1]) / DEG;
        o.pitch_deg = clampd(asin(clampd(-d[2] / len, -1, 1)) / DEG, -85, 85);
    }
    return o;
}

double ui_ease(double t)
{
    t = clampd(isfinite(t) ? t : 1, 0, 1);
    return t * t * (3 - 2 * t);
}

void ui_view_blend(const double eye0[3], const double target0[3], const double eye1[3],
                   const double target1[3], double t, double eye[3], double target[3])
{
    double s = ui_ease(t);
    for (int k = 0; k < 3; k++) {
        eye[k] = eye0[k] + s * (eye1[k] - eye0[k]);
        target[k] = target0[k] + s * (target1[k] - target0[k]);
    }
}

/* Point-to-segment distance in the plan. */
static double segment_distance(double px, double py, const app_point2 *a, const app_point2 *b)
{
    double ex = b->x - a->x, ey = b->y - a->y, len2 = ex * ex + ey * ey;
    double t = len2 > 0 ? ((px - a->x) * ex + (py - a->y) * ey) / len2 : 0;
    t = clampd(t, 0, 1);
    double dx = px - (a->x + t * ex), dy = py - (a->y + t * ey);
    return sqrt(dx * dx + dy * dy);
}

int ui_plan_point_free(const app_room_plan *plan, double x, double y, double radius)
{
    int n = plan->corner_count, inside = 0;
    if (n < 3 || !isfinite(x) || !isfinite(y))
        return 0;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        const app_point2 *a = &plan->corners[i], *b = &plan->corners[j];
        /* Even-odd crossing test along +X. */
        if ((a->y > y) != (b->y > y) && x < (b->x - a->x) * (y - a->y) / (b->y - a->y) + a->x)
            inside = !inside;
        if (segment_distance(x, y, a, b) < radius)
            return 0;
    }
    return inside;
}

ui_walk ui_walk_start(const app_room_plan *plan)
{
    double lo[2], hi[2];
    plan_bounds(plan, lo, hi);
    ui_walk w = {{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, 1600}, 0, -5};
    /* An L-shaped room's bounding-box centre may lie outside it: search a grid for a free
     * point, nearest the centre first. */
    if (!ui_plan_point_free(plan, w.eye[0], w.eye[1], UI_WALK_RADIUS_MM)) {
        double best = INFINITY;
        for (int i = 1; i < 32; i++)
            for (int j = 1; j < 32; j++) {
                double x = lo[0] + (hi[0] - lo[0]) * i / 32.0;
                double y = lo[1] + (hi[1] - lo[1]) * j / 32.0;
                double d = hypot(x - (lo[0] + hi[0]) / 2, y - (lo[1] + hi[1]) / 2);
                if (d < best && ui_plan_point_free(plan, x, y, UI_WALK_RADIUS_MM)) {
                    best = d;
                    w.eye[0] = x;
                    w.eye[1] = y;
                }
            }
    }
    if (plan->height_mm > 0 && w.eye[2] > plan->height_mm - 100)
        w.eye[2] = plan->height_mm * 0.6;
    return w;
}

void ui_walk_target(const ui_walk *w, double target[3])
{
    double cp = cos(w->pitch_deg * DEG);
    target[0] = w->eye[0] + 1000 * sin(w->yaw_deg * DEG) * cp;
    target[1] = w->eye[1] + 1000 * cos(w->yaw_deg * DEG) * cp;
    target[2] = w->eye[2] + 1000 * sin(w->pitch_deg * DEG);
}

void ui_walk_look(ui_walk *w, double dx_px, double dy_px)
{
    w->yaw_deg = fmod(w->yaw_deg + 0.2 * dx_px, 360.0);
    w->pitch_deg = clampd(w->pitch_deg - 0.2 * dy_px, -80, 80);
}

int ui_walk_move(ui_walk *w, const app_room_plan *plan, double forward_mm, double right_mm)
{
    double sy = sin(w->yaw_deg * DEG), cy = cos(w->yaw_deg * DEG);
    double dx = forward_mm * sy + right_mm * cy, dy = forward_mm * cy - right_mm * sy;
    double len = hypot(dx, dy);
    if (len == 0)
        return 1;
    /* Sub-steps no longer than half the radius, so a thin wall cannot be jumped over; at a
     * wall, slide along whichever axis is still free. */
    int steps = (int)ceil(len / (UI_WALK_RADIUS_MM * 0.5));
    double sx = dx / steps, syy = dy / steps;
    int full = 1;
    for (int i = 0; i < steps; i++) {
        double x = w->eye[0], y = w->eye[1];
        if (ui_plan_point_free(plan, x + sx, y + syy, UI_WALK_RADIUS_MM)) {
            w->eye[0] = x + sx;
            w->eye[1] = y + syy;
            continue;
        }
        full = 0;
        if (ui_plan_point_free(plan, x + sx, y, UI_WALK_RADIUS_MM))
            w->eye[0] = x + sx;
        else if (ui_plan_point_free(plan, x, y + syy, UI_WALK_RADIUS_MM))
            w->eye[1] = y + syy;
    }
    return full;
}
