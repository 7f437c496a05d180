/* A fixture's box projected into the 3D view (box_outline.h). */
#include "box_outline.h"

#include "view_ray.h"

#include <math.h>

/* How far in front of the eye (mm) an edge is cut: ui_view_project refuses points closer
 * than 1 mm, and a nearer cut would throw the end point far off the pane. */
#define NEAR_MM 10.0

/* Corner k of the box: bit 0 the local x side, bit 1 the local y side, bit 2 top or bottom,
 * in the plan's rotation (plan_draw.c's rect_corners). */
static void corner(const app_fixture *f, const double offset[2], int k, double out[3])
{
    double a = f->angle_deg * 3.14159265358979323846 / 180.0, c = cos(a), s = sin(a);
    double lx = (k & 1 ? 1 : -1) * f->half[0], ly = (k & 2 ? 1 : -1) * f->half[1];
    out[0] = f->centre[0] + offset[0] + lx * c - ly * s;
    out[1] = f->centre[1] + offset[1] + lx * s + ly * c;
    out[2] = k & 4 ? f->z1 : f->z0;
}

int ui_box_outline(const double eye[3], const double target[3], double fov_y_deg, int width,
                   int height, const app_fixture *f, const double offset_mm[2],
                   float segments[UI_BOX_EDGES][4])
{
    /* Each edge joins two corners that differ in one bit. */
    static const int edges[UI_BOX_EDGES][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                               {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    static const double no_offset[2] = {0, 0};
    const double *off = offset_mm ? offset_mm : no_offset;
    double fwd[3] = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
    double len = sqrt(fwd[0] * fwd[0] + fwd[1] * fwd[1] + fwd[2] * fwd[2]);
    if (!(len > 1e-9))
        return 0;
    double pts[8][3], depth[8];
    for (int k = 0; k < 8; k++) {
        corner(f, off, k, pts[k]);
        depth[k] = 0;
        for (int j = 0; j < 3; j++)
            depth[k] += (pts[k][j] - eye[j]) * fwd[j] / len;
    }
    int n = 0;
    for (int e = 0; e < UI_BOX_EDGES; e++) {
        int a = edges[e][0], b = edges[e][1];
        if (depth[a] < NEAR_MM && depth[b] < NEAR_MM)
            continue;
        double p[2][3];
        for (int j = 0; j < 3; j++) {
            p[0][j] = pts[a][j];
            p[1][j] = pts[b][j];
        }
        /* One end behind the cut: move it along the edge to the cut. */
        if (depth[a] < NEAR_MM || depth[b] < NEAR_MM) {
            int behind = depth[a] < NEAR_MM ? 0 : 1;
            double t = (NEAR_MM - depth[a]) / (depth[b] - depth[a]);
            for (int j = 0; j < 3; j++)
                p[behind][j] = pts[a][j] + t * (pts[b][j] - pts[a][j]);
        }
        double x0, y0, x1, y1;
        if (!ui_view_project(eye, target, fov_y_deg, width, height, p[0], &x0, &y0) ||
            !ui_view_project(eye, target, fov_y_deg, width, height, p[1], &x1, &y1))
            continue;
        segments[n][0] = (float)x0;
        segments[n][1] = (float)y0;
        segments[n][2] = (float)x1;
        segments[n][3] = (float)y1;
        n++;
    }
    return n;
}
