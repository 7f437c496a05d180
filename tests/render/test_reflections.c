/* Reflections on a real context (RENDERING.md sections 3-8, 11): which objects get probes and
 * when they are captured, the GPU cube-map lookup against the CPU sampler on all six faces,
 * the corrected reflection vector against analytic ray geometry, the prefiltered blur
 * (brightness, monotonic, no seams), k_r = 0 inert, and finite pixels at the extremes. The
 * backend comes from TESSERA_GL. */
#include "../common/check.h"
#include "render/cube_data.h"
#include "render/primitives.h"
#include "render/reflect_ref.h"
#include "render/render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static rd_mesh upload(rd_context *ctx, rd_result (*make)(rd_mesh_data *))
{
    rd_mesh_data d;
    make(&d);
    rd_mesh_desc desc = rd_mesh_data_desc(&d);
    rd_mesh m = rd_mesh_create(ctx, &desc);
    rd_mesh_data_free(&d);
    return m;
}

static rd_result make_sphere(rd_mesh_data *d)
{
    return rd_mesh_data_sphere(32, 16, d);
}

static void normalize3(float v[3])
{
    float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++)
        v[k] /= l;
}

static void cross3(const float a[3], const float b[3], float o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* A plane's model matrix: unit square scaled by `size`, facing n, centred at c. */
static void plane_transform(const float n[3], const float c[3], float size, float m[16])
{
    float a[3] = {0, 0, 0}, b[3];
    a[fabsf(n[0]) < 0.5f ? 0 : 1] = 1.0f;
    float d = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
    for (int k = 0; k < 3; k++)
        a[k] -= d * n[k];
    normalize3(a);
    cross3(n, a, b);
    memset(m, 0, 16 * sizeof(float));
    for (int k = 0; k < 3; k++) {
        m[k] = a[k] * size;
        m[4 + k] = b[k] * size;
        m[8 + k] = n[k];
        m[12 + k] = c[k];
    }
    m[15] = 1.0f;
}

/* The world ray through the centre of pixel (x, y), top row 0, as rd_render's camera. */
static void pixel_ray(const rd_view *v, int x, int y, float dir[3])
{
    float f[3] = {v->target[0] - v->eye[0], v->target[1] - v->eye[1], v->target[2] - v->eye[2]};
    float up[3] = {0, 0, 1}, r[3], u[3];
    normalize3(f);
    cross3(f, up, r);
    normalize3(r);
    cross3(r, f, u);
    float t = tanf(v->fov_y_deg * 0.5f * 3.14159265f / 180.0f);
    float nx = (2.0f * ((float)x + 0.5f) / (float)v->width - 1.0f) * t * (float)v->width /
               (float)v->height;
    float ny = (1.0f - 2.0f * ((float)y + 0.5f) / (float)v->height) * t;
    for (int k = 0; k < 3; k++)
        dir[k] = f[k] + nx * r[k] + ny * u[k];
    normalize3(dir);
}

/* ---- which objects get probes, and when they are captured ------------------------------- */

static void test_probes_and_policies(rd_context *ctx)
{
    rd_mesh sphere = upload(ctx, make_sphere);
    rd_scene *s = rd_scene_create(ctx);
    rd_object_desc plain = {.mesh = sphere, .material = {.diffuse = {0.5f, 0.5f, 0.5f}}};
    plain.transform[0] = plain.transform[5] = plain.transform[10] = plain.transform[15] = 1;
    CHECK(rd_scene_add_object(s, &plain) == RD_OK);
    CHECK(rd_scene_probe_count(s) == 0); /* k_r = 0: no probe */
    rd_object_desc shiny = plain;
    shiny.transform[12] = 2.0f;
    shiny.material.reflectivity = 0.5f;
    shiny.probe = (rd_probe_desc){.update = RD_PROBE_EVERY_FRAME, .resolution = 16};
    CHECK(rd_scene_add_object(s, &shiny) == RD_OK);
    CHECK(rd_scene_probe_count(s) == 1);
    rd_object_desc part = shiny;
    part.group = 7;
    part.transform[12] = -2.0f;
    CHECK(rd_scene_add_object(s, &part) == RD_OK);
    part.transform[13] = 1.0f;
    CHECK(rd_scene_add_object(s, &part) == RD_OK);
    CHECK_MSG(rd_scene_probe_count(s) == 2, "two parts of one group share a probe: %d",
              rd_scene_probe_count(s));
    rd_scene_destroy(s);

    /* Update policies: faces captured per frame. */
    const struct {
        rd_probe_update update;
        int every;
        int expected[6];
    } cases[] = {
        {RD_PROBE_EVERY_FRAME, 0, {6, 6, 6, 6, 6, 6}},
        {RD_PROBE_EVERY_FRAME, 3, {6, 0, 0, 6, 0, 0}},
        {RD_PROBE_ONCE, 0, {6, 0, 0, 0, 0, 0}},
        {RD_PROBE_TIME_SLICED, 0, {6, 1, 1, 1, 1, 1}},
        {RD_PROBE_ON_CHANGE, 0, {6, 0, 6, 0, 0, 0}}, /* something moves before frame 3 */
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        s = rd_scene_create(ctx);
        CHECK(rd_scene_add_object(s, &plain) == RD_OK);
        rd_object_desc o = shiny;
        o.probe.update = cases[c].update;
        o.probe.every_n = cases[c].every;
        CHECK(rd_scene_add_object(s, &o) == RD_OK);
        rd_view v = {.eye = {0, -6, 1}, .target = {0, 0, 0}, .width = 16, .height = 16};
        for (int frame = 0; frame < 6; frame++) {
            if (cases[c].update == RD_PROBE_ON_CHANGE && frame == 2) {
                float moved[16];
                memcpy(moved, plain.transform, sizeof moved);
                moved[14] = 0.5f;
                CHECK(rd_scene_set_transform(s, 0, moved) == RD_OK);
            }
            CHECK(rd_render(ctx, s, &v) == RD_OK);
            rd_frame_stats st = rd_last_frame_stats(ctx);
            CHECK_MSG(st.faces_captured == cases[c].expected[frame],
                      "policy %d every %d, frame %d: %d faces captured, expected %d",
                      (int)cases[c].update, cases[c].every, frame, st.faces_captured,
                      cases[c].expected[frame]);
        }
        rd_scene_destroy(s);
    }
    rd_mesh_destroy(ctx, sphere);
}

/* ---- k_r = 0 makes every other reflection setting inert --------------------------------- */

static void test_zero_reflectivity_is_plain(rd_context *ctx)
{
    rd_mesh sphere = upload(ctx, make_sphere);
    enum { W = 48, H = 48 };
    static uint8_t img[2][W * H * 4];
    for (int variant = 0; variant < 2; variant++) {
        rd_scene *s = rd_scene_create(ctx);
        rd_object_desc o = {.mesh = sphere,
                            .material = {.diffuse = {0.6f, 0.3f, 0.2f},
                                         .specular = {0.5f, 0.5f, 0.5f},
                                         .shininess = 40}};
        o.transform[0] = o.transform[5] = o.transform[10] = o.transform[15] = 1;
        if (variant) { /* every reflection knob turned, k_r still 0 */
            o.material.glossiness = 0.3f;
            o.material.blend = RD_REFLECT_FRESNEL;
            o.material.correction = RD_CORRECTION_SPHERE;
            o.probe.update = RD_PROBE_TIME_SLICED;
        }
        CHECK(rd_scene_add_object(s, &o) == RD_OK);
        rd_light l = {.type = RD_LIGHT_POINT,
                      .position = {1, -2, 2},
                      .diffuse = {1, 1, 1},
                      .specular = {1, 1, 1},
                      .attenuation = {1, 0, 0}};
        CHECK(rd_scene_add_light(s, &l) == RD_OK);
        rd_view v = {.eye = {0, -3, 0.5f}, .target = {0, 0, 0}, .width = W, .height = H};
        CHECK(rd_render(ctx, s, &v) == RD_OK);
        CHECK(rd_read_rgba8(ctx, img[variant], sizeof img[variant]) == RD_OK);
        CHECK(rd_scene_probe_count(s) == 0);
        rd_scene_destroy(s);
    }
    CHECK_MSG(memcmp(img[0], img[1], sizeof img[0]) == 0, "k_r = 0 output is bit for bit plain");
    rd_mesh_destroy(ctx, sphere);
}

/* ---- the GPU lookup against the CPU sampler on all six faces ----------------------------- */

static void fill_face_pattern(rd_cube_data *c)
{
    static const float base[6][3] = {{0.9f, 0.1f, 0.1f}, {0.1f, 0.9f, 0.1f}, {0.1f, 0.1f, 0.9f},
                                     {0.9f, 0.9f, 0.1f}, {0.1f, 0.9f, 0.9f}, {0.9f, 0.1f, 0.9f}};
    for (int f = 0; f < 6; f++)
        for (int j = 0; j < c->size; j++)
            for (int i = 0; i < c->size; i++) {
                float s = ((float)i + 0.5f) / (float)c->size,
                      t = ((float)j + 0.5f) / (float)c->size;
                float *px = &c->faces[f][((size_t)j * (size_t)c->size + (size_t)i) * 4];
                /* a gradient in s and in t shows a face that is flipped or turned */
                px[0] = base[f][0] * (0.6f + 0.4f * s);
                px[1] = base[f][1] * (0.6f + 0.4f * t);
                px[2] = base[f][2];
                px[3] = 1.0f;
            }
}

static rd_cubemap upload_cube(rd_context *ctx, const rd_cube_data *c)
{
    rd_cubemap_desc d = {.size = c->size};
    for (int f = 0; f < 6; f++)
        d.faces[f] = c->faces[f];
    return rd_cubemap_create(ctx, &d);
}

static void test_lookup_matches_cpu_sampler(rd_context *ctx)
{
    rd_cube_data cube;
    CHECK(rd_cube_data_alloc(32, &cube) == RD_OK);
    fill_face_pattern(&cube);
    rd_cubemap map = upload_cube(ctx, &cube);
    CHECK(map.id != 0);
    rd_mesh plane = upload(ctx, rd_mesh_data_plane);
    enum { W = 64, H = 64 };
    static float lin[W * H * 4];
    const float normals[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                 {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    int faces_seen = 0;
    for (int k = 0; k < 6; k++) {
        rd_scene *s = rd_scene_create(ctx);
        rd_object_desc o = {.mesh = plane,
                            .material = {.reflectivity = 1.0f,
                                         .glossiness = 1.0f,
                                         .correction = RD_CORRECTION_NONE},
                            .probe = {.update = RD_PROBE_STATIC, .static_map = map}};
        float centre[3] = {0, 0, 0};
        plane_transform(normals[k], centre, 50.0f, o.transform);
        CHECK(rd_scene_add_object(s, &o) == RD_OK);
        rd_view v = {.fov_y_deg = 50, .width = W, .height = H};
        for (int a = 0; a < 3; a++) { /* seen obliquely: reflections reach the neighbour faces */
            v.eye[a] = 2.0f * normals[k][a] + (a == 2 ? 0.3f : 0.7f);
            v.target[a] = 0.0f;
        }
        CHECK(rd_render(ctx, s, &v) == RD_OK);
        CHECK(rd_read_linear(ctx, lin, W * H * 4) == RD_OK);
        int compared = 0, off = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                float d[3];
                pixel_ray(&v, x, y, d);
                float dn = d[0] * normals[k][0] + d[1] * normals[k][1] + d[2] * normals[k][2];
                if (!(dn < -1e-3f))
                    continue;
                float r[3], expect[4];
                rd_ref_reflect(d, normals[k], r);
                rd_cube_sample_bilinear(&cube, r, expect);
                float cm[3], fs, ft;
                rd_ref_world_to_cmcs(r, cm);
                faces_seen |= 1 << rd_ref_cube_face_st(cm, &fs, &ft);
                const float *g = &lin[(y * W + x) * 4];
                float diff = fmaxf(fabsf(g[0] - expect[0]),
                                   fmaxf(fabsf(g[1] - expect[1]), fabsf(g[2] - expect[2])));
                compared++;
                off += diff > 0.03f;
            }
        CHECK_MSG(compared > W * H / 2 && off * 100 <= compared,
                  "mirror facing %d: %d of %d pixels differ from the CPU sampler", k, off,
                  compared);
        rd_scene_destroy(s);
    }
    CHECK_MSG(faces_seen == 0x3f, "all six faces were looked up (mask %x)", faces_seen);
    rd_mesh_destroy(ctx, plane);
    rd_cubemap_destroy(ctx, map);
    rd_cube_data_free(&cube);
}

/* ---- the corrected reflection vector against analytic ray geometry ----------------------- */

/* Which wall of the box [0, L]^3 the ray from p along r leaves through, -1 when too near an
 * edge to say; *hit gets the point. */
static int wall_hit(const float p[3], const float r[3], float room, float hit[3])
{
    float best = INFINITY;
    int wall = -1;
    for (int a = 0; a < 3; a++) {
        if (fabsf(r[a]) < 1e-9f)
            continue;
        float t = ((r[a] > 0 ? room : 0.0f) - p[a]) / r[a];
        if (t < best) {
            best = t;
            wall = a * 2 + (r[a] > 0 ? 1 : 0);
        }
    }
    for (int a = 0; a < 3; a++) {
        float h = p[a] + best * r[a];
        hit[a] = h;
        if (a != wall / 2 && (h < 0.03f || h > room - 0.03f))
            return -1;
    }
    return wall;
}

enum { CHECKER = 8 };

/* The checker colour wall w shows at world point h, or -1 near a cell border. The walls are
 * planes through plane_transform; their texture (u, v) follow its a and b axes. */
static int checker_colour(int w, const float h[3], float room, const float m[16], float out[3])
{
    float c[3] = {m[12], m[13], m[14]}, a[3] = {m[0], m[1], m[2]}, b[3] = {m[4], m[5], m[6]};
    float u = 0.5f, v = 0.5f;
    for (int k = 0; k < 3; k++) {
        u += (h[k] - c[k]) * a[k] / (room * room);
        v += (h[k] - c[k]) * b[k] / (room * room);
    }
    float cu = u * CHECKER, cv = v * CHECKER;
    if (fabsf(cu - roundf(cu)) < 0.12f || fabsf(cv - roundf(cv)) < 0.12f)
        return -1;
    int odd = ((int)floorf(cu) + (int)floorf(cv)) & 1;
    for (int k = 0; k < 3; k++)
        out[k] = odd ? 0.15f + 0.1f * (float)w : (k == w % 3 ? 0.9f : 0.4f + 0.05f * (float)w);
    return 0;
}

static void test_corrected_vector(rd_context *ctx)
{
    const float room = 3.0f;
    rd_mesh plane = upload(ctx, rd_mesh_data_plane);
    /* Each wall a checker of its own two colours, shown unlit: ambient 1 x texture. */
    rd_texture checker[6];
    /* 8 texels per cell, so bilinear magnification blends only at the cells' borders. */
    enum { TEX = CHECKER * 8 };
    static float texels[TEX * TEX * 4];
    float wall_m[6][16];
    for (int w = 0; w < 6; w++) {
        float n[3] = {0, 0, 0}, c[3] = {room / 2, room / 2, room / 2};
        n[w / 2] = (w & 1) ? -1.0f : 1.0f;
        c[w / 2] = (w & 1) ? room : 0.0f;
        plane_transform(n, c, room, wall_m[w]);
        for (int j = 0; j < TEX; j++)
            for (int i = 0; i < TEX; i++) {
                float h[3], col[3];
                /* the centre of the texel's cell on the wall, to reuse checker_colour */
                float u = ((float)(i / 8) + 0.5f) / CHECKER - 0.5f,
                      v = ((float)(j / 8) + 0.5f) / CHECKER - 0.5f;
                for (int k = 0; k < 3; k++)
                    h[k] = c[k] + u * wall_m[w][k] + v * wall_m[w][4 + k];
                checker_colour(w, h, room, wall_m[w], col);
                memcpy(&texels[(j * TEX + i) * 4], col, sizeof col);
                texels[(j * TEX + i) * 4 + 3] = 1.0f;
            }
        checker[w] =
            rd_texture_create(ctx, &(rd_texture_desc){.width = TEX, .height = TEX, .rgba = texels});
        CHECK(checker[w].id != 0);
    }
    enum { W = 96, H = 72 };
    static float lin[W * H * 4];
    int matched[2] = {0, 0}, total[2] = {0, 0};
    for (int corrected = 0; corrected < 2; corrected++) {
        rd_scene *s = rd_scene_create(ctx);
        rd_reflection_defaults rd = {.proxy_max = {room, room, room}};
        rd_scene_set_reflection_defaults(s, &rd);
        float one[3] = {1, 1, 1};
        rd_scene_set_ambient(s, one);
        for (int w = 0; w < 6; w++) { /* wall w: axis w/2, at 0 (even) or room (odd) */
            rd_object_desc o = {.mesh = plane,
                                .background = 1,
                                .material = {.ambient = {1, 1, 1}, .diffuse_texture = checker[w]}};
            memcpy(o.transform, wall_m[w], sizeof o.transform);
            CHECK(rd_scene_add_object(s, &o) == RD_OK);
        }
        rd_object_desc mirror = {
            .mesh = plane,
            .material = {.reflectivity = 1,
                         .glossiness = 1,
                         .correction = corrected ? RD_CORRECTION_BOX : RD_CORRECTION_NONE},
            .probe = {.update = RD_PROBE_ONCE, .resolution = 256}};
        float up[3] = {0, 0, 1}, mc[3] = {room / 2, room / 2, 0.05f};
        plane_transform(up, mc, 2.0f, mirror.transform);
        CHECK(rd_scene_add_object(s, &mirror) == RD_OK);
        rd_view v = {.eye = {0.4f, 0.4f, 2.2f},
                     .target = {1.8f, 1.8f, 0},
                     .fov_y_deg = 70,
                     .width = W,
                     .height = H};
        CHECK(rd_render(ctx, s, &v) == RD_OK);
        CHECK(rd_read_linear(ctx, lin, W * H * 4) == RD_OK);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                float d[3];
                pixel_ray(&v, x, y, d);
                if (!(d[2] < 0))
                    continue;
                float t = (0.05f - v.eye[2]) / d[2];
                float p[3] = {v.eye[0] + t * d[0], v.eye[1] + t * d[1], 0.05f};
                if (fabsf(p[0] - mc[0]) > 0.97f || fabsf(p[1] - mc[1]) > 0.97f)
                    continue; /* not on the mirror, or on its rim */
                float n[3] = {0, 0, 1}, r[3];
                rd_ref_reflect(d, n, r);
                float hit[3], expect[3];
                int wall = wall_hit(p, r, room, hit);
                if (wall < 0 || checker_colour(wall, hit, room, wall_m[wall], expect) < 0)
                    continue;
                const float *g = &lin[(y * W + x) * 4];
                float diff = fmaxf(fabsf(g[0] - expect[0]),
                                   fmaxf(fabsf(g[1] - expect[1]), fabsf(g[2] - expect[2])));
                total[corrected]++;
                matched[corrected] += diff < 0.1f;
            }
        rd_scene_destroy(s);
    }
    printf("corrected vector: %d of %d mirror pixels show the wall the ray hits (box), %d of %d "
           "without correction\n",
           matched[1], total[1], matched[0], total[0]);
    CHECK(total[1] > 500 && total[0] == total[1]);
    CHECK_MSG(matched[1] * 100 >= total[1] * 99, "with correction: %d of %d", matched[1], total[1]);
    CHECK_MSG((total[0] - matched[0]) * 100 >= total[0] * 10,
              "without correction at least 10 %% of the pixels must show the wrong wall: %d of %d",
              total[0] - matched[0], total[0]);
    for (int w = 0; w < 6; w++)
        rd_texture_destroy(ctx, checker[w]);
    rd_mesh_destroy(ctx, plane);
}

/* ---- the prefiltered blur ------------------------------------------------------------------ */

static double weighted_mean(const float *const faces[6], int n, int channel, double *variance)
{
    double sum = 0, sum2 = 0, wsum = 0;
    for (int f = 0; f < 6; f++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                double w = rd_ref_texel_solid_angle(i, j, n);
                double v = faces[f][((size_t)j * (size_t)n + (size_t)i) * 4 + (size_t)channel];
                sum += w * v;
                sum2 += w * v * v;
                wsum += w;
            }
    if (variance)
        *variance = sum2 / wsum - (sum / wsum) * (sum / wsum);
    return sum / wsum;
}

/* Mean |difference| of neighbouring texels across the 12 face edges and inside the faces. */
static void edge_contrast(const float *const faces[6], int n, double *across, double *inside)
{
    double a = 0, b = 0;
    long na = 0, nb = 0;
    for (int f = 0; f < 6; f++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                const float *v = &faces[f][((size_t)j * (size_t)n + (size_t)i) * 4];
                if (i + 1 < n) {
                    b += fabsf(v[0] - v[4]);
                    nb++;
                }
                if (i != 0 && i != n - 1 && j != 0 && j != n - 1)
                    continue;
                /* step one texel outward across each edge this texel touches */
                const int steps[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
                for (int k = 0; k < 4; k++) {
                    int ii = i + steps[k][0], jj = j + steps[k][1];
                    if (ii >= 0 && ii < n && jj >= 0 && jj < n)
                        continue;
                    float cm[3], s, t;
                    rd_ref_cube_face_direction(f, ((float)ii + 0.5f) / (float)n,
                                               ((float)jj + 0.5f) / (float)n, cm);
                    int g = rd_ref_cube_face_st(cm, &s, &t);
                    int gi = (int)(s * (float)n), gj = (int)(t * (float)n);
                    gi = gi < 0 ? 0 : gi >= n ? n - 1 : gi;
                    gj = gj < 0 ? 0 : gj >= n ? n - 1 : gj;
                    a += fabsf(v[0] - faces[g][((size_t)gj * (size_t)n + (size_t)gi) * 4]);
                    na++;
                }
            }
    *across = a / (double)na;
    *inside = b / (double)nb;
}

static void test_blur(rd_context *ctx, rd_blur_method method)
{
    /* A busy source: hashed noise with a bright spot. */
    rd_cube_data cube;
    CHECK(rd_cube_data_alloc(64, &cube) == RD_OK);
    unsigned h = 12345;
    for (int f = 0; f < 6; f++)
        for (int i = 0; i < 64 * 64; i++) {
            h = h * 1664525u + 1013904223u;
            float v = (float)(h >> 8) / 16777216.0f;
            for (int k = 0; k < 3; k++)
                cube.faces[f][i * 4 + k] = 0.2f + v * (k == 0 ? 1.0f : 0.5f);
            cube.faces[f][i * 4 + 3] = 1.0f;
        }
    rd_cubemap map = upload_cube(ctx, &cube);
    const float *src[6];
    for (int f = 0; f < 6; f++)
        src[f] = cube.faces[f];
    double src_var;
    double src_mean = weighted_mean(src, 64, 0, &src_var);

    rd_mesh sphere = upload(ctx, make_sphere);
    rd_scene *s = rd_scene_create(ctx);
    rd_reflection_defaults rdef = {.blur = method};
    rd_scene_set_reflection_defaults(s, &rdef);
    /* Lobes that land nearest levels 1, 2, 3 and 5 of a 64-texel map (rd_ref_gloss_lod); the
     * level read is the nearest of the two the blur made. */
    const float gloss[4] = {0.6f, 0.45f, 0.3f, 0.0f};
    for (int k = 0; k < 4; k++) {
        rd_object_desc o = {.mesh = sphere,
                            .material = {.reflectivity = 1, .glossiness = gloss[k]},
                            .probe = {.update = RD_PROBE_STATIC, .static_map = map}};
        o.transform[0] = o.transform[5] = o.transform[10] = o.transform[15] = 1;
        o.transform[12] = (float)k * 2.0f;
        CHECK(rd_scene_add_object(s, &o) == RD_OK);
    }
    rd_view v = {.eye = {3, -8, 1}, .target = {3, 0, 0}, .width = 32, .height = 16};
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_scene_probe_count(s) == 4);
    double previous_var = src_var;
    static float level[6][64 * 64 * 4];
    for (int k = 0; k < 4; k++) {
        int lod = (int)roundf(rd_ref_gloss_lod(gloss[k], 7));
        int n = 0;
        const float *faces[6];
        for (int f = 0; f < 6; f++) {
            CHECK(rd_scene_read_probe(s, k, f, lod, level[f], 64 * 64 * 4, &n) == RD_OK);
            faces[f] = level[f];
        }
        double var;
        double mean = weighted_mean(faces, n, 0, &var);
        CHECK_MSG(fabs(mean - src_mean) <= 0.01 * src_mean,
                  "blur %d, g = %g (level %d): mean %g, source %g", (int)method, (double)gloss[k],
                  lod, mean, src_mean);
        CHECK_MSG(var < previous_var, "g = %g: variance %g must fall below %g", (double)gloss[k],
                  var, previous_var);
        previous_var = var;
        if (n >= 4 && method != RD_BLUR_BOX_MIPS) { /* box mips are per face: blocky */
            double across, inside;
            edge_contrast(faces, n, &across, &inside);
            CHECK_MSG(across <= 3.0 * inside + 1e-3,
                      "g = %g: a seam: %g across the face edges, %g inside", (double)gloss[k],
                      across, inside);
        }
    }
    rd_scene_destroy(s);
    rd_mesh_destroy(ctx, sphere);
    rd_cubemap_destroy(ctx, map);
    rd_cube_data_free(&cube);
}

/* ---- RENDERING.md section 11: finite pixels at the extremes --------------------------------- */

static int all_finite(const float *px, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(px[i]))
            return 0;
    return 1;
}

static void test_extremes(rd_context *ctx)
{
    rd_mesh sphere = upload(ctx, make_sphere);
    rd_mesh plane = upload(ctx, rd_mesh_data_plane);
    const float gloss[] = {0.0f, 1e-6f, 0.5f, 1.0f - 1e-6f, 1.0f};
    const float kr[] = {0.0f, 1.0f};
    const float shininess[] = {0.0f, 10000.0f};
    const float scale[] = {1e-3f, 1.0f, 1e4f}; /* scenes from 1 mm to 10 km */
    enum { W = 16, H = 16 };
    static float lin[W * H * 4];
    int renders = 0, bad = 0;
    for (size_t sc = 0; sc < 3; sc++)
        for (size_t g = 0; g < 5; g++)
            for (size_t k = 0; k < 2; k++)
                for (int blend = 0; blend < 3; blend++)
                    for (int corr = 1; corr <= 3; corr++) {
                        float L = scale[sc];
                        rd_scene *s = rd_scene_create(ctx);
                        rd_object_desc floor_o = {.mesh = plane,
                                                  .material = {.diffuse = {0.5f, 0.5f, 0.5f}},
                                                  .double_sided = 1};
                        float up[3] = {0, 0, 1}, c0[3] = {0, 0, -L};
                        plane_transform(up, c0, 10 * L, floor_o.transform);
                        CHECK(rd_scene_add_object(s, &floor_o) == RD_OK);
                        rd_object_desc lamp = {.mesh = sphere,
                                               .material = {.emissive = {1e6f, 1e6f, 1e6f}}};
                        lamp.transform[0] = lamp.transform[5] = lamp.transform[10] = 0.2f * L;
                        lamp.transform[15] = 1;
                        lamp.transform[12] = 1.5f * L;
                        CHECK(rd_scene_add_object(s, &lamp) == RD_OK);
                        rd_object_desc o = {
                            .mesh = sphere,
                            .material = {.diffuse = {0.3f, 0.3f, 0.3f},
                                         .specular = {1, 1, 1},
                                         .shininess = shininess[(g + k) % 2],
                                         .reflectivity = kr[k],
                                         .glossiness = gloss[g],
                                         .blend = (rd_reflection_blend)blend,
                                         .correction = (rd_correction)corr,
                                         .transparency = blend == 2 ? 0.8f : 0.0f,
                                         .dispersion = blend == 2 ? 0.05f : 0.0f},
                            .probe = {.resolution = (g == 0) ? 1 : 0, .every_n = 0}};
                        o.transform[0] = o.transform[5] = o.transform[10] = L;
                        o.transform[15] = 1;
                        CHECK(rd_scene_add_object(s, &o) == RD_OK);
                        rd_object_desc tiny = o; /* an object of (almost) zero size */
                        tiny.transform[0] = tiny.transform[5] = tiny.transform[10] = 1e-9f * L;
                        tiny.transform[13] = 0.8f * L;
                        CHECK(rd_scene_add_object(s, &tiny) == RD_OK);
                        rd_light l = {.type = RD_LIGHT_POINT,
                                      .position = {0, -L, L},
                                      .diffuse = {1, 1, 1},
                                      .specular = {1, 1, 1},
                                      .attenuation = {0, 0, 1}};
                        CHECK(rd_scene_add_light(s, &l) == RD_OK);
                        rd_view v = {.eye = {0.3f * L, -3 * L, 0.5f * L},
                                     .target = {0, 0, 0},
                                     .width = W,
                                     .height = H};
                        rd_result r = rd_render(ctx, s, &v);
                        renders++;
                        if (r != RD_OK || rd_read_linear(ctx, lin, W * H * 4) != RD_OK ||
                            !all_finite(lin, W * H * 4)) {
                            bad++;
                            fprintf(stderr,
                                    "not finite: scale %g g %g kr %g blend %d corr %d (%s)\n",
                                    (double)L, (double)gloss[g], (double)kr[k], blend, corr,
                                    r == RD_OK ? "pixels" : rd_last_error());
                        }
                        rd_scene_destroy(s);
                    }
    CHECK_MSG(bad == 0, "%d of %d extreme renders gave non-finite pixels", bad, renders);
    rd_mesh_destroy(ctx, sphere);
    rd_mesh_destroy(ctx, plane);
}

/* ---- SH9 ambient: a room glowing one colour lights a white surface with that colour ------ */

static void test_sh9_ambient(rd_context *ctx)
{
    rd_mesh plane = upload(ctx, rd_mesh_data_plane);
    rd_mesh sphere = upload(ctx, make_sphere);
    rd_scene *s = rd_scene_create(ctx);
    const float glow[3] = {0.5f, 0.3f, 0.2f}, room = 3.0f;
    for (int w = 0; w < 6; w++) {
        float n[3] = {0, 0, 0}, c[3] = {room / 2, room / 2, room / 2};
        n[w / 2] = (w & 1) ? -1.0f : 1.0f;
        c[w / 2] = (w & 1) ? room : 0.0f;
        rd_object_desc o = {.mesh = plane, .background = 1};
        memcpy(o.material.emissive, glow, sizeof glow);
        plane_transform(n, c, room, o.transform);
        CHECK(rd_scene_add_object(s, &o) == RD_OK);
    }
    /* A white ball lit by nothing but the ambient term: C_a E(N) / pi = C_a L for a uniform
     * environment of radiance L, whatever the normal. */
    rd_object_desc ball = {.mesh = sphere, .material = {.ambient = {1, 1, 1}}};
    ball.transform[0] = ball.transform[5] = ball.transform[10] = 0.8f;
    ball.transform[15] = 1;
    ball.transform[12] = ball.transform[13] = ball.transform[14] = room / 2;
    CHECK(rd_scene_add_object(s, &ball) == RD_OK);
    rd_reflection_defaults d = {.ambient = RD_AMBIENT_SH9, .proxy_max = {room, room, room}};
    rd_scene_set_reflection_defaults(s, &d);
    enum { W = 32, H = 32 };
    static float lin[W * H * 4];
    rd_view v = {.eye = {room / 2, 0.2f, room / 2},
                 .target = {room / 2, room / 2, room / 2},
                 .fov_y_deg = 30,
                 .width = W,
                 .height = H};
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_read_linear(ctx, lin, W * H * 4) == RD_OK);
    CHECK(rd_last_frame_stats(ctx).faces_captured == 6); /* the ambient probe */
    float worst = 0.0f;
    for (int y = W / 2 - 3; y <= W / 2 + 3; y++) /* the ball's middle */
        for (int x = W / 2 - 3; x <= W / 2 + 3; x++)
            for (int k = 0; k < 3; k++)
                worst = fmaxf(worst, fabsf(lin[(y * W + x) * 4 + k] - glow[k]) / glow[k]);
    CHECK_MSG(worst < 0.03f, "SH9 ambient off by %.1f %% from the environment's radiance",
              100.0 * worst);
    /* The constant model ignores the room: I_a = 0 leaves the ball black. */
    d.ambient = RD_AMBIENT_CONSTANT;
    rd_scene_set_reflection_defaults(s, &d);
    CHECK(rd_render(ctx, s, &v) == RD_OK);
    CHECK(rd_read_linear(ctx, lin, W * H * 4) == RD_OK);
    CHECK(lin[(H / 2 * W + W / 2) * 4] == 0.0f);
    rd_scene_destroy(s);
    rd_mesh_destroy(ctx, plane);
    rd_mesh_destroy(ctx, sphere);
}

/* ---- per-vertex against per-pixel reflection (seed 003) ------------------------------------ */

/* mode 0: per vertex; mode 1: sphere map; against the per-pixel cube-map lookup. */
static double lookup_difference(rd_context *ctx, rd_cubemap map, int segments, int mode)
{
    rd_mesh_data d;
    rd_mesh_data_sphere(segments, segments / 2, &d);
    rd_mesh_desc desc = rd_mesh_data_desc(&d);
    rd_mesh sphere = rd_mesh_create(ctx, &desc);
    rd_mesh_data_free(&d);
    enum { W = 48, H = 48 };
    static float lin[2][W * H * 4];
    for (int pv = 0; pv < 2; pv++) {
        rd_scene *s = rd_scene_create(ctx);
        rd_object_desc o = {.mesh = sphere,
                            .material = {.reflectivity = 1,
                                         .glossiness = 1,
                                         .correction = RD_CORRECTION_NONE,
                                         .per_vertex_reflection = mode == 0 && pv,
                                         .sphere_map = mode == 1 && pv},
                            .probe = {.update = RD_PROBE_STATIC, .static_map = map}};
        o.transform[0] = o.transform[5] = o.transform[10] = o.transform[15] = 1;
        CHECK(rd_scene_add_object(s, &o) == RD_OK);
        rd_view v = {.eye = {0.3f, -2.5f, 0.4f},
                     .target = {0, 0, 0},
                     .fov_y_deg = 30,
                     .width = W,
                     .height = H};
        CHECK(rd_render(ctx, s, &v) == RD_OK);
        CHECK(rd_read_linear(ctx, lin[pv], W * H * 4) == RD_OK);
        rd_scene_destroy(s);
    }
    double sum = 0;
    for (int i = 0; i < W * H * 4; i++) {
        CHECK(isfinite(lin[1][i]));
        sum += fabs(lin[0][i] - lin[1][i]);
    }
    rd_mesh_destroy(ctx, sphere);
    return sum / (W * H * 3);
}

static void test_per_vertex_reflection(rd_context *ctx)
{
    rd_cube_data cube;
    CHECK(rd_cube_data_alloc(32, &cube) == RD_OK);
    fill_face_pattern(&cube);
    rd_cubemap map = upload_cube(ctx, &cube);
    double coarse = lookup_difference(ctx, map, 8, 0);
    double fine = lookup_difference(ctx, map, 128, 0);
    printf("per-vertex vs per-pixel reflection, mean |difference|: %.4f on 8 segments, %.4f on "
           "128\n",
           coarse, fine);
    CHECK_MSG(coarse > 0.01, "per-vertex must differ visibly on a coarse mesh: %g", coarse);
    CHECK_MSG(fine < 0.5 * coarse, "and converge on a fine one: %g vs %g", fine, coarse);
    /* Seed 000's sphere map, made for this view from the same cube map: the same picture but
     * for its resampling (strongest at the rim, where the map squeezes the back hemisphere). */
    double sphere = lookup_difference(ctx, map, 64, 1);
    printf("sphere map vs cube map, mean |difference|: %.4f\n", sphere);
    CHECK_MSG(sphere < 0.02, "sphere-map lookup strays from the cube map: %g", sphere);
    rd_cubemap_destroy(ctx, map);
    rd_cube_data_free(&cube);
}

int main(void)
{
    rd_context *ctx = NULL;
    if (rd_context_create(NULL, &ctx) != RD_OK) {
        fprintf(stderr, "no context: %s\n", rd_last_error());
        return 1;
    }
    test_probes_and_policies(ctx);
    test_zero_reflectivity_is_plain(ctx);
    test_lookup_matches_cpu_sampler(ctx);
    test_corrected_vector(ctx);
    test_blur(ctx, RD_BLUR_PREFILTERED);
    test_blur(ctx, RD_BLUR_REFERENCE);
    test_blur(ctx, RD_BLUR_BOX_MIPS);
    test_extremes(ctx);
    test_sh9_ambient(ctx);
    test_per_vertex_reflection(ctx);
    rd_context_destroy(ctx);
    return check_report("reflections");
}
