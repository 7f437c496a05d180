/* One model of a lamp for every renderer (docs/project-format.md, "Lights"; docs/rendering.md,
 * "Lamps: one model"). A lamp is drawn as a glowing shape (a pendant's opal shade, a mirror
 * light's strip) and lights the room through a light of the project (point, spot, rect). The
 * GPU lights only with the light and shows the shape by the emissive max; a path tracer and the
 * bake would also take the shape's emission for an area light, and the lamp would light the
 * room twice. So each project light's glowing object is marked as a stand-in (the flag a
 * window's exterior panel carries): seen, and seen in mirrors, but not a light of its own.
 * Emitting geometry that no light claims stays an area light of the tracer. */
#include "render_list_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

static int glows(const rd_material *m)
{
    return m->emissive[0] > 0.0f || m->emissive[1] > 0.0f || m->emissive[2] > 0.0f;
}

/* Grows box (min xyz, max xyz, metres) by the world positions of item it. */
static void grow_box(const app_render_list *l, const app_render_item *it, float box[6])
{
    const app_render_mesh *m = &l->meshes[it->mesh];
    const float *t = it->transform;
    int identity = 1;
    for (int k = 0; k < 16; k++)
        identity &= t[k] == 0.0f;
    for (int v = 0; v < m->vertex_count; v++) {
        const float *p = m->positions + 3 * (size_t)v;
        for (int k = 0; k < 3; k++) {
            float w = identity ? p[k] : t[k] * p[0] + t[4 + k] * p[1] + t[8 + k] * p[2] + t[12 + k];
            box[k] = fminf(box[k], w);
            box[3 + k] = fmaxf(box[3 + k], w);
        }
    }
}

/* Distance from point q to box (0 inside). */
static float box_distance(const float box[6], const float q[3])
{
    float d2 = 0.0f;
    for (int k = 0; k < 3; k++) {
        float d = fmaxf(fmaxf(box[k] - q[k], q[k] - box[3 + k]), 0.0f);
        d2 += d * d;
    }
    return sqrtf(d2);
}

/* The object showing light l: the named one, or the glowing object nearest the light within
 * reach of its box; -1 when none. */
static int emitter_of(const app_render_list *list, const app_project *p, const app_light *l)
{
    if (l->emitter_named) {
        for (int i = 0; l->emitter[0] && i < p->object_count; i++)
            if (!strcmp(p->objects[i].name, l->emitter))
                return i;
        return -1;
    }
    if (l->type == APP_LIGHT_DIRECTIONAL)
        return -1;
    float q[3] = {(float)(l->position_mm[0] * 1e-3), (float)(l->position_mm[1] * 1e-3),
                  (float)(l->position_mm[2] * 1e-3)};
    int best = -1;
    float best_d = (float)(APP_LIGHT_EMITTER_REACH_MM * 1e-3);
    for (int o = 0; o < p->object_count; o++) {
        float box[6] = {FLT_MAX, FLT_MAX, FLT_MAX, -FLT_MAX, -FLT_MAX, -FLT_MAX};
        int any = 0;
        for (int i = 0; i < list->item_count; i++) {
            const app_render_item *it = &list->items[i];
            if (it->object == o && glows(&it->material)) {
                grow_box(list, it, box);
                any = 1;
            }
        }
        float d = any ? box_distance(box, q) : FLT_MAX;
        if (d <= best_d) {
            best_d = d;
            best = o;
        }
    }
    return best;
}

void app_list_mark_lamp_glows(app_render_list *list, const app_project *p)
{
    for (int i = 0; i < p->light_count; i++) {
        int o = emitter_of(list, p, &p->lights[i]);
        for (int k = 0; o >= 0 && k < list->item_count; k++) {
            app_render_item *it = &list->items[k];
            if (it->object == o && glows(&it->material))
                it->light_stand_in = 1;
        }
    }
}
