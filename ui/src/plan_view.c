/* The plan view's geometry (ui/plan_view.h). */
#include "ui/plan_view.h"

#include <math.h>

#define DEG (3.14159265358979323846 / 180.0)

static double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

ui_plan_transform ui_plan_fit(const app_room_plan *plan, float width, float height, float margin_px)
{
    ui_plan_transform t = {{0, 0}, 0.1, width, height, 0, 0};
    if (plan->corner_count < 1 || width <= 2 * margin_px || height <= 2 * margin_px)
        return t;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < plan->corner_count; i++) {
        lo[0] = fmin(lo[0], plan->corners[i].x);
        lo[1] = fmin(lo[1], plan->corners[i].y);
        hi[0] = fmax(hi[0], plan->corners[i].x);
        hi[1] = fmax(hi[1], plan->corners[i].y);
    }
    /* Walls are drawn outside the inside faces: leave their thickness in the margin. */
    double wall = plan->wall_thickness_mm > 0 ? plan->wall_thickness_mm : 0;
    double w = hi[0] - lo[0] + 2 * wall, h = hi[1] - lo[1] + 2 * wall;
    t.centre_mm[0] = (lo[0] + hi[0]) / 2;
    t.centre_mm[1] = (lo[1] + hi[1]) / 2;
    double sx = (width - 2 * margin_px) / fmax(w, 1), sy = (height - 2 * margin_px) / fmax(h, 1);
    t.px_per_mm = clampd(fmin(sx, sy), 0.005, 5);
    return t;
}

void ui_plan_to_screen(const ui_plan_transform *t, double x_mm, double y_mm, float *sx, float *sy)
{
    *sx = (float)(t->x0 + t->width / 2 + (x_mm - t->centre_mm[0]) * t->px_per_mm);
    *sy = (float)(t->y0 + t->height / 2 - (y_mm - t->centre_mm[1]) * t->px_per_mm);
}

void ui_plan_to_plan(const ui_plan_transform *t, float sx, float sy, double *x_mm, double *y_mm)
{
    *x_mm = t->centre_mm[0] + (sx - t->x0 - t->width / 2) / t->px_per_mm;
    *y_mm = t->centre_mm[1] - (sy - t->y0 - t->height / 2) / t->px_per_mm;
}

void ui_plan_zoom_at(ui_plan_transform *t, float sx, float sy, double factor)
{
    double x, y;
    ui_plan_to_plan(t, sx, sy, &x, &y);
    t->px_per_mm = clampd(t->px_per_mm * factor, 0.005, 5);
    /* Move the centre so (x, y) is under (sx, sy) again. */
    t->centre_mm[0] = x - (sx - t->x0 - t->width / 2) / t->px_per_mm;
    t->centre_mm[1] = y + (sy - t->y0 - t->height / 2) / t->px_per_mm;
}

int ui_plan_hit_corner(const ui_plan_transform *t, const app_room_plan *plan, float sx, float sy,
                       float radius_px)
{
    int best = -1;
    double best_d = radius_px;
    for (int i = 0; i < plan->corner_count; i++) {
        float cx, cy;
        ui_plan_to_screen(t, plan->corners[i].x, plan->corners[i].y, &cx, &cy);
        double d = hypot(cx - sx, cy - sy);
        if (d <= best_d) {
            best_d = d;
            best = i;
        }
    }
    return best;
}

int ui_plan_hit_wall(const ui_plan_transform *t, const app_room_plan *plan, float sx, float sy,
                     float radius_px)
{
    int best = -1, n = plan->corner_count;
    double best_d = radius_px;
    for (int i = 0; i < n; i++) {
        float ax, ay, bx, by;
        ui_plan_to_screen(t, plan->corners[i].x, plan->corners[i].y, &ax, &ay);
        ui_plan_to_screen(t, plan->corners[(i + 1) % n].x, plan->corners[(i + 1) % n].y, &bx, &by);
        double ex = bx - ax, ey = by - ay, len2 = ex * ex + ey * ey;
        double u = len2 > 0 ? clampd(((sx - ax) * ex + (sy - ay) * ey) / len2, 0, 1) : 0;
        double d = hypot(sx - (ax + u * ex), sy - (ay + u * ey));
        if (d <= best_d) {
            best_d = d;
            best = i;
        }
    }
    return best;
}

int ui_plan_hit_fixture(const app_fixture *fx, int count, double x_mm, double y_mm)
{
    int best = -1;
    double best_area = INFINITY;
    for (int i = 0; i < count; i++) {
        const app_fixture *f = &fx[i];
        double c = cos(f->angle_deg * DEG), s = sin(f->angle_deg * DEG);
        double dx = x_mm - f->centre[0], dy = y_mm - f->centre[1];
        double lx = dx * c + dy * s, ly = -dx * s + dy * c;
        double area = f->half[0] * f->half[1];
        if (fabs(lx) <= f->half[0] && fabs(ly) <= f->half[1] && area < best_area) {
            best_area = area;
            best = i;
        }
    }
    return best;
}

double ui_plan_wall_length(const app_room_plan *plan, int wall)
{
    int n = plan->corner_count;
    if (wall < 0 || wall >= n)
        return 0;
    const app_point2 *a = &plan->corners[wall], *b = &plan->corners[(wall + 1) % n];
    return hypot(b->x - a->x, b->y - a->y);
}

/* The outward unit normal of wall `wall`: (uy, -ux) of its direction. 0 for a degenerate one. */
static int outward(const app_room_plan *plan, int wall, double *nx, double *ny)
{
    int n = plan->corner_count;
    if (wall < 0 || wall >= n)
        return 0;
    const app_point2 *a = &plan->corners[wall], *b = &plan->corners[(wall + 1) % n];
    double len = hypot(b->x - a->x, b->y - a->y);
    if (!(len > 0))
        return 0;
    *nx = (b->y - a->y) / len;
    *ny = -(b->x - a->x) / len;
    return 1;
}

double ui_plan_wall_offset(const app_room_plan *plan, int wall, double dx, double dy)
{
    double nx, ny;
    return outward(plan, wall, &nx, &ny) ? dx * nx + dy * ny : 0.0;
}

void ui_plan_wall_moved(const app_room_plan *plan, int wall, double offset_mm, app_point2 *start,
                        app_point2 *end)
{
    int n = plan->corner_count;
    double nx = 0, ny = 0;
    if (!outward(plan, wall, &nx, &ny))
        offset_mm = 0;
    const app_point2 *a = &plan->corners[wall % n], *b = &plan->corners[(wall + 1) % n];
    *start = (app_point2){a->x + offset_mm * nx, a->y + offset_mm * ny};
    *end = (app_point2){b->x + offset_mm * nx, b->y + offset_mm * ny};
}

app_point2 ui_plan_corner_for_length(const app_room_plan *plan, int wall, double length_mm)
{
    int n = plan->corner_count;
    const app_point2 *a = &plan->corners[wall], *b = &plan->corners[(wall + 1) % n];
    double len = hypot(b->x - a->x, b->y - a->y);
    if (len <= 0 || !(length_mm > 0))
        return *b;
    return (app_point2){a->x + (b->x - a->x) * length_mm / len,
                        a->y + (b->y - a->y) * length_mm / len};
}

double ui_plan_snap_grid(double v_mm, double grid_mm)
{
    return grid_mm > 0 ? round(v_mm / grid_mm) * grid_mm : v_mm;
}

int ui_plan_contains(const app_room_plan *plan, double x_mm, double y_mm)
{
    /* The crossing test (W. R. Franklin, "PNPOLY - Point Inclusion in Polygon Test"). */
    int inside = 0, n = plan ? plan->corner_count : 0;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        const app_point2 *a = &plan->corners[i], *b = &plan->corners[j];
        if ((a->y > y_mm) != (b->y > y_mm) &&
            x_mm < (b->x - a->x) * (y_mm - a->y) / (b->y - a->y) + a->x)
            inside = !inside;
    }
    return inside;
}
