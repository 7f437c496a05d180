/* Catalog products and tilings at scene build, without GL (scene_products.c, room_tiles.c):
 * with a real catalog built from the shipped CSVs into a temporary file, a placed product
 * without a model becomes a box of its catalog size standing on its origin
 * (app/design/placement.h's frame) in its variant's material; a bath becomes a box that covers the
 * surfaces behind and under it; an unknown product is left undrawn; the tilings become tile and
 * grout meshes whose areas add up to the tiled region. */
#include "app/project/project.h"
#include "app/design/room_mesh.h"
#include "scene_build_internal.h"
#include "test_util.h"

#include <math.h>

#define DATA TESSERA_PROJECT_TEST_DATA

int main(void)
{
    char *dir = tu_make_temp_dir();
    CHECK(dir != NULL);
    if (!dir)
        return check_report("scene_products");
    char db[1024];
    snprintf(db, sizeof db, "%s/catalog.sqlite", dir);
    setenv("TESSERA_CATALOG", db, 1);

    app_project p;
    char err[1024];
    if (app_project_read(DATA "/v2_l_room.json", &p, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return check_report("scene_products");
    }
    /* add a bath (Nordkeram Fjord 1700 x 750 x 460) against wall 0 and an unknown product */
    app_object *objects = realloc(p.objects, (size_t)(p.object_count + 2) * sizeof *objects);
    CHECK(objects != NULL);
    if (!objects)
        return check_report("scene_products");
    p.objects = objects;
    app_object *bath = &p.objects[p.object_count++];
    *bath = p.objects[1];
    snprintf(bath->name, sizeof bath->name, "bath-product");
    snprintf(bath->product.manufacturer, sizeof bath->product.manufacturer, "Nordkeram");
    snprintf(bath->product.article, sizeof bath->product.article, "NK-51258.00");
    bath->product.variant[0] = '\0';
    bath->position_mm[0] = 2150;
    bath->position_mm[1] = 0;
    bath->position_mm[2] = 0;
    bath->rotation_deg[2] = 0;
    app_object *ghost = &p.objects[p.object_count++];
    *ghost = p.objects[1];
    snprintf(ghost->name, sizeof ghost->name, "ghost");
    snprintf(ghost->product.article, sizeof ghost->product.article, "NO-SUCH-ARTICLE");

    app_scene_products q;
    app_result r = app_scene_resolve_products(&p, &q, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r == APP_OK) {
        CHECK(q.owns == 1);
        const app_object *wc = &q.q.objects[1];
        /* Cerana CE412901: 360 x 530 x 340, no model yet: a box; turned -90 degrees about Z,
         * its centre is the origin + (depth / 2 along +x, height / 2 up) */
        CHECK(wc->shape == APP_SHAPE_BOX || wc->shape == APP_SHAPE_MODEL);
        if (wc->shape == APP_SHAPE_BOX) {
            CHECK(wc->size_mm[0] == 360 && wc->size_mm[1] == 530 && wc->size_mm[2] == 340);
            CHECK(fabs(wc->position_mm[0] - (465 + 265)) < 1e-6);
            CHECK(fabs(wc->position_mm[1] - 1600) < 1e-6);
            CHECK(fabs(wc->position_mm[2] - (400 + 170)) < 1e-6);
        }
        const app_material *m = &q.q.materials[wc->material];
        CHECK(fabsf(m->diffuse[0] - 0.92f) < 1e-6f && fabsf(m->diffuse[2] - 0.9f) < 1e-6f);
        CHECK(p.objects[1].shape == APP_SHAPE_BOX &&
              p.objects[1].size_mm[0] == 0); /* p as it was */
        CHECK(!APP_OBJECT_UNRESOLVED(&q.q.objects[2]));
        CHECK(APP_OBJECT_UNRESOLVED(&q.q.objects[3]));
        CHECK(q.cover_count == 1);
        if (q.cover_count == 1) {
            const app_fixture_box *b = &q.covers[0];
            CHECK(!strcmp(b->name, "bath-product"));
            CHECK(fabs(b->min_mm[0] - 1300) < 1e-6 && fabs(b->max_mm[0] - 3000) < 1e-6);
            CHECK(fabs(b->min_mm[1]) < 1e-6 && fabs(b->max_mm[1] - 750) < 1e-6);
            CHECK(fabs(b->max_mm[2] - 460) < 1e-6);
        }

        /* the tilings as meshes; the areas below are the region's own, so without the edge
         * joint that a project file's tiling leaves along it (tested in tile_setout) */
        for (int i = 0; i < q.q.tiling_count; i++)
            q.q.tilings[i].edge_joint_mm = 0;
        app_room_geometry g;
        CHECK(app_room_geometry_build(&q.q, &g, err, sizeof err) == APP_OK);
        int before = g.mesh_count;
        app_room_add_tiles(&q.q, q.covers, q.cover_count, &q.catalog, &g);
        CHECK(g.mesh_count > before);
        const app_room_mesh *tiles = app_room_geometry_find(&g, "tiles:floor:0");
        const app_room_mesh *grout = app_room_geometry_find(&g, "tiles:floor:grout");
        CHECK(tiles && grout);
        if (tiles && grout) {
            /* the floor region: the L (7.56 m2) minus the pre-wall (0.24) and the bath (1.275) */
            double region = 7.56 - 0.24 - 1.7 * 0.75;
            double t = app_room_mesh_area(tiles), gr = app_room_mesh_area(grout);
            char msg[160];
            snprintf(msg, sizeof msg, "tiles %.4f m2, grout backing %.4f m2, region %.4f m2", t, gr,
                     region);
            CHECK_MSG(t < region && t > 0.97 * region, "%s", msg); /* 3 mm joints on 300 x 600 */
            CHECK_MSG(fabs(gr - region) < 2e-3 * region, "%s",
                      msg); /* the backing fills the region */
            CHECK(tiles->inline_material.texture[0] != '\0');
            CHECK(tiles->material == -1 && grout->inline_material.diffuse[0] == 0.3f);
            for (int i = 0; i < tiles->vertex_count; i++)
                CHECK(fabsf(tiles->positions[3 * i + 2] - 0.0025f) < 1e-6f);
        }
        CHECK(app_room_geometry_find(&g, "tiles:wall-0:0") != NULL);
        CHECK(app_room_geometry_find(&g, "tiles:wc-front:0") != NULL);
        app_room_geometry_free(&g);
        app_scene_resolved_free(&q);
    }
    app_project_free(&p);
    tu_remove_tree(dir);
    free(dir);
    return check_report("scene_products");
}
