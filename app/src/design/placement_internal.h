/* Plan geometry shared by the placement files: oriented rectangles, walls and pre-walls as
 * rectangles and segments, distances and containment in the plan polygon. */
#ifndef APP_PLACEMENT_INTERNAL_H
#define APP_PLACEMENT_INTERNAL_H

#include "app/design/placement.h"

/* An oriented rectangle: centre c, unit axes ax (local x) and ay (local y, ax turned 90
 * degrees counter-clockwise), half extents h along them. */
typedef struct pl_rect {
    double c[2], ax[2], ay[2], h[2];
} pl_rect;

/* Touching is not overlapping: overlaps and intrusions below this many mm are ignored. */
#define PL_TOLERANCE_MM 1.0

pl_rect pl_rect_make(double cx, double cy, double angle_deg, double half_w, double half_d);
pl_rect pl_rect_of_fixture(const app_fixture *f);
/* A rectangle in a fixture's local frame (x in [x0,x1], y in [y0,y1], y measured from the
 * fixture's back face) placed in the plan. */
pl_rect pl_rect_local(const app_fixture *f, double x0, double x1, double y0, double y1);
void pl_rect_corners(const pl_rect *r, double out[4][2]);

/* Penetration depth of two rectangles (separating axis test): > 0 when they overlap, the
 * smallest push that separates them. */
double pl_rect_penetration(const pl_rect *a, const pl_rect *b);
/* The shortest distance between two rectangles, 0 when they touch or overlap; p receives
 * the midpoint of the closest pair of points. */
double pl_rect_distance(const pl_rect *a, const pl_rect *b, double p[2]);
double pl_segment_rect_distance(const double s0[2], const double s1[2], const pl_rect *r,
                                double p[2]);
double pl_segment_distance(const double a0[2], const double a1[2], const double b0[2],
                           const double b1[2], double p[2]);

/* 1 when the point is inside the polygon (even-odd rule). */
int pl_point_in_polygon(const app_point2 *poly, int n, double x, double y);
/* 1 when a part of r (shrunk by PL_TOLERANCE_MM) lies outside the polygon; where = a point of
 * it outside (a corner, or the middle of the crossing). */
int pl_rect_outside_polygon(const pl_rect *r, const app_point2 *poly, int n, double where[2]);

/* Wall i of the plan: start corner, unit direction, inward unit normal, length. */
void pl_wall_frame(const app_room_plan *plan, int wall, double origin[2], double dir[2],
                   double normal[2], double *length);
/* The plan rectangle of pre-wall k. */
pl_rect pl_prewall_rect(const app_room_plan *plan, int k);

/* A face a fixture's back can stand against: a wall, or a pre-wall's front. */
typedef struct pl_face {
    int wall;
    int prewall;             /* -1 for the wall itself */
    double o[2], d[2], n[2]; /* the wall's start corner, direction, inward normal */
    double len;              /* the wall's length */
    double s0, s1;           /* the face's extent along the wall */
    double offset;           /* the face's distance from the wall line (pre-wall depth) */
} pl_face;

/* Faces are numbered walls first, then pre-walls. pl_face_get returns 0 for a degenerate
 * one. */
int pl_face_count(const app_room_plan *plan);
int pl_face_get(const app_room_plan *plan, int k, pl_face *f);
/* The face the pose's back stands on (within 1 mm, facing along its normal), or -1. */
int pl_face_of_pose(const app_room_plan *plan, app_pose in, pl_face *out);

/* DOMAIN.md "Clearances": at least 200 mm between objects (VDI 6000 sheet 1). */
#define PL_SIDE_DISTANCE_MM 200.0
/* 1 when two fixtures of these categories must keep PL_SIDE_DISTANCE_MM apart (sanitary
 * objects, one of them a basin or a WC). */
int pl_side_distance_applies(int category_a, int category_b);

/* A fixture this close to a wall, across a door or window in it, stands in front of it. */
#define PL_OPENING_REACH_MM 50.0
/* The square an inward-opening door's leaf sweeps (its width deep, in front of the
 * doorway), kept free; 0 when opening k is no door opening into the room. */
int pl_door_swing_rect(const app_room_plan *plan, int k, pl_rect *out);

/* Appends a finding; returns APP_ERR_OUT_OF_MEMORY when it cannot. */
app_result pl_add_finding(app_findings *f, app_finding_kind kind, app_severity sev, int obj_a,
                          int obj_b, const double pos[2], const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 7, 8)))
#endif
    ;

/* placement_mounting.c: the floating-basin findings (a basin neither on a vanity unit nor
 * wall-hung at a plausible rim height nor standing on the floor). */
app_result pl_check_mounting(const app_project *p, const app_fixture *fx, int count,
                             app_findings *out);

#endif
