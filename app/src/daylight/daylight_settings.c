/* Daylight defaults and the named sites a project may give instead of numbers. */
#include "app/daylight/daylight.h"

#include <stdio.h>
#include <string.h>

void app_daylight_default(app_daylight *d)
{
    memset(d, 0, sizeof *d);
    d->model = APP_SKY_CIE_OVERCAST;
    d->year = 2026;
    d->month = 6;
    d->day = 21;
    d->hour = 12.0;
    d->latitude_deg = 51.4779; /* the Royal Observatory, Greenwich */
    d->turbidity = 3.0f;
    d->strength = 1.0f;
}

/* Capitals and large cities of the studios' markets: latitude, longitude, standard time. */
static const app_daylight_site SITES[] = {
    {"amsterdam", 52.37, 4.90, 1},  {"athens", 37.98, 23.73, 2},    {"berlin", 52.52, 13.40, 1},
    {"greenwich", 51.4779, 0.0, 0}, {"kyiv", 50.45, 30.52, 2},      {"lisbon", 38.72, -9.14, 0},
    {"london", 51.51, -0.13, 0},    {"madrid", 40.42, -3.70, 1},    {"new-york", 40.71, -74.01, -5},
    {"oslo", 59.91, 10.75, 1},      {"paris", 48.86, 2.35, 1},      {"rome", 41.90, 12.50, 1},
    {"stockholm", 59.33, 18.07, 1}, {"sydney", -33.87, 151.21, 10}, {"tokyo", 35.68, 139.69, 9},
    {"vienna", 48.21, 16.37, 1},    {"warsaw", 52.23, 21.01, 1},
};

const app_daylight_site *app_daylight_site_find(const char *name)
{
    for (size_t i = 0; i < sizeof SITES / sizeof SITES[0]; i++)
        if (!strcmp(SITES[i].name, name))
            return &SITES[i];
    return NULL;
}

const char *app_daylight_site_names(void)
{
    return "amsterdam, athens, berlin, greenwich, kyiv, lisbon, london, madrid, new-york, oslo, "
           "paris, rome, stockholm, sydney, tokyo, vienna, warsaw";
}

int app_daylight_set_time(app_daylight *d, const char *hh_mm)
{
    int h, m, n = 0;
    if (sscanf(hh_mm, "%2d:%2d%n", &h, &m, &n) != 2 || hh_mm[n] || h < 0 || h > 23 || m < 0 ||
        m > 59)
        return 0;
    d->hour = h + m / 60.0;
    return 1;
}

int app_daylight_override(app_daylight *d, const char *sky, const char *hh_mm)
{
    if (d->year == 0)
        app_daylight_default(d); /* a project made in memory */
    if (sky) {
        if (!strcmp(sky, "overcast"))
            d->model = APP_SKY_CIE_OVERCAST;
        else if (!strcmp(sky, "clear"))
            d->model = APP_SKY_PREETHAM;
        else
            return 0;
    }
    if (hh_mm && !app_daylight_set_time(d, hh_mm))
        return 0;
    if (sky || hh_mm)
        d->present = 1;
    return 1;
}
