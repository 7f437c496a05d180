/* Reading UI scripts (ui/src/script.h). */
#include "script.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_ACTIONS 100000

static const struct {
    const char *word;
    ui_action_kind kind;
    int numbers; /* how many numbers follow */
    int text;    /* 1: one word of text follows; 2: the rest of the line; 3: the verb and one
                    word (UI_ACT_FILES); 4: the verb alone (UI_ACT_FILES) */
} verbs[] = {
    {"wait", UI_ACT_WAIT, 1, 0},
    {"orbit", UI_ACT_ORBIT, 2, 0},
    {"zoom", UI_ACT_ZOOM, 1, 0},
    {"mode", UI_ACT_MODE, 0, 1},
    {"walk", UI_ACT_WALK, 2, 0},
    {"camera", UI_ACT_CAMERA, 0, 1},
    {"quality", UI_ACT_QUALITY, 0, 1},
    {"screenshot", UI_ACT_SCREENSHOT, 0, 1},
    {"search", UI_ACT_SEARCH, 0, 2},
    {"select", UI_ACT_SELECT, 1, 0},
    {"expect-hits", UI_ACT_EXPECT_HITS, 1, 0},
    {"fly", UI_ACT_FLY, -1, 1}, /* a name, then seconds */
    {"present", UI_ACT_PRESENT, 0, 1},
    {"tour", UI_ACT_TOUR, 0, 1},
    {"turntable", UI_ACT_TURNTABLE, 0, 1},
    {"print-shot", UI_ACT_PRINT_SHOT, 0, 1},
    {"view", UI_ACT_VIEW, 0, 1},
    {"edit", UI_ACT_EDIT, 0, 2},
    {"place-selected", UI_ACT_PLACE_SELECTED, 2, 0},
    {"drag", UI_ACT_DRAG, -2, 1}, /* a name, then X Y */
    {"drag3d", UI_ACT_DRAG3D, -2, 1},
    {"move-wall", UI_ACT_MOVE_WALL, 2, 0},
    {"undo", UI_ACT_UNDO, 0, 0},
    {"redo", UI_ACT_REDO, 0, 0},
    {"save", UI_ACT_SAVE, 0, 1},
    {"expect-objects", UI_ACT_EXPECT_OBJECTS, 1, 0},
    {"expect-added", UI_ACT_EXPECT_ADDED, 1, 0},
    {"tile-selected", UI_ACT_TILE_SELECTED, 0, 1},
    {"share", UI_ACT_SHARE, 0, 1},
    {"drop-selected", UI_ACT_DROP_SELECTED, -2, 1}, /* plan|3d, then SX SY */
    {"drag-selected", UI_ACT_DRAG_SELECTED, -2, 1},
    {"expect-total", UI_ACT_EXPECT_TOTAL, 2, 0},
    {"new", UI_ACT_NEW, 0, 0},
    {"open", UI_ACT_OPEN, 0, 1},
    {"save-as", UI_ACT_SAVE_AS, 0, 1},
    {"expect-probe", UI_ACT_EXPECT_PROBE, 0, 2}, /* MATERIAL UPDATE (probe_props.h) */
    {"elevation-wall", UI_ACT_ELEVATION_WALL, 1, 0},
    {"tile-surface", UI_ACT_TILE_SURFACE, 0, 1},
    {"tile-pattern", UI_ACT_TILE_PATTERN, 0, 2},
    {"tile-grout", UI_ACT_TILE_GROUT, 0, 2},
    {"tile-start", UI_ACT_TILE_START, 0, 2},
    {"tile-rotate", UI_ACT_TILE_ROTATE, 0, 2},
    {"tile-band", UI_ACT_TILE_BAND, 0, 2},
    {"tile-border", UI_ACT_TILE_BORDER, 0, 2},
    {"elevation-click", UI_ACT_ELEVATION_CLICK, 2, 0},
    {"expect-pattern", UI_ACT_EXPECT_PATTERN, 0, 2},
    {"expect-tiles", UI_ACT_EXPECT_TILES, 0, 2},
    {"tile-panel", UI_ACT_TILE_PANEL, 0, 1},
    {"wait-file", UI_ACT_WAIT_FILE, 0, 1},
    {"locate", UI_ACT_LOCATE, 0, 2}, /* widget|fixture, then the label or name */
    {"expect-search", UI_ACT_EXPECT_SEARCH, 0, 2},
    {"panes", UI_ACT_PANES, 0, 1},
    {"split", UI_ACT_SPLIT, 1, 0},
    {"pick", UI_ACT_PICK, 0, 1},
    {"print-pdf", UI_ACT_FILES, 0, 3},
    {"render-image", UI_ACT_FILES, 0, 3},
    {"export-glb", UI_ACT_FILES, 0, 3},
    {"panorama", UI_ACT_FILES, 0, 3},
    {"video", UI_ACT_FILES, 0, 3},
    {"job-wait", UI_ACT_FILES, 0, 4},
    {"job-cancel", UI_ACT_FILES, 0, 4},
    {"autosave-now", UI_ACT_FILES, 0, 4},
    {"expect-recovery", UI_ACT_FILES, 0, 3},
    {"expect-read-only", UI_ACT_FILES, 0, 3},
    {"expect-save-refused", UI_ACT_FILES, 0, 4},
    {"recover", UI_ACT_FILES, 0, 3},
    {"expect-recent", UI_ACT_FILES, 0, 3},
    {"open-recent", UI_ACT_FILES, 0, 3},
    {"dialog", UI_ACT_FILES, 0, 3},
    {"wait-bake", UI_ACT_WAIT_BAKE, 0, 0},
    {"wait-warmup", UI_ACT_WAIT_WARMUP, 0, 0},
    {"wait-still", UI_ACT_WAIT_STILL, 0, 0},
    {"bake-hold", UI_ACT_BAKE_HOLD, 0, 1},
    {"quit", UI_ACT_QUIT, 0, 0},
};

static int parse_number(const char *tok, double *out)
{
    if (!tok)
        return 0;
    char *end;
    errno = 0;
    double v = strtod(tok, &end);
    if (end == tok || *end || errno || !isfinite(v) || fabs(v) > 1e7)
        return 0;
    *out = v;
    return 1;
}

static int parse_line(char *line, ui_action *a, char *why, size_t why_size)
{
    char *save = NULL, *verb = strtok_r(line, " \t\r\n", &save);
    size_t v = 0;
    for (; v < sizeof verbs / sizeof verbs[0]; v++)
        if (!strcmp(verb, verbs[v].word))
            break;
    if (v == sizeof verbs / sizeof verbs[0]) {
        snprintf(why, why_size, "unknown action \"%s\"", verb);
        return 0;
    }
    a->kind = verbs[v].kind;
    a->frames = 1;
    double *nums[2] = {&a->a, &a->b};
    for (int i = 0; i < verbs[v].numbers; i++)
        if (!parse_number(strtok_r(NULL, " \t\r\n", &save), nums[i])) {
            snprintf(why, why_size, "%s needs %d number%s", verb, verbs[v].numbers,
                     verbs[v].numbers > 1 ? "s" : "");
            return 0;
        }
    if (verbs[v].text == 2) {
        char *rest = strtok_r(NULL, "\r\n", &save);
        rest = rest ? rest + strspn(rest, " \t") : NULL;
        if (!rest || !*rest || strlen(rest) >= sizeof a->text) {
            snprintf(why, why_size, "%s needs a text of 1 to 511 bytes", verb);
            return 0;
        }
        strcpy(a->text, rest);
        return a->kind < UI_ACT_ELEVATION_WALL || a->kind > UI_ACT_EXPECT_TILES ||
               ui_tile_action_check(a->kind, a->text, why, why_size);
    }
    if (verbs[v].text >= 3) { /* the verb goes with its word: planner_actions.c reads both */
        char *t = verbs[v].text == 3 ? strtok_r(NULL, " \t\r\n", &save) : NULL;
        if (verbs[v].text == 3 && (!t || strlen(t) + strlen(verb) + 2 > sizeof a->text)) {
            snprintf(why, why_size, "%s needs a word (a file name, yes or no, ...)", verb);
            return 0;
        }
        snprintf(a->text, sizeof a->text, "%s%s%s", verb, t ? " " : "", t ? t : "");
        if ((!strcmp(verb, "expect-recovery") || !strcmp(verb, "recover") ||
             !strcmp(verb, "expect-read-only")) &&
            strcmp(t, "yes") && strcmp(t, "no")) {
            snprintf(why, why_size, "%s is yes or no, not \"%s\"", verb, t);
            return 0;
        }
    } else if (verbs[v].text) {
        char *t = strtok_r(NULL, " \t\r\n", &save);
        if (!t || strlen(t) >= sizeof a->text) {
            snprintf(why, why_size, "%s needs a %s", verb,
                     a->kind == UI_ACT_SCREENSHOT || a->kind == UI_ACT_PRINT_SHOT ||
                             a->kind == UI_ACT_SHARE
                         ? "file name"
                         : "name");
            return 0;
        }
        strcpy(a->text, t);
    }
    if (verbs[v].numbers == -1 &&
        (!parse_number(strtok_r(NULL, " \t\r\n", &save), &a->a) || a->a < 0 || a->a > 60)) {
        snprintf(why, why_size, "%s needs a viewpoint name and seconds from 0 to 60", verb);
        return 0;
    }
    if (verbs[v].numbers == -2 && (!parse_number(strtok_r(NULL, " \t\r\n", &save), &a->a) ||
                                   !parse_number(strtok_r(NULL, " \t\r\n", &save), &a->b))) {
        if (a->kind == UI_ACT_DRAG || a->kind == UI_ACT_DRAG3D)
            snprintf(why, why_size, "%s needs a name and a plan point X Y (mm)", verb);
        else
            snprintf(why, why_size, "%s needs plan or 3d and a window pixel SX SY", verb);
        return 0;
    }
    if (a->kind == UI_ACT_VIEW && !strcmp(a->text, "elevation")) {
        /* the elevation view */
    } else if ((a->kind == UI_ACT_VIEW || a->kind == UI_ACT_DROP_SELECTED ||
                a->kind == UI_ACT_DRAG_SELECTED) &&
               strcmp(a->text, "3d") && strcmp(a->text, "plan")) {
        snprintf(why, why_size, "%s is 3d or plan, not \"%s\"", verb, a->text);
        return 0;
    }
    if (a->kind == UI_ACT_PANES && strcmp(a->text, "both") && strcmp(a->text, "one")) {
        snprintf(why, why_size, "%s is both or one, not \"%s\"", verb, a->text);
        return 0;
    }
    if ((a->kind == UI_ACT_PRESENT || a->kind == UI_ACT_TOUR || a->kind == UI_ACT_TURNTABLE ||
         a->kind == UI_ACT_TILE_PANEL) &&
        strcmp(a->text, "on") && strcmp(a->text, "off")) {
        snprintf(why, why_size, "%s is on or off, not \"%s\"", verb, a->text);
        return 0;
    }
    char *t = strtok_r(NULL, " \t\r\n", &save);
    if (t && !strcmp(t, "frames")) {
        double f;
        if (!parse_number(strtok_r(NULL, " \t\r\n", &save), &f) || f < 1 || f > 100000) {
            snprintf(why, why_size, "frames needs a count from 1 to 100000");
            return 0;
        }
        a->frames = (int)f;
        t = strtok_r(NULL, " \t\r\n", &save);
    }
    if (t) {
        snprintf(why, why_size, "unexpected \"%s\" after %s", t, verb);
        return 0;
    }
    if (a->kind == UI_ACT_EXPECT_TOTAL && !(a->a <= a->b)) {
        snprintf(why, why_size, "expect-total needs MIN <= MAX");
        return 0;
    }
    if (a->kind == UI_ACT_WAIT && (a->a < 0 || a->a > 100000)) {
        snprintf(why, why_size, "wait needs a frame count from 0 to 100000");
        return 0;
    }
    if ((a->kind == UI_ACT_SELECT || a->kind == UI_ACT_EXPECT_HITS) &&
        (a->a < 1 || a->a > 200 || a->a != (int)a->a)) {
        snprintf(why, why_size, "%s needs a whole number from 1 to 200", verb);
        return 0;
    }
    if (a->kind == UI_ACT_ELEVATION_WALL && (a->a < 0 || a->a > 255 || a->a != (int)a->a)) {
        snprintf(why, why_size, "elevation-wall needs a wall number from 0 to 255");
        return 0;
    }
    if ((a->kind == UI_ACT_EXPECT_OBJECTS || a->kind == UI_ACT_EXPECT_ADDED) && a->a != (int)a->a) {
        snprintf(why, why_size, "%s needs a whole number", verb);
        return 0;
    }
    if (a->kind == UI_ACT_MODE && strcmp(a->text, "orbit") && strcmp(a->text, "walk")) {
        snprintf(why, why_size, "mode is orbit or walk, not \"%s\"", a->text);
        return 0;
    }
    return 1;
}

int ui_script_read(const char *path, ui_script *out, char *err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, err_size, "%s: cannot open: %s", path, strerror(errno));
        return 1;
    }
    char line[2048];
    int lineno = 0, cap = 0, rc = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        if (!strchr(line, '\n') && !feof(f)) {
            snprintf(err, err_size, "%s:%d: line longer than %zu bytes", path, lineno,
                     sizeof line - 1);
            rc = 1;
            break;
        }
        char *p = line + strspn(line, " \t");
        if (*p == '#' || *p == '\n' || *p == '\r' || !*p)
            continue;
        if (out->count == cap) {
            if (cap >= MAX_ACTIONS) {
                snprintf(err, err_size, "%s:%d: more than %d actions", path, lineno, MAX_ACTIONS);
                rc = 1;
                break;
            }
            int ncap = cap ? cap * 2 : 32;
            ui_action *n = realloc(out->actions, (size_t)ncap * sizeof *n);
            if (!n) {
                snprintf(err, err_size, "%s: out of memory", path);
                rc = 1;
                break;
            }
            out->actions = n;
            cap = ncap;
        }
        ui_action *a = &out->actions[out->count];
        memset(a, 0, sizeof *a);
        a->line = lineno;
        char why[600];
        if (!parse_line(p, a, why, sizeof why)) {
            snprintf(err, err_size, "%s:%d: %s", path, lineno, why);
            rc = 1;
            break;
        }
        out->count++;
    }
    if (!rc && ferror(f)) {
        snprintf(err, err_size, "%s: read error", path);
        rc = 1;
    }
    fclose(f);
    if (rc)
        ui_script_free(out);
    return rc;
}

void ui_script_free(ui_script *s)
{
    if (!s)
        return;
    free(s->actions);
    memset(s, 0, sizeof *s);
}
