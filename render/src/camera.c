/* View and projection matrices for an rd_view, with near/far fitted to the scene so that
 * scenes from 1 mm to 10 km keep usable depth precision (RENDERING.md section 11). */
#include "camera.h"
#include "probe.h"
#include "render_internal.h"

#include <cglm/cglm.h>
#include <math.h>

static void world_bounds(const rd_context *ctx, const rd_scene_view_input *in, float lo[3],
                         float hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (int i = 0; i < in->object_count; i++) {
        float a[3], b[3];
        rd_object_world_bounds((rd_context *)ctx, &in->objects[i], a, b);
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], a[k]);
            hi[k] = fmaxf(hi[k], b[k]);
        }
    }
}

rd_result rd_camera_matrices(const rd_context *ctx, const rd_view *v, const rd_scene_view_input *in,
                             float view_proj[16], float inverse_view_proj[16], float view_rot[9])
{
    vec3 eye = {v->eye[0], v->eye[1], v->eye[2]};
    vec3 target = {v->target[0], v->target[1], v->target[2]};
    vec3 up = {v->up[0], v->up[1], v->up[2]};
    for (int k = 0; k < 3; k++)
        if (!isfinite(eye[k]) || !isfinite(target[k]) || !isfinite(up[k]))
            return rd_fail(RD_ERR_INVALID_ARGUMENT,
                           "camera position, target and up must be finite");
    vec3 dir;
    glm_vec3_sub(target, eye, dir);
    float dist = glm_vec3_norm(dir);
    if (!(dist > 0.0f))
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "camera target equals its position");
    glm_vec3_scale(dir, 1.0f / dist, dir);
    if (glm_vec3_norm(up) == 0.0f)
        glm_vec3_copy((vec3){0, 0, 1}, up);
    glm_vec3_normalize(up);
    if (fabsf(glm_vec3_dot(up, dir)) > 0.9999f) /* looking straight up or down */
        glm_vec3_copy(fabsf(dir[1]) < 0.9f ? (vec3){0, 1, 0} : (vec3){1, 0, 0}, up);

    float fov = v->fov_y_deg > 0.0f ? v->fov_y_deg : 60.0f;
    if (!(fov > 0.5f && fov < 179.5f))
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "field of view %g is outside (0.5, 179.5) degrees",
                       (double)fov);
    float near_m = v->near_m, far_m = v->far_m;
    if (!(near_m > 0.0f) || !(far_m > near_m)) {
        float lo[3], hi[3];
        world_bounds(ctx, in, lo, hi);
        float reach = 0.0f;
        if (lo[0] <= hi[0])
            for (int c = 0; c < 8; c++) {
                vec3 corner = {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]};
                reach = fmaxf(reach, glm_vec3_distance(eye, corner));
            }
        if (!(reach > 0.0f) || !isfinite(reach))
            reach = 100.0f;
        /* near = far / 1000 keeps 24-bit depth steps under 0.2 mm at 3 m in a 4 m room, so a
         * tile band 4 mm proud of its wall does not fight it; nothing in a planner's view sits
         * closer to the eye than a thousandth of the scene. */
        far_m = reach * 1.05f;
        near_m = far_m * 1e-3f;
    }
    mat4 view, proj, vp;
    glm_lookat(eye, target, up, view);
    if (v->full_width > 0 && v->full_height > 0) {
        /* A window of the full image: the same frustum, cut at the window's pixel edges
         * (tiled rendering, renderer_tiled.c). */
        float top = near_m * tanf(0.5f * glm_rad(fov));
        float right = top * (float)v->full_width / (float)v->full_height;
        float fw = (float)v->full_width, fh = (float)v->full_height;
        glm_frustum(-right + 2.0f * right * (float)v->crop_x / fw,
                    -right + 2.0f * right * (float)(v->crop_x + v->width) / fw,
                    top - 2.0f * top * (float)(v->crop_y + v->height) / fh,
                    top - 2.0f * top * (float)v->crop_y / fh, near_m, far_m, proj);
    } else {
        glm_perspective(glm_rad(fov), (float)v->width / (float)v->height, near_m, far_m, proj);
    }
    if (v->jitter[0] != 0.0f || v->jitter[1] != 0.0f) {
        /* Shift the image by a fraction of a pixel: an NDC translation after the projection,
         * 2 / size NDC units per pixel (y flipped: rows run down, NDC up). */
        mat4 shift = GLM_MAT4_IDENTITY_INIT;
        shift[3][0] = 2.0f * v->jitter[0] / (float)v->width;
        shift[3][1] = -2.0f * v->jitter[1] / (float)v->height;
        glm_mat4_mul(shift, proj, proj);
    }
    glm_mat4_mul(proj, view, vp);
    if (view_rot) {
        mat3 rot;
        glm_mat4_pick3(view, rot);
        memcpy(view_rot, rot, sizeof rot);
    }
    memcpy(view_proj, vp, sizeof vp);
    if (inverse_view_proj) {
        mat4 inv;
        glm_mat4_inv(vp, inv);
        memcpy(inverse_view_proj, inv, sizeof inv);
    }
    return RD_OK;
}
