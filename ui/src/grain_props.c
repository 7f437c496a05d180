/* The Selection panel's wood grain field (grain_props.h). */
#include "grain_props.h"

#include "app/project/project.h"

#include <stdio.h>

int ui_grain_items(int pattern, float grain_deg, const char *items[4], char other[32], int *current)
{
    items[UI_GRAIN_NONE] = "none";
    items[UI_GRAIN_HORIZONTAL] = "wood, horizontal";
    items[UI_GRAIN_VERTICAL] = "wood, vertical";
    if (pattern != APP_PATTERN_WOOD) {
        *current = UI_GRAIN_NONE;
        return 3;
    }
    if (grain_deg == 0.0f || grain_deg == 90.0f) {
        *current = grain_deg == 0.0f ? UI_GRAIN_HORIZONTAL : UI_GRAIN_VERTICAL;
        return 3;
    }
    snprintf(other, 32, "wood, %g degrees", (double)grain_deg);
    items[UI_GRAIN_OTHER] = other;
    *current = UI_GRAIN_OTHER;
    return 4;
}

int ui_grain_line(char *out, size_t size, const char *material, int k)
{
    int n;
    if (k == UI_GRAIN_NONE)
        n = snprintf(out, size, "pattern \"%s\" none", material);
    else if (k == UI_GRAIN_HORIZONTAL || k == UI_GRAIN_VERTICAL)
        n = snprintf(out, size, "pattern \"%s\" wood grain %s", material,
                     k == UI_GRAIN_HORIZONTAL ? "horizontal" : "vertical");
    else
        return 1;
    return n < 0 || (size_t)n >= size;
}
