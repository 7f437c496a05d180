/* A material's reflection members: "reflectivity", "glossiness", "blend", the "probe" object,
 * and glass ("transparency", "ior", "dispersion"). RENDERING.md sections 3-9. */
#include "project_internal.h"

#include <stdio.h>
#include <string.h>

const char *const pj_blend_names[3] = {"mix", "add", "fresnel"};
const char *const pj_material_pattern_names[2] = {"none", "wood"};
const char *const pj_correction_names[5] = {"default", "none", "box", "sphere", "depth"};
const char *const pj_probe_update_names[6] = {"default",   "every-frame", "once",
                                              "on-change", "time-sliced", "static"};

static const pj_range UNIT = {0.0, 1.0, 0, 0, 1};
static const pj_range IOR = {1.0, 3.0, 0, 0, 1};
static const pj_range DISPERSION = {0.0, 0.2, 0, 0, 1};
static const pj_range GRAIN = {0.0, 180.0, 0, 0, 1};

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

/* "map": six images of a prepared cube map, '*' standing for the face names (posx ... or
 * front ... , render/cube_data.h). Its folder must exist; the faces are read when rendering. */
static app_result read_static_map(pj_ctx *c, const cJSON *probe, app_material *m)
{
    char value[sizeof m->probe_map] = "";
    app_result r = pj_get_string(c, probe, "map", 0, 0, value, sizeof value);
    if (r != APP_OK)
        return r;
    if (!value[0]) {
        if (m->probe_update == APP_PROBE_STATIC) {
            pj_path_key(c, "update");
            return pj_fail(c, APP_ERR_SCHEMA, "\"static\" needs a \"map\"");
        }
        return APP_OK;
    }
    size_t mark = pj_path_key(c, "map");
    const char *slash = strrchr(value, '/');
    if (!strchr(slash ? slash : value, '*'))
        return pj_fail(c, APP_ERR_SCHEMA, "\"%s\" has no '*' for the face names", value);
    /* The +X face must exist under one of the two naming schemes (render/cube_data.h); its
     * folder anchors the pattern. The other faces are checked when the map is loaded. */
    const char *star = strchr(slash ? slash : value, '*');
    int head = (int)(star - value);
    char face[sizeof m->probe_map], resolved[sizeof m->probe_map];
    const char *names[2] = {"posx", "right"};
    r = APP_ERR_NOT_FOUND;
    for (int i = 0; i < 2 && r != APP_OK; i++) {
        snprintf(face, sizeof face, "%.*s%s%s", head, value, names[i], star + 1);
        r = pj_resolve_file(c, face, resolved, sizeof resolved);
    }
    if (r == APP_ERR_NOT_FOUND)
        return pj_fail(c, r, "no %.*sposx%s and no %.*sright%s next to the project", head, value,
                       star + 1, head, value, star + 1);
    if (r != APP_OK)
        return r;
    const char *resolved_slash = strrchr(resolved, '/');
    int n = snprintf(m->probe_map, sizeof m->probe_map, "%.*s%s",
                     resolved_slash ? (int)(resolved_slash - resolved + 1) : 0, resolved,
                     slash ? slash + 1 : value);
    if (n < 0 || (size_t)n >= sizeof m->probe_map)
        return pj_fail(c, APP_ERR_SCHEMA, "path too long");
    m->probe_update = APP_PROBE_STATIC;
    pj_path_restore(c, mark);
    return APP_OK;
}

/* "grain": "horizontal", "vertical" or degrees 0-180 from the object's x towards its z. */
static app_result read_grain(pj_ctx *c, const cJSON *obj, float *out)
{
    const cJSON *item;
    app_result r = pj_member(c, obj, "grain", cJSON_String | cJSON_Number, 0, &item);
    if (r != APP_OK || !item)
        return r;
    if (cJSON_IsNumber(item))
        return pj_get_float(c, obj, "grain", 0, GRAIN, out);
    const char *value = item->valuestring ? item->valuestring : "";
    if (!strcmp(value, "horizontal") || !strcmp(value, "vertical")) {
        *out = value[0] == 'h' ? 0.0f : 90.0f;
        return APP_OK;
    }
    pj_path_key(c, "grain");
    return pj_fail(c, APP_ERR_SCHEMA,
                   "unknown value \"%.40s\" (use horizontal, vertical or degrees 0 to 180)", value);
}

app_result pj_read_reflection_fields(pj_ctx *c, const cJSON *item, app_material *m)
{
    app_result r;
    if ((r = pj_get_float(c, item, "reflectivity", 0, UNIT, &m->reflectivity)) != APP_OK ||
        (r = pj_get_float(c, item, "glossiness", 0, UNIT, &m->glossiness)) != APP_OK ||
        (r = get_enum(c, item, "blend", pj_blend_names, 3, &m->blend)) != APP_OK ||
        (r = pj_get_float(c, item, "transparency", 0, UNIT, &m->transparency)) != APP_OK ||
        (r = pj_get_float(c, item, "ior", 0, IOR, &m->ior)) != APP_OK ||
        (r = pj_get_float(c, item, "dispersion", 0, DISPERSION, &m->dispersion)) != APP_OK ||
        (r = get_enum(c, item, "pattern", pj_material_pattern_names, 2, &m->pattern)) != APP_OK ||
        (r = read_grain(c, item, &m->grain_deg)) != APP_OK)
        return r;
    const cJSON *probe;
    if ((r = pj_member(c, item, "probe", cJSON_Object, 0, &probe)) != APP_OK || !probe)
        return r;
    size_t mark = pj_path_key(c, "probe");
    if ((r = get_enum(c, probe, "correction", pj_correction_names, 5, &m->correction)) != APP_OK ||
        (r = get_enum(c, probe, "update", pj_probe_update_names, 6, &m->probe_update)) != APP_OK ||
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
    if ((r = read_static_map(c, probe, m)) != APP_OK)
        return r;
    static const char *const mappings[2] = {"cube", "sphere"};
    if ((r = get_enum(c, probe, "mapping", mappings, 2, &m->probe_sphere_map)) != APP_OK)
        return r;
    const cJSON *pv;
    if ((r = pj_member(c, probe, "per_vertex", cJSON_True | cJSON_False, 0, &pv)) != APP_OK)
        return r;
    if (pv)
        m->probe_per_vertex = cJSON_IsTrue(pv);
    pj_path_restore(c, mark);
    return APP_OK;
}
