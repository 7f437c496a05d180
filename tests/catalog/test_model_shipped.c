/* Every shipped product has a generated GLB model (built by make_models into the build's
 * assets/models, see catalog/CMakeLists.txt) that the real loader reads: valid glTF, normals on
 * every vertex, no zero-area triangles, its bounding box equal to the catalog row's width x depth x
 * height within 1 mm with the origin at the bottom centre of the back face, under 200 KB, Tessera
 * extras on every material, and (for one product of each category) a round trip through the writer
 * and the loader keeps it. The catalog is built from the shipped CSV files into a temporary file,
 * the way the application does. */
#include "test_util.h" /* first: it sets _XOPEN_SOURCE */
#include "catalog/catalog.h"
#include "catalog/mesh_lod.h"
#include "catalog/model_gen.h"
#include "catalog/model_write.h"

#define MAX_GLB_BYTES (200 * 1024)

static int check_product(const cat_product *p, int round_trip)
{
    int before = check_failures;
    char name[CAT_PATH_BYTES + 1], path[4096], err[2048];
    CHECK(p->model[0] != 0);
    CHECK(cat_model_file_name(p->manufacturer, p->article, name, sizeof name));
    CHECK(!strcmp(name, p->model)); /* make_catalog_csv.c and gen_path.c agree */
    CHECK(cat_model_resolve(p->model, TESSERA_ASSETS_DIR, path, sizeof path));
    struct stat st;
    CHECK(stat(path, &st) == 0 && st.st_size > 0 && st.st_size < MAX_GLB_BYTES);
    cat_model m;
    cat_result r = cat_model_load(path, &m, err, sizeof err);
    CHECK(r == CAT_OK);
    if (r != CAT_OK) {
        fprintf(stderr, "%s %s: %s\n", p->manufacturer, p->article, err);
        return 1;
    }
    CHECK(!model_broken(&m)); /* normals present and unit, indices in range, inside bounds */
    CHECK(m.mesh_count >= 1 && m.material_count == m.mesh_count);
    /* The generators drop zero-area triangles (gen_build.c): none reach the renderer. */
    cat_mesh_report rep;
    CHECK(cat_model_validate(&m, path, 0, &rep, err, sizeof err) == CAT_OK);
    CHECK(rep.degenerate_triangles == 0);
    if (rep.degenerate_triangles)
        fprintf(stderr, "%s %s: %ld degenerate triangles\n", p->manufacturer, p->article,
                rep.degenerate_triangles);
    double size[3] = {p->width_mm, p->depth_mm, p->height_mm};
    CHECK_NEAR(m.bounds_min[0], -size[0] / 2, 1.0);
    CHECK_NEAR(m.bounds_max[0], size[0] / 2, 1.0);
    for (int k = 1; k < 3; k++) {
        CHECK_NEAR(m.bounds_min[k], 0, 1.0);
        CHECK_NEAR(m.bounds_max[k], size[k], 1.0);
    }
    cat_material_extras ex[64];
    int n = 0, slots = 0;
    CHECK(cat_model_read_extras(path, ex, 64, &n, err, sizeof err) == CAT_OK);
    CHECK(n == m.material_count);
    for (int i = 0; i < n; i++) {
        CHECK(ex[i].present);
        slots += ex[i].variant_slot;
    }
    CHECK(slots >= 1);
    /* The parts taking the variant carry the parameters of one of the product's variants (the
     * first in the shipped CSV: its main finish). */
    for (int i = 0; i < n && p->variant_count; i++) {
        if (!ex[i].variant_slot)
            continue;
        int match = 0;
        for (int v = 0; v < p->variant_count; v++) {
            const cat_render_material *a = &ex[i].params, *b = &p->variants[v].material;
            match |= fabsf(a->reflectivity - b->reflectivity) < 1e-6f &&
                     fabsf(a->diffuse[1] - b->diffuse[1]) < 1e-6f &&
                     fabsf(a->glossiness - b->glossiness) < 1e-6f && a->blend == b->blend;
        }
        CHECK(match);
    }
    /* Round trip: the loaded model written again and loaded again is the same. Done for the
     * first product of each category only: every write ends in an fsync, which is slow. */
    if (!round_trip) {
        cat_model_free(&m);
        return 0;
    }
    const char *again = tmp_path("again.glb");
    CHECK(cat_model_write_glb(again, &m, ex, err, sizeof err) == CAT_OK);
    cat_model b;
    if (cat_model_load(again, &b, err, sizeof err) == CAT_OK) {
        CHECK(b.mesh_count == m.mesh_count && b.material_count == m.material_count);
        for (int i = 0; i < b.mesh_count && b.mesh_count == m.mesh_count; i++)
            CHECK(b.meshes[i].vertex_count == m.meshes[i].vertex_count &&
                  b.meshes[i].index_count == m.meshes[i].index_count);
        for (int k = 0; k < 3; k++) {
            CHECK_NEAR(b.bounds_min[k], m.bounds_min[k], 1e-3);
            CHECK_NEAR(b.bounds_max[k], m.bounds_max[k], 1e-3);
        }
        cat_model_free(&b);
    } else {
        CHECK(!"round trip load");
        fprintf(stderr, "%s\n", err);
    }
    cat_model_free(&m);
    if (check_failures != before)
        fprintf(stderr, "  ^ %s %s (%s, %s)\n", p->manufacturer, p->article,
                cat_category_name(p->category), p->name);
    return 0;
}

int main(void)
{
    tmp_make();
    char err[4096];
    cat_db *db = NULL;
    if (cat_catalog_open(tmp_path("catalog.sqlite"), TESSERA_ASSETS_DIR "/catalog", &db, err,
                         sizeof err) != CAT_DB_OK) {
        fprintf(stderr, "%s\n", err);
        tmp_remove();
        return 1;
    }
    static cat_search_hit hits[10000];
    int count = 0, products = 0;
    CHECK(cat_search(db, "", NULL, 10000, hits, &count, err, sizeof err) == CAT_DB_OK);
    for (int i = 0; i < count; i++) {
        if (hits[i].category == CAT_CATEGORY_TILES)
            continue;
        cat_product p;
        if (cat_product_get(db, hits[i].product_id, &p, err, sizeof err) != CAT_DB_OK) {
            CHECK(!"product_get");
            continue;
        }
        static int seen[CAT_CATEGORY_COUNT];
        check_product(&p, !seen[p.category]++);
        products++;
        cat_product_free(&p);
    }
    /* the shipped catalog's promise: 300 products or more, each with a model */
    CHECK(products >= 300);
    cat_db_close(db);
    tmp_remove();
    printf("test_model_shipped: %d products checked, %d failure(s)\n", products, check_failures);
    return check_report("test_model_shipped");
}
