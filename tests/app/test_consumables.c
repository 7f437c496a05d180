/* Consumables, labour and the quote (app/design/quantities.h, app/output/quote.h;
 * docs/tiling.md "Consumables and labour"), on projects whose figures are worked out by hand
 * below, priced from the shipped catalog (assets/catalog/consumables.csv). */
#include "app/design/quantities.h"
#include "app/design/room_surfaces.h"
#include "app/output/quote.h"
#include "catalog/catalog.h"

#include "../common/check.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static cat_db *db;

typedef struct run {
    app_project p;
    app_tile_layout *layouts;
    int n;
    app_quantities q;
    app_consumables c;
    app_bom bom;
} run;

static int compute(const char *name, run *r)
{
    char path[1024], err[2048] = "";
    memset(r, 0, sizeof *r);
    snprintf(path, sizeof path, "%s/tests/data/tiles/%s", TESSERA_SOURCE_DIR, name);
    if (app_project_read(path, &r->p, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return 0;
    }
    app_result res = app_room_tile_layouts(&r->p, db, &r->layouts, &r->n, err, sizeof err);
    if (res == APP_OK)
        res = app_quantities_compute(r->layouts, r->n, NULL, &r->q, err, sizeof err);
    if (res == APP_OK)
        res = app_bom_build(db, &r->p, &r->q, &r->bom, err, sizeof err);
    if (res == APP_OK)
        res = app_consumables_compute(&r->p, db, r->layouts, r->n, NULL, &r->c, err, sizeof err);
    if (res == APP_OK)
        res = app_bom_add_consumables(db, &r->c, NULL, &r->bom, err, sizeof err);
    CHECK_MSG(res == APP_OK, "%s: %s", name, err);
    return res == APP_OK;
}

static void release(run *r)
{
    app_bom_free(&r->bom);
    app_quantities_free(&r->q);
    app_tile_layouts_free(r->layouts, r->n);
    app_project_free(&r->p);
}

static const app_bom_line *line_of(const app_bom *b, const char *article)
{
    for (int i = 0; i < b->line_count; i++)
        if (!strcmp(b->lines[i].product.article, article))
            return &b->lines[i];
    return NULL;
}

static void test_rates(void)
{
    /* DOMAIN.md: 2.5-5 kg/m2 by tile size. */
    CHECK_NEAR(app_adhesive_kg_per_m2(100, 100), 2.5, 0);
    CHECK_NEAR(app_adhesive_kg_per_m2(148, 148), 2.5, 0);
    CHECK_NEAR(app_adhesive_kg_per_m2(297, 297), 3.0, 0);
    CHECK_NEAR(app_adhesive_kg_per_m2(297, 597), 4.0, 0); /* 0.18 m2 */
    CHECK_NEAR(app_adhesive_kg_per_m2(597, 597), 5.0, 0); /* 0.36 m2: large format */
    CHECK_NEAR(app_adhesive_kg_per_m2(1197, 597), 5.0, 0);
}

/* tests/data/tiles/setout_floor.json: a 1800 x 2400 floor, 600 x 600 (work 597 x 597, 10 mm
 * thick) on a 2 mm joint, the edge joint the joint width: 3 x 4 whole tiles.
 *  - tiled region 1796 x 2396 = 4 303 216 mm2; adhesive 5.0 kg/m2 (0.36 m2 tiles):
 *    21.51608 kg = 1 bag of 25 kg;
 *  - joints: 2 joints across each of 4 rows (edges 597 long on both sides: 16 edges) and 3
 *    joints along each of 3 columns (18 edges): 34 x 597 / 2 = 10 149 mm; grout 10 149 x 2 x
 *    10 mm3 = 0.20298 dm3 x 1.6 = 0.324768 kg = 1 bag of 5 kg;
 *  - edge joint: the floor's perimeter 2 x (1800 + 2400) = 8 400 mm; silicone 5 x 5 mm bead
 *    (the 2 mm gap is narrower than 5): 8.4 x 25 = 210 ml = 1 cartridge;
 *  - labour: 4.303216 m2 billed as 4.31 m2 x 48.00 = 206.88; no fixtures, no shower. */
static void test_floor(void)
{
    run r;
    if (!compute("setout_floor.json", &r))
        return;
    CHECK_NEAR(r.c.floor_m2, 4.303216, 1e-9);
    CHECK_NEAR(r.c.wall_m2, 0, 0);
    CHECK_NEAR(r.c.adhesive_kg, 21.51608, 1e-9);
    CHECK(r.c.adhesive_bags == 1);
    CHECK_NEAR(r.c.joint_length_m, 10.149, 1e-6);
    CHECK_NEAR(r.c.grout_dm3, 0.20298, 1e-9);
    CHECK_NEAR(r.c.grout_kg, 0.324768, 1e-9);
    CHECK(r.c.grout_bags == 1);
    CHECK_NEAR(r.c.edge_joint_m, 8.4, 1e-6);
    CHECK_NEAR(r.c.silicone_ml, 210.0, 1e-6);
    CHECK(r.c.silicone_cartridges == 1);
    CHECK_NEAR(r.c.waterproofing_m2, 0, 0);
    CHECK(r.c.fixtures == 0);
    const app_bom_line *l = line_of(&r.bom, "LAB-TILE-FLOOR");
    CHECK(l && l->kind == APP_BOM_LABOUR && l->unit == CAT_UNIT_M2);
    if (l) {
        CHECK_NEAR(l->quantity, 4.31, 1e-9);
        CHECK(l->net_cents == 20688);
    }
    l = line_of(&r.bom, "FW-C2-25");
    CHECK(l && l->kind == APP_BOM_CONSUMABLE && l->quantity == 1 && l->net_cents == 2190);
    CHECK(l && strstr(l->detail, "21.5 kg"));
    CHECK(line_of(&r.bom, "FW-DS-M2") == NULL);      /* no shower: no line */
    CHECK(line_of(&r.bom, "LAB-TILE-WALL") == NULL); /* no wall tiled */
    CHECK(line_of(&r.bom, "LAB-FIXTURE") == NULL);
    /* The tiles 5.76 m2 x 42.90 = 247.10; adhesive 21.90, grout 14.90, silicone 7.90, labour
     * 206.88: net 498.68, VAT 19 % 94.75 (per line: 46.95 + 4.16 + 2.83 + 1.50 + 39.31),
     * gross 593.43. */
    CHECK(r.bom.net_cents == 49868);
    CHECK(r.bom.vat_cents == 9475);
    CHECK(r.bom.gross_cents == 59343);
    release(&r);
}

/* tests/data/tiles/consumables_wall.json: wall 0 of 1803 x 2403 in 300 x 600 (work 297 x 597,
 * 10 mm) on a 3 mm joint: 3 columns x 8 rows whole; a 900 x 900 tray in the corner of walls 2
 * and 3.
 *  - region 1797 x 2397 = 4 307 409 mm2; adhesive 4.0 kg/m2 (0.18 m2 tiles) = 17.229636 kg;
 *  - joints: 2 per row x 8 rows, edges 297 (32 edges), 7 per column x 3 columns, edges 597 (42
 *    edges): (32 x 297 + 42 x 597) / 2 = 17 289 mm; grout x 3 x 10 = 0.51867 dm3, 0.829872 kg;
 *  - edge joint: 2 x (1803 + 2403) = 8 412 mm, 210.3 ml: 1 cartridge;
 *  - waterproofing: the tray's floor 0.81 m2 and 900 mm of each wall it stands against to
 *    2000 mm: 0.81 + 2 x 1.8 = 4.41 m2;
 *  - labour: wall 4.31 m2, one product installed. */
static void test_wall(void)
{
    run r;
    if (!compute("consumables_wall.json", &r))
        return;
    CHECK(r.q.line_count == 1 && r.q.lines[0].whole == 24 && r.q.lines[0].cut == 0);
    CHECK_NEAR(r.c.wall_m2, 4.307409, 1e-9);
    CHECK_NEAR(r.c.floor_m2, 0, 0);
    CHECK_NEAR(r.c.adhesive_kg, 17.229636, 1e-9);
    CHECK_NEAR(r.c.joint_length_m, 17.289, 1e-6);
    CHECK_NEAR(r.c.grout_kg, 0.829872, 1e-9);
    CHECK_NEAR(r.c.edge_joint_m, 8.412, 1e-6);
    CHECK(r.c.silicone_cartridges == 1);
    CHECK(r.c.shower_zones == 1);
    CHECK_NEAR(r.c.waterproofing_m2, 4.41, 1e-9);
    CHECK(r.c.fixtures == 1);
    const app_bom_line *l = line_of(&r.bom, "FW-DS-M2");
    CHECK(l && l->unit == CAT_UNIT_M2 && fabs(l->quantity - 4.41) < 1e-9);
    if (l)
        CHECK(l->net_cents == 5513); /* 4.41 x 12.50 = 55.125, rounded half up */
    l = line_of(&r.bom, "LAB-TILE-WALL");
    CHECK(l && fabs(l->quantity - 4.31) < 1e-9 && l->net_cents == 23274);
    l = line_of(&r.bom, "LAB-FIXTURE");
    CHECK(l && l->quantity == 1 && l->net_cents == 8500);

    /* The quote: the project's customer, number and validity. */
    app_quote q;
    char err[1024];
    CHECK(app_quote_make(&r.p, NULL, "2026-12-20", &q, err, sizeof err) == APP_OK);
    CHECK(!strcmp(q.number, "Q-2026-0042"));
    CHECK(q.valid_days == 14 && !strcmp(q.valid_until, "2027-01-03"));
    CHECK(!strcmp(q.customer.name, "Erika Mustermann") && q.customer.address_lines == 2);
    release(&r);
}

/* tests/data/tiles/consumables_floor_wall.json: the floor above and wall 0 tiled to 1200 mm.
 * The wall's bottom edge is the floor's edge along wall 0: counted once. Its top (the band's
 * edge at 1200) is no junction. Edge joint: 8 400 + 2 x 1 200 = 10 800 mm. */
static void test_shared_edge(void)
{
    run r;
    if (!compute("consumables_floor_wall.json", &r))
        return;
    CHECK_NEAR(r.c.edge_joint_m, 10.8, 1e-6);
    release(&r);
}

/* $.customer and $.quote survive a save; bad ones are refused with the key named. */
static void test_customer_roundtrip(void)
{
    char path[1024], dir[] = "/tmp/tessera-customer-XXXXXX", out[1100], err[2048] = "";
    snprintf(path, sizeof path, "%s/tests/data/tiles/consumables_wall.json", TESSERA_SOURCE_DIR);
    app_project a, b;
    CHECK_MSG(app_project_read(path, &a, err, sizeof err) == APP_OK, "%s", err);
    CHECK(mkdtemp(dir) != NULL);
    snprintf(out, sizeof out, "%s/saved.json", dir);
    CHECK_MSG(app_project_write(out, &a, err, sizeof err) == APP_OK, "%s", err);
    CHECK_MSG(app_project_read(out, &b, err, sizeof err) == APP_OK, "%s", err);
    CHECK(b.customer.present && !strcmp(b.customer.name, "Erika Mustermann"));
    CHECK(b.customer.address_lines == 2 && !strcmp(b.customer.address[1], "10115 Berlin"));
    CHECK(!strcmp(b.customer.email, "erika@example.org") && !b.customer.phone[0]);
    CHECK(!strcmp(b.customer.quote_number, "Q-2026-0042") && b.customer.valid_days == 14);
    app_project_free(&a);
    app_project_free(&b);
    unlink(out);
    rmdir(dir);
    /* A project without them is written without them. */
    snprintf(path, sizeof path, "%s/tests/data/tiles/setout_floor.json", TESSERA_SOURCE_DIR);
    CHECK(app_project_read(path, &a, err, sizeof err) == APP_OK && !a.customer.present);
    app_project_free(&a);

    const char *bad = "{\"version\": 2, \"plan\": {\"corners\": [[0,0],[1000,0],[1000,1000],"
                      "[0,1000]], \"height\": 2500}, \"room\": {}, \"cameras\": [{\"name\": "
                      "\"c\", \"position\": [500,100,1500], \"target\": [500,900,1000]}], "
                      "\"customer\": {\"address\": [\"1\",\"2\",\"3\",\"4\",\"5\"]}}";
    CHECK(app_project_parse(bad, strlen(bad), NULL, &a, err, sizeof err) == APP_ERR_SCHEMA);
    CHECK_MSG(strstr(err, "$.customer.address") && strstr(err, "at most 4"), "%s", err);
}

static void test_quote(void)
{
    char dir[] = "/tmp/tessera-quote-test-XXXXXX", path[512], err[1024];
    CHECK(mkdtemp(dir) != NULL);
    app_project p;
    memset(&p, 0, sizeof p);
    snprintf(p.name, sizeof p.name, "Bathroom");
    app_quote q;
    /* The default number: the date and a hash of the name, the same on every run. */
    CHECK(app_quote_make(&p, "/no/such/company.json", "2026-02-27", &q, err, sizeof err) ==
          APP_ERR_IO);
    CHECK(strstr(err, "/no/such/company.json") != NULL);
    snprintf(path, sizeof path, "%s/company.json", dir);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) {
        fputs("{\"name\": \"Bad & Fliese\", \"address\": [\"Hauptstr. 1\", \"12345 Ort\"], "
              "\"phone\": \"+49 30 123\", \"vat_id\": \"DE123\"}",
              f);
        fclose(f);
    }
    CHECK(app_quote_make(&p, path, "2026-02-27", &q, err, sizeof err) == APP_OK);
    CHECK(q.has_company && !strcmp(q.company.name, "Bad & Fliese"));
    CHECK(q.company.line_count == 4 && !strcmp(q.company.lines[2], "Phone +49 30 123"));
    CHECK(!strncmp(q.number, "Q-20260227-", 11) && strlen(q.number) == 15);
    CHECK(q.valid_days == 30 && !strcmp(q.valid_until, "2026-03-29"));
    f = fopen(path, "w");
    if (f) {
        fputs("{\"address\": []}", f);
        fclose(f);
    }
    CHECK(app_quote_make(&p, path, NULL, &q, err, sizeof err) == APP_ERR_SCHEMA);
    CHECK(strstr(err, "\"name\"") != NULL);
    CHECK(app_quote_make(&p, NULL, "27.02.2026", &q, err, sizeof err) == APP_ERR_SCHEMA);
    unlink(path);
    rmdir(dir);
}

int main(void)
{
    char dir[] = "/tmp/tessera-consumables-test-XXXXXX", db_path[512], err[2048];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(db_path, sizeof db_path, "%s/catalog.sqlite", dir);
    if (cat_catalog_open(db_path, TESSERA_SOURCE_DIR "/assets/catalog", &db, err, sizeof err) !=
        CAT_DB_OK) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    test_rates();
    test_floor();
    test_wall();
    test_shared_edge();
    test_quote();
    test_customer_roundtrip();
    cat_db_close(db);
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    CHECK(system(cmd) == 0);
    return check_report("test_consumables");
}
