/* The drag's snap preview: guides and clear distances (app/design/snap_guides.h). */
#include "app/design/snap_guides.h"

#include "app/project/commands.h"
#include "placement_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* How far a corner or neighbour guide reaches beyond the box's front, mm: far enough to read
 * as a line to follow, short of crossing the room. */
#define GUIDE_REACH_MM 300.0

/* Where the ray o + t d (t >= 0, a unit d) first meets segment a-b; t or INFINITY. A start a
 * hair behind the segment still counts (a side touching a wall measures 0). */
static double ray_segment(const double o[2], const double d[2], const double a[2],
                          const double b[2])
{
    double e[2] = {b[0] - a[0], b[1] - a[1]};
    double den = d[0] * e[1] - d[1] * e[0];
    if (fabs(den) < 1e-12)
        return INFINITY; /* parallel: a face along the ray is not in its way */
    double w[2] = {a[0] - o[0], a[1] - o[1]};
    double t = (w[0] * e[1] - w[1] * e[0]) / den, u = (w[0] * d[1] - w[1] * d[0]) / den;
    return t >= -PL_TOLERANCE_MM && u >= 0 && u <= 1 ? fmax(t, 0) : INFINITY;
}

static double ray_rect(const double o[2], const double d[2], const pl_rect *r)
{
    double c[4][2], best = INFINITY;
    pl_rect_corners(r, c);
    for (int k = 0; k < 4; k++)
        best = fmin(best, ray_segment(o, d, c[k], c[(k + 1) % 4]));
    return best;
}

static int rect_holds(const pl_rect *r, const double q[2])
{
    double x = q[0] - r->c[0], y = q[1] - r->c[1];
    return fabs(x * r->ax[0] + y * r->ax[1]) < r->h[0] - PL_TOLERANCE_MM &&
           fabs(x * r->ay[0] + y * r->ay[1]) < r->h[1] - PL_TOLERANCE_MM;
}

/* The nearest wall, pre-wall or fixture along the ray; skip[] marks objects not in the way. */
static void measure(const app_project *p, const app_fixture *fx, int count, const char *skip,
                    const double o[2], const double d[2], app_snap_dimension *out)
{
    const app_room_plan *pl = &p->plan;
    double t = INFINITY;
    for (int w = 0; w < pl->corner_count; w++) {
        const app_point2 *a = &pl->corners[w], *b = &pl->corners[(w + 1) % pl->corner_count];
        t = fmin(t, ray_segment(o, d, (double[2]){a->x, a->y}, (double[2]){b->x, b->y}));
    }
    for (int k = 0; k < pl->prewall_count; k++) {
        if (pl->prewalls[k].wall < 0 || pl->prewalls[k].wall >= pl->corner_count)
            continue;
        pl_rect r = pl_prewall_rect(pl, k);
        if (!rect_holds(&r, o))
            t = fmin(t, ray_rect(o, d, &r));
    }
    for (int i = 0; i < count; i++) {
        if (fx[i].role != APP_ROLE_FIXTURE || fx[i].object < 0 || fx[i].object >= p->object_count ||
            skip[fx[i].object])
            continue;
        pl_rect r = pl_rect_of_fixture(&fx[i]);
        if (!rect_holds(&r, o))
            t = fmin(t, ray_rect(o, d, &r));
    }
    memset(out, 0, sizeof *out);
    out->a[0] = o[0];
    out->a[1] = o[1];
    if (!isfinite(t))
        return;
    out->found = 1;
    out->b[0] = o[0] + t * d[0];
    out->b[1] = o[1] + t * d[1];
    out->mm = t;
}

/* A guide parallel to the box's side (sign -1 left, +1 right), `beyond` mm out from it (the
 * neighbour's edge the gap away, 0: the side itself), from the back face to beyond the
 * front. */
static app_snap_guide side_guide(const app_snap_preview *s, int sign, double beyond,
                                 app_snap_guide_kind kind)
{
    double a = s->angle_deg * M_PI / 180;
    double ax[2] = {cos(a), sin(a)}, ay[2] = {-sin(a), cos(a)};
    app_snap_guide g = {.kind = kind};
    for (int k = 0; k < 2; k++) {
        double side = s->centre[k] + sign * (s->half[0] + beyond) * ax[k];
        g.a[k] = side - s->half[1] * ay[k];
        g.b[k] = side + (s->half[1] + GUIDE_REACH_MM) * ay[k];
    }
    return g;
}

int app_fixtures_without_group(const app_project *p, int object, app_fixture *fx, int count)
{
    if (!p || object < 0 || object >= p->object_count)
        return count;
    int *members = malloc(((size_t)p->object_count + 1) * sizeof *members);
    if (!members)
        return count;
    int n = app_group_members(p, object, members), kept = 0;
    for (int i = 0; i < count; i++) {
        int in_group = 0;
        for (int k = 0; k < n && !in_group; k++)
            in_group = fx[i].object == members[k];
        if (!in_group)
            fx[kept++] = fx[i];
    }
    free(members);
    return kept;
}

/* The side (-1 left, +1 right) whose clear distance is nearest mm: the one a snap set. */
static int side_at(const app_snap_preview *s, double mm)
{
    const app_snap_dimension *l = &s->sides[APP_SNAP_LEFT], *r = &s->sides[APP_SNAP_RIGHT];
    if (!l->found || !r->found)
        return l->found ? -1 : 1;
    return fabs(l->mm - mm) <= fabs(r->mm - mm) ? -1 : 1;
}

void app_snap_preview_of(const app_project *p, const app_fixture *fx, int count, int index,
                         app_pose in, app_snap_preview *out)
{
    memset(out, 0, sizeof *out);
    out->wall = out->neighbour = -1;
    out->pose = in;
    if (!p || !fx || index < 0 || index >= count)
        return;
    const app_fixture *f = &fx[index];
    const app_room_plan *pl = &p->plan;
    double width = f->width_mm > 0 ? f->width_mm : 2 * f->half[0];
    double depth = f->depth_mm > 0 ? f->depth_mm : 2 * f->half[1];
    /* The box's centre in the object's own frame: it turns with the object. */
    const double *at = f->object >= 0 && f->object < p->object_count
                           ? p->objects[f->object].position_mm
                           : (const double[3]){f->centre[0], f->centre[1], 0};
    double a0 = f->angle_deg * M_PI / 180;
    double rx = f->centre[0] - at[0], ry = f->centre[1] - at[1];
    double local[2] = {rx * cos(a0) + ry * sin(a0), -rx * sin(a0) + ry * cos(a0)};

    /* As the drag's edit snaps it (cmd_script.c `snap wall corner neighbour`). */
    app_pose pose = in, next;
    out->wall = app_snap_to_wall(pl, width, pose, APP_SNAP_WALL_MM, &next);
    if (out->wall >= 0) {
        pose = next;
        out->corner = app_snap_to_corner(pl, width, pose, APP_SNAP_CORNER_MM, 0, &next);
        pose = next;
        app_fixture *others = malloc((size_t)count * sizeof *others);
        if (others) {
            memcpy(others, fx, (size_t)count * sizeof *others);
            int n = app_fixtures_without_group(p, f->object, others, count);
            out->neighbour =
                app_snap_to_neighbour(others, n, f->object, width, depth, pose,
                                      APP_SNAP_NEIGHBOUR_MM, APP_SNAP_NEIGHBOUR_GAP_MM, &next);
            free(others);
            pose = next;
        }
    }
    out->pose = pose;
    double a = pose.rotation_deg * M_PI / 180;
    double ax[2] = {cos(a), sin(a)}, ay[2] = {-sin(a), cos(a)};
    for (int k = 0; k < 2; k++) {
        out->centre[k] = (k ? pose.y : pose.x) + local[0] * ax[k] + local[1] * ay[k];
        out->half[k] = f->half[k];
    }
    out->angle_deg = pose.rotation_deg;

    /* The three clear distances, from the middle of the left and right sides and of the
     * front edge; the fixture and what is mounted on it are not in its way. */
    char *skip = calloc((size_t)p->object_count + 1, 1);
    int *members = malloc(((size_t)p->object_count + 1) * sizeof *members);
    if (skip && members) {
        if (f->object >= 0 && f->object < p->object_count) {
            skip[f->object] = 1;
            int n = app_group_members(p, f->object, members);
            for (int k = 0; k < n; k++)
                skip[members[k]] = 1;
        }
        static const double dirs[APP_SNAP_SIDES][2] = {{-1, 0}, {1, 0}, {0, 1}};
        for (int s = 0; s < APP_SNAP_SIDES; s++) {
            double lx = dirs[s][0] * out->half[0], ly = dirs[s][1] * out->half[1];
            double o[2] = {out->centre[0] + lx * ax[0] + ly * ay[0],
                           out->centre[1] + lx * ax[1] + ly * ay[1]};
            double d[2] = {dirs[s][0] * ax[0] + dirs[s][1] * ay[0],
                           dirs[s][0] * ax[1] + dirs[s][1] * ay[1]};
            measure(p, fx, count, skip, o, d, &out->sides[s]);
        }
    }
    free(skip);
    free(members);

    /* The guides: the face the back stands on, then the side lined up with the corner, and the
     * neighbour's edge the gap away (on the side whose clear distance is the snap's). */
    pl_face face;
    if (out->wall >= 0 && pl_face_of_pose(pl, pose, &face) >= 0) {
        app_snap_guide *g = &out->guides[out->guide_count++];
        g->kind = APP_SNAP_GUIDE_WALL;
        for (int k = 0; k < 2; k++) {
            g->a[k] = face.o[k] + face.d[k] * face.s0 + face.n[k] * face.offset;
            g->b[k] = face.o[k] + face.d[k] * face.s1 + face.n[k] * face.offset;
        }
    }
    if (out->corner)
        out->guides[out->guide_count++] =
            side_guide(out, side_at(out, 0), 0, APP_SNAP_GUIDE_CORNER);
    if (out->neighbour >= 0)
        out->guides[out->guide_count++] =
            side_guide(out, side_at(out, APP_SNAP_NEIGHBOUR_GAP_MM), APP_SNAP_NEIGHBOUR_GAP_MM,
                       APP_SNAP_GUIDE_NEIGHBOUR);
}
