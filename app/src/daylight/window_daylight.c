/* What a window opening lets in: the sky and ground it sees (the radiance of its rectangle
 * light and of the exterior drawn behind it) and whether the sun shines through it. */
#include "app/daylight/daylight.h"

#include <math.h>

#define PI 3.14159265358979323846

void app_window_mean_radiance(const app_sky *s, const double outward[2], float out[3])
{
    /* The cosine-weighted mean over the hemisphere outside the opening (a vertical plane),
     * by a 32 x 64 midpoint sum: theta from the window's normal, phi around it. */
    const double n[3] = {outward[0], outward[1], 0}, up[3] = {0, 0, 1};
    const double side[3] = {-outward[1], outward[0], 0};
    double sum[3] = {0, 0, 0};
    const int nt = 32, np = 64;
    for (int i = 0; i < nt; i++) {
        double th = (i + 0.5) / nt * PI / 2.0;
        double w = cos(th) * sin(th) * (PI / 2.0 / nt) * (2.0 * PI / np) / PI;
        for (int j = 0; j < np; j++) {
            double ph = (j + 0.5) / np * 2.0 * PI, dir[3];
            for (int k = 0; k < 3; k++)
                dir[k] = cos(th) * n[k] + sin(th) * (cos(ph) * side[k] + sin(ph) * up[k]);
            float l[3];
            app_sky_radiance(s, dir, l);
            for (int k = 0; k < 3; k++)
                sum[k] += l[k] * w;
        }
    }
    for (int k = 0; k < 3; k++)
        out[k] = (float)sum[k];
}

void app_window_view_radiance(const app_sky *s, const double outward[2], double elevation,
                              float out[3])
{
    double dir[3] = {cos(elevation) * outward[0], cos(elevation) * outward[1], sin(elevation)};
    app_sky_radiance(s, dir, out);
}

int app_window_sunlit(const app_sky *s, const double outward[2])
{
    return s->sun_irradiance > 0.0f && s->sun[2] > 0.0 &&
           s->sun[0] * outward[0] + s->sun[1] * outward[1] > 1e-6;
}
