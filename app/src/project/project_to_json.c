/* app_project -> JSON tree (format version APP_PROJECT_VERSION). Checks what the tree needs
 * from the structure (counts, material indices, finite numbers, terminated strings); the value
 * rules are checked afterwards by reading the text back (project_write.c). Every field is
 * written, defaults included, so a file says everything it means. */
#include "project_internal.h"

#include <stdio.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A builder with a sticky result: after the first failure every call does nothing. */
typedef struct jb {
    pj_ctx *c;
    app_result r;
    const app_project *p;
    const char *dest_dir; /* absolute folder the file goes to, or NULL */
} jb;

static void oom(jb *b)
{
    if (b->r == APP_OK)
        b->r = pj_fail(b->c, APP_ERR_OUT_OF_MEMORY, "out of memory");
}

static void attach(jb *b, cJSON *parent, const char *key, cJSON *item)
{
    if (!item) {
        oom(b);
        return;
    }
    cJSON_bool ok =
        key ? cJSON_AddItemToObject(parent, key, item) : cJSON_AddItemToArray(parent, item);
    if (!ok) {
        cJSON_Delete(item);
        oom(b);
    }
}

static cJSON *put_container(jb *b, cJSON *parent, const char *key, int array)
{
    if (b->r != APP_OK)
        return NULL;
    cJSON *item = array ? cJSON_CreateArray() : cJSON_CreateObject();
    attach(b, parent, key, item);
    return b->r == APP_OK ? item : NULL;
}

static int finite_or_fail(jb *b, double v)
{
    if (isfinite(v))
        return 1;
    b->r = pj_fail(b->c, APP_ERR_SCHEMA, "cannot write a non-finite number (%g)", v);
    return 0;
}

static void put_num(jb *b, cJSON *obj, const char *key, double v, int is_float)
{
    if (b->r != APP_OK)
        return;
    size_t mark = pj_path_key(b->c, key);
    if (!finite_or_fail(b, v))
        return;
    pj_path_restore(b->c, mark);
    attach(b, obj, key, is_float ? pj_json_float((float)v) : pj_json_double(v));
}

static void put_vec(jb *b, cJSON *obj, const char *key, const double *d, const float *f, int n)
{
    cJSON *arr = put_container(b, obj, key, 1);
    if (!arr)
        return;
    size_t mark = pj_path_key(b->c, key);
    for (int i = 0; i < n && b->r == APP_OK; i++) {
        size_t m = pj_path_index(b->c, i);
        double v = d ? d[i] : (double)f[i];
        if (!finite_or_fail(b, v))
            return;
        pj_path_restore(b->c, m);
        attach(b, arr, NULL, d ? pj_json_double(v) : pj_json_float(f[i]));
    }
    pj_path_restore(b->c, mark);
}

/* Fixed-size name fields must hold a terminated string. */
static void put_str(jb *b, cJSON *obj, const char *key, const char *s, size_t cap)
{
    if (b->r != APP_OK)
        return;
    if (!memchr(s, '\0', cap)) {
        pj_path_key(b->c, key);
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "string is not terminated within %zu bytes", cap);
        return;
    }
    attach(b, obj, key, cJSON_CreateString(s));
}

/* A stored absolute path, written relative to the destination's folder when possible. */
static void put_path(jb *b, cJSON *obj, const char *key, const char *path, size_t cap)
{
    if (b->r != APP_OK)
        return;
    if (!memchr(path, '\0', cap)) {
        put_str(b, obj, key, path, cap); /* reports the missing terminator */
        return;
    }
    if (path[0] != '/' || !b->dest_dir) {
        put_str(b, obj, key, path, cap);
        return;
    }
    char *rel = pj_relative_path(b->dest_dir, path);
    if (!rel) {
        oom(b);
        return;
    }
    attach(b, obj, key, cJSON_CreateString(rel));
    free(rel);
}

static const char *material_name(jb *b, int index)
{
    if (index < 0 || index >= b->p->material_count) {
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "material index %d out of range (%d materials)", index,
                       b->p->material_count);
        return NULL;
    }
    const app_material *m = &b->p->materials[index];
    if (!memchr(m->name, '\0', sizeof m->name)) {
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "the name of material %d is not terminated", index);
        return NULL;
    }
    return m->name;
}

static void put_material_ref(jb *b, cJSON *obj, const char *key, int index)
{
    if (b->r != APP_OK)
        return;
    size_t mark = pj_path_key(b->c, key);
    const char *name = material_name(b, index);
    if (!name)
        return;
    pj_path_restore(b->c, mark);
    attach(b, obj, key, cJSON_CreateString(name));
}

/* Only what differs from the defaults, so plain materials stay plain in the file. */
static void put_reflection(jb *b, cJSON *o, const app_material *m)
{
    if (m->reflectivity != 0.0f)
        put_num(b, o, "reflectivity", m->reflectivity, 1);
    if (m->glossiness != 1.0f)
        put_num(b, o, "glossiness", m->glossiness, 1);
    if (m->blend > 0 && m->blend < 3)
        put_str(b, o, "blend", pj_blend_names[m->blend], 32);
    if (m->transparency != 0.0f)
        put_num(b, o, "transparency", m->transparency, 1);
    if (m->ior != 1.5f)
        put_num(b, o, "ior", m->ior, 1);
    if (m->dispersion != 0.0f)
        put_num(b, o, "dispersion", m->dispersion, 1);
    if (m->pattern > 0 && m->pattern < 2)
        put_str(b, o, "pattern", pj_material_pattern_names[m->pattern], 32);
    if (m->grain_deg == 90.0f)
        put_str(b, o, "grain", "vertical", 32);
    else if (m->grain_deg != 0.0f)
        put_num(b, o, "grain", m->grain_deg, 1);
    if (!m->correction && !m->probe_update && !m->probe_every && !m->probe_resolution &&
        m->proxy_radius_mm == 0.0f && !m->probe_map[0] && !m->probe_sphere_map &&
        !m->probe_per_vertex)
        return;
    cJSON *probe = put_container(b, o, "probe", 0);
    if (m->correction > 0 && m->correction < 5)
        put_str(b, probe, "correction", pj_correction_names[m->correction], 32);
    if (m->probe_update > 0 && m->probe_update < 6)
        put_str(b, probe, "update", pj_probe_update_names[m->probe_update], 32);
    if (m->probe_every)
        put_num(b, probe, "every", m->probe_every, 0);
    if (m->probe_resolution)
        put_num(b, probe, "resolution", m->probe_resolution, 0);
    if (m->proxy_radius_mm != 0.0f)
        put_num(b, probe, "proxy_radius", m->proxy_radius_mm, 1);
    if (m->probe_map[0])
        put_path(b, probe, "map", m->probe_map, sizeof m->probe_map);
    if (m->probe_sphere_map)
        put_str(b, probe, "mapping", "sphere", 16);
    if (m->probe_per_vertex && b->r == APP_OK)
        attach(b, probe, "per_vertex", cJSON_CreateTrue());
}

static void put_materials(jb *b, cJSON *root)
{
    cJSON *dict = put_container(b, root, "materials", 0);
    size_t mark = pj_path_key(b->c, "materials");
    for (int i = 0; i < b->p->material_count && b->r == APP_OK; i++) {
        const app_material *m = &b->p->materials[i];
        size_t m_mark = pj_path_index(b->c, i);
        const char *name = material_name(b, i);
        if (!name)
            return;
        if (!name[0]) {
            b->r = pj_fail(b->c, APP_ERR_SCHEMA, "a material name must not be empty");
            return;
        }
        cJSON *o = put_container(b, dict, name, 0);
        put_vec(b, o, "diffuse", NULL, m->diffuse, 3);
        put_vec(b, o, "ambient", NULL, m->ambient, 3);
        put_vec(b, o, "specular", NULL, m->specular, 3);
        put_vec(b, o, "emissive", NULL, m->emissive, 3);
        put_num(b, o, "shininess", m->shininess, 1);
        if (m->texture[0])
            put_path(b, o, "texture", m->texture, sizeof m->texture);
        put_vec(b, o, "texture_size", NULL, m->texture_size_mm, 2);
        put_reflection(b, o, m);
        pj_path_restore(b->c, m_mark);
    }
    pj_path_restore(b->c, mark);
}

static void put_room(jb *b, cJSON *root)
{
    const app_room *room = &b->p->room;
    cJSON *o = put_container(b, root, "room", 0);
    size_t mark = pj_path_key(b->c, "room");
    put_material_ref(b, o, "floor", room->floor_material);
    put_material_ref(b, o, "walls", room->wall_material);
    put_material_ref(b, o, "ceiling", room->ceiling_material);
    if (b->r == APP_OK)
        pj_path_restore(b->c, mark);
}

static const char *const shape_names[] = {"box", "sphere", "cylinder", "plane", "torus"};

static void put_object(jb *b, cJSON *list, const app_object *obj)
{
    cJSON *o = put_container(b, list, NULL, 0);
    put_str(b, o, "name", obj->name, sizeof obj->name);
    if (obj->group[0])
        put_str(b, o, "group", obj->group, sizeof obj->group);
    if (obj->parent[0])
        put_str(b, o, "parent", obj->parent, sizeof obj->parent);
    if (b->r != APP_OK)
        return;
    if (obj->has_product) {
        cJSON *ref = pj_product_ref_to_json(&obj->product);
        if (!ref && b->r == APP_OK) {
            pj_path_key(b->c, "product");
            b->r = pj_fail(b->c, APP_ERR_SCHEMA,
                           "a product reference string is not terminated (or out of memory)");
            return;
        }
        attach(b, o, "product", ref);
    } else if (obj->shape == APP_SHAPE_MODEL) {
        put_path(b, o, "model", obj->model, sizeof obj->model);
    } else if ((unsigned)obj->shape < sizeof shape_names / sizeof shape_names[0]) {
        attach(b, o, "shape", cJSON_CreateString(shape_names[obj->shape]));
    } else {
        pj_path_key(b->c, "shape");
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "unknown shape %d", (int)obj->shape);
        return;
    }
    put_vec(b, o, "position", obj->position_mm, NULL, 3);
    put_vec(b, o, "rotation", obj->rotation_deg, NULL, 3);
    put_vec(b, o, "scale", obj->scale, NULL, 3);
    if (obj->shape != APP_SHAPE_MODEL && !obj->has_product)
        put_vec(b, o, "size", obj->size_mm, NULL, 3);
    put_material_ref(b, o, "material", obj->material);
}

static const char *const light_types[] = {"point", "spot", "directional", "rect"};

static void put_light(jb *b, cJSON *list, const app_light *l)
{
    cJSON *o = put_container(b, list, NULL, 0);
    put_str(b, o, "name", l->name, sizeof l->name);
    if (b->r != APP_OK)
        return;
    if ((unsigned)l->type >= sizeof light_types / sizeof light_types[0]) {
        pj_path_key(b->c, "type");
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "unknown light type %d", (int)l->type);
        return;
    }
    attach(b, o, "type", cJSON_CreateString(light_types[l->type]));
    if (l->type != APP_LIGHT_DIRECTIONAL)
        put_vec(b, o, "position", l->position_mm, NULL, 3);
    if (l->type != APP_LIGHT_POINT)
        put_vec(b, o, "direction", l->direction, NULL, 3);
    put_vec(b, o, "color", NULL, l->color, 3);
    put_num(b, o, "intensity", l->intensity, 1);
    put_vec(b, o, "specular", NULL, l->specular, 3);
    put_vec(b, o, "attenuation", NULL, l->attenuation, 3);
    if (l->type == APP_LIGHT_RECT) {
        put_num(b, o, "width", l->width_mm, 0);
        put_num(b, o, "height", l->height_mm, 0);
        put_vec(b, o, "axis", l->axis, NULL, 3);
    }
    if (l->type == APP_LIGHT_SPOT) {
        put_num(b, o, "inner", l->inner_deg, 1);
        put_num(b, o, "outer", l->outer_deg, 1);
    }
    if (l->emitter_named)
        put_str(b, o, "emitter", l->emitter, sizeof l->emitter);
}

static void put_camera(jb *b, cJSON *list, const app_camera *cam)
{
    cJSON *o = put_container(b, list, NULL, 0);
    put_str(b, o, "name", cam->name, sizeof cam->name);
    put_vec(b, o, "position", cam->position_mm, NULL, 3);
    put_vec(b, o, "target", cam->target_mm, NULL, 3);
    put_vec(b, o, "up", cam->up, NULL, 3);
    put_num(b, o, "fov", cam->fov_deg, 0);
}

/* Written only when the file had it (or an edit set it): a project without keeps the
 * default overcast sky and stays as it was. */
static void put_daylight(jb *b, cJSON *root)
{
    const app_daylight *d = &b->p->daylight;
    if (b->r != APP_OK || !d->present)
        return;
    cJSON *o = put_container(b, root, "daylight", 0);
    size_t mark = pj_path_key(b->c, "daylight");
    static const char *const sky[] = {"overcast", "overcast", "clear"};
    static const char *const model[] = {"cie", "constant", "preetham"};
    int m = (unsigned)d->model <= APP_SKY_PREETHAM ? (int)d->model : 0;
    put_str(b, o, "sky", sky[m], 16);
    put_str(b, o, "model", model[m], 16);
    char date[32], time[16];
    int minutes = (int)floor(d->hour * 60.0 + 0.5);
    snprintf(date, sizeof date, "%04d-%02d-%02d", d->year, d->month, d->day);
    snprintf(time, sizeof time, "%02d:%02d", minutes / 60 % 24, minutes % 60);
    put_str(b, o, "date", date, sizeof date);
    put_str(b, o, "time", time, sizeof time);
    if (d->site[0]) {
        put_str(b, o, "site", d->site, sizeof d->site);
    } else {
        put_num(b, o, "latitude", d->latitude_deg, 0);
        put_num(b, o, "longitude", d->longitude_deg, 0);
    }
    put_num(b, o, "utc_offset", d->utc_offset_h, 0);
    put_num(b, o, "north", d->north_deg, 0);
    put_num(b, o, "turbidity", d->turbidity, 1);
    put_num(b, o, "strength", d->strength, 1);
    if (b->r == APP_OK)
        pj_path_restore(b->c, mark);
}

/* Written only when the file had them (or an edit set them). */
static void put_customer(jb *b, cJSON *root)
{
    const app_customer *cu = &b->p->customer;
    if (b->r != APP_OK || !cu->present)
        return;
    cJSON *o = put_container(b, root, "customer", 0);
    size_t mark = pj_path_key(b->c, "customer");
    put_str(b, o, "name", cu->name, sizeof cu->name);
    if (cu->address_lines > 0) {
        cJSON *a = put_container(b, o, "address", 1);
        for (int i = 0;
             a && b->r == APP_OK && i < cu->address_lines && i < APP_CUSTOMER_ADDRESS_LINES; i++)
            attach(b, a, NULL, cJSON_CreateString(cu->address[i]));
    }
    put_str(b, o, "email", cu->email, sizeof cu->email);
    put_str(b, o, "phone", cu->phone, sizeof cu->phone);
    if (b->r == APP_OK)
        pj_path_restore(b->c, mark);
    if (b->r != APP_OK || (!cu->quote_number[0] && cu->valid_days <= 0))
        return;
    cJSON *q = put_container(b, root, "quote", 0);
    mark = pj_path_key(b->c, "quote");
    if (cu->quote_number[0])
        put_str(b, q, "number", cu->quote_number, sizeof cu->quote_number);
    if (cu->valid_days > 0 && b->r == APP_OK)
        attach(b, q, "valid_days", cJSON_CreateNumber(cu->valid_days));
    if (b->r == APP_OK)
        pj_path_restore(b->c, mark);
}

static void put_render(jb *b, cJSON *root)
{
    const app_render_settings *r = &b->p->render;
    cJSON *o = put_container(b, root, "render", 0);
    size_t mark = pj_path_key(b->c, "render");
    put_vec(b, o, "ambient", NULL, r->ambient, 3);
    if (r->exposure_auto)
        put_str(b, o, "exposure", "auto", 8);
    else
        put_num(b, o, "exposure", r->exposure_ev, 1);
    put_str(b, o, "tone", app_tone_name(r->tone), 16);
    put_num(b, o, "white", r->white, 1);
    if (r->white_balance_k > 0.0f)
        put_num(b, o, "white_balance", r->white_balance_k, 1);
    cJSON *size = put_container(b, o, "size", 1);
    if (size) {
        attach(b, size, NULL, cJSON_CreateNumber(r->width));
        attach(b, size, NULL, cJSON_CreateNumber(r->height));
    }
    if (b->r == APP_OK)
        attach(b, o, "supersample", cJSON_CreateNumber(r->supersample));
    if (b->r == APP_OK && r->ambient_model == 1)
        put_str(b, o, "ambient_model", "sh9", 16);
    if (b->r == APP_OK)
        pj_path_restore(b->c, mark);
}

/* A list must have a pointer for its count, and a count the reader accepts. */
static int check_list(jb *b, const char *key, const void *items, int count)
{
    if (count < 0 || count > APP_PROJECT_MAX_ITEMS || (count > 0 && !items)) {
        pj_path_key(b->c, key);
        b->r = pj_fail(b->c, APP_ERR_SCHEMA, "invalid list (count %d%s)", count,
                       count > 0 && !items ? ", no items" : "");
        return 0;
    }
    return 1;
}

app_result pj_project_to_json(pj_ctx *c, const app_project *p, const char *dest_dir, cJSON **out)
{
    *out = NULL;
    jb b = {c, APP_OK, p, dest_dir};
    if (!check_list(&b, "materials", p->materials, p->material_count) ||
        !check_list(&b, "objects", p->objects, p->object_count) ||
        !check_list(&b, "lights", p->lights, p->light_count) ||
        !check_list(&b, "cameras", p->cameras, p->camera_count))
        return b.r;
    cJSON *root = cJSON_CreateObject();
    if (!root)
        return pj_fail(c, APP_ERR_OUT_OF_MEMORY, "out of memory");
    attach(&b, root, "version", cJSON_CreateNumber(APP_PROJECT_VERSION));
    put_str(&b, root, "name", p->name, sizeof p->name);
    put_room(&b, root);
    if (b.r == APP_OK)
        b.r = pj_plan_to_json(c, p, root);
    if (b.r == APP_OK)
        b.r = pj_tilings_to_json(c, p, root);
    put_materials(&b, root);

    const char *lists[] = {"objects", "lights", "cameras"};
    int counts[] = {p->object_count, p->light_count, p->camera_count};
    for (int k = 0; k < 3 && b.r == APP_OK; k++) {
        cJSON *list = put_container(&b, root, lists[k], 1);
        size_t mark = pj_path_key(c, lists[k]);
        for (int i = 0; i < counts[k] && b.r == APP_OK; i++) {
            size_t i_mark = pj_path_index(c, i);
            if (k == 0)
                put_object(&b, list, &p->objects[i]);
            else if (k == 1)
                put_light(&b, list, &p->lights[i]);
            else
                put_camera(&b, list, &p->cameras[i]);
            if (b.r == APP_OK)
                pj_path_restore(c, i_mark);
        }
        if (b.r == APP_OK)
            pj_path_restore(c, mark);
    }
    put_render(&b, root);
    put_customer(&b, root);
    put_daylight(&b, root);
    if (b.r != APP_OK) {
        cJSON_Delete(root);
        return b.r;
    }
    *out = root;
    return APP_OK;
}
