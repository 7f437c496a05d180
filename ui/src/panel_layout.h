/* Where the planner's panels go, from the window's size: a left column
 * (View, Selection, Project), a right column (the frame-time overlay, Catalog, Quantities and
 * price), the Edit panel at the bottom between them and the Tiles panel above it. Below
 * UI_LAYOUT_TALL pixels of height the Project and Quantities panels start collapsed to their
 * title bars and the View panel gives room to the selection; at any height the Project panel
 * collapses while something is selected; the catalog's list gets what is left, so nothing overlaps
 * at 800 x 450 or 1280 x 720 (tests/ui/test_panel_layout.c). Pure: no GL, no Dear ImGui. */
#ifndef UI_PANEL_LAYOUT_H
#define UI_PANEL_LAYOUT_H

#define UI_LAYOUT_TALL 600      /* window height from which every panel starts open */
#define UI_LAYOUT_TITLE_H 20    /* a collapsed panel: its title bar (Dear ImGui's default font) */
#define UI_LAYOUT_OVERLAY_H 105 /* the frame-time overlay, top right (planner_panels.c) */
#define UI_LAYOUT_OVERLAY_W 230

typedef struct ui_rect {
    float x, y, w, h;
} ui_rect;

typedef struct ui_layout {
    ui_rect view, selection, project, edit, catalog, quantities, overlay, tiles;
    int project_collapsed, quantities_collapsed; /* how they start at this size */
    float catalog_list_h;                        /* the catalog browser's list of hits */
    int edit_narrow; /* the Edit panel's buttons go one under the other */
} ui_layout;

/* The rectangles for a width x height window; has_selection: the Selection panel shows (it
 * takes room from the View panel). Sizes below 640 x 360 are laid out as 640 x 360. */
void ui_layout_compute(int width, int height, int has_selection, ui_layout *out);

/* 1 when the two rectangles share more than a pixel's width of area. */
int ui_rect_overlap(ui_rect a, ui_rect b);

#endif
