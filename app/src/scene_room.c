/* The room's interior as six inward-facing rectangles, with texture coordinates in units of
 * the material's real-world texture size, so a 300 x 600 mm tile texture lays 300 x 600 mm
 * tiles from the room's corner (floor from x = 0, y = 0; walls from the floor up). */
#include "scene_build_internal.h"

#include <stdlib.h>

typedef struct quad {
    float origin[3], u_axis[3], v_axis[3]; /* metres; normal = u x v points into the room */
    float u_len, v_len;
} quad;

void app_room_surface(const app_project *p, int surface, app_room_quad *out, int *material)
{
    float w = (float)(p->room.width_mm * 1e-3), d = (float)(p->room.depth_mm * 1e-3),
          h = (float)(p->room.height_mm * 1e-3);
    const quad quads[6] = {
        {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, w, d},  /* floor, normal +Z */
        {{0, d, h}, {1, 0, 0}, {0, -1, 0}, w, d}, /* ceiling, normal -Z */
        {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, h, w},  /* wall y = 0, normal +Y (u up, v along) */
        {{w, d, 0}, {0, 0, 1}, {-1, 0, 0}, h, w}, /* wall y = d, normal -Y */
        {{0, d, 0}, {0, 0, 1}, {0, -1, 0}, h, d}, /* wall x = 0, normal +X */
        {{w, 0, 0}, {0, 0, 1}, {0, 1, 0}, h, d},  /* wall x = w, normal -X */
    };
    int mi = surface == 0   ? p->room.floor_material
             : surface == 1 ? p->room.ceiling_material
                            : p->room.wall_material;
    quad q = quads[surface];
    if (surface >= 2) {
        /* Walls: run u along the wall and v up it, so the texture's width lies along the
         * wall. The table lists them up-first; swap to along-first with the same normal by
         * starting at the other end. */
        quad t = q;
        memcpy(t.v_axis, q.u_axis, sizeof t.v_axis);
        t.u_len = q.v_len;
        t.v_len = q.u_len;
        for (int k = 0; k < 3; k++) {
            t.origin[k] = q.origin[k] + q.v_len * q.v_axis[k];
            t.u_axis[k] = -q.v_axis[k];
        }
        q = t;
    }
    const app_material *am = &p->materials[mi];
    float tex[2] = {am->texture_size_mm[0] * 1e-3f, am->texture_size_mm[1] * 1e-3f};
    float n[3] = {q.u_axis[1] * q.v_axis[2] - q.u_axis[2] * q.v_axis[1],
                  q.u_axis[2] * q.v_axis[0] - q.u_axis[0] * q.v_axis[2],
                  q.u_axis[0] * q.v_axis[1] - q.u_axis[1] * q.v_axis[0]};
    for (int c = 0; c < 4; c++) {
        float su = (float)(c & 1), sv = (float)(c >> 1);
        for (int k = 0; k < 3; k++) {
            out->positions[c * 3 + k] =
                q.origin[k] + su * q.u_len * q.u_axis[k] + sv * q.v_len * q.v_axis[k];
            out->normals[c * 3 + k] = n[k];
        }
        out->uvs[c * 2] = su * q.u_len / tex[0];
        out->uvs[c * 2 + 1] = -sv * q.v_len / tex[1]; /* image rows run down, v runs up */
    }
    static const uint32_t idx[6] = {0, 1, 3, 0, 3, 2};
    memcpy(out->indices, idx, sizeof idx);
    *material = mi;
}

app_result app_scene_add_room(rd_context *ctx, const app_project *p, app_scene *s, char *err,
                              size_t err_size)
{
    for (int i = 0; i < 6; i++) {
        app_room_quad q;
        int mi;
        app_room_surface(p, i, &q, &mi);
        rd_material m;
        app_result r = app_scene_material(ctx, p, s, mi, &m, err, err_size);
        if (r != APP_OK)
            return r;
        rd_mesh mesh = rd_mesh_create(ctx, &(rd_mesh_desc){.positions = q.positions,
                                                           .normals = q.normals,
                                                           .uvs = q.uvs,
                                                           .indices = q.indices,
                                                           .vertex_count = 4,
                                                           .index_count = 6});
        if (!mesh.id || app_scene_track_mesh(s, mesh) != APP_OK) {
            snprintf(err, err_size, "%s: room surface %d: %s", p->path, i, rd_last_error());
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
