/* $.plan (version 2): the floor plan polygon, wall height and thickness, openings, pre-walls,
 * niches and the sloped ceiling section (app/design/room.h, docs/project-format.md "Plan"). The
 * geometric rules are checked afterwards by pj_check_plan, on the whole plan. */
#include "project_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const pj_opening_type_names[2] = {"door", "window"};
const char *const pj_swing_names[5] = {"in-left", "in-right", "out-left", "out-right", "sliding"};

static const pj_range COORD = {-APP_PROJECT_MAX_ROOM_MM, APP_PROJECT_MAX_ROOM_MM, 0, 0, 1};
static const pj_range LENGTH = {0.0, APP_PROJECT_MAX_ROOM_MM, 1, 0, 0}; /* (0, 1e7] */
/* Openings, pre-walls and niches: at least a millimetre, the trade's unit. A thinner one is a
 * typing mistake and leaves the tile layout a hole without area. (The room itself may be
 * smaller: `tessera extremes` renders a scene of 1 mm.) */
static const pj_range PART = {1.0, APP_PROJECT_MAX_ROOM_MM, 0, 0, 0};     /* [1, 1e7] */
static const pj_range DISTANCE = {0.0, APP_PROJECT_MAX_ROOM_MM, 0, 0, 0}; /* [0, 1e7] */

app_result pj_get_enum(pj_ctx *c, const cJSON *obj, const char *key, int required,
                       const char *const *names, int count, int *out)
{
    const cJSON *item;
    app_result r = pj_member(c, obj, key, cJSON_String, required, &item);
    if (r != APP_OK || !item)
        return r;
    for (int k = 0; k < count; k++) {
        if (strcmp(item->valuestring, names[k]) == 0) {
            *out = k;
            return APP_OK;
        }
    }
    char expected[256];
    size_t n = 0;
    for (int k = 0; k < count && n < sizeof expected; k++)
        n += (size_t)snprintf(expected + n, sizeof expected - n, "%s%s",
                              k == 0           ? ""
                              : k == count - 1 ? " or "
                                               : ", ",
                              names[k]);
    pj_path_key(c, key);
    return pj_fail(c, APP_ERR_SCHEMA, "unknown value \"%.*s\" (expected %s)", 64, item->valuestring,
                   expected);
}

static app_result read_corners(pj_ctx *c, const cJSON *plan_obj, app_room_plan *plan)
{
    const cJSON *list;
    app_result r = pj_member(c, plan_obj, "corners", cJSON_Array, 1, &list);
    if (r != APP_OK)
        return r;
    size_t mark = pj_path_key(c, "corners");
    int count = cJSON_GetArraySize(list);
    if (count < 3 || count > APP_ROOM_MAX_CORNERS)
        return pj_fail(c, APP_ERR_SCHEMA, "a floor plan needs 3 to %d corners, got %d",
                       APP_ROOM_MAX_CORNERS, count);
    plan->corners = pj_calloc((size_t)count, sizeof *plan->corners);
    if (!plan->corners)
        return pj_fail(c, APP_ERR_OUT_OF_MEMORY, "out of memory (%d corners)", count);
    int i = 0;
    for (const cJSON *e = list->child; e; e = e->next, i++) {
        size_t e_mark = pj_path_index(c, i);
        if (!cJSON_IsArray(e) || cJSON_GetArraySize(e) != 2)
            return pj_fail(c, APP_ERR_SCHEMA, "expected [x, y] (2 numbers), got %s",
                           cJSON_IsArray(e) ? "an array of another length" : pj_type_name(e));
        double xy[2];
        for (int k = 0; k < 2; k++) {
            size_t k_mark = pj_path_index(c, k);
            if ((r = pj_check_number(c, cJSON_GetArrayItem(e, k), COORD, &xy[k])) != APP_OK)
                return r;
            pj_path_restore(c, k_mark);
        }
        plan->corners[i].x = xy[0];
        plan->corners[i].y = xy[1];
        pj_path_restore(c, e_mark);
    }
    plan->corner_count = count;
    pj_path_restore(c, mark);
    return APP_OK;
}

/* An array member of plan_obj: allocates *items (count of them, elem_size each). */
static app_result read_list(pj_ctx *c, const cJSON *plan_obj, const char *key, size_t elem_size,
                            void **items, const cJSON **list, int *count)
{
    *count = 0;
    app_result r = pj_member(c, plan_obj, key, cJSON_Array, 0, list);
    if (r != APP_OK || !*list)
        return r;
    pj_path_key(c, key);
    if ((r = pj_check_count(c, *list, key, count)) != APP_OK)
        return r;
    *items = pj_calloc((size_t)*count, elem_size);
    if (!*items)
        return pj_fail(c, APP_ERR_OUT_OF_MEMORY, "out of memory (%d %s)", *count, key);
    return APP_OK;
}

static app_result read_opening(pj_ctx *c, const cJSON *item, int index, app_opening *o)
{
    if (!cJSON_IsObject(item))
        return pj_fail(c, APP_ERR_SCHEMA, "expected an object, got %s", pj_type_name(item));
    int type = 0;
    app_result r = pj_get_enum(c, item, "type", 1, pj_opening_type_names, 2, &type);
    if (r != APP_OK)
        return r;
    pj_default_opening(o, (app_opening_type)type);
    snprintf(o->name, sizeof o->name, "%s-%d", pj_opening_type_names[type], index);
    int swing = (int)o->swing;
    if ((r = pj_get_string(c, item, "name", 0, 0, o->name, sizeof o->name)) != APP_OK ||
        (r = pj_get_int(c, item, "wall", 1, 0, APP_ROOM_MAX_CORNERS - 1, &o->wall)) != APP_OK ||
        (r = pj_get_number(c, item, "offset", 1, DISTANCE, &o->offset_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "width", 1, PART, &o->width_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "height", 1, PART, &o->height_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "sill", 0, DISTANCE, &o->sill_mm)) != APP_OK ||
        (r = pj_get_enum(c, item, "swing", 0, pj_swing_names, 5, &swing)) != APP_OK ||
        (r = pj_get_color(c, item, "light", 0, o->light)) != APP_OK)
        return r;
    o->swing = (app_door_swing)swing;
    return APP_OK;
}

static app_result read_prewall(pj_ctx *c, const cJSON *item, int index, app_prewall *w)
{
    if (!cJSON_IsObject(item))
        return pj_fail(c, APP_ERR_SCHEMA, "expected an object, got %s", pj_type_name(item));
    memset(w, 0, sizeof *w);
    snprintf(w->name, sizeof w->name, "prewall-%d", index);
    app_result r;
    if ((r = pj_get_string(c, item, "name", 0, 0, w->name, sizeof w->name)) != APP_OK ||
        (r = pj_get_int(c, item, "wall", 1, 0, APP_ROOM_MAX_CORNERS - 1, &w->wall)) != APP_OK ||
        (r = pj_get_number(c, item, "offset", 1, DISTANCE, &w->offset_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "width", 1, PART, &w->width_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "depth", 1, PART, &w->depth_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "height", 1, PART, &w->height_mm)) != APP_OK)
        return r;
    if (strchr(w->name, ':')) {
        pj_path_key(c, "name");
        return pj_fail(c, APP_ERR_SCHEMA,
                       "must not contain ':' (it is part of surface names \"prewall:NAME:front\")");
    }
    return APP_OK;
}

static app_result read_niche(pj_ctx *c, const cJSON *item, int index, app_niche *n)
{
    if (!cJSON_IsObject(item))
        return pj_fail(c, APP_ERR_SCHEMA, "expected an object, got %s", pj_type_name(item));
    memset(n, 0, sizeof *n);
    snprintf(n->name, sizeof n->name, "niche-%d", index);
    app_result r;
    if ((r = pj_get_string(c, item, "name", 0, 0, n->name, sizeof n->name)) != APP_OK ||
        (r = pj_get_int(c, item, "wall", 1, 0, APP_ROOM_MAX_CORNERS - 1, &n->wall)) != APP_OK ||
        (r = pj_get_number(c, item, "offset", 1, DISTANCE, &n->offset_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "width", 1, PART, &n->width_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "sill", 1, DISTANCE, &n->sill_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "height", 1, PART, &n->height_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "depth", 1, PART, &n->depth_mm)) != APP_OK)
        return r;
    return APP_OK;
}

static app_result read_slope(pj_ctx *c, const cJSON *plan_obj, app_ceiling_slope *s)
{
    const cJSON *item;
    app_result r = pj_member(c, plan_obj, "slope", cJSON_Object, 0, &item);
    if (r != APP_OK || !item)
        return r;
    size_t mark = pj_path_key(c, "slope");
    if ((r = pj_get_int(c, item, "wall", 1, 0, APP_ROOM_MAX_CORNERS - 1, &s->wall)) != APP_OK ||
        (r = pj_get_number(c, item, "knee", 1, LENGTH, &s->knee_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "run", 1, LENGTH, &s->run_mm)) != APP_OK)
        return r;
    s->present = 1;
    pj_path_restore(c, mark);
    return APP_OK;
}

#define READ_ITEMS(key, field, count_field, fn)                                                    \
    do {                                                                                           \
        const cJSON *list;                                                                         \
        int n;                                                                                     \
        size_t l_mark = c->json_path_len;                                                          \
        if ((r = read_list(c, item, key, sizeof *plan->field, (void **)&plan->field, &list,        \
                           &n)) != APP_OK)                                                         \
            return r;                                                                              \
        int i = 0;                                                                                 \
        for (const cJSON *e = list ? list->child : NULL; e; e = e->next, i++) {                    \
            size_t e_mark = pj_path_index(c, i);                                                   \
            if ((r = fn(c, e, i, &plan->field[i])) != APP_OK)                                      \
                return r;                                                                          \
            plan->count_field = i + 1;                                                             \
            pj_path_restore(c, e_mark);                                                            \
        }                                                                                          \
        pj_path_restore(c, l_mark);                                                                \
    } while (0)

app_result pj_read_plan(pj_ctx *c, const cJSON *root)
{
    const cJSON *item;
    app_result r = pj_member(c, root, "plan", cJSON_Object, 1, &item);
    if (r != APP_OK)
        return r;
    size_t mark = pj_path_key(c, "plan");
    app_room_plan *plan = &c->p->plan;
    pj_default_plan(plan);
    if ((r = read_corners(c, item, plan)) != APP_OK ||
        (r = pj_get_number(c, item, "height", 1, LENGTH, &plan->height_mm)) != APP_OK ||
        (r = pj_get_number(c, item, "wall_thickness", 0, LENGTH, &plan->wall_thickness_mm)) !=
            APP_OK)
        return r;
    READ_ITEMS("openings", openings, opening_count, read_opening);
    READ_ITEMS("prewalls", prewalls, prewall_count, read_prewall);
    READ_ITEMS("niches", niches, niche_count, read_niche);
    if ((r = read_slope(c, item, &plan->slope)) != APP_OK || (r = pj_check_plan(c, plan)) != APP_OK)
        return r;
    pj_path_restore(c, mark);
    pj_room_from_plan(c->p);
    return APP_OK;
}

void pj_room_from_plan(app_project *p)
{
    const app_room_plan *plan = &p->plan;
    if (plan->corner_count < 1 || !plan->corners)
        return;
    double x0 = plan->corners[0].x, x1 = x0, y0 = plan->corners[0].y, y1 = y0;
    for (int i = 1; i < plan->corner_count; i++) {
        x0 = fmin(x0, plan->corners[i].x);
        x1 = fmax(x1, plan->corners[i].x);
        y0 = fmin(y0, plan->corners[i].y);
        y1 = fmax(y1, plan->corners[i].y);
    }
    p->room.width_mm = x1 - x0;
    p->room.depth_mm = y1 - y0;
    p->room.height_mm = plan->height_mm;
}
