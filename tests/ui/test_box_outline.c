/* The selection outline's geometry (ui/src/box_outline.h): a box wholly in front of the eye
 * gives its 12 edges, ending on the pixels its 8 corners project to (view_ray.h, tested
 * against the renderer's projection in test_fixture_drag.c); a turn by 90 degrees is the box
 * with its sides swapped; a drag offset moves every end point as the moved box's corners; an
 * eye inside the box keeps only the edges in front, cut at the near plane and finite; a box
 * behind the eye gives none. */
#include "box_outline.h"
#include "check.h"
#include "view_ray.h"

#include <math.h>
#include <string.h>

static app_fixture box(double cx, double cy, double hx, double hy, double angle, double z0,
                       double z1)
{
    app_fixture f;
    memset(&f, 0, sizeof f);
    f.centre[0] = cx;
    f.centre[1] = cy;
    f.half[0] = hx;
    f.half[1] = hy;
    f.angle_deg = angle;
    f.z0 = z0;
    f.z1 = z1;
    return f;
}

static const double eye[3] = {1000, -2000, 1500}, target[3] = {1000, 1000, 900};
static const int w = 960, h = 540;
static const double fov = 60;

/* 1 when every segment end is the projection of one of the box's corners (moved by dx, dy),
 * and every corner is some segment's end. */
static int ends_are_corners(const float s[][4], int n, const app_fixture *f, double dx, double dy)
{
    int used[8] = {0};
    for (int e = 0; e < n; e++)
        for (int c = 0; c < 2; c++) {
            int found = 0;
            for (int k = 0; k < 8; k++) {
                double pt[3] = {f->centre[0] + dx + (k & 1 ? 1 : -1) * f->half[0],
                                f->centre[1] + dy + (k & 2 ? 1 : -1) * f->half[1],
                                k & 4 ? f->z1 : f->z0},
                       sx, sy;
                if (ui_view_project(eye, target, fov, w, h, pt, &sx, &sy) &&
                    fabs(sx - s[e][2 * c]) < 0.01 && fabs(sy - s[e][2 * c + 1]) < 0.01) {
                    found = used[k] = 1;
                }
            }
            if (!found)
                return 0;
        }
    for (int k = 0; k < 8; k++)
        if (!used[k])
            return 0;
    return 1;
}

int main(void)
{
    float s[UI_BOX_EDGES][4], t[UI_BOX_EDGES][4];

    /* In front: 12 edges between the projected corners. */
    app_fixture vanity = box(1000, 1500, 400, 250, 0, 160, 680);
    int n = ui_box_outline(eye, target, fov, w, h, &vanity, NULL, s);
    CHECK(n == 12);
    CHECK(ends_are_corners(s, n, &vanity, 0, 0));

    /* Turned by 90 degrees: the same points as the box with its sides swapped. */
    app_fixture turned = box(1000, 1500, 250, 400, 90, 160, 680);
    app_fixture swapped = box(1000, 1500, 400, 250, 0, 160, 680);
    n = ui_box_outline(eye, target, fov, w, h, &turned, NULL, t);
    CHECK(n == 12);
    CHECK(ends_are_corners(t, n, &swapped, 0, 0));

    /* A live drag's offset moves the outline with the box. */
    const double offset[2] = {300, -200};
    n = ui_box_outline(eye, target, fov, w, h, &vanity, offset, t);
    CHECK(n == 12);
    CHECK(ends_are_corners(t, n, &vanity, 300, -200));
    CHECK(!ends_are_corners(t, n, &vanity, 0, 0));

    /* The eye inside the box: the edges in front only, cut before the eye, all finite. */
    app_fixture room = box(1000, -2000, 500, 500, 0, 0, 2500);
    n = ui_box_outline(eye, target, fov, w, h, &room, NULL, t);
    CHECK_MSG(n > 0 && n < 12, "%d edges", n);
    for (int e = 0; e < n; e++)
        for (int k = 0; k < 4; k++)
            CHECK(isfinite(t[e][k]) && fabs(t[e][k]) < 1e6);

    /* Behind the eye: nothing. */
    app_fixture behind = box(1000, -4000, 300, 300, 0, 0, 800);
    CHECK(ui_box_outline(eye, target, fov, w, h, &behind, NULL, t) == 0);
    /* A degenerate view (eye at the target): nothing, no division by zero. */
    CHECK(ui_box_outline(eye, eye, fov, w, h, &vanity, NULL, t) == 0);
    return check_report("ui.box_outline");
}
