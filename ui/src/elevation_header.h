/* The elevation pane's header: the surface's title, the tile summary and the pointer's (s, t)
 * readout, each on its own line at the pane's top left and elided with "..." to the pane's
 * width, so no two texts are drawn over each other and none runs past the pane's right edge.
 * Pure layout over a text-width function, tested without a window
 * (tests/ui/test_elevation_header.c); elevation_draw.c draws it. */
#ifndef UI_ELEVATION_HEADER_H
#define UI_ELEVATION_HEADER_H

enum { UI_ELEV_HEADER_LINES = 3, UI_ELEV_HEADER_TEXT = 300 };

typedef struct ui_elev_header_line {
    char text[UI_ELEV_HEADER_TEXT]; /* as drawn: empty when the line is not shown */
    float x, y, w, h;               /* the text's box, window pixels */
} ui_elev_header_line;

typedef struct ui_elev_header {
    ui_elev_header_line line[UI_ELEV_HEADER_LINES]; /* title, summary, readout */
    float bottom;                                   /* window y below the last shown line */
} ui_elev_header;

typedef float (*ui_text_width_fn)(const char *text);

/* Lays out title, summary and readout (readout may be NULL or empty: not shown) in the pane
 * x..x + w from y, one line each, line_h pixels high with 2 pixels between lines and a
 * 10-pixel margin on both sides. A text wider than the room left is cut at a character
 * boundary (never inside a UTF-8 sequence) and ends in "..."; width measures a text. */
void ui_elev_header_layout(float x, float y, float w, float line_h, ui_text_width_fn width,
                           const char *title, const char *summary, const char *readout,
                           ui_elev_header *out);

/* 1 when the boxes of two shown lines intersect (shared edges do not count). */
int ui_elev_header_lines_overlap(const ui_elev_header_line *a, const ui_elev_header_line *b);

/* text cut to fit max_w pixels with "..." at its end (as is when it fits) into out. */
void ui_elide_text(const char *text, float max_w, ui_text_width_fn width, char *out, int cap);

#endif
