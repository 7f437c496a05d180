/* Absurd counts: files that are small but claim huge or impossible numbers are
 * refused by cat_model_load, each with its own message, before anything of that size is
 * allocated. (Hostile URIs, data URIs over the limit, accessors and indices out of range,
 * object counts and nesting are in test_model_files.c.) */
#include "test_util.h"

#define ASSET "\"asset\":{\"version\":\"2.0\"}"
/* One primitive whose POSITION accessor 0 has no buffer view (all zeros) and COUNT vertices. */
#define ZERO_POSITIONS(COUNT)                                                                      \
    "{" ASSET                                                                                      \
    ",\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":"          \
    "[{\"attributes\":{\"POSITION\":0}}]}],\"accessors\":[{\"componentType\":5126,"                \
    "\"count\":" COUNT ",\"type\":\"VEC3\"}]}"

static void test_vertex_counts(void)
{
    CHECK_LOAD_FAILS(write_text("c100m.gltf", ZERO_POSITIONS("100000000")), CAT_ERR_TOO_LARGE,
                     "mesh 0 primitive 0: 100000000 vertices, the limit per primitive is 16777216");
    CHECK_LOAD_FAILS(write_text("c2e32.gltf", ZERO_POSITIONS("4294967298")), CAT_ERR_TOO_LARGE,
                     "4294967298 vertices, the limit per primitive is");
    CHECK_LOAD_FAILS(write_text("cneg.gltf", ZERO_POSITIONS("-5")), CAT_ERR_INVALID,
                     "'count' property is not a positive integer");
    CHECK_LOAD_FAILS(write_text("cexp.gltf", ZERO_POSITIONS("1e30")), CAT_ERR_INVALID,
                     "'count' property is not a positive integer");
}

static void test_sparse_count(void)
{
    const char *text =
        "{" ASSET ",\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],\"meshes\":[{"
        "\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"buffers\":[{\"byteLength\":12,"
        "\"uri\":\"data:application/octet-stream;base64,"
        "AAAAAAAAAAAAAAAA\"}],\"bufferViews\":[{"
        "\"buffer\":0,\"byteLength\":12}],\"accessors\":[{\"componentType\":5126,\"count\":3,"
        "\"type\":\"VEC3\",\"sparse\":{\"count\":2000000000,\"indices\":{\"bufferView\":0,"
        "\"componentType\":5125},\"values\":{\"bufferView\":0}}}]}";
    CHECK_LOAD_FAILS(write_text("sparse.gltf", text), CAT_ERR_INVALID,
                     "accessor 0: sparse count 2000000000 is not in 1..3");
}

/* Few bytes of JSON that place more primitive instances than CAT_MODEL_MAX_MESHES: a mesh of
 * 64 primitives under 17 000 nodes (1 088 000 instances). One primitive is a triangle, the
 * others points: skipped instances count towards the limit too, and are cheap to place. */
static void test_instance_count(void)
{
    const int nodes = 17000, prims = 64;
    size_t cap = (size_t)nodes * 24 + (size_t)prims * 48 + 1024;
    char *text = malloc(cap), *t = text;
    t += sprintf(t, "{" ASSET ",\"scenes\":[{\"nodes\":[");
    for (int i = 0; i < nodes; i++)
        t += sprintf(t, i ? ",%d" : "%d", i);
    t += sprintf(t, "]}],\"nodes\":[");
    for (int i = 0; i < nodes; i++)
        t += sprintf(t, i ? ",{\"mesh\":0}" : "{\"mesh\":0}");
    t += sprintf(t, "],\"meshes\":[{\"primitives\":[");
    for (int i = 0; i < prims; i++)
        t += sprintf(t, i ? ",{\"attributes\":{\"POSITION\":0},\"mode\":0}"
                          : "{\"attributes\":{\"POSITION\":0}}");
    sprintf(t, "]}],\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/octet-stream;"
               "base64,AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA\"}],\"bufferViews\":[{"
               "\"buffer\":0,\"byteLength\":36}],\"accessors\":[{\"bufferView\":0,"
               "\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}]}");
    CHECK_LOAD_FAILS(write_text("instances.gltf", text), CAT_ERR_TOO_LARGE,
                     "the scene places more than 1048576 primitives");
    free(text);
}

int main(void)
{
    tmp_make();
    test_vertex_counts();
    test_sparse_count();
    test_instance_count();
    tmp_remove();
    return check_report("test_model_absurd");
}
