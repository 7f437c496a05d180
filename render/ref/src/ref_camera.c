/* Primary rays through the GPU camera: the lookAt and perspective of render/src/camera.c (cglm's
 * glm_lookat and glm_perspective), inverted per image point. */
#include "ref_internal.h"

#include <math.h>

static void normalize3(float v[3])
{
    float len = sqrtf(ref_dot(v, v));
    if (len > 0.0f)
        for (int k = 0; k < 3; k++)
            v[k] /= len;
}

ref_result ref_camera_make(const rd_view *v, ref_camera *out)
{
    if (!v)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "no view");
    if (v->width <= 0 || v->height <= 0)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "image size %dx%d: both sides must be at least 1",
                        v->width, v->height);
    for (int k = 0; k < 3; k++)
        if (!isfinite(v->eye[k]) || !isfinite(v->target[k]) || !isfinite(v->up[k]))
            return ref_fail(REF_ERR_INVALID_ARGUMENT,
                            "camera position, target and up must be finite");
    float dir[3] = {v->target[0] - v->eye[0], v->target[1] - v->eye[1], v->target[2] - v->eye[2]};
    if (!(sqrtf(ref_dot(dir, dir)) > 0.0f))
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "camera target equals its position");
    normalize3(dir);
    float up[3] = {v->up[0], v->up[1], v->up[2]};
    if (ref_dot(up, up) == 0.0f) {
        up[0] = up[1] = 0.0f;
        up[2] = 1.0f;
    }
    normalize3(up);
    if (fabsf(ref_dot(up, dir)) > 0.9999f) { /* looking straight up or down */
        up[0] = fabsf(dir[1]) < 0.9f ? 0.0f : 1.0f;
        up[1] = fabsf(dir[1]) < 0.9f ? 1.0f : 0.0f;
        up[2] = 0.0f;
    }
    float fov = v->fov_y_deg > 0.0f ? v->fov_y_deg : 60.0f;
    if (!(fov > 0.5f && fov < 179.5f))
        return ref_fail(REF_ERR_INVALID_ARGUMENT,
                        "field of view %g is outside (0.5, 179.5) degrees", (double)fov);
    /* glm_lookat: f = normalize(target - eye), s = normalize(f x up), u = s x f. */
    float s[3], u[3];
    ref_cross(dir, up, s);
    normalize3(s);
    ref_cross(s, dir, u);
    float tan_half = tanf(0.5f * fov * 3.14159265358979f / 180.0f);
    float aspect = (float)v->width / (float)v->height;
    for (int k = 0; k < 3; k++) {
        out->eye[k] = v->eye[k];
        out->forward[k] = dir[k];
        out->right[k] = s[k] * tan_half * aspect;
        out->up[k] = u[k] * tan_half;
    }
    out->width = v->width;
    out->height = v->height;
    return REF_OK;
}

void ref_camera_dir(const ref_camera *c, float x, float y, float dir[3])
{
    /* Normalised device coordinates: x right, y up; image rows run down from the top. */
    float nx = 2.0f * x / (float)c->width - 1.0f;
    float ny = 1.0f - 2.0f * y / (float)c->height;
    for (int k = 0; k < 3; k++)
        dir[k] = c->forward[k] + nx * c->right[k] + ny * c->up[k];
    normalize3(dir);
}

ref_result ref_camera_ray(const rd_view *v, float x, float y, float origin[3], float dir[3])
{
    ref_camera c;
    ref_result r = ref_camera_make(v, &c);
    if (r != REF_OK)
        return r;
    for (int k = 0; k < 3; k++)
        origin[k] = c.eye[k];
    ref_camera_dir(&c, x, y, dir);
    return REF_OK;
}
