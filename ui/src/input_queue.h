/* The window's input as a queue of events between frames, so that nothing a hand does is lost
 * to a slow frame: GLFW's callbacks push every key, character, button, pointer and wheel event;
 * each frame takes its share in order, with at most one change per key or button, so a press
 * and release that both happened inside one frame show as held for one frame and released in
 * the next (the trickling of Dear ImGui 1.87's input queue, which Debian's 1.86 lacks). Dear
 * ImGui and the planner both read the same frame. Pure C, no window: tests/ui/test_input_queue.c
 * drives it. */
#ifndef UI_INPUT_QUEUE_H
#define UI_INPUT_QUEUE_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum ui_input_kind {
    UI_INPUT_KEY,    /* code: GLFW key, action: GLFW_PRESS, GLFW_RELEASE or GLFW_REPEAT */
    UI_INPUT_CHAR,   /* code: a Unicode code point typed */
    UI_INPUT_BUTTON, /* code: GLFW mouse button, action: GLFW_PRESS or GLFW_RELEASE */
    UI_INPUT_CURSOR, /* x, y: the pointer in window coordinates */
    UI_INPUT_SCROLL  /* x, y: wheel steps (y > 0: away from the user) */
} ui_input_kind;

typedef struct ui_input_event {
    ui_input_kind kind;
    int code, action, mods;
    double x, y;
} ui_input_event;

enum {
    UI_INPUT_CAPACITY = 1024, /* events waiting; a frame that stalls for seconds can fill it */
    UI_INPUT_BUTTONS = 8,     /* GLFW_MOUSE_BUTTON_LAST + 1 */
    UI_INPUT_KEYS = 512       /* above GLFW_KEY_LAST */
};

/* One frame's events and the state they leave: what this frame acts on. */
typedef struct ui_input_frame {
    ui_input_event events[UI_INPUT_CAPACITY];
    int count;
    int button_down[UI_INPUT_BUTTONS]; /* held during this frame (a 1-frame click included) */
    double x, y;                       /* the pointer after this frame's events */
    double scroll_x, scroll_y;         /* this frame's wheel steps */
} ui_input_frame;

typedef struct ui_input_queue {
    ui_input_event events[UI_INPUT_CAPACITY];
    int head, count;
    long dropped; /* events lost because the queue was full (cursor moves coalesce first) */
    /* The state as far as frames have taken events. */
    unsigned char key_down[UI_INPUT_KEYS];
    int button_down[UI_INPUT_BUTTONS];
    double x, y;
} ui_input_queue;

/* An empty queue with the pointer at (x, y). */
void ui_input_queue_init(ui_input_queue *q, double x, double y);
/* Appends an event (from a GLFW callback). A cursor move right after another replaces it. */
void ui_input_push(ui_input_queue *q, const ui_input_event *e);
/* Takes the next frame's events, in order, stopping before the first event that would:
 * change a key or a button a second time; press or release a button after the pointer moved,
 * a button changed or the wheel turned (the press lands where the pointer was, on what the
 * last frame showed there); move the pointer or turn the wheel after a button changed; or mix
 * typed characters with keys that edit text (Backspace, arrows, Ctrl+A, ...) or modifiers in
 * either order.
 * The rest waits for the next frame. Fills f (f->count may be 0). */
void ui_input_take_frame(ui_input_queue *q, ui_input_frame *f);

#ifdef __cplusplus
}
#endif
#endif
