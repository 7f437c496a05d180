/* The catalog browser panel (ui/src/catalog_browser.h). */
#include "catalog_browser.h"

#include "app/design/quantities.h"
#include "gui.h"
#include "thumbnails.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void ui_catalog_browser_open(ui_catalog_browser *b)
{
    memset(b, 0, sizeof *b);
    b->selected = -1;
    b->drag_hit = -1;
    b->dirty = 1;
    char src[1024];
    const char *env = getenv("TESSERA_ASSETS");
    snprintf(src, sizeof src, "%s/catalog", env && *env ? env : TESSERA_SOURCE_DIR "/assets");
    if (cat_catalog_open(NULL, src, &b->db, b->error, sizeof b->error) != CAT_DB_OK)
        b->db = NULL;
}

void ui_catalog_browser_close(ui_catalog_browser *b)
{
    cat_product_free(&b->product);
    cat_db_close(b->db);
    b->db = NULL;
}

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

int ui_catalog_browser_refresh(ui_catalog_browser *b)
{
    if (strcmp(b->text, b->searched_text) || b->category != b->searched_category ||
        b->max_width_mm != b->searched_max_width)
        b->dirty = 1;
    if (!b->dirty || !b->db)
        return 0;
    b->dirty = 0;
    memcpy(b->searched_text, b->text, sizeof b->text);
    b->searched_category = b->category;
    b->searched_max_width = b->max_width_mm;
    cat_search_filter f = {.category = (cat_category)b->category,
                           .max_width_mm = b->max_width_mm > 0 ? b->max_width_mm : 0};
    double t0 = now_ms();
    cat_db_result r = cat_search(b->db, b->text, &f, UI_BROWSER_MAX_HITS, b->hits, &b->hit_count,
                                 b->error, sizeof b->error);
    b->search_ms = now_ms() - t0;
    b->selected = -1;
    cat_product_free(&b->product);
    if (r != CAT_DB_OK) {
        b->hit_count = 0;
        return 1;
    }
    b->error[0] = 0;
    b->unmatched[0] = 0;
    if (b->hit_count == 0 && b->text[0] &&
        cat_search_unmatched(b->db, b->text, b->unmatched, sizeof b->unmatched, b->error,
                             sizeof b->error) != CAT_DB_OK)
        b->unmatched[0] = 0;
    return 0;
}

int ui_catalog_browser_select(ui_catalog_browser *b, int i)
{
    if (i < 0 || i >= b->hit_count || !b->db)
        return 1;
    cat_product_free(&b->product);
    b->selected = i;
    b->variant = 0;
    b->without_companions = 0;
    if (cat_product_get(b->db, b->hits[i].product_id, &b->product, b->error, sizeof b->error) !=
        CAT_DB_OK) {
        b->selected = -1;
        return 1;
    }
    return 0;
}

static const char *category_items[CAT_CATEGORY_COUNT];

static void details(ui_catalog_browser *b)
{
    const cat_product *p = &b->product;
    ui_gui_separator();
    ui_gui_text("%s", p->name);
    ui_gui_text("%s %s  art. %s", p->manufacturer, p->series, p->article);
    ui_gui_text("%.0f x %.0f x %.0f mm", p->width_mm, p->depth_mm, p->height_mm);
    long long cents = p->price_cents;
    if (b->variant < p->variant_count)
        cents += p->variants[b->variant].surcharge_cents;
    char vat[32];
    ui_gui_text("%lld.%02lld %s per %s + %s %% VAT", cents / 100, cents % 100, p->currency,
                cat_unit_name(p->unit), app_format_percent(p->vat_percent, vat, sizeof vat));
    for (int v = 0; v < p->variant_count; v++) {
        char label[128];
        snprintf(label, sizeof label, "%s %s##variant%d", p->variants[v].code, p->variants[v].name,
                 v);
        if (ui_gui_selectable(label, v == b->variant))
            b->variant = v;
    }
    if (p->mounting_to != CAT_MOUNT_NONE)
        ui_gui_text("mounted: %.0f mm to its %s", p->mounting_height_mm,
                    cat_mount_to_name(p->mounting_to));
    if (p->companions[0]) {
        /* The catalog says what goes with it (a vanity's basin, tap and mirror): a drop places
         * them too, unless the user turns it off here. */
        char maker[CAT_MANUFACTURER_BYTES + 1], article[CAT_ARTICLE_BYTES + 1];
        int n = 0;
        while (cat_companion_get(p->companions, n, maker, sizeof maker, article, sizeof article) ==
               1)
            n++;
        char label[64];
        snprintf(label, sizeof label, "[%s] place with its %d companion%s##companions",
                 b->without_companions ? " " : "x", n, n == 1 ? "" : "s");
        if (ui_gui_selectable(label, !b->without_companions))
            b->without_companions = !b->without_companions;
        for (int k = 0; k < n; k++) {
            cat_companion_get(p->companions, k, maker, sizeof maker, article, sizeof article);
            ui_gui_text("    + %s %s", maker[0] ? maker : p->manufacturer, article);
        }
    }
    if (p->short_text[0])
        ui_gui_text_wrapped(p->short_text);
}

void ui_catalog_browser_draw(ui_catalog_browser *b, float x, float y, float width, float height,
                             float list_height, int place)
{
    if (!category_items[0]) {
        category_items[0] = "all categories";
        for (int c = 1; c < CAT_CATEGORY_COUNT; c++)
            category_items[c] = cat_category_name((cat_category)c);
    }
    b->drag_hit = -1;
    if (ui_gui_begin_placed("Catalog", x, y, width, height, place, -1)) {
        ui_gui_input_text("search", b->text, sizeof b->text);
        ui_gui_combo("category", &b->category, category_items, CAT_CATEGORY_COUNT);
        ui_gui_input_float("max width mm", &b->max_width_mm, 50.0f);
        ui_catalog_browser_refresh(b);
        if (b->error[0])
            ui_gui_text_wrapped(b->error);
        if (b->unmatched[0])
            ui_gui_text("no match for '%s'", b->unmatched);
        else
            ui_gui_text("%d products (drag one into a view)", b->hit_count);
        if (ui_gui_begin_child("hits", 0.0f, list_height)) {
            for (int i = 0; i < b->hit_count; i++) {
                const cat_search_hit *h = &b->hits[i];
                char id[32], text[320];
                snprintf(id, sizeof id, "##hit%d", i);
                snprintf(text, sizeof text, "%s\n%.0f x %.0f mm  %lld.%02lld %s", h->name,
                         h->width_mm, h->depth_mm, h->price_cents / 100, h->price_cents % 100,
                         h->currency);
                /* A row's thumbnail is asked for only while the row is in view. */
                unsigned tex = ui_thumbnails_get(b->thumbs, h->product_id, 0);
                if (ui_gui_image_row(id, text, i == b->selected, tex, 40.0f))
                    ui_catalog_browser_select(b, i);
                if (!tex && ui_gui_item_visible())
                    ui_thumbnails_get(b->thumbs, h->product_id, 1);
                if (ui_gui_item_dragged())
                    b->drag_hit = i; /* pressed here and moved: a drag into a view */
            }
        }
        ui_gui_end_child();
        if (b->selected >= 0)
            details(b);
    }
    ui_gui_end();
}
