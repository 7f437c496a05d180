/* $.render: image size, supersampling, ambient light, exposure, tone curve, white balance. */
#include "project_internal.h"

#include <math.h>
#include <string.h>

static const pj_range EXPOSURE = {-64.0, 64.0, 0, 0, 1};
static const pj_range WHITE_BALANCE = {0.0, 40000.0, 0, 0, 1};

/* "exposure": "auto" or a number of EV. */
static app_result read_exposure(pj_ctx *c, const cJSON *render, app_render_settings *out)
{
    const cJSON *e = cJSON_GetObjectItemCaseSensitive(render, "exposure");
    if (!e)
        return APP_OK;
    if (cJSON_IsString(e)) {
        if (strcmp(e->valuestring, "auto")) {
            pj_path_key(c, "exposure");
            return pj_fail(c, APP_ERR_SCHEMA,
                           "unknown value \"%s\" (use \"auto\" or a number of EV)", e->valuestring);
        }
        out->exposure_auto = 1;
        return APP_OK;
    }
    out->exposure_auto = 0;
    return pj_get_float(c, render, "exposure", 0, EXPOSURE, &out->exposure_ev);
}

static const char *const tone_names[] = {"neutral", "agx", "reinhard", "clamp"};

const char *app_tone_name(app_tone t)
{
    return (unsigned)t < sizeof tone_names / sizeof tone_names[0] ? tone_names[t] : "neutral";
}

int app_tone_parse(const char *name, app_tone *out)
{
    for (int i = 0; name && i < (int)(sizeof tone_names / sizeof tone_names[0]); i++)
        if (!strcmp(name, tone_names[i])) {
            *out = (app_tone)i;
            return 1;
        }
    return 0;
}

/* "tone": neutral, agx, reinhard, clamp. */
static app_result read_tone(pj_ctx *c, const cJSON *render, app_render_settings *out)
{
    char tone[16] = "";
    app_result r = pj_get_string(c, render, "tone", 0, 0, tone, sizeof tone);
    if (r != APP_OK || !tone[0])
        return r;
    if (!app_tone_parse(tone, &out->tone)) {
        pj_path_key(c, "tone");
        return pj_fail(c, APP_ERR_SCHEMA,
                       "unknown tone curve \"%s\" (use neutral, agx, reinhard or clamp)", tone);
    }
    return APP_OK;
}

app_result pj_read_render(pj_ctx *c, const cJSON *root)
{
    app_render_settings *out = &c->p->render;
    pj_default_render(out);
    const cJSON *render;
    app_result r = pj_member(c, root, "render", cJSON_Object, 0, &render);
    if (r != APP_OK || !render)
        return r;
    size_t mark = pj_path_key(c, "render");
    if ((r = pj_get_color(c, render, "ambient", 0, out->ambient)) != APP_OK ||
        (r = read_exposure(c, render, out)) != APP_OK ||
        (r = read_tone(c, render, out)) != APP_OK ||
        (r = pj_get_float(c, render, "white", 0, PJ_POSITIVE, &out->white)) != APP_OK ||
        (r = pj_get_float(c, render, "white_balance", 0, WHITE_BALANCE, &out->white_balance_k)) !=
            APP_OK ||
        (r = pj_get_int(c, render, "supersample", 0, 1, 4, &out->supersample)) != APP_OK)
        return r;
    char model[16] = "";
    if ((r = pj_get_string(c, render, "ambient_model", 0, 0, model, sizeof model)) != APP_OK)
        return r;
    if (model[0]) {
        if (strcmp(model, "constant") && strcmp(model, "sh9")) {
            pj_path_key(c, "ambient_model");
            return pj_fail(c, APP_ERR_SCHEMA, "unknown value \"%s\" (use constant or sh9)", model);
        }
        out->ambient_model = !strcmp(model, "sh9");
    }

    const cJSON *size;
    if ((r = pj_member(c, render, "size", cJSON_Array, 0, &size)) != APP_OK)
        return r;
    if (size) {
        size_t s_mark = pj_path_key(c, "size");
        int count = cJSON_GetArraySize(size);
        if (count != 2)
            return pj_fail(c, APP_ERR_SCHEMA,
                           "expected an array of 2 integers [width, height], got %d element%s",
                           count, count == 1 ? "" : "s");
        int wh[2];
        for (int i = 0; i < 2; i++) {
            size_t e_mark = pj_path_index(c, i);
            double v;
            if ((r = pj_check_number(c, cJSON_GetArrayItem(size, i), PJ_ANY, &v)) != APP_OK)
                return r;
            if (v != floor(v))
                return pj_fail(c, APP_ERR_SCHEMA, "expected an integer, got %g", v);
            if (v < 1 || v > APP_PROJECT_MAX_IMAGE_SIDE)
                return pj_fail(c, APP_ERR_SCHEMA, "must be in [1, %d], got %g",
                               APP_PROJECT_MAX_IMAGE_SIDE, v);
            wh[i] = (int)v;
            pj_path_restore(c, e_mark);
        }
        out->width = wh[0];
        out->height = wh[1];
        pj_path_restore(c, s_mark);
    }
    pj_path_restore(c, mark);
    return APP_OK;
}
