/* The `probe` edit word and APP_CMD_SET_PROBE (docs/editing.md): a material's
 * probe policy set, undone and redone exactly, bad values refused with the line and the
 * problem named (and nothing changed), two objects sharing the material both following (as
 * `reflect`), and the policy saved and read back. */
#include "test_util.h"

#include "app/project/commands.h"

#include <unistd.h>

static void make_room(app_project *p)
{
    char err[1024];
    CHECK_MSG(app_project_read(TESSERA_SOURCE_DIR "/tests/cli/data/edit-room.json", p, err,
                               sizeof err) == APP_OK,
              "%s", err);
}

static app_result run(app_project *p, app_history *h, const char *text, char *err, size_t err_size)
{
    app_script_env env = {NULL, NULL, NULL, stdout};
    return app_script_run(p, h, text, strlen(text), "probe.script", &env, NULL, err, err_size);
}

/* A line that must fail with `piece` in its message (and its line number) and leave the
 * document and the history as they were. */
static void refused(app_project *p, app_history *h, const char *line, const char *piece)
{
    app_project before;
    char err[1024] = "", diff[512];
    CHECK(app_project_copy(&before, p, err, sizeof err) == APP_OK);
    int undo = app_history_undo_count(h);
    CHECK(run(p, h, line, err, sizeof err) != APP_OK);
    printf("refused: %s\n", err);
    CHECK_MSG(tu_contains(err, piece), "%s", err);
    CHECK_MSG(tu_contains(err, "probe.script:1:"), "%s", err);
    CHECK_MSG(app_project_equal(&before, p, diff, sizeof diff), "%s", diff);
    CHECK(app_history_undo_count(h) == undo);
    app_project_free_all(&before);
}

static void check_policy(const app_material *m, int update, int every, int resolution,
                         int correction)
{
    CHECK_MSG(m->probe_update == update, "%s", m->name);
    CHECK_MSG(m->probe_every == every, "%s", m->name);
    CHECK_MSG(m->probe_resolution == resolution, "%s", m->name);
    CHECK_MSG(m->correction == correction, "%s", m->name);
}

/* A material with a prepared cube map (static probe): leaving static drops the map so the
 * file reads back what was set; undo brings map and policy back; static again needs the map. */
static void test_static_map(void)
{
    char err[1024], diff[512], path[1100];
    char *dir = tu_make_temp_dir();
    CHECK(dir != NULL);
    if (!dir)
        return;
    /* The reader checks the +X face exists; the faces are read only when rendering. */
    snprintf(path, sizeof path, "%s/env_posx.png", dir);
    CHECK(tu_write_file(path, "x", 1));
    static const char doc[] =
        "{\"version\": 1, \"name\": \"static\",\n"
        " \"room\": {\"width\": 3000, \"depth\": 2500, \"height\": 2500},\n"
        " \"materials\": {\"chrome\": {\"reflectivity\": 0.8, \"probe\": {\"map\": "
        "\"env_*.png\", \"resolution\": 64}}},\n"
        " \"objects\": [{\"name\": \"ball\", \"shape\": \"sphere\", \"position\": [1500, 1250, "
        "500], \"size\": [300, 300, 300], \"material\": \"chrome\"}],\n"
        " \"lights\": [], \"cameras\": [{\"name\": \"door\", \"position\": [1500, 2400, 1600], "
        "\"target\": [1500, 0, 900]}]}\n";
    snprintf(path, sizeof path, "%s/static.json", dir);
    CHECK(tu_write_file(path, doc, sizeof doc - 1));
    app_project p, start, back;
    CHECK_MSG(app_project_read(path, &p, err, sizeof err) == APP_OK, "%s", err);
    int m = app_project_find_material(&p, "chrome");
    CHECK(m >= 0 && p.materials[m].probe_update == APP_PROBE_STATIC && p.materials[m].probe_map[0]);
    if (m < 0) {
        tu_remove_tree(dir);
        free(dir);
        return;
    }
    CHECK(app_project_copy(&start, &p, err, sizeof err) == APP_OK);
    app_history *h = app_history_create(0);
    /* Static stays static with its map when only the resolution changes. */
    CHECK_MSG(run(&p, h, "probe chrome resolution 256\n", err, sizeof err) == APP_OK, "%s", err);
    CHECK(p.materials[m].probe_update == APP_PROBE_STATIC && p.materials[m].probe_map[0] &&
          p.materials[m].probe_resolution == 256);
    CHECK_MSG(run(&p, h, "probe chrome update time-sliced\n", err, sizeof err) == APP_OK, "%s",
              err);
    CHECK(p.materials[m].probe_update == APP_PROBE_TIME_SLICED && !p.materials[m].probe_map[0]);
    CHECK_MSG(app_project_write(path, &p, err, sizeof err) == APP_OK, "%s", err);
    CHECK_MSG(app_project_read(path, &back, err, sizeof err) == APP_OK, "%s", err);
    CHECK(back.materials[m].probe_update == APP_PROBE_TIME_SLICED &&
          !back.materials[m].probe_map[0]);
    app_project_free_all(&back);
    /* Without its map now, static is refused; undo brings the map back, and static works. */
    refused(&p, h, "probe chrome update static\n", "needs a prepared map");
    CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
    CHECK(p.materials[m].probe_update == APP_PROBE_STATIC && p.materials[m].probe_map[0]);
    CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
    CHECK_MSG(app_project_equal(&start, &p, diff, sizeof diff), "%s", diff);
    CHECK(app_history_redo(h, &p, err, sizeof err) == APP_OK);
    CHECK_MSG(run(&p, h, "probe chrome update static correction sphere\n", err, sizeof err) ==
                  APP_OK,
              "%s", err);
    app_history_destroy(h);
    app_project_free_all(&start);
    app_project_free_all(&p);
    tu_remove_tree(dir);
    free(dir);
}

int main(void)
{
    test_static_map();
    app_project p;
    char err[1024], diff[512];
    make_room(&p);
    app_history *h = app_history_create(0);
    /* Two boxes sharing one reflective material. */
    CHECK_MSG(run(&p, h,
                  "add box a at 500 500 400 size 300 300 800 material default\n"
                  "add box b at 2000 500 400 size 300 300 800 material default\n"
                  "reflect default 0.4 gloss 0.8\n",
                  err, sizeof err) == APP_OK,
              "%s", err);
    int m = app_project_find_material(&p, "default");
    CHECK(m >= 0 && p.objects[0].material == m && p.objects[1].material == m);
    check_policy(&p.materials[m], APP_PROBE_DEFAULT, 0, 0, APP_CORRECTION_DEFAULT);
    app_project start;
    CHECK(app_project_copy(&start, &p, err, sizeof err) == APP_OK);

    /* Each line is one undo step that changes the material only. */
    struct {
        const char *line;
        int update, every, resolution, correction;
    } steps[] = {
        {"probe default update time-sliced\n", APP_PROBE_TIME_SLICED, 0, 0, 0},
        {"probe default resolution 128 correction sphere\n", APP_PROBE_TIME_SLICED, 0, 128,
         APP_CORRECTION_SPHERE},
        /* `every N` alone selects every-frame */
        {"probe default every 4\n", APP_PROBE_EVERY_FRAME, 4, 128, APP_CORRECTION_SPHERE},
        {"probe default update once resolution auto correction depth\n", APP_PROBE_ONCE, 0, 0,
         APP_CORRECTION_DEPTH},
        {"probe default update every-frame every 2 correction box resolution 512\n",
         APP_PROBE_EVERY_FRAME, 2, 512, APP_CORRECTION_BOX},
        {"probe \"default\" update on-change correction none\n", APP_PROBE_ON_CHANGE, 0, 512,
         APP_CORRECTION_NONE},
    };
    int n = (int)(sizeof steps / sizeof steps[0]);
    app_project after[6];
    for (int i = 0; i < n; i++) {
        int undo = app_history_undo_count(h);
        CHECK_MSG(run(&p, h, steps[i].line, err, sizeof err) == APP_OK, "%s", err);
        CHECK(app_history_undo_count(h) == undo + 1);
        CHECK(app_history_last_changed(h) == APP_CHANGED_MATERIALS);
        CHECK_MSG(!strcmp(app_history_undo_label(h), "set the probe of \"default\""), "%s",
                  app_history_undo_label(h));
        check_policy(&p.materials[m], steps[i].update, steps[i].every, steps[i].resolution,
                     steps[i].correction);
        /* The reflection itself is untouched; both boxes still share the material. */
        CHECK(p.materials[m].reflectivity == 0.4f && p.materials[m].glossiness == 0.8f);
        CHECK(p.objects[0].material == m && p.objects[1].material == m);
        CHECK(app_project_copy(&after[i], &p, err, sizeof err) == APP_OK);
    }

    /* Undo steps back through each state exactly; redo forward again. */
    for (int i = n - 1; i >= 0; i--) {
        CHECK_MSG(app_project_equal(&after[i], &p, diff, sizeof diff), "%s", diff);
        CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
    }
    CHECK_MSG(app_project_equal(&start, &p, diff, sizeof diff), "%s", diff);
    for (int i = 0; i < n; i++) {
        CHECK(app_history_redo(h, &p, err, sizeof err) == APP_OK);
        CHECK_MSG(app_project_equal(&after[i], &p, diff, sizeof diff), "%s", diff);
    }
    CHECK(app_history_redo(h, &p, err, sizeof err) == APP_ERR_NOT_FOUND);

    /* Bad values: the line, the word and the problem are named; nothing changes. */
    refused(&p, h, "probe default update sometimes\n", "update is default, every-frame");
    refused(&p, h, "probe default update static\n", "needs a prepared map");
    refused(&p, h, "probe default every 0\n", "every is a whole number");
    refused(&p, h, "probe default every 2.5\n", "not \"2.5\"");
    refused(&p, h, "probe default every -3\n", "every is a whole number");
    refused(&p, h, "probe default update once every 4\n", "every N goes with update every-frame");
    refused(&p, h, "probe default resolution 100\n", "power of two");
    refused(&p, h, "probe default resolution 8192\n", "power of two");
    refused(&p, h, "probe default resolution\n", "resolution needs a value");
    refused(&p, h, "probe default correction cone\n", "correction is default, none, box");
    refused(&p, h, "probe default\n", "nothing to set");
    refused(&p, h, "probe default gloss 0.5\n", "unexpected word \"gloss\"");
    refused(&p, h, "probe chrome update once\n", "no material named \"chrome\"");
    refused(&p, h, "probe\n", "a word is missing");

    /* The command itself checks what the words cannot reach (a UI builds descs directly). */
    app_command_desc d = {.type = APP_CMD_SET_PROBE, .index = m, .probe_update = 9};
    CHECK(app_command_check(&p, &d, err, sizeof err) == APP_ERR_SCHEMA &&
          tu_contains(err, "not a policy"));
    d.probe_update = APP_PROBE_ONCE;
    d.probe_resolution = 96;
    CHECK(app_command_check(&p, &d, err, sizeof err) == APP_ERR_SCHEMA &&
          tu_contains(err, "power of two"));
    d.probe_resolution = 64;
    d.correction = 7;
    CHECK(app_command_check(&p, &d, err, sizeof err) == APP_ERR_SCHEMA &&
          tu_contains(err, "correction"));
    d.correction = APP_CORRECTION_BOX;
    d.probe_every = -1;
    CHECK(app_command_check(&p, &d, err, sizeof err) == APP_ERR_SCHEMA);
    d.probe_every = 0;
    d.index = p.material_count;
    CHECK(app_command_check(&p, &d, err, sizeof err) == APP_ERR_NOT_FOUND);
    d.index = m;
    CHECK_MSG(app_command_check(&p, &d, err, sizeof err) == APP_OK, "%s", err);

    /* Saved and read back: the file stores the policy. */
    char path[] = "/tmp/tessera-probe-words-XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    close(fd);
    CHECK_MSG(run(&p, h, "probe default update every-frame every 3 resolution 256\n", err,
                  sizeof err) == APP_OK,
              "%s", err);
    CHECK_MSG(app_project_write(path, &p, err, sizeof err) == APP_OK, "%s", err);
    app_project back;
    CHECK_MSG(app_project_read(path, &back, err, sizeof err) == APP_OK, "%s", err);
    int bm = app_project_find_material(&back, "default");
    CHECK(bm >= 0);
    if (bm >= 0)
        check_policy(&back.materials[bm], APP_PROBE_EVERY_FRAME, 3, 256, APP_CORRECTION_NONE);
    app_project_free_all(&back);
    /* Every policy the words can set survives the file. */
    const char *policies[] = {"update once correction depth resolution 64",
                              "update time-sliced correction sphere resolution 1",
                              "update on-change correction box resolution 4096",
                              "update default correction default resolution auto"};
    for (int i = 0; i < 4; i++) {
        char line[160];
        snprintf(line, sizeof line, "probe default %s\n", policies[i]);
        CHECK_MSG(run(&p, h, line, err, sizeof err) == APP_OK, "%s", err);
        CHECK_MSG(app_project_write(path, &p, err, sizeof err) == APP_OK, "%s", err);
        CHECK_MSG(app_project_read(path, &back, err, sizeof err) == APP_OK, "%s", err);
        bm = app_project_find_material(&back, "default");
        CHECK(bm >= 0);
        if (bm >= 0)
            check_policy(&back.materials[bm], p.materials[m].probe_update,
                         p.materials[m].probe_every, p.materials[m].probe_resolution,
                         p.materials[m].correction);
        app_project_free_all(&back);
    }
    unlink(path);

    for (int i = 0; i < n; i++)
        app_project_free_all(&after[i]);
    app_project_free_all(&start);
    app_history_destroy(h);
    app_project_free_all(&p);
    return check_report("edit_probe");
}
