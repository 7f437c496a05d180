/* The planner's document: every change goes through app's commands as an edit line (the same
 * lines `tessera edit` replays, docs/editing.md), so each is one undo step; after a change the
 * fixtures, the placement findings and the 3D scene are brought up to date. Saving is app's
 * atomic write. Nothing is left beside the user's file: autosave writes into the user's state
 * folder (user_state.h) every AUTOSAVE_S seconds while there are unsaved changes, opening a
 * project whose autosave is newer offers to recover it, and the version a save replaces (app's
 * PATH.bak) is moved there too. */
#define _GNU_SOURCE /* realpath */

#include "planner.h"
#include "planner_actions.h"
#include "user_state.h"

#include "app/project/commands.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define AUTOSAVE_S 30.0

void planner_status(planner *p, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(p->status, sizeof p->status, fmt, ap);
    va_end(ap);
    fprintf(stderr, "tessera: %s\n", p->status);
}

/* Fixtures and findings of the current document (the plan view and the 3D markers). */
static void refresh_findings(planner *p)
{
    free(p->fixtures);
    p->fixtures = NULL;
    p->fixture_count = 0;
    free(p->free_areas);
    p->free_areas = NULL;
    app_findings_free(&p->findings);
    char err[1024];
    if (app_placement_fixtures(&p->project, app_placement_lazy_lookup, &p->catalog, &p->fixtures,
                               &p->fixture_count, err, sizeof err) != APP_OK) {
        planner_status(p, "%s", err);
        return;
    }
    app_check_options opt = {.barrier_free = APP_BARRIER_FREE_OFF};
    if (app_placement_check(&p->project, p->fixtures, p->fixture_count, &opt, &p->findings, err,
                            sizeof err) != APP_OK) {
        planner_status(p, "%s", err);
        return;
    }
    /* The plan draws the free areas where the check placed them (slid sideways to stay inside
     * the room, DOMAIN.md "Clearances"), not centred on their fixtures. */
    p->free_areas =
        malloc((size_t)(p->fixture_count > 0 ? p->fixture_count : 1) * sizeof *p->free_areas);
    if (!p->free_areas) {
        planner_status(p, "out of memory for the free areas");
        return;
    }
    if (app_free_areas(&p->project, p->fixtures, p->fixture_count, opt.barrier_free, p->free_areas,
                       err, sizeof err) != APP_OK) {
        planner_status(p, "%s", err);
        free(p->free_areas);
        p->free_areas = NULL;
    }
}

int planner_rebuild_scene(planner *p)
{
    char err[1024];
    planner_fixture_drag_forget(p); /* its renderer objects go with the scene */
    if (p->scene_ready)
        app_scene_release(p->ctx, &p->scene);
    p->scene_ready = 0;
    if (planner_scene_build(p, err, sizeof err)) {
        planner_status(p, "%s", err);
        return 1;
    }
    p->scene_ready = 1;
    planner_set_quality(p, p->quality);
    planner_heap_after_rebuild();
    return 0;
}

void planner_doc_changed(planner *p)
{
    p->dirty = 1;
    p->quantities.stale = 1; /* recomputed when the panel is next drawn */
    refresh_findings(p);
    planner_rebuild_scene(p);
}

int planner_doc_open(planner *p)
{
    p->history = app_history_create(200);
    p->catalog.db_path = NULL; /* the user's catalog, as `tessera catalog` */
    if (!p->history) {
        fprintf(stderr, "tessera: out of memory\n");
        return 1;
    }
    refresh_findings(p);
    p->quantities.stale = 1;
    planner_lock_document(p);
    /* A project the user opened (not the shipped demo) is a recent file. */
    if (p->project.path[0] && strncmp(p->project.path, TESSERA_SOURCE_DIR "/assets/",
                                      strlen(TESSERA_SOURCE_DIR "/assets/")))
        planner_recent_note(p, p->project.path);
    return 0;
}

void planner_doc_close(planner *p)
{
    planner_fixture_drag_end(p, 0);
    ui_quantities_free(&p->quantities);
    if (p->thumbs.rendered > 0)
        fprintf(stderr, "tessera: %d catalog thumbnails rendered, %.1f ms each\n",
                p->thumbs.rendered, p->thumbs.total_ms / p->thumbs.rendered);
    if (p->thumbs.error[0])
        fprintf(stderr, "tessera: thumbnails: %s\n", p->thumbs.error);
    fprintf(stderr, "tessera: gui: %ld times a frame found an off-screen target bound\n",
            p->stray_target_frames);
    ui_thumbnails_free(&p->thumbs); /* the window's GL context is still current */
    app_history_destroy(p->history);
    p->history = NULL;
    free(p->fixtures);
    p->fixtures = NULL;
    free(p->free_areas);
    p->free_areas = NULL;
    app_findings_free(&p->findings);
    app_placement_lazy_close(&p->catalog);
    planner_unlock_document(p);
}

int planner_edit(planner *p, const char *line)
{
    app_script_env env = {.lookup = app_placement_lazy_lookup,
                          .user = &p->catalog,
                          .assets_dir = app_placement_assets_dir()};
    char err[1024];
    if (planner_edit_reaches_out(p, line, err, sizeof err)) {
        planner_status(p, "%s", err);
        return 1;
    }
    if (app_script_run(&p->project, p->history, line, strlen(line), "edit", &env, NULL, err,
                       sizeof err) != APP_OK) {
        planner_status(p, "%s", err);
        return 1;
    }
    planner_status(p, "%s", line);
    planner_doc_changed(p);
    return 0;
}

int planner_undo(planner *p, int redo)
{
    char err[1024];
    app_result r = redo ? app_history_redo(p->history, &p->project, err, sizeof err)
                        : app_history_undo(p->history, &p->project, err, sizeof err);
    if (r != APP_OK) {
        planner_status(p, "%s", redo ? "nothing to redo" : "nothing to undo");
        return 1;
    }
    planner_status(p, "%s", redo ? "redone" : "undone");
    planner_doc_changed(p);
    return 0;
}

/* The autosave's file in the state folder; 0 ok, else why in out. */
static int autosave_path(const planner *p, char *out, size_t size)
{
    return ui_project_state_file("autosave", p->project.path, out, size);
}

/* app's save keeps the replaced file as PATH.bak; the user's folder gets nothing but the file,
 * so the backup goes to the state folder (dropped where a rename cannot reach it). */
static void move_backup(const char *path)
{
    char bak[1100], kept[1100];
    snprintf(bak, sizeof bak, "%s.bak", path);
    if (access(bak, F_OK) != 0)
        return;
    if (ui_project_state_file("previous", path, kept, sizeof kept) || rename(bak, kept) != 0)
        unlink(bak);
}

int planner_save(planner *p, const char *path)
{
    char err[1024];
    const char *target = path && *path ? path : p->project.path;
    if (!*target) {
        planner_status(p, "save: the project has no file yet (save as)");
        return 1;
    }
    int same_file = !strcmp(target, p->project.path);
    if (same_file && p->read_only) {
        planner_status(p, "save: %s is open in another window; use Save As", target);
        return 1;
    }
    app_project_lock new_lock = {0}; /* a save as owns its new file before writing it */
    if (!same_file && planner_lock_for_save_as(p, target, &new_lock))
        return 1;
    char old_autosave[1100]; /* saved as another file: the old name's autosave goes too */
    if (autosave_path(p, old_autosave, sizeof old_autosave) || p->read_only)
        old_autosave[0] = 0; /* a read-only window's autosave name is the owner's */
    if (app_project_write(target, &p->project, err, sizeof err) != APP_OK) {
        app_project_lock_release(&new_lock);
        planner_status(p, "%s", err);
        return 1;
    }
    if (!same_file) {
        planner_unlock_document(p);
        p->lock = new_lock;
    }
    if (target != p->project.path) {
        snprintf(p->project.path, sizeof p->project.path, "%s", target);
        if (target != p->file_path) /* the file panel shows where the document now lives */
            snprintf(p->file_path, sizeof p->file_path, "%s", target);
    }
    move_backup(p->project.path);
    char a[1100];
    if (autosave_path(p, a, sizeof a) == 0)
        unlink(a); /* the saved file is newer than any autosave */
    if (old_autosave[0])
        unlink(old_autosave);
    planner_recent_note(p, p->project.path);
    p->dirty = 0;
    planner_status(p, "saved %s", p->project.path);
    return 0;
}

void planner_autosave_tick(planner *p, double now)
{
    /* A read-only window's autosave would take the owner's autosave file. */
    if (!p->dirty || p->read_only || now - p->last_autosave < AUTOSAVE_S)
        return;
    p->last_autosave = now;
    char a[1100], err[1024];
    if (autosave_path(p, a, sizeof a)) {
        planner_status(p, "autosave failed: %s", a);
        return;
    }
    /* The document's own path stays the project file: the autosave is a copy. */
    if (app_project_write(a, &p->project, err, sizeof err) != APP_OK) {
        planner_status(p, "autosave failed: %s", err);
        return;
    }
    char bak[1110];
    snprintf(bak, sizeof bak, "%s.bak", a);
    unlink(bak); /* the previous autosave is of no use */
    fprintf(stderr, "tessera: autosaved to %s\n", a);
}

int planner_recovery_available(const planner *p)
{
    char a[1100];
    struct stat sa, sp;
    return p->project.path[0] && autosave_path(p, a, sizeof a) == 0 && stat(a, &sa) == 0 &&
           stat(p->project.path, &sp) == 0 && sa.st_mtime >= sp.st_mtime;
}

int planner_recover(planner *p, int accept)
{
    char a[1100], err[1024];
    if (autosave_path(p, a, sizeof a)) {
        planner_status(p, "recover: %s", a);
        return 1;
    }
    if (!accept) {
        unlink(a);
        planner_status(p, "autosave discarded");
        return 0;
    }
    app_project rec;
    if (app_project_read(a, &rec, err, sizeof err) != APP_OK) {
        planner_status(p, "the autosave cannot be read: %s", err);
        return 1;
    }
    char path[sizeof p->project.path];
    memcpy(path, p->project.path, sizeof path);
    app_project_free_all(&p->project);
    p->project = rec;
    memcpy(p->project.path, path, sizeof path); /* saving goes to the project, not the copy */
    app_history_clear(p->history);
    planner_doc_changed(p);
    planner_status(p, "recovered the autosaved changes (not saved yet)");
    return 0;
}

/* Makes project (read by the caller) the document: the old one is freed, the history and the
 * selection forgotten, the views framed on the new room. */
static void adopt(planner *p, app_project *project)
{
    planner_bake_forget(p); /* the old room's light is no light for this one */
    app_project_free_all(&p->project);
    p->project = *project;
    app_history_clear(p->history);
    p->plan_o.selected_object = p->plan_o.selected_wall = -1;
    p->plan_o.hover_corner = p->plan_o.drag_corner = p->plan_o.drag_object = -1;
    p->plan_fitted = 0;
    p->drop.active = 0;
    app_point2 box[4];
    app_room_plan fallback;
    const app_room_plan *plan = planner_plan(p, box, &fallback);
    p->orbit = ui_orbit_framing(plan);
    p->walk = ui_walk_start(plan);
    p->camera = -1;
    p->flight.active = 0;
    if (p->project.camera_count > 0)
        planner_jump_to_camera(p, 0);
    planner_doc_changed(p);
    p->dirty = 0;
    p->objects_at_open = p->project.object_count;
}

int planner_file_open(planner *p, const char *path)
{
    if (!path || !*path) {
        planner_status(p, "open: type the path of a project file first");
        return 1;
    }
    app_project next;
    char err[1024];
    if (app_project_read(path, &next, err, sizeof err) != APP_OK) {
        /* app's messages start with the file name; make sure this one does. */
        if (strncmp(err, path, strlen(path)))
            planner_status(p, "cannot open %s: %s (the document is unchanged)", path, err);
        else
            planner_status(p, "cannot open %s (the document is unchanged)", err);
        return 1;
    }
    adopt(p, &next);
    snprintf(p->file_path, sizeof p->file_path, "%s", path);
    planner_recent_note(p, path);
    p->recovery_offered = planner_recovery_available(p);
    planner_status(p, "opened %s%s", path,
                   p->recovery_offered ? " (it has newer autosaved changes)" : "");
    planner_lock_document(p); /* after the message: a read-only one replaces it */
    if (p->read_only)
        p->recovery_offered = 0; /* the autosave is the other window's */
    return 0;
}

int planner_file_new(planner *p)
{
    /* The empty room: the designed bathroom's walls, openings and tiles, no fixtures. */
    char path[1100], err[1024];
    const char *env = getenv("TESSERA_ASSETS");
    snprintf(path, sizeof path, "%s/projects/designed-bathroom-base.json",
             env && *env ? env : TESSERA_SOURCE_DIR "/assets");
    app_project next;
    if (app_project_read(path, &next, err, sizeof err) != APP_OK) {
        planner_status(p, "new: the empty room template cannot be read: %s", err);
        return 1;
    }
    next.path[0] = 0; /* untitled: "save as" gives it a file */
    snprintf(next.name, sizeof next.name, "New bathroom");
    adopt(p, &next);
    planner_unlock_document(p);
    p->file_path[0] = 0;
    planner_status(p, "new project (an empty room; save as to keep it)");
    return 0;
}
