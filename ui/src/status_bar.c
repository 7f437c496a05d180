/* The status bar at the window's bottom: the mode (orbit, walk, plan, elevation), the active
 * tool's hint, the last edit's message, and on the right the frame time and the 3D view's
 * render scale. A change of mode, whatever caused it (a key, a menu, a flight that leaves walk
 * mode), is said there for a few seconds and on stderr (scripted sessions check it). */
#include "planner.h"

#include "gui.h"
#include "handle_geometry.h"

#include <stdio.h>
#include <string.h>

#define MESSAGE_SECONDS 4.0

/* The mode as one number: the active view, and for the 3D view its navigation. */
static int current_mode(const planner *p)
{
    if (p->presenting)
        return 10;
    if (p->view == UI_VIEW_3D)
        return p->mode == UI_MODE_WALK ? 1 : 0;
    return p->view == UI_VIEW_ELEVATION ? 3 : 2;
}

static const char *mode_name(int mode)
{
    switch (mode) {
    case 0:
        return "Orbit";
    case 1:
        return "Walk";
    case 2:
        return "Plan";
    case 3:
        return "Elevation";
    default:
        return "Presentation";
    }
}

const char *planner_tool_hint(const planner *p)
{
    if (p->handle_drag.active && p->handle_drag.kind == UI_HANDLE_ROTATE)
        return "turning the fixture by 15-degree steps: let go to turn it (one undo step)";
    if (p->handle_drag.active)
        return "moving the fixture along the arrow: let go to place it (one undo step)";
    if (p->fixture_drag.active)
        return "moving the fixture: let go to place it (one undo step)";
    if (p->drop.active)
        return "release over the plan or the 3D view to place the product";
    switch (current_mode(p)) {
    case 0:
        return "drag: orbit, wheel: zoom, drag a fixture or an arrow: move it, the ring: turn "
               "it, Tab: walk";
    case 1:
        return "W A S D: walk (Shift: faster), drag: look, Tab: orbit";
    case 2:
        return p->plan_o.selected_wall >= 0
                   ? "drag the wall to move it, type its length in the Wall panel, Insert: door, "
                     "window"
                   : "drag corners, walls and fixtures; right drag: pan, wheel: zoom, Delete: "
                     "remove";
    case 3:
        return "click: start the tile grid there, right drag: pan, wheel: zoom";
    default:
        return "P: back to the planner, T: tour, R: turntable";
    }
}

static float mean(const float *v, long count)
{
    int n = count < UI_FRAME_HISTORY ? (int)count : UI_FRAME_HISTORY;
    double s = 0;
    for (int i = 0; i < n; i++)
        s += v[i];
    return n ? (float)(s / n) : 0.0f;
}

/* Says a new mode once: in the bar for a few seconds, and on stderr. The 3D navigation (orbit,
 * walk) is said when it changes even while another view is active. */
static void note_mode(planner *p, double now)
{
    int mode = current_mode(p), key = 100 * mode + 10 * p->mode + 1;
    if (key == p->status_mode)
        return;
    int first = p->status_mode == 0, navigation_changed = key % 100 != p->status_mode % 100;
    p->status_mode = key;
    if (first)
        return; /* the window opening is no change */
    if (navigation_changed && mode >= 2 && mode < 10)
        snprintf(p->mode_message, sizeof p->mode_message, "%s mode in the 3D view: %s",
                 p->mode == UI_MODE_WALK ? "Walk" : "Orbit",
                 p->mode == UI_MODE_WALK ? "W A S D: walk, drag: look, Tab: orbit"
                                         : "drag: orbit, wheel: zoom, Tab: walk");
    else
        snprintf(p->mode_message, sizeof p->mode_message, "%s mode: %s", mode_name(mode),
                 planner_tool_hint(p));
    p->mode_message_until = now + MESSAGE_SECONDS;
    fprintf(stderr, "tessera: status: %s\n", p->mode_message);
}

void planner_status_bar(planner *p, double now)
{
    note_mode(p, now);
    const ui_rect *r = &p->layout.status;
    if (ui_gui_begin_bar("##status", r->x, r->y, r->w, r->h, 4.0f)) {
        float ms = mean(p->frame_ms, p->frame_count), rms = mean(p->render_ms, p->frame_count);
        char right[240], left[800], light[96];
        /* A bake in the background says how far it is, before the speed. */
        int baking = planner_bake_status(p, light, sizeof light);
        const char *sep = baking ? "  |  " : "";
        if (!baking)
            light[0] = 0;
        snprintf(right, sizeof right, "%s%s%s  |  3D %.1f ms at %.0f %%  |  %.1f ms %.0f fps",
                 light, sep, ui_quality_names[p->quality], rms, p->render_scale * 100.0f, ms,
                 ms > 0 ? 1000.0f / ms : 0.0f);
        if (r->w < 1100) /* a narrow window keeps the hint and the speed only */
            snprintf(right, sizeof right, "%s%s%.0f fps", light, sep, ms > 0 ? 1000.0f / ms : 0.0f);
        /* Said on every frame: a read-only window must not look like one that saves. */
        const char *ro = p->read_only ? "READ-ONLY (open in another window)  |  " : "";
        if (now < p->mode_message_until)
            snprintf(left, sizeof left, "%s[%s] %s", ro, mode_name(current_mode(p)),
                     p->mode_message);
        else
            snprintf(left, sizeof left, "%s[%s] %s%s%s", ro, mode_name(current_mode(p)),
                     planner_tool_hint(p), p->status[0] ? "  |  " : "", p->status);
        float x = r->w - ui_gui_text_width(right) - 8.0f;
        /* The left part ends before the right one starts: cut, with an ellipsis. */
        size_t n = strlen(left);
        while (n > 4 && ui_gui_text_width(left) > x - 16.0f) {
            n = n * 9 / 10;
            memcpy(left + n - 3, "...", 4);
        }
        ui_gui_text("%s", left);
        ui_gui_same_line_at(x);
        ui_gui_text("%s", right);
    }
    ui_gui_end();
}
