// The C seam over Dear ImGui (ui/src/gui.h): widgets forwarded one to one, and the window's input
// callbacks that feed both Dear ImGui and the planner from one queue (input_queue.h).
#include "gui.h"
#include "input_queue.h"

#include <GLFW/glfw3.h>
#include <cfloat>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>

#include "imgui.h"
#include "backends/imgui_impl_glfw.h"
#include "backends/imgui_impl_opengl3.h"

static bool g_ready = false;
// Inside a docked column (ui_gui_begin_column), panels are its sections: how many are open.
static bool g_in_column = false;
static int g_sections = 0;

// A panel of a docked column: a collapsible header, open at first. collapsed 0/1 applies with
// place (a new layout), -1 leaves it to the user.
static bool begin_section(const char *title, int place, int collapsed)
{
    if (place && collapsed >= 0)
        ImGui::SetNextItemOpen(collapsed == 0, ImGuiCond_Always);
    const char *id = std::strstr(title, "###"); // the stable part of a changing title
    ImGui::PushID(id ? id : title);
    g_sections++;
    return ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen);
}

// Input: the window's GLFW callbacks are this file's. Each pushes its event into one queue
// (input_queue.h) and calls whatever callback was installed before it; each frame takes its
// share once (ui_gui_take_input) and hands the same events to Dear ImGui's GLFW callbacks
// (ui_gui_new_frame) and to the planner (ui_gui_input), so neither misses an event and a
// click shorter than a frame is still a click. Dear ImGui's backend installs no callbacks of
// its own: it would set a key down and up again before the frame saw it.
static GLFWwindow *g_window = nullptr;
static ui_input_queue g_queue;
static ui_input_frame g_frame;
static bool g_frame_taken = false;
static struct {
    GLFWkeyfun key;
    GLFWcharfun chr;
    GLFWmousebuttonfun button;
    GLFWcursorposfun cursor;
    GLFWscrollfun scroll;
    GLFWwindowfocusfun focus;
    GLFWcursorenterfun enter;
} g_previous;

static void push(ui_input_kind kind, int code, int action, int mods, double x, double y)
{
    ui_input_event e;
    e.kind = kind;
    e.code = code;
    e.action = action;
    e.mods = mods;
    e.x = x;
    e.y = y;
    ui_input_push(&g_queue, &e);
}

static void on_key(GLFWwindow *w, int key, int scancode, int action, int mods)
{
    push(UI_INPUT_KEY, key, action, mods, 0, 0);
    if (g_previous.key)
        g_previous.key(w, key, scancode, action, mods);
}

static void on_char(GLFWwindow *w, unsigned int c)
{
    push(UI_INPUT_CHAR, (int)c, 0, 0, 0, 0);
    if (g_previous.chr)
        g_previous.chr(w, c);
}

static void on_button(GLFWwindow *w, int button, int action, int mods)
{
    push(UI_INPUT_BUTTON, button, action, mods, 0, 0);
    if (g_previous.button)
        g_previous.button(w, button, action, mods);
}

static void on_cursor(GLFWwindow *w, double x, double y)
{
    push(UI_INPUT_CURSOR, 0, 0, 0, x, y);
    if (g_previous.cursor)
        g_previous.cursor(w, x, y);
}

static void on_scroll(GLFWwindow *w, double dx, double dy)
{
    push(UI_INPUT_SCROLL, 0, 0, 0, dx, dy);
    if (g_previous.scroll)
        g_previous.scroll(w, dx, dy);
}

// Focus and the pointer entering need no ordering: Dear ImGui takes them at once.
static void on_focus(GLFWwindow *w, int focused)
{
    ImGui_ImplGlfw_WindowFocusCallback(w, focused);
    if (g_previous.focus)
        g_previous.focus(w, focused);
}

static void on_enter(GLFWwindow *w, int entered)
{
    ImGui_ImplGlfw_CursorEnterCallback(w, entered);
    if (g_previous.enter)
        g_previous.enter(w, entered);
}

static void install_callbacks(GLFWwindow *window)
{
    double x, y;
    glfwGetCursorPos(window, &x, &y);
    ui_input_queue_init(&g_queue, x, y);
    std::memset(&g_frame, 0, sizeof g_frame);
    g_frame.x = x;
    g_frame.y = y;
    g_window = window;
    g_previous.key = glfwSetKeyCallback(window, on_key);
    g_previous.chr = glfwSetCharCallback(window, on_char);
    g_previous.button = glfwSetMouseButtonCallback(window, on_button);
    g_previous.cursor = glfwSetCursorPosCallback(window, on_cursor);
    g_previous.scroll = glfwSetScrollCallback(window, on_scroll);
    g_previous.focus = glfwSetWindowFocusCallback(window, on_focus);
    g_previous.enter = glfwSetCursorEnterCallback(window, on_enter);
}

static void remove_callbacks(void)
{
    glfwSetKeyCallback(g_window, g_previous.key);
    glfwSetCharCallback(g_window, g_previous.chr);
    glfwSetMouseButtonCallback(g_window, g_previous.button);
    glfwSetCursorPosCallback(g_window, g_previous.cursor);
    glfwSetScrollCallback(g_window, g_previous.scroll);
    glfwSetWindowFocusCallback(g_window, g_previous.focus);
    glfwSetCursorEnterCallback(g_window, g_previous.enter);
    g_window = nullptr;
}

// Hands this frame's key, character and wheel events to Dear ImGui in their order, then its
// buttons and pointer (the backend's NewFrame polls GLFW for those: the frame's own state
// replaces what it polled).
static void feed_imgui(void)
{
    for (int i = 0; i < g_frame.count; i++) {
        const ui_input_event &e = g_frame.events[i];
        if (e.kind == UI_INPUT_KEY)
            ImGui_ImplGlfw_KeyCallback(g_window, e.code, 0, e.action, e.mods);
        else if (e.kind == UI_INPUT_CHAR)
            ImGui_ImplGlfw_CharCallback(g_window, (unsigned)e.code);
        else if (e.kind == UI_INPUT_SCROLL)
            ImGui_ImplGlfw_ScrollCallback(g_window, e.x, e.y);
    }
}

static void feed_imgui_pointer(void)
{
    ImGuiIO &io = ImGui::GetIO();
    for (int b = 0; b < IM_ARRAYSIZE(io.MouseDown) && b < UI_INPUT_BUTTONS; b++)
        io.MouseDown[b] = g_frame.button_down[b] != 0;
    if (io.MousePos.x != -FLT_MAX) // the pointer is over the window (else the backend knows)
        io.MousePos = ImVec2((float)g_frame.x, (float)g_frame.y);
}

// Where the last frame drew each labelled button and text field, for scripts that drive the
// window with real pointer events (ui_gui_locate).
enum { LOCATED_MAX = 96 };
static struct located {
    char label[64];
    float rect[4];
    bool visible;
    long frame;
} g_located[LOCATED_MAX];
static long g_frame_number = 0;

static void remember_item(const char *label)
{
    int slot = -1;
    for (int i = 0; i < LOCATED_MAX && slot < 0; i++)
        if (!std::strncmp(g_located[i].label, label, sizeof g_located[i].label - 1))
            slot = i;
    for (int i = 0; i < LOCATED_MAX && slot < 0; i++)
        if (!g_located[i].label[0] || g_located[i].frame < g_frame_number - 1)
            slot = i;
    if (slot < 0)
        return;
    located &l = g_located[slot];
    std::snprintf(l.label, sizeof l.label, "%s", label);
    ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    l.rect[0] = a.x;
    l.rect[1] = a.y;
    l.rect[2] = b.x;
    l.rect[3] = b.y;
    // Visible: all of it inside the panel's visible area, not a sliver at its edge.
    l.visible = ImGui::IsRectVisible(ImVec2(a.x + 1, a.y + 1), ImVec2(a.x + 1, a.y + 1)) &&
                ImGui::IsRectVisible(ImVec2(b.x - 1, b.y - 1), ImVec2(b.x - 1, b.y - 1));
    l.frame = g_frame_number;
}

extern "C" int ui_gui_locate(const char *label, float rect[4], int *visible)
{
    for (int i = 0; i < LOCATED_MAX; i++) {
        const located &l = g_located[i];
        if (l.label[0] && l.frame == g_frame_number &&
            !std::strncmp(l.label, label, sizeof l.label - 1)) {
            std::memcpy(rect, l.rect, sizeof l.rect);
            *visible = l.visible;
            return 1;
        }
    }
    return 0;
}

extern "C" void ui_gui_take_input(void)
{
    if (!g_window)
        return;
    ui_input_take_frame(&g_queue, &g_frame);
    g_frame_taken = true;
}

extern "C" int ui_gui_input_pending(void)
{
    return g_queue.count;
}

extern "C" const ui_input_frame *ui_gui_input(void)
{
    return &g_frame;
}

extern "C" int ui_gui_mouse_down(int button)
{
    return button >= 0 && button < UI_INPUT_BUTTONS && g_frame.button_down[button];
}

extern "C" void ui_gui_pointer(double *x, double *y)
{
    *x = g_frame.x;
    *y = g_frame.y;
}

extern "C" int ui_gui_init(GLFWwindow *window, char *err, size_t err_size)
{
    try {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGuiIO &io = ImGui::GetIO();
        io.IniFilename = nullptr; // the planner keeps no imgui.ini next to the user's files
        ImGui::StyleColorsDark();
        // Docked panels are opaque: nothing of a view shows through them, and a panel's pixels
        // are the same colour wherever it is (tests/ui/layout_session.sh looks for them).
        ImGui::GetStyle().Colors[ImGuiCol_WindowBg].w = 1.0f;
        if (!ImGui_ImplGlfw_InitForOpenGL(window, false)) {
            std::snprintf(err, err_size, "Dear ImGui: the GLFW backend failed to start");
            ImGui::DestroyContext();
            return 1;
        }
        if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
            std::snprintf(err, err_size, "Dear ImGui: the OpenGL 3 backend failed to start");
            ImGui_ImplGlfw_Shutdown();
            ImGui::DestroyContext();
            return 1;
        }
        install_callbacks(window);
        g_ready = true;
        return 0;
    } catch (const std::exception &e) {
        std::snprintf(err, err_size, "Dear ImGui: %s", e.what());
        return 1;
    }
}

extern "C" void ui_gui_shutdown(void)
{
    if (!g_ready)
        return;
    remove_callbacks();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    g_ready = false;
}

extern "C" void ui_gui_new_frame(void)
{
    if (!g_ready)
        return;
    if (!g_frame_taken) // nothing read this frame's input before the panels
        ui_gui_take_input();
    g_frame_taken = false;
    g_frame_number++;
    feed_imgui();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    feed_imgui_pointer();
    ImGui::NewFrame();
}

extern "C" void ui_gui_render(void)
{
    if (!g_ready)
        return;
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

extern "C" int ui_gui_wants_mouse(void)
{
    return g_ready && ImGui::GetIO().WantCaptureMouse;
}

extern "C" int ui_gui_wants_keyboard(void)
{
    // A text field activated by this frame's click has the keyboard before the next NewFrame
    // says so.
    return g_ready && (ImGui::GetIO().WantCaptureKeyboard || ImGui::IsAnyItemActive());
}

extern "C" int ui_gui_begin(const char *title, float x, float y, float width, float height)
{
    if (!g_ready)
        return 0;
    if (g_in_column)
        return begin_section(title, 0, -1);
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_FirstUseEver);
    return ImGui::Begin(title);
}

extern "C" int ui_gui_begin_placed(const char *title, float x, float y, float width, float height,
                                   int place, int collapsed)
{
    if (!g_ready)
        return 0;
    if (g_in_column)
        return begin_section(title, place, collapsed);
    ImGuiCond cond = place ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
    ImGui::SetNextWindowPos(ImVec2(x, y), cond);
    ImGui::SetNextWindowSize(ImVec2(width, height), cond);
    if (collapsed >= 0)
        ImGui::SetNextWindowCollapsed(collapsed != 0, cond);
    return ImGui::Begin(title);
}

extern "C" void ui_gui_end(void)
{
    if (!g_ready)
        return;
    if (g_in_column && g_sections > 0) {
        ImGui::PopID();
        g_sections--;
        return;
    }
    ImGui::End();
}

extern "C" int ui_gui_begin_overlay(const char *id, float x, float y, float alpha)
{
    if (!g_ready)
        return 0;
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(alpha);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration |
                                   ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoInputs |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    return ImGui::Begin(id, nullptr, flags);
}

extern "C" void ui_gui_text(const char *fmt, ...)
{
    if (!g_ready)
        return;
    va_list ap;
    va_start(ap, fmt);
    ImGui::TextV(fmt, ap);
    va_end(ap);
}

extern "C" void ui_gui_separator(void)
{
    if (g_ready)
        ImGui::Separator();
}

extern "C" void ui_gui_same_line(void)
{
    if (g_ready)
        ImGui::SameLine();
}

extern "C" int ui_gui_button(const char *label)
{
    if (!g_ready)
        return 0;
    bool pressed = ImGui::Button(label);
    remember_item(label);
    return pressed;
}

extern "C" int ui_gui_combo(const char *label, int *current, const char *const *items, int count)
{
    return g_ready && ImGui::Combo(label, current, items, count);
}

extern "C" int ui_gui_slider_float(const char *label, float *value, float lo, float hi)
{
    return g_ready && ImGui::SliderFloat(label, value, lo, hi);
}

extern "C" int ui_gui_input_text(const char *label, char *buf, size_t size)
{
    if (!g_ready)
        return 0;
    bool changed = ImGui::InputText(label, buf, size);
    remember_item(label);
    return changed;
}

extern "C" int ui_gui_selectable(const char *label, int selected)
{
    return g_ready && ImGui::Selectable(label, selected != 0);
}

extern "C" void ui_gui_plot_lines(const char *label, const float *values, int count, float lo,
                                  float hi, float width, float height)
{
    if (g_ready)
        ImGui::PlotLines(label, values, count, 0, nullptr, lo, hi, ImVec2(width, height));
}

extern "C" void ui_gui_text_wrapped(const char *text)
{
    if (g_ready)
        ImGui::TextWrapped("%s", text);
}

extern "C" int ui_gui_input_float(const char *label, float *value, float step)
{
    return g_ready && ImGui::InputFloat(label, value, step, step * 10.0f, "%.0f");
}

extern "C" int ui_gui_list_row(const char *label, int selected)
{
    return g_ready && ImGui::Selectable(label, selected != 0, ImGuiSelectableFlags_SpanAllColumns);
}

extern "C" int ui_gui_begin_child(const char *id, float width, float height)
{
    return g_ready && ImGui::BeginChild(id, ImVec2(width, height), true);
}

extern "C" void ui_gui_end_child(void)
{
    if (g_ready)
        ImGui::EndChild();
}

static ImDrawList *background(void)
{
    return ImGui::GetBackgroundDrawList();
}

extern "C" void ui_gui_draw_line(float x0, float y0, float x1, float y1, unsigned colour,
                                 float thickness)
{
    if (g_ready)
        background()->AddLine(ImVec2(x0, y0), ImVec2(x1, y1), colour, thickness);
}

extern "C" void ui_gui_draw_quad_filled(const float xy[8], unsigned colour)
{
    if (g_ready)
        background()->AddQuadFilled(ImVec2(xy[0], xy[1]), ImVec2(xy[2], xy[3]),
                                    ImVec2(xy[4], xy[5]), ImVec2(xy[6], xy[7]), colour);
}

extern "C" void ui_gui_draw_rect(float x0, float y0, float x1, float y1, unsigned colour,
                                 float thickness)
{
    if (g_ready)
        background()->AddRect(ImVec2(x0, y0), ImVec2(x1, y1), colour, 0.0f, 0, thickness);
}

extern "C" void ui_gui_draw_circle(float x, float y, float radius, unsigned colour, int filled)
{
    if (!g_ready)
        return;
    if (filled)
        background()->AddCircleFilled(ImVec2(x, y), radius, colour);
    else
        background()->AddCircle(ImVec2(x, y), radius, colour);
}

extern "C" void ui_gui_draw_arc(float cx, float cy, float radius, float a0, float a1,
                                unsigned colour, float thickness)
{
    if (!g_ready)
        return;
    ImDrawList *d = background();
    d->PathArcTo(ImVec2(cx, cy), radius, a0, a1, 24);
    d->PathStroke(colour, 0, thickness);
}

extern "C" void ui_gui_draw_text(float x, float y, unsigned colour, const char *text)
{
    if (g_ready)
        background()->AddText(ImVec2(x, y), colour, text);
}

extern "C" int ui_gui_input_double_enter(const char *label, double *value)
{
    return g_ready &&
           ImGui::InputDouble(label, value, 0.0, 0.0, "%.0f", ImGuiInputTextFlags_EnterReturnsTrue);
}

extern "C" int ui_gui_slider_commit(const char *label, float *value, float lo, float hi)
{
    if (!g_ready)
        return 0;
    ImGui::SliderFloat(label, value, lo, hi);
    return ImGui::IsItemDeactivatedAfterEdit();
}

static ImTextureID texture_id(unsigned texture)
{
    return (ImTextureID)(intptr_t)texture;
}

extern "C" void ui_gui_image(unsigned texture, float width, float height)
{
    if (g_ready && texture)
        ImGui::Image(texture_id(texture), ImVec2(width, height));
}

extern "C" int ui_gui_item_dragged(void)
{
    return g_ready && ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left);
}

extern "C" int ui_gui_item_visible(void)
{
    return g_ready && ImGui::IsItemVisible();
}

extern "C" int ui_gui_pointer_over_panel(void)
{
    return g_ready && ImGui::IsWindowHovered(ImGuiHoveredFlags_AnyWindow |
                                             ImGuiHoveredFlags_AllowWhenBlockedByActiveItem);
}

extern "C" void ui_gui_draw_ghost(float x, float y, unsigned texture, float image_size,
                                  const char *text)
{
    if (!g_ready)
        return;
    ImDrawList *d = ImGui::GetForegroundDrawList();
    float img = texture ? image_size : 0.0f;
    ImVec2 ts = ImGui::CalcTextSize(text);
    ImVec2 a(x + 14.0f, y + 14.0f);
    ImVec2 b(a.x + img + ts.x + 16.0f, a.y + (img > ts.y ? img : ts.y) + 8.0f);
    d->AddRectFilled(a, b, IM_COL32(30, 30, 36, 200), 4.0f);
    d->AddRect(a, b, IM_COL32(240, 200, 80, 255), 4.0f);
    if (texture)
        d->AddImage(texture_id(texture), ImVec2(a.x + 4.0f, a.y + 4.0f),
                    ImVec2(a.x + 4.0f + img, a.y + 4.0f + img));
    d->AddText(ImVec2(a.x + img + 10.0f, a.y + 4.0f), IM_COL32(255, 255, 255, 255), text);
    d->AddCircleFilled(ImVec2(x, y), 4.0f, IM_COL32(240, 200, 80, 255));
}

extern "C" int ui_gui_image_row(const char *id, const char *text, int selected, unsigned texture,
                                float size)
{
    if (!g_ready)
        return 0;
    ImVec2 start = ImGui::GetCursorScreenPos();
    bool clicked = ImGui::Selectable(id, selected != 0, 0, ImVec2(0.0f, size));
    // The image at the row's left end, the text beside it, vertically centred.
    ImDrawList *d = ImGui::GetWindowDrawList();
    if (texture)
        d->AddImage(texture_id(texture), start, ImVec2(start.x + size, start.y + size));
    else
        d->AddRect(start, ImVec2(start.x + size, start.y + size), IM_COL32(120, 120, 120, 160));
    float th = ImGui::CalcTextSize(text).y;
    d->AddText(ImVec2(start.x + size + 8.0f, start.y + (size - th) * 0.5f),
               ImGui::GetColorU32(ImGuiCol_Text), text);
    return clicked;
}

extern "C" int ui_gui_begin_menu_bar(void)
{
    return g_ready && ImGui::BeginMainMenuBar();
}

extern "C" void ui_gui_end_menu_bar(void)
{
    if (g_ready)
        ImGui::EndMainMenuBar();
}

extern "C" int ui_gui_begin_menu(const char *label, int enabled)
{
    return g_ready && ImGui::BeginMenu(label, enabled != 0);
}

extern "C" void ui_gui_end_menu(void)
{
    if (g_ready)
        ImGui::EndMenu();
}

extern "C" int ui_gui_menu_item(const char *label, const char *shortcut, int checked, int enabled)
{
    if (!g_ready)
        return 0;
    if (checked < 0)
        return ImGui::MenuItem(label, shortcut, false, enabled != 0);
    return ImGui::MenuItem(label, shortcut, checked != 0, enabled != 0);
}

static const ImGuiWindowFlags fixed_flags =
    ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
    ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoFocusOnAppearing;

extern "C" int ui_gui_begin_bar(const char *id, float x, float y, float width, float height,
                                float pad)
{
    if (!g_ready)
        return 0;
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(pad, pad));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    // The splitter is narrower than a window's default least size (32 px).
    ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1.0f, 1.0f));
    bool open = ImGui::Begin(id, nullptr,
                             fixed_flags | ImGuiWindowFlags_NoScrollbar |
                                 ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoNav);
    ImGui::PopStyleVar(4);
    return open;
}

extern "C" int ui_gui_begin_column(const char *id, float x, float y, float width, float height)
{
    if (!g_ready)
        return 0;
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
    bool open = ImGui::Begin(id, nullptr, fixed_flags);
    ImGui::PopStyleVar();
    g_in_column = true;
    g_sections = 0;
    return open;
}

extern "C" void ui_gui_end_column(void)
{
    if (!g_ready)
        return;
    while (g_sections > 0) { // a panel left without its ui_gui_end
        ImGui::PopID();
        g_sections--;
    }
    g_in_column = false;
    ImGui::End();
}

extern "C" int ui_gui_icon_button(const char *id, const float *segments, int count, float size,
                                  int active, const char *tooltip)
{
    if (!g_ready)
        return 0;
    if (active)
        ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    ImVec2 at = ImGui::GetCursorScreenPos();
    bool clicked = ImGui::Button(id, ImVec2(size, size));
    if (active)
        ImGui::PopStyleColor();
    ImDrawList *d = ImGui::GetWindowDrawList();
    float pad = size * 0.2f, s = size - 2.0f * pad;
    ImU32 ink = ImGui::GetColorU32(ImGuiCol_Text);
    for (int i = 0; i < count; i++) {
        const float *g = segments + 4 * i;
        d->AddLine(ImVec2(at.x + pad + g[0] * s, at.y + pad + g[1] * s),
                   ImVec2(at.x + pad + g[2] * s, at.y + pad + g[3] * s), ink, 1.5f);
    }
    if (tooltip && ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", tooltip);
    return clicked;
}

extern "C" void ui_gui_item_tooltip(const char *text)
{
    if (g_ready && ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", text);
}

extern "C" int ui_gui_drag_handle(const char *id, float width, float height, float *pointer_x)
{
    if (!g_ready)
        return 0;
    ImGui::InvisibleButton(id, ImVec2(width, height));
    bool held = ImGui::IsItemActive(), hovered = ImGui::IsItemHovered();
    if (held || hovered)
        ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    // A grip line down the middle, lit while the pointer is on it, as separators are.
    ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    ImGuiCol grip = held      ? ImGuiCol_SeparatorActive
                    : hovered ? ImGuiCol_SeparatorHovered
                              : ImGuiCol_Separator;
    float mid = 0.5f * (a.x + b.x);
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(mid - 1.0f, a.y), ImVec2(mid + 1.0f, b.y),
                                              ImGui::GetColorU32(grip));
    *pointer_x = ImGui::GetIO().MousePos.x;
    return held;
}

extern "C" void ui_gui_same_line_at(float x)
{
    if (g_ready)
        ImGui::SameLine(x);
}

extern "C" float ui_gui_text_width(const char *text)
{
    return g_ready ? ImGui::CalcTextSize(text).x : 0.0f;
}

extern "C" int ui_gui_begin_closable(const char *title, float x, float y, float width, float height,
                                     int *open)
{
    if (!g_ready)
        return 0;
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Appearing);
    ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Appearing);
    bool keep = *open != 0;
    bool shown = ImGui::Begin(title, &keep, ImGuiWindowFlags_NoSavedSettings);
    *open = keep;
    return shown;
}

extern "C" void ui_gui_clip_push(float x0, float y0, float x1, float y1)
{
    if (g_ready)
        background()->PushClipRect(ImVec2(x0, y0), ImVec2(x1, y1), true);
}

extern "C" void ui_gui_clip_pop(void)
{
    if (g_ready)
        background()->PopClipRect();
}

extern "C" void ui_gui_progress_bar(float fraction, const char *text)
{
    if (!g_ready)
        return;
    /* Unknown progress: a bar that sweeps with the clock, so the panel shows the job is alive. */
    float f = fraction >= 0 ? fraction : 0.5f + 0.5f * sinf((float)ImGui::GetTime() * 3.0f);
    ImGui::ProgressBar(f, ImVec2(-1.0f, 0.0f), text);
}
