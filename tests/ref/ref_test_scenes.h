/* Small scenes built straight on the tracer's API for its tests: rectangles and a closed room
 * whose walls glow in distinct colours, so what a ray reaches can be told by its colour. */
#ifndef TESTS_REF_TEST_SCENES_H
#define TESTS_REF_TEST_SCENES_H

#include "ref/ref.h"

#include <string.h>

/* A rectangle: corner o, edges u and v; its front (counter-clockwise) side faces u x v. */
static inline ref_result add_rect(ref_scene *s, const float o[3], const float u[3],
                                  const float v[3], const rd_material *m, int double_sided)
{
    float n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    float pos[12], nrm[12], uv[8];
    for (int c = 0; c < 4; c++) {
        float su = (float)(c & 1), sv = (float)(c >> 1);
        for (int k = 0; k < 3; k++) {
            pos[3 * c + k] = o[k] + su * u[k] + sv * v[k];
            nrm[3 * c + k] = n[k];
        }
        uv[2 * c] = su;
        uv[2 * c + 1] = sv;
    }
    static const uint32_t idx[6] = {0, 1, 3, 0, 3, 2};
    ref_mesh_desc d = {.positions = pos,
                       .normals = nrm,
                       .uvs = uv,
                       .indices = idx,
                       .vertex_count = 4,
                       .index_count = 6,
                       .material = *m,
                       .double_sided = double_sided};
    return ref_scene_add_mesh(s, &d);
}

/* Walls of the box [0, size]: 0 x = 0, 1 x = max, 2 y = 0, 3 y = max, 4 floor, 5 ceiling. */
static const float room_colour[6][3] = {{0.9f, 0.1f, 0.1f}, {0.1f, 0.8f, 0.1f}, {0.1f, 0.2f, 0.9f},
                                        {0.8f, 0.8f, 0.1f}, {0.6f, 0.1f, 0.7f}, {0.1f, 0.7f, 0.8f}};

/* The closed room: six single-sided rectangles facing inward, each glowing (emissive only, no
 * diffuse or specular) in room_colour. */
static inline ref_result add_glowing_room(ref_scene *s, const float size[3])
{
    float x = size[0], y = size[1], z = size[2];
    const float o[6][3] = {{0, 0, 0}, {x, 0, 0}, {0, 0, 0}, {0, y, 0}, {0, 0, 0}, {0, 0, z}};
    /* u x v points into the room. */
    const float u[6][3] = {{0, y, 0}, {0, 0, z}, {0, 0, z}, {x, 0, 0}, {x, 0, 0}, {0, y, 0}};
    const float v[6][3] = {{0, 0, z}, {0, y, 0}, {x, 0, 0}, {0, 0, z}, {0, y, 0}, {x, 0, 0}};
    for (int i = 0; i < 6; i++) {
        rd_material m = {0};
        memcpy(m.emissive, room_colour[i], sizeof m.emissive);
        ref_result r = add_rect(s, o[i], u[i], v[i], &m, 0);
        if (r != REF_OK)
            return r;
    }
    return REF_OK;
}

/* Which wall of the box [0, size] a ray from p (inside) along d reaches first, and where. */
static inline int room_wall_hit(const float size[3], const float p[3], const float d[3],
                                float hit[3])
{
    float best = 1e30f;
    int wall = -1;
    for (int k = 0; k < 3; k++) {
        if (d[k] == 0.0f)
            continue;
        float t = ((d[k] > 0.0f ? size[k] : 0.0f) - p[k]) / d[k];
        if (t > 0.0f && t < best) {
            best = t;
            wall = 2 * k + (d[k] > 0.0f ? 1 : 0);
        }
    }
    for (int k = 0; k < 3; k++)
        hit[k] = p[k] + best * d[k];
    return wall;
}

#endif
