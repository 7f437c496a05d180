/* Running a UI script (ui/src/script.h) one frame at a time, as input a user would give, and
 * the window screenshots it asks for. */
#include "planner.h"
#include "planner_actions.h"
#include "probe_props.h"

#include "render/image_io.h"

#include <GLFW/glfw3.h>
#include <stdlib.h>
#include <string.h>

int planner_screenshot(planner *p, const char *path)
{
    int w, h;
    glfwGetFramebufferSize(p->window, &w, &h);
    size_t size = (size_t)w * (size_t)h * 4;
    unsigned char *px = malloc(size);
    if (!px) {
        fprintf(stderr, "tessera: screenshot %s: out of memory\n", path);
        return 1;
    }
    char err[1024];
    int rc = 0;
    if (rd_read_window_rgba8(p->ctx, w, h, px, size) != RD_OK) {
        fprintf(stderr, "tessera: screenshot %s: %s\n", path, rd_last_error());
        rc = 1;
    } else if (rd_image_write_rgba8(path, w, h, px, err, sizeof err) != RD_IMAGE_OK) {
        fprintf(stderr, "tessera: screenshot: %s\n", err);
        rc = 1;
    } else {
        fprintf(stderr, "tessera: screenshot %s (%dx%d)\n", path, w, h);
    }
    free(px);
    return rc;
}

static int find_camera(const planner *p, const char *name)
{
    for (int i = 0; i < p->project.camera_count; i++)
        if (!strcmp(p->project.cameras[i].name, name))
            return i;
    return -1;
}

static int fail(const ui_action *a, const char *why)
{
    fprintf(stderr, "tessera: script line %d: %s\n", a->line, why);
    return 1;
}

/* This frame's share of a spread action: the whole amount divided over its frames. */
/* drag3d: the fixture grabbed at its centre, half way up, on the first frame; moved an even
 * share of the rest of the way each frame; let go (one move edit) on the last. */
static int drag3d(planner *p, const ui_action *a)
{
    ui_fixture_drag *d = &p->fixture_drag;
    if (p->action_frame == 0) {
        int object = -1;
        for (int i = 0; i < p->project.object_count && object < 0; i++)
            if (!strcmp(p->project.objects[i].name, a->text))
                object = i;
        const app_fixture *f = NULL;
        for (int i = 0; object >= 0 && i < p->fixture_count; i++)
            if (p->fixtures[i].object == object)
                f = &p->fixtures[i];
        if (!f) {
            planner_status(p, "drag3d: no fixture \"%s\"", a->text);
            return 1;
        }
        double grab[3] = {f->centre[0], f->centre[1], 0.5 * (f->z0 + f->z1)};
        if (planner_fixture_drag_begin(p, object, grab))
            return 1;
    }
    if (!d->active)
        return 1;
    p->dragging = 1; /* the frame log marks these frames "drag" */
    double t = 1.0 / (a->frames - p->action_frame);
    planner_fixture_drag_to(p, d->centre[0] + t * (a->a - d->centre[0]),
                            d->centre[1] + t * (a->b - d->centre[1]));
    if (p->action_frame + 1 < a->frames)
        return 0;
    return planner_fixture_drag_end(p, 1);
}

static int apply(planner *p, const ui_action *a)
{
    double share = 1.0 / a->frames;
    switch (a->kind) {
    case UI_ACT_WAIT:
        return 0;
    case UI_ACT_ORBIT:
        p->mode = UI_MODE_ORBIT;
        p->dragging = 1; /* logged as a drag, the state the frame-time benches measure */
        ui_orbit_drag(&p->orbit, a->a * share, a->b * share);
        return 0;
    case UI_ACT_ZOOM:
        ui_orbit_zoom(&p->orbit, a->a * share);
        return 0;
    case UI_ACT_MODE:
        p->mode = strcmp(a->text, "walk") ? UI_MODE_ORBIT : UI_MODE_WALK;
        return 0;
    case UI_ACT_WALK:
        planner_walk_move(p, a->a * share, a->b * share);
        return 0;
    case UI_ACT_CAMERA: {
        int i = find_camera(p, a->text);
        if (i < 0) {
            fprintf(stderr, "tessera: script line %d: the project has no viewpoint \"%s\"\n",
                    a->line, a->text);
            return 1;
        }
        planner_jump_to_camera(p, i);
        return 0;
    }
    case UI_ACT_QUALITY:
        for (int i = 0; i < 4; i++)
            if (!strcmp(a->text, ui_quality_names[i])) {
                planner_set_quality(p, i);
                return 0;
            }
        fprintf(stderr, "tessera: script line %d: unknown quality \"%s\"\n", a->line, a->text);
        return 1;
    case UI_ACT_SCREENSHOT:
        return planner_screenshot(p, a->text);
    case UI_ACT_SEARCH:
        /* The script reader keeps search texts under 128 bytes. */
        memcpy(p->browser.text, a->text, sizeof p->browser.text - 1);
        p->browser.text[sizeof p->browser.text - 1] = 0;
        return ui_catalog_browser_refresh(&p->browser) ? fail(a, p->browser.error) : 0;
    case UI_ACT_SELECT:
        ui_catalog_browser_refresh(&p->browser);
        if (ui_catalog_browser_select(&p->browser, (int)a->a - 1))
            return fail(a, "no such hit in the catalog browser");
        return 0;
    case UI_ACT_EXPECT_HITS:
        ui_catalog_browser_refresh(&p->browser);
        if (p->browser.hit_count < (int)a->a) {
            char why[128];
            snprintf(why, sizeof why, "the catalog browser shows %d hits, expected at least %d",
                     p->browser.hit_count, (int)a->a);
            return fail(a, why);
        }
        return 0;
    case UI_ACT_FLY: {
        int i = find_camera(p, a->text);
        if (i < 0)
            return fail(a, "the project has no such viewpoint");
        planner_fly_to_camera(p, i, a->a);
        return 0;
    }
    case UI_ACT_PRESENT:
        p->presenting = !strcmp(a->text, "on");
        return 0;
    case UI_ACT_TOUR:
        p->touring = !strcmp(a->text, "on");
        p->tour_clock = 1e9;
        return 0;
    case UI_ACT_TURNTABLE:
        p->turntable = !strcmp(a->text, "on");
        return 0;
    case UI_ACT_PRINT_SHOT:
        return planner_print_shot(p, a->text);
    case UI_ACT_VIEW:
        p->view = !strcmp(a->text, "elevation") ? UI_VIEW_ELEVATION
                  : strcmp(a->text, "plan")     ? UI_VIEW_3D
                                                : UI_VIEW_PLAN;
        return 0;
    case UI_ACT_PANES:
        planner_show_panes(p, !strcmp(a->text, "both"));
        return 0;
    case UI_ACT_SPLIT:
        if (p->layout.splitter.w <= 0)
            return fail(a, "the panes are not side by side");
        p->split = ui_layout_split_at(&p->layout, (float)a->a);
        return 0;
    case UI_ACT_EDIT:
        return planner_edit(p, a->text) ? fail(a, p->status) : 0;
    case UI_ACT_PLACE_SELECTED:
        return planner_place_selected(p, a->a, a->b) ? fail(a, p->status) : 0;
    case UI_ACT_DRAG:
        return planner_drag_object(p, a->text, a->a, a->b) ? fail(a, p->status) : 0;
    case UI_ACT_DRAG3D:
        return drag3d(p, a) ? fail(a, p->status) : 0;
    case UI_ACT_MOVE_WALL:
        return planner_move_wall(p, (int)a->a, a->b) ? fail(a, p->status) : 0;
    case UI_ACT_UNDO:
    case UI_ACT_REDO:
        return planner_undo(p, a->kind == UI_ACT_REDO) ? fail(a, p->status) : 0;
    case UI_ACT_SAVE:
        return planner_save(p, strcmp(a->text, "-") ? a->text : NULL) ? fail(a, p->status) : 0;
    case UI_ACT_EXPECT_OBJECTS:
        if (p->project.object_count != (int)a->a) {
            char why[128];
            snprintf(why, sizeof why, "the project has %d objects, expected %d",
                     p->project.object_count, (int)a->a);
            return fail(a, why);
        }
        return 0;
    case UI_ACT_EXPECT_ADDED:
        if (p->project.object_count - p->objects_at_open != (int)a->a) {
            char why[128];
            snprintf(why, sizeof why, "%d objects were added, expected %d",
                     p->project.object_count - p->objects_at_open, (int)a->a);
            return fail(a, why);
        }
        return 0;
    case UI_ACT_TILE_SELECTED:
        return planner_tile_selected(p, a->text) ? fail(a, p->status) : 0;
    case UI_ACT_SHARE:
    case UI_ACT_FILES:
        return planner_files_script(p, a); /* 2: a job or a dialog is still under way */
    case UI_ACT_DRAG_SELECTED:
    case UI_ACT_DROP_SELECTED: {
        int view = strcmp(a->text, "plan") ? UI_VIEW_3D : UI_VIEW_PLAN;
        if (view != p->view)
            return fail(a, "that view is not showing (use view first)");
        if (p->browser.selected < 0)
            return fail(a, "select a product in the catalog first");
        if (p->action_frame + 1 < a->frames || a->kind == UI_ACT_DRAG_SELECTED) {
            /* The ghost travels from where it is (else the catalog panel) to the point, as a
             * hand drags. */
            int w, h;
            glfwGetFramebufferSize(p->window, &w, &h);
            double x0 = p->drop.active ? p->drop.x : w - 200.0;
            double y0 = p->drop.active ? p->drop.y : 250.0;
            double t = 1.0 / (a->frames - p->action_frame); /* the rest of the way, evenly */
            planner_drag_ghost(p, p->browser.selected, x0 + t * (a->a - x0), y0 + t * (a->b - y0));
            return 0;
        }
        p->drop.active = 0;
        return planner_drop_selected(p, view, a->a, a->b) ? fail(a, p->status) : 0;
    }
    case UI_ACT_EXPECT_TOTAL: {
        if (p->quantities.stale || !p->quantities.valid)
            ui_quantities_refresh(&p->quantities, &p->project, p->browser.db);
        if (!p->quantities.valid)
            return fail(a, p->quantities.error);
        double total = p->quantities.bom.gross_cents / 100.0;
        fprintf(stderr, "tessera: quantities total %.2f %s (net %.2f)\n", total,
                p->quantities.bom.currency, p->quantities.bom.net_cents / 100.0);
        if (total < a->a || total > a->b) {
            char why[160];
            snprintf(why, sizeof why, "the total is %.2f, expected %.2f to %.2f", total, a->a,
                     a->b);
            return fail(a, why);
        }
        return 0;
    }
    case UI_ACT_NEW:
        p->dirty = 0; /* a script answers the unsaved-changes prompt with "discard" */
        return planner_file_new(p) ? fail(a, p->status) : 0;
    case UI_ACT_OPEN:
        p->dirty = 0;
        return planner_file_open(p, a->text) ? fail(a, p->status) : 0;
    case UI_ACT_SAVE_AS:
        return planner_save(p, a->text) ? fail(a, p->status) : 0;
    case UI_ACT_EXPECT_PROBE: { /* probe_props.h */
        char why[512];
        return ui_probe_expect(&p->project, a->text, why, sizeof why) ? fail(a, why) : 0;
    }
    case UI_ACT_ELEVATION_WALL: /* tiles.h */
    case UI_ACT_TILE_SURFACE:
    case UI_ACT_TILE_PATTERN:
    case UI_ACT_TILE_GROUT:
    case UI_ACT_TILE_START:
    case UI_ACT_TILE_ROTATE:
    case UI_ACT_TILE_BAND:
    case UI_ACT_TILE_BORDER:
    case UI_ACT_ELEVATION_CLICK:
    case UI_ACT_EXPECT_PATTERN:
    case UI_ACT_EXPECT_TILES:
    case UI_ACT_TILE_PANEL:
        return planner_tile_action(p, a) ? fail(a, p->status) : 0;
    case UI_ACT_WAIT_FILE: /* input_script.c */
    case UI_ACT_PICK:
        return planner_pick(p, a->text) ? fail(a, p->status) : 0;
    case UI_ACT_LOCATE:
    case UI_ACT_EXPECT_SEARCH:
        return planner_input_action(p, a) ? fail(a, p->status) : 0;
    case UI_ACT_WAIT_BAKE:
        return planner_bake_settled(p) ? 0 : 2;
    case UI_ACT_WAIT_WARMUP:
        return planner_warmup_done(p) ? 0 : 2;
    case UI_ACT_WAIT_STILL:
        return p->live.still && ui_live_done(&p->live.ladder) ? 0 : 2;
    case UI_ACT_BAKE_HOLD:
        if (strcmp(a->text, "on") && strcmp(a->text, "off"))
            return fail(a, "bake-hold takes on or off");
        planner_bake_hold(p, !strcmp(a->text, "on"));
        return 0;
    case UI_ACT_QUIT:
        p->quit = 1;
        return 0;
    }
    return 0;
}

/* 1 while the hand holds a drag (an outside driver pressed and has not let go): a script action
 * run meanwhile, such as a screenshot of the drag, leaves it held. */
static int pointer_drag_held(const planner *p)
{
    const ui_plan_overlay *o = &p->plan_o;
    return o->drag_object >= 0 || o->drag_corner >= 0 || o->wall_dragging ||
           p->handle_drag.active || (p->fixture_drag.active && p->fixture_drag.by_pointer);
}

int planner_script_idles(const planner *p)
{
    return p->action < p->script.count && p->script.actions[p->action].kind == UI_ACT_WAIT_STILL;
}

int planner_script_step(planner *p)
{
    if (p->action >= p->script.count)
        return 0;
    const ui_action *a = &p->script.actions[p->action];
    if (a->kind == UI_ACT_WAIT_FILE) /* the hand drives the window meanwhile */
        return planner_wait_file(p, a);
    if (!pointer_drag_held(p))
        p->dragging = 0;
    /* wait N spreads nothing over N frames; every other action takes at least one. */
    int frames = a->kind == UI_ACT_WAIT ? (int)a->a : a->frames;
    int r = frames > 0 ? apply(p, a) : 0;
    if (r == 1) {
        p->exit_code = 1;
        return 1;
    }
    if (r == 2) /* the action goes on next frame (a job or a dialog under way) */
        return 0;
    if (++p->action_frame >= frames) {
        p->action++;
        p->action_frame = 0;
    }
    return 0;
}
