/* What a fixture dragged in the window will snap to, shown while the drag lasts: the pose the
 * drag's `move ... snap wall corner neighbour` edit gives on release (the same snapping
 * functions of placement.h with the same distances), the guide lines of the wall face and the
 * corner or neighbour it snapped to, and its box's clear distances to the left, right and
 * front (to the nearest wall, pre-wall or fixture in that direction). Pure computation on the
 * plan and the fixtures; drawn by the window's plan view (ui/src/plan_draw.c) and 3D view. */
#ifndef APP_SNAP_GUIDES_H
#define APP_SNAP_GUIDES_H

#include "app/design/placement.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The distances of the `snap` edit words (cmd_script.c; docs/editing.md): a wall within
 * 500 mm of the back centre, a corner or a neighbour within 300 mm of where the side goes,
 * a neighbour kept 200 mm away (DOMAIN.md "Clearances"). tests/app/test_snap_guides.c checks
 * that the preview lands where the edit does. */
#define APP_SNAP_WALL_MM 500.0
#define APP_SNAP_CORNER_MM 300.0
#define APP_SNAP_NEIGHBOUR_MM 300.0
#define APP_SNAP_NEIGHBOUR_GAP_MM 200.0

typedef enum app_snap_guide_kind {
    APP_SNAP_GUIDE_WALL = 0,  /* along the face the back stands against */
    APP_SNAP_GUIDE_CORNER,    /* a side lined up with a corner or a pre-wall's side */
    APP_SNAP_GUIDE_NEIGHBOUR, /* a side kept the neighbour gap from another fixture */
} app_snap_guide_kind;

typedef struct app_snap_guide {
    app_snap_guide_kind kind;
    double a[2], b[2]; /* plan mm */
} app_snap_guide;

enum { APP_SNAP_LEFT = 0, APP_SNAP_RIGHT, APP_SNAP_FRONT, APP_SNAP_SIDES };

/* A clear distance from the box (a, the middle of a side) to what it faces (b). */
typedef struct app_snap_dimension {
    int found;         /* 0: nothing in that direction (an open plan) */
    double a[2], b[2]; /* plan mm */
    double mm;         /* |b - a| */
} app_snap_dimension;

typedef struct app_snap_preview {
    int wall;      /* the wall the back snapped to, -1: none near (the drag moves freely) */
    int corner;    /* 1: slid along the wall to a corner or a pre-wall's side */
    int neighbour; /* the object index it keeps the gap from, -1: none */
    app_pose pose; /* the object's position and turn after snapping */
    double centre[2], angle_deg; /* the box's plan centre and local x direction there */
    double half[2];              /* the box's half width and half depth, mm */
    app_snap_guide guides[3];
    int guide_count;
    app_snap_dimension sides[APP_SNAP_SIDES]; /* APP_SNAP_LEFT, _RIGHT, _FRONT */
} app_snap_preview;

/* Removes from fx (count fixtures) those of the objects mounted on project object `object`
 * (its group, app_group_members), keeping the order; returns how many are left. A group
 * moves as one, so the neighbour snap of a vanity must not keep its own mirror 200 mm away
 * from it where the mirror hung before the move. object -1: none removed. */
int app_fixtures_without_group(const app_project *p, int object, app_fixture *fx, int count);

/* The preview for fixture fx[index] (from app_placement_fixtures on p) whose object is asked
 * to go to pose `in` (its position_mm and turn, as the drag's edit line says it): snapped as
 * that edit snaps it, the guides, and the box's three distances measured there. Distances
 * ignore the fixture itself, attachments (they hang on something) and the fixtures whose box
 * holds the side's middle (its own group's parts). */
void app_snap_preview_of(const app_project *p, const app_fixture *fx, int count, int index,
                         app_pose in, app_snap_preview *out);

#ifdef __cplusplus
}
#endif
#endif
