/* cat_model_load on files made here: a hand-assembled GLB, external buffers and images, topology
 * conversion, mirroring, sparse accessors, generated normals; and one bad file per error, each
 * refused with its result code and a message naming the file and the problem. */
#include "test_util.h"

#include <stdint.h>

/* A glTF JSON text whose buffer 0 is the given bytes as a data: URI. body holds the rest of the
 * top-level object (without braces) and one %s for the buffer's byteLength and URI. */
static char *gltf_with_buffer(const char *body_fmt, const void *bin, size_t size)
{
    char *b64 = base64(bin, size);
    size_t cap = strlen(body_fmt) + strlen(b64) + 256;
    char *buffer = malloc(cap);
    snprintf(buffer, cap,
             "{\"byteLength\":%zu,\"uri\":\"data:application/octet-stream;base64,%s\"}", size, b64);
    char *json = malloc(cap + 256);
    snprintf(json, cap + 256, body_fmt, buffer);
    free(b64);
    free(buffer);
    return json;
}

static const char *write_gltf(const char *name, const char *body_fmt, const void *bin, size_t size)
{
    char *json = gltf_with_buffer(body_fmt, bin, size);
    const char *path = write_text(name, json);
    free(json);
    return path;
}

#define ASSET "\"asset\":{\"version\":\"2.0\"}"

/* A triangle list body: POSITION accessor 0 (count %d given), indices accessor 1 (u16). */
static const char triangle_body[] =
    "{" ASSET ",\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
    "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
    "\"buffers\":[%s],"
    "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},"
    "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6}],"
    "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":COUNT,\"type\":\"VEC3\"},"
    "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]}";

/* triangle_body with COUNT replaced. */
static char *triangle_fmt(int count)
{
    static char buf[2048];
    const char *at = strstr(triangle_body, "COUNT");
    snprintf(buf, sizeof buf, "%.*s%d%s", (int)(at - triangle_body), triangle_body, count, at + 5);
    return buf;
}

static void test_glb(void)
{
    size_t size;
    unsigned char *glb = one_triangle_glb(&size);
    /* a .bin name: the format is told by content, not by extension */
    const char *path = write_file("triangle.bin", glb, size);
    cat_model m;
    char err[1024];
    cat_result r = cat_model_load(path, &m, err, sizeof err);
    CHECK(r == CAT_OK);
    if (r != CAT_OK) {
        fprintf(stderr, "%s\n", err);
        free(glb);
        return;
    }
    CHECK(model_broken(&m) == 0);
    CHECK(m.mesh_count == 1 && m.material_count == 1);
    const cat_mesh *me = &m.meshes[0];
    CHECK(me->vertex_count == 3 && me->index_count == 3 && me->uvs == NULL);
    CHECK(me->indices[0] == 0 && me->indices[1] == 1 && me->indices[2] == 2);
    /* glTF (1,0,0) -> (1000,0,0); glTF (0,1,0) -> (0,0,1000) */
    CHECK_NEAR(me->positions[3], 1000.0, 0);
    CHECK_NEAR(me->positions[8], 1000.0, 0);
    for (int v = 0; v < 3; v++) { /* generated, facing glTF +Z = our -Y */
        CHECK_NEAR(me->normals[3 * v], 0.0, 1e-6);
        CHECK_NEAR(me->normals[3 * v + 1], -1.0, 1e-6);
        CHECK_NEAR(me->normals[3 * v + 2], 0.0, 1e-6);
    }
    CHECK(strcmp(m.materials[0].name, "glb red") == 0);
    CHECK_NEAR(m.materials[0].base_color[1], 0.25, 0);
    CHECK_NEAR(m.materials[0].metallic, 0.0, 0);
    CHECK_NEAR(m.materials[0].roughness, 0.5, 0);
    CHECK_NEAR(m.bounds_max[0], 1000.0, 0);
    CHECK_NEAR(m.bounds_max[1], 0.0, 0);
    CHECK_NEAR(m.bounds_max[2], 1000.0, 0);
    cat_model_free(&m);
    free(glb);
}

static void test_external_files(void)
{
    unsigned char bin[44];
    one_triangle_bin(bin);
    char dir[4200];
    snprintf(dir, sizeof dir, "%s/ext", g_tmp);
    mkdir(dir, 0700);
    snprintf(dir, sizeof dir, "%s/ext/sub", g_tmp);
    mkdir(dir, 0700);
    write_file("ext/sub/tri angle.bin", bin, sizeof bin);
    const char *path = write_text(
        "ext/model.gltf",
        "{" ASSET ",\"nodes\":[{\"mesh\":0}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,"
        "\"material\":0}]}],"
        "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}],"
        "\"textures\":[{\"source\":1}],"
        "\"images\":[{\"uri\":\"data:image/png;base64,iVBORw0KGgo=\"},"
        "{\"uri\":\"sub/../tex%20a.png\"}],"
        "\"buffers\":[{\"byteLength\":44,\"uri\":\"./sub/tri%20angle.bin\"}],"
        "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},"
        "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6}],"
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
        "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]}");
    cat_model m;
    char err[1024];
    cat_result r = cat_model_load(path, &m, err, sizeof err);
    CHECK(r == CAT_OK);
    if (r != CAT_OK) {
        fprintf(stderr, "%s\n", err);
        return;
    }
    CHECK(model_broken(&m) == 0);
    CHECK(m.mesh_count == 1 && m.material_count == 1);
    char *real = realpath(g_tmp, NULL);
    char expect[4300];
    snprintf(expect, sizeof expect, "%s/ext/tex a.png", real);
    free(real);
    CHECK(strcmp(m.materials[0].base_color_texture, expect) == 0);
    if (strcmp(m.materials[0].base_color_texture, expect) != 0)
        fprintf(stderr, "texture path \"%s\", expected \"%s\"\n", m.materials[0].base_color_texture,
                expect);
    cat_model_free(&m);
}

/* A strip of 4 vertices and a fan of 4 vertices, non-indexed. */
static void test_strip_and_fan(void)
{
    const float pos[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    const char *path = write_gltf(
        "strip.gltf",
        "{" ASSET ",\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":["
        "{\"attributes\":{\"POSITION\":0},\"mode\":5},{\"attributes\":{\"POSITION\":0},"
        "\"mode\":6},{\"attributes\":{\"POSITION\":0},\"mode\":0},"
        "{\"attributes\":{\"POSITION\":0},\"mode\":3}]}],"
        "\"buffers\":[%s],\"bufferViews\":[{\"buffer\":0,\"byteLength\":48}],"
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"}]}",
        pos, sizeof pos);
    cat_model m;
    char err[1024];
    cat_result r = cat_model_load(path, &m, err, sizeof err);
    CHECK(r == CAT_OK);
    if (r != CAT_OK) {
        fprintf(stderr, "%s\n", err);
        return;
    }
    CHECK(model_broken(&m) == 0);
    CHECK(m.mesh_count == 2); /* points and line strip skipped */
    if (m.mesh_count == 2) {
        const unsigned strip[6] = {0, 1, 2, 1, 3, 2}, fan[6] = {1, 2, 0, 2, 3, 0};
        CHECK(m.meshes[0].index_count == 6 && m.meshes[1].index_count == 6);
        for (int i = 0; i < 6; i++) {
            CHECK(m.meshes[0].indices[i] == strip[i]);
            CHECK(m.meshes[1].indices[i] == fan[i]);
        }
    }
    cat_model_free(&m);
}

/* 8 corners of the unit cube [0,1]^3, 12 counter-clockwise (outward) triangles, no normals. */
static const float cube_pos[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                   0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
static const unsigned short cube_idx[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                            1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

static void check_cube_normals_outward(const char *name, const char *node)
{
    unsigned char bin[96 + 72];
    memcpy(bin, cube_pos, sizeof cube_pos);
    memcpy(bin + 96, cube_idx, sizeof cube_idx);
    char fmt[2048];
    snprintf(fmt, sizeof fmt,
             "{" ASSET ",\"scenes\":[{\"nodes\":[0]}],\"nodes\":[%s],"
             "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
             "\"buffers\":[%%s],\"bufferViews\":[{\"buffer\":0,\"byteLength\":96},"
             "{\"buffer\":0,\"byteOffset\":96,\"byteLength\":72}],"
             "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":8,\"type\":"
             "\"VEC3\"},{\"bufferView\":1,\"componentType\":5123,\"count\":36,\"type\":"
             "\"SCALAR\"}]}",
             node);
    const char *path = write_gltf(name, fmt, bin, sizeof bin);
    cat_model m;
    char err[1024];
    cat_result r = cat_model_load(path, &m, err, sizeof err);
    CHECK(r == CAT_OK);
    if (r != CAT_OK) {
        fprintf(stderr, "%s\n", err);
        return;
    }
    CHECK(model_broken(&m) == 0);
    CHECK(m.mesh_count == 1);
    if (m.mesh_count == 1) {
        const cat_mesh *me = &m.meshes[0];
        double c[3];
        for (int k = 0; k < 3; k++)
            c[k] = (m.bounds_min[k] + m.bounds_max[k]) / 2;
        for (int v = 0; v < me->vertex_count; v++) {
            const float *p = me->positions + 3 * v, *n = me->normals + 3 * v;
            double out = (p[0] - c[0]) * n[0] + (p[1] - c[1]) * n[1] + (p[2] - c[2]) * n[2];
            CHECK(out > 0.0);
            /* a corner's normal leans into all three of its faces */
            for (int k = 0; k < 3; k++)
                CHECK(fabs(n[k]) > 0.1);
        }
    }
    cat_model_free(&m);
}

/* A mirroring node (scale -1 on X) keeps triangles counter-clockwise seen from outside, and the
 * file's normals follow the mirror through the inverse transpose. */
static void test_mirror(void)
{
    check_cube_normals_outward("cube.gltf", "{\"mesh\":0}");
    check_cube_normals_outward("cube_mirrored.gltf",
                               "{\"mesh\":0,\"scale\":[-1,1,1],\"translation\":[3,0,0]}");
    check_cube_normals_outward(
        "cube_matrix.gltf", "{\"mesh\":0,\"matrix\":[0,0,-2,0, 0,1,0,0, 1,0,0,0, 0.5,0.25,-4,1]}");

    /* triangle with file normal +Z under scale (-1,1,1) */
    unsigned char bin[44 + 36];
    one_triangle_bin(bin);
    const float n[9] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    memcpy(bin + 44, n, sizeof n);
    const char *path = write_gltf(
        "mirror.gltf",
        "{" ASSET ",\"nodes\":[{\"mesh\":0,\"scale\":[-1,1,1]}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":2},"
        "\"indices\":1}]}],"
        "\"buffers\":[%s],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},"
        "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6},"
        "{\"buffer\":0,\"byteOffset\":44,\"byteLength\":36}],"
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
        "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"},"
        "{\"bufferView\":2,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}]}",
        bin, sizeof bin);
    cat_model m;
    char err[1024];
    cat_result r = cat_model_load(path, &m, err, sizeof err);
    CHECK(r == CAT_OK);
    if (r != CAT_OK) {
        fprintf(stderr, "%s\n", err);
        return;
    }
    CHECK(model_broken(&m) == 0);
    if (m.mesh_count == 1) {
        const cat_mesh *me = &m.meshes[0];
        CHECK(me->indices[0] == 0 && me->indices[1] == 2 && me->indices[2] == 1); /* flipped */
        CHECK_NEAR(me->positions[3], -1000.0, 0);
        for (int v = 0; v < 3; v++) {
            CHECK_NEAR(me->normals[3 * v + 1], -1.0, 1e-6);
        }
    }
    cat_model_free(&m);
}

/* A sparse accessor moves vertex 1 from (1,0,0) to (2,0,0); KHR_mesh_quantization's normalized
 * shorts work as texture coordinates. */
static void test_sparse_and_quantized(void)
{
    unsigned char bin[44 + 4 + 12 + 12];
    one_triangle_bin(bin);
    const unsigned short sparse_index[2] = {1, 0};
    const float sparse_value[3] = {2, 0, 0};
    const unsigned short uv[6] = {0, 0, 65535, 0, 0, 32768};
    memcpy(bin + 44, sparse_index, 4);
    memcpy(bin + 48, sparse_value, 12);
    memcpy(bin + 60, uv, 12);
    const char *path = write_gltf(
        "sparse.gltf",
        "{" ASSET ",\"extensionsUsed\":[\"KHR_mesh_quantization\"],"
        "\"extensionsRequired\":[\"KHR_mesh_quantization\"],\"nodes\":[{\"mesh\":0}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":2},"
        "\"indices\":1}]}],"
        "\"buffers\":[%s],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},"
        "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6},"
        "{\"buffer\":0,\"byteOffset\":44,\"byteLength\":4},"
        "{\"buffer\":0,\"byteOffset\":48,\"byteLength\":12},"
        "{\"buffer\":0,\"byteOffset\":60,\"byteLength\":12}],"
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
        "\"sparse\":{\"count\":1,\"indices\":{\"bufferView\":2,\"componentType\":5123},"
        "\"values\":{\"bufferView\":3}}},"
        "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"},"
        "{\"bufferView\":4,\"componentType\":5123,\"normalized\":true,\"count\":3,"
        "\"type\":\"VEC2\"}]}",
        bin, sizeof bin);
    cat_model m;
    char err[1024];
    cat_result r = cat_model_load(path, &m, err, sizeof err);
    CHECK(r == CAT_OK);
    if (r != CAT_OK) {
        fprintf(stderr, "%s\n", err);
        return;
    }
    CHECK(model_broken(&m) == 0);
    if (m.mesh_count == 1) {
        const cat_mesh *me = &m.meshes[0];
        CHECK_NEAR(me->positions[3], 2000.0, 0);
        CHECK(me->uvs != NULL);
        if (me->uvs) {
            CHECK_NEAR(me->uvs[2], 1.0, 1e-7);
            CHECK_NEAR(me->uvs[5], 32768.0 / 65535.0, 1e-7);
        }
    }
    cat_model_free(&m);
}

static void test_bad_files(void)
{
    /* not there, a folder, empty, random bytes */
    CHECK_LOAD_FAILS(tmp_path("does-not-exist.gltf"), CAT_ERR_IO, "No such file");
    CHECK_LOAD_FAILS(g_tmp, CAT_ERR_IO, "not a regular file");
    CHECK_LOAD_FAILS(write_text("empty.gltf", ""), CAT_ERR_PARSE, "empty");
    unsigned char noise[256];
    uint32_t s = 12345;
    for (size_t i = 0; i < sizeof noise; i++) {
        s = s * 1664525u + 1013904223u;
        noise[i] = (unsigned char)(s >> 24);
    }
    noise[0] = 0x89; /* neither '{' nor "glTF" */
    CHECK_LOAD_FAILS(write_file("noise.gltf", noise, sizeof noise), CAT_ERR_PARSE,
                     "not a glTF file (JSON parse error at line 1, column 1");
    CHECK_LOAD_FAILS(write_text("bad.gltf", "{\"asset\":{\"version\":\"2.0\"},}"), CAT_ERR_PARSE,
                     "JSON parse error at line 1, column 28");
    CHECK_LOAD_FAILS(write_text("noasset.gltf", "{\"nodes\":[]}"), CAT_ERR_INVALID, "invalid glTF");
    CHECK_LOAD_FAILS(write_text("toobig.gltf", "{\"asset\":{\"version\":\"2.0\"},\"x\":1e999}"),
                     CAT_ERR_PARSE, "number");

    /* GLB container */
    size_t size;
    unsigned char *glb = one_triangle_glb(&size);
    CHECK_LOAD_FAILS(write_file("truncated.glb", glb, size - 10), CAT_ERR_PARSE, "truncated GLB");
    CHECK_LOAD_FAILS(write_file("header.glb", glb, 12), CAT_ERR_PARSE, "truncated GLB");
    glb[4] = 1;
    CHECK_LOAD_FAILS(write_file("v1.glb", glb, size), CAT_ERR_UNSUPPORTED, "GLB version 1");
    glb[4] = 2;
    put_u32(glb + 12, 0x7ffffff0u);
    CHECK_LOAD_FAILS(write_file("json-chunk.glb", glb, size), CAT_ERR_PARSE, "JSON chunk");
    free(glb);

    unsigned char bin[44];
    one_triangle_bin(bin);
    /* accessor past the buffer's end: 4 vertices in a 36-byte view */
    CHECK_LOAD_FAILS(write_gltf("past-end.gltf", triangle_fmt(4), bin, sizeof bin), CAT_ERR_INVALID,
                     "mesh 0 primitive 0: accessor 0 reads past the end");
    /* buffer view past the buffer's end */
    CHECK_LOAD_FAILS(write_gltf("view-past-end.gltf", triangle_fmt(3), bin, 40), CAT_ERR_INVALID,
                     "buffer view 1 reads past the end of buffer 0");
    /* index out of range */
    unsigned char bad_index[44];
    memcpy(bad_index, bin, sizeof bin);
    bad_index[38] = 5;
    CHECK_LOAD_FAILS(write_gltf("index.gltf", triangle_fmt(3), bad_index, sizeof bad_index),
                     CAT_ERR_INVALID, "index 5 (element 1 of accessor 1) is out of range");
    /* NaN position */
    unsigned char nan_pos[44];
    memcpy(nan_pos, bin, sizeof bin);
    const float nan = NAN;
    memcpy(nan_pos + 16, &nan, 4);
    CHECK_LOAD_FAILS(write_gltf("nan.gltf", triangle_fmt(3), nan_pos, sizeof nan_pos),
                     CAT_ERR_INVALID, "vertex 1 is not a finite number (NaN or Inf)");
    const float inf = INFINITY;
    memcpy(nan_pos + 16, &inf, 4);
    CHECK_LOAD_FAILS(write_gltf("inf.gltf", triangle_fmt(3), nan_pos, sizeof nan_pos),
                     CAT_ERR_INVALID, "not a finite number");

    /* external buffers: outside the folder, absolute, other schemes, missing */
    char dir[4200];
    snprintf(dir, sizeof dir, "%s/inner", g_tmp);
    mkdir(dir, 0700);
    write_file("outside.bin", bin, sizeof bin); /* exists: only the rule refuses it */
    const char *uris[][3] = {
        {"inner/dotdot.gltf", "../outside.bin", "climbs out of the model's folder"},
        {"inner/dotdot2.gltf", "a/../../outside.bin", "climbs out of the model's folder"},
        {"inner/pct.gltf", "%2e%2e/outside.bin", "climbs out of the model's folder"},
        {"inner/abs.gltf", "/etc/hostname", "is an absolute path"},
        {"inner/scheme.gltf", "file:///etc/hostname", "has a scheme (file:)"},
        {"inner/http.gltf", "http://example.com/x.bin", "has a scheme (http:)"},
        {"inner/missing.gltf", "missing.bin", "cannot open buffer file \"missing.bin\""},
        {"inner/backslash.gltf", "..\\\\outside.bin", "backslash"},
    };
    const cat_result codes[] = {CAT_ERR_INVALID, CAT_ERR_INVALID,     CAT_ERR_INVALID,
                                CAT_ERR_INVALID, CAT_ERR_UNSUPPORTED, CAT_ERR_UNSUPPORTED,
                                CAT_ERR_IO,      CAT_ERR_INVALID};
    for (size_t i = 0; i < sizeof uris / sizeof uris[0]; i++) {
        char json[2048], fmt[256];
        snprintf(fmt, sizeof fmt, "{\"byteLength\":44,\"uri\":\"%s\"}", uris[i][1]);
        snprintf(json, sizeof json, triangle_fmt(3), fmt);
        CHECK_LOAD_FAILS(write_text(uris[i][0], json), codes[i], uris[i][2]);
    }
    /* an image outside the folder */
    {
        char json[2048];
        char *ok = gltf_with_buffer(triangle_fmt(3), bin, sizeof bin);
        snprintf(json, sizeof json, "%.*s,\"images\":[{\"uri\":\"../../secret.png\"}]}",
                 (int)strlen(ok) - 1, ok);
        free(ok);
        CHECK_LOAD_FAILS(write_text("inner/image.gltf", json), CAT_ERR_INVALID,
                         "image 0 URI \"../../secret.png\" climbs out");
    }

    /* structure */
    CHECK_LOAD_FAILS(write_text("cycle.gltf", "{" ASSET ",\"scenes\":[{\"nodes\":[0]}],"
                                              "\"nodes\":[{\"children\":[1]},{\"children\":[0]}]}"),
                     CAT_ERR_INVALID, "node 0 is reached twice");
    CHECK_LOAD_FAILS(write_text("scene.gltf", "{" ASSET ",\"scene\":3,\"scenes\":[{}]}"),
                     CAT_ERR_INVALID, "scene 3 does not exist");
    CHECK_LOAD_FAILS(write_text("node.gltf", "{" ASSET ",\"scenes\":[{\"nodes\":[7]}]}"),
                     CAT_ERR_INVALID, "node 7 does not exist");
    CHECK_LOAD_FAILS(write_text("mesh.gltf", "{" ASSET ",\"nodes\":[{\"mesh\":2}]}"),
                     CAT_ERR_INVALID, "node 0: mesh 2 does not exist");
    CHECK_LOAD_FAILS(write_text("draco.gltf", "{" ASSET ",\"extensionsRequired\":"
                                              "[\"KHR_draco_mesh_compression\"]}"),
                     CAT_ERR_UNSUPPORTED, "KHR_draco_mesh_compression");
    CHECK_LOAD_FAILS(write_text("quat.gltf", "{" ASSET ",\"nodes\":[{\"rotation\":[0,0,0,0]}]}"),
                     CAT_ERR_INVALID, "rotation quaternion");
    CHECK_LOAD_FAILS(write_text("matrix.gltf", "{" ASSET ",\"nodes\":[{\"matrix\":[1,0,0]}]}"),
                     CAT_ERR_INVALID, "matrix has 3 numbers");
    CHECK_LOAD_FAILS(write_gltf("count.gltf",
                                "{" ASSET ",\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":"
                                "[{\"attributes\":{\"POSITION\":0}}]}],\"buffers\":[%s],"
                                "\"bufferViews\":[{\"buffer\":0,\"byteLength\":44}],"
                                "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,"
                                "\"count\":1,\"type\":\"VEC3\"}]}",
                                bin, sizeof bin),
                     CAT_ERR_INVALID, "1 vertices do not make whole triangles");

    /* buffers whose sizes add up past the limit; a key spelled with an escape counts too */
    CHECK_LOAD_FAILS(write_text("sum.glb.gltf", "{" ASSET ",\"buffers\":[{\"byteLength\":"
                                                "600000000,\"uri\":\"a.bin\"},{\"byteLength\":"
                                                "600000000,\"uri\":\"a.bin\"}]}"),
                     CAT_ERR_TOO_LARGE, "byteLength add up to more than");
    CHECK_LOAD_FAILS(write_text("escaped.gltf", "{" ASSET ",\"buffers\":[{\"byte\\u004cength\":"
                                                "2000000000,\"uri\":\"a.bin\"}]}"),
                     CAT_ERR_TOO_LARGE, "byteLength add up to more than");

    /* a few bytes per object, kilobytes each once parsed: the object count is limited */
    {
        size_t n = CAT_MODEL_MAX_JSON_OBJECTS + 1;
        char *text = malloc(3 * n + 64), *t = text;
        t += sprintf(t, "{" ASSET ",\"materials\":[");
        for (size_t i = 0; i < n; i++)
            t += sprintf(t, i ? ",{}" : "{}");
        strcpy(t, "]}");
        CHECK_LOAD_FAILS(write_text("objects.gltf", text), CAT_ERR_TOO_LARGE, "objects");
        free(text);
    }

    /* deep nesting */
    char deep[400];
    memset(deep, '[', 200);
    memset(deep + 200, ']', 199);
    deep[399] = '\0';
    CHECK_LOAD_FAILS(write_text("deep.gltf", deep), CAT_ERR_TOO_LARGE, "nesting deeper");
}

/* A data: URI whose base64 text decodes to more than 64 MiB is refused before any parsing. */
static void test_huge_data_uri(void)
{
    size_t n = (size_t)CAT_MODEL_MAX_DATA_URI_BYTES / 3 * 4 + 4096;
    const char head[] = "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":1,\"uri\":"
                        "\"data:application/octet-stream;base64,";
    const char tail[] = "\"}]}";
    size_t total = strlen(head) + n + strlen(tail);
    char *text = malloc(total + 1);
    memcpy(text, head, strlen(head));
    memset(text + strlen(head), 'A', n);
    memcpy(text + strlen(head) + n, tail, strlen(tail) + 1);
    const char *path = write_file("huge.gltf", text, total);
    free(text);
    CHECK_LOAD_FAILS(path, CAT_ERR_TOO_LARGE, "data URIs over 64 MiB are refused");
    remove(path);
}

static void test_api_edges(void)
{
    char err[256] = "x";
    CHECK(cat_model_load(NULL, NULL, err, sizeof err) == CAT_ERR_INVALID);
    cat_model m;
    CHECK(cat_model_load(NULL, &m, err, sizeof err) == CAT_ERR_IO);
    CHECK(cat_model_load("", &m, NULL, 0) == CAT_ERR_IO); /* no message buffer: fine */
    char tiny[8];
    CHECK(cat_model_load(tmp_path("nope.glb"), &m, tiny, sizeof tiny) == CAT_ERR_IO);
    CHECK(strlen(tiny) == 7);
    cat_model_free(NULL);
    cat_model zero;
    memset(&zero, 0, sizeof zero);
    cat_model_free(&zero);
    CHECK(strcmp(cat_result_name(CAT_ERR_TOO_LARGE), "too large") == 0);
}

int main(void)
{
    tmp_make();
    test_glb();
    test_external_files();
    test_strip_and_fan();
    test_mirror();
    test_sparse_and_quantized();
    test_bad_files();
    test_huge_data_uri();
    test_api_edges();
    tmp_remove();
    return check_report("test_model_files");
}
