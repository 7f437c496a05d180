/* $.materials (an object keyed by material name) and material references from the room and
 * the objects (a name, or an inline material object). */
#include "project_internal.h"

#include <stdio.h>
#include <string.h>

#define DEFAULT_MATERIAL_NAME "default"

static const pj_range SHININESS = {0.0, 1e6, 0, 0, 1};

app_result pj_read_material_fields(pj_ctx *c, const cJSON *item, app_material *m)
{
    app_result r;
    if ((r = pj_get_color(c, item, "diffuse", 0, m->diffuse)) != APP_OK)
        return r;
    /* ambient defaults to the diffuse colour just read */
    memcpy(m->ambient, m->diffuse, sizeof m->ambient);
    if ((r = pj_get_color(c, item, "ambient", 0, m->ambient)) != APP_OK ||
        (r = pj_get_color(c, item, "specular", 0, m->specular)) != APP_OK ||
        (r = pj_get_color(c, item, "emissive", 0, m->emissive)) != APP_OK ||
        (r = pj_get_float(c, item, "shininess", 0, SHININESS, &m->shininess)) != APP_OK ||
        (r = pj_get_vecf(c, item, "texture_size", 0, 2, PJ_POSITIVE, m->texture_size_mm)) !=
            APP_OK ||
        (r = pj_read_reflection_fields(c, item, m)) != APP_OK)
        return r;

    char texture[sizeof m->texture] = "";
    if ((r = pj_get_string(c, item, "texture", 0, 1, texture, sizeof texture)) != APP_OK)
        return r;
    m->texture[0] = '\0';
    if (texture[0]) {
        size_t mark = pj_path_key(c, "texture");
        if ((r = pj_resolve_file(c, texture, m->texture, sizeof m->texture)) != APP_OK)
            return r;
        pj_path_restore(c, mark);
    }
    return APP_OK;
}

app_result pj_read_materials(pj_ctx *c, const cJSON *root)
{
    const cJSON *dict;
    app_result r = pj_member(c, root, "materials", cJSON_Object, 0, &dict);
    if (r != APP_OK || !dict)
        return r;
    size_t mark = pj_path_key(c, "materials");
    int count;
    if ((r = pj_check_count(c, dict, "materials", &count)) != APP_OK)
        return r;
    for (const cJSON *item = dict->child; item; item = item->next) {
        const char *name = item->string ? item->string : "";
        size_t m_mark = pj_path_key(c, name);
        if (!name[0])
            return pj_fail(c, APP_ERR_SCHEMA, "a material name must not be empty");
        app_material m;
        pj_default_material(&m);
        if (strlen(name) >= sizeof m.name)
            return pj_fail(c, APP_ERR_SCHEMA,
                           "material name too long (%zu bytes, the limit is %zu)", strlen(name),
                           sizeof m.name - 1);
        if (pj_lookup_material(c, name) >= 0)
            return pj_fail(c, APP_ERR_SCHEMA, "duplicate material name \"%s\"", name);
        if (!cJSON_IsObject(item))
            return pj_fail(c, APP_ERR_SCHEMA, "expected an object, got %s", pj_type_name(item));
        memcpy(m.name, name, strlen(name) + 1);
        if ((r = pj_read_material_fields(c, item, &m)) != APP_OK)
            return r;
        int k;
        if ((r = pj_add_material(c, &m, &k)) != APP_OK)
            return r;
        pj_path_restore(c, m_mark);
    }
    pj_path_restore(c, mark);
    return APP_OK;
}

app_result pj_material_ref(pj_ctx *c, const cJSON *obj, const char *key, const char *inline_name,
                           int *index)
{
    const cJSON *ref;
    app_result r = pj_member(c, obj, key, cJSON_String | cJSON_Object, 0, &ref);
    if (r != APP_OK)
        return r;
    if (!ref) {
        int k = pj_lookup_material(c, DEFAULT_MATERIAL_NAME);
        if (k < 0) {
            app_material m;
            pj_default_material(&m);
            memcpy(m.name, DEFAULT_MATERIAL_NAME, sizeof DEFAULT_MATERIAL_NAME);
            size_t mark = pj_path_key(c, key);
            if ((r = pj_add_material(c, &m, &k)) != APP_OK)
                return r;
            pj_path_restore(c, mark);
        }
        *index = k;
        return APP_OK;
    }
    size_t mark = pj_path_key(c, key);
    if (cJSON_IsString(ref)) {
        const char *name = ref->valuestring ? ref->valuestring : "";
        int k = pj_lookup_material(c, name);
        if (k < 0)
            return pj_fail(c, APP_ERR_SCHEMA, "unknown material \"%.*s\"", 100, name);
        *index = k;
        pj_path_restore(c, mark);
        return APP_OK;
    }
    app_material m;
    pj_default_material(&m);
    if (strlen(inline_name) >= sizeof m.name)
        return pj_fail(c, APP_ERR_SCHEMA,
                       "the inline material's name \"%s\" is too long (limit %zu bytes); use a "
                       "shorter name or a named material",
                       inline_name, sizeof m.name - 1);
    if (pj_lookup_material(c, inline_name) >= 0)
        return pj_fail(c, APP_ERR_SCHEMA,
                       "the inline material's name \"%s\" is already used; give it a unique name",
                       inline_name);
    memcpy(m.name, inline_name, strlen(inline_name) + 1);
    if ((r = pj_read_material_fields(c, ref, &m)) != APP_OK)
        return r;
    int k;
    if ((r = pj_add_material(c, &m, &k)) != APP_OK)
        return r;
    *index = k;
    pj_path_restore(c, mark);
    return APP_OK;
}
