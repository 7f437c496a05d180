/* Value conversions on pixel arrays: NaN sanitising and channel-count changes. */
#include "image_internal.h"
#include "render/image_io.h"

#include <math.h>

size_t rd_image_sanitize_nonfinite(float *values, size_t count)
{
    size_t replaced = 0;
    for (size_t i = 0; i < count; i++) {
        if (!isfinite(values[i])) {
            values[i] = 0.0f;
            replaced++;
        }
    }
    return replaced;
}

/* Expands one pixel of 1..4 channels to RGBA; `one` is the opaque alpha value. */
#define TO_RGBA(src, ch, one, rgba)                                                                \
    do {                                                                                           \
        switch (ch) {                                                                              \
        case 1:                                                                                    \
            rgba[0] = rgba[1] = rgba[2] = (src)[0];                                                \
            rgba[3] = (one);                                                                       \
            break;                                                                                 \
        case 2:                                                                                    \
            rgba[0] = rgba[1] = rgba[2] = (src)[0];                                                \
            rgba[3] = (src)[1];                                                                    \
            break;                                                                                 \
        case 3:                                                                                    \
            rgba[0] = (src)[0];                                                                    \
            rgba[1] = (src)[1];                                                                    \
            rgba[2] = (src)[2];                                                                    \
            rgba[3] = (one);                                                                       \
            break;                                                                                 \
        default:                                                                                   \
            rgba[0] = (src)[0];                                                                    \
            rgba[1] = (src)[1];                                                                    \
            rgba[2] = (src)[2];                                                                    \
            rgba[3] = (src)[3];                                                                    \
            break;                                                                                 \
        }                                                                                          \
    } while (0)

void rd_image_convert_channels_u8(const unsigned char *src, int src_ch, unsigned char *dst,
                                  int dst_ch, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        unsigned char rgba[4];
        TO_RGBA(src + i * (size_t)src_ch, src_ch, 255, rgba);
        unsigned char *d = dst + i * (size_t)dst_ch;
        unsigned char gray = (unsigned char)((rgba[0] + rgba[1] + rgba[2] + 1) / 3);
        switch (dst_ch) {
        case 1:
            d[0] = gray;
            break;
        case 2:
            d[0] = gray;
            d[1] = rgba[3];
            break;
        case 3:
            d[0] = rgba[0];
            d[1] = rgba[1];
            d[2] = rgba[2];
            break;
        default:
            d[0] = rgba[0];
            d[1] = rgba[1];
            d[2] = rgba[2];
            d[3] = rgba[3];
            break;
        }
    }
}

void rd_image_convert_channels_f32(const float *src, int src_ch, float *dst, int dst_ch,
                                   size_t count)
{
    for (size_t i = 0; i < count; i++) {
        float rgba[4];
        TO_RGBA(src + i * (size_t)src_ch, src_ch, 1.0f, rgba);
        float *d = dst + i * (size_t)dst_ch;
        float gray = (rgba[0] + rgba[1] + rgba[2]) / 3.0f;
        switch (dst_ch) {
        case 1:
            d[0] = gray;
            break;
        case 2:
            d[0] = gray;
            d[1] = rgba[3];
            break;
        case 3:
            d[0] = rgba[0];
            d[1] = rgba[1];
            d[2] = rgba[2];
            break;
        default:
            d[0] = rgba[0];
            d[1] = rgba[1];
            d[2] = rgba[2];
            d[3] = rgba[3];
            break;
        }
    }
}

void rd_image_expand_rgba(const rd_image *img, float *out)
{
    rd_image_convert_channels_f32(img->pixels, img->channels, out, 4,
                                  (size_t)img->width * (size_t)img->height);
}
