/* Presentation mode for a customer at the showroom table: the UI hidden but
 * for a caption, smooth flights between stored viewpoints, an automatic tour, a turntable, and
 * one key for a print-quality screenshot. */
#include "planner.h"

#include "app/design/quantities.h"
#include "gui.h"
#include "render/image_io.h"

#include <GLFW/glfw3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TOUR_HOLD_S 4.0   /* seconds at each viewpoint */
#define TOUR_FLIGHT_S 2.5 /* seconds between two */
#define TURNTABLE_DEG_PER_S 12.0

void planner_view_points(const planner *p, double eye[3], double target[3])
{
    app_point2 box[4];
    app_room_plan fallback;
    const app_room_plan *plan = planner_plan(p, box, &fallback);
    if (p->flight.active) {
        ui_view_blend(p->flight.from_eye, p->flight.from_target, p->flight.to_eye,
                      p->flight.to_target, p->flight.elapsed / p->flight.duration, eye, target);
        /* A straight flight across an L-shaped room's inner corner would leave it. */
        ui_room_clamp_point(plan, eye, UI_CAMERA_MARGIN_MM);
    } else if (p->mode == UI_MODE_WALK) {
        memcpy(eye, p->walk.eye, 3 * sizeof *eye);
        ui_walk_target(&p->walk, target);
    } else {
        ui_orbit_eye_inside(&p->orbit, plan, eye, target);
    }
}

void planner_fly_to_camera(planner *p, int index, double seconds)
{
    if (index < 0 || index >= p->project.camera_count)
        return;
    if (seconds <= 0) {
        planner_jump_to_camera(p, index);
        return;
    }
    const app_camera *c = &p->project.cameras[index];
    planner_view_points(p, p->flight.from_eye, p->flight.from_target);
    memcpy(p->flight.to_eye, c->position_mm, sizeof p->flight.to_eye);
    memcpy(p->flight.to_target, c->target_mm, sizeof p->flight.to_target);
    p->flight.elapsed = 0;
    p->flight.duration = seconds;
    p->flight.camera = index;
    p->flight.active = 1;
    p->mode = UI_MODE_ORBIT;
}

void planner_animate(planner *p, double dt)
{
    if (!(dt > 0) || dt > 1)
        dt = 1.0 / 30.0; /* a stall (a probe capture, a breakpoint) is not a jump in time */
    if (p->flight.active) {
        p->flight.elapsed += dt;
        if (p->flight.elapsed >= p->flight.duration) {
            p->flight.active = 0;
            planner_jump_to_camera(p, p->flight.camera);
        }
        return;
    }
    if (p->touring && p->project.camera_count > 1) {
        p->tour_clock += dt;
        if (p->tour_clock >= TOUR_HOLD_S) {
            p->tour_clock = 0;
            int next = p->camera < 0 ? 0 : (p->camera + 1) % p->project.camera_count;
            planner_fly_to_camera(p, next, TOUR_FLIGHT_S);
        }
    }
    if (p->turntable && p->mode == UI_MODE_ORBIT)
        p->orbit.yaw_deg = fmod(p->orbit.yaw_deg + TURNTABLE_DEG_PER_S * dt, 360.0);
}

/* The product card of the selected fixture: what the customer points at, with its price. */
static void product_card(planner *p, int width)
{
    int i = p->plan_o.selected_object;
    if (i < 0 || i >= p->project.object_count || !p->project.objects[i].has_product ||
        !p->browser.db)
        return;
    const app_product_ref *ref = &p->project.objects[i].product;
    static cat_product card;
    static app_product_ref shown;
    if (memcmp(&shown, ref, sizeof shown)) {
        char err[1024];
        cat_product_free(&card);
        if (cat_product_find(p->browser.db, ref->manufacturer, ref->article, &card, err,
                             sizeof err) != CAT_DB_OK)
            return;
        shown = *ref;
    }
    long long cents = card.price_cents;
    const char *finish = "";
    for (int v = 0; v < card.variant_count; v++)
        if (!strcmp(card.variants[v].code, ref->variant)) {
            cents += card.variants[v].surcharge_cents;
            finish = card.variants[v].name;
        }
    if (ui_gui_begin_overlay("##product-card", (float)width - 380.0f, 20.0f, 0.6f)) {
        ui_gui_text("%s", card.name);
        ui_gui_text("%s %s, art. %s", card.manufacturer, card.series, card.article);
        if (*finish)
            ui_gui_text("finish: %s", finish);
        ui_gui_text("%.0f x %.0f x %.0f mm", card.width_mm, card.depth_mm, card.height_mm);
        char vat[32];
        ui_gui_text("%lld.%02lld %s + %s %% VAT", cents / 100, cents % 100, card.currency,
                    app_format_percent(card.vat_percent, vat, sizeof vat));
    }
    ui_gui_end();
}

void planner_draw_presentation(planner *p, int width, int height)
{
    product_card(p, width);
    if (ui_gui_begin_overlay("##caption", 20.0f, (float)height - 70.0f, 0.4f)) {
        ui_gui_text("%s", p->project.name);
        int cam = p->flight.active ? p->flight.camera : p->camera;
        if (cam >= 0)
            ui_gui_text("%s", p->project.cameras[cam].name);
    }
    ui_gui_end();
}

int planner_print_shot(planner *p, const char *path)
{
    int w, h;
    glfwGetFramebufferSize(p->window, &w, &h);
    w *= 2;
    h *= 2;
    const app_quality *print = app_quality_find("print");
    if (print)
        app_quality_apply(print, p->scene.scene);
    int saved = p->quality;
    p->quality = 3; /* planner_view takes the supersampling from it */
    rd_view v;
    planner_view(p, w, h, &v);
    p->quality = saved;
    size_t size = (size_t)w * (size_t)h * 4;
    unsigned char *px = malloc(size);
    char err[1024];
    int rc = 1;
    if (!px)
        fprintf(stderr, "tessera: print screenshot: out of memory\n");
    else if (rd_render(p->ctx, p->scene.scene, &v) != RD_OK ||
             rd_read_rgba8(p->ctx, px, size) != RD_OK)
        fprintf(stderr, "tessera: print screenshot: %s\n", rd_last_error());
    else if (rd_image_write_rgba8(path, w, h, px, err, sizeof err) != RD_IMAGE_OK)
        fprintf(stderr, "tessera: print screenshot: %s\n", err);
    else {
        fprintf(stderr, "tessera: print-quality screenshot %s (%dx%d)\n", path, w, h);
        rc = 0;
    }
    free(px);
    /* The live view puts its own settings back (planner_live.c). */
    p->live.applied = -1;
    p->live.serial++;
    return rc;
}

void planner_toggle_fullscreen(planner *p)
{
    GLFWmonitor *m = glfwGetWindowMonitor(p->window);
    if (m) {
        int *r = p->windowed_pos;
        glfwSetWindowMonitor(p->window, NULL, r[0], r[1], r[2] > 0 ? r[2] : 1280,
                             r[3] > 0 ? r[3] : 720, GLFW_DONT_CARE);
        return;
    }
    m = glfwGetPrimaryMonitor();
    const GLFWvidmode *mode = m ? glfwGetVideoMode(m) : NULL;
    if (!mode)
        return;
    glfwGetWindowPos(p->window, &p->windowed_pos[0], &p->windowed_pos[1]);
    glfwGetWindowSize(p->window, &p->windowed_pos[2], &p->windowed_pos[3]);
    glfwSetWindowMonitor(p->window, m, 0, 0, mode->width, mode->height, mode->refreshRate);
}
