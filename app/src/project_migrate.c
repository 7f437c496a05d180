/* File versions: "version" is checked first, then older files are upgraded one version at a
 * time on the JSON tree before anything else reads it (docs/project-format.md, "Migration").
 *
 * To introduce version N+1: bump APP_PROJECT_VERSION, add a function migrate_vN_to_vN1 that
 * rewrites a version N tree into a version N+1 tree (rename keys, fill new required fields,
 * convert units), add it to the table below, and teach the readers the new format only. */
#include "project_internal.h"

#include <math.h>

typedef app_result (*pj_migration_fn)(pj_ctx *c, cJSON *root);

typedef struct pj_migration {
    int from; /* upgrades a version `from` tree to version `from + 1` */
    pj_migration_fn fn;
} pj_migration;

/* Empty while only version 1 exists; the sentinel keeps the table a valid C array. */
static const pj_migration migrations[] = {
    {0, NULL},
};

static pj_migration_fn find_migration(int from)
{
    for (size_t i = 0; i < sizeof migrations / sizeof migrations[0]; i++) {
        if (migrations[i].fn && migrations[i].from == from)
            return migrations[i].fn;
    }
    return NULL;
}

app_result pj_migrate(pj_ctx *c, cJSON *root, int *file_version)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(root, "version");
    size_t mark = pj_path_key(c, "version");
    if (!item)
        return pj_fail(c, APP_ERR_VERSION,
                       "missing (required; this build reads project versions 1 to %d)",
                       APP_PROJECT_VERSION);
    if (!cJSON_IsNumber(item))
        return pj_fail(c, APP_ERR_VERSION, "expected an integer, got %s", pj_type_name(item));
    double v = item->valuedouble;
    if (!isfinite(v) || v != floor(v))
        return pj_fail(c, APP_ERR_VERSION, "expected an integer, got %g", v);
    if (v < 1)
        return pj_fail(c, APP_ERR_VERSION, "must be >= 1, got %g", v);
    if (v > APP_PROJECT_VERSION)
        return pj_fail(c, APP_ERR_VERSION,
                       "written by a newer Tessera (version %g), this build reads up to %d", v,
                       APP_PROJECT_VERSION);
    int version = (int)v;
    *file_version = version;
    for (int k = version; k < APP_PROJECT_VERSION; k++) {
        pj_migration_fn fn = find_migration(k);
        if (!fn)
            return pj_fail(c, APP_ERR_VERSION, "no migration from version %d to %d in this build",
                           k, k + 1);
        app_result r = fn(c, root);
        if (r != APP_OK)
            return r;
    }
    pj_path_restore(c, mark);
    return APP_OK;
}
