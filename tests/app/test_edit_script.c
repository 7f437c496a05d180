/* Edit scripts (`tessera edit`, docs/editing.md): a replay gives the expected document, undo
 * inside a script returns to the exact earlier state, and every bad line is reported with its
 * line number and nothing after it runs. */
#include "test_util.h"

#include "app/project/commands.h"
#include "placement_test_catalog.h"

#include <math.h>

static const char *csv = TESSERA_SOURCE_DIR "/assets/catalog/fixtures.csv";
static const char *tiles_csv = TESSERA_SOURCE_DIR "/assets/catalog/tiles.csv";

/* Fixtures from fixtures.csv, tiles from tiles.csv. */
static app_result both_lookup(void *user, const app_product_ref *ref, app_product_info *out,
                              char *err, size_t err_size)
{
    (void)user;
    app_result r = ptc_lookup((void *)csv, ref, out, err, err_size);
    if (r == APP_OK || !tu_contains(err, "no product"))
        return r;
    return ptc_lookup((void *)tiles_csv, ref, out, err, err_size);
}

static void make_room(app_project *p)
{
    memset(p, 0, sizeof *p);
    p->version = p->file_version = 1;
    p->plan.corner_count = 4;
    p->plan.corners = calloc(4, sizeof *p->plan.corners);
    p->plan.corners[1].x = p->plan.corners[2].x = 3000;
    p->plan.corners[2].y = p->plan.corners[3].y = 2500;
    p->plan.height_mm = 2500;
    p->plan.wall_thickness_mm = 120;
    p->room.width_mm = 3000;
    p->room.depth_mm = 2500;
    p->room.height_mm = 2500;
    p->material_count = 1;
    p->materials = calloc(1, sizeof *p->materials);
    snprintf(p->materials[0].name, sizeof p->materials[0].name, "default");
}

static int object_named(const app_project *p, const char *name)
{
    for (int i = 0; i < p->object_count; i++)
        if (!strcmp(p->objects[i].name, name))
            return i;
    return -1;
}

static app_result run(app_project *p, app_history *h, const char *text, app_script_stats *st,
                      char *err, size_t err_size)
{
    app_script_env env = {both_lookup, NULL, NULL, stdout};
    return app_script_run(p, h, text, strlen(text), "test.script", &env, st, err, err_size);
}

static const char *script = "# a bathroom wall\n"
                            "place Cerana CE410301 WH at 1100 80 675 snap wall as basin\n"
                            "place Vitrelux VX20051 at 1100 0 1150 as \"big mirror\"\n"
                            "place Cerana CE412901 at 1560 50 60 rot 10 snap wall neighbour as wc\n"
                            "\n"
                            "move basin 1000 0 675\n"
                            "undo\n"
                            "redo\n"
                            "nudge wc 10 0 0\n"
                            "tile floor with \"Terrazza Ceramiche\" TZ61000\n"
                            "tile floor pattern half-offset\n"
                            "tile floor grout 3 colour 0.3 0.3 0.3\n"
                            "tile floor start line 100 50\n"
                            "window w1 wall 1 at 500 width 600 height 900 sill 1200\n"
                            "door d1 wall 2 at 200 width 800 height 2000 swing in-right\n"
                            "move-opening w1 at 700\n"
                            "prewall box wall 3 at 1000 width 800 depth 200 height 1100\n"
                            "tile prewall:box:front with \"Terrazza Ceramiche\" TZ61002\n"
                            "niche soap wall 2 at 1500 width 300 sill 1000 height 400 depth 80\n"
                            "corner 2 3000 2600\n"
                            "reflect default 0.2 gloss 0.8 blend fresnel\n"
                            "add box stool at 2500 1500 225 size 350 350 450 rot 15\n";

static void test_replay(void)
{
    app_project p, original;
    char err[1024], diff[512];
    make_room(&p);
    CHECK(app_project_copy(&original, &p, err, sizeof err) == APP_OK);
    app_history *h = app_history_create(0);
    app_script_stats st;
    app_result r = run(&p, h, script, &st, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    printf("stats: %d lines, %d commands, %d undone, %d redone\n", st.lines, st.commands, st.undone,
           st.redone);
    CHECK(st.lines == 20 && st.commands == 18 && st.undone == 1 && st.redone == 1);
    int basin = object_named(&p, "basin"), wc = object_named(&p, "wc");
    int mirror = object_named(&p, "big mirror");
    CHECK(basin >= 0 && wc >= 0 && mirror >= 0 && object_named(&p, "stool") >= 0);
    /* snap wall: back onto wall 0 (y = 0), facing +y. */
    CHECK(basin >= 0 && p.objects[basin].position_mm[0] == 1000 &&
          p.objects[basin].position_mm[1] == 0 && p.objects[basin].rotation_deg[2] == 0);
    /* The WC: onto the wall (rotation 10 -> 0), then 200 mm right of the basin as it stood
     * then (x 800..1400): 1400 + 200 + 180 = 1780; nudged by 10. */
    CHECK(wc >= 0 && fabs(p.objects[wc].position_mm[0] - 1790) < 1e-9 &&
          fabs(p.objects[wc].position_mm[1]) < 1e-9 && fabs(p.objects[wc].rotation_deg[2]) < 1e-9);
    CHECK(wc >= 0 && !strcmp(p.objects[wc].product.article, "CE412901"));
    CHECK(p.tiling_count == 2);
    CHECK(p.tiling_count >= 1 && p.tilings[0].pattern == APP_PATTERN_HALF_OFFSET &&
          p.tilings[0].grout_mm == 3 && p.tilings[0].align == APP_ALIGN_LINE &&
          p.tilings[0].origin_mm[0] == 100 && fabs(p.tilings[0].grout_color[0] - 0.3f) < 1e-6);
    CHECK(p.plan.opening_count == 2 && p.plan.openings[0].offset_mm == 700);
    CHECK(p.plan.opening_count == 2 && p.plan.openings[1].swing == APP_SWING_IN_RIGHT);
    CHECK(p.plan.prewall_count == 1 && p.plan.niche_count == 1);
    CHECK(p.plan.corners[2].y == 2600 && p.room.depth_mm == 2600);
    CHECK(p.materials[0].reflectivity == 0.2f && p.materials[0].blend == APP_BLEND_FRESNEL);

    /* Undoing everything inside a script returns the original document exactly. */
    char undo_all[64];
    snprintf(undo_all, sizeof undo_all, "undo %d\n", app_history_undo_count(h));
    CHECK_MSG(run(&p, h, undo_all, &st, err, sizeof err) == APP_OK, "%s", err);
    CHECK_MSG(app_project_equal(&original, &p, diff, sizeof diff), "%s", diff);
    CHECK(run(&p, h, "undo\n", &st, err, sizeof err) != APP_OK);
    CHECK(tu_contains(err, "test.script:1:") && tu_contains(err, "nothing to undo"));
    app_history_destroy(h);
    app_project_free_all(&original);
    app_project_free_all(&p);
}

static void expect_error(const char *text, const char *piece1, const char *piece2)
{
    app_project p, before;
    char err[1024] = "", diff[512];
    make_room(&p);
    app_history *h = app_history_create(0);
    /* The first line always works; the failing line comes after it. */
    CHECK(run(&p, h, "place Cerana CE410301 at 1500 0 675 as basin\n", NULL, err, sizeof err) ==
          APP_OK);
    CHECK(app_project_copy(&before, &p, err, sizeof err) == APP_OK);
    app_result r = run(&p, h, text, NULL, err, sizeof err);
    printf("error: %s\n", err);
    CHECK(r != APP_OK);
    CHECK_MSG(tu_contains(err, piece1), "%s", err);
    CHECK_MSG(tu_contains(err, piece2), "%s", err);
    /* A failing line changes nothing (the lines before it stay applied). */
    if (strncmp(text, "move basin 1 2 3\n", 17) != 0)
        CHECK_MSG(app_project_equal(&before, &p, diff, sizeof diff), "%s", diff);
    app_history_destroy(h);
    app_project_free_all(&before);
    app_project_free_all(&p);
}

static void test_errors(void)
{
    expect_error("move nobody 1 2 3\n", "test.script:1:", "no object named \"nobody\"");
    expect_error("# ok\n\nfrobnicate 1\n", "test.script:3:", "unknown command \"frobnicate\"");
    expect_error("move basin 1 x 3\n", "test.script:1:", "expected a number, got \"x\"");
    expect_error("move basin 1 2\n", "test.script:1:", "a number is missing");
    expect_error("move basin 1 2 3 4\n", "test.script:1:", "unexpected word \"4\"");
    expect_error("place \"Cerana CE410301 at 1 2 3\n", "test.script:1:", "quote is not closed");
    expect_error("place Nobody X1 at 1 2 3\n", "test.script:1:", "no product Nobody X1");
    expect_error("place Cerana CE410301 at 1500 1250 675 snap wall\n",
                 "test.script:1:", "no wall within 500 mm");
    expect_error("place Cerana CE410301 at 2000 0 675 as basin\n",
                 "test.script:1:", "already named \"basin\"");
    expect_error("tile floor pattern herringbone\n", "test.script:1:", "no tiling on \"floor\"");
    expect_error("tile floor with Cerana CE410301\n", "test.script:1:", "is not a tile");
    expect_error("tile wall:9 with \"Terrazza Ceramiche\" TZ61000\n",
                 "test.script:1:", "no surface \"wall:9\"");
    expect_error("window w wall 0 at 2800 width 600 height 900 sill 1000\n",
                 "test.script:1:", "does not fit in wall 0");
    expect_error("corner 1 0 2500\n", "test.script:1:", "would");
    expect_error("reflect default 1.5\n", "test.script:1:", "0 to 1");
    expect_error("move basin 1 2 3\nredo\n", "test.script:2:", "nothing to redo");
    expect_error("undo 0\n", "test.script:1:", "at least 1");
    expect_error("door d wall 1e300 at 0 width 800 height 2000\n",
                 "test.script:1:", "a wall is a whole number");
    expect_error("corner 1e300 0 0\n", "test.script:1:", "whole number");
    expect_error("variant basin XX\n", "test.script:1:", "no variant \"XX\"");
    /* strtod's other notations are not numbers in a script: 0x100 is not 256. */
    expect_error("# hex\nmove basin 0x100 2 3\n",
                 "test.script:2:", "expected a number, got \"0x100\"");
    expect_error("move basin 1 inf 3\n", "test.script:1:", "expected a number, got \"inf\"");
    expect_error("move basin 1 2 nan\n", "test.script:1:", "expected a number, got \"nan\"");
    expect_error("move basin 1 2 .\n", "test.script:1:", "expected a number, got \".\"");
}

/* Random lines from the script's own words: never a crash, every failure names its line,
 * and undoing everything that worked gives back the original document. */
static void test_random_lines(void)
{
    static const char *const words[] = {"place",
                                        "move",
                                        "nudge",
                                        "rotate",
                                        "remove",
                                        "variant",
                                        "product",
                                        "tile",
                                        "untile",
                                        "door",
                                        "window",
                                        "move-opening",
                                        "remove-opening",
                                        "corner",
                                        "prewall",
                                        "remove-prewall",
                                        "niche",
                                        "remove-niche",
                                        "reflect",
                                        "undo",
                                        "redo",
                                        "add",
                                        "at",
                                        "wall",
                                        "width",
                                        "height",
                                        "sill",
                                        "depth",
                                        "rot",
                                        "as",
                                        "snap",
                                        "corner",
                                        "neighbour",
                                        "with",
                                        "pattern",
                                        "grout",
                                        "start",
                                        "line",
                                        "colour",
                                        "gloss",
                                        "blend",
                                        "fresnel",
                                        "box",
                                        "size",
                                        "basin",
                                        "wc",
                                        "floor",
                                        "wall:0",
                                        "wall:3",
                                        "Cerana",
                                        "CE410301",
                                        "CE412901",
                                        "WH",
                                        "\"Terrazza Ceramiche\"",
                                        "TZ61000",
                                        "default",
                                        "w1",
                                        "pw",
                                        "0",
                                        "1",
                                        "2",
                                        "3",
                                        "-1",
                                        "200",
                                        "600",
                                        "1200",
                                        "2500",
                                        "1e9",
                                        "1e300",
                                        "-1e300",
                                        "nan",
                                        "\"",
                                        "#",
                                        "half-offset",
                                        "in-left",
                                        "1.5",
                                        "0.5"};
    int nwords = (int)(sizeof words / sizeof words[0]);
    app_project p, original;
    char err[1024], diff[512];
    make_room(&p);
    CHECK(app_project_copy(&original, &p, err, sizeof err) == APP_OK);
    app_history *h = app_history_create(100000);
    unsigned long long state = 12345;
    int ok = 0, failed = 0;
    app_script_env env = {both_lookup, NULL, NULL, NULL};
    static const char *const templates[] = {
        "place Cerana CE410301 at N N N as O",
        "place Cerana CE412901 at N N N snap wall",
        "place Cerana CE413701 at N N N rot N snap wall neighbour as O",
        "move O N N N",
        "nudge O N N N",
        "rotate O N",
        "remove O",
        "variant O WH",
        "undo",
        "redo",
        "undo 2",
        "tile floor with \"Terrazza Ceramiche\" TZ61000",
        "tile floor pattern half-offset",
        "tile floor grout N",
        "tile floor start line N N",
        "untile floor",
        "window O wall W at N width N height N sill N",
        "door O wall W at N width N height N",
        "move-opening O at N",
        "remove-opening O",
        "corner W N N",
        "prewall O wall W at N width N depth N height N",
        "remove-prewall O",
        "niche O wall W at N width N sill N height N depth N",
        "remove-niche O",
        "reflect default 0.N",
        "add box O at N N N size N N N"};
    int ntemplates = (int)(sizeof templates / sizeof templates[0]);
    for (int i = 0; i < 4000; i++) {
        char line[512] = "";
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        if ((state >> 60) & 1) {
            /* A template with random numbers, names and walls. */
            const char *t = templates[(state >> 33) % (unsigned)ntemplates];
            for (; *t && strlen(line) < sizeof line - 16; t++) {
                state = state * 6364136223846793005ULL + 1442695040888963407ULL;
                char piece[32];
                if (*t == 'N' && (t[1] == ' ' || !t[1]))
                    snprintf(piece, sizeof piece, "%d", (int)((state >> 33) % 3200) - 100);
                else if (*t == 'O' && (t[1] == ' ' || !t[1]))
                    snprintf(piece, sizeof piece, "o%d", (int)((state >> 33) % 4));
                else if (*t == 'W' && (t[1] == ' ' || !t[1]))
                    snprintf(piece, sizeof piece, "%d", (int)((state >> 33) % 5));
                else
                    snprintf(piece, sizeof piece, "%c", *t);
                strncat(line, piece, sizeof line - strlen(line) - 1);
            }
        } else {
            int n = 1 + (int)((state >> 40) % 12);
            for (int k = 0; k < n; k++) {
                state = state * 6364136223846793005ULL + 1442695040888963407ULL;
                /* Mostly a command word first. */
                int w =
                    k == 0 ? (int)((state >> 33) % 22) : (int)((state >> 33) % (unsigned)nwords);
                strncat(line, words[w], sizeof line - strlen(line) - 2);
                strncat(line, " ", sizeof line - strlen(line) - 1);
            }
        }
        app_result r =
            app_script_run(&p, h, line, strlen(line), "fuzz", &env, NULL, err, sizeof err);
        if (r == APP_OK) {
            ok++;
        } else {
            failed++;
            CHECK_MSG(!strncmp(err, "fuzz:1: ", 8), "%s", err);
        }
    }
    printf("random lines: %d ran, %d refused\n", ok, failed);
    CHECK(ok > 50);
    while (app_history_undo_count(h) > 0)
        CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
    CHECK_MSG(app_project_equal(&original, &p, diff, sizeof diff), "%s", diff);
    app_history_destroy(h);
    app_project_free_all(&original);
    app_project_free_all(&p);
}

int main(void)
{
    test_replay();
    test_errors();
    test_random_lines();
    return check_report("edit_script");
}
