/* The live 3D view's schedule: while the view moves, one render a frame at the scale that
 * holds the frame budget; once it stands still, full-resolution passes at sub-pixel offsets
 * (live_accum.h), rendered a strip per frame, climbing a ladder of steps from the live preset
 * to the chosen one (settings switched between steps, probes refreshed a slice per frame).
 * Pure C, no GL: it decides, planner_live.c renders. Tested in tests/ui. */
#ifndef UI_LIVE_VIEW_H
#define UI_LIVE_VIEW_H

/* One rung: the quality preset (index into ui_quality_names) whose settings the renders take,
 * and how many jittered full-resolution passes it averages; or, background 1, the preset's
 * whole picture rendered by another process (still_render.h), counted as `passes` in the
 * progress. */
typedef struct ui_live_step {
    int preset;
    int passes;
    int background;
} ui_live_step;

enum { UI_LIVE_MAX_STEPS = 3, UI_LIVE_MIN_ROWS = 4 };
/* How much dearer a row of the next step is guessed to be than the last step's: in the
 * designed demo a still row at final costs about 2.3 times one at interactive on llvmpipe. */
#define UI_LIVE_STEP_COST 2.5f

typedef struct ui_live {
    ui_live_step steps[UI_LIVE_MAX_STEPS];
    int step_count;
    int step;                  /* the rung being rendered; step_count = done */
    int pass;                  /* passes finished in this step */
    int row;                   /* the next strip's first row in this pass */
    int settling;              /* 1: the last strip waited for a probe's capture (not averaged) */
    float ms_per_row;          /* what a full-width row of the current step costs, smoothed */
    float background_fraction; /* how far the current background step's render is, 0..1 */
} ui_live;

/* The preset a moving view renders with for a chosen preset: draft stays draft, the others
 * move at interactive. */
int ui_live_moving_preset(int chosen);
/* Starts the ladder for a view that has just stopped, towards preset `chosen` (0 draft ..
 * 3 print), with a first guess of a full-width row's cost (from the moving frames). */
void ui_live_begin(ui_live *l, int chosen, float ms_per_row);
/* As ui_live_begin, but final's and print's steps are background steps: the window renders
 * one interactive pass in strips, then shows final's picture (and then print's) as whole
 * renders of another process arrive, so that none of their set-up (shadow maps, probes, the
 * exposure's render, the print traces' hierarchies) lands in a frame of the window. */
void ui_live_begin_background(ui_live *l, int chosen, float ms_per_row);
/* The first background step at or after the current one, its index; -1 for none. */
int ui_live_next_background(const ui_live *l);
/* 1 when the current step is a background step (no strips: the caller waits for the render). */
int ui_live_on_background(const ui_live *l);
/* The background step `index` has its picture: the ladder goes on after it (skipping what
 * was left of the steps before it). Returns 1 when steps remain. */
int ui_live_background_done(ui_live *l, int index);
/* Rows of the next strip so that it costs about budget_ms; at least UI_LIVE_MIN_ROWS (and just
 * those while settling), at most what is left of the pass (height rows in all). */
int ui_live_strip_rows(const ui_live *l, float budget_ms, int height);
/* Reports a strip of `rows` rows that took ms (render and read back), in an image of height
 * rows. probes_busy = 1 when the renderer held a probe in view back (rd_frame_stats.
 * probes_held): the strip shows it unfinished, so the caller does not average it and the same
 * strip comes again. Returns 1 when a new step began (the caller applies its preset and
 * restarts the average). */
int ui_live_strip_done(ui_live *l, int rows, float ms, int height, int probes_busy);
/* 1 when every step is done: the view is final and needs no more renders. */
int ui_live_done(const ui_live *l);
/* How far the ladder is, 0..1 (passes done over passes in all; a background step's passes
 * count by background_fraction). */
float ui_live_progress(const ui_live *l);

#endif
