/* The room's tileable surfaces as frames and 2D regions (app/design/room_surfaces.h). The wall
 * outline and its ceiling line come from the same functions as the rendered walls
 * (room_mesh.c: rm_wall_frame, rm_ceiling_height), so a tile layout and the wall it is drawn
 * on agree. */
#include "app/design/room_surfaces.h"
#include "room_mesh_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const prewall_faces[4] = {"front", "top", "left", "right"};

/* p's plan, or a 4-corner plan of its room box (version 1 code builds projects in memory). */
typedef struct plan_view {
    app_room_plan plan;
    app_point2 box[4];
} plan_view;

static const app_room_plan *plan_of(const app_project *p, plan_view *v)
{
    if (p->plan.corner_count >= 3 && p->plan.corners)
        return &p->plan;
    memset(v, 0, sizeof *v);
    double w = p->room.width_mm, d = p->room.depth_mm;
    v->box[1] = (app_point2){w, 0};
    v->box[2] = (app_point2){w, d};
    v->box[3] = (app_point2){0, d};
    v->plan.corners = v->box;
    v->plan.corner_count = 4;
    v->plan.height_mm = p->room.height_mm;
    v->plan.wall_thickness_mm = APP_ROOM_DEFAULT_WALL_THICKNESS_MM;
    return &v->plan;
}

static void set3(double *v, double a, double b, double c)
{
    v[0] = a;
    v[1] = b;
    v[2] = c;
}

static void frame_init(app_surface_frame *f, const char *surface, app_surface_kind kind)
{
    memset(f, 0, sizeof *f);
    snprintf(f->surface, sizeof f->surface, "%.95s", surface);
    f->kind = kind;
}

static void wall_frame(const app_room_plan *plan, int i, app_surface_frame *f)
{
    rm_wall w;
    rm_wall_frame(plan, i, &w);
    char name[32];
    snprintf(name, sizeof name, "wall:%d", i);
    frame_init(f, name, APP_SURFACE_WALL);
    set3(f->origin_mm, w.a[0], w.a[1], 0);
    set3(f->s_axis, w.d[0], w.d[1], 0);
    set3(f->t_axis, 0, 0, 1);
    set3(f->normal, w.n[0], w.n[1], 0);
}

static void prewall_frame(const app_room_plan *plan, const app_prewall *pw, int face,
                          app_surface_frame *f)
{
    rm_wall w;
    rm_wall_frame(plan, pw->wall, &w);
    char name[128];
    snprintf(name, sizeof name, "prewall:%s:%s", pw->name, prewall_faces[face]);
    frame_init(f, name, face == 1 ? APP_SURFACE_PREWALL_TOP : APP_SURFACE_PREWALL_SIDE);
    double s_at = face == 2 ? pw->offset_mm + pw->width_mm : pw->offset_mm;
    switch (face) {
    case 0: /* front: the wall's s and t, depth in front of it */
        set3(f->origin_mm, w.a[0] + pw->depth_mm * w.n[0], w.a[1] + pw->depth_mm * w.n[1], 0);
        set3(f->s_axis, w.d[0], w.d[1], 0);
        set3(f->t_axis, 0, 0, 1);
        set3(f->normal, w.n[0], w.n[1], 0);
        break;
    case 1: /* top: s along the wall, t into the room */
        set3(f->origin_mm, w.a[0], w.a[1], pw->height_mm);
        set3(f->s_axis, w.d[0], w.d[1], 0);
        set3(f->t_axis, w.n[0], w.n[1], 0);
        set3(f->normal, 0, 0, 1);
        break;
    default: /* sides: s from the wall into the room, t up */
        set3(f->origin_mm, w.a[0] + s_at * w.d[0], w.a[1] + s_at * w.d[1], 0);
        set3(f->s_axis, w.n[0], w.n[1], 0);
        set3(f->t_axis, 0, 0, 1);
        if (face == 2)
            set3(f->normal, w.d[0], w.d[1], 0);
        else
            set3(f->normal, -w.d[0], -w.d[1], 0);
        break;
    }
}

app_result app_room_surface_list(const app_project *p, app_surface_frame **out, int *count,
                                 char *err, size_t err_size)
{
    plan_view v;
    const app_room_plan *plan = plan_of(p, &v);
    int reveals = app_room_reveal_count(plan);
    int n = 2 + plan->corner_count + 4 * plan->prewall_count + reveals;
    app_surface_frame *f = calloc((size_t)n, sizeof *f);
    *out = NULL;
    *count = 0;
    if (!f) {
        snprintf(err, err_size, "room_surfaces: out of memory (%d surfaces)", n);
        return APP_ERR_OUT_OF_MEMORY;
    }
    int k = 0;
    frame_init(&f[k], "floor", APP_SURFACE_FLOOR);
    set3(f[k].s_axis, 1, 0, 0);
    set3(f[k].t_axis, 0, 1, 0);
    set3(f[k].normal, 0, 0, 1);
    k++;
    frame_init(&f[k], "ceiling", APP_SURFACE_CEILING);
    set3(f[k].origin_mm, 0, 0, plan->height_mm);
    set3(f[k].s_axis, 1, 0, 0);
    set3(f[k].t_axis, 0, 1, 0);
    set3(f[k].normal, 0, 0, -1);
    k++;
    for (int i = 0; i < plan->corner_count; i++)
        wall_frame(plan, i, &f[k++]);
    for (int i = 0; i < plan->prewall_count; i++)
        for (int face = 0; face < 4; face++)
            prewall_frame(plan, &plan->prewalls[i], face, &f[k++]);
    app_room_reveal *rv = reveals > 0 ? calloc((size_t)reveals, sizeof *rv) : NULL;
    if (reveals > 0 && !rv) {
        free(f);
        snprintf(err, err_size, "room_surfaces: out of memory (%d reveals)", reveals);
        return APP_ERR_OUT_OF_MEMORY;
    }
    int nr = app_room_reveals(plan, rv, reveals);
    for (int i = 0; i < nr && i < reveals; i++)
        f[k++] = rv[i].frame;
    free(rv);
    *out = f;
    *count = k;
    return APP_OK;
}

void app_surface_frame_point(const app_surface_frame *f, double s, double t, double out_mm[3])
{
    for (int k = 0; k < 3; k++)
        out_mm[k] = f->origin_mm[k] + s * f->s_axis[k] + t * f->t_axis[k];
}

/* ---- regions -------------------------------------------------------------------------------- */

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The wall's face: (0,0) (L,0) up the end, along the ceiling line (bending where the slope
 * does), down the start. Counter-clockwise in (s, t). */
static app_result wall_outline(const app_room_plan *plan, int i, app_surface_region *r, char *err,
                               size_t err_size)
{
    rm_wall w;
    rm_wall_frame(plan, i, &w);
    double L = w.length, breaks[4] = {L, 0, 0, 0};
    int nb = 1;
    const app_ceiling_slope *sl = &plan->slope;
    if (sl->present) {
        rm_wall sw;
        rm_wall_frame(plan, sl->wall, &sw);
        double d0 = (w.a[0] - sw.a[0]) * sw.n[0] + (w.a[1] - sw.a[1]) * sw.n[1];
        double dd = w.d[0] * sw.n[0] + w.d[1] * sw.n[1];
        for (int k = 0; k < 2 && fabs(dd) > 1e-12; k++) {
            double s = ((k ? sl->run_mm : 0) - d0) / dd;
            if (s > 1e-6 && s < L - 1e-6)
                breaks[nb++] = s;
        }
    }
    breaks[nb++] = 0;
    /* top line from s = L back to s = 0 */
    qsort(breaks, (size_t)nb, sizeof breaks[0], cmp_double);
    app_point2 pts[8];
    int np = 0;
    pts[np++] = (app_point2){0, 0};
    pts[np++] = (app_point2){L, 0};
    for (int k = nb - 1; k >= 0; k--) {
        double s = breaks[k];
        double h = rm_ceiling_height(plan, w.a[0] + s * w.d[0], w.a[1] + s * w.d[1]);
        if (np > 0 && fabs(pts[np - 1].x - s) < 1e-9 && fabs(pts[np - 1].y - h) < 1e-9)
            continue;
        pts[np++] = (app_point2){s, h};
    }
    return app_region_set_outer(r, pts, np, err, err_size);
}

/* A fixture box seen from a wall: the s range it covers and its top, when it stands at most
 * APP_FIXTURE_WALL_GAP_MM in front of the wall's face and overlaps it along the wall. */
static int fixture_on_wall(const rm_wall *w, const app_fixture_box *fx, double *s0, double *s1,
                           double *t0, double *t1)
{
    double smin = HUGE_VAL, smax = -HUGE_VAL, dmin = HUGE_VAL, dmax = -HUGE_VAL;
    for (int c = 0; c < 4; c++) {
        double x = (c & 1) ? fx->max_mm[0] : fx->min_mm[0];
        double y = (c & 2) ? fx->max_mm[1] : fx->min_mm[1];
        double s = (x - w->a[0]) * w->d[0] + (y - w->a[1]) * w->d[1];
        double d = (x - w->a[0]) * w->n[0] + (y - w->a[1]) * w->n[1];
        smin = fmin(smin, s);
        smax = fmax(smax, s);
        dmin = fmin(dmin, d);
        dmax = fmax(dmax, d);
    }
    if (dmax <= 0 || dmin > APP_FIXTURE_WALL_GAP_MM || smax <= 0 || smin >= w->length)
        return 0;
    *s0 = fmax(0, smin);
    *s1 = fmin(w->length, smax);
    *t0 = fmax(0, fx->min_mm[2]);
    *t1 = fx->max_mm[2];
    return *s1 > *s0 && *t1 > *t0;
}

static app_result wall_region(const app_room_plan *plan, int i, const app_fixture_box *fx, int nfx,
                              app_surface_region *r, char *err, size_t err_size)
{
    app_result res = wall_outline(plan, i, r, err, err_size);
    for (int k = 0; res == APP_OK && k < plan->opening_count; k++) {
        const app_opening *o = &plan->openings[k];
        if (o->wall == i)
            res = app_region_add_hole_rect(r, o->offset_mm, o->sill_mm, o->offset_mm + o->width_mm,
                                           o->sill_mm + o->height_mm, APP_HOLE_OPENING, o->name,
                                           err, err_size);
    }
    for (int k = 0; res == APP_OK && k < plan->niche_count; k++) {
        const app_niche *n = &plan->niches[k];
        if (n->wall == i)
            res = app_region_add_hole_rect(r, n->offset_mm, n->sill_mm, n->offset_mm + n->width_mm,
                                           n->sill_mm + n->height_mm, APP_HOLE_NICHE, n->name, err,
                                           err_size);
    }
    for (int k = 0; res == APP_OK && k < plan->prewall_count; k++) {
        const app_prewall *pw = &plan->prewalls[k];
        if (pw->wall == i)
            res =
                app_region_add_hole_rect(r, pw->offset_mm, 0, pw->offset_mm + pw->width_mm,
                                         pw->height_mm, APP_HOLE_COVERED, pw->name, err, err_size);
    }
    rm_wall w;
    rm_wall_frame(plan, i, &w);
    for (int k = 0; res == APP_OK && k < nfx; k++) {
        double s0, s1, t0, t1;
        if (fixture_on_wall(&w, &fx[k], &s0, &s1, &t0, &t1))
            res = app_region_add_hole_rect(r, s0, t0, s1, t1, APP_HOLE_COVERED, fx[k].name, err,
                                           err_size);
    }
    return res;
}

/* The plan polygon; the floor also loses pre-wall footprints and what stands on it. */
static app_result floor_region(const app_room_plan *plan, int is_floor, const app_fixture_box *fx,
                               int nfx, app_surface_region *r, char *err, size_t err_size)
{
    app_result res = app_region_set_outer(r, plan->corners, plan->corner_count, err, err_size);
    if (!is_floor)
        return res;
    for (int k = 0; res == APP_OK && k < plan->prewall_count; k++) {
        const app_prewall *pw = &plan->prewalls[k];
        if (pw->wall < 0 || pw->wall >= plan->corner_count)
            continue;
        rm_wall w;
        rm_wall_frame(plan, pw->wall, &w);
        app_point2 q[4];
        const double s_of[4] = {pw->offset_mm, pw->offset_mm + pw->width_mm,
                                pw->offset_mm + pw->width_mm, pw->offset_mm};
        const double d_of[4] = {0, 0, pw->depth_mm, pw->depth_mm};
        for (int c = 0; c < 4; c++)
            q[c] = (app_point2){w.a[0] + s_of[c] * w.d[0] + d_of[c] * w.n[0],
                                w.a[1] + s_of[c] * w.d[1] + d_of[c] * w.n[1]};
        res = app_region_add_hole(r, q, 4, APP_HOLE_COVERED, pw->name, err, err_size);
    }
    for (int k = 0; res == APP_OK && k < nfx; k++) {
        if (fx[k].min_mm[2] > 10.0) /* wall-hung: the floor under it is tiled */
            continue;
        res =
            app_region_add_hole_rect(r, fx[k].min_mm[0], fx[k].min_mm[1], fx[k].max_mm[0],
                                     fx[k].max_mm[1], APP_HOLE_COVERED, fx[k].name, err, err_size);
    }
    return res;
}

static app_result prewall_region(const app_prewall *pw, int face, app_surface_region *r, char *err,
                                 size_t err_size)
{
    switch (face) {
    case 0:
        return app_region_set_outer_rect(r, pw->offset_mm, 0, pw->offset_mm + pw->width_mm,
                                         pw->height_mm, err, err_size);
    case 1:
        return app_region_set_outer_rect(r, pw->offset_mm, 0, pw->offset_mm + pw->width_mm,
                                         pw->depth_mm, err, err_size);
    default:
        return app_region_set_outer_rect(r, 0, 0, pw->depth_mm, pw->height_mm, err, err_size);
    }
}

app_result app_room_surface_region(const app_project *p, const char *surface,
                                   const app_fixture_box *fixtures, int fixture_count,
                                   app_surface_region *region, app_surface_frame *frame, char *err,
                                   size_t err_size)
{
    memset(region, 0, sizeof *region);
    app_surface_frame *frames = NULL;
    int count = 0;
    app_result r = app_room_surface_list(p, &frames, &count, err, err_size);
    if (r != APP_OK)
        return r;
    int found = -1;
    for (int k = 0; k < count && found < 0; k++)
        if (!strcmp(frames[k].surface, surface))
            found = k;
    if (found < 0) {
        snprintf(err, err_size, "room_surfaces: no surface \"%.96s\" in this room", surface);
        free(frames);
        return APP_ERR_NOT_FOUND;
    }
    if (frame)
        *frame = frames[found];
    app_surface_kind kind = frames[found].kind;
    free(frames);
    plan_view v;
    const app_room_plan *plan = plan_of(p, &v);
    app_surface_region_init(region, surface, kind);
    if (!strcmp(surface, "floor") || !strcmp(surface, "ceiling")) {
        r = floor_region(plan, surface[0] == 'f', fixtures, fixture_count, region, err, err_size);
    } else if (!strncmp(surface, "wall:", 5)) {
        r = wall_region(plan, atoi(surface + 5), fixtures, fixture_count, region, err, err_size);
    } else if (!strncmp(surface, "reveal:", 7) || !strncmp(surface, "niche:", 6)) {
        app_room_reveal rv;
        r = APP_ERR_NOT_FOUND;
        if (app_room_reveal_find(plan, surface, &rv))
            r = app_region_set_outer_rect(region, rv.s0, rv.t0, rv.s1, rv.t1, err, err_size);
    } else {
        /* prewall:NAME:FACE, found above, so the name and face exist */
        const char *colon = strrchr(surface, ':');
        size_t len = (size_t)(colon - (surface + 8));
        r = APP_ERR_NOT_FOUND;
        for (int k = 0; k < plan->prewall_count; k++) {
            const app_prewall *pw = &plan->prewalls[k];
            if (strlen(pw->name) != len || strncmp(pw->name, surface + 8, len))
                continue;
            for (int face = 0; face < 4; face++)
                if (!strcmp(colon + 1, prewall_faces[face]))
                    r = prewall_region(pw, face, region, err, err_size);
            break;
        }
    }
    if (r != APP_OK)
        app_surface_region_free(region);
    return r;
}

app_result app_room_region_provider(void *user, const app_project *p, const char *surface,
                                    app_surface_region *out, char *err, size_t err_size)
{
    const app_room_regions *r = user;
    return app_room_surface_region(p, surface, r ? r->fixtures : NULL, r ? r->fixture_count : 0,
                                   out, NULL, err, err_size);
}
