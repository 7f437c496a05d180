/* $.room: the interior size and the materials of floor, walls and ceiling. */
#include "project_internal.h"

static const pj_range ROOM_SIZE = {0.0, APP_PROJECT_MAX_ROOM_MM, 1, 0, 0};

app_result pj_read_room(pj_ctx *c, const cJSON *root)
{
    const cJSON *room;
    app_result r = pj_member(c, root, "room", cJSON_Object, 1, &room);
    if (r != APP_OK)
        return r;
    size_t mark = pj_path_key(c, "room");
    app_room *out = &c->p->room;
    if ((r = pj_get_number(c, room, "width", 1, ROOM_SIZE, &out->width_mm)) != APP_OK ||
        (r = pj_get_number(c, room, "depth", 1, ROOM_SIZE, &out->depth_mm)) != APP_OK ||
        (r = pj_get_number(c, room, "height", 1, ROOM_SIZE, &out->height_mm)) != APP_OK ||
        (r = pj_material_ref(c, room, "floor", "room.floor#material", &out->floor_material)) !=
            APP_OK ||
        (r = pj_material_ref(c, room, "walls", "room.walls#material", &out->wall_material)) !=
            APP_OK ||
        (r = pj_material_ref(c, room, "ceiling", "room.ceiling#material",
                             &out->ceiling_material)) != APP_OK)
        return r;
    pj_path_restore(c, mark);
    return APP_OK;
}
