/* View and projection matrices for an rd_view, with near/far fitted to the room seen from the
 * eye (depth_range.h) so that scenes from 1 mm to 10 km keep usable depth precision
 * (RENDERING.md section 11). */
#include "camera.h"
#include "depth_range.h"
#include "probe.h"
#include "render_internal.h"

#include <cglm/cglm.h>
#include <math.h>

rd_result rd_camera_matrices(const rd_context *ctx, const rd_view *v, const rd_scene_view_input *in,
                             float view_proj[16], float inverse_view_proj[16], float view_rot[9])
{
    (void)ctx;
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
        rd_scene_depth_bounds(in->scene, lo, hi);
        float reach = 0.0f;
        for (int c = 0; c < 8; c++) {
            vec3 corner = {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]};
            reach = fmaxf(reach, glm_vec3_distance(eye, corner));
        }
        if (!(reach > 0.0f) || !isfinite(reach))
            reach = 100.0f;
        /* near = far / 1000 keeps 24-bit depth steps under 0.2 mm at 3 m in a 4 m room, so a
         * tile band 4 mm proud of its wall does not fight it; nothing in a planner's view sits
         * closer to the eye than a thousandth of the scene (rd_depth_near caps it for tall
         * narrow rooms). */
        far_m = reach * 1.05f;
        near_m = rd_depth_near(far_m, lo, hi);
        /* An eye a few centimetres from a wall looks along it: the near plane must stay in
         * front of that wall in every pixel (a plane at distance d is nowhere nearer than
         * d cos(half diagonal) in view depth, and half the field's diagonal stays under 60
         * degrees), or the room opens onto the clear colour there. */
        float room_lo[3], room_hi[3], wall = INFINITY;
        rd_effective_proxy(in->scene, room_lo, room_hi);
        for (int k = 0; k < 3; k++)
            wall = fminf(wall, fminf(eye[k] - room_lo[k], room_hi[k] - eye[k]));
        if (wall > 0.0f && isfinite(wall))
            near_m = fmaxf(fminf(near_m, 0.5f * wall), far_m * 1e-6f);
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
