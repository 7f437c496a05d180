/* The 3D view's picking geometry (ui/src/view_ray.h), which the fixture drag and the catalog's
 * drop use: the ray through a pixel is the one the renderer's projection (cglm, as
 * render/src/camera.c) maps back onto that pixel; a ray hits a fixture's turned box where the
 * box is and nowhere else; projecting a point back gives its pixel; the nearest of two boxes in
 * line is picked; the drag plane at the grabbed height gives the point under the pointer; and the
 * script's drag3d action is read. */
#include "check.h"
#include "script.h"
#include "view_ray.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

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

int main(void)
{
    const double eye[3] = {1000, -2000, 1500}, target[3] = {1000, 1000, 900};
    const int w = 1280, h = 720;
    const double fov = 60;

    /* The ray through a pixel, projected with cglm, lands on that pixel. */
    double d[3];
    CHECK(ui_view_ray(eye, target, fov, w, h, 300, 500, d));
    vec3 e = {(float)eye[0], (float)eye[1], (float)eye[2]};
    vec3 t = {(float)target[0], (float)target[1], (float)target[2]};
    mat4 view, proj, vp;
    glm_lookat(e, t, (vec3){0, 0, 1}, view);
    glm_perspective(glm_rad((float)fov), (float)w / h, 10.0f, 1e5f, proj);
    glm_mat4_mul(proj, view, vp);
    vec4 p = {(float)(eye[0] + 3 * d[0]), (float)(eye[1] + 3 * d[1]), (float)(eye[2] + 3 * d[2]),
              1};
    vec4 c;
    glm_mat4_mulv(vp, p, c);
    double sx = (c[0] / c[3] * 0.5 + 0.5) * w, sy = (0.5 - c[1] / c[3] * 0.5) * h;
    CHECK_NEAR(sx, 300, 0.05);
    CHECK_NEAR(sy, 500, 0.05);
    /* ui_view_project is its inverse; behind the eye nothing shows. */
    double back[2], pt3[3] = {eye[0] + 3 * d[0], eye[1] + 3 * d[1], eye[2] + 3 * d[2]};
    CHECK(ui_view_project(eye, target, fov, w, h, pt3, &back[0], &back[1]));
    CHECK_NEAR(back[0], 300, 1e-6);
    CHECK_NEAR(back[1], 500, 1e-6);
    double behind[3] = {eye[0] - d[0], eye[1] - d[1], eye[2] - d[2]};
    CHECK(!ui_view_project(eye, target, fov, w, h, behind, &back[0], &back[1]));
    CHECK(!ui_view_ray(eye, eye, fov, w, h, 0, 0, d)); /* no direction */
    CHECK(!ui_view_ray(eye, target, 0, w, h, 0, 0, d));

    /* A box straight ahead along the view's centre is hit where its near face is. */
    CHECK(ui_view_ray(eye, target, fov, w, h, w / 2.0, h / 2.0, d));
    app_fixture ahead = box(1000, 1000, 300, 200, 0, 600, 1200); /* target (z 900) inside */
    double th = ui_ray_fixture(eye, d, &ahead);
    CHECK(th > 0);
    CHECK_NEAR(eye[1] + th * d[1], 800, 1e-6); /* the near face y = 1000 - 200 */
    /* The same box 2 m to the side is missed; turned 90 degrees it is hit on its other side. */
    app_fixture aside = box(3000, 1000, 300, 200, 0, 600, 1200);
    CHECK(ui_ray_fixture(eye, d, &aside) < 0);
    app_fixture turned = box(1000, 1000, 300, 200, 90, 600, 1200);
    CHECK_NEAR(eye[1] + ui_ray_fixture(eye, d, &turned) * d[1], 700, 1e-6);
    /* Below the ray (a box lower than the ray passes) is missed too. */
    app_fixture low = box(1000, 1000, 300, 200, 0, 0, 300);
    CHECK(ui_ray_fixture(eye, d, &low) < 0);
    /* An eye inside a box does not pick it. */
    app_fixture around = box(1000, -2000, 100, 100, 0, 1000, 2000);
    CHECK(ui_ray_fixture(eye, d, &around) < 0);

    /* Of two boxes in line the nearer is picked, whatever their order. */
    app_fixture list[3] = {box(1000, 2500, 300, 200, 0, 0, 3000), aside, ahead};
    CHECK(ui_pick_fixture(eye, d, list, 3) == 2);
    CHECK(ui_pick_fixture(eye, d, list, 2) == 0);
    CHECK(ui_pick_fixture(eye, d, list + 1, 1) == -1);

    /* The drag plane: the point at the grabbed height under the pointer. */
    double q[2];
    CHECK(ui_ray_plane_z(eye, d, 900, q));
    CHECK_NEAR(q[0], 1000, 1e-6);
    CHECK_NEAR(q[1], 1000, 1e-6);
    double up[3] = {0, 1, 1};
    CHECK(!ui_ray_plane_z(eye, up, 900, q)); /* behind the eye */
    double flat[3] = {1, 0, 0};
    CHECK(!ui_ray_plane_z(eye, flat, 900, q));

    /* drag3d NAME X Y frames N is read; a missing number is refused with the verb's name. */
    char path[] = "/tmp/tessera-drag3d-XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    if (fd >= 0) {
        FILE *f = fdopen(fd, "w");
        fputs("drag3d basin 2380 1450 frames 40\n", f);
        fclose(f);
        ui_script s;
        char err[512];
        CHECK(ui_script_read(path, &s, err, sizeof err) == 0);
        CHECK(s.count == 1 && s.actions[0].kind == UI_ACT_DRAG3D &&
              !strcmp(s.actions[0].text, "basin") && s.actions[0].a == 2380 &&
              s.actions[0].b == 1450 && s.actions[0].frames == 40);
        ui_script_free(&s);
        f = fopen(path, "w");
        fputs("drag3d basin 2380\n", f);
        fclose(f);
        CHECK(ui_script_read(path, &s, err, sizeof err) != 0);
        CHECK(strstr(err, "drag3d needs a name and a plan point") != NULL);
        unlink(path);
    }
    return check_report("ui.fixture_drag");
}
