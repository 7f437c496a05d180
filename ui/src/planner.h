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

    /* Presentation mode (presentation.c): the UI hidden, flights between viewpoints. */
    int presenting;
    int windowed_pos[4]; /* x, y, width, height before going fullscreen */
    int touring;         /* flying from viewpoint to viewpoint on its own */
    int turntable;       /* turning the orbit about its target */
    double tour_clock;   /* seconds spent at the current viewpoint */
    struct {
        int active;
        double from_eye[3], from_target[3], to_eye[3], to_target[3];
        double elapsed, duration; /* seconds */
        int camera;               /* the viewpoint flown to */
    } flight;
    double fixed_dt; /* > 0: animations advance by this per frame (scripts: reproducible) */

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
/* presentation.c */
/* Starts a flight to a stored viewpoint over `seconds` (0 = jump). */
void planner_fly_to_camera(planner *p, int index, double seconds);
/* Advances flights, the tour and the turntable by dt seconds. */
void planner_animate(planner *p, double dt);
/* The eye and target of the view being shown (flight, walk or orbit), mm. */
void planner_view_points(const planner *p, double eye[3], double target[3]);
void planner_draw_presentation(planner *p, int width, int height);
/* Renders the current view at print quality, twice the window size, into path (PNG/JPEG/
 * TIFF); the window's own quality is kept. */
int planner_print_shot(planner *p, const char *path);
void planner_toggle_fullscreen(planner *p);

/* planner.c */
/* The renderer's view of what the window shows, at a size, with the quality's supersampling. */
void planner_view(const planner *p, int width, int height, rd_view *v);
/* The project's floor plan, or its version 1 room box as a 4-corner plan in *fallback. */
const app_room_plan *planner_plan(const planner *p, app_point2 box[4], app_room_plan *fallback);
void planner_set_quality(planner *p, int index);
void planner_jump_to_camera(planner *p, int index);

#endif
