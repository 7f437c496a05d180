/* Sphere maps (RENDERING.md section 9; seed 000 eqs. 2, 4, 5): the static, view-dependent
 * mode, generated from a cube map. The rim (R_z = -1, A_z -> 0) never gives NaN. */
#include "render/reflect_ref.h"

#include <math.h>
#include <string.h>

/* Seed 000 eqs. 4-5 in GL's GL_SPHERE_MAP form: for a unit R, m = 2 sqrt(R_x^2 + R_y^2 +
 * (R_z + 1)^2) = 2 sqrt(2 (R_z + 1)) = 4 A_z, so s = R_x / m + 1/2 = (A_x + 1) / 2. Unlike
 * A_z = sqrt((R_z + 1) / 2) alone, m includes R_x and R_y, so |R_x / m| <= 1/2 holds even where
 * R_z + 1 is lost to rounding: near the rim the result goes to the rim point in the direction of
 * (R_x, R_y), which is the seed's limit. m = 0 only for R = (0, 0, -1) exactly. */
void rd_ref_sphere_map_st(const float r[3], float *s, float *t)
{
    *s = 0.5f;
    *t = 0.5f;
    if (!isfinite(r[0]) || !isfinite(r[1]) || !isfinite(r[2]))
        return;
    double x = r[0], y = r[1], z = r[2];
    double big = fmax(fabs(x), fmax(fabs(y), fabs(z)));
    if (!(big > 0.0))
        return;
    x /= big, y /= big, z /= big; /* no overflow in the squares */
    double len = sqrt(x * x + y * y + z * z);
    x /= len, y /= len, z /= len;
    double m = 2.0 * sqrt(x * x + y * y + (z + 1.0) * (z + 1.0));
    if (!(m > 0.0)) {
        *s = 1.0f; /* the rim, (R_x, R_y) = 0: the seed's R = (0, 0, -1) for every rim point */
        return;
    }
    double ss = x / m + 0.5, tt = y / m + 0.5;
    *s = (float)fmin(fmax(ss, 0.0), 1.0);
    *t = (float)fmin(fmax(tt, 0.0), 1.0);
}

/* Seed 000 eq. 2: the point A = (A_x, A_y, A_z) of the unit sphere under (s, t) reflects the
 * view direction (0, 0, -1) into R = (2 A_z A_x, 2 A_z A_y, 2 A_z^2 - 1). */
void rd_ref_sphere_map_direction(float s, float t, float r[3])
{
    double ax = isfinite(s) ? 2.0 * s - 1.0 : 0.0;
    double ay = isfinite(t) ? 2.0 * t - 1.0 : 0.0;
    double r2 = ax * ax + ay * ay;
    double az = r2 < 1.0 ? sqrt(1.0 - r2) : 0.0; /* outside the disc: the rim */
    r[0] = (float)(2.0 * az * ax);
    r[1] = (float)(2.0 * az * ay);
    r[2] = (float)(2.0 * az * az - 1.0);
}

rd_result rd_sphere_map_from_cube(const rd_cube_data *c, int size, float *rgba_out)
{
    if (c == NULL || c->size < 1 || rgba_out == NULL || size < 1 || size > RD_CUBE_MAX_SIZE)
        return RD_ERR_INVALID_ARGUMENT;
    for (int f = 0; f < 6; f++)
        if (c->faces[f] == NULL)
            return RD_ERR_INVALID_ARGUMENT;
    for (int j = 0; j < size; j++) {
        for (int i = 0; i < size; i++) {
            float dir[3];
            rd_ref_sphere_map_direction(((float)i + 0.5f) / (float)size,
                                        ((float)j + 0.5f) / (float)size, dir);
            /* The map's frame is the world frame (see reflect_ref.h). */
            rd_cube_sample_bilinear(c, dir, rgba_out + ((size_t)j * size + (size_t)i) * 4);
        }
    }
    return RD_OK;
}
