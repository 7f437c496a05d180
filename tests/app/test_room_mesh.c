/* The room's meshes from its plan (app/design/room_mesh.h): areas against hand-computed values (an
 * L-shaped floor, a wall with a window = wall - window, reveals = perimeter x thickness, a
 * sloped ceiling, a pre-wall box, a niche), every triangle wound to face its normal, a
 * version 1 room as its six rectangles, ear clipping of awkward polygons. */
#include "app/project/project.h"
#include "app/design/room_mesh.h"
#include "test_util.h"

#include <math.h>

#define NEAR(a, b, tol) (fabs((a) - (b)) <= (tol))

static int parse(const char *json, app_project *p)
{
    char err[1024];
    app_result r = app_project_parse(json, strlen(json), NULL, p, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    return r == APP_OK;
}

static double area_of(const app_room_geometry *g, const char *surface)
{
    const app_room_mesh *m = app_room_geometry_find(g, surface);
    return m ? app_room_mesh_area(m) : -1;
}

/* Every triangle's winding agrees with its vertices' normals (the GPU culls back faces). */
static void check_winding(const app_room_geometry *g)
{
    int bad = 0, total = 0;
    for (int i = 0; i < g->mesh_count; i++) {
        const app_room_mesh *m = &g->meshes[i];
        CHECK(m->index_count % 3 == 0);
        for (int t = 0; t + 2 < m->index_count; t += 3) {
            const uint32_t *ix = &m->indices[t];
            const float *a = &m->positions[3 * ix[0]], *b = &m->positions[3 * ix[1]],
                        *c = &m->positions[3 * ix[2]], *n = &m->normals[3 * ix[0]];
            double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                   e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
            double x = e1[1] * e2[2] - e1[2] * e2[1], y = e1[2] * e2[0] - e1[0] * e2[2],
                   z = e1[0] * e2[1] - e1[1] * e2[0];
            total++;
            if (x * n[0] + y * n[1] + z * n[2] <= 0) {
                bad++;
                if (bad < 5)
                    fprintf(stderr, "  %s: triangle %d faces away from its normal\n", m->surface,
                            t / 3);
            }
        }
    }
    CHECK(total > 0 && bad == 0);
}

static void test_l_shape(void)
{
    app_project p;
    if (!parse("{\"version\": 2, \"room\": {}, \"plan\": {\"corners\": [[0, 0], [3000, 0], "
               "[3000, 1800], [1800, 1800], [1800, 3000], [0, 3000]], \"height\": 2500},"
               "\"cameras\": [{\"position\": [1, 1, 1], \"target\": [0, 0, 0]}]}",
               &p))
        return;
    app_room_geometry g;
    char err[256];
    CHECK(app_room_geometry_build(&p, &g, err, sizeof err) == APP_OK);
    /* 3000 x 1800 + 1800 x 1200 = 7.56 m^2 */
    CHECK_MSG(NEAR(area_of(&g, "floor"), 7.56, 1e-5), "floor");
    CHECK(NEAR(area_of(&g, "ceiling"), 7.56, 1e-5));
    const app_room_mesh *floor = app_room_geometry_find(&g, "floor");
    CHECK(floor && floor->index_count == 3 * 4); /* 6 corners: 4 triangles */
    const double lengths[6] = {3.0, 1.8, 1.2, 1.2, 1.8, 3.0};
    for (int i = 0; i < 6; i++) {
        char name[32];
        snprintf(name, sizeof name, "wall:%d", i);
        CHECK_MSG(NEAR(area_of(&g, name), lengths[i] * 2.5, 1e-5), "%s", name);
    }
    CHECK(g.light_count == 0);
    check_winding(&g);
    app_room_geometry_free(&g);
    app_project_free(&p);
}

static void test_window_and_door(void)
{
    app_project p;
    if (!parse("{\"version\": 2, \"room\": {}, \"plan\": {\"corners\": [[0, 0], [3000, 0], "
               "[3000, 2000], [0, 2000]], \"height\": 2500, \"wall_thickness\": 120,"
               "\"openings\": [{\"type\": \"window\", \"wall\": 0, \"offset\": 1000, \"width\": "
               "800, \"sill\": 900, \"height\": 1200},"
               "{\"type\": \"door\", \"wall\": 2, \"offset\": 200, \"width\": 800, \"height\": "
               "2000}]},"
               "\"cameras\": [{\"position\": [1, 1, 1], \"target\": [0, 0, 0]}]}",
               &p))
        return;
    app_room_geometry g;
    char err[256];
    CHECK(app_room_geometry_build(&p, &g, err, sizeof err) == APP_OK);
    /* wall 0: 3 x 2.5 - 0.8 x 1.2 */
    CHECK(NEAR(area_of(&g, "wall:0"), 7.5 - 0.96, 1e-5));
    /* its reveals: the opening's perimeter x the thickness, 2 (0.8 + 1.2) x 0.12 */
    CHECK(NEAR(area_of(&g, "wall:0:reveals"), 0.48, 1e-5));
    /* wall 2 with the door: 3 x 2.5 - 0.8 x 2.0; reveals to the leaf at half the thickness:
     * jambs and head 0.06 x (2 + 2 + 0.8), the threshold in the floor 0.8 x 0.06 */
    CHECK(NEAR(area_of(&g, "wall:2"), 7.5 - 1.6, 1e-5));
    CHECK(NEAR(area_of(&g, "wall:2:reveals"), 0.06 * 4.8, 1e-5));
    CHECK(NEAR(area_of(&g, "floor"), 6.0 + 0.048, 1e-5));
    CHECK(NEAR(area_of(&g, "wall:1"), 5.0, 1e-5));
    /* the window's sky panel and its daylight; the door's leaf */
    CHECK(app_room_geometry_find(&g, "window:0") != NULL);
    CHECK(app_room_geometry_find(&g, "door:1") != NULL);
    CHECK(g.light_count == 1);
    if (g.light_count == 1) {
        const app_light *l = &g.lights[0];
        /* the opening as a rectangle light in the outside face, facing into the room (the
         * default overcast sky has no sun) */
        CHECK(l->type == APP_LIGHT_RECT);
        CHECK(NEAR(l->direction[1], 1, 1e-9) && NEAR(l->direction[2], 0, 1e-9));
        CHECK(NEAR(l->position_mm[0], 1400, 1e-9) && NEAR(l->position_mm[2], 1500, 1e-9));
        CHECK(NEAR(l->width_mm, 800, 1e-9) && NEAR(l->height_mm, 1200, 1e-9));
        CHECK(l->color[0] > 0.1f && l->color[0] < 10.0f);
    }
    check_winding(&g);
    app_room_geometry_free(&g);
    app_project_free(&p);
}

static void test_slope_prewall_niche(void)
{
    app_project p;
    if (!parse("{\"version\": 2, \"room\": {}, \"plan\": {\"corners\": [[0, 0], [3000, 0], "
               "[3000, 2000], [0, 2000]], \"height\": 2500, \"wall_thickness\": 150,"
               "\"slope\": {\"wall\": 0, \"knee\": 1500, \"run\": 1000},"
               "\"prewalls\": [{\"name\": \"wc\", \"wall\": 2, \"offset\": 1000, \"width\": 1200, "
               "\"depth\": 200, \"height\": 1100}],"
               "\"niches\": [{\"wall\": 3, \"offset\": 500, \"width\": 600, \"sill\": 1000, "
               "\"height\": 400, \"depth\": 100}]},"
               "\"cameras\": [{\"position\": [1, 1, 1], \"target\": [0, 0, 0]}]}",
               &p))
        return;
    app_room_geometry g;
    char err[256];
    CHECK(app_room_geometry_build(&p, &g, err, sizeof err) == APP_OK);
    /* ceiling: flat 3 x 1, sloped 3 x sqrt(1^2 + 1^2) */
    CHECK(NEAR(area_of(&g, "ceiling"), 3.0 + 3.0 * sqrt(2.0), 1e-5));
    CHECK(NEAR(area_of(&g, "wall:0"), 3.0 * 1.5, 1e-5));       /* at the knee */
    CHECK(NEAR(area_of(&g, "wall:1"), 2.0 * 2.5 - 0.5, 1e-5)); /* minus the slope's triangle */
    CHECK(NEAR(area_of(&g, "wall:3"), 2.0 * 2.5 - 0.5 - 0.24, 1e-5)); /* and the niche */
    /* niche recess: back 0.6 x 0.4, sides 2 (0.6 + 0.4) x 0.1 */
    CHECK(NEAR(area_of(&g, "wall:3:reveals"), 0.24 + 0.2, 1e-5));
    /* pre-wall: front 1.2 x 1.1, top 1.2 x 0.2, sides 2 x 0.2 x 1.1 */
    CHECK(NEAR(area_of(&g, "prewall:wc"), 1.32 + 0.24 + 0.44, 1e-5));
    const app_room_mesh *ceiling = app_room_geometry_find(&g, "ceiling");
    int down = 1;
    float z_min = 1e9f;
    for (int i = 0; ceiling && i < ceiling->vertex_count; i++) {
        down &= ceiling->normals[3 * i + 2] < 0;
        z_min = fminf(z_min, ceiling->positions[3 * i + 2]);
    }
    CHECK(down && NEAR(z_min, 1.5, 1e-6));
    check_winding(&g);
    app_room_geometry_free(&g);
    app_project_free(&p);
}

/* A project built by version 1 code: the room box, six rectangles of 4 vertices. */
static void test_version1_box(void)
{
    app_project p;
    memset(&p, 0, sizeof p);
    app_material m;
    memset(&m, 0, sizeof m);
    m.texture_size_mm[0] = 300;
    m.texture_size_mm[1] = 600;
    p.materials = &m;
    p.material_count = 1;
    p.room.width_mm = 2400;
    p.room.depth_mm = 3000;
    p.room.height_mm = 2500;
    app_room_geometry g;
    char err[256];
    CHECK(app_room_geometry_build(&p, &g, err, sizeof err) == APP_OK);
    CHECK(g.mesh_count == 6);
    for (int i = 0; i < g.mesh_count; i++)
        CHECK(g.meshes[i].vertex_count == 4 && g.meshes[i].index_count == 6);
    const app_room_mesh *w0 = app_room_geometry_find(&g, "wall:0");
    /* version 1's wall y = 0: u from x = width (u = 0) to x = 0 (u = 2400 / 300 = 8) */
    CHECK(w0 && NEAR(w0->positions[0], 2.4, 1e-6) && NEAR(w0->uvs[0], 0, 1e-6));
    CHECK(w0 && NEAR(w0->uvs[2], 8.0, 1e-5) && NEAR(w0->normals[1], 1.0, 1e-6));
    CHECK(g.bounds_max[0] == 2.4 && g.bounds_max[1] == 3.0 && g.bounds_max[2] == 2.5);
    check_winding(&g);
    app_room_geometry_free(&g);
}

static void test_ear_clipping(void)
{
    /* a comb: reflex corners everywhere; area 10 x 1 + 4 teeth of 1 x 3 = 22 */
    const double comb[] = {0, 0, 10, 0, 10, 4, 9, 4, 9, 1, 7, 1, 7, 4, 6, 4,
                           6, 1, 4,  1, 4,  4, 3, 4, 3, 1, 1, 1, 1, 4, 0, 4};
    int n = (int)(sizeof comb / sizeof comb[0] / 2);
    uint32_t tri[3 * 32];
    int t = app_triangulate_polygon(comb, n, tri);
    CHECK(t == n - 2);
    double area = 0;
    int ccw = 1;
    for (int k = 0; k < t; k++) {
        const double *a = &comb[2 * tri[3 * k]], *b = &comb[2 * tri[3 * k + 1]],
                     *c = &comb[2 * tri[3 * k + 2]];
        double cr = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        ccw &= cr > 0;
        area += 0.5 * cr;
    }
    CHECK(ccw);
    CHECK(NEAR(area, 22, 1e-9));
    /* the comb's area by the shoelace formula */
    double shoelace = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        shoelace += comb[2 * i] * comb[2 * j + 1] - comb[2 * j] * comb[2 * i + 1];
    }
    CHECK(NEAR(area, 0.5 * shoelace, 1e-9));

    /* an L with extra corners on straight walls (a wall split in two) and a U */
    const double l_split[] = {0,    0,    1500, 0,    3000, 0,    3000, 1800, 2400, 1800,
                              1800, 1800, 1800, 2400, 1800, 3000, 0,    3000, 0,    1500};
    const double u_shape[] = {0,    0,    3000, 0,    3000, 3000, 2000, 3000,
                              2000, 1000, 1000, 1000, 1000, 3000, 0,    3000};
    const struct {
        const double *xy;
        int n;
        double area;
    } shapes[] = {{l_split, 10, 3000.0 * 1800 + 1800 * 1200}, {u_shape, 8, 9e6 - 2e6}};
    for (int k = 0; k < 2; k++) {
        t = app_triangulate_polygon(shapes[k].xy, shapes[k].n, tri);
        double sum = 0;
        int positive = 1;
        for (int i = 0; i < (t < 0 ? shapes[k].n - 2 : t); i++) {
            const double *a = &shapes[k].xy[2 * tri[3 * i]], *b = &shapes[k].xy[2 * tri[3 * i + 1]],
                         *c = &shapes[k].xy[2 * tri[3 * i + 2]];
            double cr = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
            positive &= cr >= 0;
            sum += 0.5 * cr;
        }
        CHECK(t == shapes[k].n - 2);
        CHECK(positive);
        CHECK_MSG(NEAR(sum, shapes[k].area, 1e-6), "%s", k == 0 ? "split L" : "U");
    }
}

int main(void)
{
    test_l_shape();
    test_window_and_door();
    test_slope_prewall_niche();
    test_version1_box();
    test_ear_clipping();
    return check_report("room_mesh");
}
