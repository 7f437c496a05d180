/* The Selection panel's wood grain field: the choices its combo offers and the `pattern` edit
 * line each sends (docs/editing.md), so every change is one command with undo. Pure:
 * tests/ui/test_panel_layout.c runs the lines. */
#ifndef UI_GRAIN_PROPS_H
#define UI_GRAIN_PROPS_H

#include <stddef.h>

enum { UI_GRAIN_NONE = 0, UI_GRAIN_HORIZONTAL, UI_GRAIN_VERTICAL, UI_GRAIN_OTHER };

/* The combo's items for a material's pattern (APP_PATTERN_*) and grain angle: "none", "wood,
 * horizontal", "wood, vertical", plus "wood, N degrees" (in other[]) when the grain is another
 * angle (a project file may say 30); *current the item showing it. Returns the count (3 or 4). */
int ui_grain_items(int pattern, float grain_deg, const char *items[4], char other[32],
                   int *current);

/* The edit line for item k (UI_GRAIN_*) of material `material`: 0, or 1 when it does not fit
 * or k is UI_GRAIN_OTHER (the angle it shows is the material's already). */
int ui_grain_line(char *out, size_t size, const char *material, int k);

#endif
