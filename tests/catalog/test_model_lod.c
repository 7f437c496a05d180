/* catalog/mesh_lod.h: validation counts and refusals, and levels of detail by OpenMesh's
 * quadric decimation on dense meshes made here (a UV sphere with a split seam, a torus) and on
 * the Khronos sample models in ../shared/gltf-samples. */
#include "test_util.h"

#include "catalog/mesh_lod.h"

#include <time.h>

#define PI 3.14159265358979323846

/* A UV sphere of radius r (mm): (rings + 1) x (segments + 1) vertices, the seam and the poles
 * split the way glTF exporters split them, normals pointing out, UVs. */
static cat_mesh sphere(float r, int segments, int rings)
{
    cat_mesh m;
    memset(&m, 0, sizeof m);
    m.vertex_count = (rings + 1) * (segments + 1);
    m.index_count = 6 * rings * segments;
    m.positions = malloc(3 * sizeof(float) * (size_t)m.vertex_count);
    m.normals = malloc(3 * sizeof(float) * (size_t)m.vertex_count);
    m.uvs = malloc(2 * sizeof(float) * (size_t)m.vertex_count);
    m.indices = malloc(sizeof(unsigned) * (size_t)m.index_count);
    m.material = -1;
    int v = 0, i = 0;
    for (int y = 0; y <= rings; y++)
        for (int x = 0; x <= segments; x++, v++) {
            double th = PI * y / rings, ph = 2 * PI * (x % segments) / segments;
            double st = y == 0 || y == rings ? 0.0 : sin(th); /* poles: one point exactly */
            double n[3] = {st * cos(ph), st * sin(ph), y == rings ? -1.0 : cos(th)};
            for (int k = 0; k < 3; k++) {
                m.normals[3 * v + k] = (float)n[k];
                m.positions[3 * v + k] = (float)(r * n[k]);
            }
            m.uvs[2 * v] = (float)x / (float)segments;
            m.uvs[2 * v + 1] = (float)y / (float)rings;
        }
    for (int y = 0; y < rings; y++)
        for (int x = 0; x < segments; x++) {
            unsigned a = (unsigned)(y * (segments + 1) + x), b = a + 1;
            unsigned c = a + (unsigned)segments + 1, d = c + 1;
            /* counter-clockwise seen from outside; the pole rows give degenerate triangles */
            unsigned t[6] = {a, c, b, b, c, d};
            memcpy(m.indices + i, t, sizeof t);
            i += 6;
        }
    return m;
}

/* A torus around Z: major radius R, tube radius r, no seams split (indices wrap). */
static cat_mesh torus(float R, float r, int segments, int sides)
{
    cat_mesh m;
    memset(&m, 0, sizeof m);
    m.vertex_count = segments * sides;
    m.index_count = 6 * segments * sides;
    m.positions = malloc(3 * sizeof(float) * (size_t)m.vertex_count);
    m.normals = malloc(3 * sizeof(float) * (size_t)m.vertex_count);
    m.indices = malloc(sizeof(unsigned) * (size_t)m.index_count);
    m.material = 0;
    for (int s = 0; s < segments; s++)
        for (int t = 0; t < sides; t++) {
            double u = 2 * PI * s / segments, w = 2 * PI * t / sides;
            double n[3] = {cos(w) * cos(u), cos(w) * sin(u), sin(w)};
            int v = s * sides + t;
            m.positions[3 * v] = (float)((R + r * cos(w)) * cos(u));
            m.positions[3 * v + 1] = (float)((R + r * cos(w)) * sin(u));
            m.positions[3 * v + 2] = (float)(r * sin(w));
            for (int k = 0; k < 3; k++)
                m.normals[3 * v + k] = (float)n[k];
        }
    int i = 0;
    for (int s = 0; s < segments; s++)
        for (int t = 0; t < sides; t++) {
            unsigned a = (unsigned)(s * sides + t);
            unsigned b = (unsigned)(((s + 1) % segments) * sides + t);
            unsigned c = (unsigned)(s * sides + (t + 1) % sides);
            unsigned d = (unsigned)(((s + 1) % segments) * sides + (t + 1) % sides);
            unsigned tri[6] = {a, b, d, a, d, c};
            memcpy(m.indices + i, tri, sizeof tri);
            i += 6;
        }
    return m;
}

static cat_model model_of(cat_mesh *meshes, int n)
{
    cat_model m;
    memset(&m, 0, sizeof m);
    m.meshes = malloc(sizeof *meshes * (size_t)n);
    memcpy(m.meshes, meshes, sizeof *meshes * (size_t)n);
    m.mesh_count = n;
    m.materials = calloc(1, sizeof *m.materials);
    m.material_count = 1;
    return m;
}

/* Bounds over the vertices that triangles use. */
static void used_bounds(const cat_model *m, float lo[3], float hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (int i = 0; i < m->mesh_count; i++)
        for (int t = 0; t < m->meshes[i].index_count; t++)
            for (int k = 0; k < 3; k++) {
                float p = m->meshes[i].positions[3 * m->meshes[i].indices[t] + (unsigned)k];
                lo[k] = fminf(lo[k], p);
                hi[k] = fmaxf(hi[k], p);
            }
}

/* The LOD keeps the bounding box within tol_rel of the largest extent (vertices on the box are
 * locked, so exactly), its triangle count within
 * 10 % of the target, every mesh valid and closed meshes closed, unit normals. */
static void check_lod(const char *name, const cat_model *in, float fraction, float tol_rel)
{
    cat_model out;
    char err[512] = "";
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    cat_result r = cat_model_make_lod(in, fraction, &out, err, sizeof err);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double ms = 1e3 * (double)(t1.tv_sec - t0.tv_sec) + 1e-6 * (double)(t1.tv_nsec - t0.tv_nsec);
    CHECK(r == CAT_OK);
    if (r != CAT_OK) {
        fprintf(stderr, "%s: %s\n", name, err);
        return;
    }
    CHECK(out.mesh_count == in->mesh_count && out.material_count == in->material_count);
    float lo[3], hi[3], lo2[3], hi2[3];
    used_bounds(in, lo, hi);
    used_bounds(&out, lo2, hi2);
    float extent = fmaxf(fmaxf(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
    for (int k = 0; k < 3; k++) {
        CHECK_NEAR(lo2[k], lo[k], tol_rel * extent);
        CHECK_NEAR(hi2[k], hi[k], tol_rel * extent);
        CHECK_NEAR(out.bounds_min[k], lo2[k], 1e-3);
        CHECK_NEAR(out.bounds_max[k], hi2[k], 1e-3);
    }
    long before = 0, after = cat_model_triangle_count(&out), target = 0;
    for (int i = 0; i < in->mesh_count; i++) {
        long tris = in->meshes[i].index_count / 3;
        long t = (long)ceil(fraction * (double)tris);
        target += t < CAT_LOD_MIN_TRIANGLES ? (tris < CAT_LOD_MIN_TRIANGLES ? tris : 8) : t;
        before += tris;
    }
    printf("%s at %.0f %%: %ld -> %ld triangles (target %ld) in %.1f ms; bounds [%.2f %.2f "
           "%.2f]-[%.2f %.2f "
           "%.2f] vs [%.2f %.2f %.2f]-[%.2f %.2f %.2f]\n",
           name, 100.0 * fraction, before, after, target, ms, lo2[0], lo2[1], lo2[2], hi2[0],
           hi2[1], hi2[2], lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    CHECK(after >= (long)(0.9 * (double)target) && after <= (long)(1.1 * (double)target) + 2);
    cat_mesh_report rep, rep_in;
    CHECK(cat_model_validate(&out, name, 0, &rep, err, sizeof err) == CAT_OK);
    CHECK(cat_model_validate((cat_model *)in, name, 0, &rep_in, err, sizeof err) == CAT_OK);
    CHECK(rep.non_manifold_edges <= rep_in.non_manifold_edges);
    if (rep_in.open_edges == 0)
        CHECK(rep.open_edges == 0);
    /* decimation drops degenerate triangles; fraction 1 is a plain copy */
    CHECK(rep.degenerate_triangles == (fraction < 1.0f ? 0 : rep_in.degenerate_triangles));
    for (int i = 0; i < out.mesh_count; i++)
        for (int v = 0; v < out.meshes[i].vertex_count; v++) {
            const float *n = out.meshes[i].normals + 3 * v;
            CHECK_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-3);
        }
    cat_model_free(&out);
}

static void test_dense_shapes(void)
{
    /* 4 864 triangles: dense enough for the decimator to choose, small enough for ASan */
    enum { SEGMENTS = 48 };
    cat_mesh parts[2] = {sphere(250.0f, SEGMENTS, 24), torus(300.0f, 60.0f, 64, 20)};
    cat_model m = model_of(parts, 2);
    cat_mesh_report rep;
    char err[512];
    CHECK(cat_model_validate(&m, "shapes", 0, &rep, err, sizeof err) == CAT_OK);
    /* two pole rows of the sphere are degenerate; welded, both shapes are closed manifolds */
    CHECK(rep.degenerate_triangles == 2 * SEGMENTS);
    CHECK(rep.open_edges == 0);
    CHECK(rep.non_manifold_edges == 0);
    check_lod("sphere+torus", &m, 0.5f, 1e-6f);
    check_lod("sphere+torus", &m, 0.15f, 1e-6f);
    check_lod("sphere+torus", &m, 1.0f, 0.0f);
    /* a repair drops the degenerate triangles and nothing else */
    long before = cat_model_triangle_count(&m);
    CHECK(cat_model_validate(&m, "shapes", 1, &rep, err, sizeof err) == CAT_OK);
    CHECK(rep.removed_triangles == 2 * SEGMENTS);
    CHECK(cat_model_triangle_count(&m) == before - 2 * SEGMENTS);
    CHECK(cat_model_validate(&m, "shapes", 0, &rep, err, sizeof err) == CAT_OK);
    CHECK(rep.degenerate_triangles == 0);
    cat_model_free(&m);
}

/* Three triangles on one edge: one non-manifold edge; the LOD passes what OpenMesh refuses. */
static void test_non_manifold(void)
{
    static const float p[] = {0, 0, 0, 100, 0, 0, 50, 80, 0, 50, -80, 0, 50, 0, 80};
    static const unsigned idx[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    cat_mesh me;
    memset(&me, 0, sizeof me);
    me.vertex_count = 5;
    me.index_count = 9;
    me.positions = malloc(sizeof p);
    me.indices = malloc(sizeof idx);
    me.normals = calloc(15, sizeof(float));
    memcpy(me.positions, p, sizeof p);
    memcpy(me.indices, idx, sizeof idx);
    for (int v = 0; v < 5; v++)
        me.normals[3 * v + 2] = 1;
    cat_model m = model_of(&me, 1);
    cat_mesh_report rep;
    char err[512];
    CHECK(cat_model_validate(&m, "fin", 0, &rep, err, sizeof err) == CAT_OK);
    CHECK(rep.non_manifold_edges == 1);
    CHECK(rep.open_edges == 6);
    cat_model out;
    CHECK(cat_model_make_lod(&m, 0.5f, &out, err, sizeof err) == CAT_OK);
    CHECK(cat_model_triangle_count(&out) == 3); /* below the minimum: kept */
    cat_model_free(&out);
    cat_model_free(&m);
}

/* What no mesh may hold is refused, each with its own message. */
static void test_hostile_meshes(void)
{
    cat_mesh parts[1] = {sphere(100.0f, 16, 8)};
    cat_model m = model_of(parts, 1);
    cat_model out;
    char err[512];
    cat_mesh_report rep;
    m.meshes[0].positions[7] = NAN;
    CHECK(cat_model_make_lod(&m, 0.5f, &out, err, sizeof err) == CAT_ERR_INVALID);
    CHECK(strstr(err, "mesh 0: a position is not a finite number (NaN or Inf)") != NULL);
    CHECK(out.meshes == NULL && out.mesh_count == 0);
    CHECK(cat_model_validate(&m, "nan.glb", 0, &rep, err, sizeof err) == CAT_ERR_INVALID);
    CHECK(strstr(err, "nan.glb: mesh 0: a position is not a finite number") != NULL);
    m.meshes[0].positions[7] = 1.0f;
    m.meshes[0].normals[4] = INFINITY;
    CHECK(cat_model_validate(&m, "inf.glb", 0, &rep, err, sizeof err) == CAT_ERR_INVALID);
    CHECK(strstr(err, "a normal is not a finite number") != NULL);
    m.meshes[0].normals[4] = 0.0f;
    m.meshes[0].uvs[3] = NAN;
    CHECK(cat_model_validate(&m, "uv.glb", 0, &rep, err, sizeof err) == CAT_ERR_INVALID);
    CHECK(strstr(err, "a texture coordinate is not a finite number") != NULL);
    m.meshes[0].uvs[3] = 0.0f;
    m.meshes[0].indices[5] = 100000;
    CHECK(cat_model_make_lod(&m, 0.5f, &out, err, sizeof err) == CAT_ERR_INVALID);
    CHECK(strstr(err, "index 100000 (element 5) is out of range (153 vertices)") != NULL);
    m.meshes[0].indices[5] = 0;
    m.meshes[0].index_count -= 1;
    CHECK(cat_model_validate(&m, "odd.glb", 0, &rep, err, sizeof err) == CAT_ERR_INVALID);
    CHECK(strstr(err, "indices do not make whole triangles") != NULL);
    m.meshes[0].index_count += 1;
    CHECK(cat_model_make_lod(&m, 0.0f, &out, err, sizeof err) == CAT_ERR_INVALID);
    CHECK(strstr(err, "fraction 0 is not in (0, 1]") != NULL);
    CHECK(cat_model_make_lod(&m, NAN, &out, err, sizeof err) == CAT_ERR_INVALID);
    CHECK(cat_model_make_lod(NULL, 0.5f, &out, err, sizeof err) == CAT_ERR_INVALID);
    CHECK(cat_model_make_lod(&m, 0.5f, &out, err, sizeof err) == CAT_OK);
    cat_model_free(&out);
    cat_model_free(&m);
}

/* Real files: the Khronos samples load, validate and decimate within a millimetre. */
static void test_samples(void)
{
    static const char *const names[] = {"Box.gltf", "BoxTextured.gltf", "RiggedSimple.gltf",
                                        "SimpleMeshes.gltf", "OrientationTest.gltf"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        char path[4096], err[1024];
        snprintf(path, sizeof path, "%s/%s", TESSERA_GLTF_SAMPLES, names[i]);
        cat_model m, out;
        cat_result r = cat_model_load(path, &m, err, sizeof err);
        CHECK(r == CAT_OK);
        if (r != CAT_OK) {
            fprintf(stderr, "%s\n", err);
            continue;
        }
        cat_mesh_report rep;
        CHECK(cat_model_validate(&m, path, 0, &rep, err, sizeof err) == CAT_OK);
        printf("%s: %ld triangles, %ld degenerate, %ld non-manifold edges, %ld open edges\n",
               names[i], rep.triangles, rep.degenerate_triangles, rep.non_manifold_edges,
               rep.open_edges);
        CHECK(rep.triangles > 0);
        CHECK(cat_model_make_lod(&m, 0.5f, &out, err, sizeof err) == CAT_OK);
        for (int k = 0; k < 3; k++) { /* vertices on the box are locked: exact */
            CHECK_NEAR(out.bounds_min[k], m.bounds_min[k], 1e-3);
            CHECK_NEAR(out.bounds_max[k], m.bounds_max[k], 1e-3);
        }
        CHECK(cat_model_triangle_count(&out) <= cat_model_triangle_count(&m));
        cat_model_free(&out);
        cat_model_free(&m);
    }
}

int main(void)
{
    test_dense_shapes();
    test_non_manifold();
    test_hostile_meshes();
    test_samples();
    return check_report("test_model_lod");
}
