/* The live 3D view: while the view or a fixture moves, one render a frame at the scale that
 * holds the frame budget; once it stands still, the ladder of live_view.h renders the full
 * resolution a strip a frame at sub-pixel offsets, averaged by live_accum.h, and final's and
 * print's pictures come whole from a render in another process (still_render.h), started as
 * the view stops. No frame renders more than a strip's budget, so final and print quality
 * never freeze the window. TESSERA_STILL_RENDER=window climbs to them in the window's own
 * strips instead, a step's shadow maps, probes and exposure spread over its frames. */
#include "planner.h"

#include "gui.h"
#include "render/ui_texture.h"

#include <GLFW/glfw3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* What a still frame's strip may cost (render and read back): the frame's 100 ms ceiling less
 * the rest of the frame (the panels, the present, the swap: about 5-10 ms alone, several times
 * that on a loaded machine, so it is measured), less room for the strip's estimate to be off
 * by a third; at most STRIP_BUDGET_MS, at least STRIP_MIN_MS. */
#define FRAME_CEILING_MS 100.0f
#define STRIP_BUDGET_MS 55.0f
#define STRIP_MIN_MS 10.0f
/* Probe faces a still frame may capture: a probe's six faces at 256 texels cost about a
 * strip's budget on llvmpipe (docs/benchmarks.md, "Reflection probes"). */
#define STILL_FACES_PER_FRAME 6
/* The most a strip's split captures may take, in faces: a probe's six and its blur (which
 * counts as two, probe.c), as one whole capture did, where faces are cheap. */
#define SPLIT_MAX_FACES 8
#define SCALE_FLOOR 0.35f
/* Probe faces a moving frame may capture (a blur counts two, probe.c), and the time they may
 * take beyond the first (a 256-texel face alone takes 16-24 ms on llvmpipe). */
#define MOVING_FACES_PER_FRAME 2
#define MOVING_CAPTURE_MS 8.0f

/* The scene takes preset `index`'s settings. Probes are captured on change, never every
 * frame (final and print's policy for single renders): a still view's eye does not move, and
 * a moving view keeps its budget. Presets with no face budget get one, and first captures
 * split too (one probe a frame): a change of preset makes every probe anew, which in one
 * frame takes a second at final on llvmpipe. A moving view shows a probe still waiting for a
 * frame or two; the still view waits for it (probes_held). */
static void apply_preset(planner *p, int index)
{
    if (p->live.applied == index)
        return;
    const app_quality *q = app_quality_find(ui_quality_names[index]);
    if (!q)
        return;
    app_quality_apply(q, p->scene.scene);
    rd_reflection_defaults d = rd_scene_reflection_defaults(p->scene.scene);
    if (d.update == RD_PROBE_EVERY_FRAME)
        d.update = RD_PROBE_ON_CHANGE;
    if (d.max_faces_per_frame == 0)
        d.max_faces_per_frame = STILL_FACES_PER_FRAME;
    d.split_captures = 1;
    rd_scene_set_reflection_defaults(p->scene.scene, &d);
    p->live.applied = index;
}

/* Everything that changes the picture: a difference from the last frame means moving. */
static void view_key(const planner *p, int fw, int fh, double key[12])
{
    planner_view_points(p, key, key + 3);
    key[6] = fw;
    key[7] = fh;
    key[8] = p->quality;
    key[9] = p->live.serial;
    key[10] = p->camera >= 0 ? p->project.cameras[p->camera].fov_deg : 60.0;
    key[11] = p->project.render.exposure_ev;
}

/* The frame without its 3D view (the panels, the present, the swap), smoothed: frame_ms[n - 1]
 * holds the length of frame n - 2 (the time between its start and the next), render_ms[n - 2]
 * its 3D view. */
static void learn_rest(planner *p)
{
    long n = p->frame_count;
    if (n < 2)
        return;
    float rest = p->frame_ms[(n - 1) % UI_FRAME_HISTORY] - p->render_ms[(n - 2) % UI_FRAME_HISTORY];
    if (rest > 0 && rest < 1000)
        p->live.rest_ms =
            p->live.rest_ms > 0 ? p->live.rest_ms + 0.2f * (rest - p->live.rest_ms) : rest;
}

/* Moves the render scale towards the frame budget: the 3D view gets what the rest of the frame
 * leaves of it (at least half), and its cost is close to proportional to its pixels on
 * llvmpipe. */
static void adapt_scale(planner *p, float render_ms)
{
    if (render_ms <= 0)
        return;
    float want = p->live.rest_ms > 0 ? p->budget_ms * 0.98f - p->live.rest_ms : p->budget_ms * 0.8f;
    want = want < p->budget_ms * 0.5f ? p->budget_ms * 0.5f : want;
    float s = p->render_scale * sqrtf(want / render_ms);
    s = p->render_scale + 0.3f * (s - p->render_scale); /* damped: no flicker */
    p->render_scale = s < SCALE_FLOOR ? SCALE_FLOOR : s > 1.0f ? 1.0f : s;
}

static int render_failed(void)
{
    fprintf(stderr, "tessera: rendering the 3D view failed: %s\n", rd_last_error());
    return 1;
}

/* The last render into the 3D view's pane. */
static rd_result present_view(planner *p)
{
    const ui_rect *r = &p->live.pane;
    return rd_present_rect(p->ctx, p->live.window_w, p->live.window_h, (int)r->x, (int)r->y,
                           (int)r->w, (int)r->h);
}

/* live: the view moves (a session's first frame does not: it draws with the still view's
 * programs, so that a cold start compiles one set; the shader warm-up compiles the moving
 * frames' before the first move, shader_warmup.c). */
static int moving_frame(planner *p, int fw, int fh, int live, float *render_ms, int *rw, int *rh)
{
    ui_still_render_cancel(&p->live.still_render); /* its picture is of the view that was */
    learn_rest(p);
    apply_preset(p, ui_live_moving_preset(p->quality));
    /* A probe coming into view while the view moves is captured a few faces a frame, its blur
     * in a frame of its own (split 2): whole, with its blur, it took a moving frame over
     * 100 ms. Meanwhile it is drawn unfinished, which motion hides. */
    rd_scene_set_capture_budget(p->scene.scene, MOVING_FACES_PER_FRAME, 2);
    rd_scene_set_capture_time(p->scene.scene, MOVING_CAPTURE_MS);
    /* Back from a still: start at the scale the last moving frames held. */
    if (p->live.still && p->live.last_w > 0)
        p->render_scale = (float)p->live.last_w / (float)fw;
    p->live.still = 0;
    *rw = (int)lroundf((float)fw * p->render_scale);
    *rh = (int)lroundf((float)fh * p->render_scale);
    *rw = *rw < 1 ? 1 : *rw;
    *rh = *rh < 1 ? 1 : *rh;
    rd_view v;
    planner_view(p, *rw, *rh, &v);
    v.supersample = 1;
    v.live = live; /* cheaper where motion hides it; the still view renders exactly */
    double t0 = glfwGetTime();
    if (rd_render(p->ctx, p->scene.scene, &v) != RD_OK)
        return render_failed();
    p->live.view_ev = rd_last_frame_stats(p->ctx).exposure_ev;
    /* Kept for the still view's first picture: by the time the view stops, the context's
     * last render may be a catalog thumbnail. Read before the present: the readback binds
     * the render's own framebuffer, the present binds the window again for the panels. */
    size_t size = (size_t)*rw * (size_t)*rh * 4;
    if (size > p->live.last_size) {
        free(p->live.last);
        p->live.last = malloc(size);
        p->live.last_size = p->live.last ? size : 0;
    }
    if (p->live.last && rd_read_rgba8(p->ctx, p->live.last, size) != RD_OK)
        return render_failed();
    if (present_view(p) != RD_OK)
        return render_failed();
    *render_ms = (float)((glfwGetTime() - t0) * 1e3);
    p->live.last_w = *rw;
    p->live.last_h = *rh;
    p->live.last_ms = *render_ms;
    adapt_scale(p, *render_ms);
    return 0;
}

static int in_window_climb(void)
{
    const char *v = getenv("TESSERA_STILL_RENDER");
    return v && !strcmp(v, "window");
}

/* The ladder towards the chosen preset, whose final and print steps render in the background
 * (or in the window's strips, TESSERA_STILL_RENDER=window). */
static void begin_ladder(planner *p, float ms_per_row)
{
    ui_still_render_cancel(&p->live.still_render);
    if (in_window_climb())
        ui_live_begin(&p->live.ladder, p->quality, ms_per_row);
    else
        ui_live_begin_background(&p->live.ladder, p->quality, ms_per_row);
}

/* The view has just stopped: the still image starts as the last moving frame, scaled up. Its
 * first strip's rows are guessed from the moving frames' cost, which a still row exceeds
 * (moving frames light with rectangle lights as points, textures without anisotropy: about
 * 1.45 times cheaper a pixel, docs/benchmarks.md "What an interactive frame's pixels cost"), and
 * the first strip pays for what the moving frames left (probes sized for the still view). */
#define STILL_ROW_COST 2.0f
static int begin_still(planner *p, int fw, int fh)
{
    p->live.still = 1;
    float rows = p->live.last_h > 0 ? (float)p->live.last_h : (float)fh;
    float px_scale = p->live.last_w > 0 ? (float)fw / (float)p->live.last_w : 1.0f;
    begin_ladder(p, p->live.last_ms / rows * px_scale * STILL_ROW_COST);
    if (ui_accum_resize(&p->live.accum, fw, fh)) {
        fprintf(stderr, "tessera: out of memory for the still view\n");
        return 1;
    }
    if (p->live.last)
        ui_accum_start_from(&p->live.accum, p->live.last, p->live.last_w, p->live.last_h);
    else
        ui_accum_restart(&p->live.accum);
    apply_preset(p, p->live.ladder.steps[0].preset);
    p->live.still_ev_ok = 0;
    p->live.shadows_pending = 1;
    return 0;
}

/* The strip budget from the rest of the last measured frames. */
static float strip_budget(planner *p)
{
    learn_rest(p);
    float b = (FRAME_CEILING_MS - p->live.rest_ms) * 0.75f;
    return b > STRIP_BUDGET_MS ? STRIP_BUDGET_MS : b < STRIP_MIN_MS ? STRIP_MIN_MS : b;
}

/* The steps at final and print wait for the shader warm-up (shader_warmup.c): their first
 * strips would compile a dozen shader variants within one frame. Meanwhile the interactive
 * passes stay on screen and the window waits for input as when done. */
static int waits_for_shaders(const planner *p)
{
    const ui_live *l = &p->live.ladder;
    return !ui_live_done(l) && !ui_live_on_background(l) &&
           !planner_warmup_ready(p, l->steps[l->step].preset);
}

/* The still strip's buffer, grown to `size` bytes. 0 ok. */
static int strip_buffer(planner *p, size_t size)
{
    if (size <= p->live.strip_size)
        return 0;
    free(p->live.strip);
    p->live.strip = malloc(size);
    p->live.strip_size = p->live.strip ? size : 0;
    if (p->live.strip)
        return 0;
    fprintf(stderr, "tessera: out of memory for the still view\n");
    return 1;
}

/* A failed background render leaves its steps to the window's strips: slower to come, but
 * the picture is the same preset's. */
static void background_failed(planner *p, const char *err)
{
    ui_live *l = &p->live.ladder;
    fprintf(stderr, "tessera: %s; the window renders it itself\n", err);
    planner_status(p, "%s; the window renders it itself", err);
    int waiting = ui_live_on_background(l); /* else an interactive pass goes on as it was */
    for (int i = l->step; i < l->step_count; i++)
        l->steps[i].background = 0;
    if (waiting) {
        apply_preset(p, l->steps[l->step].preset);
        ui_accum_restart(&p->live.accum);
        p->live.still_ev_ok = 0;
        p->live.shadows_pending = 1;
    }
}

/* The ladder's next background step: started as soon as the view stands still and its light
 * has settled (the render reads the window's bake from the cache), polled each frame, its
 * picture shown whole when it comes. Returns 1 on a failure that stops the view. */
static int background_frame(planner *p, int fw, int fh)
{
    ui_live *l = &p->live.ladder;
    ui_still_render *s = &p->live.still_render;
    int index = ui_live_next_background(l);
    if (index < 0)
        return 0;
    char err[1024];
    if (!ui_still_render_busy(s)) {
        if (!planner_bake_settled(p))
            return 0;
        double eye[3], target[3];
        planner_view_points(p, eye, target);
        double fov = p->camera >= 0 ? p->project.cameras[p->camera].fov_deg : 60.0;
        int preset = l->steps[index].preset;
        if (strip_buffer(p, (size_t)fw * (size_t)fh * 4))
            return 1;
        if (ui_still_render_start(s, &p->project, eye, target, fov, preset,
                                  ui_quality_names[preset], fw, fh, p->bake != NULL,
                                  glfwPostEmptyEvent, err, sizeof err)) {
            background_failed(p, err);
            return 0;
        }
        p->live.background_step = index;
        return 0;
    }
    l->background_fraction = ui_still_render_fraction(s);
    int r = ui_still_render_poll(s, p->live.strip, err, sizeof err);
    if (r < 0) {
        background_failed(p, err);
    } else if (r > 0) {
        fprintf(stderr, "tessera: still view at %s: rendered beside the window\n",
                ui_quality_names[l->steps[p->live.background_step].preset]);
        ui_accum_start_from(&p->live.accum, p->live.strip, fw, fh);
        ui_live_background_done(l, p->live.background_step);
    }
    return 0;
}

/* A step's new shadow settings remake every light's maps (final's soft shadows: five lights,
 * four of them cubes of six faces; print's at 2048 texels), a second or two in one go on
 * llvmpipe. So before a step's first strip its maps are made a face at a time, as many faces
 * a frame as fit the strip's budget (at least one), while the last step's picture stays on
 * screen; the maps come out the same as made at once (rd_scene_prepare_shadows). Returns the
 * milliseconds spent, -1 on failure. */
static float prepare_shadows(planner *p, float budget_ms)
{
    if (!p->live.shadows_pending)
        return 0.0f;
    if (rd_scene_shadows(p->scene.scene).mode == RD_SHADOWS_OFF) {
        p->live.shadows_pending = 0; /* no maps: the step's exposure may take this frame */
        p->live.shadow_faces_left = 0;
        return 0.0f;
    }
    double t0 = glfwGetTime(), face_ms = 0.0;
    int left = 0;
    do {
        double t = glfwGetTime();
        if (rd_scene_prepare_shadows(p->ctx, p->scene.scene, 1, &left) != RD_OK)
            return -1.0f;
        face_ms = (glfwGetTime() - t) * 1e3;
    } while (left > 0 && (glfwGetTime() - t0) * 1e3 + face_ms <= budget_ms);
    p->live.shadow_faces_left = left;
    p->live.shadows_pending = left > 0;
    return (float)((glfwGetTime() - t0) * 1e3);
}

/* The probe captures a strip (or a step's exposure render) may make: what the time left after
 * its rows holds, at the renderer's prediction of each face's cost by its texels, at least one
 * face, at most SPLIT_MAX_FACES. A probe's first capture is split by faces and its blur waits
 * for a frame with room for it (split_captures 2), so no frame captures a whole probe of six
 * faces and prefilters it when faces are dear (256 texels: 16-24 ms a face on llvmpipe, 64
 * texels: about 2). */
static void set_face_budget(planner *p, float budget_ms)
{
    rd_scene_set_capture_budget(p->scene.scene, SPLIT_MAX_FACES, 2);
    rd_scene_set_capture_time(p->scene.scene, budget_ms > 1.0f ? budget_ms : 1.0f);
}

/* What a step needs before its first strip, each in frames of its own: its shadow maps (a
 * few faces a frame), then the exposure of the whole view at its settings (a small render of
 * its own, which captures the SH9 ambient and a probe). Returns 1 when this frame went to
 * them, 0 when the strip may follow, -1 on failure; *spent_ms gets their time. */
static int prepare_step(planner *p, int fw, int fh, float budget_ms, float *spent_ms)
{
    *spent_ms = prepare_shadows(p, budget_ms);
    if (*spent_ms < 0.0f)
        return -1;
    /* A strip waits for the maps, and for a frame of its own when they took most of this one. */
    if (p->live.shadows_pending || budget_ms - *spent_ms < STRIP_MIN_MS)
        return 1;
    if (p->live.still_ev_ok)
        return 0;
    /* One exposure for the whole picture: a strip that metered itself would expose the bright
     * ceiling's rows darker than the floor's, and the still would show bands. */
    rd_view v;
    planner_view(p, fw, fh, &v);
    v.keep_probes = 1; /* else the probes are made anew for the strips, each time */
    set_face_budget(p, (budget_ms - *spent_ms) * 0.5f); /* the other half for its own render */
    double t0 = glfwGetTime();
    if (rd_measure_view_exposure(p->ctx, p->scene.scene, &v, &p->live.still_ev) != RD_OK)
        return -1;
    p->live.still_ev_ok = 1;
    p->live.view_ev = p->live.still_ev; /* this frame's render: the frame log's exposure */
    /* Probes it left waiting would make the first strip's rows a waste (a strip is drawn again
     * while a probe in the picture waits): that strip takes the fewest rows, as after a busy
     * strip, and leaves its frame to the captures. */
    p->live.ladder.settling = rd_last_frame_stats(p->ctx).probes_held > 0;
    *spent_ms += (float)((glfwGetTime() - t0) * 1e3);
    return 1;
}

static int still_frame(planner *p, int fw, int fh, float *render_ms, int *rw, int *rh)
{
    ui_live *l = &p->live.ladder;
    *rw = fw;
    *rh = fh;
    p->render_scale = 1.0f;
    float budget = 0.0f, spent_ms = 0.0f;
    int busy_frame = 0;
    if (background_frame(p, fw, fh))
        return 1;
    int strips = !ui_live_done(l) && !ui_live_on_background(l) && !waits_for_shaders(p);
    if (strips) {
        budget = strip_budget(p);
        busy_frame = prepare_step(p, fw, fh, budget, &spent_ms);
        if (busy_frame < 0)
            return render_failed();
        *render_ms = spent_ms;
    }
    if (strips && !busy_frame) {
        int rows = ui_live_strip_rows(l, budget - spent_ms, fh);
        size_t size = (size_t)fw * (size_t)rows * 4;
        if (strip_buffer(p, size))
            return 1;
        rd_view v;
        planner_view(p, fw, rows, &v);
        v.supersample = 1;
        v.adaptive = 0;
        v.crop_x = 0;
        v.crop_y = l->row;
        v.full_width = fw;
        v.full_height = fh;
        ui_jitter(l->pass, v.jitter);
        v.exposure_ev = p->live.still_ev;
        v.auto_exposure = 0;
        set_face_budget(p, budget - spent_ms - l->ms_per_row * (float)rows);
        double t0 = glfwGetTime();
        if (rd_render(p->ctx, p->scene.scene, &v) != RD_OK ||
            rd_read_rgba8(p->ctx, p->live.strip, size) != RD_OK)
            return render_failed();
        rd_frame_stats st = rd_last_frame_stats(p->ctx);
        p->live.view_ev = st.exposure_ev;
        int busy = st.probes_held > 0;
        if (!busy)
            ui_accum_add(&p->live.accum, 0, l->row, fw, rows, p->live.strip);
        float strip_ms = (float)((glfwGetTime() - t0) * 1e3);
        *render_ms = spent_ms + strip_ms;
        /* A row's cost is learnt from strips that captured nothing: a thin strip's captures
         * spread over its few rows would make the next strips thin as well. */
        if (ui_live_strip_done(l, rows, st.faces_captured ? 0.0f : strip_ms, fh, busy) &&
            !ui_live_on_background(l)) {
            apply_preset(p, l->steps[l->step].preset);
            ui_accum_restart(&p->live.accum);
            p->live.still_ev_ok = 0; /* the new preset's light: measured again */
            p->live.shadows_pending = 1;
        }
    }
    const unsigned char *shown = planner_bake_fade(p, p->live.accum.image, fw, fh);
    if (rd_present_rgba8(p->ctx, fw, fh, shown, p->live.window_w, p->live.window_h,
                         (int)p->live.pane.x, (int)p->live.pane.y) != RD_OK)
        return render_failed();
    return 0;
}

/* The 3D view's first two frames leave its pane dark: the first is the panels' first layout,
 * the second makes the scene's SH9 ambient light (about 90 ms on llvmpipe in the designed demo),
 * each a frame of its own instead of the first picture's; the view's first render follows. */
static int opening_frame(planner *p, int window_w, int window_h, ui_rect pane, float *render_ms)
{
    static const unsigned char dark[4] = {26, 26, 28, 255}; /* the window's clear colour */
    if (p->live.opening++ == 1) {
        apply_preset(p, ui_live_moving_preset(p->quality));
        double t0 = glfwGetTime();
        if (rd_scene_prepare_ambient(p->ctx, p->scene.scene) != RD_OK)
            return render_failed();
        *render_ms = (float)((glfwGetTime() - t0) * 1e3);
    }
    if (rd_present_rgba8(p->ctx, 1, 1, dark, window_w, window_h, (int)pane.x, (int)pane.y) != RD_OK)
        return render_failed();
    return 0;
}

int planner_live_frame(planner *p, int window_w, int window_h, ui_rect pane, float *render_ms,
                       int *rw, int *rh)
{
    *render_ms = 0;
    p->live.window_w = window_w;
    p->live.window_h = window_h;
    p->live.pane = pane;
    if (p->live.opening < 2)
        return opening_frame(p, window_w, window_h, pane, render_ms);
    int fw = (int)pane.w, fh = (int)pane.h; /* the view's pixels */
    double key[12];
    view_key(p, fw, fh, key);
    int moving = memcmp(key, p->live.key, sizeof key) != 0 || p->fixture_drag.active;
    memcpy(p->live.key, key, sizeof key);
    if (moving)
        planner_bake_fade_stop(p); /* the old picture no longer matches the view */
    if (moving || p->live.last_w == 0)
        return moving_frame(p, fw, fh, moving, render_ms, rw, rh);
    if (!p->live.still && begin_still(p, fw, fh))
        return 1;
    return still_frame(p, fw, fh, render_ms, rw, rh);
}

void planner_live_overlay(planner *p, ui_rect pane)
{
    if (!p->live.still || ui_live_done(&p->live.ladder))
        return;
    const ui_live *l = &p->live.ladder;
    const char *preset = ui_quality_names[l->steps[l->step].preset];
    if (ui_gui_begin_overlay("##refining", pane.x + 12.0f, pane.y + pane.h - 40.0f, 0.5f)) {
        if (ui_live_on_background(l) && !ui_still_render_busy(&p->live.still_render))
            ui_gui_text("refining to %s: %.0f %% (%s, waiting for the baked light)",
                        ui_quality_names[p->quality], 100.0f * ui_live_progress(l), preset);
        else if (ui_live_on_background(l))
            ui_gui_text("refining to %s: %.0f %% (%s, rendered beside the window: %.1f s)",
                        ui_quality_names[p->quality], 100.0f * ui_live_progress(l), preset,
                        ui_still_render_elapsed(&p->live.still_render));
        else if (waits_for_shaders(p))
            ui_gui_text("refining to %s: %.0f %% (preparing the %s shaders)",
                        ui_quality_names[p->quality], 100.0f * ui_live_progress(l), preset);
        else if (p->live.shadows_pending)
            ui_gui_text("refining to %s: %.0f %% (%s shadow maps, %d faces to go)",
                        ui_quality_names[p->quality], 100.0f * ui_live_progress(l), preset,
                        p->live.shadow_faces_left);
        else
            ui_gui_text("refining to %s: %.0f %% (%s pass %d of %d)%s",
                        ui_quality_names[p->quality], 100.0f * ui_live_progress(l), preset,
                        l->pass + 1, l->steps[l->step].passes, l->settling ? ", probes" : "");
    }
    ui_gui_end();
}

int planner_live_idle(const planner *p)
{
    /* A bake under way is no reason to draw: the status bar's share is redrawn when the wait
     * times out, and the worker wakes the window when the light is there. A crossfade is. */
    /* Nor is a background render: the wait's timeout polls it (and redraws its progress). */
    return p->layout.pane_3d.w > 0 && p->live.still &&
           (ui_live_done(&p->live.ladder) || waits_for_shaders(p) ||
            ui_live_on_background(&p->live.ladder)) &&
           !planner_bake_fading(p);
}

void planner_live_restart(planner *p)
{
    if (!p->live.still)
        return; /* a moving view draws the new light on its next frame */
    float rows = p->live.last_h > 0 ? (float)p->live.last_h : 1.0f;
    float px_scale = p->live.last_w > 0 && p->live.accum.width > 0
                         ? (float)p->live.accum.width / (float)p->live.last_w
                         : 1.0f;
    begin_ladder(p, p->live.last_ms / rows * px_scale);
    ui_accum_restart(&p->live.accum); /* shows the old picture until strips replace it */
    apply_preset(p, p->live.ladder.steps[0].preset);
    p->live.shadows_pending = 1;
}

void planner_live_free(planner *p)
{
    ui_still_render_stop(&p->live.still_render);
    ui_accum_free(&p->live.accum);
    free(p->live.strip);
    free(p->live.last);
    p->live.strip = p->live.last = NULL;
    p->live.strip_size = p->live.last_size = 0;
}
