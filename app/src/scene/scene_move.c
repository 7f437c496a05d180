/* Moving a project object in a built scene (app_scene_move_object): the document first, then
 * the renderer objects drawn for it. The render list puts one renderer object per item, in the
 * list's order, so item i is renderer object i. */
#include "scene_build_internal.h"

#include <stdlib.h>

struct app_scene_parts {
    int *object; /* per renderer object: the project object it draws, -1 = the room */
    int count;
    double (*offsets_mm)[3]; /* per project object: drawn minus document position */
    int object_count;
};

app_result app_scene_parts_make(const app_render_list *l, app_scene *s)
{
    app_scene_parts *m = calloc(1, sizeof *m);
    if (!m)
        return APP_ERR_OUT_OF_MEMORY;
    s->parts = m;
    m->object = malloc(((size_t)l->item_count + 1) * sizeof *m->object);
    m->offsets_mm = malloc(((size_t)l->object_count + 1) * sizeof *m->offsets_mm);
    if (!m->object || !m->offsets_mm)
        return APP_ERR_OUT_OF_MEMORY;
    for (int i = 0; i < l->item_count; i++)
        m->object[i] = l->items[i].object;
    m->count = l->item_count;
    if (l->object_count)
        memcpy(m->offsets_mm, l->object_offsets_mm,
               (size_t)l->object_count * sizeof *m->offsets_mm);
    m->object_count = l->object_count;
    return APP_OK;
}

void app_scene_parts_free(app_scene *s)
{
    if (!s->parts)
        return;
    free(s->parts->object);
    free(s->parts->offsets_mm);
    free(s->parts);
    s->parts = NULL;
}

app_result app_scene_move_object(app_scene *s, app_project *p, int object,
                                 const double position_mm[3])
{
    const app_scene_parts *m = s->parts;
    if (!m || object < 0 || object >= p->object_count || object >= m->object_count ||
        m->count != rd_scene_object_count(s->scene))
        return APP_ERR_NOT_FOUND;
    memcpy(p->objects[object].position_mm, position_mm, sizeof p->objects[object].position_mm);
    for (int i = 0; i < m->count; i++) {
        rd_object_desc d;
        if (m->object[i] != object || rd_scene_object_desc(s->scene, i, &d) != RD_OK)
            continue;
        /* The translation column, as app_object_transform makes it from the drawn position. */
        for (int k = 0; k < 3; k++)
            d.transform[12 + k] = (float)((position_mm[k] + m->offsets_mm[object][k]) * 1e-3);
        rd_scene_set_transform(s->scene, i, d.transform);
    }
    return APP_OK;
}
