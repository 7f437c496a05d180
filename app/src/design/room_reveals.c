/* The faces inside the wall's thickness as tileable surfaces (app/design/room_surfaces.h,
 * docs/tiling.md "Reveals and niches"): a tiler tiles the reveals of a window and the inside of
 * a niche with the wall's tile and hides the cut edge where a reveal meets the wall's face
 * under a trim profile (DOMAIN.md "Setting out tiles"). Each face is a rectangle in a frame of
 * its own; the depths are those the room mesh draws (room_mesh_walls.c): a window's reveals run
 * through the whole wall thickness, a door's to its leaf in the middle of it, a niche's to its
 * back. Only the plan is needed (the project reader checks surface names with it). */
#include "app/design/room_surfaces.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

enum { FACE_LEFT, FACE_RIGHT, FACE_TOP, FACE_BOTTOM, FACE_BACK, FACE_COUNT };
static const char *const face_names[FACE_COUNT] = {"left", "right", "top", "bottom", "back"};

/* One hole through or into a wall: an opening or a niche. */
typedef struct reveal_hole {
    const char *prefix; /* "reveal" or "niche" */
    const char *name;
    int wall;
    double s0, s1, t0, t1, depth;
    int faces; /* bit per FACE_* */
} reveal_hole;

static double wall_thickness(const app_room_plan *plan)
{
    return plan->wall_thickness_mm > 0 ? plan->wall_thickness_mm
                                       : APP_ROOM_DEFAULT_WALL_THICKNESS_MM;
}

/* Hole k of the plan: openings first, then niches; 0 past the end. */
static int hole_at(const app_room_plan *plan, int k, reveal_hole *h)
{
    if (k < plan->opening_count) {
        const app_opening *o = &plan->openings[k];
        int window = o->type == APP_OPENING_WINDOW;
        *h = (reveal_hole){"reveal", o->name, o->wall, o->offset_mm, o->offset_mm + o->width_mm,
                           o->sill_mm, o->sill_mm + o->height_mm,
                           window ? wall_thickness(plan) : 0.5 * wall_thickness(plan),
                           /* a door's floor runs through as the threshold */
                           window ? 0xf : (1 << FACE_LEFT) | (1 << FACE_RIGHT) | (1 << FACE_TOP)};
        return 1;
    }
    k -= plan->opening_count;
    if (k < plan->niche_count) {
        const app_niche *n = &plan->niches[k];
        *h = (reveal_hole){"niche",
                           n->name,
                           n->wall,
                           n->offset_mm,
                           n->offset_mm + n->width_mm,
                           n->sill_mm,
                           n->sill_mm + n->height_mm,
                           n->depth_mm,
                           (1 << FACE_COUNT) - 1};
        return 1;
    }
    return 0;
}

/* Wall i's start corner a, unit direction d and inward normal n (room_mesh.c rm_wall_frame). */
typedef struct wall_axes {
    double a[2], d[2], n[2];
} wall_axes;

static void wall_axes_of(const app_room_plan *plan, int i, wall_axes *w)
{
    app_point2 a = plan->corners[i], e = plan->corners[(i + 1) % plan->corner_count];
    double dx = e.x - a.x, dy = e.y - a.y, len = hypot(dx, dy);
    w->a[0] = a.x;
    w->a[1] = a.y;
    w->d[0] = len > 0 ? dx / len : 1;
    w->d[1] = len > 0 ? dy / len : 0;
    w->n[0] = -w->d[1];
    w->n[1] = w->d[0];
}

static void set3(double *v, double a, double b, double c)
{
    v[0] = a;
    v[1] = b;
    v[2] = c;
}

/* The face's frame and its rectangle in it (s0..s1 x t0..t1), and where the trim edge lies
 * (the reveal's edge on the wall's face): edge_axis 0 = a vertical edge at s = edge_at, 1 = a
 * horizontal edge at t = edge_at; -1 = none (a niche's back). The normal faces out of the
 * face into the opening; the side, top and bottom frames are right-handed (s x t = normal), the
 * back keeps the wall's own axes (as the wall's frame does). */
static void face_geometry(const app_room_plan *plan, const reveal_hole *h, int face,
                          app_room_reveal *out)
{
    wall_axes w;
    wall_axes_of(plan, h->wall, &w);
    memset(out, 0, sizeof *out);
    snprintf(out->frame.surface, sizeof out->frame.surface, "%s:%.64s:%s", h->prefix, h->name,
             face_names[face]);
    out->face = face_names[face];
    double ax = w.a[0], ay = w.a[1], D = h->depth;
    app_surface_frame *f = &out->frame;
    switch (face) {
    case FACE_RIGHT: /* at s0, facing along the wall; s from the back out to the wall's face */
        f->kind = APP_SURFACE_PREWALL_SIDE;
        set3(f->origin_mm, ax + h->s0 * w.d[0] - D * w.n[0], ay + h->s0 * w.d[1] - D * w.n[1], 0);
        set3(f->s_axis, w.n[0], w.n[1], 0);
        set3(f->t_axis, 0, 0, 1);
        set3(f->normal, w.d[0], w.d[1], 0);
        out->s0 = 0, out->s1 = D, out->t0 = h->t0, out->t1 = h->t1;
        out->edge_axis = 0, out->edge_at = D;
        break;
    case FACE_LEFT: /* at s1, facing back along the wall; s from the wall's face inwards */
        f->kind = APP_SURFACE_PREWALL_SIDE;
        set3(f->origin_mm, ax + h->s1 * w.d[0], ay + h->s1 * w.d[1], 0);
        set3(f->s_axis, -w.n[0], -w.n[1], 0);
        set3(f->t_axis, 0, 0, 1);
        set3(f->normal, -w.d[0], -w.d[1], 0);
        out->s0 = 0, out->s1 = D, out->t0 = h->t0, out->t1 = h->t1;
        out->edge_axis = 0, out->edge_at = 0;
        break;
    case FACE_TOP: /* the soffit, facing down; s along the wall, t from the face inwards */
        f->kind = APP_SURFACE_PREWALL_TOP;
        set3(f->origin_mm, ax, ay, h->t1);
        set3(f->s_axis, w.d[0], w.d[1], 0);
        set3(f->t_axis, -w.n[0], -w.n[1], 0);
        set3(f->normal, 0, 0, -1);
        out->s0 = h->s0, out->s1 = h->s1, out->t0 = 0, out->t1 = D;
        out->edge_axis = 1, out->edge_at = 0;
        break;
    case FACE_BOTTOM: /* the sill, facing up; s along the wall, t from the back out */
        f->kind = APP_SURFACE_PREWALL_TOP;
        set3(f->origin_mm, ax - D * w.n[0], ay - D * w.n[1], h->t0);
        set3(f->s_axis, w.d[0], w.d[1], 0);
        set3(f->t_axis, w.n[0], w.n[1], 0);
        set3(f->normal, 0, 0, 1);
        out->s0 = h->s0, out->s1 = h->s1, out->t0 = 0, out->t1 = D;
        out->edge_axis = 1, out->edge_at = D;
        break;
    default: /* a niche's back: the wall's s and t, so its joints can run on from the wall's */
        f->kind = APP_SURFACE_WALL;
        set3(f->origin_mm, ax - D * w.n[0], ay - D * w.n[1], 0);
        set3(f->s_axis, w.d[0], w.d[1], 0);
        set3(f->t_axis, 0, 0, 1);
        set3(f->normal, w.n[0], w.n[1], 0);
        out->s0 = h->s0, out->s1 = h->s1, out->t0 = h->t0, out->t1 = h->t1;
        out->edge_axis = -1;
        break;
    }
}

int app_room_reveal_count(const app_room_plan *plan)
{
    int n = 0;
    reveal_hole h;
    for (int k = 0; hole_at(plan, k, &h); k++)
        for (int face = 0; face < FACE_COUNT; face++)
            n += (h.faces >> face) & 1;
    return n;
}

int app_room_reveals(const app_room_plan *plan, app_room_reveal *out, int max)
{
    int n = 0;
    reveal_hole h;
    for (int k = 0; hole_at(plan, k, &h); k++) {
        if (h.wall < 0 || h.wall >= plan->corner_count)
            continue;
        for (int face = 0; face < FACE_COUNT; face++)
            if ((h.faces >> face) & 1) {
                if (n < max)
                    face_geometry(plan, &h, face, &out[n]);
                n++;
            }
    }
    return n;
}

int app_room_reveal_find(const app_room_plan *plan, const char *surface, app_room_reveal *out)
{
    if (strncmp(surface, "reveal:", 7) && strncmp(surface, "niche:", 6))
        return 0;
    reveal_hole h;
    for (int k = 0; hole_at(plan, k, &h); k++) {
        if (h.wall < 0 || h.wall >= plan->corner_count)
            continue;
        size_t pl = strlen(h.prefix), nl = strlen(h.name);
        if (strncmp(surface, h.prefix, pl) || surface[pl] != ':' ||
            strncmp(surface + pl + 1, h.name, nl) || surface[pl + 1 + nl] != ':')
            continue;
        const char *face = surface + pl + 1 + nl + 1;
        for (int f = 0; f < FACE_COUNT; f++)
            if (((h.faces >> f) & 1) && !strcmp(face, face_names[f])) {
                app_room_reveal r;
                face_geometry(plan, &h, f, &r);
                if (out)
                    *out = r;
                return 1;
            }
    }
    return 0;
}
