/* The input queue between frames (ui/src/input_queue.h): a click or a key tap shorter than a
 * frame is held for one frame and released in the next; typed text and editing keys keep
 * their order; nothing is dropped. */
#include "check.h"
#include "input_queue.h"

#include <GLFW/glfw3.h>
#include <string.h>

static ui_input_queue q;
static ui_input_frame f;

static void push(ui_input_kind kind, int code, int action, int mods, double x, double y)
{
    ui_input_event e = {kind, code, action, mods, x, y};
    ui_input_push(&q, &e);
}

static void key(int code, int action, int mods)
{
    push(UI_INPUT_KEY, code, action, mods, 0, 0);
}

static void typed(const char *s)
{
    for (; *s; s++)
        push(UI_INPUT_CHAR, *s, 0, 0, 0, 0);
}

/* A text field's editing as Dear ImGui 1.86 applies a frame: its characters first, then its
 * key presses (InputTextEx). Backspace deletes before the cursor; Ctrl+A then a character
 * replaces everything; Home and End move the cursor; characters typed while Ctrl is held are
 * dropped. */
static void edit(char *text, int *cursor, int *all_selected)
{
    /* Dear ImGui takes a frame's characters for a shortcut while Ctrl is held. */
    int ctrl = q.key_down[GLFW_KEY_LEFT_CONTROL];
    for (int i = 0; i < f.count && !ctrl; i++) {
        const ui_input_event *e = &f.events[i];
        if (e->kind != UI_INPUT_CHAR)
            continue;
        if (*all_selected) {
            text[0] = 0;
            *cursor = 0;
            *all_selected = 0;
        }
        size_t n = strlen(text);
        memmove(text + *cursor + 1, text + *cursor, n - (size_t)*cursor + 1);
        text[(*cursor)++] = (char)e->code;
    }
    for (int i = 0; i < f.count; i++) {
        const ui_input_event *e = &f.events[i];
        if (e->kind != UI_INPUT_KEY || e->action != GLFW_PRESS)
            continue;
        if (e->code == GLFW_KEY_A && (e->mods & GLFW_MOD_CONTROL))
            *all_selected = 1;
        else if (e->code == GLFW_KEY_BACKSPACE && *cursor > 0) {
            memmove(text + *cursor - 1, text + *cursor, strlen(text) - (size_t)*cursor + 1);
            (*cursor)--;
        } else if (e->code == GLFW_KEY_HOME)
            *cursor = 0;
        else if (e->code == GLFW_KEY_END)
            *cursor = (int)strlen(text);
    }
}

static void test_click_inside_one_frame(void)
{
    ui_input_queue_init(&q, 10, 10);
    /* Moved there in one frame, pressed and released before the next. */
    push(UI_INPUT_CURSOR, 0, 0, 0, 100, 50);
    ui_input_take_frame(&q, &f);
    CHECK(f.x == 100 && f.y == 50);
    CHECK(!f.button_down[GLFW_MOUSE_BUTTON_LEFT]);
    push(UI_INPUT_BUTTON, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0, 0, 0);
    push(UI_INPUT_BUTTON, GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0, 0, 0);
    ui_input_take_frame(&q, &f);
    CHECK(f.button_down[GLFW_MOUSE_BUTTON_LEFT]);
    CHECK(f.count == 1);
    ui_input_take_frame(&q, &f);
    CHECK(!f.button_down[GLFW_MOUSE_BUTTON_LEFT]);
    CHECK(f.count == 1);
    ui_input_take_frame(&q, &f);
    CHECK(f.count == 0);
}

static void test_press_waits_for_the_move(void)
{
    /* A move and a press in one frame: the press waits a frame, so the panels have seen the
     * pointer where it lands; the move after the press waits too, so it lands there. */
    ui_input_queue_init(&q, 0, 0);
    push(UI_INPUT_CURSOR, 0, 0, 0, 300, 200);
    push(UI_INPUT_BUTTON, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0, 0, 0);
    push(UI_INPUT_CURSOR, 0, 0, 0, 310, 200);
    push(UI_INPUT_BUTTON, GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0, 0, 0);
    ui_input_take_frame(&q, &f);
    CHECK(f.x == 300 && !f.button_down[GLFW_MOUSE_BUTTON_LEFT]);
    ui_input_take_frame(&q, &f);
    CHECK(f.x == 300 && f.button_down[GLFW_MOUSE_BUTTON_LEFT]);
    ui_input_take_frame(&q, &f);
    CHECK(f.x == 310 && f.button_down[GLFW_MOUSE_BUTTON_LEFT]);
    ui_input_take_frame(&q, &f);
    CHECK(!f.button_down[GLFW_MOUSE_BUTTON_LEFT]);
}

static void test_many_short_clicks_all_count(void)
{
    /* Ten clicks queued during one long frame: each is held for a frame. */
    ui_input_queue_init(&q, 5, 5);
    for (int i = 0; i < 10; i++) {
        push(UI_INPUT_BUTTON, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0, 0, 0);
        push(UI_INPUT_BUTTON, GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0, 0, 0);
    }
    int presses = 0, was_down = 0;
    for (int frame = 0; frame < 40; frame++) {
        ui_input_take_frame(&q, &f);
        int down = f.button_down[GLFW_MOUSE_BUTTON_LEFT];
        presses += down && !was_down;
        was_down = down;
    }
    CHECK(presses == 10);
    CHECK(q.count == 0 && q.dropped == 0);
}

static void test_key_tap_inside_one_frame(void)
{
    ui_input_queue_init(&q, 0, 0);
    key(GLFW_KEY_BACKSPACE, GLFW_PRESS, 0);
    key(GLFW_KEY_BACKSPACE, GLFW_RELEASE, 0);
    ui_input_take_frame(&q, &f);
    CHECK(f.count == 1 && q.key_down[GLFW_KEY_BACKSPACE]);
    ui_input_take_frame(&q, &f);
    CHECK(f.count == 1 && !q.key_down[GLFW_KEY_BACKSPACE]);
}

static void test_ctrl_a_in_one_frame(void)
{
    /* Ctrl stays down while A goes down: both in the first frame, as a shortcut. */
    ui_input_queue_init(&q, 0, 0);
    key(GLFW_KEY_LEFT_CONTROL, GLFW_PRESS, GLFW_MOD_CONTROL);
    key(GLFW_KEY_A, GLFW_PRESS, GLFW_MOD_CONTROL);
    key(GLFW_KEY_A, GLFW_RELEASE, GLFW_MOD_CONTROL);
    key(GLFW_KEY_LEFT_CONTROL, GLFW_RELEASE, 0);
    ui_input_take_frame(&q, &f);
    CHECK(f.count == 2 && q.key_down[GLFW_KEY_LEFT_CONTROL] && q.key_down[GLFW_KEY_A]);
    ui_input_take_frame(&q, &f);
    CHECK(f.count == 2 && !q.key_down[GLFW_KEY_LEFT_CONTROL] && !q.key_down[GLFW_KEY_A]);
}

/* Everything a fast typist (xdotool) sends before the next frame, as it would be edited. */
static void test_typing_keeps_its_order(void)
{
    ui_input_queue_init(&q, 0, 0);
    /* "basinx", Backspace, End, Ctrl+A, "metro", Backspace, Home, "x": "xmetr". */
    typed("basinx");
    key(GLFW_KEY_BACKSPACE, GLFW_PRESS, 0);
    key(GLFW_KEY_BACKSPACE, GLFW_RELEASE, 0);
    key(GLFW_KEY_END, GLFW_PRESS, 0);
    key(GLFW_KEY_END, GLFW_RELEASE, 0);
    key(GLFW_KEY_LEFT_CONTROL, GLFW_PRESS, GLFW_MOD_CONTROL);
    key(GLFW_KEY_A, GLFW_PRESS, GLFW_MOD_CONTROL);
    key(GLFW_KEY_A, GLFW_RELEASE, GLFW_MOD_CONTROL);
    key(GLFW_KEY_LEFT_CONTROL, GLFW_RELEASE, 0);
    typed("metro");
    key(GLFW_KEY_BACKSPACE, GLFW_PRESS, 0);
    key(GLFW_KEY_BACKSPACE, GLFW_RELEASE, 0);
    key(GLFW_KEY_HOME, GLFW_PRESS, 0);
    key(GLFW_KEY_HOME, GLFW_RELEASE, 0);
    typed("x");
    char text[64] = "";
    int cursor = 0, all = 0, frames = 0;
    while (q.count > 0 && frames < 100) {
        ui_input_take_frame(&q, &f);
        edit(text, &cursor, &all);
        frames++;
    }
    CHECK_MSG(!strcmp(text, "xmetr"), "typed \"%s\", expected \"xmetr\"", text);
    CHECK(frames < 20);
}

/* A character typed just before Ctrl goes down is still text. */
static void test_text_then_ctrl(void)
{
    ui_input_queue_init(&q, 0, 0);
    typed("ab");
    key(GLFW_KEY_LEFT_CONTROL, GLFW_PRESS, GLFW_MOD_CONTROL);
    key(GLFW_KEY_LEFT_CONTROL, GLFW_RELEASE, 0);
    typed("c");
    char text[16] = "";
    int cursor = 0, all = 0, frames = 0;
    while (q.count > 0 && frames < 10) {
        ui_input_take_frame(&q, &f);
        edit(text, &cursor, &all);
        frames++;
    }
    CHECK_MSG(!strcmp(text, "abc"), "typed \"%s\", expected \"abc\"", text);
}

static void test_wheel_after_a_press_waits(void)
{
    ui_input_queue_init(&q, 0, 0);
    push(UI_INPUT_SCROLL, 0, 0, 0, 0, 1);
    push(UI_INPUT_SCROLL, 0, 0, 0, 0, 2);
    push(UI_INPUT_BUTTON, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0, 0, 0);
    push(UI_INPUT_SCROLL, 0, 0, 0, 0, -1);
    ui_input_take_frame(&q, &f);
    CHECK(f.scroll_y == 3 && !f.button_down[GLFW_MOUSE_BUTTON_LEFT]);
    ui_input_take_frame(&q, &f);
    CHECK(f.scroll_y == 0 && f.button_down[GLFW_MOUSE_BUTTON_LEFT]);
    ui_input_take_frame(&q, &f);
    CHECK(f.scroll_y == -1);
}

static void test_full_queue_coalesces_moves(void)
{
    ui_input_queue_init(&q, 0, 0);
    for (int i = 0; i < 5000; i++)
        push(UI_INPUT_CURSOR, 0, 0, 0, i, i);
    CHECK(q.count == 1 && q.dropped == 0);
    for (int i = 0; i < UI_INPUT_CAPACITY + 10; i++)
        push(UI_INPUT_CHAR, 'a', 0, 0, 0, 0);
    CHECK(q.count == UI_INPUT_CAPACITY && q.dropped == 11);
    ui_input_take_frame(&q, &f);
    CHECK(f.x == 4999 && f.count == UI_INPUT_CAPACITY);
}

int main(void)
{
    test_click_inside_one_frame();
    test_press_waits_for_the_move();
    test_many_short_clicks_all_count();
    test_key_tap_inside_one_frame();
    test_ctrl_a_in_one_frame();
    test_typing_keeps_its_order();
    test_text_then_ctrl();
    test_wheel_after_a_press_waits();
    test_full_queue_coalesces_moves();
    return check_report("input_queue");
}
