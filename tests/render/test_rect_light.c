/* Rectangle lights and window portals (docs/rendering.md, "Area lights"):
 *  - the CPU form factor against the closed form for a parallel rectangle (Howell's catalogue
 *    of radiation configuration factors, B-3) and horizon clipping (a rectangle reaching below
 *    a point's horizon gives what its part above gives);
 *  - energy: a plane under a very large rectangle light of radiance L reflects C_d L, the
 *    irradiance of a whole hemisphere, on the GPU as on the CPU;
 *  - the GPU's rectangle light and portal against the CPU twin on every pixel of a lit plane,
 *    within 2/255, for a matte, a glossy and a mirror-like exponent;
 *  - a live view's moving frame (rd_view.live) lights with the rectangle as a point light of
 *    its power at its centre, against that CPU formula on every pixel, and differs from the
 *    exact light where the panel is near. */
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

/* Howell B-3: a differential area parallel to a rectangle a x b at distance c, below one of
 * its corners. */
static double corner_form_factor(double a, double b, double c)
{
    double x = a / c, y = b / c;
    return (x / sqrt(1 + x * x) * atan(y / sqrt(1 + x * x)) +
            y / sqrt(1 + y * y) * atan(x / sqrt(1 + y * y))) /
           (2 * 3.14159265358979323846);
}

static rd_light rect(float cx, float cy, float cz, float hw, float hh)
{
    rd_light l = {.type = RD_LIGHT_RECT,
                  .position = {cx, cy, cz},
                  .direction = {0, 0, -1},
                  .diffuse = {1, 1, 1},
                  .specular = {1, 1, 1},
                  .half_width = {hw, 0, 0},
                  .half_height = {0, hh, 0}};
    return l;
}

static void test_form_factor(void)
{
    const float p[3] = {0, 0, 0}, n[3] = {0, 0, 1};
    /* centred 2 x 1.2 at 0.8 above: four corner rectangles 1 x 0.6 */
    rd_light l = rect(0, 0, 0.8f, 1.0f, 0.6f);
    CHECK_NEAR(rd_ref_rect_form_factor(p, n, &l), 4 * corner_form_factor(1.0, 0.6, 0.8), 1e-5);
    /* off centre, corner above p: one 1.5 x 0.5 rectangle */
    l = rect(0.75f, 0.25f, 0.5f, 0.75f, 0.25f);
    CHECK_NEAR(rd_ref_rect_form_factor(p, n, &l), corner_form_factor(1.5, 0.5, 0.5), 1e-5);
    /* very large: the whole hemisphere */
    l = rect(0, 0, 1.0f, 1e4f, 1e4f);
    CHECK_NEAR(rd_ref_rect_form_factor(p, n, &l), 1.0, 1e-3);
    /* behind the light: nothing */
    l = rect(0, 0, -1.0f, 1.0f, 1.0f);
    CHECK(rd_ref_rect_form_factor(p, n, &l) == 0.0f);
    /* Horizon clipping: a vertical rectangle in front of p (facing -y) from z = -1 to 1 lights
     * p exactly as its upper half from 0 to 1 does. */
    rd_light full = {.type = RD_LIGHT_RECT,
                     .position = {0, 1, 0},
                     .direction = {0, -1, 0},
                     .half_width = {0.7f, 0, 0},
                     .half_height = {0, 0, 1.0f}};
    rd_light upper = full;
    upper.position[2] = 0.5f;
    upper.half_height[2] = 0.5f;
    float ff_full = rd_ref_rect_form_factor(p, n, &full);
    CHECK(ff_full > 0.01f);
    CHECK_NEAR(ff_full, rd_ref_rect_form_factor(p, n, &upper), 1e-5);
}

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

/* What a live frame draws for light l at p (normal n): every light as rd_ref_light_incidence
 * gives it, a rectangle as a point light of its power at its centre (eqs. 1-7). */
static void shade_live(const rd_material *m, const float p[3], const float n[3], const rd_light *l,
                       const float ambient[3], float out[3])
{
    float v[3], dir[3], factor;
    sub(eye, p, v);
    normalize(v);
    rd_ref_light_incidence(l, p, n, dir, &factor);
    float n_dot_l = n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2];
    float h[3] = {dir[0] + v[0], dir[1] + v[1], dir[2] + v[2]};
    normalize(h);
    float spec = rd_ref_blinn_phong_power(n[0] * h[0] + n[1] * h[1] + n[2] * h[2], m->shininess);
    for (int k = 0; k < 3; k++) {
        out[k] = m->ambient[k] * ambient[k];
        if (n_dot_l > 0.0f)
            out[k] += factor * (m->diffuse[k] * l->diffuse[k] * n_dot_l +
                                m->specular[k] * l->specular[k] * spec);
        out[k] = fmaxf(m->emissive[k], out[k]);
    }
}

/* Renders a 40 m plane of material m under light l (as a live view's moving frame when live)
 * and compares every pixel with the CPU twin. Returns the number of pixels more than 2/255
 * off; *exact_off: those more than 2/255 off the exact (still) light. */
static int render_compare(rd_context *ctx, rd_mesh plane, const rd_material *m, const rd_light *l,
                          int live, const char *what, int *lit_pixels, int *exact_off)
{
    const float ambient[3] = {0.05f, 0.05f, 0.05f};
    rd_scene *scene = rd_scene_create(ctx);
    rd_object_desc obj = {.mesh = plane, .material = *m};
    obj.transform[0] = obj.transform[5] = 40.0f;
    obj.transform[10] = obj.transform[15] = 1.0f;
    CHECK(rd_scene_add_object(scene, &obj) == RD_OK);
    CHECK_MSG(rd_scene_add_light(scene, l) == RD_OK, "%s", rd_last_error());
    rd_scene_set_ambient(scene, ambient);
    rd_view view = {.eye = {eye[0], eye[1], eye[2]},
                    .target = {target[0], target[1], target[2]},
                    .fov_y_deg = fov,
                    .width = W,
                    .height = H,
                    .live = live};
    rd_result r = rd_render(ctx, scene, &view);
    CHECK_MSG(r == RD_OK, "%s", rd_last_error());
    static uint8_t img[W * H * 4];
    CHECK(rd_read_rgba8(ctx, img, sizeof img) == RD_OK);
    int off = 0, worst = 0, wx = 0, wy = 0;
    *lit_pixels = 0;
    *exact_off = 0;
    unsigned char worst_ref[3] = {0}, worst_gpu[3] = {0};
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float p[3], n[3] = {0, 0, 1}, c[3];
            if (!pixel_on_plane(x, y, p))
                continue;
            rd_ref_shade(m, NULL, p, n, eye, l, 1, ambient, c);
            unsigned char ref[3], amb[3], exact[3];
            rd_ref_display_rgb8(c, 0.0f, RD_TONEMAP_PHOTOGRAPHIC, 4.0f, exact);
            if (live)
                shade_live(m, p, n, l, ambient, c);
            float a[3] = {m->ambient[0] * ambient[0], m->ambient[1] * ambient[1],
                          m->ambient[2] * ambient[2]};
            rd_ref_display_rgb8(c, 0.0f, RD_TONEMAP_PHOTOGRAPHIC, 4.0f, ref);
            rd_ref_display_rgb8(a, 0.0f, RD_TONEMAP_PHOTOGRAPHIC, 4.0f, amb);
            *lit_pixels += ref[1] > amb[1] + 8;
            const uint8_t *g = &img[(y * W + x) * 4];
            int d = 0;
            for (int k = 0; k < 3; k++)
                d = abs((int)g[k] - (int)ref[k]) > d ? abs((int)g[k] - (int)ref[k]) : d;
            off += d > 2;
            int de = 0;
            for (int k = 0; k < 3; k++)
                de = abs((int)g[k] - (int)exact[k]) > de ? abs((int)g[k] - (int)exact[k]) : de;
            *exact_off += de > 2;
            if (d > worst) {
                worst = d, wx = x, wy = y;
                memcpy(worst_ref, ref, 3);
                memcpy(worst_gpu, g, 3);
            }
        }
    printf("%s: max difference %d/255 at (%d, %d) (expected %d %d %d, observed %d %d %d), %d "
           "pixels over 2/255, %d lit\n",
           what, worst, wx, wy, worst_ref[0], worst_ref[1], worst_ref[2], worst_gpu[0],
           worst_gpu[1], worst_gpu[2], off, *lit_pixels);
    rd_scene_destroy(scene);
    return off;
}

static int render_and_compare(rd_context *ctx, rd_mesh plane, const rd_material *m,
                              const rd_light *l, const char *what, int *lit_pixels)
{
    int exact_off;
    return render_compare(ctx, plane, m, l, 0, what, lit_pixels, &exact_off);
}

static void test_gpu(rd_context *ctx, rd_mesh plane)
{
    const float exponents[] = {1.0f, 64.0f, 2000.0f};
    for (int e = 0; e < 3; e++) {
        rd_material m = {.ambient = {0.2f, 0.25f, 0.3f},
                         .diffuse = {0.6f, 0.5f, 0.4f},
                         .specular = {0.5f, 0.5f, 0.5f},
                         .shininess = exponents[e]};
        /* a tilted 1.2 x 0.6 panel above the plane, facing down and a little towards the eye */
        float dir[3] = {0.0f, -0.3f, -1.0f}, hw[3] = {0.6f, 0.0f, 0.0f}, hh[3];
        normalize(dir);
        cross(dir, hw, hh);
        for (int k = 0; k < 3; k++)
            hh[k] *= 0.3f / 0.6f;
        rd_light l = {.type = RD_LIGHT_RECT,
                      .position = {0.1f, 0.3f, 0.9f},
                      .diffuse = {1.4f, 1.2f, 1.0f},
                      .specular = {1.4f, 1.2f, 1.0f}};
        memcpy(l.direction, dir, sizeof dir);
        memcpy(l.half_width, hw, sizeof hw);
        memcpy(l.half_height, hh, sizeof hh);
        char what[64];
        int lit;
        snprintf(what, sizeof what, "rect light, n = %g", (double)exponents[e]);
        CHECK_MSG(render_and_compare(ctx, plane, &m, &l, what, &lit) == 0, "%s: GPU and CPU differ",
                  what);
        CHECK(lit > W * H / 10);
        /* The live frame: the point of power, which a panel 0.9 m up tells from the exact
         * light under it. The plane is unshadowed, so this is the programs a live frame uses. */
        int exact_off, live_lit;
        snprintf(what, sizeof what, "live frame, rect light, n = %g", (double)exponents[e]);
        CHECK_MSG(render_compare(ctx, plane, &m, &l, 1, what, &live_lit, &exact_off) == 0,
                  "%s: GPU and the point of power differ", what);
        CHECK_MSG(exact_off > W * H / 20, "%s: only %d pixels differ from the exact light", what,
                  exact_off);
    }
    /* Clipped to the horizon: an upright panel standing through the plane, facing the eye. */
    {
        rd_material m = {.ambient = {0.2f, 0.2f, 0.2f}, .diffuse = {0.6f, 0.6f, 0.6f}};
        rd_light l = {.type = RD_LIGHT_RECT,
                      .position = {0.0f, 0.6f, 0.2f},
                      .direction = {0, -1, 0},
                      .diffuse = {2, 2, 2},
                      .specular = {2, 2, 2},
                      .half_width = {0.5f, 0, 0},
                      .half_height = {0, 0, 0.5f}};
        int lit;
        CHECK(render_and_compare(ctx, plane, &m, &l, "rect light through the plane", &lit) == 0);
        CHECK(lit > 500);
    }
    /* Energy: radiance 0.5 over the whole sky of a white plane gives 0.5 everywhere. */
    rd_material white = {.diffuse = {1, 1, 1}};
    rd_light sky = rect(0, 0, 1.0f, 1e4f, 1e4f);
    for (int k = 0; k < 3; k++)
        sky.diffuse[k] = sky.specular[k] = 0.5f;
    float p0[3] = {0, 0, 0}, n0[3] = {0, 0, 1}, c0[3];
    rd_ref_shade(&white, NULL, p0, n0, eye, &sky, 1, (float[3]){0, 0, 0}, c0);
    CHECK_NEAR(c0[1], 0.5, 0.5e-3);
    int lit;
    CHECK(render_and_compare(ctx, plane, &white, &sky, "large rect light (energy)", &lit) == 0);
    CHECK(lit == W * H);
    /* A portal: the directional light comes only through a 0.6 x 0.4 opening 1 m up. */
    rd_light sun = {.type = RD_LIGHT_DIRECTIONAL,
                    .position = {0.0f, 0.2f, 1.0f},
                    .direction = {0.3f, 0.2f, -1.0f},
                    .diffuse = {1, 1, 1},
                    .specular = {1, 1, 1},
                    .half_width = {0.3f, 0, 0},
                    .half_height = {0, 0.2f, 0}};
    normalize(sun.direction);
    rd_material matte = {.ambient = {0.2f, 0.2f, 0.2f}, .diffuse = {0.6f, 0.6f, 0.6f}};
    int off = render_and_compare(ctx, plane, &matte, &sun, "portal", &lit);
    /* the patch's edge may fall either side of a pixel centre in float rounding */
    CHECK_MSG(off <= W * H / 500, "%d pixels differ", off);
    CHECK(lit > 50 && lit < W * H / 2); /* a patch, not the whole plane */
}

int main(void)
{
    test_form_factor();
    rd_context *ctx = NULL;
    if (rd_context_create(&(rd_context_desc){0}, &ctx) != RD_OK) {
        fprintf(stderr, "no context: %s\n", rd_last_error());
        return 1;
    }
    rd_mesh_data pd;
    CHECK(rd_mesh_data_plane(&pd) == RD_OK);
    rd_mesh_desc pdesc = rd_mesh_data_desc(&pd);
    rd_mesh plane = rd_mesh_create(ctx, &pdesc);
    rd_mesh_data_free(&pd);
    test_gpu(ctx, plane);
    rd_context_destroy(ctx);
    return check_report("rect_light");
}
