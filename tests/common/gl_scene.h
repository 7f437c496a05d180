/* Small helpers for GL tests that build scenes by hand: a unit box or sphere uploaded as a
 * mesh, and a uniform scale plus translation as a column-major model matrix. */
#ifndef TESSERA_TESTS_GL_SCENE_H
#define TESSERA_TESTS_GL_SCENE_H

#include "render/primitives.h"
#include "render/render.h"

#include <string.h>

static inline rd_mesh test_upload_mesh(rd_context *ctx, int sphere)
{
    rd_mesh_data d;
    if (sphere)
        rd_mesh_data_sphere(32, 16, &d);
    else
        rd_mesh_data_box(&d);
    rd_mesh_desc desc = rd_mesh_data_desc(&d);
    rd_mesh m = rd_mesh_create(ctx, &desc);
    rd_mesh_data_free(&d);
    return m;
}

static inline void test_place(float m[16], float x, float y, float z, float scale)
{
    memset(m, 0, 16 * sizeof(float));
    m[0] = m[5] = m[10] = scale;
    m[12] = x;
    m[13] = y;
    m[14] = z;
    m[15] = 1.0f;
}

#endif
