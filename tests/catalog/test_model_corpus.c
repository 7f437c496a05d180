/* Corpus replay: the samples and a few hundred deterministic mutations of a small GLB and a
 * small .gltf (byte flips, byte sweeps, truncations) go through cat_model_load. Each must either
 * load into a model that keeps the invariants or fail with a message naming the file; never
 * crash (run under ASan/UBSan to catch memory errors). */
#include "test_util.h"

#include <dirent.h>
#include <stdint.h>

static int g_loaded, g_refused;

static void replay(const char *path)
{
    cat_model m;
    char err[1024] = "";
    cat_result r = cat_model_load(path, &m, err, sizeof err);
    if (r == CAT_OK) {
        g_loaded++;
        if (model_broken(&m)) {
            fprintf(stderr, "%s: loaded but breaks the model invariants\n", path);
            check_failures++;
        }
        cat_model_free(&m);
        return;
    }
    g_refused++;
    if (r < CAT_ERR_IO || r > CAT_ERR_TOO_LARGE || strncmp(err, path, strlen(path)) != 0 ||
        strlen(err) <= strlen(path) + 2) {
        fprintf(stderr, "%s: bad failure report %d: \"%s\"\n", path, (int)r, err);
        check_failures++;
    }
    CHECK(m.meshes == NULL && m.mesh_count == 0 && m.materials == NULL);
}

static uint32_t g_rng = 0x2545F491u;

static uint32_t next_random(void)
{
    g_rng ^= g_rng << 13; /* xorshift32: the same sequence on every run */
    g_rng ^= g_rng >> 17;
    g_rng ^= g_rng << 5;
    return g_rng;
}

static void mutate_and_replay(const char *name, const unsigned char *orig, size_t size, int count)
{
    unsigned char *buf = malloc(size);
    for (int i = 0; i < count; i++) {
        memcpy(buf, orig, size);
        size_t len = size;
        int kind = (int)(next_random() % 4);
        int flips = 1 + (int)(next_random() % 4);
        if (kind == 0) { /* random bytes anywhere */
            for (int k = 0; k < flips; k++)
                buf[next_random() % size] = (unsigned char)next_random();
        } else if (kind == 1) { /* single bit flips */
            for (int k = 0; k < flips; k++)
                buf[next_random() % size] ^= (unsigned char)(1u << (next_random() % 8));
        } else if (kind == 2) { /* interesting values over 4 bytes (lengths, counts, offsets) */
            static const uint32_t values[] = {
                0, 1, 0x7f, 0x80, 0xff, 0xffff, 0x7fffffff, 0x80000000u, 0xffffffffu, 0xfffffffcu};
            size_t at = next_random() % (size - 3);
            uint32_t v = values[next_random() % (sizeof values / sizeof values[0])];
            for (int k = 0; k < 4; k++)
                buf[at + (size_t)k] = (unsigned char)(v >> (8 * k));
        } else { /* truncation, sometimes with a flip */
            len = next_random() % size;
            if (len > 0 && next_random() % 2)
                buf[next_random() % len] ^= 0x20;
        }
        replay(write_file(name, buf, len));
    }
    free(buf);
}

/* Every digit of a JSON text replaced in turn by a few others: indices, counts and offsets are
 * pushed out of range one at a time. */
static void sweep_digits(const char *name, const char *json)
{
    size_t n = strlen(json);
    char *buf = malloc(n + 1);
    const char repl[] = "09";
    for (size_t i = 0; i < n; i++) {
        if (json[i] < '0' || json[i] > '9')
            continue;
        for (size_t k = 0; k < 2; k++) {
            if (json[i] == repl[k])
                continue;
            memcpy(buf, json, n + 1);
            buf[i] = repl[k];
            replay(write_text(name, buf));
        }
    }
    free(buf);
}

static void replay_samples(void)
{
    DIR *d = opendir(TESSERA_GLTF_SAMPLES);
    CHECK(d != NULL);
    if (!d)
        return;
    int count = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        size_t n = strlen(e->d_name);
        if (n < 5 || strcmp(e->d_name + n - 5, ".gltf") != 0)
            continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", TESSERA_GLTF_SAMPLES, e->d_name);
        int before = g_loaded;
        replay(path);
        CHECK(g_loaded == before + 1);
        count++;
    }
    closedir(d);
    CHECK(count >= 8);
}

int main(void)
{
    tmp_make();
    replay_samples();

    size_t size;
    unsigned char *glb = one_triangle_glb(&size);
    replay(write_file("seed.glb", glb, size));
    CHECK(g_loaded >= 9);
    mutate_and_replay("mutant.glb", glb, size, 400);
    for (size_t len = 0; len < size; len += 3) /* every third truncation */
        replay(write_file("cut.glb", glb, len));
    free(glb);

    unsigned char bin[44];
    one_triangle_bin(bin);
    char *b64 = base64(bin, sizeof bin);
    char json[4096];
    snprintf(
        json, sizeof json,
        "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
        "\"nodes\":[{\"children\":[1],\"scale\":[1,2,1]},{\"mesh\":0,\"translation\":"
        "[1,0,0]}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},"
        "\"indices\":1,\"material\":0,\"mode\":4}]}],\"materials\":[{}],"
        "\"buffers\":[{\"byteLength\":44,\"uri\":\"data:application/octet-stream;base64,%s\"}],"
        "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},"
        "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6}],"
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,"
        "\"type\":\"VEC3\"},{\"bufferView\":1,\"componentType\":5123,\"count\":3,"
        "\"type\":\"SCALAR\"}]}",
        b64);
    free(b64);
    int before = g_loaded;
    replay(write_text("seed.gltf", json));
    CHECK(g_loaded == before + 1);
    mutate_and_replay("mutant.gltf", (const unsigned char *)json, strlen(json), 200);
    sweep_digits("digits.gltf", json);

    printf("corpus replay: %d loaded, %d refused\n", g_loaded, g_refused);
    tmp_remove();
    return check_report("test_model_corpus");
}
