/* Glazes (glaze.h): which objects reflect the room probe without a probe of their own. */
#include "glaze.h"

#include <math.h>

int rd_material_glazed(const rd_material *m)
{
    float spec = (m->specular[0] + m->specular[1] + m->specular[2]) / 3.0f;
    int glowing = m->emissive[0] > 0.0f || m->emissive[1] > 0.0f || m->emissive[2] > 0.0f;
    return !(m->reflectivity > 0.0f) && !(m->transparency > 0.0f) && !glowing &&
           spec >= RD_GLAZE_MIN_SPECULAR && m->shininess >= RD_GLAZE_MIN_SHININESS;
}

float rd_glaze_glossiness(float shininess)
{
    float n = fmaxf(shininess, 4.0f) / 4.0f;
    float g = log2f(n) / 13.0f;
    return isfinite(g) ? fminf(fmaxf(g, 0.0f), 1.0f) : 0.0f;
}

int rd_glazes_in_view(const rd_scene *s, vec4 planes[6], float *g_min, float *g_max)
{
    int count = 0;
    *g_min = 1.0f;
    *g_max = 0.0f;
    if (s->reflection.glaze != RD_SWITCH_ON)
        return 0;
    for (int i = 0; i < s->object_count; i++) {
        const rd_material *m = &s->objects[i].material;
        if ((s->object_probe && s->object_probe[i] >= 0) || !rd_material_glazed(m))
            continue;
        float g = rd_glaze_glossiness(m->shininess);
        *g_min = fminf(*g_min, g);
        *g_max = fmaxf(*g_max, g);
        if (s->object_spheres) {
            const float *sp = s->object_spheres[i];
            int inside = 1;
            for (int k = 0; k < 6 && inside; k++)
                inside = glm_vec3_dot(planes[k], (float *)sp) + planes[k][3] >= -sp[3];
            if (!inside)
                continue;
        }
        count++;
    }
    return count;
}
