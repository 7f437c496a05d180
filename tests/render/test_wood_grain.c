/* The wood grain (rd_material.pattern, shaders/wood.glsl) against its CPU twin
 * (rd_ref_wood_grain): a flat wood panel seen straight down, lit by a unit ambient alone, so
 * each pixel's linear value is the material's colour times the grain at that point of the
 * panel. The GPU must agree with the C function pixel by pixel, the grain must run along the
 * object's x axis (variation across it, little along it), the panel's mean must stay within
 * 2 % of the material's colour, and a material without the pattern stays flat. A front panel
 * (the object's x-z plane) with its grain turned upright or slanted (rd_material.grain_angle_deg)
 * must agree with the twin too and run the way it was turned. The backend comes from
 * TESSERA_GL. */
#include "../common/check.h"
#include "render/primitives.h"
#include "render/render.h"
#include "render/shade_ref.h"
#include "ref/ref.h"

#include <math.h>
#include <stdlib.h>

enum { W = 256, H = 256 };

static const float OAK[3] = {0.55f, 0.4f, 0.26f};
#define EYE_H 0.25f
#define HALF 0.05f     /* the close view shows 10 x 10 cm of the panel: 0.4 mm a pixel */
#define WIDE_HALF 0.3f /* the wide view: a 60 x 60 cm panel, a vanity's front */

static rd_view panel_view(float half)
{
    return (rd_view){.eye = {0.0f, 0.0f, EYE_H},
                     .target = {0.0f, 0.0f, 0.0f},
                     .up = {0.0f, 1.0f, 0.0f},
                     .fov_y_deg = (float)(2.0 * atan(half / EYE_H) * 180.0 / 3.14159265358979),
                     .width = W,
                     .height = H,
                     .tonemap = RD_TONEMAP_CLAMP};
}

static void render_panel(rd_context *ctx, rd_mesh plane, rd_pattern pattern, float half,
                         float *linear)
{
    rd_scene *s = rd_scene_create(ctx);
    rd_object_desc o = {.mesh = plane};
    /* The unit plane scaled to 2 x 2 m: the grain is in metres along the object's axes (the
     * mesh position times the transform's scale), so the panel point is the world point. */
    o.transform[0] = o.transform[5] = 2.0f;
    o.transform[10] = o.transform[15] = 1.0f;
    for (int k = 0; k < 3; k++)
        o.material.ambient[k] = o.material.diffuse[k] = OAK[k];
    o.material.pattern = pattern;
    CHECK(rd_scene_add_object(s, &o) == RD_OK);
    rd_scene_set_ambient(s, (const float[3]){1, 1, 1});
    rd_view v = panel_view(half);
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_read_linear(ctx, linear, (size_t)W * H * 4) == RD_OK);
    rd_scene_destroy(s);
}

/* The panel point at the centre of pixel (i, j), the top row first, +y up in the image. */
static void pixel_point(int i, int j, float p[3])
{
    p[0] = ((2.0f * ((float)i + 0.5f) / W) - 1.0f) * HALF;
    p[1] = (1.0f - 2.0f * ((float)j + 0.5f) / H) * HALF;
    p[2] = 0.0f;
}

static void test_gpu_matches_twin(const float *img)
{
    const float footprint = 2.0f * HALF / H;
    double worst = 0.0, sum = 0.0;
    int far = 0;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            float p[3];
            pixel_point(i, j, p);
            double want = OAK[1] * rd_ref_wood_grain(p, footprint);
            double d = fabs(img[4 * (j * W + i) + 1] - want);
            worst = d > worst ? d : worst;
            sum += d;
            far += d > 1e-3 * OAK[1];
        }
    /* The target holds float16 (a step of 2.4e-4 at this colour): agreement to a step or two,
     * off by more only where the late wood's sharp edge falls between the two's positions. */
    printf("GPU vs rd_ref_wood_grain: mean |d| %.2e, max %.2e, %d pixels over 1e-3 of it\n",
           sum / (W * H), worst, far);
    CHECK_MSG(sum / (W * H) < 1.6e-4, "mean difference %.2e", sum / (W * H));
    CHECK_MSG(far < W * H / 1000, "%d pixels differ by more than 1e-3 of the colour", far);
}

/* Mean absolute difference between neighbours along x (the grain) and along y (across). */
static void test_direction(const float *img)
{
    double along = 0.0, across = 0.0;
    for (int j = 0; j < H - 1; j++)
        for (int i = 0; i < W - 1; i++) {
            const float *c = img + 4 * (j * W + i);
            along += fabs(c[4 + 1] - c[1]);
            across += fabs(c[4 * W + 1] - c[1]);
        }
    printf("neighbour difference along the grain %.2e, across %.2e\n", along, across);
    CHECK_MSG(across > 4.0 * along, "no grain direction: along %.3g, across %.3g", along, across);
    CHECK_MSG(across > 1e-3 * OAK[1] * (W - 1) * (H - 1), "no variation across the grain");
}

/* Over a panel of a vanity front's size the grain keeps the material's colour. */
static void test_mean(const float *img)
{
    double mean[3] = {0, 0, 0};
    for (int i = 0; i < W * H; i++)
        for (int k = 0; k < 3; k++)
            mean[k] += img[4 * i + k] / (W * H);
    printf("wide panel's mean %.4f %.4f %.4f (material %.4f %.4f %.4f)\n", mean[0], mean[1],
           mean[2], OAK[0], OAK[1], OAK[2]);
    for (int k = 0; k < 3; k++)
        CHECK_MSG(fabs(mean[k] / OAK[k] - 1.0) < 0.02, "channel %d's mean %.4f vs %.4f", k, mean[k],
                  OAK[k]);
}

static void test_plain_is_flat(const float *img)
{
    for (int i = 0; i < W * H; i++)
        for (int k = 0; k < 3; k++)
            if (fabsf(img[4 * i + k] - OAK[k]) > 1e-3f * OAK[k]) { /* a half-float target */
                CHECK_MSG(0, "plain pixel %d channel %d is %g, not %g", i, k, img[4 * i + k],
                          OAK[k]);
                return;
            }
}

/* The reference tracer (render/ref) shades the same panel with the twin at each hit: the
 * close view's footprint is below every fade, so it agrees with the GPU. */
static void test_reference(const rd_mesh_data *d, const float *gpu)
{
    ref_scene *rs = ref_scene_create();
    ref_mesh_desc m = {.positions = d->positions,
                       .normals = d->normals,
                       .uvs = d->uvs,
                       .indices = d->indices,
                       .vertex_count = d->vertex_count,
                       .index_count = d->index_count};
    m.transform[0] = m.transform[5] = 2.0f;
    m.transform[10] = m.transform[15] = 1.0f;
    for (int k = 0; k < 3; k++)
        m.material.ambient[k] = m.material.diffuse[k] = OAK[k];
    m.material.pattern = RD_PATTERN_WOOD;
    CHECK(ref_scene_add_mesh(rs, &m) == REF_OK);
    ref_scene_set_ambient(rs, (const float[3]){1, 1, 1});
    ref_image img;
    ref_render_desc rd = {.view = panel_view(HALF), .threads = 1};
    if (ref_render(rs, &rd, &img) == REF_OK) {
        double sum = 0.0;
        for (int i = 0; i < W * H; i++)
            sum += fabs(img.linear[4 * i + 1] - gpu[4 * i + 1]);
        printf("reference vs GPU: mean |d| %.2e\n", sum / (W * H));
        CHECK_MSG(sum / (W * H) < 1.6e-4, "the reference differs by %.2e", sum / (W * H));
        ref_image_free(&img);
    } else
        CHECK_MSG(0, "ref_render failed");
    ref_scene_destroy(rs);
}

/* The twin's own invariants, without GL: the mean over many rings is 1 and the footprint
 * fade takes a distant view to its mean. */
static void test_twin(void)
{
    double sum = 0.0;
    int n = 0;
    for (int j = 0; j < 400; j++)
        for (int i = 0; i < 40; i++) {
            float p[3] = {0.013f * (float)i, -0.3f + 0.0015f * (float)j, 0.4f};
            sum += rd_ref_wood_grain(p, 0.0f);
            n++;
        }
    CHECK_MSG(fabs(sum / n - 1.0) < 0.02, "the grain's mean is %.4f", sum / n);
    float p[3] = {0.1f, 0.2f, 0.3f};
    float distant = rd_ref_wood_grain(p, 0.05f);
    CHECK_MSG(fabsf(distant - 1.0f) <= RD_WOOD_FIGURE_CONTRAST + 1e-6f,
              "a 5 cm footprint still shows rings: %g", distant);
    CHECK(rd_ref_wood_grain((const float[3]){NAN, 0, 0}, 0.0f) == 1.0f);
}

/* A 2 x 2 m front in the object's x-z plane (y = 0, facing -y), as a catalog model's front. */
static rd_mesh make_front(rd_context *ctx)
{
    static const float pos[] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    static const float nrm[] = {0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0};
    static const uint32_t idx[] = {0, 1, 2, 0, 2, 3};
    rd_mesh_desc d = {
        .positions = pos, .normals = nrm, .indices = idx, .vertex_count = 4, .index_count = 6};
    return rd_mesh_create(ctx, &d);
}

/* The front seen straight on from -y, z up, with its grain at angle_deg (0 along x, 90 up). */
static void render_front(rd_context *ctx, rd_mesh front, float angle_deg, float *linear)
{
    rd_scene *s = rd_scene_create(ctx);
    rd_object_desc o = {.mesh = front, .double_sided = 1};
    o.transform[0] = o.transform[5] = o.transform[10] = o.transform[15] = 1.0f;
    for (int k = 0; k < 3; k++)
        o.material.ambient[k] = o.material.diffuse[k] = OAK[k];
    o.material.pattern = RD_PATTERN_WOOD;
    o.material.grain_angle_deg = angle_deg;
    CHECK(rd_scene_add_object(s, &o) == RD_OK);
    rd_scene_set_ambient(s, (const float[3]){1, 1, 1});
    rd_view v = panel_view(HALF);
    v.eye[0] = v.eye[2] = 0.0f;
    v.eye[1] = -EYE_H;
    v.up[1] = 0.0f;
    v.up[2] = 1.0f;
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_read_linear(ctx, linear, (size_t)W * H * 4) == RD_OK);
    rd_scene_destroy(s);
}

/* The turned grain against the twin at the same turned point, pixel by pixel, and its
 * direction: along the turned axis the neighbours differ far less than across it. */
static void test_turned_front(const float *img, float angle_deg)
{
    float dir[2];
    rd_ref_wood_grain_dir(angle_deg, dir);
    /* fwidth of the turned point's components: (|cos| + |sin|) pixels of the panel. */
    const float footprint = (fabsf(dir[0]) + fabsf(dir[1])) * 2.0f * HALF / H;
    double worst = 0.0, sum = 0.0, along = 0.0, across = 0.0;
    int far = 0;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            float xy[3], p[3], q[3];
            pixel_point(i, j, xy);
            p[0] = xy[0], p[1] = 0.0f, p[2] = xy[1]; /* image up is the front's z */
            rd_ref_wood_grain_point(p, dir, q);
            double want = OAK[1] * rd_ref_wood_grain(q, footprint);
            double d = fabs(img[4 * (j * W + i) + 1] - want);
            worst = d > worst ? d : worst;
            sum += d;
            far += d > 1e-3 * OAK[1];
        }
    /* Neighbour differences along the grain's direction and across it, on the image grid:
     * a step of (cos, sin) pixels (rounded, image rows run down) against (-sin, cos). */
    int ax = (int)lroundf(4.0f * dir[0]), ay = -(int)lroundf(4.0f * dir[1]);
    int cx = -ay, cy = ax;
    for (int j = 8; j < H - 8; j++)
        for (int i = 8; i < W - 8; i++) {
            float c = img[4 * (j * W + i) + 1];
            along += fabs(img[4 * ((j + ay) * W + i + ax) + 1] - c);
            across += fabs(img[4 * ((j + cy) * W + i + cx) + 1] - c);
        }
    printf("front, grain at %g deg: GPU vs twin mean |d| %.2e, max %.2e, %d pixels over 1e-3; "
           "neighbours along %.2e, across %.2e\n",
           (double)angle_deg, sum / (W * H), worst, far, along, across);
    CHECK_MSG(sum / (W * H) < 1.6e-4, "grain at %g deg: mean difference %.2e", (double)angle_deg,
              sum / (W * H));
    CHECK_MSG(far < W * H / 1000, "grain at %g deg: %d pixels differ by more than 1e-3",
              (double)angle_deg, far);
    CHECK_MSG(across > 3.0 * along, "grain at %g deg runs another way: along %.3g, across %.3g",
              (double)angle_deg, along, across);
}

int main(void)
{
    test_twin();
    rd_context *ctx = NULL;
    if (rd_context_create(NULL, &ctx) != RD_OK) {
        fprintf(stderr, "no context: %s\n", rd_last_error());
        return 1;
    }
    rd_mesh_data d;
    rd_mesh_data_plane(&d);
    rd_mesh_desc desc = rd_mesh_data_desc(&d);
    rd_mesh plane = rd_mesh_create(ctx, &desc);
    float *img = malloc((size_t)W * H * 4 * sizeof *img);
    render_panel(ctx, plane, RD_PATTERN_WOOD, HALF, img);
    test_gpu_matches_twin(img);
    test_reference(&d, img);
    rd_mesh_data_free(&d);
    test_direction(img);
    render_panel(ctx, plane, RD_PATTERN_WOOD, WIDE_HALF, img);
    test_mean(img);
    render_panel(ctx, plane, RD_PATTERN_NONE, WIDE_HALF, img);
    test_plain_is_flat(img);
    rd_mesh front = make_front(ctx);
    CHECK(front.id != 0);
    static const float angles[] = {0.0f, 90.0f, 30.0f};
    for (int a = 0; a < 3; a++) {
        render_front(ctx, front, angles[a], img);
        test_turned_front(img, angles[a]);
    }
    rd_mesh_destroy(ctx, front);
    free(img);
    rd_mesh_destroy(ctx, plane);
    rd_context_destroy(ctx);
    return check_report("wood grain");
}
