/* $.daylight: the sky seen through the windows, the date, the time and the place
 * (docs/project-format.md, "Daylight"). */
#include "project_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const pj_range LATITUDE = {-90.0, 90.0, 0, 0, 1};
static const pj_range LONGITUDE = {-180.0, 180.0, 0, 0, 1};
static const pj_range UTC_OFFSET = {-14.0, 14.0, 0, 0, 1};
static const pj_range NORTH = {-360.0, 360.0, 0, 0, 1};
static const pj_range TURBIDITY = {1.7, 10.0, 0, 0, 1};
static const pj_range STRENGTH = {0.0, 1e6, 0, 0, 1};

static int days_in_month(int year, int month)
{
    static const int days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    int leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    return month == 2 && leap ? 29 : days[month - 1];
}

static app_result read_sky(pj_ctx *c, const cJSON *o, app_daylight *d)
{
    char sky[16] = "overcast", model[24] = "";
    app_result r;
    if ((r = pj_get_string(c, o, "sky", 0, 0, sky, sizeof sky)) != APP_OK ||
        (r = pj_get_string(c, o, "model", 0, 0, model, sizeof model)) != APP_OK)
        return r;
    if (!strcmp(sky, "overcast")) {
        if (!model[0] || !strcmp(model, "cie"))
            d->model = APP_SKY_CIE_OVERCAST;
        else if (!strcmp(model, "constant"))
            d->model = APP_SKY_CONSTANT;
        else {
            pj_path_key(c, "model");
            return pj_fail(c, APP_ERR_SCHEMA,
                           "unknown overcast sky model \"%s\" (use cie or constant)", model);
        }
    } else if (!strcmp(sky, "clear")) {
        if (!model[0] || !strcmp(model, "preetham"))
            d->model = APP_SKY_PREETHAM;
        else {
            pj_path_key(c, "model");
            return pj_fail(c, APP_ERR_SCHEMA,
                           "unknown clear sky model \"%s\" (use preetham; hosek-wilkie is not "
                           "built in)",
                           model);
        }
    } else {
        pj_path_key(c, "sky");
        return pj_fail(c, APP_ERR_SCHEMA, "unknown sky \"%s\" (use overcast or clear)", sky);
    }
    return APP_OK;
}

static app_result read_date_time(pj_ctx *c, const cJSON *o, app_daylight *d)
{
    char date[16] = "", time[16] = "";
    app_result r;
    if ((r = pj_get_string(c, o, "date", 0, 0, date, sizeof date)) != APP_OK ||
        (r = pj_get_string(c, o, "time", 0, 0, time, sizeof time)) != APP_OK)
        return r;
    if (date[0]) {
        int y, m, dd, n = 0;
        if (sscanf(date, "%4d-%2d-%2d%n", &y, &m, &dd, &n) != 3 || date[n] || y < 1800 ||
            y > 2200 || m < 1 || m > 12 || dd < 1 || dd > days_in_month(y, m)) {
            pj_path_key(c, "date");
            return pj_fail(c, APP_ERR_SCHEMA,
                           "expected a date \"YYYY-MM-DD\" between 1800 and 2200, got \"%s\"",
                           date);
        }
        d->year = y;
        d->month = m;
        d->day = dd;
    }
    if (time[0] && !app_daylight_set_time(d, time)) {
        pj_path_key(c, "time");
        return pj_fail(c, APP_ERR_SCHEMA, "expected a local time \"HH:MM\" (24 h), got \"%s\"",
                       time);
    }
    return APP_OK;
}

static app_result read_place(pj_ctx *c, const cJSON *o, app_daylight *d)
{
    app_result r = pj_get_string(c, o, "site", 0, 0, d->site, sizeof d->site);
    if (r != APP_OK)
        return r;
    if (d->site[0]) {
        const app_daylight_site *s = app_daylight_site_find(d->site);
        if (!s) {
            pj_path_key(c, "site");
            return pj_fail(c, APP_ERR_SCHEMA,
                           "unknown site \"%s\" (known: %s; or give latitude "
                           "and longitude)",
                           d->site, app_daylight_site_names());
        }
        d->latitude_deg = s->latitude_deg;
        d->longitude_deg = s->longitude_deg;
        d->utc_offset_h = s->utc_offset_h;
        if (cJSON_GetObjectItemCaseSensitive(o, "latitude") ||
            cJSON_GetObjectItemCaseSensitive(o, "longitude")) {
            pj_path_key(c, "site");
            return pj_fail(c, APP_ERR_SCHEMA, "give a site or latitude and longitude, not both");
        }
    } else {
        int has_lat = cJSON_GetObjectItemCaseSensitive(o, "latitude") != NULL;
        int has_lon = cJSON_GetObjectItemCaseSensitive(o, "longitude") != NULL;
        if (has_lat != has_lon) {
            pj_path_key(c, has_lat ? "longitude" : "latitude");
            return pj_fail(c, APP_ERR_SCHEMA, "required with %s",
                           has_lat ? "latitude" : "longitude");
        }
    }
    if ((r = pj_get_number(c, o, "latitude", 0, LATITUDE, &d->latitude_deg)) != APP_OK ||
        (r = pj_get_number(c, o, "longitude", 0, LONGITUDE, &d->longitude_deg)) != APP_OK ||
        (r = pj_get_number(c, o, "utc_offset", 0, UTC_OFFSET, &d->utc_offset_h)) != APP_OK ||
        (r = pj_get_number(c, o, "north", 0, NORTH, &d->north_deg)) != APP_OK)
        return r;
    return APP_OK;
}

app_result pj_read_daylight(pj_ctx *c, const cJSON *root)
{
    app_daylight *d = &c->p->daylight;
    app_daylight_default(d);
    const cJSON *o;
    app_result r = pj_member(c, root, "daylight", cJSON_Object, 0, &o);
    if (r != APP_OK || !o)
        return r;
    d->present = 1;
    size_t mark = pj_path_key(c, "daylight");
    if ((r = read_sky(c, o, d)) != APP_OK || (r = read_date_time(c, o, d)) != APP_OK ||
        (r = read_place(c, o, d)) != APP_OK ||
        (r = pj_get_float(c, o, "turbidity", 0, TURBIDITY, &d->turbidity)) != APP_OK ||
        (r = pj_get_float(c, o, "strength", 0, STRENGTH, &d->strength)) != APP_OK)
        return r;
    pj_path_restore(c, mark);
    return APP_OK;
}
