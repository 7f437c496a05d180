/* Fixture placement: plan footprints of the objects of a project, collision and clearance
 * checks (DOMAIN.md "Clearances"), and snapping a fixture to walls, corners and neighbours.
 * The rules and their sources are listed in docs/editing.md.
 *
 * A catalog product's local frame (app/project/project.h: position_mm is the model origin): the
 * origin is the bottom centre of the product's back face; local x runs across the width
 * (-width/2 .. width/2), local y from the back face (0) to the front (depth), local z from
 * the bottom (0) to the top (height). rotation_deg[2] turns it about Z, so at 0 degrees the
 * product faces +Y (its back against wall 0 of a rectangle plan drawn from (0,0)).
 *
 * Everything here is pure computation on an app_project plus product sizes; products are
 * looked up through a callback (app_product_lookup), so the checks run without a catalog in
 * tests and with the SQLite catalog in the CLI (app_placement_catalog_lookup). */
#ifndef APP_PLACEMENT_H
#define APP_PLACEMENT_H

#include "app/project/project.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* What a check needs to know about a product. category is a cat_category value
 * (catalog/catalog.h); 0 = unknown. */
typedef struct app_product_info {
    double width_mm, depth_mm, height_mm;
    int category;
    char model[1024]; /* the product's GLB path relative to the assets folder, "" = none */
    /* The render material of the referenced variant (or the first), has_material = 1 when
     * the lookup supplies one (app/project/project.h app_material fields). */
    int has_material;
    char variant[16]; /* the variant code the material belongs to */
    float ambient[3], diffuse[3], specular[3], emissive[3];
    float shininess, reflectivity, glossiness, transparency, ior;
    int blend; /* APP_BLEND_* */
    /* The variant's pattern (APP_PATTERN_*) and its grain in degrees on the product's front
     * (app_material.grain_deg); the catalog's "along the longer side" is resolved here, by the
     * product's width and height. */
    int pattern;
    float grain_deg;
    /* The product's own mounting (catalog columns mounting_height_mm, mounting_to): when
     * has_mounting, mounting_height_mm above the floor to its underside (mounting_of
     * APP_MOUNT_BOTTOM) or top (APP_MOUNT_TOP: top, rim, seat); else its category's. */
    int has_mounting;
    double mounting_height_mm;
    int mounting_of; /* app_mount_of */
    /* Its companions (catalog/catalog.h cat_product.companions, cat_companion_get), "" = none. */
    char companions[512];
} app_product_info;

/* Returns APP_OK and fills *out, or APP_ERR_NOT_FOUND (or another error) with a message. */
typedef app_result (*app_product_lookup)(void *user, const app_product_ref *ref,
                                         app_product_info *out, char *err, size_t err_size);

/* A lookup backed by the SQLite catalog: user is a cat_db * (catalog/catalog.h). A variant
 * code the product does not have is APP_ERR_NOT_FOUND. */
app_result app_placement_catalog_lookup(void *user, const app_product_ref *ref,
                                        app_product_info *out, char *err, size_t err_size);

struct cat_db;
/* Opens the catalog for the CLI: db_path (NULL = $TESSERA_CATALOG or the default place)
 * built from the shipped data ($TESSERA_ASSETS/catalog, else the source tree's). */
app_result app_placement_open_catalog(const char *db_path, struct cat_db **out, char *err,
                                      size_t err_size);
/* The shipped assets folder ($TESSERA_ASSETS, else the source tree's assets/). */
const char *app_placement_assets_dir(void);

/* A catalog lookup that opens the catalog on its first use (so commands that need no product
 * never build it). Zero-initialise, set db_path (NULL = the default), pass as user to
 * app_placement_lazy_lookup; close with app_placement_lazy_close. */
typedef struct app_lazy_catalog {
    const char *db_path;
    struct cat_db *db;
    int failed;
    char err[1024];
} app_lazy_catalog;
app_result app_placement_lazy_lookup(void *user, const app_product_ref *ref, app_product_info *out,
                                     char *err, size_t err_size);
void app_placement_lazy_close(app_lazy_catalog *l);

/* How a fixture takes part in the checks. */
typedef enum app_fixture_role {
    APP_ROLE_FIXTURE = 0, /* collides with everything, may have a free area */
    APP_ROLE_ATTACHMENT,  /* mounted on another fixture (mixers, shower sets, accessories,
                             lamps): checked against walls only */
} app_fixture_role;

/* One fixture's plan footprint: an oriented rectangle plus a height range. For a product it
 * is the catalog box; for primitives, the box of their size (a group of primitives sharing a
 * group name is one fixture: the union of its parts' boxes in the group's first part's
 * frame). */
typedef struct app_fixture {
    int object;      /* index of the (first) object in app_project.objects */
    char name[64];   /* the object's name, or its group's */
    int category;    /* cat_category, 0 = none (a primitive) */
    int has_product; /* 1: a catalog product; 0: primitives (hand-modelled scenery) */
    app_fixture_role role;
    double centre[2];          /* plan centre of the rectangle, mm */
    double half[2];            /* half width (local x) and half depth (local y), mm */
    double angle_deg;          /* local x axis direction in the plan */
    double z0, z1;             /* bottom and top above the floor, mm */
    double width_mm, depth_mm; /* catalog size (0 for primitives) */
} app_fixture;

/* Builds the footprints of every object: product objects through lookup, primitives from
 * their size, scale and rotation (parts sharing a group merge into one fixture; planes are
 * sheets without thickness; models without a product are skipped, their size is unknown
 * here). Primitives are checked against walls and products, not against each other: a
 * hand-modelled version 1 scene builds one fixture from several overlapping parts.
 * *out is malloc'd (free() it). lookup may be NULL when no object has a product. Fails when
 * a product is not found, with the lookup's message and the object's name. */
app_result app_placement_fixtures(const app_project *p, app_product_lookup lookup, void *user,
                                  app_fixture **out, int *count, char *err, size_t err_size);

typedef enum app_finding_kind {
    APP_FINDING_COLLISION = 0, /* two fixtures overlap in plan and height */
    APP_FINDING_OUTSIDE_ROOM,  /* a fixture reaches through a wall (outside the plan) */
    APP_FINDING_PREWALL,       /* a fixture overlaps a pre-wall box */
    APP_FINDING_OPENING,       /* a fixture stands in a door (or in front of a window) */
    APP_FINDING_FREE_AREA,     /* a fixture's free area is blocked by a fixture or a wall */
    APP_FINDING_DISTANCE,      /* less than 200 mm between fixtures or to a side wall */
    APP_FINDING_BARRIER_FREE,  /* a DIN 18040-2 rule (only with barrier-free checks) */
    APP_FINDING_FLOATING,      /* a basin carried by nothing: not on a vanity unit, not
                                  wall-hung at a plausible rim height, not on the floor */
} app_finding_kind;

typedef enum app_severity {
    APP_SEVERITY_INFO = 0,
    APP_SEVERITY_WARNING,
    APP_SEVERITY_ERROR
} app_severity;

typedef struct app_finding {
    app_finding_kind kind;
    app_severity severity;
    int objects[2]; /* object indices involved, -1 = none (a wall, a pre-wall) */
    char message[320];
    double position_mm[2]; /* a plan point to show the finding at */
} app_finding;

typedef struct app_findings {
    app_finding *items;
    int count, capacity;
} app_findings;

void app_findings_free(app_findings *f);
/* "collision", "outside-room", ... and "info", "warning", "error". */
const char *app_finding_kind_name(app_finding_kind k);
const char *app_severity_name(app_severity s);
/* Number of findings of severity error. */
int app_findings_errors(const app_findings *f);

typedef enum app_barrier_free {
    APP_BARRIER_FREE_OFF = 0,
    APP_BARRIER_FREE_ON,         /* DIN 18040-2: 1200 x 1200 free areas */
    APP_BARRIER_FREE_WHEELCHAIR, /* 1500 x 1500, and the WC's 900 / 300 side distances */
} app_barrier_free;

typedef struct app_check_options {
    app_barrier_free barrier_free;
} app_check_options;

/* Runs every check on the fixtures of p (from app_placement_fixtures) and appends the
 * findings to *out (which may hold findings already). options may be NULL. */
app_result app_placement_check(const app_project *p, const app_fixture *fx, int count,
                               const app_check_options *options, app_findings *out, char *err,
                               size_t err_size);

/* The free area in front of a fixture (DOMAIN.md "Clearances"), in the fixture's local frame
 * x in [-w/2, w/2], y from the fixture's front edge to front + d, when centred on it. The
 * checks slide it sideways (by at most half the difference of the area's and the fixture's
 * widths) to keep it inside the room and clear of furniture. Returns 0 when the fixture has
 * none (a mirror, a primitive). */
int app_free_area_size(const app_fixture *f, app_barrier_free bf, double *w, double *d);

/* A fixture's free area where the checks place it (DOMAIN.md "Clearances"): the drawings of
 * the plan show these, so what is drawn is what app_placement_check checked. */
typedef struct app_free_area {
    int has_area;              /* 0: the fixture has none; the fields below are zero */
    int clear;                 /* 1: clear of walls and furniture (no finding for it) */
    double width_mm, depth_mm; /* app_free_area_size */
    double shift_mm;           /* sideways offset from the centred position, along local x */
    /* Plan mm: [0], [1] on the fixture's front edge (local -x, +x), [2], [3] at the far
     * edge (+x, -x). When no position is clear: the least shifted one inside the room, else
     * the centred one, as the finding reports it. */
    double corners[4][2];
} app_free_area;

/* Places the free area of each of the count fixtures fx (from app_placement_fixtures) with
 * the checks' own placement and writes it to out[i] (count entries). Fails only when out of
 * memory. */
app_result app_free_areas(const app_project *p, const app_fixture *fx, int count,
                          app_barrier_free bf, app_free_area *out, char *err, size_t err_size);

/* ---- mounting heights (DOMAIN.md "Typical sizes"; docs/editing.md "Mounting heights") ---- */

typedef enum app_mount_of {
    APP_MOUNT_TOP = 0, /* height_mm is the product's top: a basin's rim, a WC's seat */
    APP_MOUNT_BOTTOM   /* height_mm is its underside: a mirror, a radiator */
} app_mount_of;

/* Where a product of a category is mounted: at height_mm (measured as `of` says) above the
 * floor, or on top of a product of category `onto` when one is there (0 = never). */
typedef struct app_mounting {
    int category; /* cat_category */
    double height_mm;
    app_mount_of of;
    int onto;
} app_mounting;

/* The category's mounting, NULL when it has none (it lands on the floor). */
const app_mounting *app_mounting_of(int category);
/* The height (position_mm z) a product of that category and height lands at when dropped
 * freely: 850 - 170 = 680 for a 170 mm basin. 0 for a category without a mounting, and for
 * a product taller than its mounting height (it stands on the floor). */
double app_mounting_z(int category, double height_mm);
/* The same for a product: its own mounting when the catalog gives one (info->has_mounting),
 * else its category's (app_mounting_z). */
double app_product_mounting_z(const app_product_info *info);
/* The fixture of fx a product of that category dropped at plan point `at` is carried by: the
 * nearest one of the mounting's `onto` category within max_distance_mm of the point (a basin
 * dropped over or beside a vanity unit), or -1. */
int app_mounting_support(const app_fixture *fx, int count, int category, const double at[2],
                         double max_distance_mm);

/* ---- snapping ---------------------------------------------------------------------------- */

typedef struct app_pose {
    double x, y, z;      /* the object's position_mm */
    double rotation_deg; /* about Z */
} app_pose;

/* The back of a fixture of the given width snapped to the nearest wall face or pre-wall
 * front within max_distance_mm of its back centre: the back touches the face, the rotation
 * makes the fixture face into the room, and the fixture is moved along the wall so it lies
 * within the face. Returns the wall index (or -1 when no face is near; *out = in). */
int app_snap_to_wall(const app_room_plan *plan, double width_mm, app_pose in,
                     double max_distance_mm, app_pose *out);

/* After app_snap_to_wall: when a side of the fixture is within max_distance_mm of a corner
 * (an adjacent wall or a pre-wall side), slides it along its wall so that side is `gap_mm`
 * from it. Returns 1 when it moved. */
int app_snap_to_corner(const app_room_plan *plan, double width_mm, app_pose in,
                       double max_distance_mm, double gap_mm, app_pose *out);

/* Slides a fixture along its own width axis so its side is gap_mm from the nearest side of
 * another fixture of fx beside it (one whose footprint overlaps the band the fixture's depth
 * sweeps), when that side is within max_distance_mm of gap_mm. self_object is the object
 * index to ignore (-1: none). Returns the neighbour's object index, or -1 (*out = in). */
int app_snap_to_neighbour(const app_fixture *fx, int count, int self_object, double width_mm,
                          double depth_mm, app_pose in, double max_distance_mm, double gap_mm,
                          app_pose *out);

/* After app_snap_to_wall, for a dropped product: when the footprint of a fixture (width x
 * depth, its back on the wall or pre-wall face the pose stands on, z0..z1 above the floor)
 * lies in the swing of a door opening into the room (the square the `opening` check keeps
 * free), slides it along that face to the nearest position, on either side, clear of every
 * door swing, of the doorways and windows in front of it, of pre-walls, of the footprints
 * and free areas of the fixtures of fx, and 200 mm from those the distance check keeps a
 * product of `category` (cat_category) from, with the whole fixture on the face. Returns 1
 * when it moved, 0 when it was in no swing, -1 when no such position exists on that face (or
 * out of memory); *out = in unless it moved. */
int app_slide_out_of_swing(const app_room_plan *plan, const app_fixture *fx, int count,
                           int category, double width_mm, double depth_mm, double z0, double z1,
                           app_pose in, app_pose *out);

#ifdef __cplusplus
}
#endif
#endif
