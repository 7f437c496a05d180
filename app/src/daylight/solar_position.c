/* Where the sun stands: NOAA's solar position algorithm, the formulas of the NOAA Global
 * Monitoring Laboratory solar calculator spreadsheet (after Meeus, "Astronomical Algorithms",
 * 2nd ed., ch. 25, the low-accuracy method, and ch. 28 for the equation of time), with its
 * atmospheric refraction correction. Accurate to about 0.01 degree for 1800-2100 (NOAA). */
#include "app/daylight/daylight.h"

#include <math.h>

#define PI 3.14159265358979323846
#define RAD (PI / 180.0)

/* Julian day at 0h UT of a Gregorian calendar date (Meeus ch. 7, eq. 7.1). */
static double julian_day(int year, int month, int day)
{
    if (month <= 2) {
        year -= 1;
        month += 12;
    }
    double a = floor(year / 100.0);
    double b = 2.0 - a + floor(a / 4.0);
    return floor(365.25 * (year + 4716)) + floor(30.6001 * (month + 1)) + day + b - 1524.5;
}

/* Atmospheric refraction in degrees at true elevation e (degrees), NOAA's piecewise fit
 * (Bennett above 5 degrees, a polynomial near the horizon, a tail below it). */
static double refraction_deg(double e)
{
    if (e > 85.0)
        return 0.0;
    double t = tan(e * RAD), arcsec;
    if (e > 5.0)
        arcsec = 58.1 / t - 0.07 / (t * t * t) + 0.000086 / pow(t, 5.0);
    else if (e > -0.575)
        arcsec = 1735.0 + e * (-518.2 + e * (103.4 + e * (-12.79 + e * 0.711)));
    else
        arcsec = -20.772 / t;
    return arcsec / 3600.0;
}

app_sun_position app_sun_position_at(int year, int month, int day, double hour_local,
                                     double utc_offset_h, double latitude_deg, double longitude_deg)
{
    double jd = julian_day(year, month, day) + (hour_local - utc_offset_h) / 24.0;
    double jc = (jd - 2451545.0) / 36525.0; /* Julian centuries from J2000.0 */
    double l0 = fmod(280.46646 + jc * (36000.76983 + jc * 0.0003032), 360.0);
    double m = 357.52911 + jc * (35999.05029 - 0.0001537 * jc);
    double e = 0.016708634 - jc * (0.000042037 + 0.0000001267 * jc);
    double c = sin(m * RAD) * (1.914602 - jc * (0.004817 + 0.000014 * jc)) +
               sin(2.0 * m * RAD) * (0.019993 - 0.000101 * jc) + sin(3.0 * m * RAD) * 0.000289;
    double true_long = l0 + c;
    double omega = 125.04 - 1934.136 * jc;
    double lambda = true_long - 0.00569 - 0.00478 * sin(omega * RAD); /* apparent longitude */
    double eps0 =
        23.0 + (26.0 + (21.448 - jc * (46.815 + jc * (0.00059 - jc * 0.001813))) / 60.0) / 60.0;
    double eps = eps0 + 0.00256 * cos(omega * RAD); /* corrected obliquity */
    double ra = atan2(cos(eps * RAD) * sin(lambda * RAD), cos(lambda * RAD)) / RAD;
    double dec = asin(sin(eps * RAD) * sin(lambda * RAD)) / RAD;
    double y = tan(eps * RAD / 2.0);
    y *= y;
    double eot_min = 4.0 / RAD *
                     (y * sin(2.0 * l0 * RAD) - 2.0 * e * sin(m * RAD) +
                      4.0 * e * y * sin(m * RAD) * cos(2.0 * l0 * RAD) -
                      0.5 * y * y * sin(4.0 * l0 * RAD) - 1.25 * e * e * sin(2.0 * m * RAD));
    double tst =
        fmod(hour_local * 60.0 + eot_min + 4.0 * longitude_deg - 60.0 * utc_offset_h, 1440.0);
    if (tst < 0)
        tst += 1440.0;
    double ha = tst / 4.0 < 0 ? tst / 4.0 + 180.0 : tst / 4.0 - 180.0; /* hour angle */
    double lat = latitude_deg * RAD;
    double cos_zen = sin(lat) * sin(dec * RAD) + cos(lat) * cos(dec * RAD) * cos(ha * RAD);
    double zen = acos(fmin(fmax(cos_zen, -1.0), 1.0)) / RAD;
    double denom = cos(lat) * sin(zen * RAD);
    double az;
    if (fabs(denom) < 1e-12) {
        az = lat > 0 ? 180.0 : 0.0; /* the sun at the zenith or a pole: any bearing */
    } else {
        double a =
            acos(fmin(fmax((sin(lat) * cos(zen * RAD) - sin(dec * RAD)) / denom, -1.0), 1.0)) / RAD;
        az = ha > 0 ? fmod(a + 180.0, 360.0) : fmod(540.0 - a, 360.0);
    }
    double elev = 90.0 - zen;
    app_sun_position out = {elev + refraction_deg(elev), az, dec, ra < 0 ? ra + 360.0 : ra};
    return out;
}
