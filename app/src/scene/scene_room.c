/* The room in the GPU scene: the meshes of app_room_geometry_build (floor and ceiling
 * polygons, walls with their openings cut, reveals, niches, pre-walls, window panels and door
 * leaves), with texture coordinates in units of the material's real-world texture size, so a
 * 300 x 600 mm tile texture lays 300 x 600 mm tiles (floor from x = 0, y = 0; walls from the
 * floor up). The reference tracer gets the same meshes (ref_scene_build.c). */
#include "scene_build_internal.h"

#include <stdlib.h>

app_result app_scene_add_room(rd_context *ctx, const app_project *p, const app_room_geometry *room,
                              app_scene *s, char *err, size_t err_size)
{
    for (int i = 0; i < room->mesh_count; i++) {
        const app_room_mesh *rm = &room->meshes[i];
        if (rm->index_count == 0)
            continue;
        rd_material m;
        app_result r =
            rm->material >= 0
                ? app_scene_material(ctx, p, s, rm->material, &m, err, err_size)
                : app_scene_material_of(ctx, p, s, &rm->inline_material, &m, err, err_size);
        if (r != APP_OK)
            return r;
        rd_mesh mesh = rd_mesh_create(ctx, &(rd_mesh_desc){.positions = rm->positions,
                                                           .normals = rm->normals,
                                                           .uvs = rm->uvs,
                                                           .indices = rm->indices,
                                                           .vertex_count = rm->vertex_count,
                                                           .index_count = rm->index_count});
        if (!mesh.id || app_scene_track_mesh(s, mesh) != APP_OK) {
            snprintf(err, err_size, "%s: room surface %s: %s", p->path, rm->surface,
                     rd_last_error());
            return APP_ERR_OUT_OF_MEMORY;
        }
        rd_object_desc o = {.mesh = mesh, .material = m, .background = 1};
        if (rd_scene_add_object(s->scene, &o) != RD_OK) {
            snprintf(err, err_size, "%s: room: %s", p->path, rd_last_error());
            return APP_ERR_SCHEMA;
        }
    }
    return APP_OK;
}
