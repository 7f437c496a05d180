#ifndef RENDER_CAMERA_H
#define RENDER_CAMERA_H

#include "render/render.h"

typedef struct rd_scene_view_input {
    const rd_scene *scene; /* its depth bounds (depth_range.h) fit near and far */
} rd_scene_view_input;

rd_result rd_camera_matrices(const rd_context *ctx, const rd_view *v, const rd_scene_view_input *in,
                             float view_proj[16], float inverse_view_proj[16], float view_rot[9]);

#endif
