/* CPU twin of shaders/grout.glsl: tile joints drawn from the layout. */
#include "render/shade_ref.h"

#include <math.h>

static float joint_coverage_1d(float x, float w, float f)
{
    if (!(w > 0.0f))
        return 0.0f;
    if (f >= 1.0f)
        return fminf(w, 1.0f);
    float c = x - floorf(x); /* GLSL fract */
    if (!(f > 0.0f))
        return (c < 0.5f * w || c > 1.0f - 0.5f * w) ? 1.0f : 0.0f;
    float a = c - 0.5f * f, b = c + 0.5f * f;
    float o = fmaxf(0.0f, fminf(b, 0.5f * w) - fmaxf(a, -0.5f * w)) +
              fmaxf(0.0f, fminf(b, 1.0f + 0.5f * w) - fmaxf(a, 1.0f - 0.5f * w));
    return fminf(fmaxf(o / f, 0.0f), 1.0f);
}

float rd_ref_joint_coverage(const float uv[2], const float joint_width[2], const float footprint[2])
{
    float ju = joint_coverage_1d(uv[0], joint_width[0], footprint[0]);
    float jv = joint_coverage_1d(uv[1], joint_width[1], footprint[1]);
    return ju + jv - ju * jv;
}

void rd_ref_joint_texcoord(const float uv[2], const float joint_width[2], int tex_w, int tex_h,
                           float texels, float st[2])
{
    int size[2] = {tex_w > 0 ? tex_w : 1, tex_h > 0 ? tex_h : 1};
    for (int k = 0; k < 2; k++) {
        float lo =
            fminf(0.5f * fmaxf(joint_width[k], 0.0f) + 4.0f * fmaxf(texels, 0.25f) / (float)size[k],
                  0.5f);
        float c = uv[k] - floorf(uv[k]);
        st[k] = floorf(uv[k]) + fminf(fmaxf(c, lo), 1.0f - lo);
    }
}
