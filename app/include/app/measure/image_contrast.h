/* The contrast of a display image, as a photographer reads its histogram: how dark its darkest
 * percent is and how much of it is burnt out (`tessera render --stats`, docs/rendering.md
 * "Tone curve, exposure and white balance"). */
#ifndef APP_IMAGE_CONTRAST_H
#define APP_IMAGE_CONTRAST_H

typedef struct app_image_contrast {
    long long pixels;
    /* Luma Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' (ITU-R BT.709 weights on the sRGB-encoded
     * values), in 0..255: percentiles and mean. */
    double luma_p1, luma_p50, luma_p99, luma_mean;
    /* Pixels with a channel at 255 (clipped), as a fraction of all. */
    double clipped_fraction;
} app_image_contrast;

/* pixels: width x height x channels display values in [0, 1] (channels 1..4; 1-2: grey, alpha
 * ignored). Returns 0 on success, -1 for bad arguments or no memory (*out zeroed). */
int app_image_contrast_of(const float *pixels, int width, int height, int channels,
                          app_image_contrast *out);

#endif
