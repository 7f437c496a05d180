/* Daylight through the room's windows (docs/rendering.md, "Daylight"): where the sun stands for
 * a date, a time and a place, how bright the sky is in each direction, and what a window
 * opening lets in. Pure computation, no renderer: room_mesh turns it into an emitting pane,
 * a rectangle light and a sun. */
#ifndef APP_DAYLIGHT_H
#define APP_DAYLIGHT_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum app_sky_model {
    APP_SKY_CIE_OVERCAST = 0, /* overcast: CIE standard overcast sky (Moon and Spencer 1942) */
    APP_SKY_CONSTANT,         /* overcast: the same radiance in every direction */
    APP_SKY_PREETHAM,         /* clear: Preetham, Shirley and Smits 1999, with the sun */
} app_sky_model;

typedef struct app_daylight {
    int present;          /* 1: the project file has a "daylight" object (written back) */
    app_sky_model model;  /* default CIE overcast */
    int year, month, day; /* the local date; default 2026-06-21 */
    double hour;          /* local clock time in hours, [0, 24); default 12 */
    double utc_offset_h;  /* local time minus UTC, hours; default 0 */
    double latitude_deg;  /* north positive; default 51.4779 (Greenwich) */
    double longitude_deg; /* east positive; default 0 */
    char site[32];        /* the named site the place came from ("" = given by numbers) */
    double north_deg;     /* the plan's orientation: the compass bearing of the plan's +Y axis
                             (0 = +Y is north, 90 = +Y is east); default 0 */
    float turbidity;      /* clear sky haze, [1.7, 10]; default 3 */
    float strength;       /* multiplies sky and sun; default 1 */
} app_daylight;

void app_daylight_default(app_daylight *d);
/* "HH:MM" (24 h) into d->hour; 0 when it is not such a time. */
int app_daylight_set_time(app_daylight *d, const char *hh_mm);
/* The command line's overrides (NULL = keep): sky "overcast" (CIE) or "clear" (Preetham), a
 * local time "HH:MM". Marks d present. 0 when one is not valid. */
int app_daylight_override(app_daylight *d, const char *sky, const char *hh_mm);

/* A named site: its latitude, longitude and standard UTC offset. NULL when unknown. */
typedef struct app_daylight_site {
    const char *name;
    double latitude_deg, longitude_deg, utc_offset_h;
} app_daylight_site;
const app_daylight_site *app_daylight_site_find(const char *name);
/* The known names, comma separated, for messages. */
const char *app_daylight_site_names(void);

/* The sun as seen from the site: elevation above the horizon (refraction included) and
 * azimuth clockwise from north, degrees. NOAA's solar position algorithm (Meeus,
 * "Astronomical Algorithms", ch. 25 low accuracy; NOAA Global Monitoring Laboratory solar
 * calculator). Also the declination, for tests against Meeus's examples. */
typedef struct app_sun_position {
    double elevation_deg, azimuth_deg, declination_deg, right_ascension_deg;
} app_sun_position;
app_sun_position app_sun_position_at(int year, int month, int day, double hour_local,
                                     double utc_offset_h, double latitude_deg,
                                     double longitude_deg);

/* Sky radiance in renderer units (linear RGB) in the world direction dir (Z up, unit), for
 * the sun in world direction sun (unit, towards the sun). Below the horizon: the ground. */
typedef struct app_sky {
    app_sky_model model;
    double sun[3];        /* world direction towards the sun */
    double sun_elevation; /* radians */
    float turbidity, strength;
    double zenith[3];     /* xyY at the zenith (Preetham) or the zenith radiance (overcast) */
    float ground[3];      /* radiance of the ground below the horizon */
    float sun_irradiance; /* direct normal irradiance of the sun, renderer units; 0 = none */
} app_sky;

/* The sky of d in the world of a plan turned by d->north_deg. */
void app_sky_make(const app_daylight *d, app_sky *out);
void app_sky_radiance(const app_sky *s, const double dir[3], float out[3]);

/* What a window opening facing the horizontal world direction `outward` (unit x, y) lets in.
 * The mean radiance of the sky and ground it sees, cosine-weighted about its normal: the
 * radiance of the rectangle light that stands for the opening (the sun apart). */
void app_window_mean_radiance(const app_sky *s, const double outward[2], float out[3]);
/* The exterior seen through it at an elevation (radians; below 0 the ground), straight out. */
void app_window_view_radiance(const app_sky *s, const double outward[2], double elevation,
                              float out[3]);
/* 1 when the sun is up and on the window's side of its wall. */
int app_window_sunlit(const app_sky *s, const double outward[2]);

#ifdef __cplusplus
}
#endif
#endif
