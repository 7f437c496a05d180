/* app_flat_read: a project file with a "rooms" array -> one app_project per room. Each room is
 * read by the single-room reader (pj_read_root) from an object that joins the room's own keys
 * with the file's shared ones (version, materials, render, daylight), under the JSON path
 * $.rooms[i], so a message names the room's element. The shared sections are checked once, at
 * their own path, before any room. */
#include "project_internal.h"

#include "app/project/flat.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Keys a room of a flat holds; the others are shared by the whole flat. */
static const char *const room_keys[] = {"name",    "room",   "plan",   "tilings",
                                        "objects", "lights", "cameras"};
enum { ROOM_KEY_COUNT = sizeof room_keys / sizeof room_keys[0] };

static int is_room_key(const char *key)
{
    for (int i = 0; i < ROOM_KEY_COUNT; i++)
        if (!strcmp(key, room_keys[i]))
            return 1;
    return 0;
}

static void set_path(app_project *p, const char *path)
{
    char *real = realpath(path, NULL);
    snprintf(p->path, sizeof p->path, "%s", real ? real : path);
    free(real);
}

/* The shared sections, read once into a scratch project at their own JSON path: version,
 * materials and render settings, and no room key beside "rooms". */
static app_result check_shared(pj_ctx *c, cJSON *root)
{
    for (const cJSON *it = root->child; it; it = it->next) {
        if (it->string && is_room_key(it->string) && strcmp(it->string, "name") != 0) {
            pj_path_key(c, it->string);
            return pj_fail(c, APP_ERR_SCHEMA,
                           "a flat keeps \"%s\" in each room ($.rooms[i].%s), not at the top",
                           it->string, it->string);
        }
    }
    app_project scratch;
    memset(&scratch, 0, sizeof scratch);
    c->p = &scratch;
    app_result r = pj_migrate(c, root, &scratch.file_version);
    if (r == APP_OK && scratch.file_version != APP_PROJECT_VERSION) {
        pj_path_key(c, "version");
        r = pj_fail(c, APP_ERR_VERSION, "a flat (\"rooms\") needs version %d, got %d",
                    APP_PROJECT_VERSION, scratch.file_version);
    }
    if (r == APP_OK)
        r = pj_get_string(c, root, "name", 0, 1, scratch.name, sizeof scratch.name);
    if (r == APP_OK)
        r = pj_read_materials(c, root);
    if (r == APP_OK)
        r = pj_read_render(c, root);
    app_project_free(&scratch);
    c->p = NULL;
    return r;
}

/* Room i: its keys first (the reader takes the first of a repeated key), then the shared ones;
 * references, so nothing is copied. */
static app_result read_room(const char *path, char *err, size_t err_size, cJSON *root,
                            const cJSON *room, int i, app_project *out, double offset[2])
{
    pj_ctx c;
    pj_ctx_init(&c, path, path, err, err_size);
    pj_path_key(&c, "rooms");
    pj_path_index(&c, i);
    if (!cJSON_IsObject(room))
        return pj_fail(&c, APP_ERR_SCHEMA, "expected an object (a room), got %s",
                       pj_type_name(room));
    for (const cJSON *it = room->child; it; it = it->next) {
        if (it->string && !is_room_key(it->string) && !strcmp(it->string, "materials")) {
            pj_path_key(&c, it->string);
            return pj_fail(&c, APP_ERR_SCHEMA,
                           "materials are shared by the rooms: put them in $.materials");
        }
    }
    char name[128];
    app_result r = pj_get_string(&c, room, "name", 1, 0, name, sizeof name);
    if (r == APP_OK)
        r = pj_get_vec(&c, room, "offset", 0, 2,
                       (pj_range){-APP_PROJECT_MAX_ROOM_MM, APP_PROJECT_MAX_ROOM_MM, 0, 0, 1},
                       offset);
    if (r != APP_OK)
        return r;
    cJSON *joined = cJSON_CreateObject();
    if (!joined)
        return pj_fail_file(&c, APP_ERR_OUT_OF_MEMORY, "out of memory");
    int ok = 1;
    for (const cJSON *it = room->child; ok && it; it = it->next)
        if (it->string && is_room_key(it->string))
            ok = cJSON_AddItemReferenceToObject(joined, it->string, (cJSON *)it);
    for (const cJSON *it = root->child; ok && it; it = it->next)
        if (it->string && strcmp(it->string, "rooms") != 0 && strcmp(it->string, "name") != 0)
            ok = cJSON_AddItemReferenceToObject(joined, it->string, (cJSON *)it);
    if (!ok) {
        cJSON_Delete(joined);
        return pj_fail_file(&c, APP_ERR_OUT_OF_MEMORY, "out of memory");
    }
    app_project p;
    memset(&p, 0, sizeof p);
    c.p = &p;
    r = pj_read_root(&c, joined, &p);
    cJSON_Delete(joined);
    pj_ctx_release(&c);
    if (r != APP_OK) {
        app_project_free(&p);
        return r;
    }
    set_path(&p, path);
    *out = p;
    return APP_OK;
}

static app_result read_rooms(pj_ctx *c, const char *path, cJSON *root, const cJSON *rooms,
                             app_flat *f, char *err, size_t err_size)
{
    int n = cJSON_GetArraySize(rooms);
    if (n < 1 || n > APP_FLAT_MAX_ROOMS) {
        pj_path_key(c, "rooms");
        return pj_fail(c, APP_ERR_SCHEMA, "a flat has 1 to %d rooms, got %d", APP_FLAT_MAX_ROOMS,
                       n);
    }
    f->rooms = calloc((size_t)n, sizeof *f->rooms);
    f->offset_mm = calloc((size_t)n, sizeof *f->offset_mm);
    if (!f->rooms || !f->offset_mm)
        return pj_fail_file(c, APP_ERR_OUT_OF_MEMORY, "out of memory for %d rooms", n);
    int i = 0;
    for (const cJSON *room = rooms->child; room; room = room->next, i++) {
        app_result r = read_room(path, err, err_size, root, room, i, &f->rooms[i], f->offset_mm[i]);
        if (r != APP_OK)
            return r;
        f->room_count = i + 1;
        for (int k = 0; k < i; k++) {
            if (!strcmp(f->rooms[k].name, f->rooms[i].name)) {
                pj_path_key(c, "rooms");
                pj_path_index(c, i);
                pj_path_key(c, "name");
                return pj_fail(c, APP_ERR_SCHEMA,
                               "\"%s\" is also the name of room %d ($.rooms[%d])", f->rooms[i].name,
                               k + 1, k);
            }
        }
    }
    return APP_OK;
}

app_result app_flat_read(const char *path, app_flat *out, char *err, size_t err_size)
{
    pj_ctx c;
    pj_ctx_init(&c, path, path, err, err_size);
    if (!out)
        return pj_fail_file(&c, APP_ERR_IO, "no flat to read into (out is NULL)");
    memset(out, 0, sizeof *out);
    if (!path || !path[0])
        return pj_fail_file(&c, APP_ERR_IO, "no file name given");
    char *text = NULL;
    size_t len = 0;
    app_result r = pj_read_file(&c, path, &text, &len);
    if (r != APP_OK)
        return r;
    cJSON *root = NULL;
    r = pj_parse_json(&c, text, len, &root);
    const cJSON *rooms = r == APP_OK && cJSON_IsObject(root)
                             ? cJSON_GetObjectItemCaseSensitive(root, "rooms")
                             : NULL;
    app_flat f;
    memset(&f, 0, sizeof f);
    if (r == APP_OK && !rooms) {
        /* The single-room form, read exactly as app_project_read reads it. */
        f.rooms = calloc(1, sizeof *f.rooms);
        f.offset_mm = calloc(1, sizeof *f.offset_mm);
        if (!f.rooms || !f.offset_mm)
            r = pj_fail_file(&c, APP_ERR_OUT_OF_MEMORY, "out of memory");
        else if ((r = app_project_parse(text, len, path, &f.rooms[0], err, err_size)) == APP_OK) {
            f.room_count = 1;
            snprintf(f.name, sizeof f.name, "%s", f.rooms[0].name);
        }
    } else if (r == APP_OK) {
        f.is_flat = 1;
        if (!cJSON_IsArray(rooms)) {
            pj_path_key(&c, "rooms");
            r = pj_fail(&c, APP_ERR_SCHEMA, "expected an array of rooms, got %s",
                        pj_type_name(rooms));
        }
        if (r == APP_OK)
            r = check_shared(&c, root);
        if (r == APP_OK)
            r = pj_get_string(&c, root, "name", 0, 1, f.name, sizeof f.name);
        if (r == APP_OK)
            r = read_rooms(&c, path, root, rooms, &f, err, err_size);
    }
    cJSON_Delete(root);
    pj_ctx_release(&c);
    free(text);
    if (r != APP_OK) {
        app_flat_free(&f);
        return r;
    }
    *out = f;
    return APP_OK;
}

void app_flat_free(app_flat *f)
{
    if (!f)
        return;
    for (int i = 0; f->rooms && i < f->room_count; i++)
        app_project_free(&f->rooms[i]);
    free(f->rooms);
    free(f->offset_mm);
    memset(f, 0, sizeof *f);
}

int app_flat_room_of_camera(const app_flat *f, const char *camera)
{
    if (!f || f->room_count < 1)
        return -1;
    if (!camera)
        return 0;
    for (int i = 0; i < f->room_count; i++)
        if (app_project_find_camera(&f->rooms[i], camera))
            return i;
    return -1;
}

void app_flat_take_room(app_flat *f, int i, app_project *out)
{
    memset(out, 0, sizeof *out);
    if (f && i >= 0 && i < f->room_count) {
        *out = f->rooms[i];
        memset(&f->rooms[i], 0, sizeof f->rooms[i]);
    }
    app_flat_free(f);
}
