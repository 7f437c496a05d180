/* Cube maps on the CPU: the coordinate convention, GL's face selection, float cube-map data,
 * sampling and loading from six image files. No GL: the CPU reference that the shaders, the
 * probes and render/ref are tested against (RENDERING.md sections 3 and 8).
 *
 * Coordinates: the world is right-handed, Z up. Cube maps are stored in GL's cube-map
 * coordinate system (CMCS), reached from the world by seed 000's M_rot (eq. 7):
 * world (x, y, z) -> CMCS (x, -z, y). Faces in GL order: 0 +X, 1 -X, 2 +Y, 3 -Y, 4 +Z, 5 -Z.
 * Seed 000 Fig. 8 in these terms: world front -Y -> face 5 (-Z), back +Y -> 4 (+Z), up +Z -> 3
 * (-Y), down -Z -> 2 (+Y), left -X -> 1 (-X), right +X -> 0 (+X). */
#ifndef RENDER_CUBE_DATA_H
#define RENDER_CUBE_DATA_H

#include "render/render.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
    RD_CUBE_POS_X = 0,
    RD_CUBE_NEG_X,
    RD_CUBE_POS_Y,
    RD_CUBE_NEG_Y,
    RD_CUBE_POS_Z,
    RD_CUBE_NEG_Z,
    RD_CUBE_MAX_SIZE = 8192
};

/* Seed 000 eq. 7: M_rot (x, y, z) = (x, -z, y). */
void rd_ref_world_to_cmcs(const float w[3], float c[3]);
/* The inverse, M_rot^T: (x, y, z) -> (x, z, -y). */
void rd_ref_cmcs_to_world(const float c[3], float w[3]);

/* GL's cube-map face selection table (GL 4.5 core spec section 8.13; seed 000 section 2 gives
 * the +X row: s = -z / (2|x|) + 1/2, t = -y / (2|x|) + 1/2):
 *   +X: sc = -z, tc = -y, ma = x      -X: sc = +z, tc = -y, ma = x
 *   +Y: sc = +x, tc = +z, ma = y      -Y: sc = +x, tc = -z, ma = y
 *   +Z: sc = +x, tc = -y, ma = z      -Z: sc = -x, tc = -y, ma = z
 *   s = (sc / |ma| + 1) / 2,  t = (tc / |ma| + 1) / 2,  both in [0, 1].
 * Ties as Mesa breaks them: X wins over Y over Z (|x| >= |y| && |x| >= |z| -> X; else
 * |y| >= |z| -> Y; else Z); the sign of ma (>= 0 -> positive face) picks within the axis.
 * Returns the face, or -1 (s = t = 0.5) for a zero or non-finite vector. */
int rd_ref_cube_face_st(const float cmcs[3], float *s, float *t);
/* The inverse: the CMCS direction through (s, t) of a face, with |ma| = 1 (so not unit length).
 * s, t outside [0, 1] give points on the face's plane beyond its edges. A face outside 0..5
 * gives (0, 0, 0). */
void rd_ref_cube_face_direction(int face, float s, float t, float cmcs[3]);

typedef struct rd_cube_data {
    int size;        /* texels per side of every face */
    float *faces[6]; /* GL order; RGBA float, size*size*4, linear radiance; row j holds
                        t = (j + 0.5)/size, column i holds s = (i + 0.5)/size */
} rd_cube_data;

/* Zero-filled faces. size 1 .. RD_CUBE_MAX_SIZE (RD_ERR_INVALID_ARGUMENT below 1 or for a NULL
 * out, RD_ERR_TOO_LARGE above); on failure *out is zeroed. */
rd_result rd_cube_data_alloc(int size, rd_cube_data *out);
/* Frees and zeroes; NULL and zeroed structs are fine. */
void rd_cube_data_free(rd_cube_data *c);

/* Sampling by a WORLD direction (converted to CMCS inside; need not be unit length).
 * Nearest: texel (floor(s*size), floor(t*size)) clamped to the face, as GL_NEAREST.
 * Bilinear: GL_LINEAR's four taps around (s*size - 0.5, t*size - 0.5) with seamless filtering
 * (GL_TEXTURE_CUBE_MAP_SEAMLESS): a tap that falls off its face is re-projected through its
 * direction onto the neighbouring face, so there is no seam; at a corner the tap that is off
 * both ways has no texel and takes the mean of the other three (ARB_seamless_cube_map).
 * A zero or non-finite direction, or an empty cube, gives (0, 0, 0, 0). */
void rd_cube_sample_nearest(const rd_cube_data *c, const float world_dir[3], float out[4]);
void rd_cube_sample_bilinear(const rd_cube_data *c, const float world_dir[3], float out[4]);

/* A static cube map from six image files (RENDERING.md section 8 "static"). `pattern` holds one
 * '*', replaced by the GL names posx negx posy negy posz negz (seed 003) or, when the posx file
 * does not exist, by the 3ds Max names of seed 000 Fig. 8: right -> +X, left -> -X, down -> +Y,
 * up -> -Y, back -> +Z, front -> -Z.
 * Orientation: each image goes onto its face as it is stored, top image row = row 0 = t near 0,
 * left column = s near 0 -- the layout glTexImage2D gives a top-row-first image, and the one
 * the common cube-map exporters (posx..negz sets) assume. No flip or rotation is applied, also
 * not to 3ds Max sets (seed 000 notes their face orientation differs; re-orient such images
 * before loading if they show rotated).
 * Pixels through rd_image_read (any format OpenImageIO reads): sRGB-encoded images (8/16-bit
 * PNG, JPEG, TIFF) are decoded to linear with the exact sRGB curve, float images (EXR, HDR)
 * stay linear; NaN/Inf texels become 0; gray -> RGB, missing alpha -> 1.
 * All six must exist, be square and of one size (at most RD_CUBE_MAX_SIZE). On failure *out is
 * zeroed, err (may be NULL) and rd_last_error() name the pattern, the face and its file:
 *   "room_*.png: face negy (room_negy.png): 256x255 is not square"
 *   "room_*.png: no room_posx.png and no room_right.png"
 * Returns RD_ERR_INVALID_ARGUMENT for bad arguments and missing, unreadable or mismatched
 * files, RD_ERR_TOO_LARGE, RD_ERR_OUT_OF_MEMORY. */
rd_result rd_cube_data_load(const char *pattern, rd_cube_data *out, char *err, size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
