/* Daylight (docs/rendering.md, "Daylight"): the sun's position against published values, the
 * sky models finite and positive from the horizon to the zenith, a window's mean radiance
 * against a hand computation, and the project's "daylight" settings read, written back and
 * refused with clear messages. */
#define _GNU_SOURCE /* mkstemp */
#include "../common/check.h"
#include "app/daylight/daylight.h"
#include "app/project/project.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void test_sun_meeus(void)
{
    /* Meeus, "Astronomical Algorithms", 2nd ed., example 25.a: 1992 October 13.0 TD, the
     * apparent declination -7.78507 and right ascension 198.38083 degrees. (TD - UT was about
     * a minute then: 0.0007 degree of the sun's motion.) */
    app_sun_position s = app_sun_position_at(1992, 10, 13, 0.0, 0.0, 0.0, 0.0);
    CHECK_NEAR(s.declination_deg, -7.78507, 0.01);
    CHECK_NEAR(s.right_ascension_deg, 198.38083, 0.01);
}

static void test_sun_spa(void)
{
    /* Reda and Andreas 2004 (NREL/TP-560-34302, "Solar position algorithm for solar radiation
     * applications"), table A5.1: Golden, Colorado (39.742476 N, 105.1786 W), 2003-10-17
     * 12:30:30 local time (UTC-7): topocentric zenith 50.11162, azimuth 194.34024 degrees. */
    app_sun_position s =
        app_sun_position_at(2003, 10, 17, 12.0 + 30.5 / 60.0, -7.0, 39.742476, -105.1786);
    CHECK_NEAR(90.0 - s.elevation_deg, 50.11162, 0.5);
    CHECK_NEAR(s.azimuth_deg, 194.34024, 0.5);
    printf("SPA example: zenith %.4f (published 50.11162), azimuth %.4f (194.34024)\n",
           90.0 - s.elevation_deg, s.azimuth_deg);
}

static void test_sun_noaa(void)
{
    /* NOAA solar calculator: Greenwich (51.4779 N, 0), 2026-06-21 12:00 UTC is near solar noon
     * of the June solstice: elevation 90 - 51.4779 + 23.44 = 61.96 degrees, due south. */
    app_sun_position s = app_sun_position_at(2026, 6, 21, 12.0, 0.0, 51.4779, 0.0);
    CHECK_NEAR(s.elevation_deg, 61.96, 0.5);
    CHECK_NEAR(s.azimuth_deg, 180.0, 2.0);
    /* The same place at 06:00: east of north-east in the morning, low. */
    s = app_sun_position_at(2026, 6, 21, 6.0, 0.0, 51.4779, 0.0);
    CHECK(s.azimuth_deg > 60.0 && s.azimuth_deg < 100.0);
    CHECK(s.elevation_deg > 5.0 && s.elevation_deg < 25.0);
}

static void check_sky(const app_daylight *d, const char *what)
{
    app_sky sky;
    app_sky_make(d, &sky);
    int ok = 1;
    for (int az = 0; az < 360; az += 30)
        for (int el = 0; el <= 90; el += 15) {
            double a = az * M_PI / 180.0, e = el * M_PI / 180.0;
            double dir[3] = {cos(e) * sin(a), cos(e) * cos(a), sin(e)};
            float l[3];
            app_sky_radiance(&sky, dir, l);
            for (int k = 0; k < 3; k++)
                ok &= isfinite(l[k]) && l[k] > 0.0f && l[k] < 1e4f;
        }
    CHECK_MSG(ok, "%s: a sky radiance is not finite and positive", what);
}

static void test_sky_models(void)
{
    app_daylight d;
    app_daylight_default(&d);
    check_sky(&d, "CIE overcast");
    d.model = APP_SKY_CONSTANT;
    check_sky(&d, "constant");
    d.model = APP_SKY_PREETHAM;
    for (float t = 2.0f; t <= 10.0f; t += 4.0f)
        for (double h = 6.0; h <= 18.0; h += 3.0) {
            d.turbidity = t;
            d.hour = h;
            check_sky(&d, "Preetham");
        }
    /* CIE overcast: the zenith is three times as bright as the horizon. */
    app_daylight_default(&d);
    app_sky sky;
    app_sky_make(&d, &sky);
    float zen[3], hor[3];
    app_sky_radiance(&sky, (double[3]){0, 0, 1}, zen);
    app_sky_radiance(&sky, (double[3]){1, 0, 0}, hor);
    CHECK_NEAR(zen[1] / hor[1], 3.0, 1e-4);
    /* A clear sky at noon: bluer than white, brightest near the sun, a sun that shines. */
    d.model = APP_SKY_PREETHAM;
    app_sky_make(&d, &sky);
    app_sky_radiance(&sky, (double[3]){0, 0, 1}, zen);
    CHECK(zen[2] > zen[0]);
    CHECK(sky.sun_irradiance > 10.0f && sky.sun_irradiance < 60.0f);
    /* At midnight: no sun, a dark sky. */
    d.hour = 0.0;
    app_sky_make(&d, &sky);
    app_sky_radiance(&sky, (double[3]){0, 0, 1}, zen);
    CHECK(sky.sun_irradiance == 0.0f && zen[1] < 1e-3f);
}

static void test_window_mean(void)
{
    /* A constant sky L over a ground G: a vertical opening sees each over half its
     * cosine-weighted hemisphere, so its mean radiance is (L + G) / 2. */
    app_daylight d;
    app_daylight_default(&d);
    d.model = APP_SKY_CONSTANT;
    app_sky sky;
    app_sky_make(&d, &sky);
    float sky_l[3], mean[3];
    app_sky_radiance(&sky, (double[3]){0, 0, 1}, sky_l);
    app_window_mean_radiance(&sky, (double[2]){0, -1}, mean);
    for (int k = 0; k < 3; k++)
        CHECK_NEAR(mean[k], 0.5 * (sky_l[k] + sky.ground[k]), 0.01 * sky_l[k]);
    /* The sun in the south shines through a south window, not a north one. */
    d.model = APP_SKY_PREETHAM;
    app_sky_make(&d, &sky);
    CHECK(app_window_sunlit(&sky, (double[2]){0, -1}));
    CHECK(!app_window_sunlit(&sky, (double[2]){0, 1}));
    /* Turning the plan: with north at 180 degrees, the plan's +Y faces south. */
    d.north_deg = 180.0;
    app_sky_make(&d, &sky);
    CHECK(app_window_sunlit(&sky, (double[2]){0, 1}));
}

static const char *BASE = "{\"version\": 1, \"room\": {\"width\": 3000, \"depth\": 2000, "
                          "\"height\": 2500}, \"cameras\": [{\"position\": [1, 1, 1], "
                          "\"target\": [0, 0, 0]}], \"daylight\": %s}";

static app_result parse_daylight(const char *daylight, app_project *p, char *err, size_t n)
{
    char text[2048];
    snprintf(text, sizeof text, BASE, daylight);
    return app_project_parse(text, strlen(text), "case.json", p, err, n);
}

static void expect_error(const char *daylight, const char *message)
{
    app_project p;
    char err[512] = "";
    app_result r = parse_daylight(daylight, &p, err, sizeof err);
    CHECK_MSG(r == APP_ERR_SCHEMA && strstr(err, message), "%s: got \"%s\", wanted \"%s\"",
              daylight, err, message);
    if (r == APP_OK)
        app_project_free(&p);
}

static void test_settings(void)
{
    app_project p;
    char err[512] = "";
    CHECK(parse_daylight("{\"sky\": \"clear\", \"date\": \"2026-03-20\", \"time\": \"09:30\", "
                         "\"site\": \"berlin\", \"north\": 30, \"turbidity\": 4}",
                         &p, err, sizeof err) == APP_OK);
    CHECK(p.daylight.present && p.daylight.model == APP_SKY_PREETHAM);
    CHECK(p.daylight.month == 3 && p.daylight.day == 20 && fabs(p.daylight.hour - 9.5) < 1e-9);
    CHECK(fabs(p.daylight.latitude_deg - 52.52) < 1e-9 && p.daylight.utc_offset_h == 1.0);
    CHECK(p.daylight.north_deg == 30.0 && p.daylight.turbidity == 4.0f);
    /* written back and read again: the same settings */
    char path[] = "/tmp/tessera-daylight-XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    if (fd >= 0) {
        close(fd);
        app_project q;
        CHECK(app_project_write(path, &p, err, sizeof err) == APP_OK);
        CHECK_MSG(app_project_read(path, &q, err, sizeof err) == APP_OK, "%s", err);
        CHECK(memcmp(&q.daylight, &p.daylight, sizeof q.daylight) == 0);
        app_project_free(&q);
        unlink(path);
    }
    app_project_free(&p);

    expect_error("{\"sky\": \"stormy\"}", "$.daylight.sky: unknown sky \"stormy\"");
    expect_error("{\"sky\": \"clear\", \"model\": \"hosek-wilkie\"}",
                 "$.daylight.model: unknown clear sky model");
    expect_error("{\"date\": \"2026-02-30\"}", "$.daylight.date: expected a date");
    expect_error("{\"time\": \"25:00\"}", "$.daylight.time: expected a local time");
    expect_error("{\"latitude\": 95, \"longitude\": 0}", "$.daylight.latitude");
    expect_error("{\"latitude\": 50}", "$.daylight.longitude: required with latitude");
    expect_error("{\"site\": \"atlantis\"}", "$.daylight.site: unknown site \"atlantis\"");
    expect_error("{\"turbidity\": 20}", "$.daylight.turbidity");
}

static app_result parse_light(const char *light, app_project *p, char *err, size_t n)
{
    char text[2048];
    snprintf(text, sizeof text,
             "{\"version\": 1, \"room\": {\"width\": 3000, \"depth\": 2000, \"height\": "
             "2500}, \"cameras\": [{\"position\": [1, 1, 1], \"target\": [0, 0, 0]}], "
             "\"lights\": [%s]}",
             light);
    return app_project_parse(text, strlen(text), "case.json", p, err, n);
}

/* A rect light (a mirror strip): read with its default axis, written back, refused when
 * broken. */
static void test_rect_light_settings(void)
{
    app_project p;
    char err[512] = "";
    CHECK_MSG(parse_light("{\"type\": \"rect\", \"position\": [2900, 1000, 1900], "
                          "\"direction\": [-1, 0, 0], \"width\": 600, \"height\": 40, "
                          "\"intensity\": 60}",
                          &p, err, sizeof err) == APP_OK,
              "%s", err);
    const app_light *l = &p.lights[0];
    CHECK(l->type == APP_LIGHT_RECT && l->width_mm == 600 && l->height_mm == 40);
    /* the default axis: horizontal, square to the direction; the height then vertical */
    CHECK(fabs(fabs(l->axis[1]) - 1) < 1e-12 && fabs(l->axis[2]) < 1e-12);
    CHECK(fabs(fabs(l->height_axis[2]) - 1) < 1e-12);
    char path[] = "/tmp/tessera-rect-XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    if (fd >= 0) {
        close(fd);
        app_project q;
        CHECK(app_project_write(path, &p, err, sizeof err) == APP_OK);
        CHECK_MSG(app_project_read(path, &q, err, sizeof err) == APP_OK, "%s", err);
        CHECK(q.light_count == 1 && memcmp(&q.lights[0], l, sizeof *l) == 0);
        app_project_free(&q);
        unlink(path);
    }
    app_project_free(&p);
    const char *missing =
        "{\"type\": \"rect\", \"position\": [0, 0, 0], \"direction\": [0, 0, -1], "
        "\"width\": 600}";
    CHECK(parse_light(missing, &p, err, sizeof err) == APP_ERR_SCHEMA);
    CHECK_MSG(strstr(err, "$.lights[0].height: missing (required)"), "%s", err);
    const char *parallel =
        "{\"type\": \"rect\", \"position\": [0, 0, 0], \"direction\": [0, 0, -1], "
        "\"width\": 600, \"height\": 600, \"axis\": [0, 0, 2]}";
    CHECK(parse_light(parallel, &p, err, sizeof err) == APP_ERR_SCHEMA);
    CHECK_MSG(strstr(err, "$.lights[0].axis: must not be parallel to direction"), "%s", err);
}

int main(void)
{
    test_rect_light_settings();
    test_sun_meeus();
    test_sun_spa();
    test_sun_noaa();
    test_sky_models();
    test_window_mean();
    test_settings();
    return check_report("daylight");
}
