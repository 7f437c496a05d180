/* The room's interior as six inward-facing rectangles, with texture coordinates in units of
 * the material's real-world texture size, so a 300 x 600 mm tile texture lays 300 x 600 mm
 * tiles from the room's corner (floor from x = 0, y = 0; walls from the floor up). */
#include "scene_build_internal.h"

#include <stdlib.h>

typedef struct quad {
    float origin[3], u_axis[3], v_axis[3]; /* metres; normal = u x v points into the room */
    float u_len, v_len;
} quad;

static rd_mesh upload_quad(rd_context *ctx, const quad *q, const float tex_size_m[2])
{
    float pos[12], nrm[12], uv[8];
    float n[3] = {q->u_axis[1] * q->v_axis[2] - q->u_axis[2] * q->v_axis[1],
                  q->u_axis[2] * q->v_axis[0] - q->u_axis[0] * q->v_axis[2],
                  q->u_axis[0] * q->v_axis[1] - q->u_axis[1] * q->v_axis[0]};
    for (int c = 0; c < 4; c++) {
        float su = (float)(c & 1), sv = (float)(c >> 1);
        for (int k = 0; k < 3; k++) {
            pos[c * 3 + k] =
                q->origin[k] + su * q->u_len * q->u_axis[k] + sv * q->v_len * q->v_axis[k];
            nrm[c * 3 + k] = n[k];
        }
        uv[c * 2] = su * q->u_len / tex_size_m[0];
        /* Image rows run downwards; v grows upwards on the wall. */
        uv[c * 2 + 1] = -sv * q->v_len / tex_size_m[1];
    }
    static const uint32_t idx[6] = {0, 1, 3, 0, 3, 2};
    return rd_mesh_create(ctx, &(rd_mesh_desc){.positions = pos,
                                               .normals = nrm,
                                               .uvs = uv,
                                               .indices = idx,
                                               .vertex_count = 4,
                                               .index_count = 6});
}

app_result app_scene_add_room(rd_context *ctx, const app_project *p, app_scene *s, char *err,
                              size_t err_size)
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
    for (int i = 0; i < 6; i++) {
        int mi = i == 0   ? p->room.floor_material
                 : i == 1 ? p->room.ceiling_material
                          : p->room.wall_material;
        const app_material *am = &p->materials[mi];
        rd_material m;
        app_result r = app_scene_material(ctx, p, s, mi, &m, err, err_size);
        if (r != APP_OK)
            return r;
        float tex[2] = {am->texture_size_mm[0] * 1e-3f, am->texture_size_mm[1] * 1e-3f};
        quad q = quads[i];
        if (i >= 2) {
            /* Walls: run u along the wall and v up it, so the texture's width lies along the
             * wall. The table lists them up-first; swap to along-first with the same normal. */
            quad t = q;
            memcpy(t.u_axis, q.v_axis, sizeof t.u_axis);
            memcpy(t.v_axis, q.u_axis, sizeof t.v_axis);
            t.u_len = q.v_len;
            t.v_len = q.u_len;
            /* u x v flipped sign: mirror along u by starting at the other end. */
            for (int k = 0; k < 3; k++) {
                t.origin[k] = q.origin[k] + q.v_len * q.v_axis[k];
                t.u_axis[k] = -q.v_axis[k];
            }
            q = t;
        }
        rd_mesh mesh = upload_quad(ctx, &q, tex);
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
