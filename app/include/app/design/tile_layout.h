/* Tile layout of one surface region: every whole and cut tile, computed as real geometry
 * (DOMAIN.md "Products and catalog records", "What the best planners print").
 * docs/tiling.md describes the model, the patterns and how cuts are counted.
 *
 * Coordinates: 2D surface coordinates in millimetres, s along the surface (x of the points),
 * t up (y of the points). Walls: s along the wall from its start corner, t the height above the
 * floor (app/design/room.h). Floors and ceilings: s = plan x, t = plan y. Pre-wall faces: as the
 * room helper maps them; only "t is a height above the floor" matters here (kind, below), because a
 * wall tiling's band (app_tiling.from_mm / to_mm) and border rows are heights.
 *
 * Ownership: a region owns its arrays (build it with the app_region_* calls, free it with
 * app_surface_region_free); a layout owns its arrays (app_tile_layout_free). Nothing here keeps
 * global state; every call that can fail returns an app_result and writes "tile_layout: what
 * went wrong" into err. */
#ifndef APP_TILE_LAYOUT_H
#define APP_TILE_LAYOUT_H

#include "app/project/project.h"
#include "app/design/room.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- polygons and surface regions ----------------------------------------------------------- */

/* A simple polygon (no self-intersections), either orientation; points owned by whoever built
 * it (inside a region: the region). */
typedef struct app_polygon {
    app_point2 *points;
    int count;
} app_polygon;

/* Shoelace area: positive for counter-clockwise, negative for clockwise. */
double app_polygon_signed_area(const app_point2 *points, int count);

/* What a hole in a region is; for drawing and reporting only, all holes are cut the same. */
typedef enum app_hole_kind {
    APP_HOLE_OPENING = 0, /* a door or window */
    APP_HOLE_COVERED,     /* covered by a fixture or a pre-wall: behind a bath, under a box */
    APP_HOLE_NICHE,       /* the mouth of a niche (its inside faces are their own surfaces) */
    APP_HOLE_OTHER
} app_hole_kind;

typedef struct app_region_hole {
    app_polygon polygon; /* may overlap other holes and stick out of the outline */
    app_hole_kind kind;
    char name[64]; /* the opening's / fixture's name, may be "" */
} app_region_hole;

typedef enum app_surface_kind {
    APP_SURFACE_WALL = 0,     /* t = height above the floor; the tiling's band applies */
    APP_SURFACE_FLOOR,        /* s, t = plan x, y */
    APP_SURFACE_CEILING,      /* s, t = plan x, y */
    APP_SURFACE_PREWALL_SIDE, /* a pre-wall's front/left/right face: t = height, band applies */
    APP_SURFACE_PREWALL_TOP   /* a pre-wall's top: horizontal */
} app_surface_kind;

/* One room surface as a flat region: the outline (a simple polygon, counter-clockwise; a
 * clockwise one is reversed when set) minus the holes. */
typedef struct app_surface_region {
    char surface[96]; /* "wall:0", "floor", "prewall:wc-box:front" (app/design/room.h) */
    app_surface_kind kind;
    app_polygon outer;
    app_region_hole *holes;
    int hole_count;
    int hole_capacity;
} app_surface_region;

/* Starts an empty region (no outline). */
void app_surface_region_init(app_surface_region *r, const char *surface, app_surface_kind kind);
/* Copies the outline (3..100000 finite points, a non-zero area); clockwise input is reversed. */
app_result app_region_set_outer(app_surface_region *r, const app_point2 *points, int count,
                                char *err, size_t err_size);
/* Copies a hole outline (3.. finite points, either orientation). */
app_result app_region_add_hole(app_surface_region *r, const app_point2 *points, int count,
                               app_hole_kind kind, const char *name, char *err, size_t err_size);
/* An axis-aligned rectangular outline or hole: s0..s1 x t0..t1 (any order of the bounds). */
app_result app_region_set_outer_rect(app_surface_region *r, double s0, double t0, double s1,
                                     double t1, char *err, size_t err_size);
app_result app_region_add_hole_rect(app_surface_region *r, double s0, double t0, double s1,
                                    double t1, app_hole_kind kind, const char *name, char *err,
                                    size_t err_size);
/* Frees the arrays and zeroes *r; safe on a zeroed region and on NULL. */
void app_surface_region_free(app_surface_region *r);

/* The region's area: outline minus the union of the holes inside it (mm2), computed
 * independently of any layout (exact for polygons; used by the tests' area balance). */
double app_surface_region_area(const app_surface_region *r);

/* Fallback until the room model provides its own surface regions: the region of a surface of
 * the project's plan ("floor", "ceiling", "wall:I"): floor/ceiling = the plan polygon; a wall =
 * length x height minus its openings (doors, windows) and the footprint of pre-walls standing
 * against it (covered); "prewall:NAME:front|left|right|top" = a rectangle (front width x
 * height, sides depth x height, top width x depth). Fixtures covering a surface (a bath) are
 * not known here: the room model's provider adds them. */
app_result app_surface_region_from_plan(const app_room_plan *plan, const char *surface,
                                        app_surface_region *out, char *err, size_t err_size);

/* ---- tile specs ----------------------------------------------------------------------------- */

/* Same order as catalog's cat_tile_type (UNI field tile, BOR border, DEK decor, EIN insert). */
typedef enum app_tile_type {
    APP_TILE_UNI = 0,
    APP_TILE_BOR,
    APP_TILE_DEK,
    APP_TILE_EIN
} app_tile_type;

/* What the layout and the quantities need to know about a tile product. Fill it from the
 * catalog with app_tile_spec_from_catalog (quantities.h) or by hand (tests). */
typedef struct app_tile_spec {
    app_product_ref product;
    app_tile_type type;
    double work_w_mm, work_h_mm; /* the tile as made; w runs along s in a straight layout */
    double grout_mm;             /* the product's joint (used when app_tiling.grout_mm is 0) */
    double m2_per_box;           /* 0 = unknown */
    int pieces_per_box;          /* 0 = unknown */
    int reusable_offcuts;        /* 1: a cut's remainder may serve another cut (not for DEK) */
    int rotatable;     /* 1: a remainder may be turned 90 degrees to serve (not for DEK) */
    char texture[256]; /* catalog texture path relative to assets/, may be "" */
    int matt;          /* 1: the catalog's surface is matt or structured (no glaze to show) */
} app_tile_spec;

/* ---- the layout ----------------------------------------------------------------------------- */

/* How a piece's edge came about: on the tile's own uncut edge (a grout line), a cut along the
 * region's boundary (outline, hole or the band's edge), or an internal seam between two convex
 * pieces of the same tile (not to be drawn). */
typedef enum app_tile_edge { APP_EDGE_TILE = 0, APP_EDGE_CUT, APP_EDGE_SEAM } app_tile_edge;

/* A convex piece of a tile's clipped shape: vertices [first, first + count) of the layout's
 * points/edges arrays, counter-clockwise; edges[i] is the edge from point i to point i + 1. */
typedef struct app_tile_piece {
    int first, count;
} app_tile_piece;

typedef struct app_placed_tile {
    int product;  /* index into app_tile_layout.specs: 0 the field tile, 1 + k border k */
    int row, col; /* the uncut cell's grid id (pattern lattice indices; border rows: row = -1 -
                     the border index, col along s) */
    int herring;  /* herringbone: 0 the piece along the lattice's u, 1 the turned one; else 0 */
    app_point2 cell[4];        /* the uncut tile at work size, counter-clockwise, surface coords */
    app_point2 centre;         /* of the uncut tile */
    double rotation_deg;       /* the tile's width direction against +s (layout rotation, +45
                                  diagonal, +90 vertical stack and the turned herringbone pieces) */
    double area_mm2;           /* of the clipped shape (= work w x h when whole) */
    double cell_area_mm2;      /* the nominal cell (tile + half the joint around it) clipped to the
                                  region: tiles plus grout add up to the region's area */
    int whole;                 /* 1: uncut (the clipped shape is the whole cell) */
    double cut_w_mm, cut_h_mm; /* the clipped shape's extent in the tile's own axes (the piece
                                  a tiler cuts; offcut reuse works on these) */
    int first_piece, piece_count; /* into app_tile_layout.pieces */
    double cut_u0_mm, cut_v0_mm;  /* where that extent starts in the tile's axes, measured from
                                     cell[0] (0, 0 for a whole tile): the remainder of the tile
                                     is what lies before and after it */
} app_placed_tile;

typedef struct app_tile_layout_desc {
    const app_surface_region *region;
    const app_tiling *tiling;     /* pattern, grout, alignment, rotation, band, borders */
    const app_tile_spec *field;   /* the field tile (tiling->product) */
    const app_tile_spec *borders; /* tiling->border_count specs, in the order of the borders;
                                     may be NULL when border_count is 0 */
    int max_tiles;                /* refuse layouts with more tiles; 0 = 2 000 000 */
} app_tile_layout_desc;

typedef struct app_tile_layout {
    char surface[96];
    app_tile_spec specs[1 + APP_TILING_MAX_BORDERS]; /* [0] field, [1 + k] border k */
    int spec_count;
    double grout_mm;   /* the joint used */
    app_point2 origin; /* a grid point of the field lattice (surface coords) */
    double angle_deg;  /* the field lattice's angle against +s */
    app_placed_tile *tiles;
    int tile_count;
    app_tile_piece *pieces;
    int piece_count;
    app_point2 *points;
    unsigned char *edges; /* app_tile_edge per point */
    int point_count;
    double region_area_mm2;      /* the tiled region (band applied, holes removed) */
    double tiled_area_mm2;       /* sum of the tiles' area_mm2 */
    double grout_area_mm2;       /* region_area_mm2 - tiled_area_mm2 */
    double unassigned_grout_mm2; /* grout of cells that hold no tile (they only touch the
                                    region with their joint); sum of cell_area_mm2 + this =
                                    region_area_mm2 */
    int whole_count, cut_count;
} app_tile_layout;

/* Lays the tiles of one tiling on one region. Orientation: straight, half and third offset
 * and diagonal lay the tile's long side along the rows (lattice u); the vertical stack stands
 * it up; herringbone alternates; border rows lay the long side along s, the row's lower edge at
 * border.bottom_mm, the field cut one joint below and above the row. A tile's rotation_deg
 * says where its catalog w axis points. */
/* Lays the tiles of one tiling on one region. *out is overwritten (free it with
 * app_tile_layout_free). Errors: bad sizes (work size <= 0, grout < 0 or absurd), a tiling on
 * a region without an outline, more tiles than max_tiles, out of memory. */
app_result app_tile_layout_compute(const app_tile_layout_desc *desc, app_tile_layout *out,
                                   char *err, size_t err_size);

/* The minimum-cut rule (docs/tiling.md "Set-out"): a piece cut across a tile side of length
 * side must be at least app_tile_min_cut_mm wide: tiling->min_cut_mm when set, else a third of
 * the side and never under 50 mm (nor over the side itself). */
double app_tile_min_cut_mm(const app_tiling *tiling, double side_mm);

/* The worst cut piece of a layout against the rule: the smallest ratio of a cut piece's width to
 * the rule for the side it was cut across (>= 1: every cut keeps the rule; a large number when
 * nothing is cut across a side). *tile gets its index (-1 when none), *width_mm its width and
 * *rule_mm the rule (either may be NULL). Notched pieces whose extent is the whole tile count as
 * uncut. */
double app_tile_layout_worst_cut(const app_tile_layout *l, const app_tiling *tiling, int *tile,
                                 double *width_mm, double *rule_mm);

/* The edge joint a tiling leaves at its region's boundary: tiling->edge_joint_mm, or the joint
 * width g when it is negative. */
double app_tile_edge_joint_mm(const app_tiling *tiling, double g);

/* Frees the arrays and zeroes *l; safe on a zeroed layout and on NULL. */
void app_tile_layout_free(app_tile_layout *l);

/* "straight", "half-offset", "third-offset", "vertical-stack", "diagonal", "herringbone";
 * "centred", "corner", "line", "auto" (as the project file spells them). Never NULL ("" when out of
 * range). Parsers return 1 and set *out when known (any case; "_" for "-" too), else 0. */
const char *app_tile_pattern_name(app_tile_pattern p);
int app_tile_pattern_parse(const char *text, app_tile_pattern *out);
const char *app_tile_align_name(app_tile_align a);
int app_tile_align_parse(const char *text, app_tile_align *out);

#ifdef __cplusplus
}
#endif
#endif
