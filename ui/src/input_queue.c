/* The input queue between frames (ui/src/input_queue.h). The rules that split events over
 * frames follow Dear ImGui 1.87's ImGui::UpdateInputEvents ("trickle fast inputs"). */
#include "input_queue.h"

#include <GLFW/glfw3.h>
#include <string.h>

void ui_input_queue_init(ui_input_queue *q, double x, double y)
{
    memset(q, 0, sizeof *q);
    q->x = x;
    q->y = y;
}

static ui_input_event *at(ui_input_queue *q, int i)
{
    return &q->events[(q->head + i) % UI_INPUT_CAPACITY];
}

void ui_input_push(ui_input_queue *q, const ui_input_event *e)
{
    if (e->kind == UI_INPUT_CURSOR && q->count > 0 &&
        at(q, q->count - 1)->kind == UI_INPUT_CURSOR) {
        *at(q, q->count - 1) = *e; /* only where the pointer ended matters between two events */
        return;
    }
    if (q->count == UI_INPUT_CAPACITY) {
        q->dropped++;
        return;
    }
    *at(q, q->count) = *e;
    q->count++;
}

/* Keys whose order against typed characters changes a text field's content: the editing and
 * moving keys, any key with Ctrl or Super (select all, copy, paste, undo), and the modifiers
 * themselves (Dear ImGui drops a frame's characters while Ctrl is held, taking them for a
 * shortcut). Plain printable keys do not: their characters arrive as UI_INPUT_CHAR. */
static int orders_with_text(const ui_input_event *e)
{
    return e->code >= GLFW_KEY_ESCAPE || (e->mods & (GLFW_MOD_CONTROL | GLFW_MOD_SUPER)) != 0;
}

static int valid_key(int key)
{
    return key >= 0 && key < UI_INPUT_KEYS;
}

static int valid_button(int button)
{
    return button >= 0 && button < UI_INPUT_BUTTONS;
}

void ui_input_take_frame(ui_input_queue *q, ui_input_frame *f)
{
    unsigned char key_changed[UI_INPUT_KEYS] = {0};
    int button_changed = 0, moved = 0, wheeled = 0, typed = 0, ordered_key_changed = 0;
    f->count = 0;
    f->scroll_x = f->scroll_y = 0;
    while (q->count > 0) {
        const ui_input_event *e = at(q, 0);
        int stop = 0;
        switch (e->kind) {
        case UI_INPUT_KEY:
            if (!valid_key(e->code))
                break;
            if (e->action == GLFW_REPEAT)
                stop = typed && orders_with_text(e);
            else
                stop = q->key_down[e->code] != (e->action == GLFW_PRESS) &&
                       (key_changed[e->code] || (typed && orders_with_text(e)) || button_changed);
            break;
        case UI_INPUT_CHAR:
            stop = ordered_key_changed || button_changed;
            break;
        case UI_INPUT_BUTTON:
            if (valid_button(e->code))
                stop = q->button_down[e->code] != (e->action == GLFW_PRESS) &&
                       (button_changed || moved || wheeled);
            break;
        case UI_INPUT_CURSOR:
            stop = button_changed || wheeled;
            break;
        case UI_INPUT_SCROLL:
            stop = button_changed;
            break;
        }
        if (stop)
            break;
        switch (e->kind) {
        case UI_INPUT_KEY:
            if (valid_key(e->code) && e->action != GLFW_REPEAT &&
                q->key_down[e->code] != (e->action == GLFW_PRESS)) {
                q->key_down[e->code] = e->action == GLFW_PRESS;
                key_changed[e->code] = 1;
                ordered_key_changed |= orders_with_text(e);
            }
            break;
        case UI_INPUT_CHAR:
            typed = 1;
            break;
        case UI_INPUT_BUTTON:
            if (valid_button(e->code) && q->button_down[e->code] != (e->action == GLFW_PRESS)) {
                q->button_down[e->code] = e->action == GLFW_PRESS;
                button_changed = 1;
            }
            break;
        case UI_INPUT_CURSOR:
            moved |= e->x != q->x || e->y != q->y;
            q->x = e->x;
            q->y = e->y;
            break;
        case UI_INPUT_SCROLL:
            wheeled = 1;
            f->scroll_x += e->x;
            f->scroll_y += e->y;
            break;
        }
        f->events[f->count++] = *e;
        q->head = (q->head + 1) % UI_INPUT_CAPACITY;
        q->count--;
    }
    memcpy(f->button_down, q->button_down, sizeof f->button_down);
    f->x = q->x;
    f->y = q->y;
}
