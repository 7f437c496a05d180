/* The walls of app_room_geometry_build: each wall's inside face split into rectangles around
 * its openings and niches (the top row following a sloped ceiling), the reveals of openings
 * through the wall thickness, niche recesses, window panels and daylight, door leaves, and
 * pre-wall boxes. Wall coordinates: s along the wall from its start corner, t up (mm). */
#include "room_mesh_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_BREAKS 512

typedef struct hole {
    double s0, s1, t0, t1;
} hole;

void rm_wall_point(const rm_wall *w, double s, double t, double off, double out[3])
{
    /* off: distance in front of the inside face (negative: into the wall) */
    out[0] = w->a[0] + s * w->d[0] + off * w->n[0];
    out[1] = w->a[1] + s * w->d[1] + off * w->n[1];
    out[2] = t;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static int sort_unique(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    int m = 0;
    for (int i = 0; i < n; i++)
        if (m == 0 || v[i] - v[m - 1] > 1e-6)
            v[m++] = v[i];
    return m;
}

static int in_hole(const hole *h, int nh, double s, double t)
{
    for (int k = 0; k < nh; k++)
        if (s > h[k].s0 && s < h[k].s1 && t > h[k].t0 && t < h[k].t1)
            return 1;
    return 0;
}

/* The inside face of wall i minus its holes. Rectangles use rm_rect with version 1's frame
 * (origin at the cell's right end seen from inside, u = -d, v = up), so a wall without holes
 * is exactly version 1's wall rectangle. */
static void wall_face(rm_build *b, app_room_mesh *m, const rm_wall *w, const hole *h, int nh)
{
    const app_room_plan *plan = b->plan;
    double L = w->length;
    double sb[MAX_BREAKS], tb[MAX_BREAKS];
    int ns = 0, nt = 0;
    sb[ns++] = 0;
    sb[ns++] = L;
    for (int k = 0; k < nh && ns + 2 < MAX_BREAKS; k++) {
        sb[ns++] = fmax(0, fmin(L, h[k].s0));
        sb[ns++] = fmax(0, fmin(L, h[k].s1));
    }
    const app_ceiling_slope *sl = &plan->slope;
    if (sl->present) {
        /* where the ceiling's height function bends: distance 0 and run from the slope wall */
        rm_wall sw;
        rm_wall_frame(plan, sl->wall, &sw);
        double d0 = (w->a[0] - sw.a[0]) * sw.n[0] + (w->a[1] - sw.a[1]) * sw.n[1];
        double dd = w->d[0] * sw.n[0] + w->d[1] * sw.n[1];
        if (fabs(dd) > 1e-12)
            for (int k = 0; k < 2 && ns < MAX_BREAKS; k++) {
                double s = ((k ? sl->run_mm : 0) - d0) / dd;
                if (s > 0 && s < L)
                    sb[ns++] = s;
            }
    }
    ns = sort_unique(sb, ns);
    const double down_wall[3] = {-w->d[0], -w->d[1], 0}, up[3] = {0, 0, 1};
    double n3[3] = {w->n[0], w->n[1], 0}, tex[2];
    rm_texture_size(b, m, tex);
    for (int i = 0; i + 1 < ns; i++) {
        double sa = sb[i], se = sb[i + 1];
        if (se - sa < 1e-6)
            continue;
        double pa[3], pe[3];
        rm_wall_point(w, sa, 0, 0, pa);
        rm_wall_point(w, se, 0, 0, pe);
        double ha = rm_ceiling_height(plan, pa[0], pa[1]),
               he = rm_ceiling_height(plan, pe[0], pe[1]);
        double hmin = fmin(ha, he);
        nt = 0;
        tb[nt++] = 0;
        for (int k = 0; k < nh && nt + 2 < MAX_BREAKS; k++) {
            if (h[k].s1 <= sa || h[k].s0 >= se)
                continue;
            if (h[k].t0 > 0 && h[k].t0 < hmin)
                tb[nt++] = h[k].t0;
            if (h[k].t1 > 0 && h[k].t1 < hmin)
                tb[nt++] = h[k].t1;
        }
        nt = sort_unique(tb, nt);
        double smid = 0.5 * (sa + se);
        for (int j = 0; j < nt; j++) {
            double ta = tb[j], te = j + 1 < nt ? tb[j + 1] : hmin;
            if (te - ta > 1e-6 && !in_hole(h, nh, smid, 0.5 * (ta + te))) {
                double origin[3];
                rm_wall_point(w, se, ta, 0, origin);
                rm_rect(b, m, origin, down_wall, se - sa, up, te - ta, L - se, ta);
            }
        }
        if (fabs(ha - he) > 1e-6 && !in_hole(h, nh, smid, hmin + 1e-3)) {
            /* the sloped top: a triangle above hmin */
            double p[3][3], uv[3][2];
            rm_wall_point(w, sa, hmin, 0, p[0]);
            rm_wall_point(w, se, hmin, 0, p[1]);
            if (ha > he)
                rm_wall_point(w, sa, ha, 0, p[2]);
            else
                rm_wall_point(w, se, he, 0, p[2]);
            double s_of[3] = {sa, se, ha > he ? sa : se};
            int v[3];
            for (int k = 0; k < 3; k++) {
                uv[k][0] = (L - s_of[k]) / tex[0];
                uv[k][1] = -p[k][2] / tex[1];
                v[k] = rm_vertex(b, m, p[k], n3, uv[k]);
            }
            rm_triangle(b, m, v[0], v[1], v[2], n3);
        }
    }
}

/* The four sides of a hole through depth `depth` (into the wall), facing into the hole;
 * `floor_mesh` (may be NULL) takes the bottom side of a door: a threshold, not a sill. */
static void hole_sides(rm_build *b, app_room_mesh *m, app_room_mesh *bottom_mesh, const rm_wall *w,
                       const hole *h, double depth)
{
    double tex[2];
    rm_texture_size(b, m, tex);
    double p[4][3], uv[4][2];
    /* bottom (normal up) and top (normal down): u along the wall, v into it */
    for (int side = 0; side < 2; side++) {
        app_room_mesh *mm = side == 0 ? bottom_mesh : m;
        if (!mm)
            continue;
        double t = side == 0 ? h->t0 : h->t1;
        const double n[3] = {0, 0, side == 0 ? 1 : -1};
        rm_wall_point(w, h->s0, t, 0, p[0]);
        rm_wall_point(w, h->s1, t, 0, p[1]);
        rm_wall_point(w, h->s1, t, -depth, p[2]);
        rm_wall_point(w, h->s0, t, -depth, p[3]);
        const double s_of[4] = {h->s0, h->s1, h->s1, h->s0}, d_of[4] = {0, 0, depth, depth};
        for (int k = 0; k < 4; k++) {
            uv[k][0] = (w->length - s_of[k]) / tex[0];
            uv[k][1] = -d_of[k] / tex[1];
        }
        rm_quad(b, mm, p, uv, n);
    }
    /* the jambs: at s0 facing +d, at s1 facing -d; u into the wall, v up */
    for (int side = 0; side < 2; side++) {
        double s = side == 0 ? h->s0 : h->s1, sign = side == 0 ? 1 : -1;
        const double n[3] = {sign * w->d[0], sign * w->d[1], 0};
        rm_wall_point(w, s, h->t0, 0, p[0]);
        rm_wall_point(w, s, h->t0, -depth, p[1]);
        rm_wall_point(w, s, h->t1, -depth, p[2]);
        rm_wall_point(w, s, h->t1, 0, p[3]);
        const double d_of[4] = {0, depth, depth, 0}, t_of[4] = {h->t0, h->t0, h->t1, h->t1};
        for (int k = 0; k < 4; k++) {
            uv[k][0] = d_of[k] / tex[0];
            uv[k][1] = -t_of[k] / tex[1];
        }
        rm_quad(b, m, p, uv, n);
    }
}

void rm_panel(rm_build *b, app_room_mesh *m, const rm_wall *w, double s0, double s1, double t0,
              double t1, double off)
{
    double tex[2], p[4][3], uv[4][2];
    rm_texture_size(b, m, tex);
    const double n[3] = {w->n[0], w->n[1], 0};
    const double s_of[4] = {s0, s1, s1, s0}, t_of[4] = {t0, t0, t1, t1};
    for (int k = 0; k < 4; k++) {
        rm_wall_point(w, s_of[k], t_of[k], off, p[k]);
        uv[k][0] = (w->length - s_of[k]) / tex[0];
        uv[k][1] = -t_of[k] / tex[1];
    }
    rm_quad(b, m, p, uv, n);
}

static app_material door_material(const app_opening *o)
{
    app_material m;
    memset(&m, 0, sizeof m);
    snprintf(m.name, sizeof m.name, "%.50s#leaf", o->name);
    const float wood[3] = {0.55f, 0.45f, 0.35f};
    for (int k = 0; k < 3; k++) {
        m.diffuse[k] = m.ambient[k] = wood[k];
        m.specular[k] = 0.15f;
    }
    m.shininess = 40;
    m.texture_size_mm[0] = m.texture_size_mm[1] = 1000;
    m.glossiness = 1;
    m.ior = 1.5f;
    return m;
}

void rm_add_walls(rm_build *b)
{
    const app_room_plan *plan = b->plan;
    const app_project *p = b->p;
    double T =
        plan->wall_thickness_mm > 0 ? plan->wall_thickness_mm : APP_ROOM_DEFAULT_WALL_THICKNESS_MM;
    int hole_cap = plan->opening_count + plan->niche_count + 1;
    hole *holes = malloc((size_t)hole_cap * sizeof *holes);
    if (!holes) {
        b->oom = 1;
        return;
    }
    for (int i = 0; i < plan->corner_count && !b->oom; i++) {
        rm_wall w;
        rm_wall_frame(plan, i, &w);
        char name[96];
        snprintf(name, sizeof name, "wall:%d", i);
        app_room_mesh *m = rm_mesh(b, name, p->room.wall_material);
        if (!m)
            break;
        int nh = 0;
        for (int k = 0; k < plan->opening_count; k++) {
            const app_opening *o = &plan->openings[k];
            if (o->wall == i)
                holes[nh++] = (hole){o->offset_mm, o->offset_mm + o->width_mm, o->sill_mm,
                                     o->sill_mm + o->height_mm};
        }
        for (int k = 0; k < plan->niche_count; k++) {
            const app_niche *n = &plan->niches[k];
            if (n->wall == i)
                holes[nh++] = (hole){n->offset_mm, n->offset_mm + n->width_mm, n->sill_mm,
                                     n->sill_mm + n->height_mm};
        }
        wall_face(b, m, &w, holes, nh);
        /* Reveals and recesses: their own mesh "wall:I:reveals" (same material), so the wall
         * face alone is the tileable area. Windows go through the whole thickness to the panel
         * behind; doors to the leaf in the middle of it, the floor running through as a
         * threshold. Meshes are looked up again after each rm_mesh, which may move them. */
        char reveal_name[96];
        snprintf(reveal_name, sizeof reveal_name, "wall:%d:reveals", i);
        for (int k = 0; k < plan->opening_count && !b->oom; k++) {
            const app_opening *o = &plan->openings[k];
            if (o->wall != i)
                continue;
            hole h = {o->offset_mm, o->offset_mm + o->width_mm, o->sill_mm,
                      o->sill_mm + o->height_mm};
            int window = o->type == APP_OPENING_WINDOW;
            app_room_mesh *sides = rm_mesh(b, reveal_name, p->room.wall_material);
            app_room_mesh *bottom =
                rm_mesh(b, window ? reveal_name : "floor",
                        window ? p->room.wall_material : p->room.floor_material);
            if (!bottom || !sides)
                break;
            hole_sides(b, sides, bottom, &w, &h, window ? T : 0.5 * T);
            char extra[96];
            snprintf(extra, sizeof extra, "%s:%d", window ? "window" : "door", k);
            if (window) {
                rm_add_window(b, o, &w, T, extra); /* room_mesh_window.c */
                continue;
            }
            app_room_mesh *leaf = rm_mesh(b, extra, -1);
            if (!leaf)
                break;
            leaf->inline_material = door_material(o);
            rm_panel(b, leaf, &w, h.s0, h.s1, h.t0, h.t1, -0.5 * T);
        }
        for (int k = 0; k < plan->niche_count && !b->oom; k++) {
            const app_niche *n = &plan->niches[k];
            if (n->wall != i)
                continue;
            app_room_mesh *r = rm_mesh(b, reveal_name, p->room.wall_material);
            if (!r)
                break;
            hole h = {n->offset_mm, n->offset_mm + n->width_mm, n->sill_mm,
                      n->sill_mm + n->height_mm};
            hole_sides(b, r, r, &w, &h, n->depth_mm);
            rm_panel(b, r, &w, h.s0, h.s1, h.t0, h.t1, -n->depth_mm);
        }
    }
    free(holes);
}

void rm_add_prewalls(rm_build *b)
{
    const app_room_plan *plan = b->plan;
    for (int i = 0; i < plan->prewall_count && !b->oom; i++) {
        const app_prewall *pw = &plan->prewalls[i];
        if (pw->wall < 0 || pw->wall >= plan->corner_count)
            continue;
        rm_wall w;
        rm_wall_frame(plan, pw->wall, &w);
        char name[96];
        snprintf(name, sizeof name, "prewall:%s", pw->name);
        app_room_mesh *m = rm_mesh(b, name, b->p->room.wall_material);
        if (!m)
            return;
        double s0 = pw->offset_mm, s1 = pw->offset_mm + pw->width_mm, dp = pw->depth_mm,
               hp = pw->height_mm, tex[2], p[4][3], uv[4][2];
        rm_texture_size(b, m, tex);
        rm_panel(b, m, &w, s0, s1, 0, hp, dp); /* front */
        /* top: normal up, u along the wall, v from the wall out */
        const double up[3] = {0, 0, 1};
        const double s_top[4] = {s0, s1, s1, s0}, d_top[4] = {0, 0, dp, dp};
        for (int k = 0; k < 4; k++) {
            rm_wall_point(&w, s_top[k], hp, d_top[k], p[k]);
            uv[k][0] = (w.length - s_top[k]) / tex[0];
            uv[k][1] = -d_top[k] / tex[1];
        }
        rm_quad(b, m, p, uv, up);
        /* sides: "left" (seen from the room) at s1 facing +d, "right" at s0 facing -d */
        for (int side = 0; side < 2; side++) {
            double s = side == 0 ? s1 : s0, sign = side == 0 ? 1 : -1;
            const double n[3] = {sign * w.d[0], sign * w.d[1], 0};
            const double d_of[4] = {0, dp, dp, 0}, t_of[4] = {0, 0, hp, hp};
            for (int k = 0; k < 4; k++) {
                rm_wall_point(&w, s, t_of[k], d_of[k], p[k]);
                uv[k][0] = d_of[k] / tex[0];
                uv[k][1] = -t_of[k] / tex[1];
            }
            rm_quad(b, m, p, uv, n);
        }
    }
}
