/* The version 2 parts of the writer: $.plan, $.tilings and product references. Like
 * project_to_json.c it checks only the structure (counts, pointers, finite numbers, terminated
 * strings, enum values); the value rules are the reader's, applied to the written text. */
#include "project_internal.h"

#include <math.h>
#include <string.h>

typedef struct pb {
    pj_ctx *c;
    app_result r;
} pb;

static void fail_oom(pb *b)
{
    if (b->r == APP_OK)
        b->r = pj_fail(b->c, APP_ERR_OUT_OF_MEMORY, "out of memory");
}

static void add(pb *b, cJSON *parent, const char *key, cJSON *item)
{
    if (b->r != APP_OK || !parent) {
        cJSON_Delete(item);
        return;
    }
    if (!item) {
        fail_oom(b);
        return;
    }
    cJSON_bool ok =
        key ? cJSON_AddItemToObject(parent, key, item) : cJSON_AddItemToArray(parent, item);
    if (!ok) {
        cJSON_Delete(item);
        fail_oom(b);
    }
}

static cJSON *container(pb *b, cJSON *parent, const char *key, int array)
{
    if (b->r != APP_OK)
        return NULL;
    cJSON *item = array ? cJSON_CreateArray() : cJSON_CreateObject();
    add(b, parent, key, item);
    return b->r == APP_OK ? item : NULL;
}

static void num(pb *b, cJSON *obj, const char *key, double v)
{
    if (b->r != APP_OK)
        return;
    if (!isfinite(v)) {
        pj_path_key(b->c, key);
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "cannot write a non-finite number (%g)", v);
        return;
    }
    add(b, obj, key, pj_json_double(v));
}

static void vec(pb *b, cJSON *obj, const char *key, const double *d, const float *f, int n)
{
    if (b->r != APP_OK)
        return;
    for (int i = 0; i < n; i++) {
        double v = d ? d[i] : (double)f[i];
        if (!isfinite(v)) {
            pj_path_key(b->c, key);
            pj_path_index(b->c, i);
            b->r = pj_fail(b->c, APP_ERR_SCHEMA, "cannot write a non-finite number (%g)", v);
            return;
        }
    }
    cJSON *arr = container(b, obj, key, 1);
    for (int i = 0; i < n && b->r == APP_OK; i++)
        add(b, arr, NULL, d ? pj_json_double(d[i]) : pj_json_float(f[i]));
}

static void str(pb *b, cJSON *obj, const char *key, const char *s, size_t cap)
{
    if (b->r != APP_OK)
        return;
    if (!memchr(s, '\0', cap)) {
        pj_path_key(b->c, key);
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "string is not terminated within %zu bytes", cap);
        return;
    }
    add(b, obj, key, cJSON_CreateString(s));
}

static void name_of(pb *b, cJSON *obj, const char *key, int value, const char *const *names,
                    int count)
{
    if (b->r != APP_OK)
        return;
    if (value < 0 || value >= count) {
        pj_path_key(b->c, key);
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "unknown %s value %d", key, value);
        return;
    }
    add(b, obj, key, cJSON_CreateString(names[value]));
}

static int list_ok(pb *b, const char *key, const void *items, int count, int max)
{
    if (b->r != APP_OK)
        return 0;
    if (count < 0 || count > max || (count > 0 && !items)) {
        pj_path_key(b->c, key);
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "invalid list (count %d%s)", count,
                       count > 0 && !items ? ", no items" : "");
        return 0;
    }
    return 1;
}

cJSON *pj_product_ref_to_json(const app_product_ref *ref)
{
    if (!memchr(ref->manufacturer, '\0', sizeof ref->manufacturer) ||
        !memchr(ref->article, '\0', sizeof ref->article) ||
        !memchr(ref->variant, '\0', sizeof ref->variant))
        return NULL;
    cJSON *o = cJSON_CreateObject();
    if (!o || !cJSON_AddStringToObject(o, "manufacturer", ref->manufacturer) ||
        !cJSON_AddStringToObject(o, "article", ref->article) ||
        (ref->variant[0] && !cJSON_AddStringToObject(o, "variant", ref->variant))) {
        cJSON_Delete(o);
        return NULL;
    }
    return o;
}

static void product(pb *b, cJSON *obj, const char *key, const app_product_ref *ref)
{
    if (b->r != APP_OK)
        return;
    cJSON *o = pj_product_ref_to_json(ref);
    if (!o && (!memchr(ref->manufacturer, '\0', sizeof ref->manufacturer) ||
               !memchr(ref->article, '\0', sizeof ref->article) ||
               !memchr(ref->variant, '\0', sizeof ref->variant))) {
        pj_path_key(b->c, key);
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "a product reference string is not terminated");
        return;
    }
    add(b, obj, key, o);
}

/* One corner [x, y], numbers printed exactly (pj_json_double). */
static void put_point(pb *b, cJSON *list, double x, double y)
{
    if (b->r != APP_OK)
        return;
    if (!isfinite(x) || !isfinite(y)) {
        pj_path_index(b->c, isfinite(x) ? 1 : 0);
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "cannot write a non-finite number (%g)",
                       isfinite(x) ? y : x);
        return;
    }
    cJSON *pt = container(b, list, NULL, 1);
    add(b, pt, NULL, pj_json_double(x));
    add(b, pt, NULL, pj_json_double(y));
}

static void put_corners(pb *b, cJSON *plan, const app_project *p)
{
    cJSON *corners = container(b, plan, "corners", 1);
    size_t mark = pj_path_key(b->c, "corners");
    if (p->plan.corner_count > 0) {
        for (int i = 0; i < p->plan.corner_count && b->r == APP_OK; i++) {
            size_t i_mark = pj_path_index(b->c, i);
            put_point(b, corners, p->plan.corners[i].x, p->plan.corners[i].y);
            if (b->r == APP_OK)
                pj_path_restore(b->c, i_mark);
        }
    } else {
        /* A project built in memory by version 1 code: its room box. */
        const double w = p->room.width_mm, d = p->room.depth_mm;
        put_point(b, corners, 0, 0);
        put_point(b, corners, w, 0);
        put_point(b, corners, w, d);
        put_point(b, corners, 0, d);
    }
    if (b->r == APP_OK)
        pj_path_restore(b->c, mark);
}

static void put_openings(pb *b, cJSON *plan, const app_room_plan *rp)
{
    if (rp->opening_count == 0)
        return;
    cJSON *list = container(b, plan, "openings", 1);
    size_t mark = pj_path_key(b->c, "openings");
    for (int i = 0; i < rp->opening_count && b->r == APP_OK; i++) {
        const app_opening *o = &rp->openings[i];
        size_t i_mark = pj_path_index(b->c, i);
        cJSON *e = container(b, list, NULL, 0);
        str(b, e, "name", o->name, sizeof o->name);
        name_of(b, e, "type", (int)o->type, pj_opening_type_names, 2);
        num(b, e, "wall", o->wall);
        num(b, e, "offset", o->offset_mm);
        num(b, e, "width", o->width_mm);
        num(b, e, "height", o->height_mm);
        num(b, e, "sill", o->sill_mm);
        if (o->type == APP_OPENING_DOOR)
            name_of(b, e, "swing", (int)o->swing, pj_swing_names, 5);
        else
            vec(b, e, "light", NULL, o->light, 3);
        if (b->r == APP_OK)
            pj_path_restore(b->c, i_mark);
    }
    if (b->r == APP_OK)
        pj_path_restore(b->c, mark);
}

static void put_prewalls_niches(pb *b, cJSON *plan, const app_room_plan *rp)
{
    if (rp->prewall_count > 0) {
        cJSON *list = container(b, plan, "prewalls", 1);
        size_t mark = pj_path_key(b->c, "prewalls");
        for (int i = 0; i < rp->prewall_count && b->r == APP_OK; i++) {
            const app_prewall *w = &rp->prewalls[i];
            size_t i_mark = pj_path_index(b->c, i);
            cJSON *e = container(b, list, NULL, 0);
            str(b, e, "name", w->name, sizeof w->name);
            num(b, e, "wall", w->wall);
            num(b, e, "offset", w->offset_mm);
            num(b, e, "width", w->width_mm);
            num(b, e, "depth", w->depth_mm);
            num(b, e, "height", w->height_mm);
            if (b->r == APP_OK)
                pj_path_restore(b->c, i_mark);
        }
        if (b->r == APP_OK)
            pj_path_restore(b->c, mark);
    }
    if (rp->niche_count > 0) {
        cJSON *list = container(b, plan, "niches", 1);
        size_t mark = pj_path_key(b->c, "niches");
        for (int i = 0; i < rp->niche_count && b->r == APP_OK; i++) {
            const app_niche *n = &rp->niches[i];
            size_t i_mark = pj_path_index(b->c, i);
            cJSON *e = container(b, list, NULL, 0);
            str(b, e, "name", n->name, sizeof n->name);
            num(b, e, "wall", n->wall);
            num(b, e, "offset", n->offset_mm);
            num(b, e, "width", n->width_mm);
            num(b, e, "sill", n->sill_mm);
            num(b, e, "height", n->height_mm);
            num(b, e, "depth", n->depth_mm);
            if (b->r == APP_OK)
                pj_path_restore(b->c, i_mark);
        }
        if (b->r == APP_OK)
            pj_path_restore(b->c, mark);
    }
}

app_result pj_plan_to_json(pj_ctx *c, const app_project *p, cJSON *root)
{
    pb b = {c, APP_OK};
    const app_room_plan *rp = &p->plan;
    size_t mark = pj_path_key(c, "plan");
    if (!list_ok(&b, "corners", rp->corners, rp->corner_count, APP_ROOM_MAX_CORNERS) ||
        !list_ok(&b, "openings", rp->openings, rp->opening_count, APP_PROJECT_MAX_ITEMS) ||
        !list_ok(&b, "prewalls", rp->prewalls, rp->prewall_count, APP_PROJECT_MAX_ITEMS) ||
        !list_ok(&b, "niches", rp->niches, rp->niche_count, APP_PROJECT_MAX_ITEMS))
        return b.r;
    if (rp->corner_count == 0) {
        /* Version 1 code sets only the room box: check it with the version 1 paths. */
        pj_path_restore(c, mark);
        pj_path_key(c, "room");
        const char *keys[3] = {"width", "depth", "height"};
        double v[3] = {p->room.width_mm, p->room.depth_mm, p->room.height_mm};
        for (int k = 0; k < 3; k++) {
            if (!(v[k] > 0) || !(v[k] <= APP_PROJECT_MAX_ROOM_MM)) {
                pj_path_key(c, keys[k]);
                return pj_fail(c, APP_ERR_SCHEMA, "must be %s, got %g",
                               v[k] > 0 ? "<= 1e+07" : "> 0", v[k]);
            }
        }
        pj_path_restore(c, mark);
        pj_path_key(c, "plan");
    }
    cJSON *plan = container(&b, root, "plan", 0);
    put_corners(&b, plan, p);
    num(&b, plan, "height", rp->corner_count > 0 ? rp->height_mm : p->room.height_mm);
    num(&b, plan, "wall_thickness",
        rp->corner_count > 0 ? rp->wall_thickness_mm : APP_ROOM_DEFAULT_WALL_THICKNESS_MM);
    put_openings(&b, plan, rp);
    put_prewalls_niches(&b, plan, rp);
    if (rp->slope.present && b.r == APP_OK) {
        size_t s_mark = pj_path_key(c, "slope");
        cJSON *s = container(&b, plan, "slope", 0);
        num(&b, s, "wall", rp->slope.wall);
        num(&b, s, "knee", rp->slope.knee_mm);
        num(&b, s, "run", rp->slope.run_mm);
        if (b.r == APP_OK)
            pj_path_restore(c, s_mark);
    }
    if (b.r == APP_OK)
        pj_path_restore(c, mark);
    return b.r;
}

static void put_tiling(pb *b, cJSON *list, const app_tiling *t)
{
    cJSON *e = container(b, list, NULL, 0);
    str(b, e, "name", t->name, sizeof t->name);
    str(b, e, "surface", t->surface, sizeof t->surface);
    product(b, e, "product", &t->product);
    name_of(b, e, "pattern", (int)t->pattern, pj_pattern_names, 6);
    num(b, e, "grout", t->grout_mm);
    vec(b, e, "grout_color", NULL, t->grout_color, 3);
    name_of(b, e, "align", (int)t->align, pj_align_names, 4);
    vec(b, e, "origin", t->origin_mm, NULL, 2);
    num(b, e, "rotation", t->rotation_deg);
    num(b, e, "from", t->from_mm);
    num(b, e, "to", t->to_mm);
    if (t->edge_joint_mm >= 0)
        num(b, e, "edge_joint", t->edge_joint_mm);
    if (t->min_cut_mm > 0)
        num(b, e, "min_cut", t->min_cut_mm);
    if (t->trim.article[0])
        product(b, e, "trim", &t->trim);
    if (t->setout_room)
        str(b, e, "setout", "room", 5);
    if (b->r != APP_OK || t->border_count == 0)
        return;
    if (t->border_count < 0 || t->border_count > APP_TILING_MAX_BORDERS) {
        pj_path_key(b->c, "borders");
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "invalid border count %d", t->border_count);
        return;
    }
    cJSON *borders = container(b, e, "borders", 1);
    size_t mark = pj_path_key(b->c, "borders");
    for (int i = 0; i < t->border_count && b->r == APP_OK; i++) {
        size_t i_mark = pj_path_index(b->c, i);
        cJSON *o = container(b, borders, NULL, 0);
        product(b, o, "product", &t->borders[i].product);
        num(b, o, "bottom", t->borders[i].bottom_mm);
        if (b->r == APP_OK)
            pj_path_restore(b->c, i_mark);
    }
    if (b->r == APP_OK)
        pj_path_restore(b->c, mark);
}

app_result pj_tilings_to_json(pj_ctx *c, const app_project *p, cJSON *root)
{
    pb b = {c, APP_OK};
    if (!list_ok(&b, "tilings", p->tilings, p->tiling_count, APP_PROJECT_MAX_ITEMS))
        return b.r;
    cJSON *list = container(&b, root, "tilings", 1);
    size_t mark = pj_path_key(c, "tilings");
    for (int i = 0; i < p->tiling_count && b.r == APP_OK; i++) {
        size_t i_mark = pj_path_index(c, i);
        put_tiling(&b, list, &p->tilings[i]);
        if (b.r == APP_OK)
            pj_path_restore(c, i_mark);
    }
    if (b.r == APP_OK)
        pj_path_restore(c, mark);
    return b.r;
}
