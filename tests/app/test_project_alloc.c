/* Every allocation of the reader and the writer fails in turn (the SQLite habit): each run
 * ends in APP_OK or APP_ERR_OUT_OF_MEMORY with a message, never a crash or a leak (ASan).
 * cJSON's own allocations are failed the same way through cJSON_InitHooks. */
#include "test_util.h"

#include "app/project/project.h"

#include <cjson/cJSON.h>

#define DATA TESSERA_PROJECT_TEST_DATA

static long cjson_budget = -1; /* allocations cJSON may still make; -1 = unlimited */

static void *failing_malloc(size_t size)
{
    if (cjson_budget == 0)
        return NULL;
    if (cjson_budget > 0)
        cjson_budget--;
    return malloc(size);
}

static void test_own_allocations(void)
{
    int saw_oom = 0, n;
    for (n = 0; n < 10000; n++) {
        char err[1024] = "";
        app_project p;
        app_project_test_fail_alloc_after(n);
        app_result r = app_project_read(DATA "/valid.json", &p, err, sizeof err);
        app_project_test_fail_alloc_after(-1);
        CHECK_MSG(r == APP_OK || r == APP_ERR_OUT_OF_MEMORY, "%s", err);
        if (r == APP_OK) {
            app_project_free(&p);
            break;
        }
        saw_oom = 1;
        CHECK_MSG(tu_contains(err, "valid.json: ") && tu_contains(err, "out of memory"), "%s", err);
        CHECK(p.materials == NULL && p.objects == NULL);
    }
    CHECK(saw_oom);
    CHECK(n < 10000);
    printf("project_alloc_failure: reader survives a failure at each of %d allocations\n", n);
}

static void test_writer_allocations(void)
{
    char *dir = tu_make_temp_dir();
    CHECK(dir != NULL);
    if (!dir)
        return;
    char path[4096];
    snprintf(path, sizeof path, "%s/p.json", dir);
    char err[1024];
    app_project p;
    if (app_project_read(DATA "/valid.json", &p, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return;
    }
    int n;
    for (n = 0; n < 10000; n++) {
        err[0] = '\0';
        app_project_test_fail_alloc_after(n);
        app_result r = app_project_write(path, &p, err, sizeof err);
        app_project_test_fail_alloc_after(-1);
        CHECK_MSG(r == APP_OK || r == APP_ERR_OUT_OF_MEMORY, "%s", err);
        if (r == APP_OK)
            break;
        CHECK(access(path, F_OK) != 0); /* nothing half-written */
        CHECK(tu_count_entries(dir, ".tmp-") == 0);
    }
    CHECK(n > 0 && n < 10000);
    app_project_free(&p);
    tu_remove_tree(dir);
    free(dir);
}

/* cJSON out of memory looks like malformed JSON or out of memory, never a crash. */
static void test_cjson_allocations(void)
{
    size_t len = 0;
    char *text = tu_read_file(DATA "/valid.json", &len);
    CHECK(text != NULL);
    if (!text)
        return;
    cJSON_Hooks hooks = {failing_malloc, free};
    cJSON_InitHooks(&hooks);
    int n;
    for (n = 0; n < 100000; n++) {
        char err[1024] = "";
        app_project p;
        cjson_budget = n;
        app_result r = app_project_parse(text, len, DATA "/valid.json", &p, err, sizeof err);
        cjson_budget = -1;
        if (r == APP_OK) {
            app_project_free(&p);
            break;
        }
        CHECK_MSG(r == APP_ERR_PARSE || r == APP_ERR_OUT_OF_MEMORY, "%s", err);
        CHECK_MSG(tu_contains(err, "valid.json: "), "%s", err);
    }
    CHECK(n > 0 && n < 100000);
    cJSON_InitHooks(NULL);
    free(text);
}

int main(void)
{
    test_own_allocations();
    test_writer_allocations();
    test_cjson_allocations();
    return check_report("project_alloc_failure");
}
