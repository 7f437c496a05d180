/* Pure helpers behind image_io.c: the format table, size limits, value conversions. No file
 * I/O here, so each piece can be tested alone. Internal to render/.
 */
#ifndef RENDER_IMAGE_INTERNAL_H
#define RENDER_IMAGE_INTERNAL_H

#include "image_io_oiio.h"

#include <stddef.h>
#include <stdio.h>

typedef struct rd_image_format_info {
    const char *ext;               /* lower case, no dot */
    const char *name;              /* for messages */
    const char *oiio_name;         /* OpenImageIO format name */
    int is_float;                  /* a float (linear) format */
    int rgba8_channels;            /* channels stored by rd_image_write_rgba8; 0: refused */
    const char *rgba8_compression; /* NULL: writer default */
    int float_channels;            /* channels stored by rd_image_write_float; 0: as given,
                                      -1: refused */
    rd_oiio_type float_file_type;
    const char *float_compression;
} rd_image_format_info;

/* The entry for PATH's extension (case-insensitive), or NULL. */
const rd_image_format_info *rd_image_format_for_path(const char *path);

/* ".png, .jpg, .jpeg, ..." for messages. */
const char *rd_image_supported_extensions(void);

/* 1 when width x height is within RD_IMAGE_MAX_SIDE and RD_IMAGE_MAX_PIXELS. */
int rd_image_size_within_limits(long long width, long long height);

/* 1 when the values are sRGB-encoded display values: an explicit colour space wins, otherwise
 * integer formats are display-encoded and float formats linear. */
int rd_image_is_srgb_encoded(int stored_as_float, const char *colorspace);

/* Replaces each NaN and infinity with 0; returns how many there were. */
size_t rd_image_sanitize_nonfinite(float *values, size_t count);

/* Copies count pixels from src_ch to dst_ch interleaved channels (1..4 each): gray is
 * replicated to RGB, RGB averages to gray, alpha is kept when both sides have it, dropped
 * when the destination has none, and set to one (255 or 1.0) when the source has none. */
void rd_image_convert_channels_u8(const unsigned char *src, int src_ch, unsigned char *dst,
                                  int dst_ch, size_t count);
void rd_image_convert_channels_f32(const float *src, int src_ch, float *dst, int dst_ch,
                                   size_t count);

/* 1 when f does not start with the PNG signature, or when its chunks are all complete up to
 * IEND; 0 with a message in detail when the PNG is truncated or its chunk list is corrupt. */
int rd_image_png_chunks_complete(FILE *f, long long file_size, char *detail, size_t detail_size);

/* 1 when f does not start with the OpenEXR magic, or when every header attribute fits in the
 * file and the data window is within the image limits (image_exr_check.c); 0 with a message
 * in detail otherwise, before OpenEXR allocates what a corrupt header claims. */
int rd_image_exr_header_sane(FILE *f, long long file_size, char *detail, size_t detail_size);

/* Copies the JPEG stream data[0..size) into *out (malloc'd) with an XMP APP1 segment holding
 * the packet xmp inserted after the JFIF header (image_xmp.c). 1 on success, 0 with a message
 * in detail when the packet is too large, data is no JPEG or memory runs out. */
int rd_image_jpeg_insert_xmp(const unsigned char *data, size_t size, const char *xmp,
                             unsigned char **out, size_t *out_size, char *detail,
                             size_t detail_size);

/* snprintf into err when err is usable; trailing whitespace and newlines are trimmed. */
void rd_image_set_error(char *err, size_t err_size, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
