/* libFuzzer target for the edit-script parser (`tessera edit`, docs/editing.md): every input
 * runs as a script against a fresh copy of the designed bathroom's measured room, with the
 * products of the shipped catalog CSV files. A script may fail on any line; it must fail with
 * "NAME:LINE: message" and leave a project that can still be freed. */
#include "app/project/commands.h"
#include "placement_test_catalog.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef TESSERA_SOURCE_DIR
#define TESSERA_SOURCE_DIR "."
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const char *fixtures_csv = TESSERA_SOURCE_DIR "/assets/catalog/fixtures.csv";
static const char *tiles_csv = TESSERA_SOURCE_DIR "/assets/catalog/tiles.csv";
static app_project base;
static int base_loaded;

/* Fixtures from fixtures.csv, tiles from tiles.csv (as test_edit_script.c). */
static app_result both_lookup(void *user, const app_product_ref *ref, app_product_info *out,
                              char *err, size_t err_size)
{
    (void)user;
    app_result r = ptc_lookup((void *)fixtures_csv, ref, out, err, err_size);
    if (r == APP_OK || !strstr(err, "no product"))
        return r;
    return ptc_lookup((void *)tiles_csv, ref, out, err, err_size);
}

static void load_base_once(void)
{
    char err[1024];
    if (base_loaded)
        return;
    if (app_project_read(TESSERA_SOURCE_DIR "/assets/projects/designed-bathroom-base.json", &base,
                         err, sizeof err) != APP_OK) {
        fprintf(stderr, "%s\n", err);
        abort();
    }
    base_loaded = 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    load_base_once();
    char err[2048] = "";
    app_project p;
    if (app_project_copy(&p, &base, err, sizeof err) != APP_OK)
        abort();
    app_history *h = app_history_create(100);
    if (!h)
        abort();
    app_script_env env = {both_lookup, NULL, NULL, NULL};
    app_result r =
        app_script_run(&p, h, (const char *)data, size, "fuzz.edit", &env, NULL, err, sizeof err);
    if (r != APP_OK && strncmp(err, "fuzz.edit:", 10) != 0) {
        fprintf(stderr, "a failed script without \"fuzz.edit:LINE:\": %s\n", err);
        abort(); /* every failure names the script and the line */
    }
    app_history_destroy(h);
    app_project_free_all(&p);
    return 0;
}
