/* Drawing the plan view: walls with their thickness, openings with door
 * swings, pre-walls, fixtures with their free areas, findings, wall lengths. */
#ifndef UI_PLAN_DRAW_H
#define UI_PLAN_DRAW_H

#include "app/design/placement.h"
#include "app/design/snap_guides.h"
#include "app/project/project.h"
#include "ui/plan_view.h"

typedef struct ui_plan_overlay {
    int selected_object; /* -1 = none */
    int selected_wall;   /* -1 = none */
    int hover_corner;    /* -1 = none */
    int drag_corner;     /* -1 = none; drag_mm is where it goes */
    int drag_object;     /* -1 = none; drag_mm is where its centre goes */
    double drag_mm[2];
    int wall_dragging; /* 1: wall drag_wall moves by drag_wall_mm along its normal */
    int drag_wall;
    double drag_wall_mm;
    /* 1 while a fixture is dragged: snap is where it lands on release, drawn there with its
     * guides and its clear distances as dimension lines. */
    int snap_shown;
    app_snap_preview snap;
} ui_plan_overlay;

/* The snap guides' and distance labels' colour (magenta, as planners draw guides: it is
 * nowhere else in a plan), Dear ImGui's 0xAABBGGRR. */
#define UI_PLAN_GUIDE_COLOUR 0xff8c00d6u

/* areas: fixture_count free areas from app_free_areas (NULL: none drawn). */
void ui_plan_draw(const ui_plan_transform *t, const app_project *p, const app_fixture *fx,
                  const app_free_area *areas, int fixture_count, const app_findings *findings,
                  const ui_plan_overlay *o);

#endif
