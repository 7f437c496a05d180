/* The planner window's state and its parts: planner.c (window, frame loop), planner_input.c
 * (mouse and keyboard to navigation), planner_panels.c (ImGui panels), planner_script.c (the
 * scripted actions). Internal to ui/. */
#ifndef UI_PLANNER_H
#define UI_PLANNER_H

#include "app/design/placement.h"
#include "app/project/project.h"
#include "app/project/project_lock.h"
#include "app/scene/quality.h"
#include "app/scene/scene_build.h"
#include "catalog_browser.h"
#include "drag_drop.h"
#include "fixture_drag.h"
#include "live_accum.h"
#include "live_view.h"
#include "plan_draw.h"
#include "panel_layout.h"
#include "quantities_panel.h"
#include "render/render.h"
#include "script.h"
#include "still_render.h"
#include "thumbnails.h"
#include "ui/navigation.h"
#include "ui/plan_view.h"
#include "ui/ui.h"

#include <stdio.h>

struct GLFWwindow;

enum { UI_MODE_ORBIT = 0, UI_MODE_WALK = 1 };
enum { UI_VIEW_3D = 0, UI_VIEW_PLAN = 1, UI_VIEW_ELEVATION = 2 /* tiles.h */ };
struct app_history;
#define UI_FRAME_HISTORY 120

/* The background renders that fill Mesa's shader cache for the still view's climb
 * (shader_warmup.c). */
typedef struct ui_shader_warmup {
    int pid;          /* the running render, 0 for none */
    int stage;        /* the next or running preset: final, then print */
    int finished;     /* all done, failed or switched off */
    int paused;       /* the running render is stopped while the view moves */
    double started;   /* the running stage's start, glfwGetTime */
    char folder[512]; /* the document's copy, removed at the end */
} ui_shader_warmup;

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
    int camera_mode;    /* the mode the cameras were last set up for (planner_camera.c) */
    float render_scale; /* 3D view pixels per window pixel, adapted to the frame budget */
    int adaptive_scale; /* 1: render_scale follows the frame budget */
    float budget_ms;    /* the frame budget the adaptive scale aims for */

    float frame_ms[UI_FRAME_HISTORY];  /* whole frames, wall clock */
    float render_ms[UI_FRAME_HISTORY]; /* the 3D view alone, GPU finished */
    int frame_index;
    long frame_count;
    double last_time;
    double last_cpu;          /* this thread's CPU seconds at the last frame's start */
    long stray_target_frames; /* frames whose panels found an off-screen target bound */
    double heap_logged_at;    /* heap_log.c: the last TESSERA_HEAP_LOG line */
    FILE *frame_log;
    double waited_s;   /* how long the loop waited for input before this frame (idle) */
    float view_ms_now; /* this frame's 3D view so far, ms */

    /* The live 3D view (planner_live.c): moving frames at a reduced scale, then the still view
     * refined in strips (live_view.h) into the accumulated full-resolution image. */
    struct {
        int still;           /* 1: the view has stood still since the ladder began */
        int applied;         /* the preset whose settings the scene holds, -1 = none */
        int serial;          /* bumped when the scene or the quality changes */
        double key[12];      /* what the last frame showed: eye, target, size, ... */
        int last_w, last_h;  /* the last moving render's size */
        unsigned char *last; /* and its pixels (RGBA8, last_w x last_h) */
        size_t last_size;
        float last_ms; /* and its cost */
        float rest_ms; /* the frame without its 3D view, smoothed (the strips' budget) */
        ui_live ladder;
        ui_accum accum;
        unsigned char *strip; /* the strip read back */
        float still_ev;       /* the exposure every strip of the step shares */
        int still_ev_ok;      /* 0: measure it over the whole view before the next strip */
        float view_ev;        /* the exposure of the view's last render (the frame log) */
        size_t strip_size;
        int window_w, window_h; /* where this frame presents: the window's size */
        ui_rect pane;           /* and the 3D view's pane in it */

        int shadows_pending;   /* 1: the step's shadow maps may lack faces (made before strips) */
        int shadow_faces_left; /* what the last frame's faces left to make */

        ui_still_render still_render; /* the ladder's background step under way */
        int background_step;          /* the ladder's step it renders */
        int opening;                  /* the 3D view's frames so far, up to 2 (opening_frame) */
    } live;

    ui_catalog_browser browser;

    /* The document (planner_doc.c): edits through app's commands, one undo step each. */
    struct app_history *history;
    app_lazy_catalog catalog;
    app_fixture *fixtures;
    int fixture_count;
    app_findings findings;
    /* fixture_count entries: each fixture's free area as the checks placed it, NULL when the
     * fixtures could not be built or placed. */
    app_free_area *free_areas;
    int dirty;
    /* The project's lock file (app/project/project_lock.h): held while this window edits the
     * file; read_only when another window holds it (saving refused, save as allowed). */
    app_project_lock lock;
    int read_only;
    double last_autosave;
    char status[320];
    int objects_at_open;  /* for scripts: objects added since the window opened */
    int recovery_offered; /* the autosave prompt is showing */
    int close_requested;  /* the unsaved-changes prompt is showing */

    /* The plan view (planner_plan.c). */
    int view; /* UI_VIEW_* */
    ui_plan_transform plan_t;
    int plan_fitted;
    ui_plan_overlay plan_o;
    double drag_start_mm[2];
    int panning;
    double wall_length_edit;

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

    /* Drag and drop, thumbnails, quantities, the file panel. */
    ui_drag_drop drop;
    ui_thumbnails thumbs;
    ui_quantities_view quantities;
    char file_path[1024]; /* the file panel's path field */
    int file_pending;     /* UI_FILE_*: waits for the unsaved-changes answer */

    /* The tile panel and the elevation view (tiles.h), made on first use. */
    struct ui_tiles *tiles;

    /* The window's frame (window_panes.c): this frame's rectangles (panel_layout.h), the
     * panes shown (UI_PANES_*), the 2D pane's share of the centre, the 2D view it shows
     * (UI_VIEW_PLAN or UI_VIEW_ELEVATION; p->view is the active pane's view). */
    ui_layout layout;
    int panes;
    float split;
    int view_2d;
    int layout_logged[5]; /* width, height, panes, the 2D pane's width, presenting */
    int splitter_held;
    double pointer_seen[2];
    int columns_placed; /* the columns' sections were opened or collapsed for this size */
    /* The status bar (status_bar.c): the mode it last said, and a message with its expiry. */
    int status_mode;
    char mode_message[160];
    double mode_message_until;
    int show_shortcuts; /* Help > Keyboard shortcuts */

    /* A placed fixture dragged in the 3D view (fixture_drag.c). */
    ui_fixture_drag fixture_drag;
    /* A move or rotate handle held in the 3D view (handles_3d.c). */
    struct {
        int active;
        int kind;        /* ui_handle (handle_geometry.h) */
        double plane_z;  /* the height the pointer is followed on, mm */
        double grab[2];  /* the plan point grabbed on it */
        double turn_deg; /* a ring drag's turn, whole 15-degree steps */
    } handle_drag;

    /* The baked light, baked on a worker thread once edits settle (planner_bake.c); NULL when
     * the bake is off (TESSERA_BAKE=off). */
    struct planner_bake *bake;

    /* File dialogs, recent files and long jobs (planner_actions.c), made on first use. */
    struct planner_files *files;

    ui_shader_warmup warmup;
} planner;

enum { UI_FILE_NONE = 0, UI_FILE_NEW, UI_FILE_OPEN };

extern const char *const ui_quality_names[4];

/* planner_input.c: the window's events since the last frame, applied to the navigation. */
void planner_handle_input(planner *p, double dt);
/* 1 when the pointer and the keys drive the window: no script runs, or it waits for outside
 * input (wait-file). */
int planner_input_live(const planner *p);
/* input_script.c: wait-file (0 waiting or done, 1 failed: message printed), locate and
 * expect-search (0 ok, 1 failed: why in p->status). */
int planner_wait_file(planner *p, const ui_action *a);
int planner_input_action(planner *p, const ui_action *a);
/* planner_panels.c */
void planner_draw_panels(planner *p, int width, int height);
/* New (UI_FILE_NEW) or open the Project panel's path (UI_FILE_OPEN), asking first when there
 * are unsaved changes. */
void planner_file_request(planner *p, int what);
/* window_panes.c: the frame's rectangles from the window's size, the active pane from the
 * pointer, the splitter; logs the pane rectangles to stderr whenever they change. */
void planner_layout_frame(planner *p, int width, int height);
/* The splitter between the panes (a drag moves it). */
void planner_splitter(planner *p);
/* The rectangle the 3D view is drawn into, window pixels (w = 0: not shown). */
ui_rect planner_view_rect(const planner *p);
/* Shows the plan and the 3D view side by side (both = 1) or the active view alone. */
void planner_show_panes(planner *p, int both);
/* menu_bar.c, toolbar.c, status_bar.c: the window's frame around the views. */
void planner_menu_bar(planner *p);
void planner_toolbar(planner *p);
void planner_status_bar(planner *p, double now);
/* The hint for the active tool (status_bar.c). */
const char *planner_tool_hint(const planner *p);
/* planner_plan.c: the selected wall's length and its door, window, pre-wall and niche. */
void planner_wall_panel(planner *p);
/* The selected fixture: delete, rotate by 90 degrees (one undo step each). */
int planner_delete_selected(planner *p);
int planner_rotate_selected(planner *p);
void planner_toggle_tour(planner *p);
/* A print-quality screenshot named after the time (F12). */
int planner_print_shot_now(planner *p);
/* planner_script.c: runs this frame's share of the script; 0 ok, 1 failed (message printed). */
int planner_script_step(planner *p);
/* 1 while the script holds on wait-still: the window then waits for input between frames as
 * it does without a script, so the background renders get the machine as they do for a user. */
int planner_script_idles(const planner *p);
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

/* planner_doc.c */
int planner_doc_open(planner *p);
void planner_doc_close(planner *p);
/* Runs one edit line (docs/editing.md) as one undo step; 0 ok, else the status says why. */
int planner_edit(planner *p, const char *line);
/* 1 when the edit line would make a fixture that is inside the room reach through a wall
 * (planner_edit_guard.c); why gets "NAME would reach through a wall: VERB refused". */
int planner_edit_reaches_out(planner *p, const char *line, char *why, size_t why_size);
int planner_undo(planner *p, int redo);
void planner_doc_changed(planner *p);
int planner_rebuild_scene(planner *p);
int planner_save(planner *p, const char *path);
/* planner_lock.c: takes the lock of the document's file (a shipped project under the source
 * tree's assets/ is not locked), releasing the one held before; sets read_only and says so in the
 * status when another window has the file. */
void planner_lock_document(planner *p);
/* Takes the lock of path for a save as (the old one is kept until the save succeeds): 0 ok, 1
 * another window has that file (the status says so). */
int planner_lock_for_save_as(planner *p, const char *path, app_project_lock *out);
void planner_unlock_document(planner *p);
void planner_autosave_tick(planner *p, double now);
/* heap_log.c: with TESSERA_HEAP_LOG=SECONDS, a heap and caches line on stderr that often;
 * planner_heap_after_rebuild gives free heap pages back (TESSERA_HEAP_TRIM=0: not). */
void planner_heap_log_tick(planner *p, double now);
void planner_heap_after_rebuild(void);
int planner_recovery_available(const planner *p);
int planner_recover(planner *p, int accept);
void planner_status(planner *p, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* planner_plan.c: the 2D plan view's input and drawing. */
void planner_plan_frame(planner *p, int width, int height);
/* Places the catalog browser's selected product at a plan point, snapped to the nearest wall. */
int planner_place_selected(planner *p, double x_mm, double y_mm);
/* Selects a fixture by its object's name ("-": none), as a click on it would. */
int planner_pick(planner *p, const char *name);
/* Moves a fixture (by object name) to a plan point, as a drag in the plan would. */
int planner_drag_object(planner *p, const char *name, double x_mm, double y_mm);
void planner_plan_scroll(planner *p, double steps);
/* planner_plan.c: moves wall `wall` by offset_mm along its outward normal (both corners, one
 * undo step); 0 ok, else the status says why. */
int planner_move_wall(planner *p, int wall, double offset_mm);
/* planner_plan.c: the edit line that adds a door (kind 0), window (1), pre-wall (2) or niche
 * (3) of a common size in the middle of wall `wall`, named uniquely; 0 when the wall or the
 * line does not fit. */
int planner_wall_item_line(const planner *p, int kind, int wall, char *line, size_t size);
/* findings_3d.c: the placement findings marked over the 3D view. */
void planner_findings_3d(planner *p, int width, int height);
/* selection_3d.c: the selected fixture and its group outlined over the 3D view; the window
 * pixels x0 y0 x1 y1 around that outline inside the pane (0 when none shows). */
void planner_selection_3d(planner *p);
int planner_selection_3d_bounds(const planner *p, float bounds[4]);
/* handles_3d.c: the selected fixture's move arrows and rotation ring over the 3D view. press
 * grabs the handle under window pixel (sx, sy) (1) or none (0); pointer follows the pointer;
 * release commits the move or the turn (one edit, one undo step). locate logs where a
 * handle (move-x, move-y, rotate) is grabbed and where a drag of it goes (scripts). */
void planner_handles_3d(planner *p);
int planner_handles_press(planner *p, double sx, double sy);
void planner_handles_pointer(planner *p, double sx, double sy);
int planner_handles_dragging(const planner *p);
void planner_handles_release(planner *p);
int planner_handles_locate(planner *p, const char *name);
/* snap_guides_3d.c: a 3D drag's snap guides and distance labels at the fixture's foot. */
void planner_snap_guides_3d(planner *p);
/* "STEM-N" with the smallest N no opening, pre-wall or niche of the plan is named (a static
 * buffer, valid until the next call). */
const char *planner_unique_name(const planner *p, const char *stem);
/* Tiles a surface ("wall:0", "floor", ...) with the catalog browser's selected tile. */
int planner_tile_selected(planner *p, const char *surface);

/* drag_drop.c: places the browser's selected product where a drop at window pixel (sx, sy)
 * over view (UI_VIEW_*) lands: the plan point, or the floor point under the 3D view's ray. */
int planner_drop_selected(planner *p, int view, double sx, double sy);
/* Shows the dragged product's ghost at (x, y) (the drag under way). */
void planner_drag_ghost(planner *p, int hit, double x, double y);
/* The frame's drag: starts it from the browser, moves the ghost, drops on release. */
void planner_drag_drop_frame(planner *p);
/* planner_doc.c: new (the empty room template), open (a bad file leaves the document as it
 * is and the status names the file and the problem). */
int planner_file_new(planner *p);
int planner_file_open(planner *p, const char *path);

/* fixture_drag.c: a placed fixture dragged in the 3D view, moved live in the renderer and
 * committed as one move edit on release. begin grabs project object `object` at the world
 * point grab (mm); to puts its plan centre at (x, y); end commits (1) or puts it back (0).
 * press starts a drag when window pixel (sx, sy) shows a fixture (1) and pointer follows the
 * pointer on the grabbed height. 0 = ok for begin and end. */
int planner_fixture_drag_begin(planner *p, int object, const double grab[3]);
void planner_fixture_drag_to(planner *p, double x_mm, double y_mm);
int planner_fixture_drag_end(planner *p, int commit);
int planner_fixture_drag_press(planner *p, double sx, double sy);
void planner_fixture_drag_pointer(planner *p, double sx, double sy);
/* Drops the drag without touching the scene (it is being rebuilt or released). */
void planner_fixture_drag_forget(planner *p);

/* tile_panel.c, elevation_draw.c, tile_actions.c (tiles.h): the tile panel, the
 * elevation view's frame, the tile script actions, and freeing their state. */
void planner_tile_panel(planner *p, int width, int height);
void planner_elevation_frame(planner *p, int width, int height);
int planner_tile_action(planner *p, const ui_action *a);
void planner_tiles_free(planner *p);

/* planner_live.c: draws this frame's 3D view (fw x fh window pixels); *render_ms gets its
 * cost, *rw x *rh its render size. 0 ok, 1 the renderer failed (message printed). */
int planner_live_frame(planner *p, int window_w, int window_h, ui_rect pane, float *render_ms,
                       int *rw, int *rh);
/* The refinement indicator over the 3D view while a still view is being refined. */
void planner_live_overlay(planner *p, ui_rect pane);
/* 1 when the still view is complete (the frame loop may wait for events). */
int planner_live_idle(const planner *p);
void planner_live_free(planner *p);
/* The scene's light changed in place (a bake applied): the still view is refined again from
 * the picture it shows. */
void planner_live_restart(planner *p);

/* planner_bake.c: the baked light in the background. start makes the worker when the bake is
 * on (0 ok); scene_build builds p->scene from the document with the light it had and hands
 * its render list to the worker once the edits settle (0 ok, else why in err); bake_frame
 * submits it and swaps a finished bake in (each frame, on the GL thread). */
int planner_bake_start(planner *p);
void planner_bake_free(planner *p);
int planner_scene_build(planner *p, char *err, size_t err_size);
void planner_bake_frame(planner *p);
/* 1 while a bake waits for edits to settle or runs. */
int planner_bake_busy(const planner *p);
/* 1 when no bake waits or runs and no crossfade is under way (scripts wait for it). */
int planner_bake_settled(const planner *p);

/* Shader warm-up (shader_warmup.c): a step each frame; done when every stage ran, failed or
 * was switched off (TESSERA_SHADER_WARMUP=off); stop kills a running stage. */
void planner_warmup_frame(planner *p);
int planner_warmup_done(const planner *p);
/* 1 when the warm-up's render of preset (index into ui_quality_names) is done or not needed. */
int planner_warmup_ready(const planner *p, int preset);
void planner_warmup_stop(planner *p);
/* The status bar's "Light: baking 40 %" (1), or 0 when there is nothing to say. */
int planner_bake_status(const planner *p, char *out, size_t size);
/* The still view's w x h picture as shown: crossfaded from the picture with the old light for
 * a moment after a bake arrived (a buffer of the bake's), else image itself. */
const unsigned char *planner_bake_fade(planner *p, const unsigned char *image, int w, int h);
void planner_bake_fade_stop(planner *p);
/* 1 while the still view crossfades to a new light (the window draws every frame). */
int planner_bake_fading(const planner *p);
/* Another document: its scene takes no light from the one before. */
void planner_bake_forget(planner *p);
/* Scripts: hold = 1 keeps bakes from starting until hold = 0. */
void planner_bake_hold(planner *p, int hold);
/* planner_camera.c: switches orbit and walk; walking starts from the view on screen. */
void planner_set_mode(planner *p, int mode);
/* Catches a mode changed by assignment (a widget, a key) and sets its camera up. */
void planner_camera_sync(planner *p);
/* Walks (mm) among the walls and the fixtures; 1 when the whole move was made. */
int planner_walk_move(planner *p, double forward_mm, double right_mm);

/* gl_check_window.c (TESSERA_GL_CHECK=1): the debug context's hint before the window is made,
 * counting from the context's start, the frame's poll, and at exit the summary; 1 when any GL
 * error was seen. */
void planner_gl_check_hint(void);
/* The window's context hints (window_context.c), shared with `--backend window`. */
void ui_context_hints(void);
void *ui_gl_proc(const char *name); /* GLFW's loader, for the renderer */
void planner_gl_check_start(void);
void planner_gl_check_frame(void);
int planner_gl_check_finish(long frames);

/* planner.c */
/* The renderer's view of what the window shows, at a size, with the quality's supersampling. */
void planner_view(const planner *p, int width, int height, rd_view *v);
/* The project's floor plan, or its version 1 room box as a 4-corner plan in *fallback. */
const app_room_plan *planner_plan(const planner *p, app_point2 box[4], app_room_plan *fallback);
void planner_set_quality(planner *p, int index);
void planner_jump_to_camera(planner *p, int index);

#endif
