/* The 2D plan view: drag corners to reshape the room, drag fixtures (they
 * snap to walls when released near one), select a wall and type its exact length, pan with the
 * right button, zoom with the wheel. Every change is an edit line through app's commands. */
#include "planner.h"

#include "app/project/commands.h"
#include "gui.h"

#include <GLFW/glfw3.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define GRID_MM 10.0

static int object_index(const planner *p, const char *name)
{
    for (int i = 0; i < p->project.object_count; i++)
        if (!strcmp(p->project.objects[i].name, name))
            return i;
    return -1;
}

static const app_fixture *fixture_of(const planner *p, int object)
{
    for (int i = 0; i < p->fixture_count; i++)
        if (p->fixtures[i].object == object)
            return &p->fixtures[i];
    return NULL;
}

static int inside_room(const planner *p, double x_mm, double y_mm)
{
    app_point2 box[4];
    app_room_plan fallback;
    return ui_plan_contains(planner_plan(p, box, &fallback), x_mm, y_mm);
}

int planner_pick(planner *p, const char *name)
{
    int i = strcmp(name, "-") ? object_index(p, name) : -1;
    if (i >= 0 && !fixture_of(p, i)) {
        planner_status(p, "no fixture \"%s\" in the plan", name);
        return 1;
    }
    p->plan_o.selected_object = i;
    p->plan_o.selected_wall = -1;
    return 0;
}

int planner_drag_object(planner *p, const char *name, double x_mm, double y_mm)
{
    int i = strcmp(name, "-") ? object_index(p, name) : p->plan_o.selected_object;
    const app_fixture *f = i >= 0 ? fixture_of(p, i) : NULL;
    if (!f) {
        planner_status(p, "no fixture \"%s\" in the plan", name);
        return 1;
    }
    /* The pointer carries the footprint's centre; the object's position (its back centre)
     * moves by the same amount. */
    const app_object *o = &p->project.objects[i];
    double x = o->position_mm[0] + x_mm - f->centre[0], y = o->position_mm[1] + y_mm - f->centre[1];
    char line[256];
    /* Snapped as a fitter places it (docs/editing.md): back to the nearest wall, then a side
     * to a corner within 300 mm, then 200 mm from a neighbour within 300 mm. */
    snprintf(line, sizeof line, "move \"%s\" %.0f %.0f %.0f snap wall corner neighbour", o->name,
             ui_plan_snap_grid(x, GRID_MM), ui_plan_snap_grid(y, GRID_MM), o->position_mm[2]);
    /* No wall near: the move without snapping, inside the room only. */
    if (planner_edit(p, line) == 0)
        return 0;
    if (!inside_room(p, x_mm, y_mm)) {
        planner_status(p, "%s: outside the room, not moved", o->name);
        return 1;
    }
    snprintf(line, sizeof line, "move \"%s\" %.0f %.0f %.0f", o->name,
             ui_plan_snap_grid(x, GRID_MM), ui_plan_snap_grid(y, GRID_MM), o->position_mm[2]);
    return planner_edit(p, line);
}

int planner_place_selected(planner *p, double x_mm, double y_mm)
{
    const ui_catalog_browser *b = &p->browser;
    if (b->selected < 0 || !b->product.article[0]) {
        planner_status(p, "select a product in the catalog first");
        return 1;
    }
    const cat_product *prod = &b->product;
    const char *variant = b->variant < prod->variant_count ? prod->variants[b->variant].code : "";
    /* No height: the product lands at its mounting height, or on the product it mounts onto
     * when one is near the drop point (a basin on its vanity), against the nearest wall
     * (docs/editing.md "Mounting heights"). */
    /* A product whose catalog row names companions (a vanity's basin, tap and mirror) comes
     * with them, as one group and one undo step (docs/editing.md "Companions"), unless the
     * catalog panel's "[x] with ..." is turned off. */
    const char *with = prod->companions[0] && !b->without_companions ? " with-companions" : "";
    int first_new = p->project.object_count;
    char line[512];
    snprintf(line, sizeof line, "place \"%s\" \"%s\" %s at %.0f %.0f snap wall%s",
             prod->manufacturer, prod->article, variant, x_mm, y_mm, with);
    int rc = planner_edit(p, line);
    if (rc && !inside_room(p, x_mm, y_mm)) {
        planner_status(p, "%s: outside the room, nothing placed", prod->name);
        return 1;
    }
    if (rc) { /* no wall near: where it was dropped */
        snprintf(line, sizeof line, "place \"%s\" \"%s\" %s at %.0f %.0f%s", prod->manufacturer,
                 prod->article, variant, x_mm, y_mm, with);
        rc = planner_edit(p, line);
    }
    if (rc == 0) /* the new fixture (not a companion) is the selection, ready to be dragged */
        p->plan_o.selected_object = first_new;
    return rc;
}

int planner_tile_selected(planner *p, const char *surface)
{
    const ui_catalog_browser *b = &p->browser;
    if (b->selected < 0 || !b->product.has_tile) {
        planner_status(p, "select a tile in the catalog first");
        return 1;
    }
    const cat_product *prod = &b->product;
    const char *variant = b->variant < prod->variant_count ? prod->variants[b->variant].code : "";
    char line[512];
    snprintf(line, sizeof line, "tile %s with \"%s\" \"%s\" %s", surface, prod->manufacturer,
             prod->article, variant);
    return planner_edit(p, line);
}

void planner_wall_panel(planner *p)
{
    int w = p->plan_o.selected_wall;
    if (w < 0 || w >= p->project.plan.corner_count)
        return;
    /* In the Selection panel's place in the left column: a wall and a fixture are never both
     * selected. */
    const ui_rect *r = &p->layout.left;
    if (ui_gui_begin("Wall", r->x, r->y, r->w, 150.0f)) {
        double length = ui_plan_wall_length(&p->project.plan, w);
        ui_gui_text("wall %d: %.0f mm", w, length);
        if (ui_gui_input_double_enter("length mm", &p->wall_length_edit) &&
            p->wall_length_edit > 0) {
            app_point2 c = ui_plan_corner_for_length(&p->project.plan, w, p->wall_length_edit);
            char line[128];
            snprintf(line, sizeof line, "corner %d %.1f %.1f",
                     (w + 1) % p->project.plan.corner_count, c.x, c.y);
            planner_edit(p, line);
        }
        /* Openings, pre-walls and niches in the middle of the wall (planner_wall_item_line),
         * placed by the edit words so app checks that they fit (the status says why not);
         * each is one undo step. */
        static const char *const labels[4] = {"+ door", "+ window", "+ pre-wall", "+ niche"};
        for (int k = 0; k < 4; k++) {
            if (k)
                ui_gui_same_line();
            char line[256];
            if (ui_gui_button(labels[k]) && planner_wall_item_line(p, k, w, line, sizeof line))
                planner_edit(p, line);
        }
    }
    ui_gui_end();
}

int planner_move_wall(planner *p, int wall, double offset_mm)
{
    const app_room_plan *pl = &p->project.plan;
    if (wall < 0 || wall >= pl->corner_count || offset_mm == 0)
        return 1;
    app_point2 a, b;
    ui_plan_wall_moved(pl, wall, offset_mm, &a, &b);
    /* Both corners in one script run inside one history group: one undo step, one rebuild;
     * if the second corner is refused the first is taken back (app checks the plan stays a
     * simple polygon with its openings, pre-walls and niches fitting). */
    char text[256], err[1024];
    snprintf(text, sizeof text, "corner %d %.0f %.0f\ncorner %d %.0f %.0f\n", wall, a.x, a.y,
             (wall + 1) % pl->corner_count, b.x, b.y);
    app_script_env env = {.lookup = app_placement_lazy_lookup,
                          .user = &p->catalog,
                          .assets_dir = app_placement_assets_dir()};
    app_history_begin_group(p->history, "move wall");
    if (app_script_run(&p->project, p->history, text, strlen(text), "wall", &env, NULL, err,
                       sizeof err) != APP_OK) {
        char ignored[256];
        app_history_abort_group(p->history, &p->project, ignored, sizeof ignored);
        planner_status(p, "%s", err);
        return 1;
    }
    if (app_history_end_group(p->history, err, sizeof err) != APP_OK) {
        planner_status(p, "%s", err);
        return 1;
    }
    planner_status(p, "moved wall %d by %.0f mm", wall, offset_mm);
    planner_doc_changed(p);
    return 0;
}

int planner_wall_item_line(const planner *p, int kind, int wall, char *line, size_t size)
{
    if (wall < 0 || wall >= p->project.plan.corner_count || kind < 0 || kind > 3)
        return 0;
    /* Common sizes (DOMAIN.md): an 800 x 2010 door, an 800 x 1000 window on a 1000 mm sill, a
     * pre-wall 1200 wide, 200 deep and 1200 high for a wall-hung WC, a 600 x 400 shelf niche
     * 100 deep at 1200; centred on the wall. */
    static const char *const stems[4] = {"door", "window", "prewall", "niche"};
    static const double widths[4] = {800, 800, 1200, 600};
    double length = ui_plan_wall_length(&p->project.plan, wall);
    double at = (length - widths[kind]) / 2;
    const char *name = planner_unique_name(p, stems[kind]);
    static const char *const formats[4] = {
        "door %s wall %d at %.0f width 800 height 2010",
        "window %s wall %d at %.0f width 800 height 1000 sill 1000",
        "prewall %s wall %d at %.0f width 1200 depth 200 height 1200",
        "niche %s wall %d at %.0f width 600 sill 1200 height 400 depth 100"};
    int n = snprintf(line, size, formats[kind], name, wall, at);
    return n > 0 && (size_t)n < size && at >= 0;
}

const char *planner_unique_name(const planner *p, const char *stem)
{
    static char name[64];
    const app_room_plan *pl = &p->project.plan;
    for (int n = 1; n < 1000; n++) {
        snprintf(name, sizeof name, "%s-%d", stem, n);
        int taken = 0;
        for (int i = 0; i < pl->opening_count && !taken; i++)
            taken = !strcmp(pl->openings[i].name, name);
        for (int i = 0; i < pl->prewall_count && !taken; i++)
            taken = !strcmp(pl->prewalls[i].name, name);
        for (int i = 0; i < pl->niche_count && !taken; i++)
            taken = !strcmp(pl->niches[i].name, name);
        if (!taken)
            break;
    }
    return name;
}

/* The dragged fixture's snap preview (app/design/snap_guides.h) from the pose the release's
 * edit will ask for (planner_drag_object). While a script runs, each new preview is logged:
 * tests that drag with real events read the labels back. */
static void update_snap_preview(planner *p)
{
    ui_plan_overlay *o = &p->plan_o;
    o->snap_shown = 0;
    int k = 0;
    while (k < p->fixture_count && p->fixtures[k].object != o->drag_object)
        k++;
    if (k == p->fixture_count || o->drag_object >= p->project.object_count)
        return;
    const app_fixture *f = &p->fixtures[k];
    if (hypot(f->centre[0] - o->drag_mm[0], f->centre[1] - o->drag_mm[1]) <= 1)
        return; /* a click, not a drag: the release leaves it where it is */
    const app_object *ob = &p->project.objects[o->drag_object];
    app_pose in = {ui_plan_snap_grid(ob->position_mm[0] + o->drag_mm[0] - f->centre[0], GRID_MM),
                   ui_plan_snap_grid(ob->position_mm[1] + o->drag_mm[1] - f->centre[1], GRID_MM),
                   ob->position_mm[2], ob->rotation_deg[2]};
    app_snap_preview_of(&p->project, p->fixtures, p->fixture_count, k, in, &o->snap);
    o->snap_shown = 1;
    if (!p->script.count)
        return;
    static char last[256];
    char line[256], side[3][16];
    const app_snap_preview *s = &o->snap;
    for (int i = 0; i < APP_SNAP_SIDES; i++)
        snprintf(side[i], sizeof side[i], s->sides[i].found ? "%.0f" : "-", s->sides[i].mm);
    snprintf(line, sizeof line, "wall %d%s%s; left %s right %s front %s; box %.0f x %.0f", s->wall,
             s->corner ? " corner" : "", s->neighbour >= 0 ? " neighbour" : "", side[0], side[1],
             side[2], 2 * s->half[0], 2 * s->half[1]);
    if (strcmp(line, last)) {
        fprintf(stderr, "tessera: snap \"%s\" %s\n", ob->name, line);
        snprintf(last, sizeof last, "%s", line);
    }
}

static void handle_plan_input(planner *p)
{
    double mx, my;
    ui_gui_pointer(&mx, &my);
    float sx = (float)mx, sy = (float)my;
    double x, y;
    ui_plan_to_plan(&p->plan_t, sx, sy, &x, &y);
    ui_plan_overlay *o = &p->plan_o;
    int free_pointer = !ui_gui_wants_mouse();
    o->hover_corner =
        free_pointer ? ui_plan_hit_corner(&p->plan_t, &p->project.plan, sx, sy, 8) : -1;
    int left = ui_gui_mouse_down(GLFW_MOUSE_BUTTON_LEFT);
    int right = ui_gui_mouse_down(GLFW_MOUSE_BUTTON_RIGHT);

    if (right && free_pointer) {
        if (p->panning) {
            p->plan_t.centre_mm[0] -= (sx - p->mouse_x) / p->plan_t.px_per_mm;
            p->plan_t.centre_mm[1] += (sy - p->mouse_y) / p->plan_t.px_per_mm;
        }
        p->panning = 1;
    } else {
        p->panning = 0;
    }

    if (left && !p->dragging && free_pointer) {
        /* Press: a corner first, then a fixture, then a wall; else nothing is selected. */
        p->dragging = 1;
        o->drag_corner = o->hover_corner;
        o->drag_object = -1;
        if (o->drag_corner < 0) {
            int f = ui_plan_hit_fixture(p->fixtures, p->fixture_count, x, y);
            o->selected_object = f >= 0 ? p->fixtures[f].object : -1;
            o->selected_wall = -1;
            if (f >= 0) {
                o->drag_object = p->fixtures[f].object;
                p->drag_start_mm[0] = x - p->fixtures[f].centre[0];
                p->drag_start_mm[1] = y - p->fixtures[f].centre[1];
            } else {
                o->selected_wall = ui_plan_hit_wall(&p->plan_t, &p->project.plan, sx, sy, 6);
                if (o->selected_wall >= 0) {
                    p->wall_length_edit = ui_plan_wall_length(&p->project.plan, o->selected_wall);
                    /* A drag from the wall moves it along its normal, both corners. */
                    o->wall_dragging = 1;
                    o->drag_wall = o->selected_wall;
                    o->drag_wall_mm = 0;
                    p->drag_start_mm[0] = x;
                    p->drag_start_mm[1] = y;
                }
            }
        }
    }
    if (left && p->dragging) {
        if (o->drag_corner >= 0) {
            o->drag_mm[0] = ui_plan_snap_grid(x, GRID_MM);
            o->drag_mm[1] = ui_plan_snap_grid(y, GRID_MM);
        } else if (o->drag_object >= 0) {
            o->drag_mm[0] = x - p->drag_start_mm[0];
            o->drag_mm[1] = y - p->drag_start_mm[1];
            update_snap_preview(p);
        } else if (o->wall_dragging) {
            o->drag_wall_mm = ui_plan_snap_grid(ui_plan_wall_offset(&p->project.plan, o->drag_wall,
                                                                    x - p->drag_start_mm[0],
                                                                    y - p->drag_start_mm[1]),
                                                GRID_MM);
        }
    }
    if (!left && p->dragging) {
        /* Release: the edit happens once, as one undo step. */
        p->dragging = 0;
        if (o->drag_corner >= 0) {
            const app_point2 *c = &p->project.plan.corners[o->drag_corner];
            if (c->x != o->drag_mm[0] || c->y != o->drag_mm[1]) {
                char line[128];
                snprintf(line, sizeof line, "corner %d %.0f %.0f", o->drag_corner, o->drag_mm[0],
                         o->drag_mm[1]);
                planner_edit(p, line);
            }
        } else if (o->drag_object >= 0) {
            const app_fixture *f = fixture_of(p, o->drag_object);
            if (f && hypot(f->centre[0] - o->drag_mm[0], f->centre[1] - o->drag_mm[1]) > 1)
                planner_drag_object(p, p->project.objects[o->drag_object].name, o->drag_mm[0],
                                    o->drag_mm[1]);
        } else if (o->wall_dragging && o->drag_wall_mm != 0) {
            planner_move_wall(p, o->drag_wall, o->drag_wall_mm);
        }
        o->drag_corner = o->drag_object = -1;
        o->wall_dragging = o->snap_shown = 0;
    }
    p->mouse_x = mx;
    p->mouse_y = my;
}

void planner_plan_frame(planner *p, int width, int height)
{
    (void)width;
    (void)height;
    /* The plan fills its pane: fitted again when the pane's size changes, kept where the user
     * zoomed and panned it when the pane only moves. */
    ui_rect r = p->layout.pane_2d;
    if (!p->plan_fitted || p->plan_t.width != r.w || p->plan_t.height != r.h) {
        p->plan_t = ui_plan_fit(&p->project.plan, r.w, r.h, 40);
        p->plan_fitted = 1;
    }
    p->plan_t.x0 = r.x;
    p->plan_t.y0 = r.y;
    if (p->view == UI_VIEW_PLAN && planner_input_live(p))
        handle_plan_input(p);
    ui_gui_clip_push(r.x, r.y, r.x + r.w, r.y + r.h);
    ui_plan_draw(&p->plan_t, &p->project, p->fixtures, p->free_areas, p->fixture_count,
                 &p->findings, &p->plan_o);
    ui_gui_clip_pop();
}

void planner_plan_scroll(planner *p, double steps)
{
    double mx, my;
    ui_gui_pointer(&mx, &my);
    ui_plan_zoom_at(&p->plan_t, (float)mx, (float)my, pow(1.15, steps));
}
