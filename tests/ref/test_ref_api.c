/* The tracer's API on bad input (a result and a message, never a crash) and at the numerical
 * extremes of RENDERING.md section 11 (every pixel finite). */
#include "../common/check.h"
#include "ref_test_scenes.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static int all_finite(const ref_image *img)
{
    for (int i = 0; i < 4 * img->width * img->height; i++)
        if (!isfinite(img->linear[i]))
            return 0;
    return 1;
}

static void bad_input(void)
{
    ref_scene *s = ref_scene_create();
    CHECK(s != NULL);
    float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0}, nrm[9] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    uint32_t idx[3] = {0, 1, 2}, bad_idx[3] = {0, 1, 3};
    ref_mesh_desc d = {
        .positions = pos, .normals = nrm, .indices = idx, .vertex_count = 3, .index_count = 3};
    CHECK(ref_scene_add_mesh(s, NULL) == REF_ERR_INVALID_ARGUMENT);
    ref_mesh_desc e = d;
    e.indices = bad_idx;
    CHECK(ref_scene_add_mesh(s, &e) == REF_ERR_INVALID_ARGUMENT);
    CHECK(strstr(ref_last_error(), "index") != NULL);
    e = d;
    e.index_count = 2;
    CHECK(ref_scene_add_mesh(s, &e) == REF_ERR_INVALID_ARGUMENT);
    e = d;
    e.positions = NULL;
    CHECK(ref_scene_add_mesh(s, &e) == REF_ERR_INVALID_ARGUMENT);
    e = d;
    e.texture = 3;
    CHECK(ref_scene_add_mesh(s, &e) == REF_ERR_INVALID_ARGUMENT);
    e = d;
    e.transform[0] = NAN;
    CHECK(ref_scene_add_mesh(s, &e) == REF_ERR_INVALID_ARGUMENT);
    float nan_pos[9] = {0, 0, 0, NAN, 0, 0, 0, 1, 0};
    e = d;
    e.positions = nan_pos;
    CHECK(ref_scene_add_mesh(s, &e) == REF_ERR_INVALID_ARGUMENT);
    CHECK(ref_scene_mesh_count(s) == 0);
    CHECK(ref_scene_add_mesh(s, &d) == REF_OK);
    CHECK(ref_scene_mesh_count(s) == 1);

    CHECK(ref_scene_add_texture(s, NULL) == 0);
    CHECK(ref_scene_add_texture(s, &(ref_texture_desc){0, 4, pos}) == 0);

    rd_light dir0 = {.type = RD_LIGHT_DIRECTIONAL};
    CHECK(ref_scene_add_light(s, &dir0) == REF_ERR_INVALID_ARGUMENT);
    rd_light pt = {.type = RD_LIGHT_POINT, .diffuse = {1, 1, 1}, .attenuation = {1, 0, 0}};
    for (int i = 0; i < RD_MAX_LIGHTS; i++)
        CHECK(ref_scene_add_light(s, &pt) == REF_OK);
    CHECK(ref_scene_add_light(s, &pt) == REF_ERR_TOO_LARGE);

    rd_view v = {.eye = {0.2f, 0.2f, 1}, .target = {0.2f, 0.2f, 0}, .width = 8, .height = 8};
    ref_image img;
    CHECK(ref_render(NULL, &(ref_render_desc){.view = v}, &img) == REF_ERR_INVALID_ARGUMENT);
    CHECK(img.linear == NULL && img.width == 0);
    CHECK(ref_render(s, NULL, &img) == REF_ERR_INVALID_ARGUMENT);
    CHECK(ref_render(s, &(ref_render_desc){.view = v}, NULL) == REF_ERR_INVALID_ARGUMENT);
    rd_view w = v;
    w.width = 0;
    CHECK(ref_render(s, &(ref_render_desc){.view = w}, &img) == REF_ERR_INVALID_ARGUMENT);
    w = v;
    w.width = 100000;
    CHECK(ref_render(s, &(ref_render_desc){.view = w}, &img) == REF_ERR_TOO_LARGE);
    w = v;
    w.supersample = 17;
    CHECK(ref_render(s, &(ref_render_desc){.view = w}, &img) == REF_ERR_INVALID_ARGUMENT);
    CHECK(ref_render(s, &(ref_render_desc){.view = v, .samples = -1}, &img) ==
          REF_ERR_INVALID_ARGUMENT);
    CHECK(strstr(ref_last_error(), "samples") != NULL);
    CHECK(ref_render(s, &(ref_render_desc){.view = v, .threads = -2}, &img) ==
          REF_ERR_INVALID_ARGUMENT);
    w = v;
    w.exposure_ev = 100.0f;
    CHECK(ref_render(s, &(ref_render_desc){.view = w}, &img) == REF_ERR_INVALID_ARGUMENT);
    w = v;
    memcpy(w.target, w.eye, sizeof w.target);
    CHECK(ref_render(s, &(ref_render_desc){.view = w}, &img) == REF_ERR_INVALID_ARGUMENT);
    CHECK(strstr(ref_last_error(), "target") != NULL);
    w = v;
    w.fov_y_deg = 180.0f;
    CHECK(ref_render(s, &(ref_render_desc){.view = w}, &img) == REF_ERR_INVALID_ARGUMENT);
    float o[3], dir[3];
    CHECK(ref_camera_ray(&w, 1, 1, o, dir) == REF_ERR_INVALID_ARGUMENT);
    CHECK(ref_trace_ray(s, o, (float[3]){0, 0, 0}, 4, 0, dir) == REF_ERR_INVALID_ARGUMENT);
    ref_hit hit;
    CHECK(ref_scene_intersect(s, (float[3]){0.2f, 0.2f, 1}, (float[3]){0, 0, 0}, &hit) == 0);
    CHECK(ref_scene_intersect(s, (float[3]){0.2f, 0.2f, 1}, (float[3]){0, 0, -2}, &hit) == 1);
    CHECK(hit.mesh == 0 && hit.triangle == 0 && hit.front == 1 && fabsf(hit.t - 1.0f) < 1e-6f);
    CHECK(fabsf(hit.position[0] - 0.2f) < 1e-6f && fabsf(hit.normal[2] - 1.0f) < 1e-6f);
    /* A good render after the bad ones; the pure-black background where nothing is hit. */
    CHECK(ref_render(s, &(ref_render_desc){.view = v, .threads = 1}, &img) == REF_OK);
    CHECK(img.width == 8 && img.height == 8 && all_finite(&img) && img.rays == 64);
    ref_image_free(&img);
    ref_image_free(&img); /* twice is fine */
    ref_scene_destroy(s);
    ref_scene_destroy(NULL);

    /* An empty scene renders black. */
    s = ref_scene_create();
    CHECK(ref_render(s, &(ref_render_desc){.view = v}, &img) == REF_OK);
    int black = 1;
    for (int i = 0; i < 64; i++)
        black &= img.linear[4 * i] == 0.0f && img.rgba8[4 * i] == 0 && img.rgba8[4 * i + 3] == 255;
    CHECK(black);
    ref_image_free(&img);
    ref_scene_destroy(s);
}

/* Section 11: gloss 0 and 1 and 1e-6 from each, k_r 0 and 1, shininess 0 and 10 000, zero-length
 * and back-facing normals, a zero-size object, HDR 1e6 and NaN texels, scenes of 1 mm and
 * 10 km: all finite. */
static void extremes(float scale)
{
    const float glosses[] = {0.0f, 1e-6f, 0.5f, 1.0f - 1e-6f, 1.0f};
    const float krs[] = {0.0f, 1.0f};
    const float shin[] = {0.0f, 10000.0f};
    const float room[3] = {4 * scale, 4 * scale, 3 * scale};
    ref_scene *s = ref_scene_create();
    CHECK(add_glowing_room(s, room) == REF_OK);
    float tex[4 * 4] = {NAN,      0.5f, 0.5f, 1, 1e6f, 1e6f, 1e6f, 1,
                        INFINITY, 0,    0,    1, 0.2f, 0.3f, 0.4f, 1};
    int t = ref_scene_add_texture(s, &(ref_texture_desc){2, 2, tex});
    CHECK(t == 1);
    int n = 0;
    for (int g = 0; g < 5; g++)
        for (int k = 0; k < 2; k++)
            for (int h = 0; h < 2; h++, n++) {
                rd_material m = {.diffuse = {0.5f, 0.5f, 0.5f},
                                 .specular = {1, 1, 1},
                                 .emissive = {n == 3 ? 1e6f : 0.0f, 0, 0},
                                 .shininess = shin[h],
                                 .reflectivity = krs[k],
                                 .glossiness = glosses[g],
                                 .blend = (rd_reflection_blend)(n % 3),
                                 .transparency = n % 4 == 1 ? 0.5f : 0.0f,
                                 .dispersion = n % 8 == 1 ? 0.05f : 0.0f};
                /* Patches on the wall x = max, with degenerate normals on every other one. */
                float o[3] = {3.9f * scale, (0.2f + 0.18f * (float)(n % 20)) * scale,
                              (0.5f + 0.1f * (float)(n % 7)) * scale};
                float u[3] = {0, 0, 0.3f * scale}, v[3] = {0, 0.15f * scale, 0};
                float pos[12], nrm[12], uv[8] = {0, 0, 1, 0, 0, 1, 1, 1};
                for (int c = 0; c < 4; c++)
                    for (int q = 0; q < 3; q++) {
                        pos[3 * c + q] = o[q] + (float)(c & 1) * u[q] + (float)(c >> 1) * v[q];
                        /* zero-length, and facing away from the camera */
                        nrm[3 * c + q] = n % 2 ? 0.0f : (q == 0 ? 1.0f : 0.0f);
                    }
                static const uint32_t idx[6] = {0, 1, 3, 0, 3, 2};
                ref_mesh_desc d = {.positions = pos,
                                   .normals = nrm,
                                   .uvs = uv,
                                   .indices = idx,
                                   .vertex_count = 4,
                                   .index_count = 6,
                                   .material = m,
                                   .texture = n % 5 == 0 ? t : 0,
                                   .double_sided = n % 3 == 0};
                CHECK(ref_scene_add_mesh(s, &d) == REF_OK);
            }
    /* A zero-size object: every vertex at one point. */
    float zero[16] = {0};
    zero[15] = 1.0f;
    zero[12] = 2 * scale;
    rd_material chrome = {.reflectivity = 1, .glossiness = 0.3f};
    float p3[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0}, n3[9] = {0};
    uint32_t i3[3] = {0, 1, 2};
    ref_mesh_desc zd = {.positions = p3,
                        .normals = n3,
                        .indices = i3,
                        .vertex_count = 3,
                        .index_count = 3,
                        .material = chrome};
    memcpy(zd.transform, zero, sizeof zero);
    zd.transform[0] = 1e-30f; /* not all zero (that means identity) but no area */
    CHECK(ref_scene_add_mesh(s, &zd) == REF_OK);
    rd_light l = {.type = RD_LIGHT_SPOT,
                  .position = {2 * scale, 2 * scale, 2.9f * scale},
                  .direction = {0.5f, 0, -1},
                  .diffuse = {1, 1, 1},
                  .specular = {1, 1, 1},
                  .attenuation = {1, 0, 1},
                  .spot_inner_cos = 0.9f,
                  .spot_outer_cos = 0.9f};
    CHECK(ref_scene_add_light(s, &l) == REF_OK);
    rd_view v = {.eye = {1 * scale, 2 * scale, 1.4f * scale},
                 .target = {4 * scale, 2 * scale, 1.2f * scale},
                 .fov_y_deg = 80,
                 .width = 48,
                 .height = 32,
                 .supersample = 2};
    ref_image img;
    CHECK(ref_render(s, &(ref_render_desc){.view = v, .samples = 8}, &img) == REF_OK);
    int masked = 0;
    for (int i = 0; i < 48 * 32; i++)
        masked += img.mask[i];
    CHECK_MSG(all_finite(&img), "scale %g: a pixel is not finite", (double)scale);
    CHECK_MSG(masked > 0, "scale %g: no reflective pixel", (double)scale);
    printf("extremes at scale %g: %d reflective pixels, all finite\n", (double)scale, masked);
    ref_image_free(&img);
    ref_scene_destroy(s);
}

/* ref_trace_ray gives what ref_render gives a pixel centre (no footprint, no randomness on a
 * mirror). */
static void single_ray(void)
{
    ref_scene *s = ref_scene_create();
    const float room[3] = {4, 4, 3};
    CHECK(add_glowing_room(s, room) == REF_OK);
    rd_material mirror = {.reflectivity = 0.7f, .glossiness = 1.0f, .diffuse = {0.2f, 0.2f, 0.2f}};
    const float o[3] = {3.5f, 1, 0.5f}, u[3] = {0, 0, 2}, v[3] = {0, 2, 0};
    CHECK(add_rect(s, o, u, v, &mirror, 1) == REF_OK);
    rd_view view = {.eye = {1, 2, 1.5f}, .target = {3.5f, 2, 1.5f}, .width = 16, .height = 12};
    ref_image img;
    CHECK(ref_render(s, &(ref_render_desc){.view = view}, &img) == REF_OK);
    int same = 1;
    for (int y = 0; y < 12; y++)
        for (int x = 0; x < 16; x++) {
            float org[3], dir[3], c[3];
            ref_camera_ray(&view, (float)x + 0.5f, (float)y + 0.5f, org, dir);
            CHECK(ref_trace_ray(s, org, dir, 1, 0, c) == REF_OK);
            for (int k = 0; k < 3; k++)
                same &= c[k] == img.linear[4 * (y * 16 + x) + k];
        }
    CHECK(same);
    ref_image_free(&img);
    ref_scene_destroy(s);
}

int main(void)
{
    bad_input();
    extremes(1.0f);
    extremes(1e-3f);   /* a 4 mm room */
    extremes(2500.0f); /* a 10 km room */
    single_ray();
    return check_report("test_ref_api");
}
