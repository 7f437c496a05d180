/* $.lights: point, spot and directional lights. */
#include "project_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const pj_range SPOT_ANGLE = {0.0, 90.0, 0, 0, 1};

static app_result read_type(pj_ctx *c, const cJSON *item, app_light *l)
{
    const cJSON *t;
    app_result r = pj_member(c, item, "type", cJSON_String, 0, &t);
    if (r != APP_OK || !t)
        return r; /* absent: a point light */
    if (strcmp(t->valuestring, "point") == 0)
        l->type = APP_LIGHT_POINT;
    else if (strcmp(t->valuestring, "spot") == 0)
        l->type = APP_LIGHT_SPOT;
    else if (strcmp(t->valuestring, "directional") == 0)
        l->type = APP_LIGHT_DIRECTIONAL;
    else if (strcmp(t->valuestring, "rect") == 0)
        l->type = APP_LIGHT_RECT;
    else {
        pj_path_key(c, "type");
        return pj_fail(c, APP_ERR_SCHEMA,
                       "unknown light type \"%.*s\" (expected point, spot, directional or rect)",
                       64, t->valuestring);
    }
    return APP_OK;
}

static app_result read_direction(pj_ctx *c, const cJSON *item, app_light *l)
{
    app_result r = pj_get_vec(c, item, "direction", 1, 3, PJ_ANY, l->direction);
    if (r != APP_OK)
        return r;
    double *d = l->direction;
    /* Scale first so that tiny and huge (finite) vectors normalise without under/overflow. */
    double m = fmax(fabs(d[0]), fmax(fabs(d[1]), fabs(d[2])));
    if (m == 0) {
        pj_path_key(c, "direction");
        return pj_fail(c, APP_ERR_SCHEMA, "must not be the zero vector");
    }
    double x = d[0] / m, y = d[1] / m, z = d[2] / m;
    double len = sqrt(x * x + y * y + z * z);
    d[0] = x / len;
    d[1] = y / len;
    d[2] = z / len;
    return APP_OK;
}

/* A rectangle light's size and the direction of its width: given, or horizontal and square
 * to the direction (X when the light faces straight up or down). */
static app_result read_rect(pj_ctx *c, const cJSON *item, app_light *l)
{
    app_result r;
    if ((r = pj_get_number(c, item, "width", 1, PJ_POSITIVE, &l->width_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "height", 1, PJ_POSITIVE, &l->height_mm)) != APP_OK)
        return r;
    const double *d = l->direction;
    double a[3] = {d[1], -d[0], 0}; /* direction x Z */
    if (cJSON_GetObjectItemCaseSensitive(item, "axis")) {
        if ((r = pj_get_vec(c, item, "axis", 1, 3, PJ_ANY, a)) != APP_OK)
            return r;
    } else if (hypot(a[0], a[1]) < 1e-6) {
        a[0] = 1;
        a[1] = a[2] = 0;
    }
    /* Square to the direction: the part of the axis across it. */
    double along = a[0] * d[0] + a[1] * d[1] + a[2] * d[2];
    for (int k = 0; k < 3; k++)
        a[k] -= along * d[k];
    double len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (!(len > 1e-9)) {
        pj_path_key(c, "axis");
        return pj_fail(c, APP_ERR_SCHEMA, "must not be parallel to direction");
    }
    for (int k = 0; k < 3; k++)
        l->axis[k] = a[k] / len;
    l->height_axis[0] = d[1] * l->axis[2] - d[2] * l->axis[1];
    l->height_axis[1] = d[2] * l->axis[0] - d[0] * l->axis[2];
    l->height_axis[2] = d[0] * l->axis[1] - d[1] * l->axis[0];
    return APP_OK;
}

/* Objects are read before lights (project_parse.c), so an emitter can be checked here. */
static int emitter_exists(const app_project *p, const char *name)
{
    for (int i = 0; i < p->object_count; i++)
        if (!strcmp(p->objects[i].name, name))
            return 1;
    return 0;
}

static app_result read_light(pj_ctx *c, const cJSON *item, int index, void *out)
{
    app_light *l = out;
    if (!cJSON_IsObject(item))
        return pj_fail(c, APP_ERR_SCHEMA, "expected an object, got %s", pj_type_name(item));
    pj_default_light(l);
    snprintf(l->name, sizeof l->name, "light-%d", index);
    app_result r;
    if ((r = pj_get_string(c, item, "name", 0, 0, l->name, sizeof l->name)) != APP_OK ||
        (r = read_type(c, item, l)) != APP_OK)
        return r;
    if (l->type != APP_LIGHT_DIRECTIONAL &&
        (r = pj_get_vec(c, item, "position", 1, 3, PJ_ANY, l->position_mm)) != APP_OK)
        return r;
    if (l->type != APP_LIGHT_POINT && (r = read_direction(c, item, l)) != APP_OK)
        return r;
    if ((r = pj_get_color(c, item, "color", 0, l->color)) != APP_OK ||
        (r = pj_get_float(c, item, "intensity", 0, PJ_FLOAT_NONNEG, &l->intensity)) != APP_OK)
        return r;
    memcpy(l->specular, l->color, sizeof l->specular); /* specular defaults to color */
    if ((r = pj_get_color(c, item, "specular", 0, l->specular)) != APP_OK ||
        (r = pj_get_vecf(c, item, "attenuation", 0, 3, PJ_FLOAT_NONNEG, l->attenuation)) != APP_OK)
        return r;
    if (l->type == APP_LIGHT_RECT && (r = read_rect(c, item, l)) != APP_OK)
        return r;
    if (l->attenuation[0] == 0 && l->attenuation[1] == 0 && l->attenuation[2] == 0) {
        pj_path_key(c, "attenuation");
        return pj_fail(c, APP_ERR_SCHEMA, "at least one coefficient must be > 0");
    }
    if (cJSON_GetObjectItemCaseSensitive(item, "emitter")) {
        l->emitter_named = 1;
        if ((r = pj_get_string(c, item, "emitter", 0, 1, l->emitter, sizeof l->emitter)) != APP_OK)
            return r;
        if (l->emitter[0] && !emitter_exists(c->p, l->emitter)) {
            pj_path_key(c, "emitter");
            return pj_fail(c, APP_ERR_SCHEMA,
                           "\"%s\" names no object (the lamp showing light \"%s\")", l->emitter,
                           l->name);
        }
    }
    if (l->type == APP_LIGHT_SPOT) {
        if ((r = pj_get_float(c, item, "inner", 0, SPOT_ANGLE, &l->inner_deg)) != APP_OK ||
            (r = pj_get_float(c, item, "outer", 0, SPOT_ANGLE, &l->outer_deg)) != APP_OK)
            return r;
        /* The falloff is a smoothstep between the two cones; equal edges would divide by 0. */
        if (!(l->inner_deg < l->outer_deg)) {
            pj_path_key(c, "inner");
            return pj_fail(c, APP_ERR_SCHEMA, "must be < outer (%g), got %g", l->outer_deg,
                           l->inner_deg);
        }
    }
    return APP_OK;
}

app_result pj_read_lights(pj_ctx *c, const cJSON *root)
{
    pj_array a = {.size = sizeof *c->p->lights, .read = read_light};
    app_result r = pj_read_array(c, root, "lights", &a);
    c->p->lights = a.items;
    c->p->light_count = a.count;
    return r;
}
