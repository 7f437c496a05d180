/* Next-event estimation of the renderer's lights in the path tracer (docs/reference.md,
 * "Indirect light"): on a lone plane, where no light can bounce back, the path-traced image
 * with bounces is the direct-only image without the ambient term -- section 1's point, spot and
 * directional terms exactly as rd_ref_shade computes them -- however many paths and bounces;
 * and the ambient term the direct-only tracer adds is left out. */
#include "../common/check.h"
#include "ref_test_scenes.h"

#include <math.h>
#include <stdio.h>

#define W 48
#define H 32

static const rd_material plane_mat = {.ambient = {0.2f, 0.25f, 0.3f},
                                      .diffuse = {0.7f, 0.5f, 0.3f},
                                      .specular = {0.9f, 0.9f, 0.8f},
                                      .shininess = 40.0f};

static const rd_light lights[3] = {
    {.type = RD_LIGHT_POINT,
     .position = {0.3f, -0.2f, 1.2f},
     .diffuse = {1.0f, 0.9f, 0.8f},
     .specular = {1.0f, 1.0f, 1.0f},
     .attenuation = {1.0f, 0.2f, 0.5f}},
    {.type = RD_LIGHT_SPOT,
     .position = {-0.5f, 0.4f, 1.5f},
     .direction = {0.3f, -0.2f, -1.0f},
     .diffuse = {0.4f, 0.6f, 1.0f},
     .specular = {0.5f, 0.5f, 0.5f},
     .attenuation = {1.0f, 0.0f, 0.3f},
     .spot_inner_cos = 0.95f,
     .spot_outer_cos = 0.8f},
    {.type = RD_LIGHT_DIRECTIONAL,
     .direction = {-0.3f, 0.5f, -0.8f},
     .diffuse = {0.5f, 0.5f, 0.45f},
     .specular = {0.3f, 0.3f, 0.3f}},
};

static ref_image render(float ambient, int bounces, int paths)
{
    ref_scene *s = ref_scene_create();
    CHECK(s != NULL);
    const float o[3] = {-2, -2, 0}, u[3] = {4, 0, 0}, v[3] = {0, 4, 0};
    CHECK(add_rect(s, o, u, v, &plane_mat, 0) == REF_OK);
    for (int i = 0; i < 3; i++)
        CHECK(ref_scene_add_light(s, &lights[i]) == REF_OK);
    ref_scene_set_ambient(s, (const float[3]){ambient, ambient, ambient});
    rd_view view = {.eye = {0.4f, -1.6f, 1.4f},
                    .target = {0.1f, 0.2f, 0.0f},
                    .fov_y_deg = 60.0f,
                    .width = W,
                    .height = H};
    ref_image img = {0};
    ref_render_desc d = {
        .view = view, .threads = 2, .bounces = bounces, .samples = paths, .seed = 3};
    CHECK(ref_render(s, &d, &img) == REF_OK);
    ref_scene_destroy(s);
    return img;
}

int main(void)
{
    ref_image direct = render(0.0f, 0, 0), lit_ambient = render(0.15f, 0, 0);
    ref_image paths = render(0.15f, 3, 5);
    int bad = 0, ambient_differs = 0;
    float worst = 0.0f;
    for (int i = 0; i < W * H; i++)
        for (int k = 0; k < 3; k++) {
            float want = direct.linear[4 * i + k], got = paths.linear[4 * i + k];
            float err = fabsf(got - want) / fmaxf(1.0f, want);
            worst = fmaxf(worst, err);
            bad += err > 2e-5f;
            ambient_differs += lit_ambient.linear[4 * i + k] > want + 1e-3f;
        }
    printf("path-traced against direct-only without ambient: worst relative error %.3g\n",
           (double)worst);
    CHECK_MSG(bad == 0, "%d channels off (worst %g)", bad, (double)worst);
    CHECK_MSG(ambient_differs > W * H, "the ambient term lit only %d channels", ambient_differs);
    ref_image_free(&direct);
    ref_image_free(&lit_ambient);
    ref_image_free(&paths);
    return check_report("test_ref_path_direct");
}
