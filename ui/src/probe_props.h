/* The Selection panel's probe policy fields (for power users): the
 * choices the combos offer and the `probe` edit line each change sends (docs/editing.md), so
 * every change is one command with undo. Pure: tests/ui/test_probe_props.c runs the lines. */
#ifndef UI_PROBE_PROPS_H
#define UI_PROBE_PROPS_H

#include <stddef.h>

typedef enum ui_probe_field {
    UI_PROBE_UPDATE = 0, /* value: APP_PROBE_* */
    UI_PROBE_EVERY,      /* value: capture every N-th frame (N >= 1; selects every-frame) */
    UI_PROBE_RESOLUTION, /* value: texels per cube face side, 0 = auto */
    UI_PROBE_CORRECTION  /* value: APP_CORRECTION_* */
} ui_probe_field;

/* Combo labels in APP_PROBE_* and APP_CORRECTION_* order. */
extern const char *const ui_probe_update_labels[6];
extern const char *const ui_probe_correction_labels[5];

/* The resolution combo: "auto", "64" .. "512", plus the material's own value when it is
 * another one (a file may say 1024); items[] gets the labels (other[] holds the extra one),
 * *current the item showing `resolution`. Returns the item count (5 or 6). */
int ui_probe_resolution_items(int resolution, const char *items[6], char other[16], int *current);
/* The texels of resolution item k (0 = auto) as ui_probe_resolution_items listed them. */
int ui_probe_resolution_of(int k, int resolution);

/* The edit line for one field of material `material`: 0, or 1 when it does not fit. */
int ui_probe_line(char *out, size_t size, const char *material, ui_probe_field field, int value);

/* The `expect-probe MATERIAL UPDATE` script check (script.h): MATERIAL (quotes optional) is a
 * material of p, UPDATE a word of the `probe` line (every-frame, time-sliced, ...). 0 when
 * the material's policy is UPDATE; else 1 and why. */
struct app_project;
int ui_probe_expect(const struct app_project *p, const char *text, char *why, size_t why_size);

#endif
