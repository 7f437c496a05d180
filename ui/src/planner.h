/* The planner window's state and its parts: planner.c (window, frame loop), planner_input.c
 * (mouse and keyboard to navigation), planner_panels.c (ImGui panels), planner_script.c (the
 * scripted actions). Internal to ui/. */
#ifndef UI_PLANNER_H
#define UI_PLANNER_H

#include "app/project.h"
#include "app/quality.h"
#include "app/scene_build.h"
#include "catalog_browser.h"
#include "render/render.h"
#include "script.h"
#include "ui/navigation.h"
#include "ui/ui.h"

#include <stdio.h>

struct GLFWwindow;

enum { UI_MODE_ORBIT = 0, UI_MODE_WALK = 1 };
#define UI_FRAME_HISTORY 120

typedef struct planner {
    struct GLFWwindow *window;
    rd_context *ctx;
    app_project project;
    app_scene scene;
    int scene_ready;

    int quality; /* index into ui_quality_names */
    int mode;    /* UI_MODE_* */
    ui_orbit orbit;
    ui_walk walk;
    int camera;         /* stored viewpoint last jumped to, -1 = none */
    float render_scale; /* 3D view pixels per window pixel, adapted to the frame budget */
    int adaptive_scale; /* 1: render_scale follows the frame budget */
    float budget_ms;    /* the frame budget the adaptive scale aims for */

    float frame_ms[UI_FRAME_HISTORY];  /* whole frames, wall clock */
    float render_ms[UI_FRAME_HISTORY]; /* the 3D view alone, GPU finished */
    int frame_index;
    long frame_count;
    double last_time;
    FILE *frame_log;

    ui_catalog_browser browser;

    ui_script script;
    int action, action_frame;
    int quit;
    int exit_code;

    double mouse_x, mouse_y;
    int dragging;
} planner;

extern const char *const ui_quality_names[4];

/* planner_input.c: the window's events since the last frame, applied to the navigation. */
void planner_handle_input(planner *p, double dt);
/* planner_panels.c */
void planner_draw_panels(planner *p, int width, int height);
/* planner_script.c: runs this frame's share of the script; 0 ok, 1 failed (message printed). */
int planner_script_step(planner *p);
int planner_screenshot(planner *p, const char *path);
/* planner.c */
/* The project's floor plan, or its version 1 room box as a 4-corner plan in *fallback. */
const app_room_plan *planner_plan(const planner *p, app_point2 box[4], app_room_plan *fallback);
void planner_set_quality(planner *p, int index);
void planner_jump_to_camera(planner *p, int index);

#endif
