/* The window's file and job actions (planner_actions.h): native dialogs, recent files, jobs
 * in a worker with a progress panel, and their script verbs. */
#define _GNU_SOURCE /* realpath, mkdtemp */

#include "planner_actions.h"

#include "file_dialog.h"
#include "gui.h"
#include "planner.h"
#include "planner_files.h"

#include <GLFW/glfw3.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const struct {
    const char *label, *command, *suffix; /* suffix: the result's default name after the stem */
    ui_dialog_kind dialog;
    int is_folder;
} jobs[PLANNER_JOB_KIND_COUNT] = {
    [PLANNER_JOB_PRINT_PDF] = {"Print to PDF", "print", ".pdf", UI_DIALOG_PRINT_PDF, 0},
    [PLANNER_JOB_RENDER_IMAGE] = {"Render at print quality", "render", "-render.png",
                                  UI_DIALOG_SAVE_IMAGE, 0},
    [PLANNER_JOB_SHARE] = {"Share folder", "share", "-share", UI_DIALOG_SAVE_FOLDER, 1},
    [PLANNER_JOB_PANORAMA] = {"360-degree panorama", "panorama", "-panorama.jpg",
                              UI_DIALOG_SAVE_IMAGE, 0},
    [PLANNER_JOB_VIDEO] = {"Video", "video", ".mp4", UI_DIALOG_SAVE_VIDEO, 0},
    [PLANNER_JOB_EXPORT_GLB] = {"Export GLB", "export-glb", ".glb", UI_DIALOG_EXPORT_GLB, 0},
};

/* The camera a job renders the window's view through (render, panorama). */
static const char view_camera[] = "window view";

planner_files *planner_files_get(planner *p)
{
    if (!p->files)
        p->files = calloc(1, sizeof *p->files);
    return p->files;
}

const ui_recent *planner_recent_files(planner *p)
{
    planner_files *f = planner_files_get(p);
    if (!f)
        return NULL;
    if (!f->recent_loaded) {
        char file[1100];
        f->recent_loaded = 1;
        if (ui_recent_file(file, sizeof file) || ui_recent_load(&f->recent, file))
            fprintf(stderr, "tessera: the recent files cannot be read (%s)\n", file);
    }
    return &f->recent;
}

void planner_recent_note(planner *p, const char *path)
{
    planner_files *f = planner_files_get(p);
    char abs[PATH_MAX], file[1100], err[1200];
    if (!f || !planner_recent_files(p) || !path || !*path)
        return;
    ui_recent_add(&f->recent, realpath(path, abs) ? abs : path);
    if (ui_recent_file(file, sizeof file) || ui_recent_save(&f->recent, file, err, sizeof err))
        fprintf(stderr, "tessera: the recent files cannot be written: %s\n",
                ui_recent_file(file, sizeof file) ? file : err);
}

int planner_job_running(const planner *p)
{
    return p->files && p->files->job;
}

/* The default name of a result: the project's file without .json, then the suffix, in the
 * project's folder (an untitled project: the working folder). */
static void default_output(const planner *p, const char *suffix, char *out, size_t size)
{
    const char *path = p->project.path[0] ? p->project.path : "untitled.json";
    size_t n = strlen(path);
    if (n > 5 && !strcmp(path + n - 5, ".json"))
        n -= 5;
    snprintf(out, size, "%.*s%s", (int)n, path, suffix);
}

static void act(planner *p, int use, const char *path)
{
    if (use == USE_OPEN)
        planner_action_open_to(p, path);
    else if (use == USE_SAVE_AS)
        planner_action_save_as_to(p, path);
    else
        planner_action_job_to(p, (planner_job_kind)(use - USE_JOB), path);
}

int planner_files_choose(planner *p, int use)
{
    planner_files *f = planner_files_get(p);
    if (!f)
        return 1;
    if (f->dialog_open || f->prompt_open) {
        planner_status(p, "a file dialog is already open");
        return 1;
    }
    ui_dialog_kind kind = use == USE_OPEN      ? UI_DIALOG_OPEN_PROJECT
                          : use == USE_SAVE_AS ? UI_DIALOG_SAVE_PROJECT
                                               : jobs[use - USE_JOB].dialog;
    char suggested[1100], err[256];
    if (use == USE_OPEN)
        default_output(p, "", suggested, sizeof suggested);
    else if (use == USE_SAVE_AS)
        default_output(p, ".json", suggested, sizeof suggested);
    else
        default_output(p, jobs[use - USE_JOB].suffix, suggested, sizeof suggested);
    if (use == USE_OPEN) { /* the project's folder */
        char *slash = strrchr(suggested, '/');
        if (slash)
            *slash = 0;
        else
            snprintf(suggested, sizeof suggested, ".");
    }
    if (ui_file_dialog_start(kind, suggested, err, sizeof err) == 0) {
        f->dialog_open = 1;
        f->dialog_use = use;
        return 0;
    }
    fprintf(stderr, "tessera: %s; asking for a typed path\n", err);
    f->prompt_open = 1;
    f->prompt_use = use;
    snprintf(f->prompt_path, sizeof f->prompt_path, "%s", use == USE_OPEN ? "" : suggested);
    return 0;
}

int planner_action_open_dialog(planner *p)
{
    return planner_files_choose(p, USE_OPEN);
}
int planner_action_save_as(planner *p)
{
    return planner_files_choose(p, USE_SAVE_AS);
}
int planner_action_export_glb(planner *p)
{
    return planner_files_choose(p, USE_JOB + PLANNER_JOB_EXPORT_GLB);
}
int planner_action_print_pdf(planner *p)
{
    return planner_files_choose(p, USE_JOB + PLANNER_JOB_PRINT_PDF);
}
int planner_action_share(planner *p)
{
    return planner_files_choose(p, USE_JOB + PLANNER_JOB_SHARE);
}
int planner_action_panorama(planner *p)
{
    return planner_files_choose(p, USE_JOB + PLANNER_JOB_PANORAMA);
}
int planner_action_video(planner *p)
{
    return planner_files_choose(p, USE_JOB + PLANNER_JOB_VIDEO);
}
int planner_action_render_image(planner *p)
{
    return planner_files_choose(p, USE_JOB + PLANNER_JOB_RENDER_IMAGE);
}

int planner_action_open_to(planner *p, const char *path)
{
    if (p->dirty) { /* the unsaved-changes prompt (planner_panels.c) asks, then opens it */
        snprintf(p->file_path, sizeof p->file_path, "%s", path);
        p->file_pending = UI_FILE_OPEN;
        return 0;
    }
    return planner_file_open(p, path);
}

int planner_action_save(planner *p)
{
    return p->project.path[0] ? planner_save(p, NULL) : planner_action_save_as(p);
}

int planner_action_save_as_to(planner *p, const char *path)
{
    return planner_save(p, path);
}

int planner_action_open_recent(planner *p, int index)
{
    const ui_recent *r = planner_recent_files(p);
    if (!r || index < 0 || index >= r->count) {
        planner_status(p, "no recent file %d", index + 1);
        return 1;
    }
    char path[sizeof r->paths[0]];
    memcpy(path, r->paths[index], sizeof path); /* opening reorders the list */
    return planner_action_open_to(p, path);
}

/* The document as it is now, in a folder of its own for the job's command; render and
 * panorama get the window's view as one more camera. 0 ok. */
static int write_job_project(planner *p, planner_job_kind kind, char *out, size_t size)
{
    const char *tmp = getenv("TMPDIR");
    char folder[512], err[1024];
    snprintf(folder, sizeof folder, "%s/tessera-job-XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (!mkdtemp(folder)) {
        planner_status(p, "%s: cannot make a temporary folder", jobs[kind].label);
        return 1;
    }
    snprintf(out, size, "%s/project.json", folder);
    app_project copy = p->project; /* shallow: only its camera list differs */
    app_camera *cams = NULL;
    if (kind == PLANNER_JOB_RENDER_IMAGE || kind == PLANNER_JOB_PANORAMA) {
        cams = malloc((size_t)(copy.camera_count + 1) * sizeof *cams);
        if (!cams) {
            planner_status(p, "%s: out of memory", jobs[kind].label);
            rmdir(folder);
            return 1;
        }
        if (copy.camera_count)
            memcpy(cams, copy.cameras, (size_t)copy.camera_count * sizeof *cams);
        app_camera *c = &cams[copy.camera_count];
        memset(c, 0, sizeof *c);
        snprintf(c->name, sizeof c->name, "%s", view_camera);
        planner_view_points(p, c->position_mm, c->target_mm);
        c->up[2] = 1;
        c->fov_deg = p->camera >= 0 ? p->project.cameras[p->camera].fov_deg : 60.0;
        copy.cameras = cams;
        copy.camera_count++;
    }
    int rc = app_project_write(out, &copy, err, sizeof err) != APP_OK;
    free(cams);
    if (rc) {
        planner_status(p, "%s: %s", jobs[kind].label, err);
        rmdir(folder);
    }
    return rc;
}

int planner_action_job_to(planner *p, planner_job_kind kind, const char *output)
{
    planner_files *f = planner_files_get(p);
    if (!f || kind < 0 || kind >= PLANNER_JOB_KIND_COUNT || !output || !*output)
        return 1;
    if (f->job) {
        planner_status(p, "%s: wait for the running job or cancel it", jobs[kind].label);
        return 1;
    }
    char project[1100], size[32], err[512];
    if (write_job_project(p, kind, project, sizeof project))
        return 1;
    int w = 0, h = 0;
    glfwGetFramebufferSize(p->window, &w, &h);
    snprintf(size, sizeof size, "%dx%d", w > 0 ? 2 * w : 1920, h > 0 ? 2 * h : 1080);
    const char *render_args[] = {"--camera", view_camera, "--quality", "print",
                                 "--size",   size,        NULL};
    const char *panorama_args[] = {"--camera", view_camera, NULL};
    ui_job_desc d = {.label = jobs[kind].label,
                     .command = jobs[kind].command,
                     .project = project,
                     .owns_project = 1,
                     .output = output,
                     .is_folder = jobs[kind].is_folder,
                     .args = kind == PLANNER_JOB_RENDER_IMAGE ? render_args
                             : kind == PLANNER_JOB_PANORAMA   ? panorama_args
                                                              : NULL,
                     .open_result = kind != PLANNER_JOB_EXPORT_GLB};
    f->job = ui_job_start(&d, err, sizeof err);
    if (!f->job) {
        planner_status(p, "%s: %s", jobs[kind].label, err);
        unlink(project);
        *strrchr(project, '/') = 0;
        rmdir(project);
        return 1;
    }
    f->job_kind = kind;
    snprintf(f->job_output, sizeof f->job_output, "%s", output);
    f->longest_ms = 0;
    f->job_frames = 0;
    planner_status(p, "%s: %s (the window stays usable; Esc cancels)", jobs[kind].label, output);
    return 0;
}

void planner_action_cancel_job(planner *p)
{
    if (p->files && p->files->job)
        ui_job_cancel(p->files->job);
}

int planner_action_key(planner *p, int key, int mods)
{
    int ctrl = (mods & GLFW_MOD_CONTROL) != 0, shift = (mods & GLFW_MOD_SHIFT) != 0;
    if (ctrl && key == GLFW_KEY_O)
        planner_action_open_dialog(p);
    else if (ctrl && shift && key == GLFW_KEY_S)
        planner_action_save_as(p);
    else if (ctrl && key == GLFW_KEY_S)
        planner_action_save(p);
    else if (ctrl && key == GLFW_KEY_P)
        planner_action_print_pdf(p);
    else if (ctrl && key == GLFW_KEY_E)
        planner_action_export_glb(p);
    else if (key == GLFW_KEY_ESCAPE && planner_job_running(p))
        planner_action_cancel_job(p);
    else
        return 0;
    return 1;
}

const char *planner_action_shortcut(const char *action)
{
    static const char *const keys[][2] = {
        {"open", "Ctrl+O"},      {"save", "Ctrl+S"},       {"save-as", "Ctrl+Shift+S"},
        {"print-pdf", "Ctrl+P"}, {"export-glb", "Ctrl+E"}, {"cancel-job", "Esc"},
    };
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        if (!strcmp(keys[i][0], action))
            return keys[i][1];
    return "";
}

/* The job's end: its state kept for scripts, the status line says how it went. */
static void job_finished(planner *p, planner_files *f, const ui_job_status *s)
{
    const char *label = jobs[f->job_kind].label;
    f->has_last = 1;
    f->last_state = s->state;
    snprintf(f->last_line, sizeof f->last_line, "%s", s->line);
    if (s->state == UI_JOB_DONE)
        planner_status(p, "%s: %s done in %.1f s (longest frame meanwhile %.0f ms, %ld frames)",
                       label, f->job_output, s->seconds, f->longest_ms, f->job_frames);
    else if (s->state == UI_JOB_CANCELLED)
        planner_status(p, "%s: cancelled after %.1f s (nothing written to %s)", label, s->seconds,
                       f->job_output);
    else
        planner_status(p, "%s failed: %s", label, s->line);
    ui_job_free(f->job);
    f->job = NULL;
}

static void job_panel(planner *p, planner_files *f, int width, int height, double dt)
{
    ui_job_status s;
    ui_job_status_get(f->job, &s);
    if (s.state != UI_JOB_RUNNING) {
        job_finished(p, f, &s);
        return;
    }
    f->job_frames++;
    if (dt * 1e3 > f->longest_ms)
        f->longest_ms = dt * 1e3;
    float w = 420.0f;
    if (ui_gui_begin("Job##jobs", ((float)width - w) / 2, (float)height - 170.0f, w, 130.0f)) {
        ui_gui_text("%s: %s", jobs[f->job_kind].label, f->job_output);
        char text[64];
        if (s.progress >= 0)
            snprintf(text, sizeof text, "%.0f %%", s.progress * 100.0);
        else
            snprintf(text, sizeof text, "working");
        ui_gui_progress_bar(s.progress >= 0 ? (float)s.progress : -1.0f, text);
        ui_gui_text("%.0f s  %.60s", s.seconds, s.line);
        if (ui_gui_button("Cancel (Esc)"))
            ui_job_cancel(f->job);
    }
    ui_gui_end();
}

/* No native dialog: the path typed into a small window (the dialog's fallback). */
static void prompt_panel(planner *p, planner_files *f, int width, int height)
{
    static const char *const titles[] = {"Open project", "Save project as"};
    const char *title =
        f->prompt_use < USE_JOB ? titles[f->prompt_use] : jobs[f->prompt_use - USE_JOB].label;
    char id[96];
    snprintf(id, sizeof id, "%s##path-prompt", title);
    if (ui_gui_begin(id, (float)width / 2 - 260.0f, (float)height / 2 - 50.0f, 520.0f, 100.0f)) {
        ui_gui_text("No file dialog here: type the path.");
        ui_gui_input_text("path", f->prompt_path, sizeof f->prompt_path);
        if (ui_gui_button("OK") && f->prompt_path[0]) {
            f->prompt_open = 0;
            act(p, f->prompt_use, f->prompt_path);
        }
        ui_gui_same_line();
        if (ui_gui_button("Cancel"))
            f->prompt_open = 0;
    }
    ui_gui_end();
}

void planner_files_frame(planner *p, int width, int height, double dt)
{
    planner_files *f = p->files;
    if (!f)
        return;
    if (f->dialog_open) {
        char path[1100];
        ui_dialog_state s = ui_file_dialog_poll(path, sizeof path);
        if (s != UI_DIALOG_RUNNING) {
            f->dialog_open = 0;
            if (s == UI_DIALOG_ACCEPTED)
                act(p, f->dialog_use, path);
        }
    }
    if (f->prompt_open)
        prompt_panel(p, f, width, height);
    if (f->job)
        job_panel(p, f, width, height, dt);
}

void planner_files_free(planner *p)
{
    planner_files *f = p->files;
    if (!f)
        return;
    if (f->job) {
        ui_job_cancel(f->job);
        ui_job_free(f->job);
    }
    if (f->dialog_open)
        ui_file_dialog_close();
    free(f);
    p->files = NULL;
}
