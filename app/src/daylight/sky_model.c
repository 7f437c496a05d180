/* Sky radiance by direction (docs/rendering.md, "Daylight"), in renderer units: 1 unit of
 * radiance is 2.5 kcd/m^2 (a bright overcast zenith of 5 kcd/m^2 is 2 units), the scale at
 * which the room's lamps of intensity about 1 and the daylight read together. */
#include "app/daylight/daylight.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846
#define RAD (PI / 180.0)
#define UNITS_PER_KCD 0.4 /* renderer radiance per kcd/m^2 */

static double smoothstep(double a, double b, double x)
{
    double t = fmin(fmax((x - a) / (b - a), 0.0), 1.0);
    return t * t * (3.0 - 2.0 * t);
}

/* Perez et al. 1993 all-weather luminance distribution as Preetham, Shirley and Smits 1999
 * ("A practical analytic model for daylight", eq. 3) use it: theta the view's zenith angle,
 * gamma its angle to the sun. */
static double perez(const double c[5], double cos_theta, double gamma)
{
    double cg = cos(gamma);
    return (1.0 + c[0] * exp(c[1] / fmax(cos_theta, 0.01))) *
           (1.0 + c[2] * exp(c[3] * gamma) + c[4] * cg * cg);
}

/* Preetham et al. 1999, appendix A.2: the distribution coefficients for Y, x and y. */
static void preetham_coefficients(double t, double cy[5], double cx[5], double cyc[5])
{
    const double y[5][2] = {{0.1787, -1.4630},
                            {-0.3554, 0.4275},
                            {-0.0227, 5.3251},
                            {0.1206, -2.5771},
                            {-0.0670, 0.3703}};
    const double x[5][2] = {{-0.0193, -0.2592},
                            {-0.0665, 0.0008},
                            {-0.0004, 0.2125},
                            {-0.0641, -0.8989},
                            {-0.0033, 0.0452}};
    const double yc[5][2] = {{-0.0167, -0.2608},
                             {-0.0950, 0.0092},
                             {-0.0079, 0.2102},
                             {-0.0441, -1.6537},
                             {-0.0109, 0.0529}};
    for (int i = 0; i < 5; i++) {
        cy[i] = y[i][0] * t + y[i][1];
        cx[i] = x[i][0] * t + x[i][1];
        cyc[i] = yc[i][0] * t + yc[i][1];
    }
}

/* xyY (Y in kcd/m^2) to linear sRGB in renderer units (IEC 61966-2-1 matrix). */
static void xyy_to_rgb(double x, double y, double big_y, float out[3])
{
    double yy = fmax(y, 1e-6);
    double X = x / yy * big_y, Z = (1.0 - x - y) / yy * big_y;
    double rgb[3] = {3.2406 * X - 1.5372 * big_y - 0.4986 * Z,
                     -0.9689 * X + 1.8758 * big_y + 0.0415 * Z,
                     0.0557 * X - 0.2040 * big_y + 1.0570 * Z};
    for (int k = 0; k < 3; k++)
        out[k] = (float)(fmax(rgb[k], 0.0) * UNITS_PER_KCD);
}

/* The sky alone (no ground) in direction dir, which must point at or above the horizon. */
static void sky_only(const app_sky *s, const double dir[3], float out[3])
{
    double cos_theta = fmax(dir[2], 0.0);
    if (s->model == APP_SKY_CIE_OVERCAST || s->model == APP_SKY_CONSTANT) {
        /* CIE standard overcast sky (Moon and Spencer 1942, CIE S 011/E:2003 type 1):
         * L = L_z (1 + 2 cos theta) / 3; the constant sky has the same horizontal
         * illuminance: L = 7/9 L_z. */
        double f = s->model == APP_SKY_CONSTANT ? 7.0 / 9.0 : (1.0 + 2.0 * cos_theta) / 3.0;
        for (int k = 0; k < 3; k++)
            out[k] = (float)(s->zenith[k] * f);
        return;
    }
    double cy[5], cx[5], cyc[5];
    preetham_coefficients(s->turbidity, cy, cx, cyc);
    double theta_s = PI / 2.0 - s->sun_elevation;
    double cg = dir[0] * s->sun[0] + dir[1] * s->sun[1] + dir[2] * s->sun[2];
    double gamma = acos(fmin(fmax(cg, -1.0), 1.0));
    double Y = s->zenith[2] * perez(cy, cos_theta, gamma) / perez(cy, 1.0, theta_s);
    double x = s->zenith[0] * perez(cx, cos_theta, gamma) / perez(cx, 1.0, theta_s);
    double y = s->zenith[1] * perez(cyc, cos_theta, gamma) / perez(cyc, 1.0, theta_s);
    xyy_to_rgb(x, y, fmax(Y, 0.0), out);
}

void app_sky_radiance(const app_sky *s, const double dir[3], float out[3])
{
    if (dir[2] < 0.0) {
        memcpy(out, s->ground, sizeof s->ground);
        return;
    }
    sky_only(s, dir, out);
    for (int k = 0; k < 3; k++)
        out[k] *= s->strength;
}

void app_sky_make(const app_daylight *d, app_sky *s)
{
    memset(s, 0, sizeof *s);
    s->model = d->model;
    s->turbidity = d->turbidity;
    s->strength = d->strength;
    app_sun_position sun = app_sun_position_at(d->year, d->month, d->day, d->hour, d->utc_offset_h,
                                               d->latitude_deg, d->longitude_deg);
    /* A compass bearing b lies (b - north) clockwise from the plan's +Y seen from above. */
    double el = sun.elevation_deg * RAD, a = (sun.azimuth_deg - d->north_deg) * RAD;
    s->sun[0] = cos(el) * sin(a);
    s->sun[1] = cos(el) * cos(a);
    s->sun[2] = sin(el);
    s->sun_elevation = el;
    /* Twilight: the sky fades out as the sun sinks 6 degrees below the horizon (civil
     * twilight); the models themselves hold only for a sun above it. */
    double day = smoothstep(-6.0, 0.0, sun.elevation_deg);
    double sin_el = fmax(sin(el), 0.0);
    if (d->model == APP_SKY_PREETHAM) {
        /* Preetham et al. 1999 appendix A.2: zenith luminance (kcd/m^2) and chromaticity for
         * turbidity T and the sun's zenith angle theta_s (kept just above the horizon). */
        double t = d->turbidity, ts = fmin(PI / 2.0 - el, PI / 2.0 - 0.01);
        s->sun_elevation = PI / 2.0 - ts;
        double chi = (4.0 / 9.0 - t / 120.0) * (PI - 2.0 * ts);
        double yz = ((4.0453 * t - 4.9710) * tan(chi) - 0.2155 * t + 2.4192) * day;
        double t2 = t * t, ts2 = ts * ts, ts3 = ts2 * ts;
        double xz = t2 * (0.00166 * ts3 - 0.00375 * ts2 + 0.00209 * ts) +
                    t * (-0.02903 * ts3 + 0.06377 * ts2 - 0.03202 * ts + 0.00394) +
                    (0.11693 * ts3 - 0.21196 * ts2 + 0.06052 * ts + 0.25886);
        double yzc = t2 * (0.00275 * ts3 - 0.00610 * ts2 + 0.00317 * ts) +
                     t * (-0.04214 * ts3 + 0.08970 * ts2 - 0.04153 * ts + 0.00516) +
                     (0.15346 * ts3 - 0.26756 * ts2 + 0.06670 * ts + 0.26688);
        s->zenith[0] = xz;
        s->zenith[1] = yzc;
        s->zenith[2] = fmax(yz, 0.0);
        /* Direct normal illuminance of the sun: 128 klx outside the atmosphere, through the
         * air mass m (Kasten and Young 1989) with Kasten's Rayleigh optical thickness and the
         * turbidity as the Linke factor (the ESRA clear-sky model, Rigollier, Bauer and Wald
         * 2000, eqs. 3-5). */
        if (sun.elevation_deg > 0.0) {
            double zen = 90.0 - sun.elevation_deg;
            double m = 1.0 / (cos(zen * RAD) + 0.50572 * pow(96.07995 - zen, -1.6364));
            double rayleigh =
                m <= 20.0
                    ? 1.0 / (6.6296 + m * (1.7513 + m * (-0.1202 + m * (0.0065 - m * 0.00013))))
                    : 1.0 / (10.4 + 0.718 * m);
            double klx = 128.0 * exp(-0.8662 * t * m * rayleigh);
            s->sun_irradiance = (float)(klx * UNITS_PER_KCD * d->strength);
        }
    } else {
        /* Horizontal illuminance under an overcast sky, Krochmann and Seidl 1974:
         * E = 300 + 21000 sin(elevation) lx, and the CIE overcast sky gives E = 7 pi / 9 L_z. */
        double e_lux = 300.0 * day + 21000.0 * sin_el;
        double lz = e_lux * 9.0 / (7.0 * PI) / 1000.0 * UNITS_PER_KCD;
        for (int k = 0; k < 3; k++)
            s->zenith[k] = lz;
    }
    /* The ground: grass and trees, a diffuse albedo of about 0.15 (green), under the sky and
     * the sun (horizontal irradiance by a 16 x 64 midpoint sum over the upper hemisphere). */
    const double albedo[3] = {0.14, 0.19, 0.09};
    double e[3] = {0, 0, 0};
    const int nt = 16, np = 64;
    for (int i = 0; i < nt; i++) {
        double th = (i + 0.5) / nt * PI / 2.0;
        double w = cos(th) * sin(th) * (PI / 2.0 / nt) * (2.0 * PI / np);
        for (int j = 0; j < np; j++) {
            double ph = (j + 0.5) / np * 2.0 * PI;
            double dir[3] = {sin(th) * cos(ph), sin(th) * sin(ph), cos(th)};
            float l[3];
            sky_only(s, dir, l);
            for (int k = 0; k < 3; k++)
                e[k] += l[k] * w;
        }
    }
    for (int k = 0; k < 3; k++) {
        double sun_e = s->sun_irradiance / fmax(d->strength, 1e-30) * sin_el;
        s->ground[k] = (float)(albedo[k] * (e[k] + sun_e) / PI * d->strength);
    }
}
