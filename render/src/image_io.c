/* rd_image_read / rd_image_write_*: argument checks, limits, conversions and atomic
 * replacement in C; the pixels themselves go through the OpenImageIO adapter. */
#include "render/image_io.h"

#include "image_internal.h"
#include "image_io_oiio.h"
#include "image_write_file.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static _Thread_local rd_image_fault fault_injected = RD_IMAGE_FAULT_NONE;

void rd_image_debug_set_fault(rd_image_fault fault)
{
    fault_injected = fault;
}

rd_image_fault rd_image_fault_injected(void)
{
    return fault_injected;
}

void rd_image_free(rd_image *img)
{
    if (img != NULL) {
        free(img->pixels);
        memset(img, 0, sizeof *img);
    }
}

/* ---- reading ---------------------------------------------------------------------------- */

rd_image_result rd_image_read(const char *path, rd_image *out, int *nonfinite_replaced, char *err,
                              size_t err_size)
{
    char detail[512] = "";
    if (nonfinite_replaced != NULL) {
        *nonfinite_replaced = 0;
    }
    if (out == NULL || path == NULL || path[0] == '\0') {
        rd_image_set_error(err, err_size, "%s: cannot read: %s", path != NULL ? path : "(null)",
                           out == NULL ? "no output image given" : "empty path");
        return RD_IMAGE_ERR_INVALID;
    }
    memset(out, 0, sizeof *out);

    /* Ask the file system first: its answer ("No such file or directory") is clearer than
     * OpenImageIO's "could not find a format reader". */
    struct stat st;
    if (stat(path, &st) != 0) {
        rd_image_set_error(err, err_size, "%s: cannot read: %s", path, strerror(errno));
        return RD_IMAGE_ERR_IO;
    }
    if (S_ISDIR(st.st_mode)) {
        rd_image_set_error(err, err_size, "%s: cannot read: %s", path, strerror(EISDIR));
        return RD_IMAGE_ERR_IO;
    }
    if (!S_ISREG(st.st_mode)) {
        /* A FIFO would block and a device never end. */
        rd_image_set_error(err, err_size, "%s: cannot read: not a regular file", path);
        return RD_IMAGE_ERR_IO;
    }
    FILE *probe = fopen(path, "rb");
    if (probe == NULL) {
        rd_image_set_error(err, err_size, "%s: cannot read: %s", path, strerror(errno));
        return RD_IMAGE_ERR_IO;
    }
    int complete =
        rd_image_png_chunks_complete(probe, (long long)st.st_size, detail, sizeof detail) &&
        rd_image_exr_header_sane(probe, (long long)st.st_size, detail, sizeof detail);
    fclose(probe);
    if (!complete) {
        rd_image_set_error(err, err_size, "%s: not a readable image: %s", path, detail);
        return RD_IMAGE_ERR_FORMAT;
    }

    rd_oiio_input *in = NULL;
    rd_oiio_input_info info;
    rd_oiio_status st_open = rd_oiio_open(path, 1, &in, &info, detail, sizeof detail);
    if (st_open != RD_OIIO_OK) {
        rd_image_set_error(err, err_size, "%s: not a readable image: %s", path, detail);
        return st_open == RD_OIIO_ERR_NOMEM ? RD_IMAGE_ERR_OUT_OF_MEMORY : RD_IMAGE_ERR_FORMAT;
    }

    rd_image_result result = RD_IMAGE_OK;
    float *pixels = NULL;
    int channels = info.channels > 4 ? 4 : info.channels;
    if (info.deep || info.depth > 1) {
        rd_image_set_error(err, err_size, "%s: %s images are not supported (%s file)", path,
                           info.deep ? "deep" : "volume", info.format_name);
        result = RD_IMAGE_ERR_FORMAT;
    } else if (info.width < 1 || info.height < 1 || info.channels < 1) {
        rd_image_set_error(err, err_size, "%s: %s header gives %d x %d pixels, %d channels", path,
                           info.format_name, info.width, info.height, info.channels);
        result = RD_IMAGE_ERR_FORMAT;
    } else if (!rd_image_size_within_limits(info.width, info.height)) {
        rd_image_set_error(err, err_size,
                           "%s: image is %d x %d pixels, over the limit of %d per side and %ld "
                           "pixels",
                           path, info.width, info.height, RD_IMAGE_MAX_SIDE, RD_IMAGE_MAX_PIXELS);
        result = RD_IMAGE_ERR_TOO_LARGE;
    } else {
        size_t count = (size_t)info.width * (size_t)info.height * (size_t)channels;
        pixels = fault_injected == RD_IMAGE_FAULT_ALLOC ? NULL : malloc(count * sizeof(float));
        if (pixels == NULL) {
            rd_image_set_error(err, err_size, "%s: out of memory for %d x %d x %d floats", path,
                               info.width, info.height, channels);
            result = RD_IMAGE_ERR_OUT_OF_MEMORY;
        } else {
            rd_oiio_status st_read =
                rd_oiio_read_float(in, channels, pixels, detail, sizeof detail);
            if (st_read != RD_OIIO_OK) {
                rd_image_set_error(err, err_size, "%s: cannot decode %s image: %s", path,
                                   info.format_name, detail);
                result =
                    st_read == RD_OIIO_ERR_NOMEM ? RD_IMAGE_ERR_OUT_OF_MEMORY : RD_IMAGE_ERR_FORMAT;
            } else {
                size_t replaced = rd_image_sanitize_nonfinite(pixels, count);
                if (nonfinite_replaced != NULL) {
                    *nonfinite_replaced = replaced > INT32_MAX ? INT32_MAX : (int)replaced;
                }
            }
        }
    }
    rd_oiio_close(in);

    if (result != RD_IMAGE_OK) {
        free(pixels);
        return result;
    }
    out->width = info.width;
    out->height = info.height;
    out->channels = channels;
    out->pixels = pixels;
    out->srgb_encoded = rd_image_is_srgb_encoded(info.is_float, info.colorspace);
    return RD_IMAGE_OK;
}

/* ---- writing ---------------------------------------------------------------------------- */

/* The 8-bit writes' compression. Print-size PNGs (above 4 M pixels) take zlib level 1 instead
 * of libpng's default 6: a print's PNG is written in well under half the time for a file about
 * a third larger, a trade a print pays gladly (docs/benchmarks.md). */
static const char *rgba8_compression(const rd_image_format_info *fmt, size_t pixels)
{
    if (fmt->rgba8_compression == NULL && strcmp(fmt->oiio_name, "png") == 0 &&
        pixels > ((size_t)1 << 22))
        return "zip:1";
    return fmt->rgba8_compression;
}

/* Checks shared by both writes; returns the format or NULL with *result and the message set. */
static const rd_image_format_info *check_write_args(const char *path, int width, int height,
                                                    int channels, const void *pixels,
                                                    rd_image_result *result, char *err,
                                                    size_t err_size)
{
    const char *shown = path != NULL ? path : "(null)";
    *result = RD_IMAGE_ERR_INVALID;
    if (path == NULL || path[0] == '\0') {
        rd_image_set_error(err, err_size, "%s: cannot write: empty path", shown);
        return NULL;
    }
    if (pixels == NULL) {
        rd_image_set_error(err, err_size, "%s: cannot write: no pixels given", path);
        return NULL;
    }
    if (width < 1 || height < 1) {
        rd_image_set_error(err, err_size, "%s: cannot write: invalid size %d x %d", path, width,
                           height);
        return NULL;
    }
    if (channels < 1 || channels > 4) {
        rd_image_set_error(err, err_size, "%s: cannot write: %d channels, expected 1 to 4", path,
                           channels);
        return NULL;
    }
    if (!rd_image_size_within_limits(width, height)) {
        rd_image_set_error(err, err_size,
                           "%s: cannot write: %d x %d pixels is over the limit of %d per side "
                           "and %ld pixels",
                           path, width, height, RD_IMAGE_MAX_SIDE, RD_IMAGE_MAX_PIXELS);
        *result = RD_IMAGE_ERR_TOO_LARGE;
        return NULL;
    }
    const rd_image_format_info *fmt = rd_image_format_for_path(path);
    if (fmt == NULL) {
        rd_image_set_error(err, err_size,
                           "%s: cannot write: unknown image extension (supported: %s)", path,
                           rd_image_supported_extensions());
        *result = RD_IMAGE_ERR_FORMAT;
        return NULL;
    }
    *result = RD_IMAGE_OK;
    return fmt;
}

rd_image_result rd_image_write_rgba8(const char *path, int width, int height,
                                     const unsigned char *rgba, char *err, size_t err_size)
{
    return rd_image_write_rgba8_dpi(path, width, height, rgba, 0.0f, err, err_size);
}

rd_image_result rd_image_read_dpi(const char *path, float *dpi, char *err, size_t err_size)
{
    *dpi = 0.0f;
    rd_oiio_input *in = NULL;
    rd_oiio_input_info info;
    if (rd_oiio_open(path, 0, &in, &info, err, err_size) != RD_OIIO_OK)
        return RD_IMAGE_ERR_FORMAT;
    rd_oiio_close(in);
    float x = info.x_resolution;
    if (!strcmp(info.resolution_unit, "cm"))
        x *= 2.54f;
    else if (strcmp(info.resolution_unit, "inch") && strcmp(info.resolution_unit, "in"))
        x = 0.0f; /* no unit (a pixel aspect only): no DPI */
    *dpi = x;
    return RD_IMAGE_OK;
}

static rd_image_result write_rgba8(const char *path, int width, int height,
                                   const unsigned char *rgba, float dpi, const char *xmp, char *err,
                                   size_t err_size)
{
    rd_image_result result;
    const rd_image_format_info *fmt =
        check_write_args(path, width, height, 4, rgba, &result, err, err_size);
    if (fmt == NULL) {
        return result;
    }
    if (fmt->rgba8_channels == 0) {
        rd_image_set_error(err, err_size,
                           "%s: cannot write: %s stores linear floats; use rd_image_write_float "
                           "(8-bit formats: .png, .jpg, .jpeg, .tif, .tiff)",
                           path, fmt->name);
        return RD_IMAGE_ERR_FORMAT;
    }
    size_t count = (size_t)width * (size_t)height;
    unsigned char *converted = NULL;
    const unsigned char *data = rgba;
    if (fmt->rgba8_channels != 4) {
        converted = malloc(count * (size_t)fmt->rgba8_channels);
        if (converted == NULL) {
            rd_image_set_error(err, err_size, "%s: cannot write: out of memory", path);
            return RD_IMAGE_ERR_OUT_OF_MEMORY;
        }
        rd_image_convert_channels_u8(rgba, 4, converted, fmt->rgba8_channels, count);
        data = converted;
    }
    rd_oiio_write_desc desc = {
        .format = fmt->oiio_name,
        .width = width,
        .height = height,
        .channels = fmt->rgba8_channels,
        .data_type = RD_OIIO_UINT8,
        .file_type = RD_OIIO_UINT8,
        .pixels = data,
        .compression = rgba8_compression(fmt, count),
        .colorspace = "sRGB",
        /* Renders and textures hold straight alpha; store it as given. */
        .unassociated_alpha = 1,
        .dpi = dpi > 0.0f && dpi < 1e6f ? dpi : 0.0f,
    };
    result = rd_image_write_atomic(path, desc, fmt, xmp, err, err_size);
    free(converted);
    return result;
}

rd_image_result rd_image_write_rgba8_dpi(const char *path, int width, int height,
                                         const unsigned char *rgba, float dpi, char *err,
                                         size_t err_size)
{
    return write_rgba8(path, width, height, rgba, dpi, NULL, err, err_size);
}

rd_image_result rd_image_write_rgba8_xmp(const char *path, int width, int height,
                                         const unsigned char *rgba, const char *xmp, char *err,
                                         size_t err_size)
{
    return write_rgba8(path, width, height, rgba, 0.0f, xmp, err, err_size);
}

rd_image_result rd_image_write_float(const char *path, int width, int height, int channels,
                                     const float *pixels, char *err, size_t err_size)
{
    rd_image_result result;
    const rd_image_format_info *fmt =
        check_write_args(path, width, height, channels, pixels, &result, err, err_size);
    if (fmt == NULL) {
        return result;
    }
    if (fmt->float_channels < 0) {
        rd_image_set_error(err, err_size,
                           "%s: cannot write: %s is an 8-bit format; use rd_image_write_rgba8 "
                           "(float formats: .exr, .hdr, .tif, .tiff)",
                           path, fmt->name);
        return RD_IMAGE_ERR_FORMAT;
    }
    int file_channels = fmt->float_channels == 0 ? channels : fmt->float_channels;
    size_t count = (size_t)width * (size_t)height;
    float *converted = NULL;
    const float *data = pixels;
    if (file_channels != channels) {
        converted = malloc(count * (size_t)file_channels * sizeof(float));
        if (converted == NULL) {
            rd_image_set_error(err, err_size, "%s: cannot write: out of memory", path);
            return RD_IMAGE_ERR_OUT_OF_MEMORY;
        }
        rd_image_convert_channels_f32(pixels, channels, converted, file_channels, count);
        data = converted;
    }
    rd_oiio_write_desc desc = {
        .format = fmt->oiio_name,
        .width = width,
        .height = height,
        .channels = file_channels,
        .data_type = RD_OIIO_FLOAT,
        .file_type = fmt->float_file_type,
        .pixels = data,
        .compression = fmt->float_compression,
        .colorspace = "Linear",
        .unassociated_alpha = 0,
    };
    result = rd_image_write_atomic(path, desc, fmt, NULL, err, err_size);
    free(converted);
    return result;
}
