// The C seam over Dear ImGui (ui/src/gui.h): widgets forwarded one to one, no logic here.
#include "gui.h"

#include <GLFW/glfw3.h>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <exception>

#include "imgui.h"
#include "backends/imgui_impl_glfw.h"
#include "backends/imgui_impl_opengl3.h"

static bool g_ready = false;

extern "C" int ui_gui_init(GLFWwindow *window, char *err, size_t err_size)
{
    try {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGuiIO &io = ImGui::GetIO();
        io.IniFilename = nullptr; // the planner keeps no imgui.ini next to the user's files
        ImGui::StyleColorsDark();
        if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) {
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
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    g_ready = false;
}

extern "C" void ui_gui_new_frame(void)
{
    if (!g_ready)
        return;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
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
    return g_ready && ImGui::GetIO().WantCaptureKeyboard;
}

extern "C" int ui_gui_begin(const char *title, float x, float y, float width, float height)
{
    if (!g_ready)
        return 0;
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_FirstUseEver);
    return ImGui::Begin(title);
}

extern "C" int ui_gui_begin_placed(const char *title, float x, float y, float width, float height,
                                   int place, int collapsed)
{
    if (!g_ready)
        return 0;
    ImGuiCond cond = place ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
    ImGui::SetNextWindowPos(ImVec2(x, y), cond);
    ImGui::SetNextWindowSize(ImVec2(width, height), cond);
    if (collapsed >= 0)
        ImGui::SetNextWindowCollapsed(collapsed != 0, cond);
    return ImGui::Begin(title);
}

extern "C" void ui_gui_end(void)
{
    if (g_ready)
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
    return g_ready && ImGui::Button(label);
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
    return g_ready && ImGui::InputText(label, buf, size);
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

extern "C" void ui_gui_progress_bar(float fraction, const char *text)
{
    if (!g_ready)
        return;
    /* Unknown progress: a bar that sweeps with the clock, so the panel shows the job is alive. */
    float f = fraction >= 0 ? fraction : 0.5f + 0.5f * sinf((float)ImGui::GetTime() * 3.0f);
    ImGui::ProgressBar(f, ImVec2(-1.0f, 0.0f), text);
}
