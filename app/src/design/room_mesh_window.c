/* A window opening: the exterior drawn behind it and the daylight it lets in
 * (docs/rendering.md, "Daylight"; the project's sky in app/daylight/daylight.h).
 *
 *  - the exterior: a panel beyond the outside face, wider than the opening so the reveals frame
 *    it from any angle inside, emitting what a person standing 2 m inside at eye height
 *    (1500 mm) sees through the window: ground below the horizon, the sky model's gradient
 *    above it, in horizontal bands (the surface `window:K`, then `window:K:1`, ...);
 *  - the sky and ground it sees as one rectangle light filling the opening in the outside
 *    face, facing into the room, of their cosine-weighted mean radiance;
 *  - the sun, when it stands on the window's side, as a directional light that comes in only
 *    through the opening (a portal in the middle plane of the wall): the wall shades the rest.
 * The window's `light` colour multiplies all three; 0 lets nothing in and leaves a dim grey
 * panel so that the opening still reads as a window. */
#include "room_mesh_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EYE_HEIGHT_MM 1500.0 /* where the horizon lies on the exterior */
#define EYE_DISTANCE_MM 2000.0
#define BANDS 12

static app_material exterior_material(const app_opening *o, int band, const float radiance[3])
{
    app_material m;
    memset(&m, 0, sizeof m);
    snprintf(m.name, sizeof m.name, "%.50s#sky%d", o->name, band);
    for (int k = 0; k < 3; k++)
        m.emissive[k] = radiance[k];
    m.texture_size_mm[0] = m.texture_size_mm[1] = 1000;
    m.glossiness = 1;
    m.ior = 1.5f;
    return m;
}

static app_light *new_light(rm_build *b)
{
    app_room_geometry *g = b->g;
    app_light *l = realloc(g->lights, (size_t)(g->light_count + 1) * sizeof *l);
    if (!l) {
        b->oom = 1;
        return NULL;
    }
    g->lights = l;
    l = &g->lights[g->light_count++];
    memset(l, 0, sizeof *l);
    l->intensity = 1.0f;
    l->attenuation[0] = 1.0f;
    return l;
}

/* The bands' edges (t, mm) over [t0, t1], the horizon one of them where it falls inside. */
static int band_edges(double t0, double t1, double edges[BANDS + 2])
{
    int n = 0;
    for (int i = 0; i <= BANDS; i++)
        edges[n++] = t0 + (t1 - t0) * i / BANDS;
    if (EYE_HEIGHT_MM > t0 && EYE_HEIGHT_MM < t1) {
        int at = 0;
        while (at < n && edges[at] < EYE_HEIGHT_MM)
            at++;
        if (fabs(edges[at] - EYE_HEIGHT_MM) > 1e-6) {
            memmove(&edges[at + 1], &edges[at], (size_t)(n - at) * sizeof *edges);
            edges[at] = EYE_HEIGHT_MM;
            n++;
        }
    }
    return n;
}

void rm_add_window(rm_build *b, const app_opening *o, const rm_wall *w, double T, const char *name)
{
    double s0 = o->offset_mm, s1 = o->offset_mm + o->width_mm;
    double t0 = o->sill_mm, t1 = o->sill_mm + o->height_mm;
    float tint_peak = fmaxf(o->light[0], fmaxf(o->light[1], o->light[2]));
    double ps0 = s0 - 400, ps1 = s1 + 400, pt0 = t0 - 400, pt1 = t1 + 400, off = -T - 30;
    if (!(tint_peak > 0)) {
        app_room_mesh *m = rm_mesh(b, name, -1);
        if (!m)
            return;
        const float grey[3] = {0.25f, 0.25f, 0.25f};
        m->inline_material = exterior_material(o, 0, grey);
        rm_panel(b, m, w, ps0, ps1, pt0, pt1, off);
        return;
    }
    app_daylight day;
    if (b->p->daylight.year == 0)
        app_daylight_default(&day); /* a project made in memory, not read */
    else
        day = b->p->daylight;
    app_sky sky;
    app_sky_make(&day, &sky);
    const double outward[2] = {-w->n[0], -w->n[1]};

    double edges[BANDS + 2];
    int n = band_edges(pt0, pt1, edges);
    for (int i = 0; i + 1 < n && !b->oom; i++) {
        char band[128];
        if (i == 0)
            snprintf(band, sizeof band, "%s", name);
        else
            snprintf(band, sizeof band, "%s:%d", name, i);
        app_room_mesh *m = rm_mesh(b, band, -1);
        if (!m)
            return;
        double mid = 0.5 * (edges[i] + edges[i + 1]);
        float r[3];
        app_window_view_radiance(&sky, outward, atan2(mid - EYE_HEIGHT_MM, EYE_DISTANCE_MM), r);
        for (int k = 0; k < 3; k++)
            r[k] *= o->light[k];
        m->inline_material = exterior_material(o, i, r);
        m->light_stand_in = 1;
        rm_panel(b, m, w, ps0, ps1, edges[i], edges[i + 1], off);
    }

    /* The opening as a rectangle light in the outside face, facing into the room. */
    float mean[3];
    app_window_mean_radiance(&sky, outward, mean);
    app_light *l = new_light(b);
    if (!l)
        return;
    snprintf(l->name, sizeof l->name, "%.50s#sky", o->name);
    l->type = APP_LIGHT_RECT;
    rm_wall_point(w, 0.5 * (s0 + s1), 0.5 * (t0 + t1), -T, l->position_mm);
    l->direction[0] = w->n[0];
    l->direction[1] = w->n[1];
    l->axis[0] = w->d[0];
    l->axis[1] = w->d[1];
    l->height_axis[2] = 1.0;
    l->width_mm = o->width_mm;
    l->height_mm = o->height_mm;
    for (int k = 0; k < 3; k++)
        l->color[k] = l->specular[k] = mean[k] * o->light[k];

    if (!app_window_sunlit(&sky, outward))
        return;
    l = new_light(b);
    if (!l)
        return;
    snprintf(l->name, sizeof l->name, "%.50s#sun", o->name);
    l->type = APP_LIGHT_DIRECTIONAL;
    rm_wall_point(w, 0.5 * (s0 + s1), 0.5 * (t0 + t1), -0.5 * T, l->position_mm);
    for (int k = 0; k < 3; k++)
        l->direction[k] = -sky.sun[k];
    l->axis[0] = w->d[0];
    l->axis[1] = w->d[1];
    l->height_axis[2] = 1.0;
    l->width_mm = o->width_mm;
    l->height_mm = o->height_mm;
    for (int k = 0; k < 3; k++)
        l->color[k] = l->specular[k] = sky.sun_irradiance * o->light[k];
}
