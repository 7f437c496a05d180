/* The tile panel ("tile assignment per surface with pattern, grout width and
 * colour, start point, border rows"): pick a surface (floor, ceiling, each wall, each face of
 * each pre-wall: app_room_surface_list), then its tile (the catalog browser's selected tile or
 * one from the catalog's tile list), pattern, rotation, grout width and colour, start point
 * (centred, corner, or a grid line through a point: also by clicking the elevation), the band
 * of a wall tiling and its border rows. Each change is one edit line through app's commands
 * (tile_actions.c), one undo step; the 3D view, the quantities and the elevation follow. */
#include "tiles.h"

#include "gui.h"
#include "panel_layout.h"

#include <stdio.h>
#include <string.h>

#define MAX_SURFACES 512

static const char *const pattern_names[6] = {"straight",       "half-offset", "third-offset",
                                             "vertical-stack", "diagonal",    "herringbone"};
static const char *const align_names[4] = {"centred", "corner", "line through a point",
                                           "auto (set-out)"};

static void load_fields(ui_tiles *t, const app_tiling *g, int index)
{
    t->shown_tiling = index;
    t->shown_hash = t->hash;
    t->pattern = (int)g->pattern;
    t->align = (int)g->align;
    t->rotation = g->rotation_deg;
    t->grout_mm = (float)g->grout_mm;
    memcpy(t->grout_rgb, g->grout_color, sizeof t->grout_rgb);
    t->start[0] = g->origin_mm[0];
    t->start[1] = g->origin_mm[1];
    t->band[0] = g->from_mm;
    t->band[1] = g->to_mm;
    for (int k = 0; k < g->border_count && k < APP_TILING_MAX_BORDERS; k++)
        t->border_at[k] = g->borders[k].bottom_mm;
}

static void catalog_tiles(planner *p, ui_tiles *t)
{
    if (t->catalog_loaded)
        return;
    t->catalog_loaded = 1;
    cat_db *db = ui_tiles_db(p);
    cat_search_filter f = {.category = CAT_CATEGORY_TILES};
    char err[512];
    if (!db || cat_search(db, "", &f, UI_TILES_MAX_CATALOG, t->catalog, &t->catalog_count, err,
                          sizeof err) != CAT_DB_OK)
        t->catalog_count = 0;
}

/* The tile: the browser's selected tile, or one from the catalog's list. */
static void tile_choice(planner *p, ui_tiles *t)
{
    const cat_product *b = &p->browser.product;
    if (p->browser.selected >= 0 && b->has_tile) {
        char label[200];
        snprintf(label, sizeof label, "Use the browser's %.60s", b->name);
        if (ui_gui_button(label)) {
            app_product_ref ref;
            ui_tiles_ref_of(b, p->browser.variant, &ref);
            planner_tile_product(p, t->surface, &ref);
        }
    }
    catalog_tiles(p, t);
    if (t->catalog_count > 0) {
        const char *names[UI_TILES_MAX_CATALOG];
        for (int i = 0; i < t->catalog_count; i++)
            names[i] = t->catalog[i].name;
        int pick = t->catalog_pick;
        if (ui_gui_combo("tile", &pick, names, t->catalog_count) && pick >= 0) {
            t->catalog_pick = pick;
            cat_product hit;
            memset(&hit, 0, sizeof hit);
            memcpy(hit.manufacturer, t->catalog[pick].manufacturer, sizeof hit.manufacturer);
            memcpy(hit.article, t->catalog[pick].article, sizeof hit.article);
            app_product_ref ref;
            ui_tiles_ref_of(&hit, -1, &ref);
            planner_tile_product(p, t->surface, &ref);
        }
    }
}

static void tiling_fields(planner *p, ui_tiles *t, int i)
{
    const app_tiling *g = &p->project.tilings[i];
    if (t->shown_tiling != i || t->shown_hash != t->hash)
        load_fields(t, g, i);
    ui_gui_text("%s %s %s", g->product.manufacturer, g->product.article, g->product.variant);
    if (i < t->layout_count) {
        const app_tile_layout *l = &t->layouts[i];
        int whole, cut;
        ui_elev_count_tiles(l, &whole, &cut);
        ui_gui_text("%.0f x %.0f mm: %d whole, %d cut, %.2f m2", l->specs[0].work_w_mm,
                    l->specs[0].work_h_mm, whole, cut, l->region_area_mm2 * 1e-6);
    }
    if (ui_gui_combo("pattern", &t->pattern, pattern_names, 6))
        planner_tile_pattern(p, i, (app_tile_pattern)t->pattern);
    if (ui_gui_input_double_enter("rotation", &t->rotation))
        planner_tile_rotation(p, i, t->rotation);
    int grout = ui_gui_slider_commit("grout mm", &t->grout_mm, 0.0f, 15.0f);
    grout |= ui_gui_slider_commit("red", &t->grout_rgb[0], 0.0f, 1.0f);
    grout |= ui_gui_slider_commit("green", &t->grout_rgb[1], 0.0f, 1.0f);
    grout |= ui_gui_slider_commit("blue", &t->grout_rgb[2], 0.0f, 1.0f);
    if (grout)
        planner_tile_grout(p, i, t->grout_mm, t->grout_rgb);
    if (ui_gui_combo("start", &t->align, align_names, 4))
        planner_tile_start(p, i, (app_tile_align)t->align, t->start[0], t->start[1]);
    if (t->align == APP_ALIGN_LINE) {
        int moved = ui_gui_input_double_enter("start s", &t->start[0]);
        moved |= ui_gui_input_double_enter("start t", &t->start[1]);
        if (moved)
            planner_tile_start(p, i, APP_ALIGN_LINE, t->start[0], t->start[1]);
    }
    int vertical = t->frame.kind == APP_SURFACE_WALL || t->frame.kind == APP_SURFACE_PREWALL_SIDE;
    if (!vertical)
        return;
    int band = ui_gui_input_double_enter("band from", &t->band[0]);
    band |= ui_gui_input_double_enter("band to", &t->band[1]);
    if (band)
        planner_tile_band(p, i, t->band[0], t->band[1]);
    for (int k = 0; k < g->border_count; k++) {
        char label[64];
        snprintf(label, sizeof label, "row %d at##b%d", k + 1, k);
        if (ui_gui_input_double_enter(label, &t->border_at[k]))
            planner_tile_border_move(p, i, k, t->border_at[k]);
        ui_gui_same_line();
        snprintf(label, sizeof label, "x##rb%d", k);
        if (ui_gui_button(label)) {
            planner_tile_border_remove(p, i, k);
            return; /* the tiling changed under the loop */
        }
    }
    const cat_product *b = &p->browser.product;
    if (p->browser.selected >= 0 && b->has_tile && g->border_count < APP_TILING_MAX_BORDERS) {
        ui_gui_input_double_enter("new row at", &t->new_border_at);
        if (ui_gui_button("Add a border row of the browser's tile")) {
            app_product_ref ref;
            ui_tiles_ref_of(b, p->browser.variant, &ref);
            planner_tile_border_add(p, i, &ref, t->new_border_at);
        }
    }
}

void planner_tile_panel(planner *p, int width, int height)
{
    /* Shown with the elevation, with the plan when a wall is selected (for that wall), and
     * with the 3D view after "Back to 3D" (until closed). */
    (void)width;
    (void)height;
    int wall = p->plan_o.selected_wall;
    /* The 2D pane shows the active view when it is the plan or the elevation, else the last
     * of them (window_panes.c); the active view always shows. */
    int active_2d = p->view == UI_VIEW_PLAN || p->view == UI_VIEW_ELEVATION;
    int view_2d = active_2d ? p->view : p->view_2d;
    int shown_2d = active_2d || p->layout.pane_2d.w > 0;
    int elevation = shown_2d && view_2d == UI_VIEW_ELEVATION;
    int plan_wall =
        shown_2d && view_2d == UI_VIEW_PLAN && wall >= 0 && wall < p->project.plan.corner_count;
    if (!elevation && !plan_wall && (!p->tiles || !p->tiles->in_3d))
        return;
    ui_tiles *t = planner_tiles(p);
    if (!t)
        return;
    if (plan_wall && wall != t->plan_wall) {
        /* A wall picked in the plan: the panel shows it (the surface list may pick another). */
        char s[32];
        snprintf(s, sizeof s, "wall:%d", wall);
        ui_tiles_show(p, s);
        t->plan_wall = wall;
    }
    ui_tiles_refresh(p, t);
    /* A section of the right column (panel_layout.h); the elevation has the 2D pane. */
    const ui_rect *r = &p->layout.right;
    if (ui_gui_begin("Tiles", r->x, r->y, r->w, r->h)) {
        const char *names[MAX_SURFACES];
        int n = 0, current = -1;
        for (int k = 0; k < t->surface_count && n < MAX_SURFACES; k++, n++) {
            names[n] = t->surfaces[k].surface;
            if (!strcmp(names[n], t->surface))
                current = n;
        }
        if (ui_gui_combo("surface", &current, names, n) && current >= 0)
            ui_tiles_show(p, names[current]);
        if (!elevation && ui_gui_button("Show its elevation"))
            p->view = UI_VIEW_ELEVATION;
        if (!elevation && !plan_wall) {
            /* Over the 3D view the edits show live in the room; Close puts the panel away. */
            ui_gui_same_line();
            if (ui_gui_button("Close"))
                t->in_3d = 0;
        }
        if (elevation) {
            if (ui_gui_button("Back to 3D")) { /* the panel comes along; the plan comes back */
                p->view = UI_VIEW_3D;
                p->view_2d = UI_VIEW_PLAN;
                t->in_3d = 1;
            }
            /* Zoom about the drawing's centre; the right button pans. */
            ui_gui_same_line();
            if (ui_gui_button(" + "))
                t->zoom = t->zoom * 1.25 < 20 ? t->zoom * 1.25 : 20;
            ui_gui_same_line();
            if (ui_gui_button(" - "))
                t->zoom = t->zoom / 1.25 > 0.25 ? t->zoom / 1.25 : 0.25;
            ui_gui_same_line();
            if (ui_gui_button("fit")) {
                t->zoom = 1;
                t->pan[0] = t->pan[1] = 0;
            }
        }
        /* A surface may carry several tilings (a band below, another above). */
        const char *regions[16];
        int count = 0;
        for (int k = 0; k < 16 && ui_tiles_on_surface(&p->project, t->surface, k) >= 0; k++)
            regions[count++] =
                p->project.tilings[ui_tiles_on_surface(&p->project, t->surface, k)].name;
        if (t->pick >= count)
            t->pick = 0;
        if (count > 1)
            ui_gui_combo("tiling", &t->pick, regions, count);
        ui_gui_separator();
        if (t->error[0])
            ui_gui_text_wrapped(t->error);
        int i = ui_tiles_on_surface(&p->project, t->surface, t->pick);
        if (i >= 0)
            tiling_fields(p, t, i);
        else
            ui_gui_text("%s is not tiled", t->surface);
        ui_gui_separator();
        tile_choice(p, t);
        if (i >= 0 && ui_gui_button("Remove this tiling"))
            planner_untile(p, i);
    }
    ui_gui_end();
}
