/* The tracer's SH9 ambient (RENDERING.md section 7; ref_scene_set_ambient_sh9): in a closed room
 * whose walls glow one colour L, a small patch lit by nothing but its ambient term (C_a = 1)
 * shows max(E(N), 0) / pi = L, the environment's radiance, as the GPU's SH9 test shows it
 * (tests/render/test_reflections.c, test_sh9_ambient). With the constant model and I_a = 0 it
 * is black, and before the tracer knew SH9 it could only be that. No GL. */
#include "../common/check.h"
#include "ref_test_scenes.h"

#include <math.h>
#include <stdio.h>

static const float glow[3] = {0.5f, 0.4f, 0.3f};

static ref_scene *make_scene(void)
{
    ref_scene *s = ref_scene_create();
    if (!s)
        return NULL;
    const float x = 2.0f, y = 2.0f, z = 2.0f;
    const float o[6][3] = {{0, 0, 0}, {x, 0, 0}, {0, 0, 0}, {0, y, 0}, {0, 0, 0}, {0, 0, z}};
    const float u[6][3] = {{0, y, 0}, {0, 0, z}, {0, 0, z}, {x, 0, 0}, {x, 0, 0}, {0, y, 0}};
    const float v[6][3] = {{0, 0, z}, {0, y, 0}, {x, 0, 0}, {0, 0, z}, {0, y, 0}, {x, 0, 0}};
    rd_material wall = {0};
    memcpy(wall.emissive, glow, sizeof wall.emissive);
    for (int i = 0; i < 6; i++)
        CHECK(add_rect(s, o[i], u[i], v[i], &wall, 0) == REF_OK);
    /* A 0.1 m patch facing up, 0.5 m under the capture's centre: it hides little of the room. */
    rd_material patch = {.ambient = {1, 1, 1}};
    const float po[3] = {0.95f, 0.95f, 0.5f}, pu[3] = {0.1f, 0, 0}, pv[3] = {0, 0.1f, 0};
    CHECK(add_rect(s, po, pu, pv, &patch, 0) == REF_OK);
    const float zero[3] = {0, 0, 0};
    ref_scene_set_ambient(s, zero);
    return s;
}

/* The patch's colour seen from straight above. */
static void patch_colour(ref_scene *s, float out[3])
{
    const float eye[3] = {1.0f, 1.0f, 1.5f}, down[3] = {0, 0, -1};
    CHECK(ref_trace_ray(s, eye, down, 1, 0, out) == REF_OK);
}

int main(void)
{
    ref_scene *s = make_scene();
    CHECK(s != NULL);
    if (!s)
        return check_report("test_ref_sh9");
    float c[3];
    patch_colour(s, c);
    CHECK_MSG(c[0] == 0.0f && c[1] == 0.0f && c[2] == 0.0f,
              "constant I_a = 0 lights the patch: %g %g %g", c[0], c[1], c[2]);
    rd_sh9 sh;
    CHECK(!ref_scene_ambient_sh9(s, &sh)); /* off: no coefficients */

    const float centre[3] = {1.0f, 1.0f, 1.0f};
    ref_scene_set_ambient_sh9(s, centre);
    patch_colour(s, c);
    printf("SH9 ambient in a room glowing %.2f %.2f %.2f: the patch shows %.4f %.4f %.4f\n",
           glow[0], glow[1], glow[2], c[0], c[1], c[2]);
    for (int k = 0; k < 3; k++)
        CHECK_MSG(fabsf(c[k] - glow[k]) < 0.03f * glow[k], "channel %d: %g against %g", k, c[k],
                  glow[k]);
    CHECK(ref_scene_ambient_sh9(s, &sh));
    /* L00 of a uniform radiance L is L sqrt(4 pi) (Y00 = 0.282095 over 4 pi steradians). */
    CHECK_MSG(fabsf(sh.coeff[0][0] - glow[0] * 3.5449077f) < 0.05f * glow[0] * 3.5449077f, "L00 %g",
              sh.coeff[0][0]);

    ref_scene_set_ambient_sh9(s, NULL); /* back to I_a */
    patch_colour(s, c);
    CHECK(c[0] == 0.0f && c[1] == 0.0f && c[2] == 0.0f);
    ref_scene_destroy(s);
    return check_report("test_ref_sh9");
}
