/* Fuzz target for the project reader (tests/fuzz/CMakeLists.txt, docs/fuzzing.md).
 * Random bytes go to app_project_parse; what parses is freed. The write of what parses is
 * covered by the replay test (test_project_fuzz_replay.c), which needs no libFuzzer. */
#include "app/project/project.h"

#include <stddef.h>
#include <stdint.h>

#ifndef TESSERA_PROJECT_TEST_DATA
#define TESSERA_PROJECT_TEST_DATA "."
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[512];
    app_project p;
    /* next to the fixtures, so "models/tap.glb" and "textures/wall.png" resolve */
    if (app_project_parse((const char *)data, size, TESSERA_PROJECT_TEST_DATA "/fuzz.json", &p, err,
                          sizeof err) == APP_OK)
        app_project_free(&p);
    return 0;
}
