/* CPU twin of shaders/tonemap.frag. */
#include "render/shade_ref.h"

#include <math.h>

void rd_ref_tonemap(const float radiance[3], float exposure_ev, rd_tonemap mode, float white,
                    float out[3])
{
    float scale = exp2f(exposure_ev);
    float c[3];
    for (int k = 0; k < 3; k++) {
        float x = radiance[k] * scale;
        c[k] = isnan(x) ? 0.0f : fminf(fmaxf(x, 0.0f), 1e30f);
    }
    if (mode == RD_TONEMAP_CLAMP) {
        for (int k = 0; k < 3; k++)
            out[k] = fminf(c[k], 1.0f);
        return;
    }
    /* Reinhard et al. 2002, eq. 4, on luminance (Rec. 709 weights) so hue is kept. */
    float w = white > 0.0f ? white : 4.0f;
    float y = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
    if (!(y > 0.0f)) {
        out[0] = out[1] = out[2] = 0.0f;
        return;
    }
    float ratio = (1.0f + y / (w * w)) / (1.0f + y);
    for (int k = 0; k < 3; k++)
        out[k] = fminf(fmaxf(c[k] * ratio, 0.0f), 1.0f);
}

float rd_ref_srgb_encode(float x)
{
    return x < 0.0031308f ? 12.92f * x : 1.055f * powf(x, 1.0f / 2.4f) - 0.055f;
}

void rd_ref_display_rgb8(const float radiance[3], float exposure_ev, rd_tonemap mode, float white,
                         unsigned char out[3])
{
    float d[3];
    rd_ref_tonemap(radiance, exposure_ev, mode, white, d);
    for (int k = 0; k < 3; k++)
        out[k] = (unsigned char)(rd_ref_srgb_encode(d[k]) * 255.0f + 0.5f);
}
