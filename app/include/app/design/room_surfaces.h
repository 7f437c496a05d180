/* The room's tileable surfaces: every surface a tiling can name
 * (app/design/room.h: "floor", "ceiling", "wall:I", "prewall:NAME:front|top|left|right") with its
 * 3D frame and its 2D region (app/design/tile_layout.h): the outline minus the holes, which are the
 * openings, the mouths of niches, the footprints of pre-walls and the fixtures that cover the
 * surface (a bath or shower tray standing against a wall covers the wall below its rim; it covers
 * the floor under it).
 *
 * Frames (mm): world point = origin + s * s_axis + t * t_axis; normal faces into the room.
 *  - "wall:I": origin the wall's start corner on the floor, s along the wall (app/design/room.h), t
 * up; normal the wall's inward normal. The outline follows a sloped ceiling.
 *  - "floor": s = plan x, t = plan y, z = 0, normal +Z. "ceiling": the same plan coordinates at
 *    the flat ceiling height, normal -Z (a sloped section is included, projected onto the plan).
 *  - "reveal:OPENING:left|right|top|bottom" (doors: no bottom) and
 *    "niche:NAME:left|right|top|bottom|back": the faces inside the wall's thickness
 *    (app_room_reveal below).
 *  - "prewall:NAME:front": the wall's s and t (so its joints can line up with the wall's),
 *    in the plane depth mm in front of the wall; "top": s along the wall, t from the wall into
 *    the room, at the pre-wall's height; "left" / "right" (seen from the room, facing the
 *    wall; left is at the larger s): s from the wall into the room, t up.
 * Every call that can fail returns an app_result and writes "room_surfaces: ..." into err. */
#ifndef APP_ROOM_SURFACES_H
#define APP_ROOM_SURFACES_H

#include "app/design/placement.h"
#include "app/project/project.h"
#include "app/design/tile_layout.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct app_surface_frame {
    char surface[96];
    app_surface_kind kind;
    double origin_mm[3], s_axis[3], t_axis[3], normal[3];
} app_surface_frame;

/* A fixture as an axis-aligned box in the room (mm) that covers what it stands in front of
 * or on. Make them with app_room_fixture_boxes (room_fixtures.c) or by hand. */
typedef struct app_fixture_box {
    char name[64];
    double min_mm[3], max_mm[3];
} app_fixture_box;

/* A placed product's covering box: 1 and *b filled when the product covers what it stands in
 * front of or on (a bath, a shower tray), else 0. */
int app_room_fixture_box(const app_object *o, const app_product_info *info, app_fixture_box *b);
/* The covering boxes of every placed product of p (malloc'ed; free it), products looked up
 * with lookup(user, ...). A product the catalog does not have is an error naming the object. */
app_result app_room_fixture_boxes(const app_project *p, app_product_lookup lookup, void *user,
                                  app_fixture_box **out, int *count, char *err, size_t err_size);

/* The tile layouts of every tiling of p, with the placed products' covering boxes as holes:
 * the layouts the renderer draws, so quantities and printed elevations count the same tiles.
 * db supplies the tiles and the products (app/design/quantities.h app_project_tile_layouts). */
struct cat_db;
app_result app_room_tile_layouts(const app_project *p, struct cat_db *db, app_tile_layout **out,
                                 int *count, char *err, size_t err_size);

/* The room's set-out (room_setout.c, docs/tiling.md "Set-out of a room"): when tilings of p are
 * marked "setout": "room", *out is a copy of p's tilings (malloc'ed; free it) in which those
 * get the shared grid as a fixed start (align line); else *out is NULL and p's own tilings
 * stand. fixtures cover surfaces as in app_room_surface_region. */
app_result app_room_setout_tilings(const app_project *p, struct cat_db *db,
                                   const app_fixture_box *fixtures, int fixture_count,
                                   app_tiling **out, char *err, size_t err_size);

/* A fixture covers a wall when its box is at most this far in front of the wall's face. */
#define APP_FIXTURE_WALL_GAP_MM 50.0

/* The names and frames of all tileable surfaces, in the order floor, ceiling, wall:0.., then
 * each pre-wall's front, top, left, right. *out is malloc'ed (free it). A project without a
 * plan uses its room box. */
app_result app_room_surface_list(const app_project *p, app_surface_frame **out, int *count,
                                 char *err, size_t err_size);

/* One surface's frame and region. fixtures may be NULL (count 0). *region is overwritten;
 * free it with app_surface_region_free. An unknown surface name is an error. */
app_result app_room_surface_region(const app_project *p, const char *surface,
                                   const app_fixture_box *fixtures, int fixture_count,
                                   app_surface_region *region, app_surface_frame *frame, char *err,
                                   size_t err_size);

/* A region provider for app_project_tile_layouts (app/design/quantities.h app_region_provider):
 * user points to an app_room_regions (the fixtures that cover surfaces; NULL = none). */
typedef struct app_room_regions {
    const app_fixture_box *fixtures;
    int fixture_count;
} app_room_regions;
app_result app_room_region_provider(void *user, const app_project *p, const char *surface,
                                    app_surface_region *out, char *err, size_t err_size);

/* A face inside the wall's thickness: a reveal of an opening (left, right, top, bottom; seen
 * from the room, left is at the larger s of the wall, as for pre-walls) or a niche's face
 * (the same and its back). Its region is the rectangle s0..s1 x t0..t1 of its frame: the sides
 * are depth x the opening's height (t the height above the floor, so a band applies), top and
 * bottom the opening's width x depth, a niche's back the wall's own s and t. The depth: a
 * window's reveal the wall thickness, a door's half of it (to the leaf), a niche's its depth.
 * The edge on the wall's face (an outside corner, where a trim profile goes) is the line
 * s = edge_at (edge_axis 0) or t = edge_at (edge_axis 1); a niche's back has none (-1). */
typedef struct app_room_reveal {
    app_surface_frame frame; /* frame.surface is the surface name */
    const char *face;        /* "left", "right", "top", "bottom", "back" */
    double s0, s1, t0, t1;
    int edge_axis;
    double edge_at;
} app_room_reveal;

/* The number of reveal and niche faces of plan. */
int app_room_reveal_count(const app_room_plan *plan);
/* Fills up to max faces (openings in their order, then niches); returns how many there are. */
int app_room_reveals(const app_room_plan *plan, app_room_reveal *out, int max);
/* 1 and *out (may be NULL) when surface names a reveal or niche face of plan, else 0. */
int app_room_reveal_find(const app_room_plan *plan, const char *surface, app_room_reveal *out);

/* The world point (mm) of surface coordinates (s, t). */
void app_surface_frame_point(const app_surface_frame *f, double s, double t, double out_mm[3]);

#ifdef __cplusplus
}
#endif
#endif
