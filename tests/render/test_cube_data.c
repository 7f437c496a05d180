/* Cube maps on the CPU (RENDERING.md sections 3 and 8): GL's face selection table by hand,
 * M_rot and seed 000 Fig. 8, nearest and seamless bilinear sampling, loading six files under
 * GL and 3ds Max names, and the loader's error messages. */
#include "../common/check.h"
#include "render/cube_data.h"
#include "render/image_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int near(float a, float b, float tol)
{
    return fabsf(a - b) <= tol;
}

/* ---- face selection --------------------------------------------------------------------- */

typedef struct face_case {
    float v[3];
    int face;
    float s, t;
} face_case;

/* Worked by hand from the GL table (see cube_data.h): 6 centres, 12 edge midpoints (ties: X
 * wins over Y over Z), 8 corners (all X), one off-centre point per face, a zero vector. */
static const face_case face_cases[] = {
    /* centres */
    {{1, 0, 0}, 0, 0.5f, 0.5f},
    {{-1, 0, 0}, 1, 0.5f, 0.5f},
    {{0, 1, 0}, 2, 0.5f, 0.5f},
    {{0, -1, 0}, 3, 0.5f, 0.5f},
    {{0, 0, 1}, 4, 0.5f, 0.5f},
    {{0, 0, -1}, 5, 0.5f, 0.5f},
    /* XY edges -> X: s = 0.5, t = (-y + 1) / 2 */
    {{1, 1, 0}, 0, 0.5f, 0.0f},
    {{1, -1, 0}, 0, 0.5f, 1.0f},
    {{-1, 1, 0}, 1, 0.5f, 0.0f},
    {{-1, -1, 0}, 1, 0.5f, 1.0f},
    /* XZ edges -> X: +X s = (-z + 1) / 2, -X s = (z + 1) / 2, t = 0.5 */
    {{1, 0, 1}, 0, 0.0f, 0.5f},
    {{1, 0, -1}, 0, 1.0f, 0.5f},
    {{-1, 0, 1}, 1, 1.0f, 0.5f},
    {{-1, 0, -1}, 1, 0.0f, 0.5f},
    /* YZ edges -> Y: +Y t = (z + 1) / 2, -Y t = (-z + 1) / 2, s = 0.5 */
    {{0, 1, 1}, 2, 0.5f, 1.0f},
    {{0, 1, -1}, 2, 0.5f, 0.0f},
    {{0, -1, 1}, 3, 0.5f, 0.0f},
    {{0, -1, -1}, 3, 0.5f, 1.0f},
    /* corners -> X */
    {{1, 1, 1}, 0, 0.0f, 0.0f},
    {{1, 1, -1}, 0, 1.0f, 0.0f},
    {{1, -1, 1}, 0, 0.0f, 1.0f},
    {{1, -1, -1}, 0, 1.0f, 1.0f},
    {{-1, 1, 1}, 1, 1.0f, 0.0f},
    {{-1, 1, -1}, 1, 0.0f, 0.0f},
    {{-1, -1, 1}, 1, 1.0f, 1.0f},
    {{-1, -1, -1}, 1, 0.0f, 1.0f},
    /* off-centre: every row of the table with both signs of sc and tc in play */
    {{1, -0.25f, 0.5f}, 0, 0.25f, 0.625f},    /* +X: sc = -z, tc = -y */
    {{-1, -0.25f, 0.5f}, 1, 0.75f, 0.625f},   /* -X: sc = z, tc = -y */
    {{0.5f, 1, -0.25f}, 2, 0.75f, 0.375f},    /* +Y: sc = x, tc = z */
    {{0.5f, -1, -0.25f}, 3, 0.75f, 0.625f},   /* -Y: sc = x, tc = -z */
    {{0.5f, -0.25f, 1}, 4, 0.75f, 0.625f},    /* +Z: sc = x, tc = -y */
    {{0.5f, -0.25f, -1}, 5, 0.25f, 0.625f},   /* -Z: sc = -x, tc = -y */
    {{2, -0.5f, 1}, 0, 0.25f, 0.625f},        /* scale does not matter */
    {{0.25f, 0.25f, -0.5f}, 5, 0.25f, 0.25f}, /* |ma| = 0.5 */
};

static void test_face_selection(void)
{
    for (size_t k = 0; k < sizeof face_cases / sizeof face_cases[0]; k++) {
        const face_case *fc = &face_cases[k];
        float s = -1, t = -1;
        int face = rd_ref_cube_face_st(fc->v, &s, &t);
        CHECK_MSG(face == fc->face && near(s, fc->s, 1e-6f) && near(t, fc->t, 1e-6f),
                  "(%g, %g, %g): face %d s %g t %g, expected face %d s %g t %g", fc->v[0], fc->v[1],
                  fc->v[2], face, s, t, fc->face, fc->s, fc->t);
    }

    /* Seed 000's +X formula: s = -z / (2|x|) + 1/2, t = -y / (2|x|) + 1/2. */
    unsigned seed = 12345;
    for (int k = 0; k < 200; k++) {
        float v[3];
        seed = seed * 1103515245u + 12345u;
        v[0] = 0.1f + (float)(seed >> 8) / (float)(1u << 24) * 3.0f;
        seed = seed * 1103515245u + 12345u;
        v[1] = ((float)(seed >> 8) / (float)(1u << 24) * 2.0f - 1.0f) * v[0] * 0.999f;
        seed = seed * 1103515245u + 12345u;
        v[2] = ((float)(seed >> 8) / (float)(1u << 24) * 2.0f - 1.0f) * v[0] * 0.999f;
        float s, t;
        int face = rd_ref_cube_face_st(v, &s, &t);
        float es = -v[2] / (2.0f * fabsf(v[0])) + 0.5f, et = -v[1] / (2.0f * fabsf(v[0])) + 0.5f;
        CHECK_MSG(face == 0 && near(s, es, 1e-6f) && near(t, et, 1e-6f),
                  "seed 000 +X formula at (%g, %g, %g)", v[0], v[1], v[2]);
    }

    /* Zero and non-finite vectors: -1, and s, t still defined. */
    float bad[4][3] = {{0, 0, 0}, {NAN, 1, 0}, {INFINITY, 0, 0}, {0, -INFINITY, 1}};
    for (int k = 0; k < 4; k++) {
        float s = -7, t = -7;
        CHECK(rd_ref_cube_face_st(bad[k], &s, &t) == -1 && s == 0.5f && t == 0.5f);
    }
    float dir[3] = {9, 9, 9};
    rd_ref_cube_face_direction(6, 0.5f, 0.5f, dir);
    CHECK(dir[0] == 0 && dir[1] == 0 && dir[2] == 0);

    /* face_st and face_direction are inverse on a grid of every face. */
    const int grid = 16;
    for (int f = 0; f < 6; f++) {
        for (int j = 0; j < grid; j++) {
            for (int i = 0; i < grid; i++) {
                float s0 = (i + 0.5f) / grid, t0 = (j + 0.5f) / grid, d[3], s, t;
                rd_ref_cube_face_direction(f, s0, t0, d);
                float ma = fmaxf(fabsf(d[0]), fmaxf(fabsf(d[1]), fabsf(d[2])));
                int face = rd_ref_cube_face_st(d, &s, &t);
                CHECK_MSG(face == f && ma == 1.0f && near(s, s0, 1e-6f) && near(t, t0, 1e-6f),
                          "face %d (s %g, t %g) -> face %d (s %g, t %g)", f, s0, t0, face, s, t);
            }
        }
    }
}

/* ---- M_rot and seed 000 Fig. 8 ---------------------------------------------------------- */

static void test_world_to_cmcs(void)
{
    /* Fig. 8: world direction -> CMCS axis and GL face. */
    static const struct {
        const char *name;
        float world[3], cmcs[3];
        int face;
    } fig8[] = {
        {"FRONT", {0, -1, 0}, {0, 0, -1}, 5}, {"BACK", {0, 1, 0}, {0, 0, 1}, 4},
        {"UP", {0, 0, 1}, {0, -1, 0}, 3},     {"DOWN", {0, 0, -1}, {0, 1, 0}, 2},
        {"LEFT", {-1, 0, 0}, {-1, 0, 0}, 1},  {"RIGHT", {1, 0, 0}, {1, 0, 0}, 0},
    };
    for (int k = 0; k < 6; k++) {
        float c[3], w[3], s, t;
        rd_ref_world_to_cmcs(fig8[k].world, c);
        CHECK_MSG(c[0] == fig8[k].cmcs[0] && c[1] == fig8[k].cmcs[1] && c[2] == fig8[k].cmcs[2],
                  "Fig. 8 %s: CMCS (%g, %g, %g)", fig8[k].name, c[0], c[1], c[2]);
        CHECK_MSG(rd_ref_cube_face_st(c, &s, &t) == fig8[k].face, "Fig. 8 %s: face", fig8[k].name);
        rd_ref_cmcs_to_world(c, w);
        CHECK(w[0] == fig8[k].world[0] && w[1] == fig8[k].world[1] && w[2] == fig8[k].world[2]);
    }
    /* M_rot of seed 000 eq. 7 on a generic vector, the inverse, and in-place use. */
    float v[3] = {1.5f, -2.25f, 3.125f}, c[3], w[3];
    rd_ref_world_to_cmcs(v, c);
    CHECK(c[0] == 1.5f && c[1] == -3.125f && c[2] == -2.25f);
    rd_ref_cmcs_to_world(c, w);
    CHECK(w[0] == v[0] && w[1] == v[1] && w[2] == v[2]);
    rd_ref_world_to_cmcs(w, w);
    CHECK(w[0] == c[0] && w[1] == c[1] && w[2] == c[2]);
}

/* ---- storage and sampling --------------------------------------------------------------- */

/* Face f: constant colour (f + 1) / 6 in red, 1 - f / 10 in green, f-th bit pattern in blue. */
static void face_colour(int f, float rgba[4])
{
    rgba[0] = (f + 1) / 6.0f;
    rgba[1] = 1.0f - f / 10.0f;
    rgba[2] = (float)(f % 2);
    rgba[3] = 1.0f;
}

static void fill_constant_faces(rd_cube_data *c)
{
    for (int f = 0; f < 6; f++) {
        float col[4];
        face_colour(f, col);
        for (int p = 0; p < c->size * c->size; p++)
            memcpy(c->faces[f] + p * 4, col, sizeof col);
    }
}

static void test_alloc(void)
{
    rd_cube_data c;
    CHECK(rd_cube_data_alloc(0, &c) == RD_ERR_INVALID_ARGUMENT && c.size == 0 && !c.faces[0]);
    CHECK(rd_cube_data_alloc(-3, &c) == RD_ERR_INVALID_ARGUMENT);
    CHECK(rd_cube_data_alloc(RD_CUBE_MAX_SIZE + 1, &c) == RD_ERR_TOO_LARGE && c.faces[5] == NULL);
    CHECK(rd_cube_data_alloc(4, NULL) == RD_ERR_INVALID_ARGUMENT);
    CHECK(rd_cube_data_alloc(3, &c) == RD_OK && c.size == 3);
    for (int f = 0; f < 6; f++)
        for (int k = 0; k < 3 * 3 * 4; k++)
            CHECK(c.faces[f][k] == 0.0f);
    rd_cube_data_free(&c);
    CHECK(c.size == 0 && c.faces[0] == NULL);
    rd_cube_data_free(&c); /* again, zeroed */
    rd_cube_data_free(NULL);
}

static void test_sample_centres(void)
{
    /* World directions of the six face centres (Fig. 8) give the six colours, both filters. */
    static const float world[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 0, -1},
                                      {0, 0, 1}, {0, 1, 0},  {0, -1, 0}};
    for (int size = 1; size <= 4; size++) {
        rd_cube_data c;
        CHECK(rd_cube_data_alloc(size, &c) == RD_OK);
        fill_constant_faces(&c);
        for (int f = 0; f < 6; f++) {
            float want[4], got[4], lin[4];
            face_colour(f, want);
            rd_cube_sample_nearest(&c, world[f], got);
            rd_cube_sample_bilinear(&c, world[f], lin);
            CHECK_MSG(memcmp(got, want, sizeof want) == 0, "size %d face %d nearest", size, f);
            for (int ch = 0; ch < 4; ch++)
                CHECK_MSG(near(lin[ch], want[ch], 1e-6f), "size %d face %d bilinear ch %d: %g",
                          size, f, ch, lin[ch]);
        }
        float zero[3] = {0, 0, 0}, nan3[3] = {NAN, 0, 1}, out[4] = {1, 1, 1, 1};
        rd_cube_sample_nearest(&c, zero, out);
        CHECK(out[0] == 0 && out[3] == 0);
        out[0] = 1;
        rd_cube_sample_bilinear(&c, nan3, out);
        CHECK(out[0] == 0 && out[3] == 0);
        rd_cube_data_free(&c);
    }
    /* An empty cube samples to zero instead of crashing. */
    rd_cube_data empty = {0};
    float d[3] = {1, 0, 0}, out[4] = {1, 1, 1, 1};
    rd_cube_sample_bilinear(&empty, d, out);
    CHECK(out[0] == 0);
    rd_cube_sample_nearest(NULL, d, out);
    CHECK(out[0] == 0);

    /* Nearest picks the texel (floor(s size), floor(t size)) of the face: mark one texel. */
    rd_cube_data c;
    CHECK(rd_cube_data_alloc(4, &c) == RD_OK);
    c.faces[RD_CUBE_POS_Z][(1 * 4 + 3) * 4] = 7.0f; /* row j = 1, column i = 3 */
    float cm[3], w[3], got[4];
    rd_ref_cube_face_direction(RD_CUBE_POS_Z, 3.5f / 4, 1.5f / 4, cm);
    rd_ref_cmcs_to_world(cm, w);
    rd_cube_sample_nearest(&c, w, got);
    CHECK(got[0] == 7.0f);
    rd_ref_cube_face_direction(RD_CUBE_POS_Z, 2.5f / 4, 1.5f / 4, cm);
    rd_ref_cmcs_to_world(cm, w);
    rd_cube_sample_nearest(&c, w, got);
    CHECK(got[0] == 0.0f);
    rd_cube_data_free(&c);
}

static const float axes[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                 {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};

/* The largest difference between two texels that bilinear filtering may blend: any two texels
 * of the cube (an upper bound of the neighbour difference, cheap to get). */
static float value_range(const rd_cube_data *c, int ch)
{
    float lo = INFINITY, hi = -INFINITY;
    for (int f = 0; f < 6; f++)
        for (int p = 0; p < c->size * c->size; p++) {
            lo = fminf(lo, c->faces[f][p * 4 + ch]);
            hi = fmaxf(hi, c->faces[f][p * 4 + ch]);
        }
    return hi - lo;
}

/* Walk across each of the 12 edges in small steps: seamless bilinear has no jump larger than
 * what the texel gradient allows for the step, so no seam. Per-face clamping would jump by the
 * difference of the two faces' edge texels. */
static void check_edges_continuous(const rd_cube_data *c, const char *what)
{
    const int steps = 4000;
    int n = c->size, edges = 0;
    float range = value_range(c, 0);
    for (int a = 0; a < 6; a++) {
        for (int b = a + 1; b < 6; b++) {
            if (a / 2 == b / 2)
                continue; /* opposite faces share no edge */
            edges++;
            const float *na = axes[a], *nb = axes[b];
            float e[3] = {na[1] * nb[2] - na[2] * nb[1], na[2] * nb[0] - na[0] * nb[2],
                          na[0] * nb[1] - na[1] * nb[0]};
            float prev = 0.0f, prev_dir[3] = {0, 0, 0}, worst = 0.0f, worst_allowed = 0.0f;
            int crossed = 0, first_face = -1, ok = 1;
            for (int k = 0; k <= steps; k++) {
                float lam = 0.3f + 0.4f * (float)k / (float)steps, cm[3], w[3], out[4], s, t;
                for (int q = 0; q < 3; q++)
                    cm[q] = (1.0f - lam) * na[q] + lam * nb[q] + 0.3f * e[q];
                float len = sqrtf(cm[0] * cm[0] + cm[1] * cm[1] + cm[2] * cm[2]);
                for (int q = 0; q < 3; q++)
                    cm[q] /= len;
                int face = rd_ref_cube_face_st(cm, &s, &t);
                if (k == 0)
                    first_face = face;
                else if (face != first_face)
                    crossed = 1;
                rd_ref_cmcs_to_world(cm, w);
                rd_cube_sample_bilinear(c, w, out);
                if (k > 0) {
                    /* The chord, not acos of the dot (which rounds to 0 for tiny steps). */
                    float dx = cm[0] - prev_dir[0], dy = cm[1] - prev_dir[1],
                          dz = cm[2] - prev_dir[2];
                    float angle = sqrtf(dx * dx + dy * dy + dz * dz) * 1.001f + 1e-7f;
                    /* Texel units per radian are at most 3 n / 2 (face coordinate u = tan,
                     * du/dtheta <= 1 + u^2 + v^2 <= 3); |du| + |dv| <= sqrt 2 |d(u, v)|. */
                    float allowed = range * 1.5f * 1.4143f * 3.0f * (float)n / 2.0f * angle + 1e-6f;
                    float jump = fabsf(out[0] - prev);
                    if (jump > allowed)
                        ok = 0;
                    if (jump - allowed > worst - worst_allowed) {
                        worst = jump;
                        worst_allowed = allowed;
                    }
                }
                prev = out[0];
                memcpy(prev_dir, cm, sizeof cm);
            }
            CHECK_MSG(crossed, "%s: path %d-%d did not cross the edge", what, a, b);
            CHECK_MSG(ok, "%s: seam between faces %d and %d: jump %g where %g is allowed", what, a,
                      b, worst, worst_allowed);
        }
    }
    CHECK(edges == 12);
}

static void test_bilinear_seamless(void)
{
    rd_cube_data c;
    for (int size = 1; size <= 8; size *= 2) {
        CHECK(rd_cube_data_alloc(size, &c) == RD_OK);
        fill_constant_faces(&c);
        char what[64];
        snprintf(what, sizeof what, "constant faces, size %d", size);
        check_edges_continuous(&c, what);
        /* Random texels. */
        unsigned seed = 777u + (unsigned)size;
        for (int f = 0; f < 6; f++)
            for (int p = 0; p < size * size; p++) {
                seed = seed * 1664525u + 1013904223u;
                c.faces[f][p * 4] = (float)(seed >> 8) / (float)(1u << 24);
            }
        snprintf(what, sizeof what, "random texels, size %d", size);
        check_edges_continuous(&c, what);
        rd_cube_data_free(&c);
    }

    /* At an edge midpoint both faces' edge texels weigh one half. */
    CHECK(rd_cube_data_alloc(4, &c) == RD_OK);
    fill_constant_faces(&c);
    float cm[3] = {1, 1, 0.1f}, w[3], out[4], a[4], b[4];
    rd_ref_cmcs_to_world(cm, w);
    rd_cube_sample_bilinear(&c, w, out);
    face_colour(RD_CUBE_POS_X, a);
    face_colour(RD_CUBE_POS_Y, b);
    CHECK_MSG(near(out[0], 0.5f * (a[0] + b[0]), 1e-6f), "edge midpoint %g", out[0]);
    /* At a cube corner the three faces meet: the mean of the three. */
    float corner[3] = {1, 1, 1}, third[4];
    rd_ref_cmcs_to_world(corner, w);
    rd_cube_sample_bilinear(&c, w, out);
    face_colour(RD_CUBE_POS_Z, third);
    CHECK_MSG(near(out[0], (a[0] + b[0] + third[0]) / 3.0f, 1e-6f), "corner %g", out[0]);
    rd_cube_data_free(&c);
}

/* ---- loading ---------------------------------------------------------------------------- */

static char tmpdir[64];

static void path_in_tmp(char *out, size_t size, const char *name)
{
    snprintf(out, size, "%s/%s", tmpdir, name);
}

/* An 8-bit RGBA image of one colour with pixel (0, 0) (top left) set to 128 grey. */
static int write_png(const char *name, int w, int h, const unsigned char rgb[3])
{
    char path[256];
    path_in_tmp(path, sizeof path, name);
    unsigned char *px = malloc((size_t)w * h * 4);
    for (int p = 0; p < w * h; p++) {
        px[p * 4 + 0] = rgb[0];
        px[p * 4 + 1] = rgb[1];
        px[p * 4 + 2] = rgb[2];
        px[p * 4 + 3] = 255;
    }
    px[0] = px[1] = px[2] = 128;
    rd_image_result r = rd_image_write_rgba8(path, w, h, px, NULL, 0);
    free(px);
    return r == RD_IMAGE_OK;
}

static const unsigned char palette[6][3] = {{255, 0, 0},   {0, 255, 0},   {0, 0, 255},
                                            {255, 255, 0}, {0, 255, 255}, {255, 0, 255}};

static void check_face_colour(const rd_cube_data *c, int face, const unsigned char rgb[3],
                              const char *what)
{
    /* Row 0 column 0 is the image's top-left pixel: sRGB 128 -> linear 0.2158605. */
    const float *p = c->faces[face];
    CHECK_MSG(near(p[0], 0.2158605f, 1e-5f) && near(p[2], 0.2158605f, 1e-5f),
              "%s face %d: top-left %g", what, face, p[0]);
    const float *q = c->faces[face] + ((size_t)c->size * c->size - 1) * 4;
    for (int ch = 0; ch < 3; ch++)
        CHECK_MSG(q[ch] == rgb[ch] / 255.0f, "%s face %d ch %d: %g", what, face, ch, q[ch]);
    CHECK(q[3] == 1.0f);
}

static int write_set(const char *prefix, const char *const names[6], int sizes[6])
{
    int ok = 1;
    for (int f = 0; f < 6; f++) {
        char name[64];
        snprintf(name, sizeof name, "%s_%s.png", prefix, names[f]);
        ok &= write_png(name, sizes[f], sizes[f], palette[f]);
    }
    return ok;
}

static const char *const gl_names[6] = {"posx", "negx", "posy", "negy", "posz", "negz"};

static void remove_tmp_files(void)
{
    static const char *const all[] = {"posx",  "negx", "posy", "negy", "posz", "negz",
                                      "right", "left", "down", "up",   "back", "front"};
    static const char *const prefixes[] = {"gl", "max", "miss", "ns", "uq", "cr", "exr", "none"};
    for (size_t p = 0; p < sizeof prefixes / sizeof prefixes[0]; p++)
        for (size_t k = 0; k < sizeof all / sizeof all[0]; k++) {
            char name[64], path[256];
            snprintf(name, sizeof name, "%s_%s.%s", prefixes[p], all[k],
                     strcmp(prefixes[p], "exr") == 0 ? "exr" : "png");
            path_in_tmp(path, sizeof path, name);
            unlink(path);
        }
    rmdir(tmpdir);
}

static void expect_load_error(const char *pattern_name, const char *file, const char *problem)
{
    char pattern[256], err[512] = "", want[256];
    path_in_tmp(pattern, sizeof pattern, pattern_name);
    path_in_tmp(want, sizeof want, file);
    rd_cube_data c;
    memset(&c, 0x5a, sizeof c);
    rd_result r = rd_cube_data_load(pattern, &c, err, sizeof err);
    CHECK_MSG(r != RD_OK, "%s loaded", pattern_name);
    CHECK_MSG(c.size == 0 && c.faces[0] == NULL && c.faces[5] == NULL, "%s: out not zeroed",
              pattern_name);
    CHECK_MSG(strstr(err, want) != NULL && strstr(err, pattern) == err,
              "%s: message does not start with the pattern and name %s: \"%s\"", pattern_name, want,
              err);
    CHECK_MSG(strstr(err, problem) != NULL, "%s: message does not say \"%s\": \"%s\"", pattern_name,
              problem, err);
    CHECK_MSG(strcmp(rd_last_error(), err) == 0, "%s: rd_last_error differs", pattern_name);
    rd_cube_data_free(&c);
}

static void test_load(void)
{
    const char *base = getenv("TMPDIR");
    snprintf(tmpdir, sizeof tmpdir, "%s/tessera_cube_XXXXXX", base && *base ? base : "/tmp");
    if (mkdtemp(tmpdir) == NULL) {
        CHECK_MSG(0, "mkdtemp(%s) failed", tmpdir);
        return;
    }
    int four[6] = {4, 4, 4, 4, 4, 4};
    char pattern[256], err[512];
    rd_cube_data c;

    /* GL names: face k is the k-th file. */
    CHECK(write_set("gl", gl_names, four));
    path_in_tmp(pattern, sizeof pattern, "gl_*.png");
    CHECK_MSG(rd_cube_data_load(pattern, &c, err, sizeof err) == RD_OK, "%s", err);
    CHECK(c.size == 4);
    for (int f = 0; f < 6 && c.size == 4; f++)
        check_face_colour(&c, f, palette[f], "GL names");
    rd_cube_data_free(&c);

    /* 3ds Max names, placed by seed 000 Fig. 8. Colours by name: */
    static const char *const max_names[6] = {"front", "back", "up", "down", "left", "right"};
    static const int fig8_face[6] = {RD_CUBE_NEG_Z, RD_CUBE_POS_Z, RD_CUBE_NEG_Y,
                                     RD_CUBE_POS_Y, RD_CUBE_NEG_X, RD_CUBE_POS_X};
    static const float fig8_world[6][3] = {{0, -1, 0}, {0, 1, 0},  {0, 0, 1},
                                           {0, 0, -1}, {-1, 0, 0}, {1, 0, 0}};
    CHECK(write_set("max", max_names, four));
    path_in_tmp(pattern, sizeof pattern, "max_*.png");
    CHECK_MSG(rd_cube_data_load(pattern, &c, err, sizeof err) == RD_OK, "%s", err);
    for (int k = 0; k < 6 && c.size == 4; k++) {
        check_face_colour(&c, fig8_face[k], palette[k], max_names[k]);
        float got[4];
        rd_cube_sample_nearest(&c, fig8_world[k], got);
        CHECK_MSG(got[0] == palette[k][0] / 255.0f && got[1] == palette[k][1] / 255.0f &&
                      got[2] == palette[k][2] / 255.0f,
                  "world direction of %s does not show the %s image", max_names[k], max_names[k]);
    }
    rd_cube_data_free(&c);

    /* EXR faces stay linear; a NaN texel becomes 0. */
    for (int f = 0; f < 6; f++) {
        float px[2 * 2 * 4];
        for (int p = 0; p < 4; p++) {
            px[p * 4 + 0] = 100.0f * (f + 1);
            px[p * 4 + 1] = 0.5f;
            px[p * 4 + 2] = 0.25f;
            px[p * 4 + 3] = 1.0f;
        }
        px[1] = NAN;
        char name[64], path[256];
        snprintf(name, sizeof name, "exr_%s.exr", gl_names[f]);
        path_in_tmp(path, sizeof path, name);
        CHECK(rd_image_write_float(path, 2, 2, 4, px, NULL, 0) == RD_IMAGE_OK);
    }
    path_in_tmp(pattern, sizeof pattern, "exr_*.exr");
    CHECK_MSG(rd_cube_data_load(pattern, &c, err, sizeof err) == RD_OK, "%s", err);
    for (int f = 0; f < 6 && c.size == 2; f++) {
        CHECK(c.faces[f][0] == 100.0f * (f + 1) && c.faces[f][1] == 0.0f);
        CHECK(c.faces[f][5] == 0.5f && c.faces[f][6] == 0.25f);
    }
    rd_cube_data_free(&c);

    /* Errors name the pattern, the face's file and the problem. */
    CHECK(write_set("miss", gl_names, four));
    char path[256];
    path_in_tmp(path, sizeof path, "miss_negy.png");
    unlink(path);
    expect_load_error("miss_*.png", "miss_negy.png", "no such file");

    int non_square[6] = {4, 4, 4, 4, 4, 4};
    CHECK(write_set("ns", gl_names, non_square));
    CHECK(write_png("ns_negy.png", 4, 3, palette[3]));
    expect_load_error("ns_*.png", "ns_negy.png", "4x3 is not square");

    int unequal[6] = {4, 4, 4, 4, 2, 4};
    CHECK(write_set("uq", gl_names, unequal));
    expect_load_error("uq_*.png", "uq_posz.png", "2x2 differs");

    CHECK(write_set("cr", gl_names, four));
    path_in_tmp(path, sizeof path, "cr_negz.png");
    FILE *f = fopen(path, "wb");
    if (f != NULL) {
        fputs("\x89PNG\r\n\x1a\nthis is not a PNG at all", f);
        fclose(f);
    }
    expect_load_error("cr_*.png", "cr_negz.png", "face negz");

    expect_load_error("none_*.png", "none_right.png", "none_posx.png and no");

    /* A pattern needs exactly one '*'. */
    path_in_tmp(pattern, sizeof pattern, "gl_posx.png");
    CHECK(rd_cube_data_load(pattern, &c, err, sizeof err) == RD_ERR_INVALID_ARGUMENT);
    CHECK(strstr(err, "'*'") != NULL);
    path_in_tmp(pattern, sizeof pattern, "*_*.png");
    CHECK(rd_cube_data_load(pattern, &c, err, sizeof err) == RD_ERR_INVALID_ARGUMENT);
    CHECK(rd_cube_data_load(NULL, &c, NULL, 0) == RD_ERR_INVALID_ARGUMENT);

    remove_tmp_files();
}

int main(void)
{
    test_face_selection();
    test_world_to_cmcs();
    test_alloc();
    test_sample_centres();
    test_bilinear_seamless();
    test_load();
    return check_report("test_cube_data");
}
