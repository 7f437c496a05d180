/* The live quantities and price panel: per tile product the laid area, whole
 * and cut tiles, boxes to order with the surplus and price; every placed product with its price;
 * net, VAT and the total. The numbers are app's (app/design/quantities.h, the same as `tessera
 * quantities`); this file keeps them up to date with the document and draws them. */
#ifndef UI_QUANTITIES_PANEL_H
#define UI_QUANTITIES_PANEL_H

#include "app/design/quantities.h"

typedef struct ui_quantities_view {
    int stale; /* the document changed since the last computation */
    int valid; /* q and bom hold the document's numbers */
    app_quantities q;
    app_bom bom;
    double compute_ms; /* the last computation's time */
    char error[1024];  /* why the numbers are missing */
} ui_quantities_view;

/* Computes the quantities and the bill of materials of p from db (the layouts with the room
 * model's regions, as `tessera quantities`). 0 ok; 1 on failure (v->error says why, the
 * previous numbers are dropped). */
int ui_quantities_refresh(ui_quantities_view *v, const app_project *p, cat_db *db);
void ui_quantities_free(ui_quantities_view *v);
/* Draws the panel at (x, y, width x height) the first time, or now when place is 1
 * (panel_layout.h), collapsed to its title bar then when collapsed is 1 (small windows);
 * refreshes first when stale. */
void ui_quantities_draw(ui_quantities_view *v, const app_project *p, cat_db *db, float x, float y,
                        float width, float height, int place, int collapsed);
/* "1234.56" for cents (negative with a minus). */
void ui_money(char *out, size_t size, long long cents);

#endif
