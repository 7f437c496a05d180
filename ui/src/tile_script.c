/* The words of the tile script actions (script.h: tile-pattern, tile-grout, tile-start,
 * tile-rotate, tile-band, tile-border, expect-pattern, expect-tiles), checked when the script
 * is read so a typo is reported before the window opens. No app dependency: the pattern names
 * are the project file's (app/design/tile_layout.h app_tile_pattern_name). */
#include "script.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const patterns[6] = {"straight",       "half-offset", "third-offset",
                                        "vertical-stack", "diagonal",    "herringbone"};

static int is_number(const char *w)
{
    char *end;
    errno = 0;
    double v = strtod(w, &end);
    return end != w && !*end && !errno && isfinite(v) && fabs(v) <= 1e7;
}

static int is_pattern(const char *w)
{
    for (int i = 0; i < 6; i++)
        if (!strcmp(w, patterns[i]))
            return 1;
    return 0;
}

int ui_tile_action_check(ui_action_kind kind, const char *text, char *why, size_t why_size)
{
    char copy[512], *save = NULL, *w[8];
    int n = 0;
    snprintf(copy, sizeof copy, "%s", text);
    for (char *t = strtok_r(copy, " \t", &save); t; t = strtok_r(NULL, " \t", &save)) {
        if (n == 8) {
            snprintf(why, why_size, "too many words");
            return 0;
        }
        w[n++] = t;
    }
    int numbers_from = 1, want_min = 2, want_max = 2;
    const char *usage = "";
    switch (kind) {
    case UI_ACT_TILE_PATTERN:
    case UI_ACT_EXPECT_PATTERN:
        usage = "SURFACE PATTERN";
        if (n == 2 && !is_pattern(w[1])) {
            snprintf(why, why_size,
                     "the pattern is straight, half-offset, third-offset, vertical-stack, "
                     "diagonal or herringbone, not \"%s\"",
                     w[1]);
            return 0;
        }
        numbers_from = 2;
        break;
    case UI_ACT_TILE_GROUT:
        usage = "SURFACE WIDTH_MM [R G B]";
        want_max = 5;
        if (n == 3 || n == 4) {
            snprintf(why, why_size, "tile-grout needs SURFACE WIDTH_MM [R G B]");
            return 0;
        }
        break;
    case UI_ACT_TILE_START:
        usage = "SURFACE X Y, or SURFACE centred|corner";
        want_max = 3;
        if (n == 2 && (!strcmp(w[1], "centred") || !strcmp(w[1], "corner")))
            return 1;
        want_min = 3;
        break;
    case UI_ACT_TILE_ROTATE:
        usage = "SURFACE DEG";
        break;
    case UI_ACT_TILE_BAND:
        usage = "SURFACE FROM TO";
        want_min = want_max = 3;
        break;
    case UI_ACT_TILE_BORDER:
        usage = "SURFACE BOTTOM_MM";
        break;
    case UI_ACT_EXPECT_TILES:
        usage = "SURFACE N";
        break;
    default:
        return 1;
    }
    if (n < want_min || n > want_max) {
        snprintf(why, why_size, "needs %s", usage);
        return 0;
    }
    for (int i = numbers_from; i < n; i++)
        if (!is_number(w[i])) {
            snprintf(why, why_size, "expected a number, got \"%s\" (%s)", w[i], usage);
            return 0;
        }
    return 1;
}
