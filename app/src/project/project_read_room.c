/* $.room: the materials of floor, walls and ceiling. Since version 2 the room's shape is
 * $.plan (project_read_plan.c); a version 1 box was turned into a plan by the migration. */
#include "project_internal.h"

app_result pj_read_room(pj_ctx *c, const cJSON *root)
{
    const cJSON *room;
    app_result r = pj_member(c, root, "room", cJSON_Object, 1, &room);
    if (r != APP_OK)
        return r;
    size_t mark = pj_path_key(c, "room");
    app_room *out = &c->p->room;
    if ((r = pj_material_ref(c, room, "floor", "room.floor#material", &out->floor_material)) !=
            APP_OK ||
        (r = pj_material_ref(c, room, "walls", "room.walls#material", &out->wall_material)) !=
            APP_OK ||
        (r = pj_material_ref(c, room, "ceiling", "room.ceiling#material",
                             &out->ceiling_material)) != APP_OK)
        return r;
    pj_path_restore(c, mark);
    return APP_OK;
}
