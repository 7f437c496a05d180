/* Export -> import -> export: the shipped catalog exported, imported into an empty catalog and
 * exported again gives the same bytes and the same product records; importing the export a
 * second time updates every product and duplicates none. */
#include "test_db_util.h"

static void same_material(const cat_render_material *a, const cat_render_material *b, int *bad)
{
    for (int i = 0; i < 3; i++)
        *bad += a->ambient[i] != b->ambient[i] || a->diffuse[i] != b->diffuse[i] ||
                a->specular[i] != b->specular[i] || a->emissive[i] != b->emissive[i];
    *bad += a->shininess != b->shininess || a->reflectivity != b->reflectivity ||
            a->glossiness != b->glossiness || a->blend != b->blend ||
            a->transparency != b->transparency || a->ior != b->ior;
}

/* Every field but the row id and the origin. */
static int same_product(const cat_product *a, const cat_product *b)
{
    int bad = strcmp(a->manufacturer, b->manufacturer) || strcmp(a->article, b->article) ||
              strcmp(a->gtin, b->gtin) || a->category != b->category ||
              strcmp(a->series, b->series) || strcmp(a->name, b->name) ||
              strcmp(a->short_text, b->short_text) || strcmp(a->long_text, b->long_text) ||
              a->width_mm != b->width_mm || a->depth_mm != b->depth_mm ||
              a->height_mm != b->height_mm || a->price_cents != b->price_cents ||
              a->vat_percent != b->vat_percent || strcmp(a->currency, b->currency) ||
              a->unit != b->unit || strcmp(a->discount_group, b->discount_group) ||
              strcmp(a->model, b->model) || a->variant_count != b->variant_count ||
              a->has_tile != b->has_tile;
    for (int i = 0; !bad && i < a->variant_count; i++) {
        const cat_variant *x = &a->variants[i], *y = &b->variants[i];
        bad += strcmp(x->code, y->code) || strcmp(x->name, y->name) ||
               x->surcharge_cents != y->surcharge_cents;
        same_material(&x->material, &y->material, &bad);
    }
    if (!bad && a->has_tile) {
        const cat_tile *x = &a->tile, *y = &b->tile;
        bad += x->type != y->type || x->nominal_w_mm != y->nominal_w_mm ||
               x->nominal_h_mm != y->nominal_h_mm || x->work_w_mm != y->work_w_mm ||
               x->work_h_mm != y->work_h_mm || x->grout_mm != y->grout_mm ||
               x->thickness_mm != y->thickness_mm || strcmp(x->calibre, y->calibre) ||
               x->surface != y->surface || x->m2_per_box != y->m2_per_box ||
               x->pieces_per_box != y->pieces_per_box || strcmp(x->texture, y->texture);
    }
    return !bad;
}

int main(void)
{
    tmp_make();
    char err[2048];
    cat_db *shipped = open_catalog("shipped.sqlite", 1);
    const char *a = tmp_path("a.csv");
    long rows_a = 0;
    CHECK(cat_export_csv_file(shipped, a, &rows_a, err, sizeof err) == CAT_DB_OK);
    cat_db_stats s;
    cat_db_get_stats(shipped, &s, NULL, 0);
    CHECK(rows_a == s.variants + 0); /* every shipped product has at least one variant */

    /* The stream form writes the same bytes. */
    FILE *f = fopen(tmp_path("a-stream.csv"), "wb");
    long rows_stream = 0;
    CHECK(f && cat_export_csv(shipped, f, &rows_stream, err, sizeof err) == CAT_DB_OK);
    fclose(f);
    CHECK(rows_stream == rows_a && same_bytes(a, tmp_path("a-stream.csv")));

    cat_db *copy = open_catalog("copy.sqlite", 0);
    cat_import_report rep;
    CHECK(cat_import_csv(copy, a, NULL, &rep, err, sizeof err) == CAT_DB_OK);
    print_problems(&rep);
    CHECK(rep.rows == rows_a && rep.products_added == s.products && rep.products_updated == 0);
    cat_import_report_free(&rep);
    long rows_b = 0;
    CHECK(cat_export_csv_file(copy, tmp_path("b.csv"), &rows_b, err, sizeof err) == CAT_DB_OK);
    CHECK(rows_b == rows_a);
    CHECK(same_bytes(a, tmp_path("b.csv")));

    /* Record for record. */
    static cat_search_hit all[10000];
    int n = 0;
    CHECK(cat_search(shipped, "", NULL, 10000, all, &n, err, sizeof err) == CAT_DB_OK);
    CHECK(n == s.products);
    for (int i = 0; i < n; i++) {
        cat_product x, y;
        CHECK(cat_product_get(shipped, all[i].product_id, &x, err, sizeof err) == CAT_DB_OK);
        CHECK(cat_product_find(copy, x.manufacturer, x.article, &y, err, sizeof err) == CAT_DB_OK);
        CHECK_MSG(same_product(&x, &y), "%s %s differs after the round trip", x.manufacturer,
                  x.article);
        CHECK(x.shipped == 1 && y.shipped == 0);
        cat_product_free(&x);
        cat_product_free(&y);
    }

    /* Importing the same file again: all updated, nothing added, the export unchanged. */
    CHECK(cat_import_csv(copy, a, NULL, &rep, err, sizeof err) == CAT_DB_OK);
    CHECK(rep.products_added == 0 && rep.products_updated == s.products);
    cat_import_report_free(&rep);
    cat_db_stats t;
    cat_db_get_stats(copy, &t, NULL, 0);
    CHECK(t.products == s.products && t.variants == s.variants && t.tiles == s.tiles &&
          t.manufacturers == s.manufacturers && t.series == s.series);
    CHECK(cat_export_csv_file(copy, tmp_path("c.csv"), NULL, err, sizeof err) == CAT_DB_OK);
    CHECK(same_bytes(a, tmp_path("c.csv")));
    CHECK(fts_consistent(tmp_path("copy.sqlite")));

    /* An export that cannot be written fails cleanly and leaves nothing behind. */
    cat_db_result r =
        cat_export_csv_file(copy, tmp_path("no-such-dir/x.csv"), NULL, err, sizeof err);
    CHECK_MSG(r == CAT_DB_ERR_IO && strstr(err, "x.csv"), "%s", err);
    CHECK(cat_export_csv(copy, NULL, NULL, err, sizeof err) == CAT_DB_ERR_INVALID);

    cat_db_close(copy);
    cat_db_close(shipped);
    tmp_remove();
    return check_report("test_db_roundtrip");
}
