/* GPU against the CPU reference (RENDERING.md section 1): every pixel of a lit plane, for each
 * light type, specular exponents 0, 1, 64 and 10 000, and an emissive colour that wins in one
 * channel and loses in the others, must equal the reference within 2/255. The backend comes
 * from TESSERA_GL, so ctest runs this once per backend. */
#include "../common/check.h"
#include "render/primitives.h"
#include "render/render.h"
#include "render/shade_ref.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { W = 160, H = 120 };
static const float eye[3] = {0.0f, -1.0f, 2.5f};
static const float target[3] = {0.0f, 0.0f, 0.0f};
static const float fov = 60.0f;

static void sub(const float a[3], const float b[3], float o[3])
{
    for (int k = 0; k < 3; k++)
        o[k] = a[k] - b[k];
}
static void cross(const float a[3], const float b[3], float o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}
static void normalize(float v[3])
{
    float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++)
        v[k] /= l;
}

/* Where the ray through the centre of pixel (x, y) (top row 0) meets the plane z = 0. */
static int pixel_on_plane(int x, int y, float p[3])
{
    float f[3], r[3], u[3], up[3] = {0, 0, 1};
    sub(target, eye, f);
    normalize(f);
    cross(f, up, r);
    normalize(r);
    cross(r, f, u);
    float t = tanf(fov * 0.5f * 3.14159265f / 180.0f);
    float nx = (2.0f * ((float)x + 0.5f) / W - 1.0f) * t * (float)W / H;
    float ny = (1.0f - 2.0f * ((float)y + 0.5f) / H) * t;
    float d[3];
    for (int k = 0; k < 3; k++)
        d[k] = f[k] + nx * r[k] + ny * u[k];
    if (!(d[2] < 0.0f))
        return 0;
    float s = -eye[2] / d[2];
    for (int k = 0; k < 3; k++)
        p[k] = eye[k] + s * d[k];
    return 1;
}

static rd_light make_light(rd_light_type type)
{
    rd_light l = {.type = type,
                  .diffuse = {0.9f, 0.8f, 0.7f},
                  .specular = {1.0f, 1.0f, 1.0f},
                  .attenuation = {1.0f, 0.2f, 0.5f},
                  .spot_inner_cos = cosf(20.0f * 3.14159265f / 180.0f),
                  .spot_outer_cos = cosf(35.0f * 3.14159265f / 180.0f)};
    float pos[3] = {0.2f, 0.4f, 1.2f}, dir[3] = {-0.1f, 0.1f, -1.0f};
    if (type == RD_LIGHT_DIRECTIONAL) {
        dir[0] = 0.0f, dir[1] = 0.35f, dir[2] = -1.0f; /* highlight lands inside the view */
    }
    normalize(dir);
    memcpy(l.position, pos, sizeof pos);
    memcpy(l.direction, dir, sizeof dir);
    return l;
}

static void run_case(rd_context *ctx, rd_mesh plane, rd_light_type type, float shininess,
                     int emissive_case)
{
    rd_material m = {.ambient = {0.2f, 0.25f, 0.3f},
                     .diffuse = {0.6f, 0.5f, 0.4f},
                     .specular = {0.5f, 0.5f, 0.5f},
                     .shininess = shininess};
    if (emissive_case) {
        m.emissive[0] = 1.3f;  /* wins in red wherever the lit red is below it */
        m.emissive[1] = 0.02f; /* loses in green: the lit green is above it everywhere */
    }
    rd_light light = make_light(type);
    float ambient[3] = {0.3f, 0.3f, 0.3f};

    rd_scene *scene = rd_scene_create(ctx);
    rd_object_desc obj = {.mesh = plane, .material = m};
    obj.transform[0] = obj.transform[5] = 40.0f; /* 40 m square: fills the view */
    obj.transform[10] = obj.transform[15] = 1.0f;
    CHECK(rd_scene_add_object(scene, &obj) == RD_OK);
    CHECK(rd_scene_add_light(scene, &light) == RD_OK);
    rd_scene_set_ambient(scene, ambient);
    rd_view view = {.eye = {eye[0], eye[1], eye[2]},
                    .target = {target[0], target[1], target[2]},
                    .fov_y_deg = fov,
                    .width = W,
                    .height = H};
    rd_result r = rd_render(ctx, scene, &view);
    CHECK_MSG(r == RD_OK, "%s", rd_last_error());
    static uint8_t img[W * H * 4];
    CHECK(rd_read_rgba8(ctx, img, sizeof img) == RD_OK);

    int worst = 0, wx = 0, wy = 0, compared = 0, emissive_wins = 0, emissive_loses = 0;
    unsigned char worst_ref[3] = {0}, worst_gpu[3] = {0};
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float p[3], n[3] = {0, 0, 1}, c[3];
            if (!pixel_on_plane(x, y, p))
                continue;
            rd_ref_shade(&m, NULL, p, n, eye, &light, 1, ambient, c);
            if (emissive_case) {
                float lit_only[3];
                rd_material no_e = m;
                memset(no_e.emissive, 0, sizeof no_e.emissive);
                rd_ref_shade(&no_e, NULL, p, n, eye, &light, 1, ambient, lit_only);
                emissive_wins += lit_only[0] < m.emissive[0];
                emissive_loses += lit_only[1] > m.emissive[1];
            }
            unsigned char ref[3];
            rd_ref_display_rgb8(c, 0.0f, RD_TONEMAP_PHOTOGRAPHIC, 4.0f, ref);
            const uint8_t *g = &img[(y * W + x) * 4];
            for (int k = 0; k < 3; k++) {
                int d = abs((int)g[k] - (int)ref[k]);
                if (d > worst) {
                    worst = d, wx = x, wy = y;
                    memcpy(worst_ref, ref, 3);
                    memcpy(worst_gpu, g, 3);
                }
            }
            compared++;
        }
    CHECK(compared == W * H);
    CHECK_MSG(worst <= 2,
              "light %d, n = %g, emissive %d: pixel (%d, %d) expected %d %d %d, observed %d %d %d",
              (int)type, (double)shininess, emissive_case, wx, wy, worst_ref[0], worst_ref[1],
              worst_ref[2], worst_gpu[0], worst_gpu[1], worst_gpu[2]);
    if (emissive_case)
        CHECK_MSG(
            emissive_wins > 0 && emissive_loses == compared,
            "emissive must win in red somewhere (%d px) and lose in green everywhere (%d of %d px)",
            emissive_wins, emissive_loses, compared);
    printf("light %d n=%-6g emissive=%d: max difference %d/255 over %d pixels\n", (int)type,
           (double)shininess, emissive_case, worst, compared);
    rd_scene_destroy(scene);
}

int main(void)
{
    rd_context *ctx = NULL;
    rd_result r = rd_context_create(&(rd_context_desc){0}, &ctx);
    if (r != RD_OK) {
        fprintf(stderr, "no context: %s\n", rd_last_error());
        return 1;
    }
    printf("backend %s: %s\n", rd_backend_name(rd_context_backend(ctx)),
           rd_context_description(ctx));
    rd_mesh_data pd;
    CHECK(rd_mesh_data_plane(&pd) == RD_OK);
    rd_mesh_desc pdesc = rd_mesh_data_desc(&pd);
    rd_mesh plane = rd_mesh_create(ctx, &pdesc);
    rd_mesh_data_free(&pd);
    CHECK(plane.id != 0);
    const float exponents[] = {0.0f, 1.0f, 64.0f, 10000.0f};
    const rd_light_type types[] = {RD_LIGHT_POINT, RD_LIGHT_SPOT, RD_LIGHT_DIRECTIONAL};
    for (int t = 0; t < 3; t++)
        for (int e = 0; e < 4; e++)
            for (int em = 0; em < 2; em++)
                run_case(ctx, plane, types[t], exponents[e], em);
    rd_context_destroy(ctx);
    return check_report("gpu_vs_ref");
}
