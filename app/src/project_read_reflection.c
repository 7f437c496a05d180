/* A material's reflection members: "reflectivity", "glossiness", "blend", the "probe" object,
 * and glass ("transparency", "ior", "dispersion"). RENDERING.md sections 3-9. */
#include "project_internal.h"

#include <string.h>

const char *const pj_blend_names[3] = {"mix", "add", "fresnel"};
const char *const pj_correction_names[4] = {"default", "none", "box", "sphere"};
const char *const pj_probe_update_names[5] = {"default", "every-frame", "once", "on-change",
                                              "time-sliced"};

static const pj_range UNIT = {0.0, 1.0, 0, 0, 1};
static const pj_range IOR = {1.0, 3.0, 0, 0, 1};
static const pj_range DISPERSION = {0.0, 0.2, 0, 0, 1};

/* A string member that must be one of `names`; absent leaves *out as it is. */
static app_result get_enum(pj_ctx *c, const cJSON *obj, const char *key, const char *const *names,
                           int count, int *out)
{
    const cJSON *item;
    app_result r = pj_member(c, obj, key, cJSON_String, 0, &item);
    if (r != APP_OK || !item)
        return r;
    const char *value = item->valuestring ? item->valuestring : "";
    for (int i = 0; i < count; i++)
        if (!strcmp(value, names[i])) {
            *out = i;
            return APP_OK;
        }
    char list[160] = "";
    for (int i = 0; i < count; i++) {
        strncat(list, i ? ", " : "", sizeof list - strlen(list) - 1);
        strncat(list, names[i], sizeof list - strlen(list) - 1);
    }
    pj_path_key(c, key);
    return pj_fail(c, APP_ERR_SCHEMA, "unknown value \"%.40s\" (use one of: %s)", value, list);
}

app_result pj_read_reflection_fields(pj_ctx *c, const cJSON *item, app_material *m)
{
    app_result r;
    if ((r = pj_get_float(c, item, "reflectivity", 0, UNIT, &m->reflectivity)) != APP_OK ||
        (r = pj_get_float(c, item, "glossiness", 0, UNIT, &m->glossiness)) != APP_OK ||
        (r = get_enum(c, item, "blend", pj_blend_names, 3, &m->blend)) != APP_OK ||
        (r = pj_get_float(c, item, "transparency", 0, UNIT, &m->transparency)) != APP_OK ||
        (r = pj_get_float(c, item, "ior", 0, IOR, &m->ior)) != APP_OK ||
        (r = pj_get_float(c, item, "dispersion", 0, DISPERSION, &m->dispersion)) != APP_OK)
        return r;
    const cJSON *probe;
    if ((r = pj_member(c, item, "probe", cJSON_Object, 0, &probe)) != APP_OK || !probe)
        return r;
    size_t mark = pj_path_key(c, "probe");
    if ((r = get_enum(c, probe, "correction", pj_correction_names, 4, &m->correction)) != APP_OK ||
        (r = get_enum(c, probe, "update", pj_probe_update_names, 5, &m->probe_update)) != APP_OK ||
        (r = pj_get_int(c, probe, "every", 0, 0, 1000000, &m->probe_every)) != APP_OK ||
        (r = pj_get_float(c, probe, "proxy_radius", 0, PJ_FLOAT_NONNEG, &m->proxy_radius_mm)) !=
            APP_OK)
        return r;
    /* "resolution": a power of two from 1 to 4096, or "auto". */
    const cJSON *res;
    if ((r = pj_member(c, probe, "resolution", cJSON_Number | cJSON_String, 0, &res)) != APP_OK)
        return r;
    if (res && cJSON_IsString(res)) {
        if (strcmp(res->valuestring, "auto") != 0) {
            pj_path_key(c, "resolution");
            return pj_fail(c, APP_ERR_SCHEMA, "expected a number or \"auto\", got \"%s\"",
                           res->valuestring);
        }
        m->probe_resolution = 0;
    } else if (res) {
        int n = 0;
        if ((r = pj_get_int(c, probe, "resolution", 0, 1, 4096, &n)) != APP_OK)
            return r;
        if (n & (n - 1)) {
            pj_path_key(c, "resolution");
            return pj_fail(c, APP_ERR_SCHEMA, "must be a power of two, got %d", n);
        }
        m->probe_resolution = n;
    }
    pj_path_restore(c, mark);
    return APP_OK;
}
