/* The elevation view's geometry (ui/src/elevation_view.h) on real surface frames and a real
 * tile layout from app: a wall seen from inside has s growing to the left, the floor seen
 * from above does not; the fit keeps the whole surface inside the area and round-trips; a
 * fixture in front of a wall gets its silhouette, one behind or far away none; convex pieces
 * split into quads that cover them; whole and cut tiles are counted as the layout says. */
#include "check.h"
#include "elevation_view.h"

#include "app/design/room_surfaces.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const app_surface_frame *frame_of(const app_surface_frame *f, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(f[i].surface, name))
            return &f[i];
    return NULL;
}

/* Twice the area of a polygon (shoelace). */
static double area2(const app_point2 *p, int n)
{
    double a = 0;
    for (int i = 0; i < n; i++)
        a += p[i].x * p[(i + 1) % n].y - p[(i + 1) % n].x * p[i].y;
    return a;
}

int main(void)
{
    /* A 3000 x 2500 room, 2500 high, with a pre-wall on wall 3. */
    app_point2 corners[4] = {{0, 0}, {3000, 0}, {3000, 2500}, {0, 2500}};
    app_prewall pw = {.name = "box",
                      .wall = 3,
                      .offset_mm = 1000,
                      .width_mm = 800,
                      .depth_mm = 200,
                      .height_mm = 1100};
    app_project p;
    memset(&p, 0, sizeof p);
    p.plan = (app_room_plan){.corners = corners,
                             .corner_count = 4,
                             .height_mm = 2500,
                             .wall_thickness_mm = 120,
                             .prewalls = &pw,
                             .prewall_count = 1};
    p.room.width_mm = 3000;
    p.room.depth_mm = 2500;
    p.room.height_mm = 2500;
    app_surface_frame *frames = NULL;
    int n = 0;
    char err[1024];
    CHECK_MSG(app_room_surface_list(&p, &frames, &n, err, sizeof err) == APP_OK, "%s", err);
    const app_surface_frame *wall0 = frame_of(frames, n, "wall:0");
    const app_surface_frame *wall1 = frame_of(frames, n, "wall:1");
    const app_surface_frame *floor = frame_of(frames, n, "floor");
    const app_surface_frame *ceiling = frame_of(frames, n, "ceiling");
    const app_surface_frame *front = frame_of(frames, n, "prewall:box:front");
    CHECK(wall0 && wall1 && floor && ceiling && front);
    if (!wall0 || !wall1 || !floor || !ceiling || !front)
        return check_report("ui_elevation_view");

    /* Seen from the room: walls and pre-wall fronts mirrored (their start corner is on the
     * viewer's right, as the printed elevations draw them), the floor from above not, the
     * ceiling from below mirrored. */
    CHECK(ui_elev_mirrored(wall0) && ui_elev_mirrored(wall1) && ui_elev_mirrored(front));
    CHECK(!ui_elev_mirrored(floor));
    CHECK(ui_elev_mirrored(ceiling));

    /* The fit: the whole wall inside the area and its margin, the same scale both ways. */
    ui_elev_transform v = ui_elev_fit(0, 0, 3000, 2500, 1, 570, 40, 920, 560, 50);
    float sx0, sy0, sx1, sy1;
    ui_elev_to_screen(&v, 0, 0, &sx0, &sy0);
    ui_elev_to_screen(&v, 3000, 2500, &sx1, &sy1);
    CHECK(sx0 > sx1); /* s grows to the left */
    CHECK(sy1 < sy0); /* t grows upwards */
    CHECK(sx1 >= 570 + 50 - 1e-3 && sx0 <= 920 - 50 + 1e-3);
    CHECK(sy1 >= 40 - 1e-3 && sy0 <= 560 + 1e-3);
    CHECK(fabs((sx0 - sx1) / 3000.0 - (sy0 - sy1) / 2500.0) < 1e-4);
    CHECK(fabs(v.px_per_mm - 250.0 / 3000.0) < 1e-9); /* the width limits: 350 - 100 px */
    double s, t;
    ui_elev_to_surface(&v, 700.5f, 321.25f, &s, &t);
    float bx, by;
    ui_elev_to_screen(&v, s, t, &bx, &by);
    CHECK(fabsf(bx - 700.5f) < 1e-3f && fabsf(by - 321.25f) < 1e-3f);
    /* The centre of the area shows the centre of the wall. */
    ui_elev_to_surface(&v, 745, 300, &s, &t);
    CHECK(fabs(s - 1500) < 1e-6 && fabs(t - 1250) < 1e-6);
    /* Degenerate boxes and areas do not divide by zero. */
    ui_elev_transform d = ui_elev_fit(0, 0, 0, 2500, 1, 0, 0, 100, 100, 10);
    CHECK(d.px_per_mm == 0.1);
    d = ui_elev_fit(0, 0, 3000, 2500, 0, 0, 0, 50, 50, 40);
    CHECK(d.px_per_mm == 0.1);

    /* A bath (1700 x 750, 600 high) against wall 0: its silhouette on wall 0 spans its width
     * and height; on wall 2 (2500 mm away) it is too far; on the floor it is its footprint. */
    app_fixture bath = {
        .name = "bath", .centre = {1150, 375}, .half = {850, 375}, .z0 = 0, .z1 = 600};
    app_point2 out[8], lo, hi;
    double depth;
    int k = ui_elev_fixture_outline(wall0, &bath, 450, out, &depth);
    CHECK(k == 4 && fabs(depth) < 1e-9);
    CHECK(ui_elev_bounds(out, k, &lo, &hi));
    CHECK(fabs(lo.x - 300) < 1e-9 && fabs(hi.x - 2000) < 1e-9 && fabs(lo.y) < 1e-9 &&
          fabs(hi.y - 600) < 1e-9);
    CHECK(area2(out, k) > 0); /* counter-clockwise */
    CHECK(ui_elev_fixture_outline(frame_of(frames, n, "wall:2"), &bath, 450, out, &depth) == 0);
    CHECK(depth > 1700);
    k = ui_elev_fixture_outline(floor, &bath, 450, out, &depth);
    CHECK(k == 4 && fabs(area2(out, k) / 2 - 1700.0 * 750.0) < 1e-6);
    /* A ceiling lamp is not drawn on the floor, but on the ceiling. */
    app_fixture lamp = {
        .name = "lamp", .centre = {1500, 1250}, .half = {150, 150}, .z0 = 2350, .z1 = 2500};
    CHECK(ui_elev_fixture_outline(floor, &lamp, 450, out, &depth) == 0 && depth == 2350);
    CHECK(ui_elev_fixture_outline(ceiling, &lamp, 450, out, &depth) == 4 && fabs(depth) < 1e-9);
    /* Turned 30 degrees on the floor: still its footprint's area (a rotated rectangle). */
    bath.angle_deg = 30;
    k = ui_elev_fixture_outline(floor, &bath, 450, out, &depth);
    CHECK(k == 4 && fabs(area2(out, k) / 2 - 1700.0 * 750.0) < 1e-6);
    /* Turned so a corner reaches through the wall (more than 50 mm): not a fixture in front
     * of it. Moved 1 m into the room, its silhouette is the turned box's extent along the
     * wall, its nearest corner 250 mm away. */
    CHECK(ui_elev_fixture_outline(wall0, &bath, 450, out, &depth) == 0 && depth < -50);
    bath.centre[1] = 1000;
    k = ui_elev_fixture_outline(wall0, &bath, 450, out, &depth);
    CHECK(fabs(depth - (1000 - (850 * 0.5 + 375 * sqrt(0.75)))) < 1e-6);
    double c = cos(30 * 3.14159265358979323846 / 180), sn = sin(30 * 3.14159265358979323846 / 180);
    CHECK(k == 4 && ui_elev_bounds(out, k, &lo, &hi) &&
          fabs((hi.x - lo.x) - 2 * (850 * c + 375 * sn)) < 1e-6);

    /* Clipped to a box: a rectangle reaching past the surface keeps its part over it; one
     * outside it vanishes; a diamond's corners are cut off (8 points). */
    app_point2 wide[4] = {{-500, 0}, {4000, 0}, {4000, 600}, {-500, 600}}, clipped[12];
    app_point2 blo = {0, 0}, bhi = {3000, 2500};
    k = ui_elev_clip_box(wide, 4, blo, bhi, clipped);
    CHECK(k == 4 && ui_elev_bounds(clipped, k, &lo, &hi) && lo.x == 0 && hi.x == 3000 &&
          fabs(area2(clipped, k) / 2 - 3000.0 * 600) < 1e-6);
    app_point2 away[4] = {{3500, 0}, {4000, 0}, {4000, 600}, {3500, 600}};
    CHECK(ui_elev_clip_box(away, 4, blo, bhi, clipped) == 0);
    app_point2 diamond[4] = {{1500, -200}, {3200, 1250}, {1500, 2700}, {-200, 1250}};
    k = ui_elev_clip_box(diamond, 4, blo, bhi, clipped);
    CHECK(k == 8 && area2(clipped, k) > 0 && area2(clipped, k) < area2(diamond, 4));

    /* Fans of quads: a triangle is one quad repeating its last point, a hexagon two. */
    int quads[8][4];
    CHECK(ui_elev_fan_quads(2, quads, 8) == 0);
    CHECK(ui_elev_fan_quads(3, quads, 8) == 1 && quads[0][3] == 2);
    CHECK(ui_elev_fan_quads(6, quads, 8) == 2 && quads[1][0] == 0 && quads[1][1] == 3 &&
          quads[1][3] == 5);
    CHECK(ui_elev_fan_quads(5, quads, 8) == 2 && quads[1][2] == 4 && quads[1][3] == 4);
    /* The quads of a convex pentagon add up to its area. */
    app_point2 pent[5] = {{0, 0}, {400, 0}, {500, 300}, {200, 500}, {-100, 300}};
    int q = ui_elev_fan_quads(5, quads, 8);
    double sum = 0;
    for (int i = 0; i < q; i++) {
        app_point2 quad[4];
        for (int j = 0; j < 4; j++)
            quad[j] = pent[quads[i][j]];
        sum += area2(quad, 4);
    }
    CHECK(fabs(sum - area2(pent, 5)) < 1e-6);

    /* A real layout of wall 1 (2500 x 2500) with 297 x 597 tiles, half offset, from the
     * corner: counted whole and cut tiles match the layout's own counts. */
    app_surface_region region;
    app_surface_frame f;
    CHECK_MSG(app_room_surface_region(&p, "wall:1", NULL, 0, &region, &f, err, sizeof err) ==
                  APP_OK,
              "%s", err);
    app_tiling tiling = {.name = "wall:1",
                         .surface = "wall:1",
                         .pattern = APP_PATTERN_HALF_OFFSET,
                         .grout_mm = 3,
                         .align = APP_ALIGN_CORNER};
    app_tile_spec spec = {.work_w_mm = 597, .work_h_mm = 297, .grout_mm = 3};
    app_tile_layout_desc desc = {.region = &region, .tiling = &tiling, .field = &spec};
    app_tile_layout l;
    CHECK_MSG(app_tile_layout_compute(&desc, &l, err, sizeof err) == APP_OK, "%s", err);
    int whole, cut;
    ui_elev_count_tiles(&l, &whole, &cut);
    printf("wall:1 layout: %d whole, %d cut (layout says %d, %d)\n", whole, cut, l.whole_count,
           l.cut_count);
    CHECK(whole == l.whole_count && cut == l.cut_count && whole + cut == l.tile_count);
    CHECK(whole > 0 && cut > 0);
    app_tile_layout_free(&l);
    app_surface_region_free(&region);
    ui_elev_count_tiles(NULL, &whole, &cut);
    CHECK(whole == 0 && cut == 0);

    /* Wall names and the start point's snapping. */
    CHECK(ui_elev_wall_index("wall:0") == 0 && ui_elev_wall_index("wall:12") == 12);
    CHECK(ui_elev_wall_index("floor") == -1 && ui_elev_wall_index("wall:") == -1 &&
          ui_elev_wall_index("wall:2x") == -1 && ui_elev_wall_index("prewall:box:front") == -1);
    double ss, tt;
    ui_elev_snap_point(1234.6, 887.4, 10, &ss, &tt);
    CHECK(ss == 1230 && tt == 890);
    ui_elev_snap_point(1234.6, 887.4, 0, &ss, &tt);
    CHECK(ss == 1234.6 && tt == 887.4);
    free(frames);
    return check_report("ui_elevation_view");
}
