/* $.objects: primitives ("shape"), imported models ("model") and catalog products ("product",
 * version 2) placed in the room. */
#include "project_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const shape_names[] = {"box", "sphere", "cylinder", "plane", "torus"};

static app_result read_shape(pj_ctx *c, const cJSON *shape, app_object *o)
{
    size_t mark = pj_path_key(c, "shape");
    if (!cJSON_IsString(shape))
        return pj_fail(c, APP_ERR_SCHEMA, "expected a string, got %s", pj_type_name(shape));
    for (int k = 0; k < (int)(sizeof shape_names / sizeof shape_names[0]); k++) {
        if (strcmp(shape->valuestring, shape_names[k]) == 0) {
            o->shape = (app_shape)k;
            pj_path_restore(c, mark);
            return APP_OK;
        }
    }
    return pj_fail(c, APP_ERR_SCHEMA,
                   "unknown shape \"%.*s\" (expected box, sphere, cylinder, plane or torus)", 64,
                   shape->valuestring);
}

/* Primitive sizes: all > 0, except a plane's unused z (>= 0, and it may be left out). */
static app_result read_size(pj_ctx *c, const cJSON *item, app_object *o)
{
    const cJSON *size;
    app_result r = pj_member(c, item, "size", cJSON_Array, 1, &size);
    if (r != APP_OK)
        return r;
    size_t mark = pj_path_key(c, "size");
    int count = cJSON_GetArraySize(size);
    int plane = o->shape == APP_SHAPE_PLANE;
    if (count != 3 && !(plane && count == 2))
        return pj_fail(c, APP_ERR_SCHEMA, "expected an array of %s numbers, got %d element%s",
                       plane ? "2 or 3" : "3", count, count == 1 ? "" : "s");
    double v[3] = {0, 0, 0};
    for (int i = 0; i < count; i++) {
        size_t e_mark = pj_path_index(c, i);
        /* Within the room limit: a larger primitive overflows the renderer's float transform. */
        pj_range range = (plane && i == 2) ? (pj_range){0.0, APP_PROJECT_MAX_ROOM_MM, 0, 0, 0}
                                           : (pj_range){0.0, APP_PROJECT_MAX_ROOM_MM, 1, 0, 0};
        if ((r = pj_check_number(c, cJSON_GetArrayItem(size, i), range, &v[i])) != APP_OK)
            return r;
        pj_path_restore(c, e_mark);
    }
    if (o->shape == APP_SHAPE_TORUS && 2 * v[2] > (v[0] < v[1] ? v[0] : v[1])) {
        pj_path_index(c, 2);
        return pj_fail(c, APP_ERR_SCHEMA,
                       "a torus tube (%g) cannot be thicker than half its outer diameter (%g)",
                       v[2], v[0] < v[1] ? v[0] : v[1]);
    }
    memcpy(o->size_mm, v, sizeof v);
    pj_path_restore(c, mark);
    return APP_OK;
}

static app_result read_scale(pj_ctx *c, const cJSON *item, app_object *o)
{
    /* A thousandfold is far beyond any real fixture; 1e300 overflows the float transform the
     * renderer and the path tracer build. */
    static const pj_range SCALE = {-1000.0, 1000.0, 0, 0, 1};
    app_result r = pj_get_vec(c, item, "scale", 0, 3, SCALE, o->scale);
    if (r != APP_OK)
        return r;
    for (int i = 0; i < 3; i++) {
        if (o->scale[i] == 0) {
            pj_path_key(c, "scale");
            pj_path_index(c, i);
            return pj_fail(c, APP_ERR_SCHEMA, "must not be 0");
        }
    }
    return APP_OK;
}

static app_result read_object(pj_ctx *c, const cJSON *item, int index, void *out)
{
    app_object *o = out;
    if (!cJSON_IsObject(item))
        return pj_fail(c, APP_ERR_SCHEMA, "expected an object, got %s", pj_type_name(item));
    pj_default_object(o);
    snprintf(o->name, sizeof o->name, "object-%d", index);
    app_result r = pj_get_string(c, item, "name", 0, 0, o->name, sizeof o->name);
    if (r == APP_OK)
        r = pj_get_string(c, item, "group", 0, 1, o->group, sizeof o->group);
    if (r == APP_OK)
        r = pj_get_string(c, item, "parent", 0, 1, o->parent, sizeof o->parent);
    if (r != APP_OK)
        return r;

    const cJSON *shape = cJSON_GetObjectItemCaseSensitive(item, "shape");
    const cJSON *model = cJSON_GetObjectItemCaseSensitive(item, "model");
    const cJSON *product = cJSON_GetObjectItemCaseSensitive(item, "product");
    if ((shape != NULL) + (model != NULL) + (product != NULL) != 1)
        return pj_fail(c, APP_ERR_SCHEMA, "%s (an object has exactly one of the three)",
                       shape || model || product
                           ? "has more than one of \"shape\", \"model\" and \"product\""
                           : "needs a \"shape\", a \"model\" or a \"product\"");
    if (shape) {
        if ((r = read_shape(c, shape, o)) != APP_OK || (r = read_size(c, item, o)) != APP_OK)
            return r;
    } else if (product) {
        /* A catalog product: its model, size and material are looked up at scene build. */
        if ((r = pj_read_product_ref(c, item, "product", 1, &o->product)) != APP_OK)
            return r;
        o->has_product = 1;
    } else {
        char rel[sizeof o->model];
        if ((r = pj_get_string(c, item, "model", 1, 0, rel, sizeof rel)) != APP_OK)
            return r;
        o->shape = APP_SHAPE_MODEL;
        size_t mark = pj_path_key(c, "model");
        if ((r = pj_resolve_file(c, rel, o->model, sizeof o->model)) != APP_OK)
            return r;
        pj_path_restore(c, mark);
    }
    if ((r = pj_get_vec(c, item, "position", 1, 3, PJ_ANY, o->position_mm)) != APP_OK ||
        (r = pj_get_vec(c, item, "rotation", 0, 3, PJ_ANY, o->rotation_deg)) != APP_OK ||
        (r = read_scale(c, item, o)) != APP_OK)
        return r;

    char inline_name[sizeof o->name + 16];
    snprintf(inline_name, sizeof inline_name, "%s#material", o->name);
    return pj_material_ref(c, item, "material", inline_name, &o->material);
}

app_result pj_read_objects(pj_ctx *c, const cJSON *root)
{
    pj_array a = {.size = sizeof *c->p->objects, .read = read_object};
    app_result r = pj_read_array(c, root, "objects", &a);
    c->p->objects = a.items;
    c->p->object_count = a.count;
    /* A "parent" names another object: the one this object is mounted on. */
    const app_project *p = c->p;
    for (int i = 0; r == APP_OK && i < p->object_count; i++) {
        const char *parent = p->objects[i].parent;
        int found = 0;
        for (int k = 0; parent[0] && k < p->object_count && !found; k++)
            found = k != i && !strcmp(p->objects[k].name, parent);
        if (parent[0] && !found) {
            size_t mark = pj_path_key(c, "objects");
            pj_path_index(c, i);
            pj_path_key(c, "parent");
            r = pj_fail(c, APP_ERR_SCHEMA,
                        "\"%s\" names no other object (the object \"%s\" is mounted on)", parent,
                        p->objects[i].name);
            pj_path_restore(c, mark);
        }
    }
    return r;
}
