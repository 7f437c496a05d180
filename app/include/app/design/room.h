/* The designed room (project file version 2): a floor plan polygon of walls with openings,
 * pre-walls, niches, a sloped ceiling section, and the tiling of its surfaces; fixtures that
 * refer to catalog products by manufacturer + article (+ variant).
 *
 * Coordinates: millimetres, right-handed, Z up, the floor at z = 0. The plan polygon is the
 * rooms's inside face of its walls, counter-clockwise seen from above (+Z), so the interior is
 * on the left of each wall. Wall i runs from corner i to corner (i + 1) % n; its "along"
 * coordinate s runs from 0 at corner i to its length at corner i + 1, its "up" coordinate from
 * the floor; its inward normal is the along direction turned 90 degrees counter-clockwise.
 *
 * Surfaces are named by a stable string, used by tilings and by the printed elevations:
 *   "floor", "ceiling", "wall:I" (I from 0), "prewall:NAME:front|top|left|right".
 *
 * These types are part of app_project (app/project/project.h: app_project.plan, .tilings and the
 * product reference of app_object). Version 1 files migrate to a 4-corner plan
 * (0,0) (width,0) (width,depth) (0,depth) with no openings (docs/project-format.md). */
#ifndef APP_ROOM_H
#define APP_ROOM_H

#ifdef __cplusplus
extern "C" {
#endif

#define APP_ROOM_MAX_CORNERS 256
#define APP_ROOM_DEFAULT_WALL_THICKNESS_MM 120.0

typedef struct app_point2 {
    double x, y; /* mm */
} app_point2;

typedef enum app_opening_type { APP_OPENING_DOOR = 0, APP_OPENING_WINDOW } app_opening_type;

/* Door swing, seen from inside the room looking at the wall: the hinge side and whether the
 * leaf opens into the room. */
typedef enum app_door_swing {
    APP_SWING_IN_LEFT = 0,
    APP_SWING_IN_RIGHT,
    APP_SWING_OUT_LEFT,
    APP_SWING_OUT_RIGHT,
    APP_SWING_SLIDING
} app_door_swing;

typedef struct app_opening {
    char name[64];
    app_opening_type type;
    int wall;             /* index of the wall it is cut into */
    double offset_mm;     /* along the wall, from its start corner to the opening's near edge */
    double width_mm;      /* along the wall */
    double height_mm;     /* clear height */
    double sill_mm;       /* bottom edge above the floor; 0 for doors */
    app_door_swing swing; /* doors only */
    float light[3];       /* windows: linear RGB of the daylight coming in (0 = none) */
} app_opening;

/* A boxed-in installation wall (pre-wall for a wall-hung WC, a shelf-high duct) standing
 * against a wall: a box from the wall's face into the room. Its faces can be tiled. */
typedef struct app_prewall {
    char name[64];
    int wall;
    double offset_mm; /* along the wall, from its start corner to the box's near edge */
    double width_mm;  /* along the wall */
    double depth_mm;  /* into the room */
    double height_mm; /* from the floor; the full wall height for a floor-to-ceiling duct */
} app_prewall;

/* A recess into a wall (shower niche): a box cut depth_mm deep into the wall's thickness. */
typedef struct app_niche {
    char name[64];
    int wall;
    double offset_mm, width_mm; /* along the wall */
    double sill_mm, height_mm;  /* bottom edge above the floor, clear height */
    double depth_mm;            /* into the wall, < wall thickness */
} app_niche;

/* A sloped ceiling section along one wall (an attic): the ceiling comes down to knee_mm at
 * that wall and reaches the full room height run_mm into the room. present = 0: none. */
typedef struct app_ceiling_slope {
    int present;
    int wall;
    double knee_mm; /* height at the wall, > 0 and < the room height */
    double run_mm;  /* horizontal distance from the wall's face to where the slope meets the
                       flat ceiling, > 0 */
} app_ceiling_slope;

typedef struct app_room_plan {
    app_point2 *corners; /* counter-clockwise, a simple polygon, 3..APP_ROOM_MAX_CORNERS */
    int corner_count;
    double height_mm;         /* wall height (flat ceiling) */
    double wall_thickness_mm; /* drawn in plans, cut by openings; default 120 */
    app_opening *openings;
    int opening_count;
    app_prewall *prewalls;
    int prewall_count;
    app_niche *niches;
    int niche_count;
    app_ceiling_slope slope;
} app_room_plan;

/* A product reference: manufacturer + article number (+ finish variant code, "" = the
 * product's first variant or none). The catalog supplies the model, dimensions, price and the
 * variant's material. */
typedef struct app_product_ref {
    char manufacturer[64];
    char article[40];
    char variant[16];
} app_product_ref;

typedef enum app_tile_pattern {
    APP_PATTERN_STRAIGHT = 0,   /* grid */
    APP_PATTERN_HALF_OFFSET,    /* running bond, each row shifted by half a tile */
    APP_PATTERN_THIRD_OFFSET,   /* each row shifted by a third */
    APP_PATTERN_VERTICAL_STACK, /* tiles stood upright (long side vertical), in a grid */
    APP_PATTERN_DIAGONAL,       /* a grid turned 45 degrees */
    APP_PATTERN_HERRINGBONE
} app_tile_pattern;

typedef enum app_tile_align {
    APP_ALIGN_CENTRED = 0, /* a grout cross (or a tile centre, see align_tile_centre) at the
                              centre of the surface region */
    APP_ALIGN_CORNER,      /* a whole tile at the region's start corner (bottom-left) */
    APP_ALIGN_LINE,        /* the grid passes through origin_mm (surface coordinates) */
    APP_ALIGN_AUTO         /* the set-out solver chooses the grid point (tile_setout.c) */
} app_tile_align;

/* A row of border (BOR) or decor (DEK) tiles across a wall at a height. */
typedef struct app_tile_border {
    app_product_ref product;
    double bottom_mm; /* the row's lower edge above the floor (walls) */
} app_tile_border;

#define APP_TILING_MAX_BORDERS 8

/* One tiled region of one surface. A surface may carry several regions (a wall tiled to
 * 1200 mm with one tile and above with another). */
typedef struct app_tiling {
    char name[64];
    char surface[96];        /* "wall:0", "floor", "prewall:wc-box:front", ... */
    app_product_ref product; /* the field tile (UNI) */
    app_tile_pattern pattern;
    double grout_mm;      /* joint width, >= 0; 0 = the tile's own default */
    float grout_color[3]; /* linear RGB */
    app_tile_align align;
    double origin_mm[2];   /* APP_ALIGN_LINE: a grid point, surface coordinates (s, up) */
    double rotation_deg;   /* the whole layout turned about the origin */
    double from_mm, to_mm; /* walls: the band tiled, heights above the floor; to_mm = 0
                              means up to the ceiling. Floors and ceilings: ignored. */
    app_tile_border borders[APP_TILING_MAX_BORDERS];
    int border_count;
    double edge_joint_mm; /* the elastic joint left open along the region's boundary: < 0 = the
                             joint width (a project file's default), 0 = none */
    double min_cut_mm;    /* the smallest cut piece allowed: 0 = a third of the tile's short
                             side, never under 50 mm (docs/tiling.md "Set-out") */
    int setout_room;      /* 1 ("setout": "room"): the grid is set out with the room's other such
                             tilings, rows and joints running on round the corners and from
                             the floor to the walls (docs/tiling.md "Set-out of a room") */
    app_product_ref trim; /* the profile along the surface's outside edges (a reveal's edge on
                             the wall, a pre-wall's corners); article "" = none
                             (app/design/trims.h) */
} app_tiling;

#ifdef __cplusplus
}
#endif
#endif
