/* The planner window: GLFW makes the window and its OpenGL context, the renderer adopts that
 * context, Dear ImGui draws the panels on top of the 3D view. */
#include "planner.h"
#include "planner_actions.h"

#include "app/project/commands.h"
#include "app/scene/scene_bake.h"
#include "gui.h"
#include "render/ui_texture.h"

#include <GLFW/glfw3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

const char *const ui_quality_names[4] = {"draft", "interactive", "final", "print"};

/* Closing with unsaved changes asks first (the panel in planner_panels.c). */
static void on_close(GLFWwindow *w)
{
    planner *p = glfwGetWindowUserPointer(w);
    if (p && p->dirty) {
        glfwSetWindowShouldClose(w, GLFW_FALSE);
        p->close_requested = 1;
    }
}

static void glfw_error(int code, const char *text)
{
    fprintf(stderr, "tessera: window system error 0x%x: %s\n", code, text);
}

void planner_set_quality(planner *p, int index)
{
    if (index < 0 || index > 3)
        return;
    p->quality = index;
    /* The moving view renders at the live preset and fewer pixels to keep the frame budget;
     * the chosen preset is what the still view is refined to (planner_live.c). */
    p->budget_ms = index == 0 ? 25.0f : 1000.0f / 30.0f;
    p->adaptive_scale = 1;
    p->live.applied = -1; /* a rebuilt scene holds the renderer's defaults */
    p->live.serial++;
}

void planner_jump_to_camera(planner *p, int index)
{
    if (index < 0 || index >= p->project.camera_count)
        return;
    const app_camera *c = &p->project.cameras[index];
    p->camera = index;
    p->mode = UI_MODE_ORBIT;
    p->flight.active = 0;
    p->orbit = ui_orbit_from_view(c->position_mm, c->target_mm);
}

const app_room_plan *planner_plan(const planner *p, app_point2 box[4], app_room_plan *fallback)
{
    if (p->project.plan.corner_count >= 3)
        return &p->project.plan;
    /* Until a project carries its version 2 plan, its room box is the plan. */
    const app_room *r = &p->project.room;
    box[0] = (app_point2){0, 0};
    box[1] = (app_point2){r->width_mm, 0};
    box[2] = (app_point2){r->width_mm, r->depth_mm};
    box[3] = (app_point2){0, r->depth_mm};
    *fallback = (app_room_plan){.corners = box, .corner_count = 4, .height_mm = r->height_mm};
    return fallback;
}

void planner_view(const planner *p, int width, int height, rd_view *v)
{
    double eye[3], target[3];
    planner_view_points(p, eye, target);
    memset(v, 0, sizeof *v);
    for (int k = 0; k < 3; k++) {
        v->eye[k] = (float)(eye[k] * 1e-3);
        v->target[k] = (float)(target[k] * 1e-3);
    }
    v->up[2] = 1;
    v->fov_y_deg = p->camera >= 0 ? (float)p->project.cameras[p->camera].fov_deg : 60.0f;
    v->width = width;
    v->height = height;
    v->exposure_ev = p->project.render.exposure_ev;
    v->white = p->project.render.white;
    v->auto_exposure = p->project.render.exposure_auto;
    v->tonemap = app_tone_to_rd(p->project.render.tone);
    v->white_balance_k = p->project.render.white_balance_k;
    const app_quality *q = app_quality_find(ui_quality_names[p->quality]);
    v->supersample = q && q->supersample > 1 ? q->supersample : 1;
}

static int open_project(planner *p, const ui_options *o)
{
    char err[1024];
    char demo[1024];
    const char *path = o->project;
    if (!path) {
        snprintf(demo, sizeof demo, "%s/assets/projects/designed-bathroom.json",
                 TESSERA_SOURCE_DIR);
        path = demo;
    }
    if (app_project_read(path, &p->project, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return 1;
    }
    /* The baked indirect light, as the CLI renders it (TESSERA_BAKE=off: the plain ambient).
     * Cached: an edit re-bakes only what lies within reach of what it changed. */
    const char *bake_env = getenv("TESSERA_BAKE");
    app_bake_configure(
        &(app_bake_settings){.on = !(bake_env && !strcmp(bake_env, "off")), .progress = 1});
    /* The window bakes on a thread of its own and draws the plain ambient until the first
     * light arrives (from the cache at once when the scene is unchanged). */
    if (planner_bake_start(p))
        return 1;
    if (planner_scene_build(p, err, sizeof err)) {
        fprintf(stderr, "tessera: %s\n", err);
        return 1;
    }
    p->scene_ready = 1;
    app_point2 box[4];
    app_room_plan fallback;
    const app_room_plan *plan = planner_plan(p, box, &fallback);
    p->orbit = ui_orbit_framing(plan);
    p->walk = ui_walk_start(plan);
    p->camera = -1;
    if (p->project.camera_count > 0)
        planner_jump_to_camera(p, 0);
    return 0;
}

/* Work done in the frame (a render target made for a preset, an edit's scene rebuild, a
 * thumbnail) may leave its own framebuffer bound: the panels are drawn into the window
 * whatever came before, and each such frame is logged with the stage that left it. */
static void window_target(planner *p, const char *after, int width, int height)
{
    unsigned stray = rd_draw_framebuffer(p->ctx);
    if (!stray)
        return;
    p->stray_target_frames++;
    fprintf(stderr, "tessera: gui: frame %ld: framebuffer %u bound after %s, not the window\n",
            p->frame_count, stray, after);
    rd_bind_window(p->ctx, width, height);
}

static double thread_cpu_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int frame(planner *p)
{
    int fw, fh;
    glfwGetFramebufferSize(p->window, &fw, &fh);
    if (fw <= 0 || fh <= 0) {
        glfwWaitEventsTimeout(0.1); /* minimised */
        return 0;
    }
    double now = glfwGetTime();
    double dt = now - p->last_time;
    p->last_time = now;
    /* The window thread's own work in the last frame: a frame can be long on a loaded machine
     * while it did little (the bake's threads and other programs take the cores). */
    double cpu = thread_cpu_seconds(), cpu_dt = cpu - p->last_cpu;
    p->last_cpu = cpu;
    planner_layout_frame(p, fw, fh); /* window_panes.c: the panes for this size */
    planner_handle_input(p, dt);
    planner_bake_frame(p); /* a finished bake swapped in before this frame draws */
    planner_warmup_frame(p);
    planner_animate(p, p->fixed_dt > 0 ? p->fixed_dt : dt);
    planner_camera_sync(p);

    /* The 3D view fills its pane (the whole window while presenting): moving frames at a
     * reduced scale, then the still view refined (planner_live.c). */
    ui_rect pane = planner_view_rect(p);
    int vw = (int)pane.w, vh = (int)pane.h;
    int rw = 0, rh = 0;
    float render_ms = 0;
    if (vw > 0 && vh > 0 && p->scene_ready &&
        planner_live_frame(p, fw, fh, pane, &render_ms, &rw, &rh))
        return 1;

    p->view_ms_now = render_ms; /* the panels' thumbnails wait for a cheaper frame */
    window_target(p, "the 3D view", fw, fh);
    ui_gui_new_frame();
    if (p->presenting) {
        planner_draw_presentation(p, fw, fh);
    } else {
        if (p->layout.pane_2d.w > 0 && p->view_2d == UI_VIEW_ELEVATION)
            planner_elevation_frame(p, fw, fh);
        else if (p->layout.pane_2d.w > 0)
            planner_plan_frame(p, fw, fh);
        if (vw > 0)
            planner_selection_3d(p);
        if (vw > 0)
            planner_handles_3d(p);
        if (vw > 0)
            planner_snap_guides_3d(p);
        if (vw > 0)
            planner_findings_3d(p, fw, fh);
        if (vw > 0)
            planner_live_overlay(p, pane);
        planner_draw_panels(p, fw, fh);
        planner_status_bar(p, now);
    }
    planner_files_frame(p, fw, fh, dt); /* dialogs and the job panel, presenting or not */
    planner_autosave_tick(p, now);
    planner_heap_log_tick(p, now);
    window_target(p, "the panels", fw, fh);
    ui_gui_render();
    planner_gl_check_frame();
    if (p->script.count && planner_script_step(p))
        return 1;
    glfwSwapBuffers(p->window);

    int i = (int)(p->frame_count % UI_FRAME_HISTORY);
    p->frame_ms[i] = (float)(dt * 1e3);
    p->render_ms[i] = render_ms;
    if (p->frame_log && p->frame_count > 0) {
        double eye[3], target[3];
        planner_view_points(p, eye, target);
        fprintf(p->frame_log,
                "%ld,%s,%s,%.3f,%.3f,%.3f,%d,%d,%s,%.3f,%.0f,%.0f,%.0f,%.3f,%.4f,%.3f\n",
                p->frame_count, ui_quality_names[p->quality],
                p->dragging                ? "drag"
                : planner_job_running(p)   ? "job"
                : !planner_bake_settled(p) ? "bake"
                                           : "idle",
                dt * 1e3, render_ms, p->render_scale, rw, rh,
                !p->live.still                  ? "moving"
                : ui_live_done(&p->live.ladder) ? "still"
                                                : "refining",
                p->live.still ? ui_live_progress(&p->live.ladder) : 0.0f, eye[0], eye[1], eye[2],
                cpu_dt * 1e3, p->live.view_ev, p->waited_s * 1e3);
    }
    p->frame_count++;
    return 0;
}

int ui_run(const ui_options *o)
{
    planner p;
    memset(&p, 0, sizeof p);
    p.render_scale = 1.0f;
    p.live.applied = -1;
    p.exit_code = 0;
    char err[1024];
    p.fixed_dt = o->script ? 1.0 / 30.0 : 0.0;
    if (o->script && ui_script_read(o->script, &p.script, err, sizeof err)) {
        fprintf(stderr, "tessera: %s\n", err);
        return 2;
    }
    if (o->frame_log) {
        p.frame_log = fopen(o->frame_log, "w");
        if (!p.frame_log) {
            fprintf(stderr, "tessera: %s: cannot write the frame log\n", o->frame_log);
            ui_script_free(&p.script);
            return 1;
        }
        fprintf(p.frame_log, "frame,quality,state,frame_ms,render_ms,render_scale,width,height,"
                             "live,progress,eye_x,eye_y,eye_z,cpu_ms,exposure_ev,wait_ms\n");
    }
    glfwSetErrorCallback(glfw_error);
    if (!glfwInit()) {
        fprintf(stderr, "tessera: the window system did not start (is the display reachable?)\n");
        ui_script_free(&p.script);
        return 1;
    }
    ui_context_hints();
    int w = o->width > 0 ? o->width : 1280, h = o->height > 0 ? o->height : 720;
    GLFWmonitor *mon = o->fullscreen ? glfwGetPrimaryMonitor() : NULL;
    if (mon) {
        const GLFWvidmode *mode = glfwGetVideoMode(mon);
        w = mode->width;
        h = mode->height;
    }
    /* Shown after its first frame: that frame builds the GL state every later one reuses (the
     * panels' font atlas and program, the present's blit), about 160 ms on llvmpipe, part of
     * opening the window rather than a frame the user waits on. */
    glfwWindowHint(GLFW_VISIBLE, mon ? GLFW_TRUE : GLFW_FALSE);
    p.window = glfwCreateWindow(w, h, "Tessera", mon, NULL);
    int rc = 1;
    if (!p.window) {
        fprintf(stderr, "tessera: cannot open a %dx%d window with OpenGL 3.3\n", w, h);
        goto done;
    }
    glfwMakeContextCurrent(p.window);
    glfwSwapInterval(0); /* measured frame times are the renderer's, not the display's */
    planner_gl_check_start();
    glfwSetWindowUserPointer(p.window, &p);
    glfwSetWindowCloseCallback(p.window, on_close);
    if (rd_context_create(
            &(rd_context_desc){.backend = RD_BACKEND_ADOPT, .get_proc_address = ui_gl_proc},
            &p.ctx) != RD_OK) {
        fprintf(stderr, "tessera: the renderer cannot use the window's OpenGL: %s\n",
                rd_last_error());
        goto done;
    }
    if (ui_gui_init(p.window, err, sizeof err)) {
        fprintf(stderr, "tessera: %s\n", err);
        goto done;
    }
    p.plan_o.selected_object = p.plan_o.selected_wall = -1;
    p.plan_o.hover_corner = p.plan_o.drag_corner = p.plan_o.drag_object = -1;
    if (open_project(&p, o) || planner_doc_open(&p))
        goto done;
    p.recovery_offered = !p.read_only && planner_recovery_available(&p);
    p.objects_at_open = p.project.object_count;
    ui_catalog_browser_open(&p.browser);
    int qi = 1;
    for (int i = 0; o->quality && i < 4; i++)
        if (!strcmp(o->quality, ui_quality_names[i]))
            qi = i;
    planner_set_quality(&p, qi);
    p.last_time = glfwGetTime();
    p.last_cpu = thread_cpu_seconds();
    rc = 0;
    while (!p.quit && !glfwWindowShouldClose(p.window)) {
        /* A finished still view waits for input instead of drawing the same frame again (the
         * machine is shared; a script keeps its own pace). */
        double wait_start = glfwGetTime();
        if (planner_live_idle(&p) && (!p.script.count || planner_script_idles(&p)))
            glfwWaitEventsTimeout(0.1);
        else
            glfwPollEvents();
        p.waited_s = glfwGetTime() - wait_start; /* the frame log's wait_ms */
        if (frame(&p)) {
            rc = 1;
            break;
        }
        if (!glfwGetWindowAttrib(p.window, GLFW_VISIBLE))
            glfwShowWindow(p.window);
        if (p.script.count && p.action >= p.script.count)
            break;
    }
    if (!rc)
        rc = p.exit_code;
done:
    planner_warmup_stop(&p);
    planner_bake_free(&p); /* stops a running bake first */
    planner_files_free(&p);
    planner_doc_close(&p);
    planner_tiles_free(&p);
    planner_live_free(&p);
    ui_catalog_browser_close(&p.browser);
    ui_gui_shutdown();
    if (p.scene_ready)
        app_scene_release(p.ctx, &p.scene);
    if (p.ctx)
        rd_context_destroy(p.ctx);
    if (p.window && planner_gl_check_finish(p.frame_count) && rc == 0)
        rc = 1;
    app_project_free_all(&p.project);
    if (p.window)
        glfwDestroyWindow(p.window);
    glfwTerminate();
    ui_script_free(&p.script);
    if (p.frame_log)
        fclose(p.frame_log);
    return rc;
}
