/* The thin C seam over Dear ImGui (C++; ARCHITECTURE.md "the C/C++ seam"): the widgets the
 * planner's panels use, nothing more. Implemented in gui_imgui.cpp with the GLFW and OpenGL 3
 * backends that ship with Debian's libimgui-dev. Every function is a no-op returning 0 before
 * ui_gui_init. */
#ifndef UI_GUI_H
#define UI_GUI_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

struct GLFWwindow;

/* 0 on success; err gets the reason otherwise. */
int ui_gui_init(struct GLFWwindow *window, char *err, size_t err_size);
void ui_gui_shutdown(void);
void ui_gui_new_frame(void);
/* Draws the frame's widgets into the current framebuffer (after the 3D view). */
void ui_gui_render(void);
/* 1 when the pointer or the keyboard belong to a widget, not to the 3D view. */
int ui_gui_wants_mouse(void);
int ui_gui_wants_keyboard(void);

/* Input (input_queue.h). ui_gui_init installs the window's key, character, button, pointer
 * and wheel callbacks (chained to any installed before); they queue every event. Once a frame,
 * before anything reads input, ui_gui_take_input takes the frame's share; ui_gui_new_frame
 * hands the same events to Dear ImGui. The planner reads them here, never by polling GLFW, so
 * a press and release inside one frame is still seen as one frame held. */
struct ui_input_frame;
void ui_gui_take_input(void);
const struct ui_input_frame *ui_gui_input(void);
/* Events still waiting for a later frame. */
int ui_gui_input_pending(void);
/* 1 while the button (GLFW_MOUSE_BUTTON_*) is held this frame. */
int ui_gui_mouse_down(int button);
/* The pointer in window pixels as of this frame's events. */
void ui_gui_pointer(double *x, double *y);
/* Where the last frame drew the button or text field labelled label (window pixels x0 y0 x1
 * y1) and whether all of it was inside its panel's visible area; 0 when it was not drawn. */
int ui_gui_locate(const char *label, float rect[4], int *visible);

/* A panel at a fixed place the first time it is shown. Always pair with ui_gui_end. */
int ui_gui_begin(const char *title, float x, float y, float width, float height);
/* A panel placed by the layout (panel_layout.h): place = 1 moves and sizes it to the
 * rectangle now (the window's size changed), else only the first time; collapsed 0/1 sets its
 * collapsed state with it, -1 leaves it to the user. */
int ui_gui_begin_placed(const char *title, float x, float y, float width, float height, int place,
                        int collapsed);
void ui_gui_end(void);
/* A borderless, input-transparent overlay (frame time, product card). */
int ui_gui_begin_overlay(const char *id, float x, float y, float alpha);

void ui_gui_text(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void ui_gui_separator(void);
void ui_gui_same_line(void);
int ui_gui_button(const char *label);
int ui_gui_combo(const char *label, int *current, const char *const *items, int count);
int ui_gui_slider_float(const char *label, float *value, float lo, float hi);
int ui_gui_input_text(const char *label, char *buf, size_t size);
int ui_gui_selectable(const char *label, int selected);
void ui_gui_text_wrapped(const char *text);
int ui_gui_input_float(const char *label, float *value, float step);
/* A row of the list being drawn; returns 1 when clicked. */
int ui_gui_list_row(const char *label, int selected);
int ui_gui_begin_child(const char *id, float width, float height);
void ui_gui_end_child(void);
/* Drawing on the background behind every panel (the plan and elevation views), in window
 * pixels; colours are 0xAABBGGRR as Dear ImGui packs them. */
void ui_gui_draw_line(float x0, float y0, float x1, float y1, unsigned colour, float thickness);
void ui_gui_draw_quad_filled(const float xy[8], unsigned colour); /* convex */
void ui_gui_draw_rect(float x0, float y0, float x1, float y1, unsigned colour, float thickness);
void ui_gui_draw_circle(float x, float y, float radius, unsigned colour, int filled);
void ui_gui_draw_arc(float cx, float cy, float radius, float a0, float a1, unsigned colour,
                     float thickness);
void ui_gui_draw_text(float x, float y, unsigned colour, const char *text);
/* A slider whose value is committed when the user lets go (one undo step per change);
 * returns 1 then. *value follows the drag meanwhile. */
int ui_gui_slider_commit(const char *label, float *value, float lo, float hi);
/* Text input with a number (exact lengths); returns 1 when Enter was pressed. */
int ui_gui_input_double_enter(const char *label, double *value);
void ui_gui_plot_lines(const char *label, const float *values, int count, float lo, float hi,
                       float width, float height);

/* Images, drag sources and the pointer (thumbnails and drag and drop). */
/* An image of a GL texture (render/ui_texture.h) at width x height pixels. */
void ui_gui_image(unsigned texture, float width, float height);
/* 1 when the last widget was pressed and the pointer has moved past the drag threshold. */
int ui_gui_item_dragged(void);
/* 1 when the last widget is inside its window's visible area (lazy thumbnails). */
int ui_gui_item_visible(void);
/* 1 when the pointer is over any panel (a drop there is no drop). */
int ui_gui_pointer_over_panel(void);
/* A label with an optional image (texture 0: none) at (x, y) above every panel: the ghost that
 * follows the pointer while a product is dragged. */
void ui_gui_draw_ghost(float x, float y, unsigned texture, float image_size, const char *text);
/* A selectable row (id "##...") of the image's height: the image (texture 0: an empty frame),
 * then text; returns 1 when clicked. */
int ui_gui_image_row(const char *id, const char *text, int selected, unsigned texture, float size);
/* A progress bar the panel's width; fraction < 0 shows an indeterminate bar with the text. */
void ui_gui_progress_bar(float fraction, const char *text);

/* The window's frame (menu_bar.c, toolbar.c, status_bar.c, window_panes.c). */
/* The main menu bar at the window's top; ui_gui_end_menu_bar only when begin returned 1. */
int ui_gui_begin_menu_bar(void);
void ui_gui_end_menu_bar(void);
/* A menu of the bar (or a submenu); ui_gui_end_menu only when begin returned 1. */
int ui_gui_begin_menu(const char *label, int enabled);
void ui_gui_end_menu(void);
/* A menu entry with its keyboard shortcut shown at the right (NULL: none); checked 0/1 shows a
 * check mark, -1 none. Returns 1 when chosen. */
int ui_gui_menu_item(const char *label, const char *shortcut, int checked, int enabled);
/* A fixed undecorated window at a rectangle (toolbar, status bar, splitter) with pad pixels of
 * padding, never scrolled. Always pair with ui_gui_end. */
int ui_gui_begin_bar(const char *id, float x, float y, float width, float height, float pad);
/* A docked panel column at a rectangle: it scrolls, and every panel opened inside it with
 * ui_gui_begin_placed or ui_gui_begin becomes a collapsible section of it (its ui_gui_end
 * closes the section). Always pair with ui_gui_end_column. */
int ui_gui_begin_column(const char *id, float x, float y, float width, float height);
void ui_gui_end_column(void);
/* A square toolbar button of size pixels (id "##..."), its icon drawn from count line segments
 * (x0 y0 x1 y1, in a unit square, y down), the tooltip on hover; active draws it pressed.
 * Returns 1 when clicked. */
int ui_gui_icon_button(const char *id, const float *segments, int count, float size, int active,
                       const char *tooltip);
/* A tooltip for the last widget while the pointer is over it. */
void ui_gui_item_tooltip(const char *text);
/* An invisible handle of width x height at the cursor (the splitter); *pointer_x gets the
 * pointer's window x. Returns 1 while it is being dragged. */
int ui_gui_drag_handle(const char *id, float width, float height, float *pointer_x);
/* The next widget on this row, starting x pixels from the window's left edge. */
void ui_gui_same_line_at(float x);
/* The width of text in the current font, pixels. */
float ui_gui_text_width(const char *text);
/* A window the user can close (its title bar's X clears *open). Always pair with ui_gui_end. */
int ui_gui_begin_closable(const char *title, float x, float y, float width, float height,
                          int *open);
/* Drawing on the background list inside a rectangle only (a pane); pairs. */
void ui_gui_clip_push(float x0, float y0, float x1, float y1);
void ui_gui_clip_pop(void);

#ifdef __cplusplus
}
#endif
#endif
