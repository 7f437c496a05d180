/* Typed readers for JSON values: each checks type, finiteness and range, and names the
 * offending JSON path in its message. */
#include "project_internal.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

const pj_range PJ_ANY = {-HUGE_VAL, HUGE_VAL, 0, 0, 0};
const pj_range PJ_FLOAT_ANY = {-FLT_MAX, FLT_MAX, 0, 0, 0};
const pj_range PJ_FLOAT_NONNEG = {0.0, FLT_MAX, 0, 0, 0};
const pj_range PJ_POSITIVE = {0.0, HUGE_VAL, 1, 0, 0};

static const char *type_article(int type_mask)
{
    switch (type_mask) {
    case cJSON_Object:
        return "an object";
    case cJSON_Array:
        return "an array";
    case cJSON_String:
        return "a string";
    case cJSON_Number:
        return "a finite number";
    case cJSON_String | cJSON_Object:
        return "a string or an object";
    default:
        return "a different type";
    }
}

app_result pj_member(pj_ctx *c, const cJSON *obj, const char *key, int type_mask, int required,
                     const cJSON **out)
{
    *out = NULL;
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!item) {
        if (!required)
            return APP_OK;
        pj_path_key(c, key);
        return pj_fail(c, APP_ERR_SCHEMA, "missing (required)");
    }
    if (type_mask && !(item->type & type_mask)) {
        pj_path_key(c, key);
        return pj_fail(c, APP_ERR_SCHEMA, "expected %s, got %s", type_article(type_mask),
                       pj_type_name(item));
    }
    *out = item;
    return APP_OK;
}

static app_result range_error(pj_ctx *c, pj_range r, double v)
{
    if (r.as_interval)
        return pj_fail(c, APP_ERR_SCHEMA, "must be in %c%g, %g%c, got %g", r.min_open ? '(' : '[',
                       r.min, r.max, r.max_open ? ')' : ']', v);
    if (r.min_open ? !(v > r.min) : !(v >= r.min))
        return pj_fail(c, APP_ERR_SCHEMA, "must be %s %g, got %g", r.min_open ? ">" : ">=", r.min,
                       v);
    return pj_fail(c, APP_ERR_SCHEMA, "must be %s %g, got %g", r.max_open ? "<" : "<=", r.max, v);
}

app_result pj_check_number(pj_ctx *c, const cJSON *item, pj_range range, double *out)
{
    if (!cJSON_IsNumber(item))
        return pj_fail(c, APP_ERR_SCHEMA, "expected a finite number, got %s", pj_type_name(item));
    double v = item->valuedouble;
    /* JSON has no NaN or Inf, but 1e999 overflows to Inf in the parser. */
    if (!isfinite(v))
        return pj_fail(c, APP_ERR_SCHEMA, "must be a finite number, got %s",
                       v > 0   ? "inf (overflow)"
                       : v < 0 ? "-inf (overflow)"
                               : "nan");
    int low_ok = range.min_open ? v > range.min : v >= range.min;
    int high_ok = range.max_open ? v < range.max : v <= range.max;
    if (!low_ok || !high_ok)
        return range_error(c, range, v);
    *out = v;
    return APP_OK;
}

app_result pj_get_number(pj_ctx *c, const cJSON *obj, const char *key, int required, pj_range range,
                         double *out)
{
    const cJSON *item;
    app_result r = pj_member(c, obj, key, 0, required, &item);
    if (r != APP_OK || !item)
        return r;
    size_t mark = pj_path_key(c, key);
    double v;
    r = pj_check_number(c, item, range, &v);
    if (r != APP_OK)
        return r;
    *out = v;
    pj_path_restore(c, mark);
    return APP_OK;
}

/* Float fields also refuse what a float cannot hold. */
static pj_range float_range(pj_range r)
{
    if (r.min < -FLT_MAX) {
        r.min = -FLT_MAX;
        r.min_open = 0;
    }
    if (r.max > FLT_MAX) {
        r.max = FLT_MAX;
        r.max_open = 0;
    }
    return r;
}

app_result pj_get_float(pj_ctx *c, const cJSON *obj, const char *key, int required, pj_range range,
                        float *out)
{
    double v = *out;
    app_result r = pj_get_number(c, obj, key, required, float_range(range), &v);
    if (r == APP_OK)
        *out = (float)v;
    return r;
}

app_result pj_get_int(pj_ctx *c, const cJSON *obj, const char *key, int required, int min, int max,
                      int *out)
{
    const cJSON *item;
    app_result r = pj_member(c, obj, key, 0, required, &item);
    if (r != APP_OK || !item)
        return r;
    size_t mark = pj_path_key(c, key);
    double v;
    r = pj_check_number(c, item, PJ_ANY, &v);
    if (r != APP_OK)
        return r;
    if (v != floor(v))
        return pj_fail(c, APP_ERR_SCHEMA, "expected an integer, got %g", v);
    if (v < min || v > max)
        return pj_fail(c, APP_ERR_SCHEMA, "must be in [%d, %d], got %g", min, max, v);
    *out = (int)v;
    pj_path_restore(c, mark);
    return APP_OK;
}

app_result pj_get_vec(pj_ctx *c, const cJSON *obj, const char *key, int required, int n,
                      pj_range range, double *out)
{
    const cJSON *arr;
    app_result r = pj_member(c, obj, key, cJSON_Array, required, &arr);
    if (r != APP_OK || !arr)
        return r;
    size_t mark = pj_path_key(c, key);
    int count = cJSON_GetArraySize(arr);
    if (count != n)
        return pj_fail(c, APP_ERR_SCHEMA, "expected an array of %d numbers, got %d element%s", n,
                       count, count == 1 ? "" : "s");
    double tmp[4];
    int i = 0;
    for (const cJSON *e = arr->child; e && i < n; e = e->next, i++) {
        size_t m = pj_path_index(c, i);
        r = pj_check_number(c, e, range, &tmp[i]);
        if (r != APP_OK)
            return r;
        pj_path_restore(c, m);
    }
    memcpy(out, tmp, (size_t)n * sizeof *out);
    pj_path_restore(c, mark);
    return APP_OK;
}

app_result pj_get_vecf(pj_ctx *c, const cJSON *obj, const char *key, int required, int n,
                       pj_range range, float *out)
{
    double tmp[4];
    for (int i = 0; i < n; i++)
        tmp[i] = out[i];
    app_result r = pj_get_vec(c, obj, key, required, n, float_range(range), tmp);
    if (r != APP_OK)
        return r;
    for (int i = 0; i < n; i++)
        out[i] = (float)tmp[i];
    return APP_OK;
}

app_result pj_get_color(pj_ctx *c, const cJSON *obj, const char *key, int required, float out[3])
{
    return pj_get_vecf(c, obj, key, required, 3, PJ_FLOAT_NONNEG, out);
}

app_result pj_get_string(pj_ctx *c, const cJSON *obj, const char *key, int required,
                         int allow_empty, char *out, size_t out_size)
{
    const cJSON *item;
    app_result r = pj_member(c, obj, key, cJSON_String, required, &item);
    if (r != APP_OK || !item)
        return r;
    const char *s = item->valuestring ? item->valuestring : "";
    size_t len = strlen(s);
    if (len == 0 && !allow_empty) {
        pj_path_key(c, key);
        return pj_fail(c, APP_ERR_SCHEMA, "must not be empty");
    }
    if (len >= out_size) {
        pj_path_key(c, key);
        return pj_fail(c, APP_ERR_SCHEMA, "too long (%zu bytes, the limit is %zu)", len,
                       out_size - 1);
    }
    memcpy(out, s, len + 1);
    return APP_OK;
}

app_result pj_check_count(pj_ctx *c, const cJSON *array, const char *what, int *count)
{
    int n = 0;
    for (const cJSON *e = array->child; e; e = e->next) {
        if (++n > APP_PROJECT_MAX_ITEMS)
            return pj_fail(c, APP_ERR_SCHEMA, "too many %s (more than %d)", what,
                           APP_PROJECT_MAX_ITEMS);
    }
    *count = n;
    return APP_OK;
}
