/* Drag and drop's geometry (ui/src/drag_drop.h): the floor point under a window pixel is where
 * the renderer's own projection (cglm look-at and perspective, as render/src/camera.c) puts it
 * back; rays above the horizon find no floor. And the script actions of drag and drop, the
 * quantities and the file panel are read and checked (ui/src/script.h). */
#include "check.h"
#include "drag_drop.h"
#include "script.h"

#include <cglm/cglm.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* Window pixel of world point (mm) for the camera, with cglm as the renderer does. */
static void project(const double eye[3], const double target[3], double fov, int w, int h,
                    const double pt[3], double *sx, double *sy)
{
    vec3 e = {(float)eye[0], (float)eye[1], (float)eye[2]};
    vec3 t = {(float)target[0], (float)target[1], (float)target[2]};
    vec3 up = {0, 0, 1};
    mat4 view, proj, vp;
    glm_lookat(e, t, up, view);
    glm_perspective(glm_rad((float)fov), (float)w / (float)h, 10.0f, 1e6f, proj);
    glm_mat4_mul(proj, view, vp);
    vec4 p = {(float)pt[0], (float)pt[1], (float)pt[2], 1.0f}, c;
    glm_mat4_mulv(vp, p, c);
    *sx = (c[0] / c[3] * 0.5 + 0.5) * w;
    *sy = (0.5 - c[1] / c[3] * 0.5) * h;
}

static void test_floor_point(void)
{
    const double eyes[3][3] = {{1300, -500, 1600}, {200, 300, 2400}, {2500, 3000, 900}};
    const double targets[3][3] = {{1300, 1600, 700}, {1800, 2500, 0}, {600, 800, 500}};
    const double fovs[3] = {60, 45, 75};
    const double pixels[4][2] = {{640, 360}, {100, 700}, {1200, 650}, {333.5, 512.25}};
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < 4; i++) {
            double out[2];
            int hit = ui_floor_point(eyes[c], targets[c], fovs[c], 1280, 720, pixels[i][0],
                                     pixels[i][1], out);
            CHECK_MSG(hit, "camera %d pixel %d", c, i);
            if (!hit)
                continue;
            double pt[3] = {out[0], out[1], 0}, sx, sy;
            project(eyes[c], targets[c], fovs[c], 1280, 720, pt, &sx, &sy);
            CHECK_MSG(fabs(sx - pixels[i][0]) < 0.05 && fabs(sy - pixels[i][1]) < 0.05,
                      "camera %d: pixel %.2f %.2f -> floor %.1f %.1f -> pixel %.2f %.2f", c,
                      pixels[i][0], pixels[i][1], out[0], out[1], sx, sy);
        }
    /* The centre pixel of a camera looking at a floor point finds that point. */
    double eye[3] = {0, 0, 1000}, target[3] = {1000, 500, 0}, out[2];
    CHECK(ui_floor_point(eye, target, 50, 800, 600, 400, 300, out));
    CHECK(fabs(out[0] - 1000) < 1e-6 && fabs(out[1] - 500) < 1e-6);
    /* A level camera: the top half of the window is above the horizon. */
    double level[3] = {1000, 0, 1000};
    CHECK(!ui_floor_point(eye, level, 60, 800, 600, 400, 100, out));
    CHECK(ui_floor_point(eye, level, 60, 800, 600, 400, 500, out));
    /* Straight down: the centre is under the eye. */
    double down[3] = {0, 0, 0};
    CHECK(ui_floor_point(eye, down, 60, 800, 600, 400, 300, out));
    CHECK(fabs(out[0]) < 1e-6 && fabs(out[1]) < 1e-6);
    /* Degenerate input. */
    CHECK(!ui_floor_point(eye, eye, 60, 800, 600, 400, 300, out));
    CHECK(!ui_floor_point(eye, target, 0, 800, 600, 400, 300, out));
    CHECK(!ui_floor_point(eye, target, 60, 0, 600, 400, 300, out));
    double below[3] = {0, 0, -10};
    CHECK(!ui_floor_point(below, target, 60, 800, 600, 400, 300, out));
}

static int read_script(const char *text, ui_script *s, char *err, size_t size)
{
    char path[] = "/tmp/tessera-ui-dnd-XXXXXX";
    int fd = mkstemp(path);
    if (fd < 0)
        return -1;
    FILE *f = fdopen(fd, "w");
    fputs(text, f);
    fclose(f);
    int rc = ui_script_read(path, s, err, size);
    unlink(path);
    return rc;
}

static void test_script_actions(void)
{
    ui_script s;
    char err[1024] = "";
    CHECK_MSG(read_script("drag-selected plan 400 300 frames 5\ndrop-selected plan 400 300\n"
                          "drop-selected 3d 640.5 500 frames 4\nexpect-total 100 99999.5\nnew\n"
                          "open /tmp/a b.json\n",
                          &s, err, sizeof err) == 1,
              "a path with a space is two words");
    CHECK_MSG(read_script("drag-selected plan 400 300 frames 5\ndrop-selected plan 400 300\n"
                          "drop-selected 3d 640.5 500 frames 4\nexpect-total 100 99999.5\nnew\n"
                          "open /tmp/a.json\nsave-as /tmp/b.json\n",
                          &s, err, sizeof err) == 0,
              "%s", err);
    CHECK(s.count == 7);
    if (s.count == 7) {
        CHECK(s.actions[0].kind == UI_ACT_DRAG_SELECTED && s.actions[0].frames == 5 &&
              !strcmp(s.actions[0].text, "plan") && s.actions[0].a == 400 && s.actions[0].b == 300);
        CHECK(s.actions[1].kind == UI_ACT_DROP_SELECTED && s.actions[1].frames == 1);
        CHECK(s.actions[2].kind == UI_ACT_DROP_SELECTED && !strcmp(s.actions[2].text, "3d") &&
              s.actions[2].a == 640.5 && s.actions[2].frames == 4);
        CHECK(s.actions[3].kind == UI_ACT_EXPECT_TOTAL && s.actions[3].a == 100 &&
              s.actions[3].b == 99999.5);
        CHECK(s.actions[4].kind == UI_ACT_NEW);
        CHECK(s.actions[5].kind == UI_ACT_OPEN && !strcmp(s.actions[5].text, "/tmp/a.json"));
        CHECK(s.actions[6].kind == UI_ACT_SAVE_AS && !strcmp(s.actions[6].text, "/tmp/b.json"));
    }
    ui_script_free(&s);
    static const struct {
        const char *text, *message;
    } bad[] = {
        {"drop-selected side 1 2\n", "drop-selected is 3d or plan"},
        {"drop-selected plan 1\n", "drop-selected needs plan or 3d and a window pixel SX SY"},
        {"drag-selected 3d\n", "drag-selected needs plan or 3d and a window pixel SX SY"},
        {"expect-total 500 100\n", "expect-total needs MIN <= MAX"},
        {"expect-total 5\n", "expect-total needs 2 numbers"},
        {"open\n", "open needs a name"},
        {"save-as\n", "save-as needs a name"},
        {"new now\n", "unexpected \"now\" after new"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        err[0] = 0;
        CHECK_MSG(read_script(bad[i].text, &s, err, sizeof err) == 1 &&
                      strstr(err, bad[i].message) && strstr(err, ":1: "),
                  "%s -> %s", bad[i].text, err);
    }
}

int main(void)
{
    test_floor_point();
    test_script_actions();
    return check_report("ui.drag_drop");
}
