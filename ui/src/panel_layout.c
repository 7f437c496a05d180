/* The window's rectangles from its size (panel_layout.h). The column widths hold the panels'
 * widest rows in Dear ImGui's default style (a combo with its label, the catalog's rows with a
 * 40 px thumbnail); wider windows give the extra room to the views. */
#include "panel_layout.h"

static float clampf(float v, float lo, float hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

static float column_width(float w, int right)
{
    if (w >= 1800)
        return right ? 380.0f : 320.0f;
    if (w >= 1200)
        return right ? 330.0f : 280.0f;
    if (w >= 900)
        return right ? 280.0f : 250.0f;
    return right ? 250.0f : 220.0f;
}

static void place_panes(ui_layout *out, int panes, float split, int active_2d)
{
    ui_rect c = out->centre;
    out->pane_2d = out->pane_3d = out->splitter = (ui_rect){0, 0, 0, 0};
    if (panes == UI_PANES_BOTH && c.w >= 2 * UI_LAYOUT_MIN_PANE_W + UI_LAYOUT_SPLITTER_W) {
        float room = c.w - UI_LAYOUT_SPLITTER_W;
        float w2d = clampf(split * room, UI_LAYOUT_MIN_PANE_W, room - UI_LAYOUT_MIN_PANE_W);
        w2d = (float)(int)w2d; /* whole pixels: the 3D view's viewport is in pixels */
        out->pane_2d = (ui_rect){c.x, c.y, w2d, c.h};
        out->splitter = (ui_rect){c.x + w2d, c.y, UI_LAYOUT_SPLITTER_W, c.h};
        float x3 = c.x + w2d + UI_LAYOUT_SPLITTER_W;
        out->pane_3d = (ui_rect){x3, c.y, c.x + c.w - x3, c.h};
    } else if (active_2d) {
        out->pane_2d = c;
    } else {
        out->pane_3d = c;
    }
}

void ui_layout_compute(int width, int height, int panes, float split, int active_2d, ui_layout *out)
{
    float w = (float)(width < UI_LAYOUT_MIN_W ? UI_LAYOUT_MIN_W : width);
    float h = (float)(height < UI_LAYOUT_MIN_H ? UI_LAYOUT_MIN_H : height);
    out->menu = (ui_rect){0, 0, w, UI_LAYOUT_MENU_H};
    out->toolbar = (ui_rect){0, UI_LAYOUT_MENU_H, w, UI_LAYOUT_TOOLBAR_H};
    out->status = (ui_rect){0, h - UI_LAYOUT_STATUS_H, w, UI_LAYOUT_STATUS_H};
    float top = UI_LAYOUT_MENU_H + UI_LAYOUT_TOOLBAR_H, body_h = h - UI_LAYOUT_STATUS_H - top;
    float left_w = column_width(w, 0), right_w = column_width(w, 1);
    out->left = (ui_rect){0, top, left_w, body_h};
    out->right = (ui_rect){w - right_w, top, right_w, body_h};
    out->centre = (ui_rect){left_w, top, w - left_w - right_w, body_h};
    place_panes(out, panes, split, active_2d);
    /* The catalog's list: three 44 px rows at least, more on a tall window (the column
     * scrolls to the product's details below it). */
    out->catalog_list_h = clampf(body_h * 0.45f, 3 * 44.0f, 420.0f);
    out->edit_narrow = left_w < 380.0f;
}

float ui_layout_split_at(const ui_layout *l, float x)
{
    float room = l->centre.w - UI_LAYOUT_SPLITTER_W;
    if (room <= 0)
        return 0.5f;
    float w2d = clampf(x - UI_LAYOUT_SPLITTER_W / 2 - l->centre.x, UI_LAYOUT_MIN_PANE_W,
                       room - UI_LAYOUT_MIN_PANE_W);
    return w2d / room;
}

int ui_rect_overlap(ui_rect a, ui_rect b)
{
    float ox = (a.x + a.w < b.x + b.w ? a.x + a.w : b.x + b.w) - (a.x > b.x ? a.x : b.x);
    float oy = (a.y + a.h < b.y + b.h ? a.y + a.h : b.y + b.h) - (a.y > b.y ? a.y : b.y);
    return ox > 1.0f && oy > 1.0f;
}

int ui_rect_contains(ui_rect r, double x, double y)
{
    return x >= r.x && y >= r.y && x < r.x + r.w && y < r.y + r.h;
}
