/* Rays through the 3D view (view_ray.h). */
#include "view_ray.h"

#include <math.h>

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static int normalise(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(l > 1e-12))
        return 0;
    for (int k = 0; k < 3; k++)
        v[k] /= l;
    return 1;
}

/* The camera's unit forward, right and up vectors (z up; straight down: north is up). */
static int basis(const double eye[3], const double target[3], double f[3], double r[3], double u[3])
{
    double up[3] = {0, 0, 1};
    for (int k = 0; k < 3; k++)
        f[k] = target[k] - eye[k];
    if (!normalise(f))
        return 0;
    cross(f, up, r);
    if (!normalise(r)) {
        double north[3] = {0, 1, 0};
        cross(f, north, r);
        if (!normalise(r))
            return 0;
    }
    cross(r, f, u);
    return 1;
}

int ui_view_ray(const double eye[3], const double target[3], double fov_y_deg, int width,
                int height, double sx, double sy, double dir[3])
{
    double f[3], r[3], u[3];
    if (width <= 0 || height <= 0 || !(fov_y_deg > 0 && fov_y_deg < 180) ||
        !basis(eye, target, f, r, u))
        return 0;
    /* Vertical field of view, aspect width / height, window y down. */
    double t = tan(fov_y_deg * 3.14159265358979323846 / 360.0), aspect = (double)width / height;
    double nx = 2.0 * sx / width - 1.0, ny = 1.0 - 2.0 * sy / height;
    for (int k = 0; k < 3; k++)
        dir[k] = f[k] + nx * t * aspect * r[k] + ny * t * u[k];
    return 1;
}

int ui_view_project(const double eye[3], const double target[3], double fov_y_deg, int width,
                    int height, const double pt[3], double *sx, double *sy)
{
    double f[3], r[3], u[3], v[3] = {pt[0] - eye[0], pt[1] - eye[1], pt[2] - eye[2]};
    if (width <= 0 || height <= 0 || !(fov_y_deg > 0 && fov_y_deg < 180) ||
        !basis(eye, target, f, r, u))
        return 0;
    double z = v[0] * f[0] + v[1] * f[1] + v[2] * f[2];
    if (!(z > 1.0)) /* behind the eye or at it */
        return 0;
    double t = tan(fov_y_deg * 3.14159265358979323846 / 360.0), aspect = (double)width / height;
    double x = (v[0] * r[0] + v[1] * r[1] + v[2] * r[2]) / (z * t * aspect);
    double y = (v[0] * u[0] + v[1] * u[1] + v[2] * u[2]) / (z * t);
    *sx = (x + 1.0) * 0.5 * width;
    *sy = (1.0 - y) * 0.5 * height;
    return 1;
}

int ui_ray_plane_z(const double o[3], const double d[3], double height, double out[2])
{
    if (!(fabs(d[2]) > 1e-12))
        return 0;
    double t = (height - o[2]) / d[2];
    if (!(t > 0) || !isfinite(t))
        return 0;
    out[0] = o[0] + t * d[0];
    out[1] = o[1] + t * d[1];
    return 1;
}

double ui_ray_fixture(const double o[3], const double d[3], const app_fixture *f)
{
    /* Into the fixture's frame: x along its width, y along its depth (slab test). */
    double a = -f->angle_deg * 3.14159265358979323846 / 180.0, c = cos(a), s = sin(a);
    double px = o[0] - f->centre[0], py = o[1] - f->centre[1];
    double lo[3] = {-f->half[0], -f->half[1], f->z0}, hi[3] = {f->half[0], f->half[1], f->z1};
    double lo_o[3] = {c * px - s * py, s * px + c * py, o[2]};
    double lo_d[3] = {c * d[0] - s * d[1], s * d[0] + c * d[1], d[2]};
    double t0 = 0, t1 = INFINITY;
    for (int k = 0; k < 3; k++) {
        if (fabs(lo_d[k]) < 1e-12) {
            if (lo_o[k] < lo[k] || lo_o[k] > hi[k])
                return -1;
            continue;
        }
        double ta = (lo[k] - lo_o[k]) / lo_d[k], tb = (hi[k] - lo_o[k]) / lo_d[k];
        if (ta > tb) {
            double x = ta;
            ta = tb;
            tb = x;
        }
        t0 = ta > t0 ? ta : t0;
        t1 = tb < t1 ? tb : t1;
        if (t0 > t1)
            return -1;
    }
    return t0 > 0 ? t0 : -1; /* an eye inside a box does not pick it */
}

int ui_pick_fixture(const double o[3], const double d[3], const app_fixture *fixtures, int count)
{
    int best = -1;
    double best_t = INFINITY;
    for (int i = 0; i < count; i++) {
        double t = ui_ray_fixture(o, d, &fixtures[i]);
        if (t > 0 && t < best_t) {
            best_t = t;
            best = i;
        }
    }
    return best;
}
