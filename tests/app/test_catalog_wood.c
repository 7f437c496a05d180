/* A wooden product placed from the catalog carries its grain (docs/catalog.md "pattern",
 * docs/rendering.md "Wood grain"): the lookup of an oak vanity says wood with its grain along
 * the width, a tall oak cabinet along its height, a lacquered finish plain; `place` gives the
 * project a material with the pattern and grain, which a save and a read keep and the render
 * list hands to the renderers; the `pattern` word turns the grain. Uses a catalog built from
 * the shipped CSV files in a temporary folder. */
#include "test_util.h"

#include "app/design/placement.h"
#include "app/project/commands.h"
#include "app/scene/render_list.h"
#include "catalog/catalog.h"

static char tmp[] = "/tmp/tessera-catalog-wood-XXXXXX";

/* The CLI test's room (tests/cli/data/wood-room.json): 2400 x 2000, one camera. */
static void make_room(app_project *p)
{
    char err[1024] = "";
    CHECK_MSG(app_project_read(TESSERA_SOURCE_DIR "/tests/cli/data/wood-room.json", p, err,
                               sizeof err) == APP_OK,
              "%s", err);
}

static int run(app_project *p, app_history *h, cat_db *db, const char *text)
{
    app_script_env env = {app_placement_catalog_lookup, db, NULL, stdout};
    char err[1024] = "";
    app_result r =
        app_script_run(p, h, text, strlen(text), "test.edit", &env, NULL, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s: %s", text, err);
    return r == APP_OK;
}

static void lookup(cat_db *db, const char *article, const char *variant, app_product_info *info)
{
    app_product_ref ref;
    memset(&ref, 0, sizeof ref);
    snprintf(ref.manufacturer, sizeof ref.manufacturer, "Holmwood");
    snprintf(ref.article, sizeof ref.article, "%s", article);
    snprintf(ref.variant, sizeof ref.variant, "%s", variant);
    char err[512] = "";
    CHECK_MSG(app_placement_catalog_lookup(db, &ref, info, err, sizeof err) == APP_OK, "%s", err);
}

static void test_lookup(cat_db *db)
{
    app_product_info info;
    lookup(db, "HW1514", "OK", &info); /* vanity unit 800 x 460 x 520, oak */
    CHECK(info.has_material && info.pattern == APP_PATTERN_WOOD && info.grain_deg == 0.0f);
    lookup(db, "HW1522", "WN", &info); /* tall cabinet 350 x 330 x 1700, walnut */
    CHECK(info.pattern == APP_PATTERN_WOOD && info.grain_deg == 90.0f);
    lookup(db, "HW1514", "WG", &info); /* white high-gloss lacquer */
    CHECK(info.has_material && info.pattern == APP_PATTERN_NONE);
    lookup(db, "HW1522", "WG", &info); /* a tall lacquered front: no grain to turn */
    CHECK(info.pattern == APP_PATTERN_NONE && info.grain_deg == 0.0f);
}

static const app_material *material_of(const app_project *p, const char *object)
{
    for (int i = 0; i < p->object_count; i++)
        if (!strcmp(p->objects[i].name, object))
            return &p->materials[p->objects[i].material];
    return NULL;
}

/* The rd_material of the object's first item drawn in the project's material (a model's finish
 * parts, or the catalog box). */
static int drawn_material(const app_project *p, const char *object, rd_material *out)
{
    app_render_list l;
    char err[1024] = "";
    if (app_render_list_build(p, 0, &l, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "render list: %s", err);
        return 0;
    }
    int found = 0;
    for (int i = 0; i < l.item_count && !found; i++) {
        const app_render_item *it = &l.items[i];
        if (it->object >= 0 && !strcmp(p->objects[it->object].name, object) &&
            it->material.pattern == RD_PATTERN_WOOD) {
            *out = it->material;
            found = 1;
        }
    }
    app_render_list_free(&l);
    return found;
}

static void test_place(cat_db *db)
{
    app_project p;
    make_room(&p);
    app_history *h = app_history_create(0);
    run(&p, h, db,
        "place Holmwood HW1514 OK at 1000 0 snap wall as vanity\n"
        "place Holmwood HW1522 WN at 2200 0 snap wall as tall\n");
    const app_material *v = material_of(&p, "vanity"), *t = material_of(&p, "tall");
    CHECK(v && v->pattern == APP_PATTERN_WOOD && v->grain_deg == 0.0f);
    CHECK(t && t->pattern == APP_PATTERN_WOOD && t->grain_deg == 90.0f);

    /* The renderers get the grain: the vanity's along x, the tall cabinet's along z. */
    rd_material m;
    CHECK_MSG(drawn_material(&p, "vanity", &m) && m.grain_angle_deg == 0.0f,
              "the vanity is not drawn with the wood grain");
    CHECK_MSG(drawn_material(&p, "tall", &m) && m.grain_angle_deg == 90.0f,
              "the tall cabinet is not drawn with an upright grain");

    /* A save and a read keep both. */
    char path[sizeof tmp + 32];
    snprintf(path, sizeof path, "%s/wood.json", tmp);
    char err[1024] = "";
    CHECK_MSG(app_project_write(path, &p, err, sizeof err) == APP_OK, "%s", err);
    app_project q;
    CHECK_MSG(app_project_read(path, &q, err, sizeof err) == APP_OK, "%s", err);
    v = material_of(&q, "vanity");
    t = material_of(&q, "tall");
    CHECK(v && v->pattern == APP_PATTERN_WOOD && v->grain_deg == 0.0f);
    CHECK(t && t->pattern == APP_PATTERN_WOOD && t->grain_deg == 90.0f);
    app_project_free_all(&q);

    /* The edit word turns the grain and keeps it when not given; nonsense is refused. */
    char line[160];
    snprintf(line, sizeof line, "pattern \"%s\" wood grain 30\n", material_of(&p, "vanity")->name);
    run(&p, h, db, line);
    CHECK(material_of(&p, "vanity")->grain_deg == 30.0f);
    snprintf(line, sizeof line, "pattern \"%s\" wood\n", material_of(&p, "vanity")->name);
    run(&p, h, db, line);
    CHECK(material_of(&p, "vanity")->grain_deg == 30.0f);
    snprintf(line, sizeof line, "pattern \"%s\" wood grain sideways\n",
             material_of(&p, "vanity")->name);
    app_script_env env = {app_placement_catalog_lookup, db, NULL, stdout};
    CHECK(app_script_run(&p, h, line, strlen(line), "test.edit", &env, NULL, err, sizeof err) !=
              APP_OK &&
          tu_contains(err, "grain horizontal, vertical or 0 to 180 degrees, not \"sideways\""));
    app_history_destroy(h);
    app_project_free_all(&p);
}

int main(void)
{
    CHECK(mkdtemp(tmp) != NULL);
    char db_path[sizeof tmp + 32];
    snprintf(db_path, sizeof db_path, "%s/catalog.sqlite", tmp);
    setenv("TESSERA_CATALOG", db_path, 1);
    cat_db *db = NULL;
    char err[2048] = "";
    if (cat_catalog_open(db_path, TESSERA_SOURCE_DIR "/assets/catalog", &db, err, sizeof err) !=
        CAT_DB_OK) {
        fprintf(stderr, "cannot build the catalog: %s\n", err);
        return 1;
    }
    test_lookup(db);
    test_place(db);
    cat_db_close(db);
    char cmd[sizeof tmp + 16];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmp);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", tmp);
    return check_report("catalog wood");
}
