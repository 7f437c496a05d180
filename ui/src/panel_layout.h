/* The planner window's layout from its size, as desktop planners arrange it: a menu bar and a
 * toolbar at the top, a status bar at the bottom, a docked column of panels on each side (left:
 * View, Edit, Selection, Project; right: Catalog, Tiles, Quantities), and between them the
 * views in panes: the 2D view (plan or elevation) and the 3D view side by side with a draggable
 * splitter, or one of them alone. Nothing is drawn over a view: every rectangle is disjoint
 * from every other (tests/ui/test_panel_layout.c). Pure: no GL, no Dear ImGui. */
#ifndef UI_PANEL_LAYOUT_H
#define UI_PANEL_LAYOUT_H

#define UI_LAYOUT_MENU_H 19.0f    /* Dear ImGui's main menu bar: a 13 px font, 3 px padding */
#define UI_LAYOUT_TOOLBAR_H 34.0f /* 26 px icon buttons and their padding */
#define UI_LAYOUT_STATUS_H 22.0f
#define UI_LAYOUT_SPLITTER_W 6.0f
#define UI_LAYOUT_MIN_PANE_W 240.0f /* narrower panes: the active view alone */
#define UI_LAYOUT_MIN_W 640         /* smaller windows are laid out as 640 x 360 */
#define UI_LAYOUT_MIN_H 360

enum { UI_PANES_BOTH = 0, UI_PANES_ONE = 1 }; /* ONE: the active view alone */

typedef struct ui_rect {
    float x, y, w, h;
} ui_rect;

typedef struct ui_layout {
    ui_rect menu, toolbar, status;
    ui_rect left, right;  /* the docked panel columns */
    ui_rect centre;       /* between the columns: the panes and the splitter */
    ui_rect pane_2d;      /* plan or elevation; w = h = 0 when hidden */
    ui_rect pane_3d;      /* w = h = 0 when hidden */
    ui_rect splitter;     /* w = h = 0 unless both panes show */
    float catalog_list_h; /* the catalog browser's list of hits */
    int edit_narrow;      /* the Edit panel's buttons go one under the other */
} ui_layout;

/* The rectangles for a width x height window. panes: UI_PANES_*; split: the 2D pane's share of
 * the centre's width when both show (clamped so each keeps UI_LAYOUT_MIN_PANE_W); active_2d:
 * the view that shows alone (1: the 2D view, 0: the 3D view) under UI_PANES_ONE or when the
 * centre is too narrow for two panes. */
void ui_layout_compute(int width, int height, int panes, float split, int active_2d,
                       ui_layout *out);

/* The split that puts the splitter's centre at window x (a drag), clamped as above. */
float ui_layout_split_at(const ui_layout *l, float x);

/* 1 when the two rectangles share more than a pixel's width of area. */
int ui_rect_overlap(ui_rect a, ui_rect b);
/* 1 when (x, y) is inside r (left and top edges included). */
int ui_rect_contains(ui_rect r, double x, double y);

#endif
