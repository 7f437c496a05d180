/* Snapping a fixture's pose (its back centre, placement.h) to wall faces, pre-wall fronts,
 * corners and neighbours. Pure functions: the pose in, the snapped pose out. */
#include "placement_internal.h"

#include <math.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

int pl_face_count(const app_room_plan *plan)
{
    return plan->corner_count + plan->prewall_count;
}

int pl_face_get(const app_room_plan *plan, int k, pl_face *f)
{
    memset(f, 0, sizeof *f);
    if (k < plan->corner_count) {
        f->wall = k;
        f->prewall = -1;
    } else {
        const app_prewall *pw = &plan->prewalls[k - plan->corner_count];
        if (pw->wall < 0 || pw->wall >= plan->corner_count)
            return 0;
        f->wall = pw->wall;
        f->prewall = k - plan->corner_count;
    }
    pl_wall_frame(plan, f->wall, f->o, f->d, f->n, &f->len);
    if (f->prewall < 0) {
        f->s1 = f->len;
    } else {
        const app_prewall *pw = &plan->prewalls[f->prewall];
        f->s0 = pw->offset_mm;
        f->s1 = pw->offset_mm + pw->width_mm;
        f->offset = pw->depth_mm;
    }
    return f->len > 0;
}

/* The rotation about Z that turns local +y onto the normal n. */
static double facing_deg(const double n[2])
{
    return atan2(-n[0], n[1]) * 180.0 / M_PI;
}

int app_snap_to_wall(const app_room_plan *plan, double width_mm, app_pose in,
                     double max_distance_mm, app_pose *out)
{
    *out = in;
    if (!plan || plan->corner_count < 3 || !plan->corners)
        return -1;
    int best = -1;
    double best_dist = INFINITY, best_s = 0;
    pl_face bf;
    memset(&bf, 0, sizeof bf);
    for (int k = 0; k < pl_face_count(plan); k++) {
        pl_face f;
        if (!pl_face_get(plan, k, &f))
            continue;
        double rx = in.x - f.o[0], ry = in.y - f.o[1];
        double s = rx * f.d[0] + ry * f.d[1];
        double t = rx * f.n[0] + ry * f.n[1] - f.offset; /* in front of the face: > 0 */
        double ds = s < f.s0 ? f.s0 - s : s > f.s1 ? s - f.s1 : 0;
        double dist = hypot(ds, t);
        if (dist <= max_distance_mm && dist < best_dist) {
            best = k;
            best_dist = dist;
            best_s = s;
            bf = f;
        }
    }
    if (best < 0)
        return -1;
    /* Keep the fixture within the face when it fits, else centre it on the face. */
    double lo = bf.s0 + 0.5 * width_mm, hi = bf.s1 - 0.5 * width_mm;
    double s = lo <= hi ? fmin(fmax(best_s, lo), hi) : 0.5 * (bf.s0 + bf.s1);
    out->x = bf.o[0] + bf.d[0] * s + bf.n[0] * bf.offset;
    out->y = bf.o[1] + bf.d[1] * s + bf.n[1] * bf.offset;
    out->rotation_deg = facing_deg(bf.n);
    return bf.wall;
}

int pl_face_of_pose(const app_room_plan *plan, app_pose in, pl_face *out)
{
    double a = in.rotation_deg * M_PI / 180;
    double fy[2] = {-sin(a), cos(a)};
    for (int k = 0; k < pl_face_count(plan); k++) {
        pl_face f;
        if (!pl_face_get(plan, k, &f))
            continue;
        if (fy[0] * f.n[0] + fy[1] * f.n[1] < 0.999)
            continue;
        double rx = in.x - f.o[0], ry = in.y - f.o[1];
        double s = rx * f.d[0] + ry * f.d[1];
        double t = rx * f.n[0] + ry * f.n[1] - f.offset;
        if (fabs(t) <= PL_TOLERANCE_MM && s >= f.s0 - PL_TOLERANCE_MM &&
            s <= f.s1 + PL_TOLERANCE_MM) {
            *out = f;
            return k;
        }
    }
    return -1;
}

int app_snap_to_corner(const app_room_plan *plan, double width_mm, app_pose in,
                       double max_distance_mm, double gap_mm, app_pose *out)
{
    *out = in;
    if (!plan || plan->corner_count < 3 || !plan->corners)
        return 0;
    pl_face f;
    if (pl_face_of_pose(plan, in, &f) < 0)
        return 0;
    double s = (in.x - f.o[0]) * f.d[0] + (in.y - f.o[1]) * f.d[1];
    double left = s - 0.5 * width_mm, right = s + 0.5 * width_mm;
    /* Stops along the wall: its ends, and for a fixture on the wall itself the sides of the
     * pre-walls standing on it. */
    double stops[2 + 2 * 64];
    int is_left[2 + 2 * 64];
    int n = 0;
    stops[n] = 0;
    is_left[n++] = 1;
    stops[n] = f.len;
    is_left[n++] = 0;
    for (int k = 0; f.prewall < 0 && k < plan->prewall_count && n + 2 <= 2 + 2 * 64; k++) {
        const app_prewall *pw = &plan->prewalls[k];
        if (pw->wall != f.wall)
            continue;
        stops[n] = pw->offset_mm + pw->width_mm;
        is_left[n++] = 1;
        stops[n] = pw->offset_mm;
        is_left[n++] = 0;
    }
    double best_shift = INFINITY;
    for (int i = 0; i < n; i++) {
        double shift = is_left[i] ? (stops[i] + gap_mm) - left : (stops[i] - gap_mm) - right;
        /* Only stops on the correct side: a left stop not right of the fixture's centre. */
        if (is_left[i] ? stops[i] > s : stops[i] < s)
            continue;
        if (fabs(shift) <= max_distance_mm && fabs(shift) < fabs(best_shift))
            best_shift = shift;
    }
    if (!isfinite(best_shift))
        return 0;
    out->x = in.x + f.d[0] * best_shift;
    out->y = in.y + f.d[1] * best_shift;
    return 1;
}

int app_snap_to_neighbour(const app_fixture *fx, int count, int self_object, double width_mm,
                          double depth_mm, app_pose in, double max_distance_mm, double gap_mm,
                          app_pose *out)
{
    *out = in;
    double a = in.rotation_deg * M_PI / 180;
    double ax[2] = {cos(a), sin(a)}, ay[2] = {-sin(a), cos(a)};
    double left = -0.5 * width_mm, right = 0.5 * width_mm;
    double best_shift = INFINITY;
    int best = -1;
    for (int i = 0; i < count; i++) {
        const app_fixture *b = &fx[i];
        if (b->object == self_object || b->role != APP_ROLE_FIXTURE)
            continue;
        pl_rect r = pl_rect_of_fixture(b);
        double c[4][2];
        pl_rect_corners(&r, c);
        double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
        for (int k = 0; k < 4; k++) {
            double rx = c[k][0] - in.x, ry = c[k][1] - in.y;
            double u = rx * ax[0] + ry * ax[1], v = rx * ay[0] + ry * ay[1];
            u0 = fmin(u0, u);
            u1 = fmax(u1, u);
            v0 = fmin(v0, v);
            v1 = fmax(v1, v);
        }
        if (v1 <= PL_TOLERANCE_MM || v0 >= depth_mm - PL_TOLERANCE_MM)
            continue; /* not beside it */
        double shift = INFINITY;
        if (u1 <= 0) /* on the left */
            shift = (u1 + gap_mm) - left;
        else if (u0 >= 0) /* on the right */
            shift = (u0 - gap_mm) - right;
        if (fabs(shift) <= max_distance_mm && fabs(shift) < fabs(best_shift)) {
            best_shift = shift;
            best = b->object;
        }
    }
    if (best < 0)
        return -1;
    out->x = in.x + ax[0] * best_shift;
    out->y = in.y + ax[1] * best_shift;
    return best;
}
