/* Image files in and out: textures, HDR environment maps, renders, golden images.
 *
 * Reading and writing go through OpenImageIO behind a thin C++ adapter; this header has no GL
 * and no C++ types. Every call returns a result enum and, on failure, writes a readable
 * message naming the file into err (truncated to err_size; err may be NULL). Nothing aborts,
 * whatever the file contains.
 */
#ifndef RENDER_IMAGE_IO_H
#define RENDER_IMAGE_IO_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Refused on read before any pixel memory is allocated, and on write. */
#define RD_IMAGE_MAX_SIDE 16384
#define RD_IMAGE_MAX_PIXELS (1L << 27)

typedef struct rd_image {
    int width, height, channels; /* channels 1..4: gray, gray+alpha, RGB, RGBA */
    float *pixels;               /* row-major, top row first, width*height*channels floats */
    int srgb_encoded;            /* 1: sRGB-encoded display values (8/16-bit PNG, JPEG, TIFF);
                                    0: linear (EXR, HDR, float TIFF) */
} rd_image;

typedef enum rd_image_result {
    RD_IMAGE_OK = 0,
    RD_IMAGE_ERR_IO,        /* missing file, unwritable folder, failed rename */
    RD_IMAGE_ERR_FORMAT,    /* not an image, corrupt or truncated, unsupported extension */
    RD_IMAGE_ERR_TOO_LARGE, /* over RD_IMAGE_MAX_SIDE per side or RD_IMAGE_MAX_PIXELS */
    RD_IMAGE_ERR_OUT_OF_MEMORY,
    RD_IMAGE_ERR_INVALID /* bad arguments: NULL pointer, size <= 0, channels not 1..4 */
} rd_image_result;

/* Reads subimage 0 of any format OpenImageIO knows. Integer formats are scaled to 0..1 (8-bit
 * by 255, 16-bit by 65535); float formats are returned as stored. Alpha is returned as stored
 * in the file (straight alpha for PNG and TIFF, not premultiplied). Files with more than four
 * channels keep their first four. Each NaN or infinite value becomes 0 and is counted in
 * *nonfinite_replaced (values, not pixels; may be NULL). On failure *out is zeroed. */
rd_image_result rd_image_read(const char *path, rd_image *out, int *nonfinite_replaced, char *err,
                              size_t err_size);

/* Writes 8-bit RGBA by extension, case-insensitive: .png (RGBA), .jpg/.jpeg (RGB, alpha
 * dropped, quality 95), .tif/.tiff (RGBA). .exr/.hdr are refused: use rd_image_write_float. */
rd_image_result rd_image_write_rgba8(const char *path, int width, int height,
                                     const unsigned char *rgba, char *err, size_t err_size);

/* The same with a print resolution: dpi > 0 is written as the file's pixels per inch (PNG pHYs,
 * JPEG JFIF density, TIFF XResolution/YResolution). */
rd_image_result rd_image_write_rgba8_dpi(const char *path, int width, int height,
                                         const unsigned char *rgba, float dpi, char *err,
                                         size_t err_size);
/* The same with an XMP packet (UTF-8 RDF text, under 64 KB) stored as an APP1 segment when the
 * format is JPEG (image_xmp.c); PNG and TIFF are written without it. The packet is in the file
 * before the file gets its name. */
rd_image_result rd_image_write_rgba8_xmp(const char *path, int width, int height,
                                         const unsigned char *rgba, const char *xmp, char *err,
                                         size_t err_size);
/* The pixels per inch a file states (0 when it states none or only an aspect). */
rd_image_result rd_image_read_dpi(const char *path, float *dpi, char *err, size_t err_size);

/* Writes linear floats, channels 1..4: .exr (half float, zip compression), .tif/.tiff (32-bit
 * float), .hdr (RGBE; gray is replicated and alpha dropped). .png/.jpg are refused. */
rd_image_result rd_image_write_float(const char *path, int width, int height, int channels,
                                     const float *pixels, char *err, size_t err_size);

/* Every write is atomic: the image goes to PATH.tmp-<pid>-<n> in the same folder as PATH's
 * target (a symbolic link is followed and stays a link), every write, the fsync and the close
 * are checked, a PNG must end in IEND and a JPEG in EOI, and only then is the file renamed
 * over the target. On any failure (a full disk: "No space left on device") the temporary file
 * is removed, an existing file is left untouched and err names PATH and the reason. */

/* 1 for .exr/.hdr, 0 for .png/.jpg/.jpeg/.tif/.tiff, -1 for an unknown extension or NULL. */
int rd_image_format_is_float(const char *path);

/* Copies the pixels as RGBA (gray -> RGB, missing alpha -> 1) into out, which holds
 * width * height * 4 floats. */
void rd_image_expand_rgba(const rd_image *img, float *out);

/* Frees the pixels and zeroes the struct; NULL and zeroed images are fine. */
void rd_image_free(rd_image *img);

/* Test hook, so the failure paths can be exercised on purpose (STYLE.md: SQLite). The fault
 * applies to the calling thread only and stays until reset with RD_IMAGE_FAULT_NONE. */
typedef enum rd_image_fault {
    RD_IMAGE_FAULT_NONE = 0,
    RD_IMAGE_FAULT_AFTER_TEMP_WRITE, /* a write fails after its temporary file is complete */
    RD_IMAGE_FAULT_ALLOC             /* a read fails to allocate its pixels */
} rd_image_fault;
void rd_image_debug_set_fault(rd_image_fault fault);

#ifdef __cplusplus
}
#endif

#endif
