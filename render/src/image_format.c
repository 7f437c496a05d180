/* Which extensions Tessera writes, how, and the size limits for every image it touches. */
#include "image_internal.h"

#include "render/image_io.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static const rd_image_format_info formats[] = {
    {"png", "PNG", "png", 0, 4, NULL, -1, RD_OIIO_FLOAT, NULL},
    {"jpg", "JPEG", "jpeg", 0, 3, "jpeg:95", -1, RD_OIIO_FLOAT, NULL},
    {"jpeg", "JPEG", "jpeg", 0, 3, "jpeg:95", -1, RD_OIIO_FLOAT, NULL},
    {"tif", "TIFF", "tiff", 0, 4, "zip", 0, RD_OIIO_FLOAT, "zip"},
    {"tiff", "TIFF", "tiff", 0, 4, "zip", 0, RD_OIIO_FLOAT, "zip"},
    /* Half floats: renders and environment maps need range, not 24 bits of mantissa. */
    {"exr", "OpenEXR", "openexr", 1, 0, NULL, 0, RD_OIIO_HALF, "zip"},
    /* RGBE stores exactly three channels. */
    {"hdr", "Radiance HDR", "hdr", 1, 0, NULL, 3, RD_OIIO_FLOAT, NULL},
};

const char *rd_image_supported_extensions(void)
{
    return ".png, .jpg, .jpeg, .tif, .tiff, .exr, .hdr";
}

const rd_image_format_info *rd_image_format_for_path(const char *path)
{
    if (path == NULL) {
        return NULL;
    }
    const char *slash = strrchr(path, '/');
    const char *base = slash != NULL ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    if (dot == NULL || dot == base) {
        return NULL; /* no extension, or a hidden file like ".png" */
    }
    const char *ext = dot + 1;
    for (size_t i = 0; i < sizeof formats / sizeof formats[0]; i++) {
        const char *a = formats[i].ext;
        const char *b = ext;
        while (*a != '\0' && *b != '\0' && *a == tolower((unsigned char)*b)) {
            a++;
            b++;
        }
        if (*a == '\0' && *b == '\0') {
            return &formats[i];
        }
    }
    return NULL;
}

int rd_image_format_is_float(const char *path)
{
    const rd_image_format_info *f = rd_image_format_for_path(path);
    return f == NULL ? -1 : f->is_float;
}

int rd_image_size_within_limits(long long width, long long height)
{
    return width > 0 && height > 0 && width <= RD_IMAGE_MAX_SIDE && height <= RD_IMAGE_MAX_SIDE &&
           width * height <= RD_IMAGE_MAX_PIXELS;
}

static int equals_ignoring_case(const char *a, const char *b)
{
    while (*a != '\0' && *b != '\0' && tolower((unsigned char)*a) == tolower((unsigned char)*b)) {
        a++;
        b++;
    }
    return *a == '\0' && *b == '\0';
}

int rd_image_is_srgb_encoded(int stored_as_float, const char *colorspace)
{
    if (colorspace != NULL && (equals_ignoring_case(colorspace, "linear") ||
                               equals_ignoring_case(colorspace, "scene_linear") ||
                               equals_ignoring_case(colorspace, "lin_srgb"))) {
        return 0;
    }
    if (colorspace != NULL && equals_ignoring_case(colorspace, "srgb")) {
        return 1;
    }
    return stored_as_float ? 0 : 1;
}

void rd_image_set_error(char *err, size_t err_size, const char *fmt, ...)
{
    if (err == NULL || err_size == 0) {
        return;
    }
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, err_size, fmt, ap);
    va_end(ap);
    size_t n = strlen(err);
    while (n > 0 && isspace((unsigned char)err[n - 1])) {
        err[--n] = '\0';
    }
}
