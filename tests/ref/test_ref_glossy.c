/* Monte-Carlo over the gloss lobe (RENDERING.md section 5): against a 4096-sample image the error
 * falls from 1 to 16 to 256 samples, and an image depends only on its seed, never on the number
 * of threads or the tiling. */
#include "../common/check.h"
#include "ref_test_scenes.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define W 24
#define H 18

static const float room[3] = {4.0f, 4.0f, 3.0f};

static ref_scene *glossy_scene(void)
{
    ref_scene *s = ref_scene_create();
    CHECK(s && add_glowing_room(s, room) == REF_OK);
    /* A glossy panel (g = 0.5: n = 2^6.5) on the wall x = 3.9, facing the camera, lit. */
    rd_material m = {.diffuse = {0.2f, 0.2f, 0.2f},
                     .specular = {0.5f, 0.5f, 0.5f},
                     .shininess = 30.0f,
                     .reflectivity = 0.8f,
                     .glossiness = 0.5f};
    const float o[3] = {3.9f, 0.5f, 0.3f}, u[3] = {0, 0, 2.4f}, v[3] = {0, 3, 0};
    CHECK(add_rect(s, o, u, v, &m, 1) == REF_OK);
    /* Something with edges for the lobe to blur: a bright bar across the opposite wall. */
    rd_material bar = {.emissive = {3.0f, 3.0f, 2.5f}};
    const float bo[3] = {0.05f, 1.0f, 1.2f}, bu[3] = {0, 2.0f, 0}, bv[3] = {0, 0, 0.4f};
    CHECK(add_rect(s, bo, bu, bv, &bar, 1) == REF_OK);
    rd_light l = {.type = RD_LIGHT_POINT,
                  .position = {2, 2, 2.5f},
                  .diffuse = {1, 1, 1},
                  .specular = {1, 1, 1},
                  .attenuation = {1, 0, 0.2f}};
    CHECK(ref_scene_add_light(s, &l) == REF_OK);
    return s;
}

static ref_image render(ref_scene *s, int samples, int threads, int tile, uint32_t seed)
{
    rd_view view = {.eye = {1.2f, 2.0f, 1.5f},
                    .target = {3.9f, 2.0f, 1.5f},
                    .fov_y_deg = 40.0f,
                    .width = W,
                    .height = H};
    ref_image img;
    ref_result r = ref_render(
        s,
        &(ref_render_desc){
            .view = view, .samples = samples, .threads = threads, .tile = tile, .seed = seed},
        &img);
    CHECK_MSG(r == REF_OK, "%s", ref_last_error());
    return img;
}

static double rmse(const ref_image *a, const ref_image *b)
{
    double sum = 0.0;
    for (int i = 0; i < W * H; i++)
        for (int k = 0; k < 3; k++) {
            double d = (double)a->linear[4 * i + k] - b->linear[4 * i + k];
            sum += d * d;
        }
    return sqrt(sum / (3.0 * W * H));
}

int main(void)
{
    ref_scene *s = glossy_scene();
    ref_image truth = render(s, 4096, 0, 0, 7);
    int masked = 0;
    for (int i = 0; i < W * H; i++)
        masked += truth.mask[i];
    CHECK_MSG(masked == W * H, "the panel should fill the view: %d of %d masked", masked, W * H);

    double err[3];
    const int counts[3] = {1, 16, 256};
    for (int i = 0; i < 3; i++) {
        ref_image img = render(s, counts[i], 0, 0, 1234); /* a seed the truth does not use */
        err[i] = rmse(&img, &truth);
        printf("samples %4d: rmse %.5f against 4096 samples\n", counts[i], err[i]);
        ref_image_free(&img);
    }
    CHECK_MSG(err[0] > err[1] && err[1] > err[2], "%g %g %g", err[0], err[1], err[2]);
    /* Importance sampling: the error falls about as 1 / sqrt(samples) or faster; 16x the samples
     * must at least halve it. */
    CHECK(err[1] < 0.5 * err[0] && err[2] < 0.5 * err[1]);
    CHECK(err[0] > 0.0);

    /* The same seed: the same image, bit for bit, whatever the threads and tiles. */
    ref_image one = render(s, 16, 1, 0, 99);
    ref_image three = render(s, 16, 3, 5, 99);
    ref_image again = render(s, 16, 2, 1, 99);
    CHECK(memcmp(one.linear, three.linear, sizeof(float) * 4 * W * H) == 0);
    CHECK(memcmp(one.linear, again.linear, sizeof(float) * 4 * W * H) == 0);
    CHECK(memcmp(one.rgba8, three.rgba8, 4 * W * H) == 0);
    CHECK(memcmp(one.mask, three.mask, W * H) == 0);
    CHECK(three.threads_used == 3 && one.threads_used == 1);
    /* Another seed: another image. */
    ref_image other = render(s, 16, 2, 0, 100);
    CHECK(memcmp(one.linear, other.linear, sizeof(float) * 4 * W * H) != 0);

    ref_image_free(&one);
    ref_image_free(&three);
    ref_image_free(&again);
    ref_image_free(&other);
    ref_image_free(&truth);
    ref_scene_destroy(s);
    return check_report("test_ref_glossy");
}
