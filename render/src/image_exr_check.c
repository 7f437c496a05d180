/* An OpenEXR header is checked before OpenImageIO sees the file. OpenEXR 3.1 allocates what a
 * header attribute's size field claims before it reads the value, so a few hundred bytes that
 * claim a 1.8 GB string take seconds and gigabytes before "Unexpected end of file"
 * (docs/fuzzing.md). Walking the header first refuses an attribute longer than the rest of the
 * file, and a data window over the image limits (render/image_io.h), in microseconds.
 *
 * Layout (OpenEXR "File Layout", openexr.com/en/latest/OpenEXRFileLayout.html): the magic
 * 76 2f 31 01, a version word (flags 0x400 long names, 0x1000 multi-part), then per part a
 * header: attributes "name\0type\0" + int32 size + value, ending in an empty name; a
 * multi-part file ends its list of headers with an empty header. */
#include "image_internal.h"

#include "render/image_io.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

enum { EXR_LONG_NAMES = 0x400, EXR_MULTI_PART = 0x1000 };

static uint32_t le32(const unsigned char *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

/* Reads a NUL-terminated name of at most max bytes; its length, or -1 when it does not end. */
static int read_name(FILE *f, char *out, int max)
{
    for (int i = 0; i <= max; i++) {
        int ch = fgetc(f);
        if (ch == EOF)
            return -1;
        out[i] = (char)ch;
        if (ch == 0)
            return i;
    }
    return -1;
}

/* Bytes a pixel over every channel of a chlist value: per channel "name\0", int32 pixel type
 * (0 uint, 1 half, 2 float), 12 more bytes; a final NUL. -1 when malformed. */
static long long channel_bytes(const unsigned char *v, size_t n)
{
    long long bytes = 0;
    size_t i = 0;
    while (i < n && v[i] != 0) {
        const void *end = memchr(v + i, 0, n - i);
        if (!end)
            return -1;
        i = (size_t)((const unsigned char *)end - v) + 1;
        if (i + 16 > n)
            return -1;
        uint32_t type = le32(v + i);
        bytes += type == 1 ? 2 : 4;
        i += 16;
    }
    return i < n ? bytes : -1;
}

static int fail(char *detail, size_t detail_size, const char *what, long long at)
{
    rd_image_set_error(detail, detail_size, "corrupt OpenEXR header: %s (at byte %lld)", what, at);
    return 0;
}

int rd_image_exr_header_sane(FILE *f, long long file_size, char *detail, size_t detail_size)
{
    unsigned char head[8];
    if (fseek(f, 0, SEEK_SET) != 0 || fread(head, 1, 8, f) != 8 || head[0] != 0x76 ||
        head[1] != 0x2f || head[2] != 0x31 || head[3] != 0x01)
        return 1; /* not OpenEXR: someone else's business */
    uint32_t flags = le32(head + 4);
    int max_name = flags & EXR_LONG_NAMES ? 255 : 31;
    int parts = 0;
    for (;;) {
        long long window_pixels = -1, pixel_bytes = -1, attributes = 0;
        for (;;) {
            char name[256], type[256];
            long long at = ftell(f);
            int len = read_name(f, name, max_name);
            if (len < 0)
                return fail(detail, detail_size, "an attribute name does not end", at);
            if (len == 0)
                break;
            if (read_name(f, type, max_name) <= 0)
                return fail(detail, detail_size, "an attribute type does not end", at);
            unsigned char size_le[4];
            if (fread(size_le, 1, 4, f) != 4)
                return fail(detail, detail_size, "the file ends in an attribute", at);
            int32_t size = (int32_t)le32(size_le);
            long long value_at = ftell(f);
            if (size < 0 || (long long)size > file_size - value_at) {
                char what[400];
                snprintf(what, sizeof what,
                         "attribute \"%s\" claims %ld bytes, more than the %lld left in the file",
                         name, (long)size, file_size - value_at);
                return fail(detail, detail_size, what, at);
            }
            attributes++;
            if (!strcmp(name, "dataWindow") && !strcmp(type, "box2i") && size == 16) {
                unsigned char v[16];
                if (fread(v, 1, 16, f) != 16)
                    return fail(detail, detail_size, "the file ends in the data window", at);
                long long w = (long long)(int32_t)le32(v + 8) - (int32_t)le32(v) + 1;
                long long h = (long long)(int32_t)le32(v + 12) - (int32_t)le32(v + 4) + 1;
                if (w < 1 || h < 1)
                    return fail(detail, detail_size, "the data window is empty", at);
                if (w > RD_IMAGE_MAX_SIDE || h > RD_IMAGE_MAX_SIDE) {
                    rd_image_set_error(detail, detail_size,
                                       "OpenEXR data window of %lld x %lld pixels, over the limit "
                                       "of %d a side",
                                       w, h, RD_IMAGE_MAX_SIDE);
                    return 0;
                }
                window_pixels = w * h;
            } else if (!strcmp(name, "channels") && !strcmp(type, "chlist") && size <= 65536) {
                unsigned char v[65536];
                if (fread(v, 1, (size_t)size, f) != (size_t)size)
                    return fail(detail, detail_size, "the file ends in the channel list", at);
                pixel_bytes = channel_bytes(v, (size_t)size);
                if (pixel_bytes < 0)
                    return fail(detail, detail_size, "the channel list is malformed", at);
            } else if (fseek(f, size, SEEK_CUR) != 0) {
                return fail(detail, detail_size, "cannot skip an attribute", at);
            }
        }
        /* The decoded pixels: at most the image limit in 4 float channels. */
        if (window_pixels > 0 && pixel_bytes > 0 &&
            window_pixels * pixel_bytes >
                (long long)RD_IMAGE_MAX_PIXELS * 4 * (long long)sizeof(float)) {
            rd_image_set_error(detail, detail_size,
                               "OpenEXR data window of %lld pixels x %lld bytes a pixel, over the "
                               "limit of %ld pixels in 4 float channels",
                               window_pixels, pixel_bytes, RD_IMAGE_MAX_PIXELS);
            return 0;
        }
        parts++;
        if (!(flags & EXR_MULTI_PART) || attributes == 0)
            break;
        if (parts > 4096)
            return fail(detail, detail_size, "more than 4096 parts", ftell(f));
    }
    return 1;
}
