/* The renderer's API contract on a real context: validation, stale handles, limits,
 * read-back, exposure, supersampling. The backend comes from TESSERA_GL. */
#include "../common/check.h"
#include "render/primitives.h"
#include "render/render.h"
#include "render/shade_ref.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static rd_mesh make_plane(rd_context *ctx)
{
    rd_mesh_data d;
    rd_mesh_data_plane(&d);
    rd_mesh_desc desc = rd_mesh_data_desc(&d);
    rd_mesh m = rd_mesh_create(ctx, &desc);
    rd_mesh_data_free(&d);
    return m;
}

static rd_view view_of_plane(int w, int h)
{
    return (rd_view){
        .eye = {0, -0.01f, 3}, .target = {0, 0, 0}, .fov_y_deg = 40, .width = w, .height = h};
}

static void test_validation(rd_context *ctx)
{
    const char *want = getenv("TESSERA_GL");
    if (want && *want)
        CHECK_MSG(!strcmp(rd_backend_name(rd_context_backend(ctx)), want), "backend %s, want %s",
                  rd_backend_name(rd_context_backend(ctx)), want);
    CHECK(rd_context_max_size(ctx) >= 4096);

    float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0}, nrm[9] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    uint32_t bad_idx[3] = {0, 1, 7};
    rd_mesh m = rd_mesh_create(ctx, &(rd_mesh_desc){.positions = pos,
                                                    .normals = nrm,
                                                    .indices = bad_idx,
                                                    .vertex_count = 3,
                                                    .index_count = 3});
    CHECK(m.id == 0 && strstr(rd_last_error(), "index"));
    pos[4] = NAN;
    uint32_t idx[3] = {0, 1, 2};
    m = rd_mesh_create(
        ctx,
        &(rd_mesh_desc){
            .positions = pos, .normals = nrm, .indices = idx, .vertex_count = 3, .index_count = 3});
    CHECK(m.id == 0 && strstr(rd_last_error(), "finite"));

    /* A destroyed mesh's handle is stale, even after its slot is reused. */
    rd_mesh a = make_plane(ctx);
    CHECK(a.id != 0);
    rd_mesh_destroy(ctx, a);
    rd_mesh b = make_plane(ctx);
    CHECK(b.id != 0 && b.id != a.id);
    rd_scene *s = rd_scene_create(ctx);
    CHECK(rd_scene_add_object(s, &(rd_object_desc){.mesh = a}) == RD_ERR_STALE_HANDLE);
    CHECK(rd_scene_add_object(s, &(rd_object_desc){.mesh = b}) == RD_OK);
    CHECK(rd_scene_add_object(s, &(rd_object_desc){.mesh = {12345}}) == RD_ERR_STALE_HANDLE);
    rd_mesh_destroy(ctx, a); /* twice: harmless */

    rd_light dir = {.type = RD_LIGHT_DIRECTIONAL};
    CHECK(rd_scene_add_light(s, &dir) == RD_ERR_INVALID_ARGUMENT);
    rd_light point = {.type = RD_LIGHT_POINT, .attenuation = {1, 0, 0}};
    for (int i = 0; i < RD_MAX_LIGHTS; i++)
        CHECK(rd_scene_add_light(s, &point) == RD_OK);
    CHECK(rd_scene_add_light(s, &point) == RD_ERR_TOO_LARGE);

    uint8_t px[4];
    rd_view v = view_of_plane(0, 10);
    CHECK(rd_render(ctx, s, &v) == RD_ERR_INVALID_ARGUMENT);
    v = view_of_plane(100000, 100000);
    CHECK(rd_render(ctx, s, &v) == RD_ERR_TOO_LARGE && strstr(rd_last_error(), "100000x100000"));
    v = view_of_plane(8, 8);
    v.supersample = 5;
    CHECK(rd_render(ctx, s, &v) == RD_ERR_INVALID_ARGUMENT);
    v = view_of_plane(8, 8);
    memcpy(v.target, v.eye, sizeof v.eye);
    CHECK(rd_render(ctx, s, &v) == RD_ERR_INVALID_ARGUMENT);
    v = view_of_plane(8, 8);
    v.eye[0] = INFINITY;
    CHECK(rd_render(ctx, s, &v) == RD_ERR_INVALID_ARGUMENT);
    v = view_of_plane(1, 1);
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_read_rgba8(ctx, px, 3) == RD_ERR_INVALID_ARGUMENT);
    CHECK(rd_read_rgba8(ctx, px, 4) == RD_OK);
    /* Looking straight down the up vector still gives a view. */
    v = (rd_view){.eye = {0, 0, 3}, .target = {0, 0, 0}, .width = 4, .height = 4};
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    rd_scene_destroy(s);
    rd_mesh_destroy(ctx, b);
}

/* An emissive plane filling the view: the linear read-back is emissive x 2^EV exactly (to
 * half precision), and the 8-bit read-back is the reference's display value. */
static void test_exposure_and_readback(rd_context *ctx)
{
    rd_mesh plane = make_plane(ctx);
    rd_scene *s = rd_scene_create(ctx);
    rd_object_desc o = {.mesh = plane, .material = {.emissive = {0.3f, 0.05f, 2.0f}}};
    o.transform[0] = o.transform[5] = 100.0f;
    o.transform[10] = o.transform[15] = 1.0f;
    CHECK(rd_scene_add_object(s, &o) == RD_OK);
    enum { W = 16, H = 12 };
    for (int ev = -1; ev <= 1; ev++) {
        rd_view v = view_of_plane(W, H);
        v.exposure_ev = (float)ev;
        CHECK(rd_render(ctx, s, &v) == RD_OK);
        float lin[W * H * 4];
        uint8_t rgb[W * H * 4];
        CHECK(rd_read_linear(ctx, lin, W * H * 4) == RD_OK);
        CHECK(rd_read_rgba8(ctx, rgb, sizeof rgb) == RD_OK);
        unsigned char ref[3];
        rd_ref_display_rgb8(o.material.emissive, (float)ev, RD_TONEMAP_PHOTOGRAPHIC, 4.0f, ref);
        float scale = exp2f((float)ev);
        int worst = 0;
        float worst_lin = 0.0f;
        for (int i = 0; i < W * H; i++)
            for (int k = 0; k < 3; k++) {
                worst = abs(rgb[i * 4 + k] - ref[k]) > worst ? abs(rgb[i * 4 + k] - ref[k]) : worst;
                float rel = fabsf(lin[i * 4 + k] - o.material.emissive[k] * scale) /
                            (o.material.emissive[k] * scale);
                worst_lin = rel > worst_lin ? rel : worst_lin;
            }
        CHECK_MSG(worst <= 1, "ev %d: 8-bit off by %d", ev, worst);
        CHECK_MSG(worst_lin < 1e-3f, "ev %d: linear off by %g relative", ev, worst_lin);
    }
    rd_scene_destroy(s);
    rd_mesh_destroy(ctx, plane);
}

/* 2x2 supersampling: the same picture, with edges antialiased (intermediate values). */
static void test_supersampling(rd_context *ctx)
{
    rd_mesh plane = make_plane(ctx);
    rd_scene *s = rd_scene_create(ctx);
    rd_object_desc o = {.mesh = plane, .material = {.emissive = {100, 100, 100}}}; /* saturates */
    float c = cosf(0.3f), sn = sinf(0.3f);
    o.transform[0] = c, o.transform[1] = sn, o.transform[4] = -sn, o.transform[5] = c;
    o.transform[10] = o.transform[15] = 1.0f;
    CHECK(rd_scene_add_object(s, &o) == RD_OK);
    enum { W = 64, H = 64 };
    static uint8_t one[W * H * 4], four[W * H * 4];
    rd_view v = view_of_plane(W, H);
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_read_rgba8(ctx, one, sizeof one) == RD_OK);
    v.supersample = 2;
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_read_rgba8(ctx, four, sizeof four) == RD_OK);
    long sum1 = 0, sum4 = 0;
    int partial1 = 0, partial4 = 0;
    for (int i = 0; i < W * H; i++) {
        sum1 += one[i * 4];
        sum4 += four[i * 4];
        partial1 += one[i * 4] > 10 && one[i * 4] < 200;
        partial4 += four[i * 4] > 10 && four[i * 4] < 200;
    }
    CHECK_MSG(labs(sum1 - sum4) < W * H * 4, "same coverage: %ld vs %ld", sum1, sum4);
    CHECK_MSG(partial1 == 0 && partial4 > 20, "antialiased edge pixels: %d without, %d with",
              partial1, partial4);
    rd_scene_destroy(s);
    rd_mesh_destroy(ctx, plane);
}

/* Back faces of closed meshes are culled; a mirroring transform (negative determinant) must
 * not turn the mesh inside out: a lit sphere mirrored in x looks like the sphere. */
static void test_culling_and_mirroring(rd_context *ctx)
{
    rd_mesh_data d;
    rd_mesh_data_sphere(32, 16, &d);
    rd_mesh_desc desc = rd_mesh_data_desc(&d);
    rd_mesh sphere = rd_mesh_create(ctx, &desc);
    rd_mesh_data_free(&d);
    enum { W = 48, H = 48 };
    static uint8_t img[2][W * H * 4];
    for (int mirrored = 0; mirrored < 2; mirrored++) {
        rd_scene *s = rd_scene_create(ctx);
        rd_object_desc o = {.mesh = sphere,
                            .material = {.diffuse = {0.8f, 0.8f, 0.8f},
                                         .specular = {0.5f, 0.5f, 0.5f},
                                         .shininess = 30}};
        o.transform[0] = mirrored ? -1.0f : 1.0f;
        o.transform[5] = o.transform[10] = o.transform[15] = 1.0f;
        CHECK(rd_scene_add_object(s, &o) == RD_OK);
        rd_light l = {.type = RD_LIGHT_POINT,
                      .position = {0, -2, 1},
                      .diffuse = {1, 1, 1},
                      .specular = {1, 1, 1},
                      .attenuation = {1, 0, 0}};
        CHECK(rd_scene_add_light(s, &l) == RD_OK);
        rd_view v = {.eye = {0, -3, 0}, .target = {0, 0, 0}, .width = W, .height = H};
        CHECK(rd_render(ctx, s, &v) == RD_OK);
        CHECK(rd_read_rgba8(ctx, img[mirrored], sizeof img[mirrored]) == RD_OK);
        rd_scene_destroy(s);
    }
    int worst = 0, lit = 0;
    for (int i = 0; i < W * H * 4; i++) {
        int diff = abs(img[0][i] - img[1][i]);
        worst = diff > worst ? diff : worst;
    }
    for (int i = 0; i < W * H; i++)
        lit += img[0][i * 4] > 40;
    CHECK_MSG(lit > W * H / 20, "the sphere is visible and lit (%d pixels)", lit);
    CHECK_MSG(worst <= 2, "mirrored sphere differs by %d", worst);
    rd_mesh_destroy(ctx, sphere);
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(NULL, &ctx) != RD_OK) {
        fprintf(stderr, "no context: %s\n", rd_last_error());
        return 1;
    }
    test_validation(ctx);
    test_exposure_and_readback(ctx);
    test_supersampling(ctx);
    test_culling_and_mirroring(ctx);
    rd_context_destroy(ctx);
    return check_report("render_api");
}
