/* The value every optional field takes when the file leaves it out (docs/project-format.md,
 * "Defaults"). The reader fills these in first and then overwrites what the file gives. */
#include "project_internal.h"

#include <string.h>

static void set3f(float *v, float a, float b, float c)
{
    v[0] = a;
    v[1] = b;
    v[2] = c;
}

static void set3d(double *v, double a, double b, double c)
{
    v[0] = a;
    v[1] = b;
    v[2] = c;
}

void pj_default_material(app_material *m)
{
    memset(m, 0, sizeof *m);
    set3f(m->diffuse, 0.8f, 0.8f, 0.8f);
    set3f(m->ambient, 0.8f, 0.8f, 0.8f); /* = diffuse; the reader copies a given diffuse */
    m->shininess = 32.0f;
    m->texture_size_mm[0] = 1000.0f;
    m->texture_size_mm[1] = 1000.0f;
    m->glossiness = 1.0f;
    m->ior = 1.5f;
}

void pj_default_object(app_object *o)
{
    memset(o, 0, sizeof *o);
    o->shape = APP_SHAPE_BOX;
    set3d(o->scale, 1, 1, 1);
}

void pj_default_light(app_light *l)
{
    memset(l, 0, sizeof *l);
    l->type = APP_LIGHT_POINT;
    set3d(l->direction, 0, 0, -1);
    set3f(l->color, 1, 1, 1);
    l->intensity = 1.0f;
    set3f(l->specular, 1, 1, 1); /* = color; the reader copies a given color */
    set3f(l->attenuation, 1, 0, 1);
    l->inner_deg = 25.0f;
    l->outer_deg = 35.0f;
}

void pj_default_camera(app_camera *cam)
{
    memset(cam, 0, sizeof *cam);
    set3d(cam->up, 0, 0, 1);
    cam->fov_deg = 60.0;
}

void pj_default_render(app_render_settings *r)
{
    memset(r, 0, sizeof *r);
    set3f(r->ambient, 0.1f, 0.1f, 0.1f);
    r->exposure_ev = 0.0f;
    r->exposure_auto = 1;
    r->tone = APP_TONE_NEUTRAL;
    r->white = 4.0f;
    r->width = 1280;
    r->height = 720;
    r->supersample = 1;
}

void pj_default_plan(app_room_plan *plan)
{
    memset(plan, 0, sizeof *plan);
    plan->wall_thickness_mm = APP_ROOM_DEFAULT_WALL_THICKNESS_MM;
}

/* Windows let daylight in unless told otherwise (app_opening.light); doors none. */
void pj_default_opening(app_opening *o, app_opening_type type)
{
    memset(o, 0, sizeof *o);
    o->type = type;
    o->swing = APP_SWING_IN_LEFT;
    if (type == APP_OPENING_WINDOW)
        set3f(o->light, 1.0f, 1.0f, 1.0f);
}

void pj_default_tiling(app_tiling *t)
{
    memset(t, 0, sizeof *t);
    t->pattern = APP_PATTERN_STRAIGHT;
    t->align = APP_ALIGN_AUTO;                /* the set-out solver, until the user fixes a start */
    t->edge_joint_mm = -1;                    /* the joint width */
    set3f(t->grout_color, 0.6f, 0.6f, 0.58f); /* a light grey cement grout */
}
