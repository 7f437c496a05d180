/* 4x4 column-major double matrices for node transforms (glTF 2.0, section 3.5.3 "Transformations":
 * a node's local matrix is T * R * S, or its "matrix" property, column-major). */
#include "model_internal.h"

#include <math.h>
#include <string.h>

void cat_mat4_identity(double m[16])
{
    memset(m, 0, 16 * sizeof m[0]);
    m[0] = m[5] = m[10] = m[15] = 1.0;
}

void cat_mat4_mul(const double a[16], const double b[16], double out[16])
{
    double r[16];
    for (int col = 0; col < 4; col++)
        for (int row = 0; row < 4; row++) {
            double s = 0.0;
            for (int k = 0; k < 4; k++)
                s += a[k * 4 + row] * b[col * 4 + k];
            r[col * 4 + row] = s;
        }
    memcpy(out, r, sizeof r);
}

void cat_mat4_from_trs(const double t[3], const double q[4], const double s[3], double out[16])
{
    double len = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    double x = q[0] / len, y = q[1] / len, z = q[2] / len, w = q[3] / len;
    /* rotation matrix of a unit quaternion, columns scaled by s */
    double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),
                   2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                   2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y)};
    for (int col = 0; col < 3; col++) {
        for (int row = 0; row < 3; row++)
            out[col * 4 + row] = r[col * 3 + row] * s[col];
        out[col * 4 + 3] = 0.0;
    }
    out[12] = t[0];
    out[13] = t[1];
    out[14] = t[2];
    out[15] = 1.0;
}

/* Element (row, col) of the upper-left 3x3. */
#define M3(m, row, col) ((m)[(col)*4 + (row)])

double cat_mat3_det(const double m[16])
{
    return M3(m, 0, 0) * (M3(m, 1, 1) * M3(m, 2, 2) - M3(m, 1, 2) * M3(m, 2, 1)) -
           M3(m, 0, 1) * (M3(m, 1, 0) * M3(m, 2, 2) - M3(m, 1, 2) * M3(m, 2, 0)) +
           M3(m, 0, 2) * (M3(m, 1, 0) * M3(m, 2, 1) - M3(m, 1, 1) * M3(m, 2, 0));
}

void cat_mat3_cofactor(const double m[16], double out[9])
{
    for (int row = 0; row < 3; row++)
        for (int col = 0; col < 3; col++) {
            int r0 = (row + 1) % 3, r1 = (row + 2) % 3;
            int c0 = (col + 1) % 3, c1 = (col + 2) % 3;
            /* cyclic minor order gives the cofactor sign for free */
            out[row * 3 + col] = M3(m, r0, c0) * M3(m, r1, c1) - M3(m, r0, c1) * M3(m, r1, c0);
        }
}
