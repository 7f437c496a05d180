/* The bake (ref/ref_bake.h): the atlas packing, contact occlusion on a floor beside a block,
 * and a partial re-bake that computes only what lies within reach of a change. */
#include "../common/check.h"
#include "ref/ref_bake.h"

#include <stdlib.h>
#include <string.h>

static void test_atlas_pack(void)
{
    enum { N = 60 };
    int w[N], h[N], x[N], y[N], aw, ah;
    unsigned seed = 12345u;
    for (int i = 0; i < N; i++) {
        seed = seed * 1103515245u + 12345u;
        w[i] = 1 + (int)((seed >> 16) % 90);
        seed = seed * 1103515245u + 12345u;
        h[i] = 1 + (int)((seed >> 16) % 70);
    }
    CHECK(ref_atlas_pack(w, h, N, 512, x, y, &aw, &ah));
    CHECK(aw <= 512 && aw % 4 == 0 && ah > 0);
    long long area = 0;
    for (int i = 0; i < N; i++) {
        area += (long long)w[i] * h[i];
        CHECK_MSG(x[i] >= 0 && y[i] >= 0 && x[i] + w[i] <= aw && y[i] + h[i] <= ah,
                  "rectangle %d (%dx%d at %d,%d) outside the %dx%d atlas", i, w[i], h[i], x[i],
                  y[i], aw, ah);
        for (int j = 0; j < i; j++) {
            int apart = x[i] + w[i] <= x[j] || x[j] + w[j] <= x[i] || y[i] + h[i] <= y[j] ||
                        y[j] + h[j] <= y[i];
            CHECK_MSG(apart, "rectangles %d and %d overlap", i, j);
        }
    }
    /* Shelves waste some room, not most of it. */
    CHECK_MSG(area * 2 >= (long long)aw * ah, "%lld texels used of %dx%d", area, aw, ah);
    int wide[1] = {600}, tall[1] = {10};
    CHECK(!ref_atlas_pack(wide, tall, 1, 512, x, y, &aw, &ah));
    int zero[1] = {0};
    CHECK(!ref_atlas_pack(zero, tall, 1, 512, x, y, &aw, &ah));
}

/* A quad of side s centred at c with normal +Z (flip: -Z), as two triangles. */
static void add_quad(ref_scene *s, float cx, float cy, float z, float half, int down)
{
    float p[12] = {cx - half, cy - half, z, cx + half, cy - half, z,
                   cx + half, cy + half, z, cx - half, cy + half, z};
    float nz = down ? -1.0f : 1.0f;
    float n[12] = {0, 0, nz, 0, 0, nz, 0, 0, nz, 0, 0, nz};
    uint32_t up_idx[6] = {0, 1, 2, 0, 2, 3}, down_idx[6] = {0, 2, 1, 0, 3, 2};
    ref_mesh_desc d = {.positions = p,
                       .normals = n,
                       .indices = down ? down_idx : up_idx,
                       .vertex_count = 4,
                       .index_count = 6,
                       .material = {.ambient = {0.8f, 0.8f, 0.8f}, .diffuse = {0.8f, 0.8f, 0.8f}},
                       .background = 1};
    CHECK(ref_scene_add_mesh(s, &d) == REF_OK);
}

/* A closed axis-aligned block standing on z = 0, faces outward, 24 vertices (the four sides
 * first); block_positions keeps the last one's. */
static float block_positions[72];

static void add_block(ref_scene *s, const float lo[3], const float hi[3])
{
    float *p = block_positions, n[72];
    uint32_t idx[36];
    int v = 0, t = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int side = 0; side < 2; side++) {
            int a = (axis + 1) % 3, b = (axis + 2) % 3;
            float sign = side ? 1.0f : -1.0f;
            for (int k = 0; k < 4; k++) {
                float q[3];
                q[axis] = side ? hi[axis] : lo[axis];
                q[a] = (k == 1 || k == 2) ? hi[a] : lo[a];
                q[b] = (k >= 2) ? hi[b] : lo[b];
                for (int c = 0; c < 3; c++) {
                    p[3 * (v + k) + c] = q[c];
                    n[3 * (v + k) + c] = c == axis ? sign : 0.0f;
                }
            }
            /* (a, b) is right-handed about +axis: counter-clockwise seen from outside on +. */
            uint32_t quad_pos[6] = {0, 1, 2, 0, 2, 3}, quad_neg[6] = {0, 2, 1, 0, 3, 2};
            for (int k = 0; k < 6; k++)
                idx[t + k] = (uint32_t)v + (side ? quad_pos[k] : quad_neg[k]);
            v += 4;
            t += 6;
        }
    ref_mesh_desc d = {.positions = p,
                       .normals = n,
                       .indices = idx,
                       .vertex_count = 24,
                       .index_count = 36,
                       .material = {.ambient = {0.7f, 0.7f, 0.7f}, .diffuse = {0.7f, 0.7f, 0.7f}}};
    CHECK(ref_scene_add_mesh(s, &d) == REF_OK);
}

/* Floor (mesh 0), ceiling (mesh 1), a block (mesh 2) at x in [x0, x0 + 0.5] unless x0 is NAN,
 * one point light. */
static ref_scene *make_scene(float x0)
{
    ref_scene *s = ref_scene_create();
    add_quad(s, 0.0f, 0.0f, 0.0f, 2.0f, 0);
    add_quad(s, 0.0f, 0.0f, 2.6f, 2.0f, 1);
    if (!isnan(x0))
        add_block(s, (float[3]){x0, -0.25f, 0.0f}, (float[3]){x0 + 0.5f, 0.25f, 0.5f});
    rd_light l = {.type = RD_LIGHT_POINT,
                  .position = {0.0f, 0.0f, 2.4f},
                  .diffuse = {3.0f, 3.0f, 3.0f},
                  .attenuation = {1.0f, 0.0f, 0.0f}};
    CHECK(ref_scene_add_light(s, &l) == REF_OK);
    return s;
}

/* The stored light (rgb mean; channel 3: the occlusion) at floor point (x, y). */
static float floor_value(const ref_bake *b, float x, float y, int occlusion)
{
    for (int i = 0; i < b->chart_count; i++) {
        const ref_bake_chart *c = &b->charts[i];
        if (c->mesh != 0)
            continue;
        float d[3] = {x - c->origin[0], y - c->origin[1], -c->origin[2]};
        int tx = c->x + 1 + (int)((d[0] * c->u[0] + d[1] * c->u[1] + d[2] * c->u[2]) / c->texel_m);
        int ty = c->y + 1 + (int)((d[0] * c->v[0] + d[1] * c->v[1] + d[2] * c->v[2]) / c->texel_m);
        const float *t = b->atlas + 4 * ((size_t)ty * (size_t)b->atlas_width + (size_t)tx);
        return occlusion ? t[3] : (t[0] + t[1] + t[2]) / 3.0f;
    }
    return -1.0f;
}

static float floor_light(const ref_bake *b, float x, float y)
{
    return floor_value(b, x, y, 0);
}

static void test_contact_and_partial(void)
{
    unsigned char lightmapped[3] = {1, 1, 0};
    ref_scene *s = make_scene(0.8f);
    ref_bake b;
    ref_bake_desc d = {.samples = 64, .threads = 2, .lightmapped = lightmapped};
    CHECK(ref_bake_run(s, &d, &b) == REF_OK);
    CHECK(b.chart_count == 2 && b.atlas && b.meshes[2].kind == REF_BAKE_VERTEX);
    /* 2 cm from the block's side turned from the light, against the same spot without it. */
    ref_scene *empty = make_scene(NAN);
    ref_bake e;
    unsigned char room_only[2] = {1, 1};
    ref_bake_desc ed = {.samples = 64, .threads = 2, .lightmapped = room_only};
    CHECK(ref_bake_run(empty, &ed, &e) == REF_OK);
    float near = floor_light(&b, 1.32f, 0.0f), open = floor_light(&e, 1.32f, 0.0f);
    CHECK_MSG(near > 0.0f && open > 0.0f && near < 0.8f * open,
              "floor beside the block %.4f, open floor %.4f", near, open);
    float near_ao = floor_value(&b, 1.32f, 0.0f, 1), open_ao = floor_value(&e, 1.32f, 0.0f, 1);
    CHECK_MSG(near_ao < 0.8f && open_ao > 0.99f, "occlusion beside the block %.3f, open %.3f",
              near_ao, open_ao);
    /* Under the block the floor sees only the block's inside: those texels take their
     * neighbours' light, so a bilinear lookup beside the block does not read their darkness. */
    float under = floor_light(&b, 1.05f, 0.0f), edge_in = floor_light(&b, 0.82f, 0.0f);
    CHECK_MSG(under > 0.5f * open && edge_in > 0.5f * near,
              "floor under the block %.4f, just inside its edge %.4f (beside %.4f, open %.4f)",
              under, edge_in, near, open);
    ref_bake_free(&e);
    ref_scene_destroy(empty);
    CHECK(b.baked_texels == b.total_texels && b.total_texels > 1000);
    /* The block's side vertices at the floor are in contact: less open than those at its top. */
    float bottom = 0.0f, top = 0.0f;
    for (int v = 0; v < 16; v++) { /* the four sides: 8 vertices at the floor, 8 at the top */
        const float *val = b.meshes[2].vertex + 4 * v;
        *(block_positions[3 * v + 2] == 0.0f ? &bottom : &top) += val[3];
    }
    CHECK_MSG(bottom < 0.8f * top, "occlusion at the block's foot %.3f, at its top %.3f", bottom,
              top);

    /* Move the block by 0.5 m: only what lies within reach of its old and new boxes is baked
     * again, the rest is copied. */
    ref_scene *moved = make_scene(1.3f);
    float boxes[2][6] = {{0.8f, -0.25f, 0.0f, 1.3f, 0.25f, 0.5f},
                         {1.3f, -0.25f, 0.0f, 1.8f, 0.25f, 0.5f}};
    unsigned char keep[3] = {1, 1, 0};
    ref_bake_desc pd = d;
    pd.previous = &b;
    pd.keep = keep;
    pd.dirty_boxes = (const float(*)[6])boxes;
    pd.dirty_box_count = 2;
    pd.reach_m = 0.5f;
    ref_bake b2;
    CHECK(ref_bake_run(moved, &pd, &b2) == REF_OK);
    CHECK_MSG(b2.baked_texels > 0 && b2.baked_texels < b2.total_texels / 2,
              "%lld of %lld texels baked again", b2.baked_texels, b2.total_texels);
    CHECK(b2.baked_vertices == 24);
    CHECK(floor_light(&b2, -1.5f, 1.5f) == floor_light(&b, -1.5f, 1.5f)); /* out of reach */
    float before = floor_light(&b, 0.78f, 0.0f), after = floor_light(&b2, 0.78f, 0.0f);
    CHECK_MSG(after < before, "beside the lit face that left: %.4f, now %.4f", before, after);
    ref_bake_free(&b2);
    ref_bake_free(&b);
    ref_scene_destroy(moved);
    ref_scene_destroy(s);
}

/* A glowing ceiling that stands in for a light (a lamp's shade, a window's exterior) brings the
 * floor the light it reflects, as a ceiling of a faint glow would, and none of its own glow:
 * that comes in through the light it stands for. (Both glow, so neither stores baked light.) */
static void test_stand_in_reflects(void)
{
    float lit[2];
    for (int stand_in = 0; stand_in < 2; stand_in++) {
        ref_scene *s = ref_scene_create();
        add_quad(s, 0.0f, 0.0f, 0.0f, 2.0f, 0);
        float glow = stand_in ? 5.0f : 1e-6f;
        float p[12] = {-2, -2, 2.6f, 2, -2, 2.6f, 2, 2, 2.6f, -2, 2, 2.6f};
        float n[12] = {0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1};
        uint32_t idx[6] = {0, 2, 1, 0, 3, 2};
        ref_mesh_desc d = {.positions = p,
                           .normals = n,
                           .indices = idx,
                           .vertex_count = 4,
                           .index_count = 6,
                           .material = {.ambient = {0.8f, 0.8f, 0.8f},
                                        .diffuse = {0.8f, 0.8f, 0.8f},
                                        .emissive = {glow, glow, glow}},
                           .background = 1,
                           .light_stand_in = stand_in};
        CHECK(ref_scene_add_mesh(s, &d) == REF_OK);
        rd_light l = {.type = RD_LIGHT_POINT,
                      .position = {0.0f, 0.0f, 0.3f},
                      .diffuse = {3.0f, 3.0f, 3.0f},
                      .attenuation = {1.0f, 0.0f, 0.0f}};
        CHECK(ref_scene_add_light(s, &l) == REF_OK);
        unsigned char lightmapped[2] = {1, 0};
        ref_bake b;
        ref_bake_desc bd = {.samples = 64, .threads = 2, .lightmapped = lightmapped};
        CHECK(ref_bake_run(s, &bd, &b) == REF_OK);
        lit[stand_in] = floor_light(&b, 0.5f, 0.5f);
        ref_bake_free(&b);
        ref_scene_destroy(s);
    }
    CHECK_MSG(lit[0] > 0.0f && fabsf(lit[1] - lit[0]) < 0.02f * lit[0],
              "floor under a faintly glowing ceiling %.4f, under a glowing stand-in %.4f", lit[0],
              lit[1]);
}

/* A strip light tilted under a shelf's edge, its centre in the shelf's plane (a mirror light's
 * diffuser over its rectangle light): the shelf's underside is lit by the half of the rectangle
 * below it, as the GPU and the tracer shade it by the clipped form factor, and the floor under
 * the shelf gets that light back. Lowered by a centimetre, the light changes that little; a
 * point light at the centre would light the underside only once the centre is below it. */
static float shelf_bounce(float drop)
{
    ref_scene *s = ref_scene_create();
    add_quad(s, 0.0f, 0.0f, 0.0f, 2.0f, 0);
    float z = 0.5f;
    float p[12] = {-1, -1, z, 1, -1, z, 1, 1, z, -1, 1, z};
    float n[12] = {0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1};
    uint32_t idx[6] = {0, 2, 1, 0, 3, 2};
    ref_mesh_desc d = {.positions = p,
                       .normals = n,
                       .indices = idx,
                       .vertex_count = 4,
                       .index_count = 6,
                       .material = {.diffuse = {0.8f, 0.8f, 0.8f}}};
    CHECK(ref_scene_add_mesh(s, &d) == REF_OK);
    rd_light l = {.type = RD_LIGHT_RECT,
                  .position = {0.9f, 0.0f, z - drop},
                  .direction = {-0.9701425f, 0.0f, -0.2425356f},
                  .diffuse = {5.0f, 5.0f, 5.0f},
                  .half_width = {0.0f, 0.3f, 0.0f},
                  .half_height = {-0.0048507f, 0.0f, 0.0194029f}};
    CHECK(ref_scene_add_light(s, &l) == REF_OK);
    unsigned char lightmapped[2] = {1, 0};
    ref_bake b;
    ref_bake_desc bd = {.samples = 64, .threads = 2, .passes = 1, .lightmapped = lightmapped};
    CHECK(ref_bake_run(s, &bd, &b) == REF_OK);
    float v = floor_light(&b, 0.6f, 0.0f);
    ref_bake_free(&b);
    ref_scene_destroy(s);
    return v;
}

static void test_rect_light_near_field(void)
{
    float level = shelf_bounce(0.0f), lowered = shelf_bounce(0.01f);
    CHECK_MSG(lowered > 0.0f && level > 0.5f * lowered,
              "floor under the shelf: light centre in the shelf's plane %.4f, 1 cm below %.4f",
              level, lowered);
}

int main(void)
{
    test_atlas_pack();
    test_contact_and_partial();
    test_stand_in_reflects();
    test_rect_light_near_field();
    return check_report("test_ref_bake");
}
