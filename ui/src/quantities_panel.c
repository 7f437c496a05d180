/* The live quantities and price panel (ui/src/quantities_panel.h). DOMAIN.md "What the best
 * planners print": the tile part list with whole and cut tiles and the amount to order with a
 * surplus, and the priced part list with VAT. */
#include "quantities_panel.h"

#include "app/design/room_surfaces.h"
#include "app/design/trims.h"
#include "gui.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void ui_money(char *out, size_t size, long long cents)
{
    snprintf(out, size, "%s%lld.%02lld", cents < 0 ? "-" : "", llabs(cents) / 100,
             llabs(cents) % 100);
}

void ui_quantities_free(ui_quantities_view *v)
{
    if (v->valid) {
        app_bom_free(&v->bom);
        app_quantities_free(&v->q);
    }
    v->valid = 0;
}

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

int ui_quantities_refresh(ui_quantities_view *v, const app_project *p, cat_db *db)
{
    ui_quantities_free(v);
    v->stale = 0;
    v->error[0] = 0;
    if (!db) {
        snprintf(v->error, sizeof v->error, "quantities: the catalog is not open");
        return 1;
    }
    double t0 = now_ms();
    app_tile_layout *layouts = NULL;
    int n = 0;
    memset(&v->q, 0, sizeof v->q);
    memset(&v->bom, 0, sizeof v->bom);
    app_result r = app_room_tile_layouts(p, db, &layouts, &n, v->error, sizeof v->error);
    if (r == APP_OK)
        r = app_quantities_compute(layouts, n, NULL, &v->q, v->error, sizeof v->error);
    if (r == APP_OK) {
        r = app_bom_build(db, p, &v->q, &v->bom, v->error, sizeof v->error);
        /* Trims, consumables and labour: the same positions as the quotation. */
        if (r == APP_OK)
            r = app_bom_add_project_trims(db, p, &v->bom, v->error, sizeof v->error);
        app_consumables c;
        if (r == APP_OK)
            r = app_consumables_compute(p, db, layouts, n, NULL, &c, v->error, sizeof v->error);
        if (r == APP_OK)
            r = app_bom_add_consumables(db, &c, NULL, &v->bom, v->error, sizeof v->error);
        if (r != APP_OK) {
            app_bom_free(&v->bom);
            app_quantities_free(&v->q);
        }
    }
    app_tile_layouts_free(layouts, n);
    v->compute_ms = now_ms() - t0;
    v->valid = r == APP_OK;
    return !v->valid;
}

static void tiles(const ui_quantities_view *v)
{
    for (int i = 0; i < v->q.line_count; i++) {
        const app_tile_quantity *t = &v->q.lines[i];
        ui_gui_text("%s %s: %.2f m2", t->spec.product.manufacturer, t->spec.product.article,
                    t->area_m2);
        ui_gui_text("  %d whole + %d cut tiles, %d cuts from offcuts", t->whole, t->cut, t->reused);
        ui_gui_text("  order %d boxes = %d pieces (+%.0f %% surplus)", t->boxes, t->pieces_to_order,
                    t->surplus_percent);
    }
}

void ui_quantities_draw(ui_quantities_view *v, const app_project *p, cat_db *db, float x, float y,
                        float width, float height, int place, int collapsed)
{
    if (v->stale)
        ui_quantities_refresh(v, p, db);
    /* Collapsed, the panel still says the total in its title bar (a small window). */
    char title[96] = "Quantities and price###quantities";
    if (v->valid) {
        char gross[32];
        ui_money(gross, sizeof gross, v->bom.gross_cents);
        snprintf(title, sizeof title, "Quantities and price: %s %s###quantities", gross,
                 v->bom.currency);
    }
    if (ui_gui_begin_placed(title, x, y, width, height, place, place ? collapsed : -1)) {
        if (!v->valid) {
            ui_gui_text_wrapped(v->error[0] ? v->error : "not computed yet");
        } else {
            /* The total first: it stays in view when the panel is small. */
            char net[32], gross[32], vat[32];
            ui_money(net, sizeof net, v->bom.net_cents);
            ui_money(vat, sizeof vat, v->bom.vat_cents);
            ui_money(gross, sizeof gross, v->bom.gross_cents);
            ui_gui_text("Total %s %s (net %s + VAT %s)", gross, v->bom.currency, net, vat);
            if (v->bom.missing)
                ui_gui_text("%d product(s) not in the catalog, priced 0", v->bom.missing);
            ui_gui_separator();
            if (v->q.line_count == 0)
                ui_gui_text("no tiled surface yet");
            else
                ui_gui_text("Tiles: %.2f m2 tiled", v->q.tiled_area_m2);
            tiles(v);
            ui_gui_separator();
            for (int i = 0; i < v->bom.line_count; i++) {
                const app_bom_line *l = &v->bom.lines[i];
                if (l->is_tile)
                    continue;
                ui_money(gross, sizeof gross, l->gross_cents);
                ui_gui_text("%g x %.28s  %s%s", l->quantity,
                            l->found ? l->name : l->product.article, gross,
                            l->found ? "" : " (not in the catalog)");
            }
            for (int i = 0; i < v->bom.line_count; i++) {
                const app_bom_line *l = &v->bom.lines[i];
                if (!l->is_tile)
                    continue;
                ui_money(gross, sizeof gross, l->gross_cents);
                ui_gui_text("%g %s %.24s  %s", l->quantity, cat_unit_name(l->unit), l->name, gross);
            }
            ui_gui_separator();
            ui_gui_text("(computed in %.1f ms)", v->compute_ms);
        }
    }
    ui_gui_end();
}
