/* The live quantities and price panel's numbers (ui/src/quantities_panel.h) with the shipped
 * catalog and the designed demo: they are app's quantities and bill of materials, the total
 * adds up its lines, and placing a product raises the total by exactly that product's gross
 * price (as the panel recomputes after every edit). Money formatting. */
#include "app/project/commands.h"
#include "check.h"
#include "quantities_panel.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void test_money(void)
{
    char b[32];
    ui_money(b, sizeof b, 123456);
    CHECK(!strcmp(b, "1234.56"));
    ui_money(b, sizeof b, 5);
    CHECK(!strcmp(b, "0.05"));
    ui_money(b, sizeof b, -1999);
    CHECK(!strcmp(b, "-19.99"));
}

static void test_demo(void)
{
    char err[1024] = "", dir[] = "/tmp/tessera-ui-qty-XXXXXX", db_path[512];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(db_path, sizeof db_path, "%s/catalog.sqlite", dir);
    cat_db *db = NULL;
    CHECK_MSG(cat_catalog_open(db_path, TESSERA_SOURCE_DIR "/assets/catalog", &db, err,
                               sizeof err) == CAT_DB_OK,
              "%s", err);
    app_project p;
    CHECK_MSG(app_project_read(TESSERA_SOURCE_DIR "/assets/projects/designed-bathroom.json", &p,
                               err, sizeof err) == APP_OK,
              "%s", err);
    if (!db)
        return;

    ui_quantities_view v;
    memset(&v, 0, sizeof v);
    /* No catalog: no numbers, and the panel says why. */
    CHECK(ui_quantities_refresh(&v, &p, NULL) == 1 && !v.valid && strstr(v.error, "catalog"));

    CHECK_MSG(ui_quantities_refresh(&v, &p, db) == 0, "%s", v.error);
    CHECK(v.valid && !v.stale);
    if (!v.valid)
        return;
    /* The demo tiles walls and floor with three products; every line is priced. */
    CHECK(v.q.line_count >= 2);
    CHECK(v.q.tiled_area_m2 > 10 && v.q.tiled_area_m2 < 60);
    for (int i = 0; i < v.q.line_count; i++) {
        const app_tile_quantity *t = &v.q.lines[i];
        CHECK(t->whole + t->cut > 0 && t->boxes > 0 && t->pieces_to_order >= t->pieces_needed);
    }
    long long sum = 0;
    int fixtures = 0;
    for (int i = 0; i < v.bom.line_count; i++) {
        sum += v.bom.lines[i].gross_cents;
        fixtures += !v.bom.lines[i].is_tile;
    }
    CHECK(sum == v.bom.gross_cents);
    CHECK(v.bom.net_cents + v.bom.vat_cents == v.bom.gross_cents);
    CHECK(v.bom.missing == 0 && !strcmp(v.bom.currency, "EUR"));
    CHECK(fixtures >= 10);
    long long before = v.bom.gross_cents;
    printf("designed demo: total %.2f EUR, %d tile products, %d lines, %.1f ms\n", before / 100.0,
           v.q.line_count, v.bom.line_count, v.compute_ms);

    /* Place one hand basin: the total rises by its gross price and its installation. */
    app_lazy_catalog lazy = {.db_path = db_path};
    app_script_env env = {.lookup = app_placement_lazy_lookup, .user = &lazy};
    app_history *h = app_history_create(10);
    const char *line = "place \"Cerana\" \"CE411001\" WH at 1200 300 0";
    CHECK_MSG(app_script_run(&p, h, line, strlen(line), "test", &env, NULL, err, sizeof err) ==
                  APP_OK,
              "%s", err);
    cat_search_hit hit;
    int n = 0;
    CHECK(cat_search(db, "CE411001", NULL, 1, &hit, &n, err, sizeof err) == CAT_DB_OK && n == 1);
    cat_product prod;
    long long expect = 0;
    if (n == 1 && cat_product_get(db, hit.product_id, &prod, err, sizeof err) == CAT_DB_OK) {
        long long net = prod.price_cents;
        for (int i = 0; i < prod.variant_count; i++)
            if (!strcmp(prod.variants[i].code, "WH"))
                net += prod.variants[i].surcharge_cents;
        expect = net + llround(net * prod.vat_percent / 100.0);
        cat_product_free(&prod);
    }
    /* ... and one fixture installation (the labour line, docs/tiling.md). */
    app_consumable_rules rules = app_consumable_rules_default();
    memset(&prod, 0, sizeof prod);
    CHECK(cat_product_find(db, rules.labour_fixture.manufacturer, rules.labour_fixture.article,
                           &prod, err, sizeof err) == CAT_DB_OK);
    if (prod.price_cents > 0) {
        expect += prod.price_cents + llround(prod.price_cents * prod.vat_percent / 100.0);
        cat_product_free(&prod);
    }
    CHECK_MSG(ui_quantities_refresh(&v, &p, db) == 0, "%s", v.error);
    CHECK_MSG(llabs(v.bom.gross_cents - before - expect) <= 1,
              "total %lld -> %lld, the basin and its installation cost %lld", before,
              v.bom.gross_cents, expect);
    /* Undo: back to the same total. */
    CHECK(app_history_undo(h, &p, err, sizeof err) == APP_OK);
    CHECK(ui_quantities_refresh(&v, &p, db) == 0 && v.bom.gross_cents == before);

    ui_quantities_free(&v);
    CHECK(!v.valid);
    ui_quantities_free(&v); /* twice is harmless */
    app_history_destroy(h);
    app_placement_lazy_close(&lazy);
    app_project_free_all(&p);
    cat_db_close(db);
    unlink(db_path);
    rmdir(dir);
}

int main(void)
{
    test_money();
    test_demo();
    return check_report("ui.quantities_panel");
}
