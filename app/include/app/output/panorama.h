/* 360-degree panoramas: six cube faces around a viewpoint, resampled into an
 * equirectangular image, with the GPano XMP that panorama viewers read. No GL here: the faces
 * are rendered by the caller (app/src/cli/cli_panorama.c). */
#ifndef APP_PANORAMA_H
#define APP_PANORAMA_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
    APP_PANO_FRONT = 0,
    APP_PANO_RIGHT,
    APP_PANO_BACK,
    APP_PANO_LEFT,
    APP_PANO_UP,
    APP_PANO_DOWN
};
/* "front", "right", "back", "left", "up", "down" */
const char *app_pano_face_name(int face);

/* The six faces' view directions and up vectors for a camera looking along `look` (Z up): the
 * panorama's centre is the look direction's heading; front, right, back, left are horizontal,
 * up and down look along +Z and -Z. */
void app_pano_frames(const float look[3], float fwd[6][3], float up[6][3]);

/* Resamples six square RGBA8 faces (side `face`, top row first, each rendered with a 90 degree
 * field of view along fwd[k] with up[k]) into an equirectangular w x h RGBA8 image: longitude
 * -180..180 degrees left to right with the front at the centre, latitude 90..-90 top to
 * bottom; 2 x 2 samples per pixel, bilinear in the faces. */
void app_pano_equirect(const uint8_t *const faces[6], int face, const float fwd[6][3],
                       const float up[6][3], uint8_t *out, int w, int h);

/* The XMP packet of a full w x h equirectangular panorama (Google's Photo Sphere XMP
 * metadata: GPano ProjectionType, FullPanoWidthPixels, ...). Returns the length, or -1 when
 * out is too small. */
int app_pano_xmp(int w, int h, char *out, size_t size);

#ifdef __cplusplus
}
#endif
#endif
