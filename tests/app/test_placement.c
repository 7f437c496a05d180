/* Placement: collisions, clearances (DOMAIN.md "Clearances") and snapping on known layouts,
 * with the shipped catalog's product sizes. */
#include "test_util.h"

#include "app/project/commands.h"
#include "app/design/placement.h"
#include "placement_test_catalog.h"

#include <math.h>

static const char *csv = TESSERA_SOURCE_DIR "/assets/catalog/fixtures.csv";

/* A 3000 x 2500 room, 2500 high, one material. */
static void make_room(app_project *p)
{
    memset(p, 0, sizeof *p);
    p->version = p->file_version = 1;
    p->plan.corner_count = 4;
    p->plan.corners = calloc(4, sizeof *p->plan.corners);
    p->plan.corners[1].x = p->plan.corners[2].x = 3000;
    p->plan.corners[2].y = p->plan.corners[3].y = 2500;
    p->plan.height_mm = 2500;
    p->plan.wall_thickness_mm = 120;
    p->room.width_mm = 3000;
    p->room.depth_mm = 2500;
    p->room.height_mm = 2500;
    p->material_count = 1;
    p->materials = calloc(1, sizeof *p->materials);
    snprintf(p->materials[0].name, sizeof p->materials[0].name, "default");
}

static int add_product(app_project *p, const char *name, const char *maker, const char *article,
                       double x, double y, double z, double rot)
{
    p->objects = realloc(p->objects, (size_t)(p->object_count + 1) * sizeof *p->objects);
    app_object *o = &p->objects[p->object_count];
    memset(o, 0, sizeof *o);
    snprintf(o->name, sizeof o->name, "%s", name);
    o->shape = APP_SHAPE_MODEL;
    o->position_mm[0] = x;
    o->position_mm[1] = y;
    o->position_mm[2] = z;
    o->rotation_deg[2] = rot;
    o->scale[0] = o->scale[1] = o->scale[2] = 1;
    o->has_product = 1;
    snprintf(o->product.manufacturer, sizeof o->product.manufacturer, "%s", maker);
    snprintf(o->product.article, sizeof o->product.article, "%s", article);
    return p->object_count++;
}

static app_findings run_checks(const app_project *p, app_barrier_free bf)
{
    app_fixture *fx = NULL;
    int n = 0;
    char err[512] = "";
    app_findings f = {0};
    app_result r = app_placement_fixtures(p, ptc_lookup, (void *)csv, &fx, &n, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    app_check_options opt = {bf};
    r = app_placement_check(p, fx, n, &opt, &f, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    free(fx);
    return f;
}

static void print_findings(const char *title, const app_findings *f)
{
    printf("%s: %d findings\n", title, f->count);
    for (int i = 0; i < f->count; i++)
        printf("  %s %s [%d,%d] at (%.0f, %.0f): %s\n", app_severity_name(f->items[i].severity),
               app_finding_kind_name(f->items[i].kind), f->items[i].objects[0],
               f->items[i].objects[1], f->items[i].position_mm[0], f->items[i].position_mm[1],
               f->items[i].message);
}

/* The finding of kind k between objects a and b (either order; b = -1: a wall), or NULL. */
static const app_finding *find(const app_findings *f, app_finding_kind k, int a, int b)
{
    for (int i = 0; i < f->count; i++) {
        const app_finding *x = &f->items[i];
        if (x->kind == k && ((x->objects[0] == a && x->objects[1] == b) ||
                             (x->objects[0] == b && x->objects[1] == a)))
            return x;
    }
    return NULL;
}

static int count_kind(const app_findings *f, app_finding_kind k)
{
    int n = 0;
    for (int i = 0; i < f->count; i++)
        n += f->items[i].kind == k;
    return n;
}

static void test_clean_basin_with_mirror(void)
{
    app_project p;
    make_room(&p);
    /* Cerana CE410301: washbasin 600 x 550 x 175, rim at 850. Vitrelux VX20051: mirror
     * 800 x 25 x 700 above it. */
    add_product(&p, "basin", "Cerana", "CE410301", 1500, 0, 675, 0);
    add_product(&p, "mirror", "Vitrelux", "VX20051", 1500, 0, 1100, 0);
    /* A 10 mm bath mat in the basin's free area is walked on, not around. */
    int mat = add_product(&p, "mat", "x", "x", 0, 0, 0, 0);
    p.objects[mat].has_product = 0;
    p.objects[mat].shape = APP_SHAPE_BOX;
    p.objects[mat].position_mm[0] = 1500;
    p.objects[mat].position_mm[1] = 800;
    p.objects[mat].position_mm[2] = 5;
    p.objects[mat].size_mm[0] = 800;
    p.objects[mat].size_mm[1] = 500;
    p.objects[mat].size_mm[2] = 10;
    app_findings f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("basin + mirror + mat", &f);
    CHECK(f.count == 0);
    /* A 400 mm stool there blocks it. */
    p.objects[mat].size_mm[2] = 400;
    p.objects[mat].position_mm[2] = 200;
    app_findings_free(&f);
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    CHECK(find(&f, APP_FINDING_FREE_AREA, 0, mat) != NULL);
    app_findings_free(&f);
    /* The mirror lowered into the basin: now they collide (3D). */
    p.objects[1].position_mm[2] = 700;
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("mirror lowered into the basin", &f);
    CHECK(find(&f, APP_FINDING_COLLISION, 0, 1) != NULL);
    CHECK(app_findings_errors(&f) >= 1);
    app_findings_free(&f);
    app_project_free_all(&p);
}

static void test_wc_beside_basin(void)
{
    app_project p;
    make_room(&p);
    int basin = add_product(&p, "basin", "Cerana", "CE410301", 1000, 0, 675, 0); /* x 700..1300 */
    /* Cerana CE412901: wall-hung WC 360 wide; 100 mm from the basin: x 1400..1760. */
    int wc = add_product(&p, "wc", "Cerana", "CE412901", 1580, 0, 60, 0);
    app_findings f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("WC 100 mm beside the basin", &f);
    const app_finding *d = find(&f, APP_FINDING_DISTANCE, basin, wc);
    CHECK(d != NULL);
    /* DOMAIN.md "Clearances": the 200 mm are a rule, so a shorter distance is an error. */
    CHECK(d && d->severity == APP_SEVERITY_ERROR);
    CHECK(app_findings_errors(&f) >= 1);
    CHECK(d && tu_contains(d->message, "100 mm apart"));
    CHECK(d && tu_contains(d->message, "200 mm"));
    CHECK(d && fabs(d->position_mm[0] - 1350) < 1 && d->position_mm[1] < 551);
    CHECK(count_kind(&f, APP_FINDING_COLLISION) == 0);
    app_findings_free(&f);
    /* 250 mm apart: no distance finding any more, and no error at all. */
    p.objects[wc].position_mm[0] = 1730;
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("WC 250 mm beside the basin", &f);
    CHECK(find(&f, APP_FINDING_DISTANCE, basin, wc) == NULL);
    CHECK(app_findings_errors(&f) == 0);
    app_findings_free(&f);
    app_project_free_all(&p);
}

static void test_bath_blocks_basin_area(void)
{
    app_project p;
    make_room(&p);
    /* The basin on wall 0 at x = 1000: its 900 x 550 free area spans x 550..1450, y 550..1100.
     * Nordkeram NK-51258.00, bath 1700 x 750, against wall 3 (x = 0) facing +x: x 0..750,
     * y 150..1850. It reaches 200 mm into the free area; in height it stays below the basin. */
    int basin = add_product(&p, "basin", "Cerana", "CE410301", 1000, 0, 675, 0);
    int bath = add_product(&p, "bath", "Nordkeram", "NK-51258.00", 0, 1000, 0, -90);
    app_findings f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("bath in the basin's free area", &f);
    const app_finding *a = find(&f, APP_FINDING_FREE_AREA, basin, bath);
    CHECK(a != NULL);
    CHECK(a && a->severity == APP_SEVERITY_ERROR);
    CHECK(a && tu_contains(a->message, "900 x 550"));
    CHECK(a && tu_contains(a->message, "200 mm into it"));
    CHECK(find(&f, APP_FINDING_COLLISION, basin, bath) == NULL);
    CHECK(find(&f, APP_FINDING_OUTSIDE_ROOM, bath, -1) == NULL);
    app_findings_free(&f);
    /* The bath's own free area (900 x 750 in front of it) is clear. */
    app_project_free_all(&p);
}

static void test_walls_prewalls_doors(void)
{
    app_project p;
    make_room(&p);
    p.plan.prewall_count = 1;
    p.plan.prewalls = calloc(1, sizeof *p.plan.prewalls);
    app_prewall *pw = &p.plan.prewalls[0];
    snprintf(pw->name, sizeof pw->name, "wc-box");
    pw->wall = 0;
    pw->offset_mm = 2000;
    pw->width_mm = 800;
    pw->depth_mm = 200;
    pw->height_mm = 1100;
    p.plan.opening_count = 1;
    p.plan.openings = calloc(1, sizeof *p.plan.openings);
    app_opening *door = &p.plan.openings[0];
    snprintf(door->name, sizeof door->name, "door");
    door->type = APP_OPENING_DOOR;
    door->wall = 2; /* from (3000,2500) to (0,2500) */
    door->offset_mm = 300;
    door->width_mm = 800;
    door->height_mm = 2000;
    door->swing = APP_SWING_IN_LEFT;
    /* The WC on the pre-wall's front: no finding. */
    int wc = add_product(&p, "wc", "Cerana", "CE412901", 2400, 200, 60, 0);
    app_findings f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("WC on its pre-wall", &f);
    CHECK(f.count == 0);
    app_findings_free(&f);
    /* 100 mm into the pre-wall. */
    p.objects[wc].position_mm[1] = 100;
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    CHECK(find(&f, APP_FINDING_PREWALL, wc, -1) != NULL);
    app_findings_free(&f);
    p.objects[wc].position_mm[1] = 200;
    /* A basin through the right wall. */
    int basin = add_product(&p, "basin", "Cerana", "CE410301", 2900, 1200, 675, 0);
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("basin through a wall", &f);
    const app_finding *o = find(&f, APP_FINDING_OUTSIDE_ROOM, basin, -1);
    CHECK(o != NULL);
    CHECK(o && o->position_mm[0] > 3000);
    app_findings_free(&f);
    /* A tall cabinet in the door's swing (the door is in wall 2, x 2700..1900). */
    p.objects[basin].position_mm[0] = 1500;
    p.objects[basin].position_mm[1] = 0;
    int cab = add_product(&p, "cabinet", "Holmwood", "HW1522", 2300, 2100, 0, 0);
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("cabinet in the door swing", &f);
    CHECK(find(&f, APP_FINDING_OPENING, cab, -1) != NULL);
    CHECK(app_findings_errors(&f) >= 1);
    CHECK(find(&f, APP_FINDING_BARRIER_FREE, -1, -1) == NULL);
    app_findings_free(&f);
    /* Barrier-free: a door opening into the bathroom is a finding (DIN 18040-2); opening
     * outwards it is not. */
    f = run_checks(&p, APP_BARRIER_FREE_ON);
    const app_finding *door_in = find(&f, APP_FINDING_BARRIER_FREE, -1, -1);
    CHECK(door_in && tu_contains(door_in->message, "\"door\" opens into the room"));
    CHECK(door_in && fabs(door_in->position_mm[0] - 2300) < 1e-9 &&
          fabs(door_in->position_mm[1] - 2500) < 1e-9);
    app_findings_free(&f);
    p.plan.openings[0].swing = APP_SWING_OUT_LEFT;
    f = run_checks(&p, APP_BARRIER_FREE_ON);
    CHECK(find(&f, APP_FINDING_BARRIER_FREE, -1, -1) == NULL);
    /* ... and outside the barrier-free checks nothing stands in its swing any more. */
    app_findings_free(&f);
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    CHECK(find(&f, APP_FINDING_OPENING, cab, -1) == NULL);
    app_findings_free(&f);
    /* A window in wall 1 (x = 3000) from y 1000 to 1600, sill 900: a mirror cabinet (Vitrelux
     * VX20068, 800 x 150 x 700) hung across it at 1200 is in front of it (a warning); moved
     * beside it, 20 mm from its edge, it is not. */
    p.plan.opening_count = 2;
    p.plan.openings = realloc(p.plan.openings, 2 * sizeof *p.plan.openings);
    app_opening *win = &p.plan.openings[1];
    memset(win, 0, sizeof *win);
    snprintf(win->name, sizeof win->name, "window");
    win->type = APP_OPENING_WINDOW;
    win->wall = 1;
    win->offset_mm = 1000;
    win->width_mm = 600;
    win->sill_mm = 900;
    win->height_mm = 1000;
    int mc = add_product(&p, "cabinet-mirror", "Vitrelux", "VX20068", 3000, 1500, 1200, 90);
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    const app_finding *w = find(&f, APP_FINDING_OPENING, mc, -1);
    CHECK(w && w->severity == APP_SEVERITY_WARNING && tu_contains(w->message, "window"));
    app_findings_free(&f);
    p.objects[mc].position_mm[1] = 1600 + 20 + 400;
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("mirror cabinet beside the window", &f);
    CHECK(find(&f, APP_FINDING_OPENING, mc, -1) == NULL);
    app_findings_free(&f);
    app_project_free_all(&p);
}

static void test_side_wall_and_barrier_free(void)
{
    app_project p;
    make_room(&p);
    /* A WC 100 mm from the left wall: side distance warning. */
    int wc = add_product(&p, "wc", "Cerana", "CE412901", 280, 0, 60, 0);
    app_findings f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("WC 100 mm from the side wall", &f);
    const app_finding *d = find(&f, APP_FINDING_DISTANCE, wc, -1);
    CHECK(d && tu_contains(d->message, "left side"));
    CHECK(d && d->severity == APP_SEVERITY_ERROR);
    app_findings_free(&f);
    /* Centred on the wall: fine, and barrier-free (1200 x 1200) fits in a 2500 deep room. */
    p.objects[wc].position_mm[0] = 1500;
    f = run_checks(&p, APP_BARRIER_FREE_ON);
    print_findings("WC centred, barrier-free", &f);
    CHECK(f.count == 0);
    app_findings_free(&f);
    /* Wheelchair: a basin 250 mm to the right blocks the 900 mm side and the 300 mm side on
     * the right; the left has 1320 mm. Both sides need one >= 900 and the other >= 300, so a
     * basin at 300 mm right is fine, at 250 mm it is not. */
    int basin = add_product(&p, "basin", "Cerana", "CE410301", 1500 + 180 + 250 + 300, 0, 675, 0);
    f = run_checks(&p, APP_BARRIER_FREE_WHEELCHAIR);
    print_findings("wheelchair WC, basin 250 mm beside it", &f);
    const app_finding *w = find(&f, APP_FINDING_BARRIER_FREE, wc, -1);
    CHECK(w && tu_contains(w->message, "right: under 300"));
    app_findings_free(&f);
    p.objects[basin].position_mm[0] += 60;
    f = run_checks(&p, APP_BARRIER_FREE_WHEELCHAIR);
    CHECK(find(&f, APP_FINDING_BARRIER_FREE, wc, -1) == NULL);
    app_findings_free(&f);
    /* A 1200 deep room cannot hold 1500 x 1500 in front of anything. */
    p.plan.corners[2].y = p.plan.corners[3].y = 1200;
    f = run_checks(&p, APP_BARRIER_FREE_WHEELCHAIR);
    CHECK(count_kind(&f, APP_FINDING_BARRIER_FREE) >= 2);
    app_findings_free(&f);
    app_project_free_all(&p);
}

static void test_primitives_group(void)
{
    app_project p;
    make_room(&p);
    p.object_count = 3;
    p.objects = calloc(3, sizeof *p.objects);
    for (int i = 0; i < 3; i++) {
        app_object *o = &p.objects[i];
        snprintf(o->name, sizeof o->name, "part%d", i);
        o->shape = APP_SHAPE_BOX;
        o->scale[0] = o->scale[1] = o->scale[2] = 1;
        o->size_mm[0] = o->size_mm[1] = o->size_mm[2] = 400;
        o->position_mm[0] = 1000 + 300 * i;
        o->position_mm[1] = 1000;
        o->position_mm[2] = 200;
    }
    /* Parts 0 and 1 overlap but form one fixture; part 2 overlaps part 1 and is separate. */
    snprintf(p.objects[0].group, sizeof p.objects[0].group, "cabinet");
    snprintf(p.objects[1].group, sizeof p.objects[1].group, "cabinet");
    app_fixture *fx = NULL;
    int n = 0;
    char err[256];
    CHECK(app_placement_fixtures(&p, NULL, NULL, &fx, &n, err, sizeof err) == APP_OK);
    CHECK(n == 2);
    CHECK(n == 2 && fabs(fx[0].half[0] - 350) < 1e-9 && fabs(fx[0].centre[0] - 1150) < 1e-9);
    free(fx);
    /* Overlapping primitives are scenery parts: not a collision. */
    app_findings f = run_checks(&p, APP_BARRIER_FREE_OFF);
    CHECK(f.count == 0);
    app_findings_free(&f);
    /* A catalog WC (Cerana CE413501, close-coupled, 365 x 670 x 790) standing in the
     * grouped cabinet collides with it. */
    int wc = add_product(&p, "wc", "Cerana", "CE413501", 1100, 700, 0, 0);
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("WC in a primitive cabinet", &f);
    CHECK(find(&f, APP_FINDING_COLLISION, 0, wc) != NULL);
    CHECK(find(&f, APP_FINDING_COLLISION, 2, wc) == NULL);
    app_findings_free(&f);
    /* An unknown product fails with its name. */
    add_product(&p, "ghost", "Nobody", "X-1", 500, 500, 0, 0);
    CHECK(app_placement_fixtures(&p, ptc_lookup, (void *)csv, &fx, &n, err, sizeof err) ==
          APP_ERR_NOT_FOUND);
    CHECK(tu_contains(err, "ghost") && tu_contains(err, "X-1"));
    app_project_free_all(&p);
}

/* DOMAIN.md "Clearances": no furniture may stand in a free area, whatever its product group;
 * a vanity unit is exempt only from the basin it carries. */
static void test_vanity_carries_basin_only(void)
{
    app_project p;
    make_room(&p);
    /* Cerana CE419501: vanity unit 800 x 460 x 520 hung at 160, its top at 680, carrying
     * Cerana CE410401 (800 x 480 furniture basin) from 680: no finding. */
    int vanity = add_product(&p, "vanity", "Cerana", "CE419501", 1500, 0, 160, 0);
    int basin = add_product(&p, "basin", "Cerana", "CE410401", 1500, 0, 680, 0);
    app_findings f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("basin on its vanity unit", &f);
    CHECK(f.count == 0);
    app_findings_free(&f);
    /* Holmwood HW1522, a tall cabinet 350 x 330 x 1700 of the same product group, 450 mm in
     * front of the basin (y 930..1260): it stands in the 1100 x 550 free area (y 480..1030),
     * which cannot slide past it. */
    int tall = add_product(&p, "tall-cabinet", "Holmwood", "HW1522", 1500, 480 + 450, 0, 0);
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("tall cabinet 450 mm in front of the basin", &f);
    const app_finding *a = find(&f, APP_FINDING_FREE_AREA, basin, tall);
    CHECK(a != NULL);
    CHECK(a && a->severity == APP_SEVERITY_ERROR);
    CHECK(a && tu_contains(a->message, "100 mm into it"));
    CHECK(find(&f, APP_FINDING_FREE_AREA, basin, vanity) == NULL);
    CHECK(find(&f, APP_FINDING_COLLISION, basin, vanity) == NULL);
    app_findings_free(&f);
    /* The vanity unit moved out from under the basin, 450 mm in front of it: it no longer
     * carries it, so it blocks the free area like any cabinet. */
    p.objects[tall].position_mm[0] = 2700;
    p.objects[vanity].position_mm[1] = 480 + 450;
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("vanity unit in front of the basin", &f);
    CHECK(find(&f, APP_FINDING_FREE_AREA, basin, vanity) != NULL);
    app_findings_free(&f);
    /* Back under the basin, sunk to the floor: it still stands under it (no collision, no
     * distance, no free-area finding). */
    p.objects[vanity].position_mm[1] = 0;
    p.objects[vanity].position_mm[2] = 0;
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("vanity unit on the floor under the basin", &f);
    CHECK(f.count == 0);
    app_findings_free(&f);
    /* The tall cabinet under the basin reaches above its rim: it does not carry it, the two
     * collide. */
    p.objects[tall].position_mm[0] = 1500;
    p.objects[tall].position_mm[1] = 0;
    p.objects[vanity].position_mm[0] = 600;
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("tall cabinet under the basin", &f);
    CHECK(find(&f, APP_FINDING_COLLISION, basin, tall) != NULL);
    app_findings_free(&f);
    app_project_free_all(&p);
}

/* DOMAIN.md "Clearances": a free area lies in front of its fixture and may slide sideways to
 * stay inside the room; only when no sideways position fits is it an error. */
static void test_free_area_slides(void)
{
    app_project p;
    make_room(&p);
    /* Cerana CE412901 (360 x 530) 200 mm from the left wall (x 200..560), as the side-distance
     * rule allows: centred, its 800 x 550 area would reach 20 mm into the wall (x -20..780);
     * slid 20 mm it fits (x 0..800). */
    int wc = add_product(&p, "wc", "Cerana", "CE412901", 200 + 180, 0, 60, 0);
    app_findings f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("WC 200 mm from the side wall", &f);
    CHECK(f.count == 0);
    app_findings_free(&f);
    /* Barrier-free (1200 x 1200) slides the same way: x 0..1200. */
    f = run_checks(&p, APP_BARRIER_FREE_ON);
    print_findings("WC 200 mm from the side wall, barrier-free", &f);
    CHECK(f.count == 0);
    app_findings_free(&f);
    /* A tall cabinet (Holmwood HW1522, 350 wide) in front of the WC at x 800..1150, y 600:
     * the slid area touches it, which is not overlapping. */
    int cab = add_product(&p, "tall-cabinet", "Holmwood", "HW1522", 975, 600, 0, 0);
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("WC area beside a cabinet", &f);
    CHECK(find(&f, APP_FINDING_FREE_AREA, wc, cab) == NULL);
    app_findings_free(&f);
    /* 100 mm further left (x 700..1050): the wall on one side and the cabinet on the other
     * leave no position for the 800 mm area. */
    p.objects[cab].position_mm[0] = 875;
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("WC area between wall and cabinet", &f);
    const app_finding *a = find(&f, APP_FINDING_FREE_AREA, wc, cab);
    CHECK(a && a->severity == APP_SEVERITY_ERROR);
    app_findings_free(&f);
    p.objects[cab].position_mm[0] = 2500;
    /* A room 760 wide (the WC 200 mm from both walls) has no sideways position for it. */
    p.plan.corners[1].x = p.plan.corners[2].x = 760;
    f = run_checks(&p, APP_BARRIER_FREE_OFF);
    print_findings("WC in a 760 mm wide room", &f);
    const app_finding *w = find(&f, APP_FINDING_FREE_AREA, wc, -1);
    CHECK(w && w->severity == APP_SEVERITY_ERROR);
    CHECK(w && tu_contains(w->message, "every sideways position"));
    CHECK(find(&f, APP_FINDING_DISTANCE, wc, -1) == NULL);
    app_findings_free(&f);
    app_project_free_all(&p);
}

static int near(double a, double b)
{
    return fabs(a - b) < 1e-6;
}

/* The free areas the drawings show are the ones the checks place (app_free_areas). */
static void test_free_areas_as_placed(void)
{
    app_project p;
    make_room(&p);
    /* The WC of test_free_area_slides 200 mm from the left wall: its 800 x 550 area slides
     * 20 mm right (x 0..800) to stay inside the room; a second WC centred on the wall keeps
     * its area centred (x 1100..1900). Both stand with their backs on wall 0 and are 530 deep,
     * so the areas run from y 530 to 1080. */
    int slid = add_product(&p, "wc-side", "Cerana", "CE412901", 200 + 180, 0, 60, 0);
    int centred = add_product(&p, "wc-centre", "Cerana", "CE412901", 1500, 0, 60, 0);
    int mirror = add_product(&p, "mirror", "Vitrelux", "VX20051", 1500, 0, 1100, 0);
    app_fixture *fx = NULL;
    int n = 0;
    char err[256] = "";
    CHECK_MSG(app_placement_fixtures(&p, ptc_lookup, (void *)csv, &fx, &n, err, sizeof err) ==
                  APP_OK,
              "%s", err);
    app_free_area *areas = calloc((size_t)(n > 0 ? n : 1), sizeof *areas);
    CHECK_MSG(app_free_areas(&p, fx, n, APP_BARRIER_FREE_OFF, areas, err, sizeof err) == APP_OK,
              "%s", err);
    for (int i = 0; i < n; i++) {
        const app_free_area *a = &areas[i];
        if (fx[i].object == mirror) {
            CHECK(!a->has_area);
            continue;
        }
        CHECK(a->has_area && a->clear);
        CHECK(near(a->width_mm, 800) && near(a->depth_mm, 550));
        double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
        for (int k = 0; k < 4; k++) {
            x0 = fmin(x0, a->corners[k][0]);
            x1 = fmax(x1, a->corners[k][0]);
            y0 = fmin(y0, a->corners[k][1]);
            y1 = fmax(y1, a->corners[k][1]);
        }
        printf("free area of %s: x %.1f..%.1f, y %.1f..%.1f, shift %.1f\n", fx[i].name, x0, x1, y0,
               y1, a->shift_mm);
        CHECK(near(y0, 530) && near(y1, 1080));
        if (fx[i].object == slid) {
            /* Every corner inside the 3000 x 2500 room. */
            CHECK(x0 >= -1e-6 && x1 <= 3000 + 1e-6 && y0 >= -1e-6 && y1 <= 2500 + 1e-6);
            CHECK(near(a->shift_mm, 20) && near(x0, 0) && near(x1, 800));
        } else if (fx[i].object == centred) {
            CHECK(near(a->shift_mm, 0) && near(x0, 1100) && near(x1, 1900));
        }
    }
    free(areas);
    free(fx);
    app_project_free_all(&p);
}

static void test_snapping(void)
{
    app_project p;
    make_room(&p);
    p.plan.prewall_count = 1;
    p.plan.prewalls = calloc(1, sizeof *p.plan.prewalls);
    app_prewall *pw = &p.plan.prewalls[0];
    snprintf(pw->name, sizeof pw->name, "wc-box");
    pw->wall = 0;
    pw->offset_mm = 2000;
    pw->width_mm = 800;
    pw->depth_mm = 200;
    pw->height_mm = 1100;
    app_pose in = {2900, 1200, 675, 0}, out;
    /* Near the right wall (x = 3000): back onto it, facing -x (90 degrees). */
    CHECK(app_snap_to_wall(&p.plan, 600, in, 300, &out) == 1);
    CHECK(near(out.x, 3000) && near(out.y, 1200) && near(out.rotation_deg, 90) && out.z == 675);
    /* Too far from every wall. */
    in = (app_pose){1500, 1200, 0, 0};
    CHECK(app_snap_to_wall(&p.plan, 600, in, 300, &out) == -1);
    CHECK(out.x == 1500 && out.y == 1200);
    /* Near the pre-wall's front (y = 200): onto it. */
    in = (app_pose){2400, 150, 60, 30};
    CHECK(app_snap_to_wall(&p.plan, 360, in, 300, &out) == 0);
    CHECK(near(out.x, 2400) && near(out.y, 200) && near(out.rotation_deg, 0));
    /* Past the wall's end: kept within the wall. */
    in = (app_pose){3100, 2450, 0, 0};
    CHECK(app_snap_to_wall(&p.plan, 600, in, 300, &out) == 1);
    CHECK(near(out.x, 3000) && near(out.y, 2200));
    /* Corner: on wall 1 the fixture spans y 1850..2450; its right side is 50 mm from the
     * corner at y = 2500. */
    in = (app_pose){3000, 2150, 675, 90};
    CHECK(app_snap_to_corner(&p.plan, 600, in, 100, 0, &out) == 1);
    CHECK(near(out.x, 3000) && near(out.y, 2200));
    CHECK(app_snap_to_corner(&p.plan, 600, in, 200, 200, &out) == 1);
    CHECK(near(out.y, 2000));
    CHECK(app_snap_to_corner(&p.plan, 600, in, 20, 0, &out) == 0);
    /* On wall 0 the pre-wall's left side (x = 2000) is a stop too. */
    in = (app_pose){1650, 0, 675, 0};
    CHECK(app_snap_to_corner(&p.plan, 600, in, 100, 0, &out) == 1);
    CHECK(near(out.x, 1700) && near(out.y, 0));
    /* Neighbour: a basin at x 700..1300; a WC placed 50 mm right of it slides to 200 mm. */
    int basin = add_product(&p, "basin", "Cerana", "CE410301", 1000, 0, 675, 0);
    app_fixture *fx = NULL;
    int n = 0;
    char err[256];
    CHECK(app_placement_fixtures(&p, ptc_lookup, (void *)csv, &fx, &n, err, sizeof err) == APP_OK);
    in = (app_pose){1300 + 50 + 180, 0, 60, 0};
    CHECK(app_snap_to_neighbour(fx, n, -1, 360, 530, in, 200, 200, &out) == basin);
    CHECK(near(out.x, 1300 + 200 + 180) && near(out.y, 0));
    /* ... and on its left side, from 120 mm to 200 mm. */
    in = (app_pose){700 - 120 - 180, 0, 60, 0};
    CHECK(app_snap_to_neighbour(fx, n, -1, 360, 530, in, 200, 200, &out) == basin);
    CHECK(near(out.x, 700 - 200 - 180));
    /* Too far away. */
    in = (app_pose){2200, 0, 60, 0};
    CHECK(app_snap_to_neighbour(fx, n, -1, 360, 530, in, 100, 200, &out) == -1);
    free(fx);
    app_project_free_all(&p);
}

int main(void)
{
    test_clean_basin_with_mirror();
    test_wc_beside_basin();
    test_bath_blocks_basin_area();
    test_walls_prewalls_doors();
    test_side_wall_and_barrier_free();
    test_vanity_carries_basin_only();
    test_free_area_slides();
    test_primitives_group();
    test_snapping();
    test_free_areas_as_placed();
    return check_report("placement");
}
