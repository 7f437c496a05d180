/* Orbit and walk-through navigation. See ui/navigation.h. */
#include "ui/navigation.h"

#include <math.h>
#include <stddef.h>

#define DEG (3.14159265358979323846 / 180.0)
#define UI_ORBIT_MIN_ARM_MM 100.0

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
    return ui_walk_move_among(w, plan, NULL, 0, forward_mm, right_mm);
}

int ui_walk_point_free(const app_room_plan *plan, const ui_obstacle *obstacles, int count, double x,
                       double y, double radius)
{
    if (!ui_plan_point_free(plan, x, y, radius))
        return 0;
    for (int i = 0; i < count; i++) {
        const ui_obstacle *o = &obstacles[i];
        /* The point in the rectangle's frame; its distance to the rectangle is the length of
         * the part of |local| beyond the half sides (0 inside). */
        double c = cos(o->angle_deg * DEG), s = sin(o->angle_deg * DEG);
        double dx = x - o->centre[0], dy = y - o->centre[1];
        double lx = fabs(c * dx + s * dy) - o->half[0], ly = fabs(-s * dx + c * dy) - o->half[1];
        if ((lx <= 0 && ly <= 0) || hypot(fmax(lx, 0), fmax(ly, 0)) < radius)
            return 0;
    }
    return 1;
}

int ui_walk_move_among(ui_walk *w, const app_room_plan *plan, const ui_obstacle *obstacles,
                       int count, double forward_mm, double right_mm)
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
        if (ui_walk_point_free(plan, obstacles, count, x + sx, y + syy, UI_WALK_RADIUS_MM)) {
            w->eye[0] = x + sx;
            w->eye[1] = y + syy;
            continue;
        }
        full = 0;
        if (ui_walk_point_free(plan, obstacles, count, x + sx, y, UI_WALK_RADIUS_MM))
            w->eye[0] = x + sx;
        else if (ui_walk_point_free(plan, obstacles, count, x, y + syy, UI_WALK_RADIUS_MM))
            w->eye[1] = y + syy;
    }
    return full;
}

static double room_height(const app_room_plan *plan)
{
    return plan->height_mm > 0 ? plan->height_mm : 2500;
}

int ui_room_point_free(const app_room_plan *plan, const double p[3], double margin)
{
    return isfinite(p[2]) && p[2] >= margin && p[2] <= room_height(plan) - margin &&
           ui_plan_point_free(plan, p[0], p[1], margin);
}

/* The nearest point of segment ab to (x, y) moved inward by margin along the wall's inner
 * normal (the plan runs counter-clockwise, so the interior is on the left of a -> b). */
static void inset_nearest(const app_point2 *a, const app_point2 *b, double x, double y,
                          double margin, double out[2])
{
    double ex = b->x - a->x, ey = b->y - a->y, len = hypot(ex, ey);
    double t = len > 0 ? clampd(((x - a->x) * ex + (y - a->y) * ey) / (len * len), 0, 1) : 0;
    double nx = len > 0 ? -ey / len : 0, ny = len > 0 ? ex / len : 0;
    out[0] = a->x + t * ex + nx * margin;
    out[1] = a->y + t * ey + ny * margin;
}

int ui_room_clamp_point(const app_room_plan *plan, double p[3], double margin)
{
    if (ui_room_point_free(plan, p, margin) || plan->corner_count < 3)
        return 0;
    double h = room_height(plan), q[3] = {p[0], p[1], clampd(p[2], margin, h - margin)};
    if (h < 2 * margin || !isfinite(q[2]))
        q[2] = h / 2;
    if (!ui_plan_point_free(plan, q[0], q[1], margin)) {
        /* Candidates: each wall's nearest point pushed in by the margin (a little more, so
         * the next wall's margin at a corner is met too); the nearest free one wins. */
        double best = INFINITY, bx = q[0], by = q[1];
        int n = plan->corner_count;
        for (int i = 0; i < n; i++) {
            for (double k = 1.001; k < 4; k *= 1.5) {
                double c[2];
                inset_nearest(&plan->corners[i], &plan->corners[(i + 1) % n], p[0], p[1],
                              margin * k, c);
                double d = hypot(c[0] - p[0], c[1] - p[1]);
                if (d < best && ui_plan_point_free(plan, c[0], c[1], margin)) {
                    best = d;
                    bx = c[0];
                    by = c[1];
                    break;
                }
            }
        }
        /* And each corner of the inset polygon: past a convex corner the nearest free point
         * is there, where both walls' margins meet (offset by the normals' sum over
         * 1 + n1.n2, the miter). */
        for (int i = 0; i < n; i++) {
            const app_point2 *a = &plan->corners[(i + n - 1) % n], *c = &plan->corners[i],
                             *b = &plan->corners[(i + 1) % n];
            double l1 = hypot(c->x - a->x, c->y - a->y), l2 = hypot(b->x - c->x, b->y - c->y);
            if (!(l1 > 0 && l2 > 0))
                continue;
            double n1[2] = {-(c->y - a->y) / l1, (c->x - a->x) / l1};
            double n2[2] = {-(b->y - c->y) / l2, (b->x - c->x) / l2};
            double k = 1 + n1[0] * n2[0] + n1[1] * n2[1];
            if (k < 1e-6)
                continue;
            double m = margin * 1.001 / k;
            double v[2] = {c->x + (n1[0] + n2[0]) * m, c->y + (n1[1] + n2[1]) * m};
            double d = hypot(v[0] - p[0], v[1] - p[1]);
            if (d < best && ui_plan_point_free(plan, v[0], v[1], margin)) {
                best = d;
                bx = v[0];
                by = v[1];
            }
        }
        if (!isfinite(best))
            return 0; /* no interior that wide */
        q[0] = bx;
        q[1] = by;
    }
    int moved = q[0] != p[0] || q[1] != p[1] || q[2] != p[2];
    p[0] = q[0];
    p[1] = q[1];
    p[2] = q[2];
    return moved;
}

void ui_orbit_eye_inside(const ui_orbit *o, const app_room_plan *plan, double eye[3],
                         double target[3])
{
    for (int k = 0; k < 3; k++)
        target[k] = o->target[k];
    ui_room_clamp_point(plan, target, UI_CAMERA_MARGIN_MM);
    ui_orbit shifted = *o;
    for (int k = 0; k < 3; k++)
        shifted.target[k] = target[k];
    ui_orbit_eye(&shifted, eye);
    if (!ui_room_point_free(plan, target, UI_CAMERA_MARGIN_MM))
        return; /* a room too small for the margin: nothing to keep inside */
    /* The arm from the target to the eye, cut at its first point outside: steps of at most 20
     * mm find the wall, then bisection places the eye within a millimetre of it. A wall thinner
     * than a step cannot be skipped, as the room is one polygon. */
    double d = o->distance_mm, dir[3];
    for (int k = 0; k < 3; k++)
        dir[k] = (eye[k] - target[k]) / d;
    int steps = (int)ceil(d / 20.0);
    double free_t = 0;
    for (int i = 1; i <= steps; i++) {
        double t = d * i / steps,
               q[3] = {target[0] + dir[0] * t, target[1] + dir[1] * t, target[2] + dir[2] * t};
        if (!ui_room_point_free(plan, q, UI_CAMERA_MARGIN_MM)) {
            double lo = free_t, hi = t;
            while (hi - lo > 1) {
                double mid = (lo + hi) / 2,
                       m[3] = {target[0] + dir[0] * mid, target[1] + dir[1] * mid,
                               target[2] + dir[2] * mid};
                if (ui_room_point_free(plan, m, UI_CAMERA_MARGIN_MM))
                    lo = mid;
                else
                    hi = mid;
            }
            for (int k = 0; k < 3; k++)
                eye[k] = target[k] + dir[k] * lo;
            /* The target at the margin with the arm pointing out: the eye stays, and the point
             * looked at moves ahead along the same view so the two never meet. */
            if (lo < UI_ORBIT_MIN_ARM_MM)
                for (int k = 0; k < 3; k++)
                    target[k] = eye[k] - dir[k] * UI_ORBIT_MIN_ARM_MM;
            return;
        }
        free_t = t;
    }
}

ui_walk ui_walk_from_view(const app_room_plan *plan, const ui_obstacle *obstacles, int count,
                          const double eye[3], const double target[3])
{
    ui_walk w = ui_walk_start(plan);
    double dx = target[0] - eye[0], dy = target[1] - eye[1];
    if (hypot(dx, dy) > 0)
        w.yaw_deg = atan2(dx, dy) / DEG;
    w.pitch_deg = 0;
    w.eye[2] = fmin(UI_EYE_HEIGHT_MM, room_height(plan) - UI_CAMERA_MARGIN_MM);
    /* Under the eye if free, else the nearest free point on rings around it. */
    if (ui_walk_point_free(plan, obstacles, count, eye[0], eye[1], UI_WALK_RADIUS_MM)) {
        w.eye[0] = eye[0];
        w.eye[1] = eye[1];
        return w;
    }
    for (double r = 50; r < 20000; r += 50)
        for (int a = 0; a < 72; a++) {
            double x = eye[0] + r * cos(a * 5 * DEG), y = eye[1] + r * sin(a * 5 * DEG);
            if (ui_walk_point_free(plan, obstacles, count, x, y, UI_WALK_RADIUS_MM)) {
                w.eye[0] = x;
                w.eye[1] = y;
                return w;
            }
        }
    return w; /* nowhere free: the room's own start */
}
