/* The render list (app/scene/render_list.h) and moving an object through the document
 * (app_scene_move_object): the list has one item per room surface, primitive and model part,
 * probe meshes only when asked for; a moved object is moved in the document, and its renderer
 * objects, and only they, take the transforms a scene built from the moved document has. Run on
 * a project with every primitive shape (valid.json), one with a glTF model of several parts
 * (with-model.json) and one with a catalog
 * product drawn as a box standing on its origin (v2_l_room.json). */
#include "app/project/project.h"
#include "app/scene/render_list.h"
#include "app/scene/scene_build.h"
#include "test_util.h"

#include <math.h>

#define DATA TESSERA_PROJECT_TEST_DATA
#define CLI_DATA TESSERA_SOURCE_DIR "/tests/cli/data"

static int find(const app_project *p, const char *name)
{
    for (int i = 0; i < p->object_count; i++)
        if (!strcmp(p->objects[i].name, name))
            return i;
    return -1;
}

/* Items of each kind, and probe meshes only with APP_RENDER_LIST_PROBE_MESHES. */
static void check_list(const app_project *p)
{
    char err[2048];
    app_render_list plain, gpu;
    app_result r = app_render_list_build(p, 0, &plain, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    r = app_render_list_build(p, APP_RENDER_LIST_PROBE_MESHES, &gpu, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r != APP_OK)
        return;
    CHECK(plain.item_count == gpu.item_count);
    CHECK(gpu.item_count > p->object_count);
    CHECK(gpu.object_count == p->object_count);
    CHECK(gpu.light_count >= p->light_count);
    int room = 0, probe_meshes = 0, plain_probe_meshes = 0;
    for (int i = 0; i < gpu.item_count; i++) {
        const app_render_item *it = &gpu.items[i];
        room += it->object < 0;
        /* the room first, then the objects in order */
        CHECK(i == 0 || it->object >= gpu.items[i - 1].object);
        CHECK(it->mesh >= 0 && it->mesh < gpu.mesh_count);
        CHECK(it->object < 0 || it->background == 0);
        probe_meshes += it->probe_mesh >= 0;
        plain_probe_meshes += plain.items[i].probe_mesh >= 0;
    }
    CHECK(room > 0);
    CHECK(probe_meshes > 0); /* the cylinder, sphere and torus have coarse copies */
    CHECK(plain_probe_meshes == 0);
    int lamp = find(p, "lamp");
    for (int i = 0; lamp >= 0 && i < gpu.item_count; i++)
        if (gpu.items[i].object == lamp) {
            CHECK(gpu.items[i].shape == RD_SHAPE_SPHERE);
            CHECK(fabsf(gpu.items[i].transform[12] -
                        (float)(p->objects[lamp].position_mm[0] * 1e-3)) < 1e-6f);
        }
    app_render_list_free(&plain);
    app_render_list_free(&gpu);
}

typedef struct transforms {
    float (*m)[16];
    int count;
} transforms;

static transforms transforms_of(const app_scene *s)
{
    transforms t = {0};
    t.count = rd_scene_object_count(s->scene);
    t.m = calloc((size_t)t.count + 1, sizeof *t.m);
    for (int i = 0; t.m && i < t.count; i++) {
        rd_object_desc d;
        if (rd_scene_object_desc(s->scene, i, &d) == RD_OK)
            memcpy(t.m[i], d.transform, sizeof t.m[i]);
    }
    return t;
}

static int same(const float *a, const float *b)
{
    for (int k = 0; k < 16; k++)
        if (fabsf(a[k] - b[k]) > 1e-6f)
            return 0;
    return 1;
}

/* Moves `name` by delta: the document has it there, and the scene's transforms are those of a
 * scene built from the moved document; the other objects stayed. */
static void check_move(rd_context *ctx, app_project *p, const char *name, const double delta[3])
{
    char err[2048];
    int object = find(p, name);
    CHECK_MSG(object >= 0, "%s", name);
    if (object < 0)
        return;
    app_scene s, fresh;
    app_result r = app_scene_build(ctx, p, &s, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r != APP_OK)
        return;
    transforms before = transforms_of(&s);
    double at[3];
    for (int k = 0; k < 3; k++)
        at[k] = p->objects[object].position_mm[k] + delta[k];
    CHECK(app_scene_move_object(&s, p, object, at) == APP_OK);
    for (int k = 0; k < 3; k++)
        CHECK(p->objects[object].position_mm[k] == at[k]);
    transforms moved = transforms_of(&s);
    r = app_scene_build(ctx, p, &fresh, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    transforms want = r == APP_OK ? transforms_of(&fresh) : (transforms){0};
    CHECK(moved.count == want.count && moved.count == before.count);
    int parts = 0;
    for (int i = 0; moved.m && want.m && before.m && i < moved.count && i < want.count; i++) {
        CHECK_MSG(same(moved.m[i], want.m[i]), "%s", name);
        if (same(before.m[i], moved.m[i]))
            continue;
        parts++;
        for (int k = 0; k < 3; k++)
            CHECK(fabs(moved.m[i][12 + k] - before.m[i][12 + k] - delta[k] * 1e-3) < 1e-5);
    }
    CHECK_MSG(parts > 0, "%s", name);
    /* no such object: nothing moves */
    CHECK(app_scene_move_object(&s, p, p->object_count, at) == APP_ERR_NOT_FOUND);
    CHECK(app_scene_move_object(&s, p, -1, at) == APP_ERR_NOT_FOUND);
    free(before.m);
    free(moved.m);
    free(want.m);
    app_scene_release(ctx, &s);
    if (r == APP_OK)
        app_scene_release(ctx, &fresh);
}

int main(void)
{
    char *dir = tu_make_temp_dir();
    CHECK(dir != NULL);
    if (!dir)
        return check_report("scene_move");
    char db[1024];
    snprintf(db, sizeof db, "%s/catalog.sqlite", dir);
    setenv("TESSERA_CATALOG", db, 1); /* built from the shipped CSVs on first use */
    setenv("TESSERA_MODELS", dir, 1); /* no generated models: products are catalog boxes */
    rd_context *ctx = NULL;
    if (rd_context_create(NULL, &ctx) != RD_OK) {
        fprintf(stderr, "no context: %s\n", rd_last_error());
        return 1;
    }
    char err[1024];
    app_project p;
    if (app_project_read(DATA "/valid.json", &p, err, sizeof err) == APP_OK) {
        check_list(&p);
        check_move(ctx, &p, "towel-ring", (const double[3]){0, 250, -100});
        app_project_free(&p);
    } else {
        CHECK_MSG(0, "%s", err);
    }
    if (app_project_read(CLI_DATA "/with-model.json", &p, err, sizeof err) == APP_OK) {
        check_move(ctx, &p, "mesh-instances", (const double[3]){120, -40, 15}); /* parts */
        app_project_free(&p);
    } else {
        CHECK_MSG(0, "%s", err);
    }
    if (app_project_read(DATA "/v2_l_room.json", &p, err, sizeof err) == APP_OK) {
        /* a catalog box: drawn at its centre, moved with its document origin */
        check_move(ctx, &p, "wc", (const double[3]){300, -200, 0});
        app_project_free(&p);
    } else {
        CHECK_MSG(0, "%s", err);
    }
    rd_context_destroy(ctx);
    tu_remove_tree(dir);
    free(dir);
    return check_report("scene_move");
}
