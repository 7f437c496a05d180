/* Analytic reflections and transmission (RENDERING.md sections 2, 6, 9): in a closed room whose
 * six walls glow in distinct colours, a mirror pixel shows exactly the wall its reflected ray
 * reaches; partial k_r and the Fresnel blend scale it as section 6 says; a clear pane shows the
 * wall straight behind it, and a closed glass surface the wall its refracted ray reaches. A
 * textured wall seen in a mirror is filtered exactly as its mirror image seen directly: the
 * pixel footprint follows the reflected ray. */
#include "../common/check.h"
#include "ref_test_scenes.h"
#include "render/reflect_ref.h"

#include <math.h>
#include <stdio.h>

#define W 64
#define H 48

static const float room[3] = {4.0f, 4.0f, 3.0f};
/* The panel: x = 3.5, y in [1, 3], z in [0.5, 2.5], its front facing -X (the camera). */
static const float panel_o[3] = {3.5f, 1.0f, 0.5f}, panel_u[3] = {0, 0, 2}, panel_v[3] = {0, 2, 0};

typedef enum { MIRROR, PANE, THICK } panel_kind;

static const rd_view view = {.eye = {1.0f, 2.2f, 1.6f},
                             .target = {3.5f, 1.9f, 1.4f},
                             .fov_y_deg = 60.0f,
                             .width = W,
                             .height = H};

/* 1 if p is at least `margin` away from every edge of the face it lies on (no ambiguity). */
static int clear_of_edges(const float p[3], float margin)
{
    int inside = 0;
    for (int k = 0; k < 3; k++)
        inside += p[k] > margin && p[k] < room[k] - margin;
    return inside >= 2;
}

/* The expected colour of pixel (x, y); 0 when it lies too near an edge to call. *on_panel says
 * whether the camera ray meets the panel. */
static int expected(panel_kind kind, const rd_material *m, int x, int y, float out[3],
                    int *on_panel)
{
    float o[3], d[3], hit[3];
    ref_camera_ray(&view, (float)x + 0.5f, (float)y + 0.5f, o, d);
    float t = (panel_o[0] - o[0]) / d[0];
    float p[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
    const float margin = 0.02f;
    *on_panel = t > 0.0f && p[1] > 1.0f && p[1] < 3.0f && p[2] > 0.5f && p[2] < 2.5f;
    int near_rim = t > 0.0f && p[1] > 1.0f - margin && p[1] < 3.0f + margin &&
                   p[2] > 0.5f - margin && p[2] < 2.5f + margin &&
                   !(p[1] > 1.0f + margin && p[1] < 3.0f - margin && p[2] > 0.5f + margin &&
                     p[2] < 2.5f - margin);
    if (near_rim)
        return 0;
    if (!*on_panel) {
        int wall = room_wall_hit(room, o, d, hit);
        for (int k = 0; k < 3; k++)
            out[k] = room_colour[wall][k];
        return clear_of_edges(hit, 0.02f);
    }
    float n[3] = {-1, 0, 0}, dir[3];
    if (kind == MIRROR) {
        rd_ref_reflect(d, n, dir); /* R = I - 2 (N.I) N, I the incident ray */
    } else if (kind == PANE) {
        for (int k = 0; k < 3; k++)
            dir[k] = d[k]; /* a thin sheet: straight through */
    } else if (!rd_ref_refract(d, n, 1.0f / m->ior, dir)) {
        return 0;
    }
    int wall = room_wall_hit(room, p, dir, hit);
    if (!clear_of_edges(hit, 0.02f))
        return 0;
    const float *c = room_colour[wall];
    float kr = m->reflectivity;
    for (int k = 0; k < 3; k++) {
        if (kind != MIRROR)
            out[k] = c[k]; /* transparency 1, k_r 0: lit = mix(lit, refr, 1) = refr */
        else if (m->blend == RD_REFLECT_FRESNEL)
            out[k] = rd_ref_fresnel(kr, d[0]) * c[k]; /* N.V = (-1, 0, 0).(-d) = d.x; lit = 0 */
        else
            out[k] = kr * c[k]; /* mix: (1 - k_r) 0 + k_r C_refl */
    }
    return 1;
}

static void check_panel(panel_kind kind, rd_material m, const char *name)
{
    ref_scene *s = ref_scene_create();
    CHECK(s && add_glowing_room(s, room) == REF_OK);
    CHECK(add_rect(s, panel_o, panel_u, panel_v, &m, kind != THICK) == REF_OK);
    ref_image img;
    CHECK(ref_render(s, &(ref_render_desc){.view = view, .samples = 4, .threads = 2}, &img) ==
          REF_OK);
    int on = 0, off = 0, bad = 0, bad_mask = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float want[3];
            int on_panel;
            if (!expected(kind, &m, x, y, want, &on_panel))
                continue;
            const float *got = img.linear + 4 * (y * W + x);
            int ok = 1;
            for (int k = 0; k < 3; k++)
                ok &= fabsf(got[k] - want[k]) <= 1e-5f;
            if (!ok && bad < 5)
                fprintf(stderr, "%s: pixel (%d, %d) %s: got %g %g %g, want %g %g %g\n", name, x, y,
                        on_panel ? "on the panel" : "on a wall", (double)got[0], (double)got[1],
                        (double)got[2], (double)want[0], (double)want[1], (double)want[2]);
            bad += !ok;
            bad_mask += img.mask[y * W + x] != on_panel;
            on += on_panel;
            off += !on_panel;
        }
    CHECK_MSG(bad == 0, "%s: %d pixels differ from the analytic colour", name, bad);
    CHECK_MSG(bad_mask == 0, "%s: %d mask pixels wrong", name, bad_mask);
    CHECK_MSG(on > 600 && off > 600, "%s: %d panel pixels, %d wall pixels checked", name, on, off);
    printf("%s: %d panel pixels and %d wall pixels exact\n", name, on, off);
    ref_image_free(&img);
    ref_scene_destroy(s);
}

/* A 64x64 texture of fine random stripes: minified, its mip level shows in every pixel. */
static int add_stripes(ref_scene *s)
{
    static float rgba[64 * 64 * 4];
    unsigned x = 12345;
    for (int i = 0; i < 64 * 64; i++) {
        x = x * 1103515245u + 12345u;
        float v = (float)((x >> 16) & 255) / 255.0f;
        rgba[4 * i] = (i % 64) % 2 ? v : 1.0f - v;
        rgba[4 * i + 1] = (i / 64) % 3 ? 0.2f : 0.9f;
        rgba[4 * i + 2] = v;
        rgba[4 * i + 3] = 1.0f;
    }
    return ref_scene_add_texture(s, &(ref_texture_desc){64, 64, rgba});
}

/* The textured wall (ambient-lit only, so its colour is the filtered texture whatever the view)
 * either at x = 0.2, seen in the mirror at x = 3.5, or mirrored to x = 6.8 and seen directly. */
static ref_image textured_view(int mirrored)
{
    ref_scene *s = ref_scene_create();
    int tex = add_stripes(s);
    CHECK(tex == 1);
    ref_scene_set_ambient(s, (float[3]){1, 1, 1});
    float x = mirrored ? 6.8f : 0.2f;
    float pos[12] = {x, -3, -2, x, 7, -2, x, -3, 5, x, 7, 5}, nrm[12] = {0};
    float uv[8] = {0, 0, 40, 0, 0, 30, 40, 30};
    static const uint32_t idx[6] = {0, 1, 3, 0, 3, 2};
    rd_material wall = {.ambient = {1, 1, 1}};
    ref_mesh_desc d = {.positions = pos,
                       .normals = nrm,
                       .uvs = uv,
                       .indices = idx,
                       .vertex_count = 4,
                       .index_count = 6,
                       .material = wall,
                       .texture = tex,
                       .double_sided = 1};
    CHECK(ref_scene_add_mesh(s, &d) == REF_OK);
    if (!mirrored) {
        rd_material mirror = {.reflectivity = 1.0f, .glossiness = 1.0f};
        const float o[3] = {3.5f, -3, -2}, u[3] = {0, 0, 7}, v[3] = {0, 10, 0};
        CHECK(add_rect(s, o, u, v, &mirror, 1) == REF_OK);
    }
    rd_view view = {.eye = {2.0f, 2.0f, 1.5f},
                    .target = {3.5f, 2.6f, 1.2f},
                    .fov_y_deg = 70.0f,
                    .width = W,
                    .height = H,
                    .supersample = 2};
    ref_image img;
    CHECK(ref_render(s, &(ref_render_desc){.view = view}, &img) == REF_OK);
    ref_scene_destroy(s);
    return img;
}

static void check_footprint(void)
{
    ref_image in_mirror = textured_view(0), direct = textured_view(1);
    float worst = 0.0f, spread = 0.0f;
    for (int i = 0; i < 4 * W * H; i++) {
        worst = fmaxf(worst, fabsf(in_mirror.linear[i] - direct.linear[i]));
        spread = fmaxf(spread, fabsf(direct.linear[i] - direct.linear[i % 4]));
    }
    CHECK_MSG(worst < 2e-3f, "mirror vs direct: worst difference %g", (double)worst);
    CHECK_MSG(spread > 0.1f, "the texture should vary across the view (%g)", (double)spread);
    printf("textured wall in a mirror = seen directly, within %.2g\n", (double)worst);
    ref_image_free(&in_mirror);
    ref_image_free(&direct);
}

int main(void)
{
    check_footprint();
    check_panel(MIRROR, (rd_material){.reflectivity = 1.0f, .glossiness = 1.0f}, "mirror");
    check_panel(MIRROR, (rd_material){.reflectivity = 0.25f, .glossiness = 1.0f}, "k_r 0.25");
    check_panel(
        MIRROR,
        (rd_material){.reflectivity = 0.04f, .glossiness = 1.0f, .blend = RD_REFLECT_FRESNEL},
        "fresnel");
    check_panel(PANE, (rd_material){.transparency = 1.0f, .glossiness = 1.0f}, "clear pane");
    check_panel(THICK, (rd_material){.transparency = 1.0f, .glossiness = 1.0f, .ior = 1.5f},
                "refracting glass");
    return check_report("test_ref_mirror");
}
