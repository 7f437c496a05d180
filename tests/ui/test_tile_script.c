/* The tile script actions (ui/src/script.h: view elevation, elevation-wall, tile-surface,
 * tile-pattern, tile-grout, tile-start, tile-rotate, tile-band, tile-border, elevation-click,
 * expect-pattern, expect-tiles): every form parses, and each mistake is reported with the
 * file and line before the window opens. */
#include "check.h"
#include "script.h"

#include <stdio.h>
#include <string.h>

static int read_text(const char *text, ui_script *s, char *err, size_t n)
{
    const char *path = "ui_tile_script_test.txt";
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fputs(text, f);
    fclose(f);
    return ui_script_read(path, s, err, n);
}

static void expect_error(const char *text, const char *piece)
{
    ui_script s;
    char err[1024] = "";
    int rc = read_text(text, &s, err, sizeof err);
    CHECK_MSG(rc == 1 && strstr(err, piece) && strstr(err, "ui_tile_script_test.txt:"),
              "\"%s\" gave rc %d, \"%s\" (wanted \"%s\")", text, rc, err, piece);
}

int main(void)
{
    ui_script s;
    char err[1024] = "";
    int rc = read_text("view elevation\n"
                       "elevation-wall 2\n"
                       "tile-surface prewall:wc-wall:front\n"
                       "tile-pattern wall:0 herringbone\n"
                       "tile-grout wall:0 5\n"
                       "tile-grout \"wall-0\" 2.5 0.1 0.2 0.3\n"
                       "tile-start wall:0 300 -20\n"
                       "tile-start floor centred\n"
                       "tile-rotate floor 45\n"
                       "tile-band wall:2 0 1250\n"
                       "tile-border wall:2 1200\n"
                       "elevation-click 1000 900\n"
                       "expect-pattern wall:0 herringbone\n"
                       "expect-tiles wall:0 20\n"
                       "tile-panel on\n",
                       &s, err, sizeof err);
    CHECK_MSG(rc == 0, "%s", err);
    CHECK(s.count == 15);
    if (s.count == 15) {
        CHECK(s.actions[0].kind == UI_ACT_VIEW && !strcmp(s.actions[0].text, "elevation"));
        CHECK(s.actions[1].kind == UI_ACT_ELEVATION_WALL && s.actions[1].a == 2);
        CHECK(s.actions[2].kind == UI_ACT_TILE_SURFACE &&
              !strcmp(s.actions[2].text, "prewall:wc-wall:front"));
        CHECK(s.actions[3].kind == UI_ACT_TILE_PATTERN &&
              !strcmp(s.actions[3].text, "wall:0 herringbone"));
        CHECK(s.actions[5].kind == UI_ACT_TILE_GROUT &&
              !strcmp(s.actions[5].text, "\"wall-0\" 2.5 0.1 0.2 0.3"));
        CHECK(s.actions[6].kind == UI_ACT_TILE_START && s.actions[6].line == 7);
        CHECK(s.actions[11].kind == UI_ACT_ELEVATION_CLICK && s.actions[11].a == 1000 &&
              s.actions[11].b == 900);
        CHECK(s.actions[12].kind == UI_ACT_EXPECT_PATTERN);
        CHECK(s.actions[13].kind == UI_ACT_EXPECT_TILES);
        CHECK(s.actions[14].kind == UI_ACT_TILE_PANEL && !strcmp(s.actions[14].text, "on"));
    }
    ui_script_free(&s);

    expect_error("wait 1\nview side\n", ":2: view is 3d or plan");
    expect_error("elevation-wall\n", ":1: elevation-wall needs 1 number");
    expect_error("elevation-wall 1.5\n", "elevation-wall needs a wall number");
    expect_error("elevation-wall -1\n", "elevation-wall needs a wall number");
    expect_error("tile-pattern wall:0\n", "needs SURFACE PATTERN");
    expect_error("tile-pattern wall:0 zigzag\n", "not \"zigzag\"");
    expect_error("expect-pattern floor basket\n", "not \"basket\"");
    expect_error("tile-grout wall:0\n", "needs SURFACE WIDTH_MM");
    expect_error("tile-grout wall:0 3 0.5\n", "tile-grout needs SURFACE WIDTH_MM [R G B]");
    expect_error("tile-grout wall:0 wide\n", "expected a number, got \"wide\"");
    expect_error("tile-start wall:0 100\n", "needs SURFACE X Y");
    expect_error("tile-start wall:0 middle\n", "needs SURFACE X Y");
    expect_error("tile-start wall:0 1 2 3\n", "needs SURFACE X Y");
    expect_error("tile-rotate floor\n", "needs SURFACE DEG");
    expect_error("tile-band wall:2 0\n", "needs SURFACE FROM TO");
    expect_error("tile-border wall:2 high\n", "expected a number");
    expect_error("elevation-click 10\n", "elevation-click needs 2 numbers");
    expect_error("expect-tiles wall:0\n", "needs SURFACE N");
    expect_error("tile-pattern\n", "tile-pattern needs a text");
    expect_error("tile-surface\n", "tile-surface needs a name");
    expect_error("tile-panel maybe\n", "tile-panel is on or off");
    remove("ui_tile_script_test.txt");
    return check_report("ui_tile_script");
}
