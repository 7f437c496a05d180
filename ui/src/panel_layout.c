/* Panel rectangles from the window's size (panel_layout.h). The numbers are the panels'
 * contents in Dear ImGui's default style: a row (combo, input, button) is about 23 px, a line
 * of text 17 px, a title bar 19-20 px. */
#include "panel_layout.h"

#define MARGIN 10.0f
#define GAP 8.0f

static float clampf(float v, float lo, float hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

void ui_layout_compute(int width, int height, int has_selection, ui_layout *out)
{
    float w = (float)(width < 640 ? 640 : width), h = (float)(height < 360 ? 360 : height);
    int tall = h >= UI_LAYOUT_TALL;
    float left_w = w >= 1100 ? 260.0f : w >= 800 ? 250.0f : 220.0f;
    float right_w = w >= 1100 ? 340.0f : w >= 800 ? 300.0f : 250.0f;
    /* The Project panel gives its room to a selection's properties (its reflection and probe
     * fields need about 420 px) and comes back when nothing is selected. */
    out->project_collapsed = !tall || has_selection;
    out->quantities_collapsed = !tall;

    /* Left column: View on top, Project at the bottom, Selection between them. */
    float project_h = out->project_collapsed ? UI_LAYOUT_TITLE_H : 180.0f;
    out->project = (ui_rect){MARGIN, h - MARGIN - project_h, left_w, project_h};
    float room = out->project.y - GAP - MARGIN; /* for View and Selection */
    float view_h = 250.0f;                      /* every row of the View panel */
    if (has_selection)
        view_h = tall ? clampf(room - 420.0f - GAP, 150.0f, 250.0f)
                      : clampf(room * 0.38f, 110.0f, 250.0f);
    view_h = clampf(view_h, 60.0f, room);
    out->view = (ui_rect){MARGIN, MARGIN, left_w, view_h};
    float sel_y = MARGIN + view_h + GAP;
    out->selection = (ui_rect){MARGIN, sel_y, left_w, out->project.y - GAP - sel_y};

    /* Right column: the overlay, then Catalog, Quantities at the bottom. */
    float right_x = w - MARGIN - right_w;
    out->overlay = (ui_rect){w - UI_LAYOUT_OVERLAY_W, MARGIN, UI_LAYOUT_OVERLAY_W - MARGIN,
                             UI_LAYOUT_OVERLAY_H};
    float quant_h = tall ? 130.0f : UI_LAYOUT_TITLE_H;
    out->quantities = (ui_rect){right_x, h - MARGIN - quant_h, right_w, quant_h};
    float cat_y = MARGIN + UI_LAYOUT_OVERLAY_H + GAP;
    out->catalog = (ui_rect){right_x, cat_y, right_w, out->quantities.y - GAP - cat_y};
    /* The catalog: title, search, category, width filter and count (about 130 px), the
     * selected product's details below the list (about 150 px); the list takes the rest, at
     * least three rows (the panel scrolls to the details then). */
    out->catalog_list_h = clampf(out->catalog.h - 130.0f - 150.0f, 3 * 44.0f, 300.0f);

    /* Centre: Edit at the bottom between the columns, at most 400 wide; Tiles above it. */
    float centre_l = MARGIN + left_w + MARGIN, centre_r = right_x - MARGIN;
    float edit_w = clampf(centre_r - centre_l, 60.0f, 560.0f);
    float edit_h = tall ? 140.0f : 120.0f;
    out->edit =
        (ui_rect){(centre_l + centre_r) / 2 - edit_w / 2, h - MARGIN - edit_h, edit_w, edit_h};
    out->edit_narrow = edit_w < 380.0f;
    /* Tiles: beside the View panel (tile_panel.c places it at x 280, 280 wide). */
    out->tiles = (ui_rect){centre_l, MARGIN, clampf(centre_r - centre_l, 60.0f, 280.0f),
                           out->edit.y - GAP - MARGIN};
}

int ui_rect_overlap(ui_rect a, ui_rect b)
{
    float ox = (a.x + a.w < b.x + b.w ? a.x + a.w : b.x + b.w) - (a.x > b.x ? a.x : b.x);
    float oy = (a.y + a.h < b.y + b.h ? a.y + a.h : b.y + b.h) - (a.y > b.y ? a.y : b.y);
    return ox > 1.0f && oy > 1.0f;
}
