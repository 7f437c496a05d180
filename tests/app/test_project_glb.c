/* tessera export-glb (app/output/project_glb.h): a test room with a pre-wall and a tiled floor, a
 * primitive and two catalog products (a WC turned -90 degrees, a mixer) exported as GLB with a
 * real catalog built from the shipped CSVs into a temporary file and the build's generated
 * models, then loaded back with the catalog's importer (cat_model_load): the node names are
 * there, every material, the bounds are the room's, the products' parts sit where their
 * placement puts them and keep their own materials; an unwritable output is a clear error. */
#include "app/project/project.h"
#include "app/output/project_glb.h"
#include "app/design/room_mesh.h"
#include "catalog/model_gen.h"
#include "catalog/model_write.h"
#include "test_util.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdint.h>

#define DATA TESSERA_PROJECT_TEST_DATA

/* The JSON chunk of a GLB file, parsed (NULL when it is not a GLB). */
static cJSON *glb_json(const char *path)
{
    size_t len = 0;
    char *bytes = tu_read_file(path, &len);
    cJSON *j = NULL;
    if (bytes && len > 20 && !memcmp(bytes, "glTF", 4)) {
        uint32_t chunk;
        memcpy(&chunk, bytes + 12, 4);
        if (20 + (size_t)chunk <= len)
            j = cJSON_ParseWithLength(bytes + 20, chunk);
    }
    free(bytes);
    return j;
}

static const cJSON *node_named(const cJSON *nodes, const char *prefix)
{
    const cJSON *n;
    cJSON_ArrayForEach(n, nodes)
    {
        const cJSON *name = cJSON_GetObjectItemCaseSensitive(n, "name");
        if (cJSON_IsString(name) && !strncmp(name->valuestring, prefix, strlen(prefix)))
            return n;
    }
    return NULL;
}

/* The catalog model of a product, from the build's generated files. */
static int load_source(const char *maker, const char *article, cat_model *m, char *path,
                       size_t size)
{
    char rel[512], err[1024];
    if (!cat_model_file_name(maker, article, rel, sizeof rel) ||
        !cat_model_resolve(rel, NULL, path, size))
        return 0;
    if (cat_model_load(path, m, err, sizeof err) != CAT_OK) {
        CHECK_MSG(0, "%s", err);
        return 0;
    }
    return 1;
}

/* The materials a product brings into the export: its fixed ones, plus one for all its
 * variant slots together (they all take the product's variant). */
static int own_materials(const char *path, const cat_model *m)
{
    cat_material_extras x[32];
    int n = 0, fixed = 0, slots = 0;
    char err[1024];
    CHECK_MSG(cat_model_read_extras(path, x, 32, &n, err, sizeof err) == CAT_OK, "%s", err);
    CHECK(n == m->material_count);
    for (int i = 0; i < n; i++) {
        fixed += !x[i].variant_slot;
        slots += x[i].variant_slot;
    }
    return fixed + (slots > 0);
}

/* p placed by T(pos) * Rz(deg), mm. */
static void place(const float *p, const double pos[3], double deg, double out[3])
{
    double a = deg * 3.14159265358979323846 / 180.0, c = cos(a), s = sin(a);
    out[0] = pos[0] + c * p[0] - s * p[1];
    out[1] = pos[1] + s * p[0] + c * p[1];
    out[2] = pos[2] + p[2];
}

/* Every vertex of the source's parts, placed, equals the exported part's (the writer's node
 * matrix and the importer's baking undo each other up to float rounding). */
static void check_placed(const cat_model *src, const cat_model *out, int first, const double pos[3],
                         double deg, const char *what)
{
    double worst = 0;
    for (int i = 0; i < src->mesh_count && first + i < out->mesh_count; i++) {
        const cat_mesh *a = &src->meshes[i], *b = &out->meshes[first + i];
        CHECK(a->vertex_count == b->vertex_count && a->index_count == b->index_count);
        if (a->vertex_count != b->vertex_count)
            continue;
        for (int v = 0; v < a->vertex_count; v++) {
            double w[3];
            place(a->positions + 3 * v, pos, deg, w);
            for (int k = 0; k < 3; k++)
                worst = fmax(worst, fabs(w[k] - b->positions[3 * v + k]));
        }
    }
    char msg[128];
    snprintf(msg, sizeof msg, "%s: largest vertex error %.4f mm", what, worst);
    CHECK_MSG(worst < 0.01, "%s", msg);
}

int main(void)
{
    char *dir = tu_make_temp_dir();
    CHECK(dir != NULL);
    if (!dir)
        return check_report("project_glb");
    char db[1024], out[1024], err[2048];
    snprintf(db, sizeof db, "%s/catalog.sqlite", dir);
    snprintf(out, sizeof out, "%s/room.glb", dir);
    setenv("TESSERA_CATALOG", db, 1);

    app_project p;
    if (app_project_read(DATA "/export_glb.json", &p, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return check_report("project_glb");
    }
    app_glb_stats st;
    app_result r = app_project_export_glb(&p, out, &st, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    CHECK(st.object_count == 3 && st.skipped_count == 0);

    cat_model wc_src = {0}, mixer_src = {0}, back = {0};
    char wc_path[4096], mixer_path[4096];
    int have_src = load_source("Cerana", "CE412901", &wc_src, wc_path, sizeof wc_path) &&
                   load_source("Aquavera", "31000000", &mixer_src, mixer_path, sizeof mixer_path);
    CHECK_MSG(have_src, "the build's generated models of CE412901 and 31000000");
    cat_result cr = cat_model_load(out, &back, err, sizeof err);
    CHECK_MSG(cr == CAT_OK, "%s", err);
    if (r != APP_OK || cr != CAT_OK || !have_src)
        return check_report("project_glb");

    /* every part came back; the materials: 4 of the project (floor, walls, ceiling, oak), the
     * tiling's grout and tile, and each product's own (its variant slot becomes the variant) */
    CHECK(back.mesh_count == st.part_count);
    CHECK(back.material_count == st.material_count);
    CHECK(back.material_count ==
          4 + 2 + own_materials(wc_path, &wc_src) + own_materials(mixer_path, &mixer_src));

    /* bounds: the room's interior, within 1 mm (tiles and products are inside it) */
    app_room_geometry g;
    CHECK(app_room_geometry_build(&p, &g, err, sizeof err) == APP_OK);
    for (int k = 0; k < 3; k++) {
        CHECK(fabs(back.bounds_min[k] - g.bounds_min[k] * 1000.0) < 1.0);
        CHECK(fabs(back.bounds_max[k] - g.bounds_max[k] * 1000.0) < 1.0);
        CHECK(fabs(st.bounds_min_mm[k] - back.bounds_min[k]) < 0.01);
    }
    app_room_geometry_free(&g);

    /* node names: the room's surfaces under "room", the objects by name, products with their
     * manufacturer and article */
    cJSON *j = glb_json(out);
    CHECK(j != NULL);
    const cJSON *nodes = cJSON_GetObjectItemCaseSensitive(j, "nodes");
    const char *names[] = {"GLB export test room",
                           "room",
                           "floor",
                           "ceiling",
                           "wall:0",
                           "wall:3",
                           "prewall:wc-box",
                           "tiles:floor:grout",
                           "tiles:floor:0",
                           "vanity",
                           "wc (Cerana CE412901 WH)",
                           "mixer (Aquavera 31000000"};
    for (size_t i = 0; i < sizeof names / sizeof *names; i++)
        CHECK_MSG(node_named(nodes, names[i]) != NULL, "%s", names[i]);
    CHECK(cJSON_GetArraySize(nodes) == st.node_count);
    /* the WC's node carries its placement: translation (200, 1050, 400) mm -> (0.2, 0.4, -1.05) m
     */
    const cJSON *wc = node_named(nodes, "wc (");
    const cJSON *mat = wc ? cJSON_GetObjectItemCaseSensitive(wc, "matrix") : NULL;
    CHECK(cJSON_GetArraySize(mat) == 16);
    if (cJSON_GetArraySize(mat) == 16) {
        CHECK(fabs(cJSON_GetArrayItem(mat, 12)->valuedouble - 0.2) < 1e-9);
        CHECK(fabs(cJSON_GetArrayItem(mat, 13)->valuedouble - 0.4) < 1e-9);
        CHECK(fabs(cJSON_GetArrayItem(mat, 14)->valuedouble + 1.05) < 1e-9);
    }
    /* the project's camera: at C(eye) = (2.2, 1.6, -1.8) m, its -Z towards C(target) */
    const cJSON *cams = cJSON_GetObjectItemCaseSensitive(j, "cameras");
    CHECK(cJSON_GetArraySize(cams) == 1 && st.camera_count == 1);
    const cJSON *cam = node_named(nodes, "corner");
    const cJSON *cm = cam ? cJSON_GetObjectItemCaseSensitive(cam, "matrix") : NULL;
    CHECK(cam && cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(cam, "camera")));
    CHECK(cJSON_GetArraySize(cm) == 16);
    if (cJSON_GetArraySize(cm) == 16) {
        double e[3] = {2.2, 1.6, -1.8}, t[3] = {0.6, 0.7, -0.3}, d[3], len = 0, dot = 0;
        for (int k = 0; k < 3; k++) {
            CHECK(fabs(cJSON_GetArrayItem(cm, 12 + k)->valuedouble - e[k]) < 1e-9);
            d[k] = t[k] - e[k];
            len += d[k] * d[k];
        }
        for (int k = 0; k < 3; k++)
            dot -= cJSON_GetArrayItem(cm, 8 + k)->valuedouble * d[k] / sqrt(len);
        CHECK(fabs(dot - 1.0) < 1e-9);
        /* and its +Y points up-ish (glTF +Y = Tessera +Z) */
        CHECK(cJSON_GetArrayItem(cm, 5)->valuedouble > 0.5);
    }
    cJSON_Delete(j);

    /* depth first: the room's meshes, then vanity (1 part), wc, mixer */
    int mixer_first = back.mesh_count - mixer_src.mesh_count;
    int wc_first = mixer_first - wc_src.mesh_count;
    const cat_mesh *vanity = &back.meshes[wc_first - 1];
    float lo[3] = {1e9f, 1e9f, 1e9f}, hi[3] = {-1e9f, -1e9f, -1e9f};
    for (int v = 0; v < vanity->vertex_count; v++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], vanity->positions[3 * v + k]);
            hi[k] = fmaxf(hi[k], vanity->positions[3 * v + k]);
        }
    CHECK(fabsf(lo[0] - 1100) < 0.01f && fabsf(hi[0] - 1900) < 0.01f);
    CHECK(fabsf(lo[1] - 0) < 0.01f && fabsf(hi[1] - 500) < 0.01f);
    CHECK(fabsf(lo[2] - 250) < 0.01f && fabsf(hi[2] - 550) < 0.01f);
    check_placed(&wc_src, &back, wc_first, (const double[3]){200, 1050, 400}, -90, "wc");
    check_placed(&mixer_src, &back, mixer_first, (const double[3]){1500, 20, 550}, 0, "mixer");

    /* each product part keeps its own material: a fixed part (the mixer's aerator) the
     * source's, the variant slot the product's variant; both different */
    cat_material_extras x[16];
    int xn = 0;
    CHECK(cat_model_read_extras(mixer_path, x, 16, &xn, err, sizeof err) == CAT_OK);
    int fixed = 0, slot = 0, slot_material = -1, fixed_material = -1;
    for (int i = 0; i < mixer_src.mesh_count; i++) {
        int sm = mixer_src.meshes[i].material, bm = back.meshes[mixer_first + i].material;
        CHECK(sm >= 0 && sm < xn && bm >= 0 && bm < back.material_count);
        if (sm < 0 || sm >= xn || bm < 0 || bm >= back.material_count)
            continue;
        const cat_material *a = &mixer_src.materials[sm], *b = &back.materials[bm];
        if (x[sm].variant_slot) {
            slot++;
            slot_material = bm;
            CHECK_MSG(!strncmp(b->name, "Aquavera 31000000", 17), "%s", b->name);
        } else {
            fixed++;
            fixed_material = bm;
            CHECK_MSG(!strcmp(a->name, b->name), "%s", b->name);
            for (int k = 0; k < 4; k++)
                CHECK(fabsf(a->base_color[k] - b->base_color[k]) < 1e-6f);
            CHECK(fabsf(a->metallic - b->metallic) < 1e-6f);
            CHECK(fabsf(a->roughness - b->roughness) < 1e-6f);
        }
    }
    CHECK(fixed > 0 && slot > 0 && fixed_material != slot_material);
    /* Tessera's own parameters survive in the extras (the oak's diffuse) */
    int n = 0;
    cat_material_extras *all = calloc((size_t)back.material_count, sizeof *all);
    CHECK(all &&
          cat_model_read_extras(out, all, back.material_count, &n, err, sizeof err) == CAT_OK);
    int oak = 0;
    for (int i = 0; all && i < n; i++)
        if (!strcmp(back.materials[i].name, "oak")) {
            oak = 1;
            CHECK(all[i].present && fabsf(all[i].params.diffuse[0] - 0.55f) < 1e-6f);
            CHECK(fabsf(back.materials[i].roughness - powf(2.0f / 10.0f, 0.25f)) < 1e-5f);
        }
    CHECK(oak);
    free(all);

    /* an unwritable output: a clear error naming the file, nothing written */
    r = app_project_export_glb(&p, "/no/such/folder/x.glb", NULL, err, sizeof err);
    CHECK(r == APP_ERR_IO);
    CHECK_MSG(tu_contains(err, "/no/such/folder/x.glb") && tu_contains(err, "cannot write"), "%s",
              err);

    cat_model_free(&back);
    cat_model_free(&wc_src);
    cat_model_free(&mixer_src);
    app_project_free(&p);
    free(dir);
    return check_report("project_glb");
}
