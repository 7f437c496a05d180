/* The tile band and border-row edit words (docs/editing.md: `tile SURFACE band FROM TO`,
 * `tile SURFACE border add|K|remove ...`): each is one undo step through APP_CMD_SET_TILING,
 * a refused line changes nothing, and the rows survive a save and a read. */
#include "test_util.h"

#include "app/project/commands.h"
#include "placement_test_catalog.h"

#include <unistd.h>

static const char *csv = TESSERA_SOURCE_DIR "/assets/catalog/fixtures.csv";
static const char *tiles_csv = TESSERA_SOURCE_DIR "/assets/catalog/tiles.csv";

static app_result both_lookup(void *user, const app_product_ref *ref, app_product_info *out,
                              char *err, size_t err_size)
{
    (void)user;
    app_result r = ptc_lookup((void *)csv, ref, out, err, err_size);
    if (r == APP_OK || !tu_contains(err, "no product"))
        return r;
    return ptc_lookup((void *)tiles_csv, ref, out, err, err_size);
}

/* The CLI test's empty room (a 4-wall plan, a camera, a material): one that can be saved. */
static void make_room(app_project *p)
{
    char err[1024];
    CHECK_MSG(app_project_read(TESSERA_SOURCE_DIR "/tests/cli/data/edit-room.json", p, err,
                               sizeof err) == APP_OK,
              "%s", err);
}

static app_result run(app_project *p, app_history *h, const char *text, char *err, size_t err_size)
{
    app_script_env env = {both_lookup, NULL, NULL, stdout};
    return app_script_run(p, h, text, strlen(text), "tile.script", &env, NULL, err, err_size);
}

/* A line that must fail with `piece` in its message and leave the document as it was. */
static void refused(app_project *p, app_history *h, const char *line, const char *piece)
{
    app_project before;
    char err[1024] = "", diff[512];
    CHECK(app_project_copy(&before, p, err, sizeof err) == APP_OK);
    int undo = app_history_undo_count(h);
    CHECK(run(p, h, line, err, sizeof err) != APP_OK);
    printf("refused: %s\n", err);
    CHECK_MSG(tu_contains(err, piece), "%s", err);
    CHECK_MSG(app_project_equal(&before, p, diff, sizeof diff), "%s", diff);
    CHECK(app_history_undo_count(h) == undo);
    app_project_free_all(&before);
}

int main(void)
{
    app_project p;
    char err[1024], diff[512];
    make_room(&p);
    app_history *h = app_history_create(0);
    CHECK_MSG(run(&p, h, "tile wall:1 with \"Fliesenwerk Altena\" FA-10110 GL\n", err,
                  sizeof err) == APP_OK,
              "%s", err);
    CHECK(p.tiling_count == 1 && p.tilings[0].from_mm == 0 && p.tilings[0].to_mm == 0);
    app_project tiled;
    CHECK(app_project_copy(&tiled, &p, err, sizeof err) == APP_OK);

    /* Each word is one undo step. */
    const char *lines[] = {
        "tile wall:1 band 0 1250\n",
        "tile wall:1 border add \"Fliesenwerk Altena\" FA-10132 GL at 1200\n",
        "tile wall:1 border add \"Fliesenwerk Altena\" FA-10131 at 900\n",
        "tile wall:1 border 1 at 1100\n",
        "tile wall:1 border remove 2\n",
    };
    for (int i = 0; i < 5; i++) {
        int undo = app_history_undo_count(h);
        CHECK_MSG(run(&p, h, lines[i], err, sizeof err) == APP_OK, "%s", err);
        CHECK(app_history_undo_count(h) == undo + 1);
        CHECK(app_history_last_changed(h) & APP_CHANGED_TILINGS);
    }
    const app_tiling *t = &p.tilings[0];
    CHECK(t->from_mm == 0 && t->to_mm == 1250);
    CHECK(t->border_count == 1 && !strcmp(t->borders[0].product.article, "FA-10132") &&
          !strcmp(t->borders[0].product.variant, "GL") && t->borders[0].bottom_mm == 1100);
    /* Removing a row shifts the rows behind it down. */
    CHECK_MSG(run(&p, h,
                  "tile wall:1 border add \"Fliesenwerk Altena\" FA-10131 at 300\n"
                  "tile wall:1 border add \"Fliesenwerk Altena\" FA-10132 at 600\n"
                  "tile wall:1 border remove 1\n",
                  err, sizeof err) == APP_OK,
              "%s", err);
    t = &p.tilings[0];
    CHECK(t->border_count == 2 && !strcmp(t->borders[0].product.article, "FA-10131") &&
          t->borders[0].bottom_mm == 300 && t->borders[1].bottom_mm == 600);
    CHECK(!t->borders[2].product.article[0] && t->borders[2].bottom_mm == 0);

    /* Refused lines change nothing. */
    refused(&p, h, "tile wall:1 band 1300 1200\n", "band");
    refused(&p, h, "tile wall:1 band 0\n", "number");
    refused(&p, h, "tile wall:1 border add Cerana CE410301 WH at 1000\n", "not a tile");
    refused(&p, h, "tile wall:1 border add \"Fliesenwerk Altena\" FA-10131\n", "border add");
    refused(&p, h, "tile wall:1 border remove 3\n", "no row 3");
    refused(&p, h, "tile wall:1 border 0 at 100\n", "no row 0");
    refused(&p, h, "tile wall:1 border 1\n", "\"at\" is missing");
    refused(&p, h, "tile wall:1 border 1 at -5\n", "border");
    refused(&p, h, "tile wall:1 banded 0 100\n", "band or border");
    refused(&p, h, "tile wall:2 band 0 1000\n", "no tiling");
    /* At most APP_TILING_MAX_BORDERS rows. */
    for (int i = 2; i < APP_TILING_MAX_BORDERS; i++)
        CHECK_MSG(run(&p, h, "tile wall:1 border add \"Fliesenwerk Altena\" FA-10131 at 1500\n",
                      err, sizeof err) == APP_OK,
                  "%s", err);
    CHECK(p.tilings[0].border_count == APP_TILING_MAX_BORDERS);
    refused(&p, h, "tile wall:1 border add \"Fliesenwerk Altena\" FA-10131 at 1600\n",
            "border rows already");

    /* Saved and read back. */
    char path[] = "/tmp/tessera-tile-words-XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    close(fd);
    CHECK_MSG(app_project_write(path, &p, err, sizeof err) == APP_OK, "%s", err);
    app_project back;
    CHECK_MSG(app_project_read(path, &back, err, sizeof err) == APP_OK, "%s", err);
    CHECK(back.tiling_count == 1 && back.tilings[0].to_mm == 1250 &&
          back.tilings[0].border_count == APP_TILING_MAX_BORDERS &&
          back.tilings[0].borders[1].bottom_mm == 600);
    app_project_free_all(&back);
    unlink(path);

    /* Undoing every step of the words gives the tiled document back exactly. */
    char undo_all[64];
    snprintf(undo_all, sizeof undo_all, "undo %d\n", app_history_undo_count(h) - 1);
    CHECK_MSG(run(&p, h, undo_all, err, sizeof err) == APP_OK, "%s", err);
    CHECK_MSG(app_project_equal(&tiled, &p, diff, sizeof diff), "%s", diff);

    app_project_free_all(&tiled);
    app_history_destroy(h);
    app_project_free_all(&p);
    return check_report("edit_tile_words");
}
