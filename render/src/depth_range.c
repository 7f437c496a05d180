/* The box that depth ranges follow: the room and what stands in or near it. */
#include "depth_range.h"
#include "probe.h"
#include "scene_internal.h"

#include <math.h>

static int room_given(const rd_scene *s, float room_lo[3], float room_hi[3])
{
    int given = 0;
    for (int k = 0; k < 3; k++) {
        room_lo[k] = s->reflection.proxy_min[k];
        room_hi[k] = s->reflection.proxy_max[k];
        given |= room_lo[k] != 0.0f || room_hi[k] != 0.0f;
    }
    for (int k = 0; k < 3; k++)
        if (!(room_lo[k] <= room_hi[k]) || !isfinite(room_lo[k]) || !isfinite(room_hi[k]))
            return 0;
    return given;
}

void rd_scene_depth_bounds(const rd_scene *s, float lo[3], float hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (int i = 0; i < s->object_count; i++) {
        float a[3], b[3];
        rd_object_world_bounds(s->ctx, &s->objects[i], a, b);
        if (!(a[0] <= b[0] && a[1] <= b[1] && a[2] <= b[2]))
            continue; /* an empty mesh */
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], a[k]);
            hi[k] = fmaxf(hi[k], b[k]);
        }
    }
    float room_lo[3], room_hi[3];
    if (room_given(s, room_lo, room_hi)) {
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(fmaxf(lo[k], room_lo[k] - RD_DEPTH_ROOM_MARGIN_M), room_lo[k]);
            hi[k] = fmaxf(fminf(hi[k], room_hi[k] + RD_DEPTH_ROOM_MARGIN_M), room_hi[k]);
        }
        return;
    }
    if (!(lo[0] <= hi[0]))
        for (int k = 0; k < 3; k++) {
            lo[k] = -1.0f;
            hi[k] = 1.0f;
        }
}

float rd_depth_near(float far_m, const float lo[3], const float hi[3])
{
    float near_m = far_m * 1e-3f;
    float side = INFINITY;
    for (int k = 0; k < 3; k++)
        if (hi[k] > lo[k])
            side = fminf(side, hi[k] - lo[k]);
    if (isfinite(side) && side * 4e-3f < near_m)
        near_m = side * 4e-3f;
    return near_m;
}
