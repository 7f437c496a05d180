/* $.tilings (version 2): which tile product covers which surface region, in which pattern,
 * with which grout (app/design/room.h app_tiling); and the product reference shared with objects.
 * Surface names are checked against the plan, which is read first. */
#include "project_internal.h"

#include "app/design/room_surfaces.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const pj_pattern_names[6] = {"straight",       "half-offset", "third-offset",
                                         "vertical-stack", "diagonal",    "herringbone"};
const char *const pj_align_names[4] = {"centred", "corner", "line", "auto"};

/* "setout": each surface on its own, or with the room's other "room" tilings (room_setout.c) */
static const char *const setout_names[2] = {"surface", "room"};

static const pj_range HEIGHT = {0.0, APP_PROJECT_MAX_ROOM_MM, 0, 0, 0};
static const pj_range GROUT = {0.0, 100.0, 0, 0, 1};
/* A pattern turned by more than a full turn is a typing mistake; huge angles also lose every
 * digit of precision in sin and cos. */
static const pj_range ROTATION = {-360.0, 360.0, 0, 0, 1};
/* The set-out point lies near the room: within the room limit of either side of it. */
static const pj_range ORIGIN = {-APP_PROJECT_MAX_ROOM_MM, APP_PROJECT_MAX_ROOM_MM, 0, 0, 1};

app_result pj_read_product_ref(pj_ctx *c, const cJSON *obj, const char *key, int required,
                               app_product_ref *out)
{
    const cJSON *item;
    app_result r = pj_member(c, obj, key, cJSON_Object, required, &item);
    if (r != APP_OK || !item)
        return r;
    size_t mark = pj_path_key(c, key);
    memset(out, 0, sizeof *out);
    if ((r = pj_get_string(c, item, "manufacturer", 1, 0, out->manufacturer,
                           sizeof out->manufacturer)) != APP_OK ||
        (r = pj_get_string(c, item, "article", 1, 0, out->article, sizeof out->article)) !=
            APP_OK ||
        (r = pj_get_string(c, item, "variant", 0, 1, out->variant, sizeof out->variant)) != APP_OK)
        return r;
    pj_path_restore(c, mark);
    return APP_OK;
}

/* "floor", "ceiling", "wall:I" (I a wall of the plan), "prewall:NAME:front|top|left|right". */
static app_result check_surface(pj_ctx *c, const char *s)
{
    const app_room_plan *plan = &c->p->plan;
    if (!strcmp(s, "floor") || !strcmp(s, "ceiling") || app_room_reveal_find(plan, s, NULL))
        return APP_OK;
    if (!strncmp(s, "reveal:", 7) || !strncmp(s, "niche:", 6)) {
        pj_path_key(c, "surface");
        return pj_fail(c, APP_ERR_SCHEMA,
                       "no face \"%.96s\" (reveal:OPENING:left|right|top|bottom, no bottom for a "
                       "door; niche:NAME:left|right|top|bottom|back)",
                       s);
    }
    if (!strncmp(s, "wall:", 5)) {
        char *end = NULL;
        long i = strtol(s + 5, &end, 10);
        /* Digits only, without leading zeros: the room names its walls "wall:1", so "wall:01"
         * would name no surface. */
        int canonical = s[5] >= '0' && s[5] <= '9' && (s[5] != '0' || s[6] == '\0');
        if (canonical && end && *end == '\0') {
            if (i < plan->corner_count)
                return APP_OK;
            pj_path_key(c, "surface");
            return pj_fail(c, APP_ERR_SCHEMA, "wall %ld does not exist (the plan has %d walls)", i,
                           plan->corner_count);
        }
    } else if (!strncmp(s, "prewall:", 8)) {
        const char *name = s + 8, *colon = strrchr(name, ':');
        if (colon && colon > name) {
            const char *face = colon + 1;
            int face_ok = !strcmp(face, "front") || !strcmp(face, "top") || !strcmp(face, "left") ||
                          !strcmp(face, "right");
            size_t len = (size_t)(colon - name);
            for (int k = 0; face_ok && k < plan->prewall_count; k++)
                if (strlen(plan->prewalls[k].name) == len &&
                    !strncmp(plan->prewalls[k].name, name, len))
                    return APP_OK;
            pj_path_key(c, "surface");
            if (!face_ok)
                return pj_fail(c, APP_ERR_SCHEMA,
                               "unknown pre-wall face \"%.16s\" (expected front, top, left or "
                               "right)",
                               face);
            return pj_fail(c, APP_ERR_SCHEMA, "no pre-wall named \"%.*s\" in $.plan.prewalls",
                           (int)(len > 64 ? 64 : len), name);
        }
    }
    pj_path_key(c, "surface");
    if (!strncmp(s, "wall:0", 6) && s[6] >= '0' && s[6] <= '9')
        return pj_fail(c, APP_ERR_SCHEMA,
                       "unknown surface \"%.96s\": a wall number has no leading zeros "
                       "(\"wall:%ld\")",
                       s, strtol(s + 5, NULL, 10));
    return pj_fail(c, APP_ERR_SCHEMA,
                   "unknown surface \"%.96s\" (expected floor, ceiling, wall:I, "
                   "prewall:NAME:front|top|left|right, reveal:OPENING:FACE or niche:NAME:FACE)",
                   s);
}

static app_result read_borders(pj_ctx *c, const cJSON *item, app_tiling *t)
{
    const cJSON *list;
    app_result r = pj_member(c, item, "borders", cJSON_Array, 0, &list);
    if (r != APP_OK || !list)
        return r;
    size_t mark = pj_path_key(c, "borders");
    int count = cJSON_GetArraySize(list);
    if (count > APP_TILING_MAX_BORDERS)
        return pj_fail(c, APP_ERR_SCHEMA, "at most %d border rows, got %d", APP_TILING_MAX_BORDERS,
                       count);
    int i = 0;
    for (const cJSON *e = list->child; e; e = e->next, i++) {
        size_t e_mark = pj_path_index(c, i);
        if (!cJSON_IsObject(e))
            return pj_fail(c, APP_ERR_SCHEMA, "expected an object, got %s", pj_type_name(e));
        app_tile_border *b = &t->borders[i];
        if ((r = pj_read_product_ref(c, e, "product", 1, &b->product)) != APP_OK ||
            (r = pj_get_number(c, e, "bottom", 1, HEIGHT, &b->bottom_mm)) != APP_OK)
            return r;
        t->border_count = i + 1;
        pj_path_restore(c, e_mark);
    }
    pj_path_restore(c, mark);
    return APP_OK;
}

static app_result read_tiling(pj_ctx *c, const cJSON *item, int index, void *out)
{
    app_tiling *t = out;
    if (!cJSON_IsObject(item))
        return pj_fail(c, APP_ERR_SCHEMA, "expected an object, got %s", pj_type_name(item));
    pj_default_tiling(t);
    snprintf(t->name, sizeof t->name, "tiling-%d", index);
    int pattern = (int)t->pattern, align = (int)t->align, setout = 0;
    app_result r;
    if ((r = pj_get_string(c, item, "name", 0, 0, t->name, sizeof t->name)) != APP_OK ||
        (r = pj_get_string(c, item, "surface", 1, 0, t->surface, sizeof t->surface)) != APP_OK ||
        (r = check_surface(c, t->surface)) != APP_OK ||
        (r = pj_read_product_ref(c, item, "product", 1, &t->product)) != APP_OK ||
        (r = pj_get_enum(c, item, "pattern", 0, pj_pattern_names, 6, &pattern)) != APP_OK ||
        (r = pj_get_number(c, item, "grout", 0, GROUT, &t->grout_mm)) != APP_OK ||
        (r = pj_get_color(c, item, "grout_color", 0, t->grout_color)) != APP_OK ||
        (r = pj_get_enum(c, item, "align", 0, pj_align_names, 4, &align)) != APP_OK ||
        (r = pj_get_vec(c, item, "origin", 0, 2, ORIGIN, t->origin_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "rotation", 0, ROTATION, &t->rotation_deg)) != APP_OK ||
        (r = pj_get_number(c, item, "from", 0, HEIGHT, &t->from_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "to", 0, HEIGHT, &t->to_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "edge_joint", 0, GROUT, &t->edge_joint_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "min_cut", 0, HEIGHT, &t->min_cut_mm)) != APP_OK ||
        (r = read_borders(c, item, t)) != APP_OK ||
        (r = pj_read_product_ref(c, item, "trim", 0, &t->trim)) != APP_OK ||
        (r = pj_get_enum(c, item, "setout", 0, setout_names, 2, &setout)) != APP_OK)
        return r;
    t->setout_room = setout == 1;
    t->pattern = (app_tile_pattern)pattern;
    t->align = (app_tile_align)align;
    if (t->to_mm != 0 && t->to_mm <= t->from_mm) {
        pj_path_key(c, "to");
        return pj_fail(c, APP_ERR_SCHEMA,
                       "must be above \"from\" (%g mm), or 0 for up to the ceiling, got %g",
                       t->from_mm, t->to_mm);
    }
    return APP_OK;
}

app_result pj_read_tilings(pj_ctx *c, const cJSON *root)
{
    pj_array a = {.size = sizeof *c->p->tilings, .read = read_tiling};
    app_result r = pj_read_array(c, root, "tilings", &a);
    c->p->tilings = a.items;
    c->p->tiling_count = a.count;
    return r;
}
