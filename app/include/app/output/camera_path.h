/* A smooth camera path through a project's stored viewpoints: a uniform
 * Catmull-Rom spline (Catmull and Rom 1974) on the positions and on the targets, with the end
 * points repeated, so the path passes through every viewpoint with a continuous tangent. */
#ifndef APP_CAMERA_PATH_H
#define APP_CAMERA_PATH_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct app_path_key {
    float eye[3], target[3], fov_deg;
} app_path_key;

/* The camera at t in [0, 1] along keys[0..count-1] (each segment takes an equal share of t);
 * count 1 gives keys[0]. */
app_path_key app_camera_path_at(const app_path_key *keys, int count, double t);

#ifdef __cplusplus
}
#endif
#endif
