/* cat_model_load on the Khronos glTF sample models in shared/gltf-samples (see SOURCES.md there):
 * every sample loads, and concrete facts of each come out as the file says. */
#include "test_util.h"

#ifndef TESSERA_GLTF_SAMPLES
#error "TESSERA_GLTF_SAMPLES must name the sample folder"
#endif

static int load_sample(const char *name, cat_model *m)
{
    char path[4096], err[2048];
    snprintf(path, sizeof path, "%s/%s", TESSERA_GLTF_SAMPLES, name);
    cat_result r = cat_model_load(path, m, err, sizeof err);
    if (r != CAT_OK) {
        fprintf(stderr, "loading %s failed: %s: %s\n", name, cat_result_name(r), err);
        check_failures++;
        return 0;
    }
    if (model_broken(m)) {
        fprintf(stderr, "%s: loaded model breaks the invariants\n", name);
        check_failures++;
    }
    return 1;
}

/* For flat-shaded files: each triangle's winding normal agrees with its vertices' normals, so
 * counter-clockwise is kept through the transforms. */
static void check_winding_matches_normals(const cat_model *m)
{
    for (int i = 0; i < m->mesh_count; i++) {
        const cat_mesh *me = &m->meshes[i];
        for (int t = 0; t < me->index_count; t += 3) {
            const float *a = me->positions + 3 * me->indices[t];
            const float *b = me->positions + 3 * me->indices[t + 1];
            const float *c = me->positions + 3 * me->indices[t + 2];
            double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
            double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
            double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                           e1[0] * e2[1] - e1[1] * e2[0]};
            for (int k = 0; k < 3; k++) {
                const float *vn = me->normals + 3 * me->indices[t + k];
                CHECK(n[0] * vn[0] + n[1] * vn[1] + n[2] * vn[2] > 0.0);
            }
        }
    }
}

static void mesh_bounds(const cat_mesh *me, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = 1e30;
        hi[k] = -1e30;
    }
    for (int v = 0; v < me->vertex_count; v++)
        for (int k = 0; k < 3; k++) {
            double x = me->positions[3 * v + k];
            lo[k] = x < lo[k] ? x : lo[k];
            hi[k] = x > hi[k] ? x : hi[k];
        }
}

static void test_box(void)
{
    cat_model m;
    if (!load_sample("Box.gltf", &m))
        return;
    CHECK(m.mesh_count == 1);
    /* A unit cube: 1000 mm on every side, centred; the node's Z-up->Y-up matrix and our
     * Y-up->Z-up conversion cancel, so the mesh's raw +-0.5 m lands on +-500 mm exactly. */
    for (int k = 0; k < 3; k++) {
        CHECK_NEAR(m.bounds_min[k], -500.0, 1e-3);
        CHECK_NEAR(m.bounds_max[k], 500.0, 1e-3);
    }
    CHECK(m.meshes[0].vertex_count == 24);
    CHECK(m.meshes[0].index_count == 36);
    CHECK(m.meshes[0].uvs == NULL);
    CHECK(m.meshes[0].material == 0);
    CHECK(m.material_count == 1);
    CHECK_NEAR(m.materials[0].base_color[0], 0.800000011920929, 1e-7);
    CHECK_NEAR(m.materials[0].base_color[1], 0.0, 0);
    CHECK_NEAR(m.materials[0].base_color[2], 0.0, 0);
    CHECK_NEAR(m.materials[0].base_color[3], 1.0, 0);
    CHECK_NEAR(m.materials[0].metallic, 1.0, 0); /* defaults */
    CHECK_NEAR(m.materials[0].roughness, 1.0, 0);
    CHECK(m.materials[0].base_color_texture[0] == '\0');
    /* File normals of a cube face: each normal is an axis, and the face lies 500 mm out. */
    const cat_mesh *me = &m.meshes[0];
    for (int v = 0; v < me->vertex_count; v++) {
        const float *p = me->positions + 3 * v, *n = me->normals + 3 * v;
        CHECK_NEAR(p[0] * n[0] + p[1] * n[1] + p[2] * n[2], 500.0, 1e-3);
    }
    check_winding_matches_normals(&m);
    cat_model_free(&m);
    CHECK(m.meshes == NULL && m.mesh_count == 0);
    cat_model_free(&m); /* twice is fine */
}

static void test_simple_meshes(void)
{
    cat_model m;
    if (!load_sample("SimpleMeshes.gltf", &m))
        return;
    /* One triangle (0,0,0) (1,0,0) (0,1,0) with normal +Z, placed by two nodes, the second
     * translated by +1 m along X. glTF +Y is our +Z, glTF +Z is our -Y. */
    CHECK(m.mesh_count == 2);
    CHECK(m.material_count == 0);
    if (m.mesh_count == 2) {
        const cat_mesh *a = &m.meshes[0], *b = &m.meshes[1];
        CHECK(a->vertex_count == 3 && b->vertex_count == 3);
        CHECK(a->material == -1 && b->material == -1);
        for (int v = 0; v < 3 && b->vertex_count == 3; v++) {
            CHECK_NEAR(b->positions[3 * v], a->positions[3 * v] + 1000.0, 1e-3);
            CHECK_NEAR(b->positions[3 * v + 1], a->positions[3 * v + 1], 0);
            CHECK_NEAR(b->positions[3 * v + 2], a->positions[3 * v + 2], 0);
            CHECK_NEAR(a->normals[3 * v + 0], 0.0, 1e-6);
            CHECK_NEAR(a->normals[3 * v + 1], -1.0, 1e-6);
            CHECK_NEAR(a->normals[3 * v + 2], 0.0, 1e-6);
        }
        CHECK_NEAR(a->positions[3], 1000.0, 1e-3);     /* glTF (1,0,0) */
        CHECK_NEAR(a->positions[6 + 2], 1000.0, 1e-3); /* glTF (0,1,0) -> Z up */
    }
    const float lo[3] = {0, 0, 0}, hi[3] = {2000, 0, 1000};
    for (int k = 0; k < 3; k++) {
        CHECK_NEAR(m.bounds_min[k], lo[k], 1e-3);
        CHECK_NEAR(m.bounds_max[k], hi[k], 1e-3);
    }
    check_winding_matches_normals(&m);
    cat_model_free(&m);
}

static void test_cameras(void)
{
    cat_model m;
    if (!load_sample("Cameras.gltf", &m))
        return;
    /* A unit quad in glTF's XY plane rotated -45 degrees about X; no normals in the file. */
    CHECK(m.mesh_count == 1);
    CHECK_NEAR(m.bounds_min[0], 0.0, 1e-3);
    CHECK_NEAR(m.bounds_max[0], 1000.0, 1e-3);
    CHECK_NEAR(m.bounds_min[1], 0.0, 1e-3);
    CHECK_NEAR(m.bounds_max[1], 707.1, 0.5);
    CHECK_NEAR(m.bounds_min[2], 0.0, 1e-3);
    CHECK_NEAR(m.bounds_max[2], 707.1, 0.5);
    if (m.mesh_count == 1) {
        const cat_mesh *me = &m.meshes[0];
        CHECK(me->vertex_count == 4 && me->index_count == 6);
        for (int v = 0; v < me->vertex_count; v++) { /* generated: the quad's facing side */
            CHECK_NEAR(me->normals[3 * v + 0], 0.0, 1e-3);
            CHECK_NEAR(me->normals[3 * v + 1], -0.7071, 1e-3);
            CHECK_NEAR(me->normals[3 * v + 2], 0.7071, 1e-3);
        }
    }
    cat_model_free(&m);
}

static void test_box_textured(void)
{
    cat_model m;
    if (!load_sample("BoxTextured.gltf", &m))
        return;
    CHECK(m.mesh_count == 1);
    CHECK(m.material_count == 1);
    if (m.mesh_count == 1)
        CHECK(m.meshes[0].uvs != NULL);
    if (m.material_count == 1) {
        CHECK(m.materials[0].base_color_texture[0] == '\0'); /* embedded PNG */
        for (int k = 0; k < 4; k++)
            CHECK_NEAR(m.materials[0].base_color[k], 1.0, 0);
    }
    for (int k = 0; k < 3; k++) {
        CHECK_NEAR(m.bounds_min[k], -500.0, 1e-3);
        CHECK_NEAR(m.bounds_max[k], 500.0, 1e-3);
    }
    check_winding_matches_normals(&m);
    cat_model_free(&m);
}

static void test_box_vertex_colors(void)
{
    cat_model m;
    if (!load_sample("BoxVertexColors.gltf", &m))
        return;
    CHECK(m.mesh_count == 1);
    CHECK(m.material_count == 1);
    if (m.material_count == 1) {
        CHECK(strcmp(m.materials[0].name, "Default") == 0);
        CHECK_NEAR(m.materials[0].metallic, 0.100000001490116, 1e-7);
        CHECK_NEAR(m.materials[0].roughness, 0.990000005960464, 1e-7);
        CHECK_NEAR(m.materials[0].base_color[0], 0.800000011920929, 1e-7);
    }
    for (int k = 0; k < 3; k++) {
        CHECK_NEAR(m.bounds_min[k], -500.0, 1e-3);
        CHECK_NEAR(m.bounds_max[k], 500.0, 1e-3);
    }
    cat_model_free(&m);
}

/* OrientationTest: six arrows, each placed by a node (TRS with a quaternion, or a column-major
 * matrix), must point from their node's origin at a target whose vertices are baked in place.
 * The scene lists nodes 5 12 10 3 1 8 11 4 7 0 9 2 6, one primitive each, so the baked meshes
 * come in that order. A transposed matrix or an inverted quaternion turns the arrow away. */
static void test_orientation(void)
{
    cat_model m;
    if (!load_sample("OrientationTest.gltf", &m))
        return;
    CHECK(m.mesh_count == 13);
    CHECK(m.material_count == 7);
    if (m.mesh_count != 13) {
        cat_model_free(&m);
        return;
    }
    struct {
        const char *name;
        int arrow, target;
        double origin[3]; /* node translation, glTF metres */
        int material;
    } arrows[] = {
        {"ArrowX1 (TRS)", 9, 8, {5, 0, 0}, 1},   {"ArrowX2 (matrix)", 4, 5, {-5, 0, 0}, 2},
        {"ArrowY1 (TRS)", 11, 10, {0, 5, 0}, 3}, {"ArrowY2 (matrix)", 3, 2, {0, -5, 0}, 4},
        {"ArrowZ1 (TRS)", 7, 6, {0, 0, 5}, 5},   {"ArrowZ2 (matrix)", 0, 1, {0, 0, -5}, 6},
    };
    for (size_t i = 0; i < sizeof arrows / sizeof arrows[0]; i++) {
        /* node origin in our space: (x, -z, y) * 1000 */
        double o[3] = {arrows[i].origin[0] * 1000, -arrows[i].origin[2] * 1000,
                       arrows[i].origin[1] * 1000};
        const cat_mesh *arrow = &m.meshes[arrows[i].arrow];
        const cat_mesh *target = &m.meshes[arrows[i].target];
        CHECK(arrow->material == arrows[i].material);
        CHECK(target->material == arrows[i].material);
        /* the arrow's tip: its vertex farthest from the node origin */
        double tip[3] = {0, 0, 0}, best = -1;
        for (int v = 0; v < arrow->vertex_count; v++) {
            const float *p = arrow->positions + 3 * v;
            double d = (p[0] - o[0]) * (p[0] - o[0]) + (p[1] - o[1]) * (p[1] - o[1]) +
                       (p[2] - o[2]) * (p[2] - o[2]);
            if (d > best) {
                best = d;
                for (int k = 0; k < 3; k++)
                    tip[k] = p[k] - o[k];
            }
        }
        double lo[3], hi[3], to[3];
        mesh_bounds(target, lo, hi);
        for (int k = 0; k < 3; k++)
            to[k] = (lo[k] + hi[k]) / 2 - o[k];
        double lt = sqrt(tip[0] * tip[0] + tip[1] * tip[1] + tip[2] * tip[2]);
        double lg = sqrt(to[0] * to[0] + to[1] * to[1] + to[2] * to[2]);
        double cosine = (tip[0] * to[0] + tip[1] * to[1] + tip[2] * to[2]) / (lt * lg);
        if (!(cosine > 0.988)) { /* right: 0.9935 for all six; a transposed matrix: < 0.98 */
            fprintf(stderr, "%s points away from its target (cosine %.4f)\n", arrows[i].name,
                    cosine);
            check_failures++;
        }
    }
    /* The base cube: 10 m, centred at the origin. */
    double lo[3], hi[3];
    mesh_bounds(&m.meshes[12], lo, hi);
    for (int k = 0; k < 3; k++) {
        CHECK_NEAR(lo[k], -5000.0, 0.01);
        CHECK_NEAR(hi[k], 5000.0, 0.01);
    }
    CHECK(strcmp(m.materials[0].name, "BaseMaterial") == 0);
    CHECK_NEAR(m.materials[0].roughness, 0.5, 0);
    cat_model_free(&m);
}

static void test_texture_coordinates(void)
{
    cat_model m;
    if (!load_sample("TextureCoordinateTest.gltf", &m))
        return;
    CHECK(m.mesh_count == 5);
    CHECK(m.material_count == 5);
    int with_uvs = 0;
    for (int i = 0; i < m.mesh_count; i++)
        with_uvs += m.meshes[i].uvs != NULL;
    CHECK(with_uvs == 4);
    if (m.material_count == 5) {
        /* BottomRightMaterial tints green */
        CHECK(strcmp(m.materials[1].name, "BottomRightMaterial") == 0);
        CHECK_NEAR(m.materials[1].base_color[0], 0.0, 0);
        CHECK_NEAR(m.materials[1].base_color[1], 1.0, 0);
    }
    cat_model_free(&m);
}

static void test_rigged_simple(void)
{
    cat_model m;
    if (!load_sample("RiggedSimple.gltf", &m))
        return;
    CHECK(m.mesh_count == 1); /* skin ignored: the cylinder in its bind shape */
    CHECK(m.material_count == 1);
    if (m.material_count == 1)
        CHECK(strcmp(m.materials[0].name, "Material_001-effect") == 0);
    CHECK(m.bounds_max[0] > m.bounds_min[0]);
    cat_model_free(&m);
}

int main(void)
{
    test_box();
    test_simple_meshes();
    test_cameras();
    test_box_textured();
    test_box_vertex_colors();
    test_orientation();
    test_texture_coordinates();
    test_rigged_simple();
    return check_report("test_model_samples");
}
