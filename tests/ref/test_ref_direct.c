/* The tracer's direct light is rd_ref_shade (RENDERING.md section 1): a lit plane, traced pixel by
 * pixel, equals the formula evaluated at the analytic intersection of each camera ray, for a
 * point, a spot and a directional light and all three together; back faces of a sheet are lit
 * on the side seen, and a closed mesh is invisible from behind. */
#include "../common/check.h"
#include "ref_test_scenes.h"
#include "render/shade_ref.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define W 64
#define H 48

static const rd_material plane_mat = {.ambient = {0.2f, 0.25f, 0.3f},
                                      .diffuse = {0.7f, 0.5f, 0.3f},
                                      .specular = {0.9f, 0.9f, 0.8f},
                                      .emissive = {0.02f, 0.0f, 0.01f},
                                      .shininess = 40.0f};
static const float ambient[3] = {0.1f, 0.12f, 0.15f};

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

/* The expected radiance of the pixel centre (x, y): the camera ray meets the plane z = 0 at
 * t = -o_z / d_z, the normal faces the eye. Returns 0 if the ray misses the rectangle. */
static int expected(const rd_view *v, int x, int y, const rd_light *l, int n, float out[3])
{
    float o[3], d[3];
    ref_camera_ray(v, (float)x + 0.5f, (float)y + 0.5f, o, d);
    float t = -o[2] / d[2];
    float p[3] = {o[0] + t * d[0], o[1] + t * d[1], 0.0f};
    if (!(t > 0.0f) || fabsf(p[0]) > 1.95f || fabsf(p[1]) > 1.95f)
        return 0;
    float nrm[3] = {0, 0, o[2] > 0.0f ? 1.0f : -1.0f}; /* seen from below: the flipped normal */
    /* Lights as the scene stores them: spot and directional directions normalised. */
    rd_light ls[RD_MAX_LIGHTS];
    for (int i = 0; i < n; i++) {
        ls[i] = l[i];
        if (ls[i].type != RD_LIGHT_POINT) {
            float len = sqrtf(ls[i].direction[0] * ls[i].direction[0] +
                              ls[i].direction[1] * ls[i].direction[1] +
                              ls[i].direction[2] * ls[i].direction[2]);
            for (int k = 0; k < 3; k++)
                ls[i].direction[k] /= len;
        }
    }
    rd_ref_shade(&plane_mat, NULL, p, nrm, v->eye, ls, n, ambient, out);
    return 1;
}

/* Renders the plane (double-sided or closed) under lights l[0..n) from eye and compares every
 * pixel that hits it. Returns the pixels compared. */
static int check_plane(const rd_light *l, int n, const float eye[3], int double_sided,
                       const char *name)
{
    ref_scene *s = ref_scene_create();
    CHECK(s != NULL);
    const float o[3] = {-2, -2, 0}, u[3] = {4, 0, 0}, v[3] = {0, 4, 0};
    CHECK(add_rect(s, o, u, v, &plane_mat, double_sided) == REF_OK);
    for (int i = 0; i < n; i++)
        CHECK(ref_scene_add_light(s, &l[i]) == REF_OK);
    ref_scene_set_ambient(s, ambient);
    rd_view view = {.eye = {eye[0], eye[1], eye[2]},
                    .target = {0.1f, 0.2f, 0.0f},
                    .fov_y_deg = 60.0f,
                    .width = W,
                    .height = H};
    ref_image img;
    CHECK(ref_render(s, &(ref_render_desc){.view = view, .threads = 2}, &img) == REF_OK);
    int compared = 0, bad = 0, bad8 = 0, masked = 0;
    float worst = 0.0f;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const float *got = img.linear + 4 * (y * W + x);
            masked += img.mask[y * W + x];
            float want[3];
            if (!expected(&view, x, y, l, n, want))
                continue;
            if (!double_sided && eye[2] < 0.0f) {
                /* A closed mesh seen from behind is culled: the ray misses, black. */
                bad += got[0] != 0.0f || got[1] != 0.0f || got[2] != 0.0f;
                compared++;
                continue;
            }
            for (int k = 0; k < 3; k++) {
                float err = fabsf(got[k] - want[k]);
                worst = fmaxf(worst, err / fmaxf(1.0f, want[k]));
                /* The same function on hit points that differ by float rounding only. */
                bad += err > 2e-5f * fmaxf(1.0f, want[k]);
            }
            unsigned char want8[3];
            rd_ref_display_rgb8(want, view.exposure_ev, view.tonemap, view.white, want8);
            for (int k = 0; k < 3; k++)
                bad8 += abs((int)img.rgba8[4 * (y * W + x) + k] - (int)want8[k]) > 1;
            compared++;
        }
    CHECK_MSG(bad == 0 && bad8 == 0, "%s: %d channels off (worst relative error %g), %d bytes off",
              name, bad, (double)worst, bad8);
    CHECK_MSG(compared > W * H / 2, "%s: only %d pixels hit the plane", name, compared);
    CHECK_MSG(masked == 0, "%s: %d pixels in the reflection mask", name, masked);
    printf("%s: %d pixels, worst relative error %.3g\n", name, compared, (double)worst);
    ref_image_free(&img);
    ref_scene_destroy(s);
    return compared;
}

int main(void)
{
    const float above[3] = {0.4f, -1.6f, 1.4f}, below[3] = {0.4f, -1.6f, -1.4f};
    check_plane(&lights[0], 1, above, 0, "point");
    check_plane(&lights[1], 1, above, 0, "spot");
    check_plane(&lights[2], 1, above, 0, "directional");
    check_plane(lights, 3, above, 0, "all three");
    /* From below: a sheet is lit on the side seen (the GPU flips the normal on back faces; the
     * lights are above, so only ambient and emissive remain), a closed mesh is culled. */
    check_plane(lights, 3, below, 1, "sheet from below");
    check_plane(lights, 3, below, 0, "closed from below");
    return check_report("test_ref_direct");
}
