/* Tiling in the planner: the tile panel (tile_panel.c: a surface's
 * tile, pattern, rotation, grout, start point, band and border rows), the wall elevation view
 * (elevation_draw.c: the surface unfolded with its exact tile layout) and their script actions
 * (tile_actions.c). Every change is an edit line through app's commands (planner_edit), so it
 * is one undo step and the 3D view follows. Internal to ui/. */
#ifndef UI_TILES_H
#define UI_TILES_H

#include "app/design/room_surfaces.h"
#include "app/design/tile_layout.h"
#include "catalog/catalog.h"
#include "elevation_view.h"
#include "planner.h"

#define UI_TILES_MAX_CATALOG 200

typedef struct ui_tiles {
    char surface[96]; /* the surface the panel and the elevation show */
    int pick;         /* which of the surface's tilings the panel edits (0 = the first) */
    int plan_wall;    /* the plan's selected wall the panel last followed (-1 = none) */
    int in_3d;        /* the panel shows over the 3D view too (opened from the elevation) */

    /* Derived from the document, recomputed when it changes (a hash of what they depend on). */
    unsigned long long hash;
    int valid;
    double refresh_ms; /* the last recomputation of the layouts (wall clock) */
    char error[1024];  /* why the layouts could not be made, shown in the view and the panel */
    app_surface_frame *surfaces;
    int surface_count;
    app_fixture_box *boxes; /* fixtures covering surfaces (baths, trays) */
    int box_count;
    app_tile_layout *layouts; /* app_room_tile_layouts: one per tiling, in the project's order */
    int layout_count;
    float (*colours)[1 + APP_TILING_MAX_BORDERS][3]; /* per layout and spec, sRGB 0-1 */
    /* The shown surface's frame and region (outline, openings, covered parts). */
    app_surface_region region;
    app_surface_frame frame;
    char region_surface[96];
    int region_ok;

    /* The elevation view: fitted between the panels, then zoomed (1 = fitted) about its
     * centre and panned (surface mm) by the panel's buttons and a right-button drag. */
    ui_elev_transform view;
    double zoom, pan[2];
    int panning;
    float pan_x, pan_y;
    int pressed;
    float press_x, press_y;
    int hovering;
    double hover[2];

    /* The panel's fields, reloaded when the document or the tiling shown changes. */
    int shown_tiling;
    unsigned long long shown_hash;
    float grout_mm, grout_rgb[3];
    double rotation, start[2], band[2], border_at[APP_TILING_MAX_BORDERS], new_border_at;
    int pattern, align;
    cat_search_hit catalog[UI_TILES_MAX_CATALOG]; /* the catalog's tiles, for the tile list */
    int catalog_count, catalog_loaded, catalog_pick;
} ui_tiles;

/* The planner's tile state, made on first use (NULL when out of memory). */
ui_tiles *planner_tiles(planner *p);
/* Brings the surfaces, layouts and the shown surface's region up to date with the document;
 * cheap when nothing changed. 0 ok, 1 failed (t->error says why). */
int ui_tiles_refresh(planner *p, ui_tiles *t);
/* The catalog the layouts take their tiles from (the browser's, else the planner's). */
cat_db *ui_tiles_db(planner *p);

/* The tiling a script or an edit line means by SURFACE: the first on that surface, else the
 * one of that name; -1 if none. */
int ui_tiles_find(const app_project *p, const char *surface_or_name);
/* The k-th tiling (from 0) on a surface, or -1. */
int ui_tiles_on_surface(const app_project *p, const char *surface, int k);
/* A product reference to a catalog product and its variant (index, out of range: none). */
void ui_tiles_ref_of(const cat_product *prod, int variant, app_product_ref *ref);
/* Shows a surface in the panel and the elevation. */
void ui_tiles_show(planner *p, const char *surface);

/* Edit lines (docs/editing.md) for tiling `tiling`, each one undo step; 0 ok, 1 refused (the
 * status says why). */
int planner_tile_pattern(planner *p, int tiling, app_tile_pattern pattern);
int planner_tile_grout(planner *p, int tiling, double mm, const float rgb[3]);
int planner_tile_start(planner *p, int tiling, app_tile_align align, double s, double t);
int planner_tile_rotation(planner *p, int tiling, double deg);
int planner_tile_band(planner *p, int tiling, double from, double to);
int planner_tile_border_add(planner *p, int tiling, const app_product_ref *ref, double bottom);
int planner_tile_border_move(planner *p, int tiling, int k, double bottom);
int planner_tile_border_remove(planner *p, int tiling, int k);
int planner_tile_product(planner *p, const char *surface, const app_product_ref *ref);
int planner_untile(planner *p, int tiling);
/* A click on the elevation at surface point (s, t): the shown surface's tiling starts there
 * (its grid passes through the point, snapped to 10 mm). */
int planner_elevation_click(planner *p, double s, double t);

#endif
