/* Fuzz target for the glTF/GLB loader (tests/fuzz/CMakeLists.txt, docs/fuzzing.md).
 * Each input is written to a file in a private temporary folder and loaded from there, so
 * external buffer URIs resolve inside that folder. */
#define _XOPEN_SOURCE 700 /* mkdtemp */
#include "catalog/model.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char g_path[4096];

static void remove_input(void)
{
    char dir[4096];
    unlink(g_path);
    snprintf(dir, sizeof dir, "%s", g_path);
    char *slash = strrchr(dir, '/');
    if (slash) {
        *slash = '\0';
        rmdir(dir);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!g_path[0]) {
        const char *base = getenv("TMPDIR");
        char dir[4000];
        snprintf(dir, sizeof dir, "%s/tessera-fuzz-XXXXXX", base && *base ? base : "/tmp");
        if (!mkdtemp(dir))
            abort();
        snprintf(g_path, sizeof g_path, "%s/input.gltf", dir);
        atexit(remove_input);
    }
    FILE *f = fopen(g_path, "wb");
    if (!f)
        abort();
    if (size && fwrite(data, 1, size, f) != size)
        abort();
    fclose(f);
    cat_model m;
    char err[512];
    if (cat_model_load(g_path, &m, err, sizeof err) == CAT_OK)
        cat_model_free(&m);
    return 0;
}
