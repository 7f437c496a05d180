/* Catmull-Rom camera path (app/output/camera_path.h). */
#include "app/output/camera_path.h"

#include <math.h>

/* The uniform Catmull-Rom segment from p1 to p2 at u in [0, 1]. */
static float catmull_rom(float p0, float p1, float p2, float p3, float u)
{
    float u2 = u * u, u3 = u2 * u;
    return 0.5f * (2.0f * p1 + (-p0 + p2) * u + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * u2 +
                   (-p0 + 3.0f * p1 - 3.0f * p2 + p3) * u3);
}

app_path_key app_camera_path_at(const app_path_key *keys, int count, double t)
{
    if (count <= 1)
        return keys[0];
    if (!(t > 0.0))
        t = 0.0;
    if (t > 1.0)
        t = 1.0;
    double x = t * (double)(count - 1);
    int seg = (int)floor(x);
    if (seg >= count - 1)
        seg = count - 2;
    float u = (float)(x - seg);
    const app_path_key *k0 = &keys[seg > 0 ? seg - 1 : 0], *k1 = &keys[seg], *k2 = &keys[seg + 1],
                       *k3 = &keys[seg + 2 < count ? seg + 2 : count - 1];
    app_path_key out;
    for (int c = 0; c < 3; c++) {
        out.eye[c] = catmull_rom(k0->eye[c], k1->eye[c], k2->eye[c], k3->eye[c], u);
        out.target[c] = catmull_rom(k0->target[c], k1->target[c], k2->target[c], k3->target[c], u);
    }
    out.fov_deg = catmull_rom(k0->fov_deg, k1->fov_deg, k2->fov_deg, k3->fov_deg, u);
    return out;
}
