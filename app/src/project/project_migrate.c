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

static const pj_range ROOM_SIZE = {0.0, APP_PROJECT_MAX_ROOM_MM, 1, 0, 0};

/* Version 1 -> 2: the room box $.room {width, depth, height} becomes the floor plan
 * $.plan {corners (0,0) (w,0) (w,d) (0,d), height}; $.room keeps only its materials. The box
 * is checked here with the version 1 messages ($.room.width: ...), since nothing else reads
 * it any more. A "plan" key in a version 1 file meant nothing and is replaced. */
static app_result migrate_v1_to_v2(pj_ctx *c, cJSON *root)
{
    const cJSON *room_c;
    app_result r = pj_member(c, root, "room", cJSON_Object, 1, &room_c);
    if (r != APP_OK)
        return r;
    cJSON *room = (cJSON *)room_c;
    size_t mark = pj_path_key(c, "room");
    double w = 0, d = 0, h = 0;
    if ((r = pj_get_number(c, room, "width", 1, ROOM_SIZE, &w)) != APP_OK ||
        (r = pj_get_number(c, room, "depth", 1, ROOM_SIZE, &d)) != APP_OK ||
        (r = pj_get_number(c, room, "height", 1, ROOM_SIZE, &h)) != APP_OK)
        return r;
    pj_path_restore(c, mark);
    const double xy[4][2] = {{0, 0}, {w, 0}, {w, d}, {0, d}};
    cJSON *plan = cJSON_CreateObject();
    cJSON *corners = cJSON_AddArrayToObject(plan, "corners");
    int ok = plan && corners && cJSON_AddNumberToObject(plan, "height", h);
    for (int i = 0; ok && i < 4; i++) {
        cJSON *pt = cJSON_CreateDoubleArray(xy[i], 2);
        ok = pt && cJSON_AddItemToArray(corners, pt);
        if (!ok)
            cJSON_Delete(pt);
    }
    if (!ok) {
        cJSON_Delete(plan);
        return pj_fail(c, APP_ERR_OUT_OF_MEMORY, "out of memory (migrating to version 2)");
    }
    cJSON_DeleteItemFromObjectCaseSensitive(room, "width");
    cJSON_DeleteItemFromObjectCaseSensitive(room, "depth");
    cJSON_DeleteItemFromObjectCaseSensitive(room, "height");
    cJSON_DeleteItemFromObjectCaseSensitive(root, "plan");
    cJSON_DeleteItemFromObjectCaseSensitive(root, "tilings");
    if (!cJSON_AddItemToObject(root, "plan", plan)) {
        cJSON_Delete(plan);
        return pj_fail(c, APP_ERR_OUT_OF_MEMORY, "out of memory (migrating to version 2)");
    }
    return APP_OK;
}

static const pj_migration migrations[] = {
    {1, migrate_v1_to_v2},
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
    pj_path_restore(c, mark);
    for (int k = version; k < APP_PROJECT_VERSION; k++) {
        pj_migration_fn fn = find_migration(k);
        if (!fn)
            return pj_fail(c, APP_ERR_VERSION, "no migration from version %d to %d in this build",
                           k, k + 1);
        app_result r = fn(c, root);
        if (r != APP_OK)
            return r;
    }
    return APP_OK;
}
