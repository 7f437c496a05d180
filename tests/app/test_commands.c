/* Commands with undo and redo: random sequences of edits, valid and invalid,
 * on a project with every kind of element; undoing all of them must give back the exact
 * original document, redoing all of them the exact edited one. Plus the history's rules:
 * redo cleared by a new command, the step limit, groups, labels. */
#include "test_util.h"

#include "app/project/commands.h"

#include <math.h>

/* The reader's defaults for a material (project_defaults.c). */
static void default_material(app_material *m)
{
    memset(m, 0, sizeof *m);
    for (int k = 0; k < 3; k++)
        m->diffuse[k] = m->ambient[k] = 0.8f;
    m->shininess = 32;
    m->texture_size_mm[0] = m->texture_size_mm[1] = 1000;
    m->glossiness = 1;
    m->ior = 1.5f;
}

/* An L-shaped room with two materials, three objects (one a catalog product), a door, a
 * window, a pre-wall with a tiled front, a niche and two tilings. */
static void make_project(app_project *p)
{
    memset(p, 0, sizeof *p);
    p->version = p->file_version = 1;
    snprintf(p->name, sizeof p->name, "undo test");
    static const app_point2 l[6] = {{0, 0},       {3000, 0},    {3000, 1500},
                                    {1800, 1500}, {1800, 2600}, {0, 2600}};
    p->plan.corner_count = 6;
    p->plan.corners = malloc(sizeof l);
    memcpy(p->plan.corners, l, sizeof l);
    p->plan.height_mm = 2500;
    p->plan.wall_thickness_mm = 120;
    p->room.width_mm = 3000;
    p->room.depth_mm = 2600;
    p->room.height_mm = 2500;
    p->plan.opening_count = 2;
    p->plan.openings = calloc(2, sizeof *p->plan.openings);
    snprintf(p->plan.openings[0].name, 64, "door");
    p->plan.openings[0].wall = 5; /* (0,2600) -> (0,0) */
    p->plan.openings[0].offset_mm = 200;
    p->plan.openings[0].width_mm = 800;
    p->plan.openings[0].height_mm = 2000;
    snprintf(p->plan.openings[1].name, 64, "window");
    p->plan.openings[1].type = APP_OPENING_WINDOW;
    p->plan.openings[1].wall = 0;
    p->plan.openings[1].offset_mm = 1200;
    p->plan.openings[1].width_mm = 600;
    p->plan.openings[1].sill_mm = 1200;
    p->plan.openings[1].height_mm = 900;
    p->plan.openings[1].light[0] = 1.5f;
    p->plan.prewall_count = 1;
    p->plan.prewalls = calloc(1, sizeof *p->plan.prewalls);
    snprintf(p->plan.prewalls[0].name, 64, "wc-box");
    p->plan.prewalls[0].wall = 1;
    p->plan.prewalls[0].offset_mm = 200;
    p->plan.prewalls[0].width_mm = 800;
    p->plan.prewalls[0].depth_mm = 200;
    p->plan.prewalls[0].height_mm = 1100;
    p->plan.niche_count = 1;
    p->plan.niches = calloc(1, sizeof *p->plan.niches);
    snprintf(p->plan.niches[0].name, 64, "soap");
    p->plan.niches[0].wall = 4;
    p->plan.niches[0].offset_mm = 300;
    p->plan.niches[0].width_mm = 300;
    p->plan.niches[0].sill_mm = 1000;
    p->plan.niches[0].height_mm = 400;
    p->plan.niches[0].depth_mm = 80;
    p->tiling_count = 2;
    p->tilings = calloc(2, sizeof *p->tilings);
    snprintf(p->tilings[0].name, 64, "floor");
    snprintf(p->tilings[0].surface, 96, "floor");
    snprintf(p->tilings[0].product.manufacturer, 64, "Terrazza Ceramiche");
    snprintf(p->tilings[0].product.article, 40, "TZ61000");
    p->tilings[0].grout_mm = 3;
    p->tilings[0].grout_color[0] = p->tilings[0].grout_color[1] = p->tilings[0].grout_color[2] =
        0.5f;
    snprintf(p->tilings[1].name, 64, "box front");
    snprintf(p->tilings[1].surface, 96, "prewall:wc-box:front");
    p->tilings[1].product = p->tilings[0].product;
    p->tilings[1].pattern = APP_PATTERN_HALF_OFFSET;
    p->material_count = 2;
    p->materials = calloc(2, sizeof *p->materials);
    for (int i = 0; i < 2; i++)
        default_material(&p->materials[i]);
    snprintf(p->materials[0].name, 64, "white");
    snprintf(p->materials[1].name, 64, "chrome");
    p->materials[1].reflectivity = 0.8f;
    p->materials[1].glossiness = 0.9f;
    p->object_count = 3;
    p->objects = calloc(3, sizeof *p->objects);
    const char *names[3] = {"basin", "wc", "stool"};
    for (int i = 0; i < 3; i++) {
        app_object *o = &p->objects[i];
        snprintf(o->name, sizeof o->name, "%s", names[i]);
        o->shape = i == 2 ? APP_SHAPE_CYLINDER : APP_SHAPE_MODEL;
        o->position_mm[0] = 500 + 700 * i;
        o->position_mm[2] = i == 0 ? 675 : 0;
        o->scale[0] = o->scale[1] = o->scale[2] = 1;
        o->material = i == 2 ? 1 : 0;
    }
    p->objects[2].size_mm[0] = p->objects[2].size_mm[1] = 350;
    p->objects[2].size_mm[2] = 450;
    for (int i = 0; i < 2; i++) {
        p->objects[i].has_product = 1;
        snprintf(p->objects[i].product.manufacturer, 64, "Cerana");
        snprintf(p->objects[i].product.article, 40, i == 0 ? "CE410301" : "CE412901");
        snprintf(p->objects[i].product.variant, 16, "WH");
    }
    p->light_count = 1;
    p->lights = calloc(1, sizeof *p->lights);
    snprintf(p->lights[0].name, 64, "ceiling");
    p->lights[0].type = APP_LIGHT_POINT;
    p->lights[0].position_mm[0] = 1000;
    p->lights[0].position_mm[1] = 1000;
    p->lights[0].position_mm[2] = 2300;
    p->lights[0].direction[2] = -1;
    p->lights[0].intensity = 1;
    for (int k = 0; k < 3; k++)
        p->lights[0].color[k] = p->lights[0].specular[k] = 1;
    p->lights[0].attenuation[0] = p->lights[0].attenuation[2] = 1;
    p->lights[0].inner_deg = 25;
    p->lights[0].outer_deg = 35;
    p->camera_count = 1;
    p->cameras = calloc(1, sizeof *p->cameras);
    snprintf(p->cameras[0].name, 64, "door");
    p->cameras[0].fov_deg = 60;
    p->cameras[0].position_mm[0] = 500;
    p->cameras[0].position_mm[1] = 2400;
    p->cameras[0].position_mm[2] = 1600;
    p->cameras[0].target_mm[0] = 1500;
    p->cameras[0].up[2] = 1;
    p->render.ambient[0] = p->render.ambient[1] = p->render.ambient[2] = 0.1f;
    p->render.white = 4;
    p->render.width = 640;
    p->render.height = 480;
    p->render.supersample = 1;
}

static unsigned long long rng_state;
static unsigned next_u32(void)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (unsigned)(rng_state >> 33);
}
static int rnd(int n)
{
    return n > 0 ? (int)(next_u32() % (unsigned)n) : 0;
}
static double rnd_mm(double lo, double hi)
{
    return lo + (hi - lo) * (next_u32() / 4294967296.0);
}

/* A random command, sometimes invalid (index out of range, bad numbers, overlapping, a
 * crossing plan). */
static app_command_desc random_desc(const app_project *p, int serial)
{
    app_command_desc d;
    memset(&d, 0, sizeof d);
    d.type = (app_command_type)rnd(APP_CMD_COUNT);
    int count = 0;
    switch (d.type) {
    case APP_CMD_ADD_OBJECT:
    case APP_CMD_SET_OBJECT:
        snprintf(d.object.name, sizeof d.object.name, "obj-%d", serial % 7);
        d.object.shape = (app_shape)rnd(5);
        for (int k = 0; k < 3; k++) {
            d.object.position_mm[k] = rnd_mm(0, 2500);
            d.object.size_mm[k] = rnd_mm(10, 800);
            d.object.scale[k] = 1;
        }
        d.object.material = rnd(p->material_count + 1);
        count = p->object_count + 1;
        break;
    case APP_CMD_REMOVE_OBJECT:
    case APP_CMD_MOVE_OBJECT:
    case APP_CMD_ROTATE_OBJECT:
    case APP_CMD_SET_PRODUCT:
    case APP_CMD_SET_VARIANT:
        count = p->object_count;
        break;
    case APP_CMD_SET_TILING:
        snprintf(d.tiling.name, sizeof d.tiling.name, "t%d", serial);
        snprintf(d.tiling.surface, sizeof d.tiling.surface, "%s",
                 rnd(4) == 0 ? "wall:99"
                 : rnd(2)    ? "wall:2"
                             : "prewall:wc-box:top");
        d.tiling.pattern = (app_tile_pattern)rnd(6);
        snprintf(d.tiling.product.manufacturer, sizeof d.tiling.product.manufacturer,
                 "Terrazza Ceramiche");
        snprintf(d.tiling.product.article, sizeof d.tiling.product.article, "%s",
                 rnd(8) ? "TZ61002" : ""); /* sometimes refused: no article */
        d.tiling.grout_mm = rnd_mm(0, 8);
        count = p->tiling_count + 1;
        break;
    case APP_CMD_ADD_OPENING:
        snprintf(d.opening.name, sizeof d.opening.name, "o%d", serial % 5);
        d.opening.wall = rnd(7);
        d.opening.offset_mm = rnd_mm(0, 1500);
        d.opening.width_mm = rnd_mm(300, 1000);
        d.opening.height_mm = rnd_mm(500, 2100);
        d.opening.type = (app_opening_type)rnd(2);
        break;
    case APP_CMD_MOVE_OPENING:
        d.wall = rnd(7);
        d.offset_mm = rnd_mm(0, 2000);
        count = p->plan.opening_count;
        break;
    case APP_CMD_MOVE_CORNER:
        d.corner.x = rnd_mm(-500, 3500);
        d.corner.y = rnd_mm(-500, 3000);
        count = p->plan.corner_count;
        break;
    case APP_CMD_ADD_PREWALL:
        snprintf(d.prewall.name, sizeof d.prewall.name, "pw%d", serial % 4);
        d.prewall.wall = rnd(7);
        d.prewall.offset_mm = rnd_mm(0, 1000);
        d.prewall.width_mm = rnd_mm(100, 1200);
        d.prewall.depth_mm = rnd_mm(100, 300);
        d.prewall.height_mm = rnd_mm(800, 1300);
        break;
    case APP_CMD_ADD_NICHE:
        snprintf(d.niche.name, sizeof d.niche.name, "n%d", serial % 4);
        d.niche.wall = rnd(7);
        d.niche.offset_mm = rnd_mm(0, 1000);
        d.niche.width_mm = rnd_mm(100, 600);
        d.niche.sill_mm = rnd_mm(0, 1500);
        d.niche.height_mm = rnd_mm(100, 600);
        d.niche.depth_mm = rnd_mm(20, 160);
        break;
    case APP_CMD_ADD_MATERIAL:
        default_material(&d.material);
        snprintf(d.material.name, sizeof d.material.name, "m%d", serial % 6);
        d.material.diffuse[0] = (float)rnd_mm(0, 1);
        if (rnd(6) == 0)
            d.material.ior = 0; /* refused: 1 to 3 */
        break;
    case APP_CMD_SET_REFLECTION:
        count = p->material_count;
        d.reflectivity = (float)rnd_mm(-0.1, 1.1);
        d.glossiness = (float)rnd_mm(0, 1);
        d.blend = rnd(4);
        break;
    case APP_CMD_SET_PATTERN: /* sometimes refused (3 is no pattern) */
        count = p->material_count;
        d.material_pattern = rnd(4);
        break;
    case APP_CMD_SET_PROBE: /* cmd_probe.c; sometimes refused (static without a map, 96) */
        count = p->material_count;
        d.probe_update = rnd(6);
        d.probe_every = rnd(5);
        d.probe_resolution = rnd(3) == 0 ? 96 : (rnd(2) ? 0 : 128);
        d.correction = rnd(5);
        break;
    case APP_CMD_REMOVE_OPENING:
        count = p->plan.opening_count;
        break;
    case APP_CMD_REMOVE_PREWALL:
        count = p->plan.prewall_count;
        break;
    case APP_CMD_REMOVE_NICHE:
        count = p->plan.niche_count;
        break;
    default: /* tiling edits */
        count = p->tiling_count;
        break;
    }
    /* Mostly a valid index, sometimes one past the end or -1. */
    d.index = rnd(8) == 0 ? count + rnd(3) : rnd(8) == 0 ? -1 : rnd(count > 0 ? count : 1);
    for (int k = 0; k < 3; k++)
        d.position_mm[k] = rnd(20) == 0 ? NAN : rnd_mm(-100, 3000);
    d.rotation_deg = rnd_mm(-180, 180);
    snprintf(d.product.manufacturer, sizeof d.product.manufacturer, "Cerana");
    snprintf(d.product.article, sizeof d.product.article, "CE4%05d", rnd(100000));
    snprintf(d.variant, sizeof d.variant, "%s", rnd(2) ? "WH" : "MW");
    d.pattern = (app_tile_pattern)rnd(7); /* 6 is out of range */
    d.grout_mm = rnd_mm(-1, 10);
    d.grout_color[0] = (float)rnd_mm(0, 1);
    d.align = (app_tile_align)rnd(3);
    d.origin_mm[0] = rnd_mm(-500, 500);
    return d;
}

static char *tmp_dir;

static void test_random_sequences(void)
{
    int applied_total = 0, refused_total = 0, kinds_applied[APP_CMD_COUNT] = {0};
    for (int seed = 1; seed <= 150; seed++) {
        rng_state = (unsigned long long)seed * 0x9E3779B97F4A7C15ULL;
        app_project p, original, copy;
        make_project(&p);
        char err[512], diff[512];
        CHECK(app_project_copy(&original, &p, err, sizeof err) == APP_OK);
        app_history *h = app_history_create(1000);
        int applied = 0;
        for (int i = 0; i < 60; i++) {
            app_command_desc d = random_desc(&p, i);
            CHECK(app_project_copy(&copy, &p, err, sizeof err) == APP_OK);
            app_result r = app_history_do(h, &p, &d, err, sizeof err);
            if (r == APP_OK) {
                applied++;
                kinds_applied[d.type]++;
            } else {
                refused_total++;
                /* A refused command changes nothing and says why. */
                CHECK_MSG(app_project_equal(&copy, &p, diff, sizeof diff), "%s", diff);
                CHECK(err[0] != 0);
            }
            app_project_free_all(&copy);
            /* Now and then undo and redo in the middle: a redo gives back the same document. */
            if (r == APP_OK && rnd(5) == 0) {
                CHECK(app_project_copy(&copy, &p, err, sizeof err) == APP_OK);
                CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
                CHECK(app_history_redo(h, &p, err, sizeof err) == APP_OK);
                CHECK_MSG(app_project_equal(&copy, &p, diff, sizeof diff), "%s", diff);
                app_project_free_all(&copy);
            }
        }
        applied_total += applied;
        CHECK(app_history_undo_count(h) == applied);
        /* Whatever the commands allow can be saved and read back. */
        {
            char path[256];
            snprintf(path, sizeof path, "%s/edited-%d.json", tmp_dir, seed);
            app_result w = app_project_write(path, &p, err, sizeof err);
            CHECK_MSG(w == APP_OK, "%s", err);
            app_project back;
            if (w == APP_OK) {
                app_result rr = app_project_read(path, &back, err, sizeof err);
                CHECK_MSG(rr == APP_OK, "%s", err);
                if (rr == APP_OK) {
                    CHECK(back.object_count == p.object_count &&
                          back.tiling_count == p.tiling_count &&
                          back.plan.corner_count == p.plan.corner_count &&
                          back.plan.opening_count == p.plan.opening_count &&
                          back.plan.prewall_count == p.plan.prewall_count &&
                          back.plan.niche_count == p.plan.niche_count);
                    app_project_free_all(&back);
                }
            }
        }
        app_project edited;
        CHECK(app_project_copy(&edited, &p, err, sizeof err) == APP_OK);
        for (int i = 0; i < applied; i++)
            CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
        CHECK(app_history_undo(h, &p, err, sizeof err) == APP_ERR_NOT_FOUND);
        CHECK_MSG(app_project_equal(&original, &p, diff, sizeof diff), "%s", diff);
        for (int i = 0; i < applied; i++)
            CHECK(app_history_redo(h, &p, err, sizeof err) == APP_OK);
        CHECK(app_history_redo(h, &p, err, sizeof err) == APP_ERR_NOT_FOUND);
        CHECK_MSG(app_project_equal(&edited, &p, diff, sizeof diff), "%s", diff);
        while (app_history_undo_count(h) > 0)
            CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
        CHECK_MSG(app_project_equal(&original, &p, diff, sizeof diff), "%s", diff);
        app_history_destroy(h);
        app_project_free_all(&edited);
        app_project_free_all(&original);
        app_project_free_all(&p);
    }
    printf("random sequences: %d commands applied, %d refused\n", applied_total, refused_total);
    /* The sequences must have exercised every command type. */
    for (int t = 0; t < APP_CMD_COUNT; t++) {
        CHECK_MSG(kinds_applied[t] > 0, "%s", app_command_type_name((app_command_type)t));
        printf("  %-18s %d\n", app_command_type_name((app_command_type)t), kinds_applied[t]);
    }
}

static void test_history_rules(void)
{
    app_project p, original;
    char err[512], diff[512];
    make_project(&p);
    CHECK(app_project_copy(&original, &p, err, sizeof err) == APP_OK);
    app_history *h = app_history_create(3);
    CHECK(app_history_undo_count(h) == 0 && !strcmp(app_history_undo_label(h), ""));
    app_command_desc d = {.type = APP_CMD_MOVE_OBJECT, .index = 0, .position_mm = {900, 0, 675}};
    CHECK(app_history_do(h, &p, &d, err, sizeof err) == APP_OK);
    CHECK(!strcmp(app_history_undo_label(h), "move \"basin\""));
    CHECK(p.objects[0].position_mm[0] == 900);
    CHECK(app_history_last_changed(h) == APP_CHANGED_OBJECTS);
    /* A dry run says what a do would say and changes nothing. */
    app_command_desc far = d;
    far.index = 7;
    CHECK(app_command_check(&p, &far, err, sizeof err) == APP_ERR_NOT_FOUND);
    CHECK(tu_contains(err, "no object 7"));
    CHECK(app_command_check(&p, &d, err, sizeof err) == APP_OK);
    CHECK(p.objects[0].position_mm[0] == 900);
    /* A redo stack is cleared by a new command. */
    CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
    CHECK(app_history_redo_count(h) == 1);
    CHECK(!strcmp(app_history_redo_label(h), "move \"basin\""));
    d.position_mm[0] = 950;
    CHECK(app_history_do(h, &p, &d, err, sizeof err) == APP_OK);
    CHECK(app_history_redo_count(h) == 0);
    /* The limit: 3 steps kept of 5. */
    for (int i = 0; i < 4; i++) {
        d.position_mm[0] = 1000 + i;
        CHECK(app_history_do(h, &p, &d, err, sizeof err) == APP_OK);
    }
    CHECK(app_history_undo_count(h) == 3);
    for (int i = 0; i < 3; i++)
        CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
    CHECK(p.objects[0].position_mm[0] == 1000); /* after the 2nd of the 4 moves */
    CHECK(app_history_undo(h, &p, err, sizeof err) == APP_ERR_NOT_FOUND);
    CHECK(tu_contains(err, "nothing to undo"));
    app_history_clear(h);
    /* A group is one step: a pre-wall removed (with its face's tiling) and an object moved. */
    app_project_free_all(&p);
    CHECK(app_project_copy(&p, &original, err, sizeof err) == APP_OK);
    app_history_begin_group(h, "rebuild the WC wall");
    app_command_desc rm = {.type = APP_CMD_REMOVE_PREWALL, .index = 0};
    CHECK(app_history_do(h, &p, &rm, err, sizeof err) == APP_OK);
    CHECK(p.plan.prewall_count == 0 && p.tiling_count == 1);
    CHECK(app_history_last_changed(h) == (APP_CHANGED_PLAN | APP_CHANGED_TILINGS));
    CHECK(app_history_do(h, &p, &d, err, sizeof err) == APP_OK);
    CHECK(app_history_end_group(h, err, sizeof err) == APP_OK);
    CHECK(app_history_undo_count(h) == 1);
    CHECK(!strcmp(app_history_undo_label(h), "rebuild the WC wall"));
    CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
    CHECK_MSG(app_project_equal(&original, &p, diff, sizeof diff), "%s", diff);
    /* A cancelled group leaves no trace: the document as before, no undo step, the redo
     * stack kept. */
    CHECK(app_history_redo_count(h) == 1);
    app_history_begin_group(h, "drag");
    for (int i = 0; i < 5; i++) {
        d.position_mm[0] = 1100 + 10 * i;
        CHECK(app_history_do(h, &p, &d, err, sizeof err) == APP_OK);
    }
    CHECK(app_history_do(h, &p, &rm, err, sizeof err) == APP_OK);
    CHECK(app_history_abort_group(h, &p, err, sizeof err) == APP_OK);
    CHECK_MSG(app_project_equal(&original, &p, diff, sizeof diff), "%s", diff);
    CHECK(app_history_undo_count(h) == 0 && app_history_redo_count(h) == 1);
    /* Specific refusals, each naming the rule. */
    app_command_desc bad = {.type = APP_CMD_MOVE_CORNER, .index = 3, .corner = {1800, -500}};
    CHECK(app_history_do(h, &p, &bad, err, sizeof err) == APP_ERR_SCHEMA);
    printf("crossing plan: %s\n", err);
    CHECK(tu_contains(err, "cross") || tu_contains(err, "counter-clockwise"));
    app_command_desc overlap = {.type = APP_CMD_ADD_OPENING};
    overlap.opening = p.plan.openings[1];
    snprintf(overlap.opening.name, 64, "window 2");
    overlap.opening.offset_mm = 1500;
    CHECK(app_history_do(h, &p, &overlap, err, sizeof err) == APP_ERR_SCHEMA);
    CHECK(tu_contains(err, "overlap"));
    app_command_desc tile = {.type = APP_CMD_SET_TILING, .index = -1};
    snprintf(tile.tiling.surface, 96, "wall:6");
    CHECK(app_history_do(h, &p, &tile, err, sizeof err) == APP_ERR_NOT_FOUND);
    CHECK(tu_contains(err, "wall:6"));
    app_command_desc variant = {.type = APP_CMD_SET_VARIANT, .index = 2};
    CHECK(app_history_do(h, &p, &variant, err, sizeof err) == APP_ERR_SCHEMA);
    CHECK(tu_contains(err, "stool"));
    /* Moving a corner keeps the room box in step with the plan. */
    app_command_desc corner = {.type = APP_CMD_MOVE_CORNER, .index = 1, .corner = {3200, 0}};
    CHECK(app_history_do(h, &p, &corner, err, sizeof err) == APP_OK);
    CHECK(p.room.width_mm == 3200);
    CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
    CHECK(p.room.width_mm == 3000);
    CHECK_MSG(app_project_equal(&original, &p, diff, sizeof diff), "%s", diff);
    app_history_destroy(h);
    app_project_free_all(&original);
    app_project_free_all(&p);
}

int main(void)
{
    tmp_dir = tu_make_temp_dir();
    test_history_rules();
    test_random_sequences();
    tu_remove_tree(tmp_dir);
    free(tmp_dir);
    return check_report("commands");
}
