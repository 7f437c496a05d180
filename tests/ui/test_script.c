/* UI scripts (ui/src/script.h): every action parses, and each kind of mistake is reported
 * with the file and line before any window opens. */
#include "check.h"
#include "script.h"

#include <stdio.h>
#include <string.h>

static int read_text(const char *text, ui_script *s, char *err, size_t n)
{
    const char *path = "ui_script_test.txt";
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
    CHECK_MSG(rc == 1 && strstr(err, piece) && strstr(err, "ui_script_test.txt:"),
              "\"%s\" gave rc %d, \"%s\" (wanted \"%s\")", text, rc, err, piece);
}

int main(void)
{
    ui_script s;
    char err[1024];
    int rc = read_text("# a tour\n\nwait 3\norbit 120 -30 frames 40\nzoom 2\nmode walk\n"
                       "walk 500 -100 frames 10\ncamera door\nquality print\n"
                       "screenshot out.png\nquit\n",
                       &s, err, sizeof err);
    CHECK_MSG(rc == 0, "%s", err);
    CHECK(s.count == 9);
    if (s.count == 9) {
        CHECK(s.actions[0].kind == UI_ACT_WAIT && s.actions[0].a == 3);
        CHECK(s.actions[1].kind == UI_ACT_ORBIT && s.actions[1].a == 120 && s.actions[1].b == -30 &&
              s.actions[1].frames == 40 && s.actions[1].line == 4);
        CHECK(s.actions[3].kind == UI_ACT_MODE && !strcmp(s.actions[3].text, "walk"));
        CHECK(s.actions[6].kind == UI_ACT_QUALITY && !strcmp(s.actions[6].text, "print"));
        CHECK(s.actions[7].kind == UI_ACT_SCREENSHOT && !strcmp(s.actions[7].text, "out.png"));
        CHECK(s.actions[8].kind == UI_ACT_QUIT);
    }
    ui_script_free(&s);

    expect_error("wait 1\nhover 3\n", ":2: unknown action \"hover\"");
    expect_error("orbit 10\n", ":1: orbit needs 2 numbers");
    expect_error("orbit 10 nan\n", "orbit needs 2 numbers");
    expect_error("zoom 1e300\n", "zoom needs 1 number");
    expect_error("screenshot\n", "screenshot needs a file name");
    expect_error("mode fly\n", "mode is orbit or walk");
    expect_error("wait -4\n", "wait needs a frame count");
    expect_error("orbit 1 2 frames 0\n", "frames needs a count");
    expect_error("quit now\n", "unexpected \"now\" after quit");
    expect_error("fly door\n", "fly needs a viewpoint name and seconds");
    expect_error("fly door 99\n", "fly needs a viewpoint name and seconds");
    expect_error("present maybe\n", "present is on or off");
    expect_error("print-shot\n", "print-shot needs a file name");
    expect_error("share\n", "share needs a file name");
    expect_error("view side\n", "view is 3d or plan");
    expect_error("panes three\n", "panes is both or one");
    expect_error("split\n", "split needs 1 number");
    CHECK(read_text("panes one\nsplit 600\n", &s, err, sizeof err) == 0 && s.count == 2 &&
          s.actions[0].kind == UI_ACT_PANES && !strcmp(s.actions[0].text, "one") &&
          s.actions[1].kind == UI_ACT_SPLIT && s.actions[1].a == 600);
    ui_script_free(&s);
    expect_error("drag basin 10\n", "drag needs a name and a plan point");
    expect_error("expect-objects 2.5\n", "expect-objects needs a whole number");
    rc = read_text("fly bath 1.5\npresent on\ntour off\nturntable on\nprint-shot a.png\n", &s, err,
                   sizeof err);
    CHECK_MSG(rc == 0, "%s", err);
    CHECK(s.count == 5 && s.actions[0].kind == UI_ACT_FLY && !strcmp(s.actions[0].text, "bath") &&
          s.actions[0].a == 1.5 && s.actions[4].kind == UI_ACT_PRINT_SHOT);
    ui_script_free(&s);
    expect_error("search\n", "search needs a text");
    expect_error("select 0\n", "select needs a whole number");
    expect_error("expect-hits 2.5\n", "expect-hits needs a whole number");
    rc = read_text("search wall-hung  basin 600\nselect 2\nexpect-hits 3\n", &s, err, sizeof err);
    CHECK_MSG(rc == 0, "%s", err);
    CHECK(s.count == 3 && !strcmp(s.actions[0].text, "wall-hung  basin 600") &&
          s.actions[1].kind == UI_ACT_SELECT && s.actions[1].a == 2);
    ui_script_free(&s);
    /* The file and job verbs (planner_actions.h): the verb travels with its word. */
    expect_error("print-pdf\n", "print-pdf needs a word");
    expect_error("recover maybe\n", "recover is yes or no");
    expect_error("job-wait now\n", "unexpected \"now\" after job-wait");
    rc = read_text("print-pdf out.pdf\njob-wait\nexpect-recovery no\n", &s, err, sizeof err);
    CHECK_MSG(rc == 0, "%s", err);
    CHECK(s.count == 3 && s.actions[0].kind == UI_ACT_FILES &&
          !strcmp(s.actions[0].text, "print-pdf out.pdf") &&
          !strcmp(s.actions[1].text, "job-wait") &&
          !strcmp(s.actions[2].text, "expect-recovery no"));
    ui_script_free(&s);
    CHECK(ui_script_read("/nonexistent/script.txt", &s, err, sizeof err) == 1 &&
          strstr(err, "/nonexistent/script.txt: cannot open"));
    remove("ui_script_test.txt");
    return check_report("ui_script");
}
