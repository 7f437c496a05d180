/* The catalog browser panel: search as you type over the catalog's full-text
 * index, category and width filters, a product's details with its variants and price. The
 * search itself is the catalog's (cat_search); this file only keeps the panel's state. */
#ifndef UI_CATALOG_BROWSER_H
#define UI_CATALOG_BROWSER_H

#include "catalog/catalog.h"

#define UI_BROWSER_MAX_HITS 200

typedef struct ui_catalog_browser {
    cat_db *db;
    char error[1024]; /* shown in the panel when the catalog cannot be opened */
    char text[128], searched_text[128];
    int category, searched_category; /* 0 = all, else a cat_category */
    float max_width_mm, searched_max_width;
    int dirty; /* the query changed: search again */
    cat_search_hit hits[UI_BROWSER_MAX_HITS];
    int hit_count;
    char unmatched[128];          /* no hits: the search word that matches nothing, or "" */
    double search_ms;             /* the last search's time, shown beside the hits */
    int selected;                 /* index into hits, -1 = none */
    cat_product product;          /* details of the selected hit */
    int variant;                  /* selected variant of product */
    int without_companions;       /* 1: a drop places the product alone, not with its companions */
    struct ui_thumbnails *thumbs; /* thumbnails of the hits (NULL: none shown) */
    int drag_hit; /* a hit being dragged out of the list this frame (drag and drop), -1 = none */
} ui_catalog_browser;

/* Opens the catalog (--db semantics of `tessera catalog`: $TESSERA_CATALOG or the user's
 * cache, built from the shipped data on first use). On failure the panel shows why. */
void ui_catalog_browser_open(ui_catalog_browser *b);
void ui_catalog_browser_close(ui_catalog_browser *b);
/* Runs the search when the query changed (as the user types). 0 ok, 1 failed (b->error). */
int ui_catalog_browser_refresh(ui_catalog_browser *b);
/* Selects hit i and loads its details. */
int ui_catalog_browser_select(ui_catalog_browser *b, int i);
/* Draws the panel; a hit pressed and dragged sets b->drag_hit (the planner's drag_drop.c
 * takes it from there). */
/* At (x, y, width x height) the first time, or now when place is 1 (panel_layout.h); the
 * list of hits is list_height pixels tall. */
void ui_catalog_browser_draw(ui_catalog_browser *b, float x, float y, float width, float height,
                             float list_height, int place);

#endif
