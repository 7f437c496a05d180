/* An XMP packet in a JPEG: the APP1 segment of the XMP specification part 3 (1.1.3): marker
 * FFE1, a big-endian length, the namespace "http://ns.adobe.com/xap/1.0/" with its NUL, then
 * the packet. Written after the JFIF APP0 segment, where readers (Google's panorama viewers,
 * exiftool) look for it. OpenImageIO writes XMP only for tags it knows, and GPano is not one.
 * The segment is spliced into the encoded bytes in memory, before the file is written, so a
 * JPEG reaches its final name with its metadata or not at all. */
#include "image_internal.h"

#include <stdlib.h>
#include <string.h>

static const char xmp_ns[] = "http://ns.adobe.com/xap/1.0/"; /* written with its NUL */

int rd_image_jpeg_insert_xmp(const unsigned char *data, size_t size, const char *xmp,
                             unsigned char **out, size_t *out_size, char *detail,
                             size_t detail_size)
{
    *out = NULL;
    *out_size = 0;
    size_t xmp_len = strlen(xmp), seg_len = 2 + sizeof xmp_ns + xmp_len;
    if (seg_len > 65535) {
        rd_image_set_error(detail, detail_size, "XMP packet of %zu bytes is over the 64 KB limit",
                           xmp_len);
        return 0;
    }
    if (size < 4 || data[0] != 0xFF || data[1] != 0xD8) {
        rd_image_set_error(detail, detail_size, "not a JPEG stream, cannot add XMP");
        return 0;
    }
    size_t at = 2;
    if (data[2] == 0xFF && data[3] == 0xE0 && size > 6) /* after JFIF APP0 */
        at = 4 + ((size_t)data[4] << 8 | data[5]);
    if (at > size)
        at = 2;
    size_t total = size + 2 + seg_len;
    unsigned char *o = malloc(total);
    if (!o) {
        rd_image_set_error(detail, detail_size, "out of memory");
        return 0;
    }
    unsigned char head[4] = {0xFF, 0xE1, (unsigned char)(seg_len >> 8),
                             (unsigned char)(seg_len & 0xFF)};
    size_t pos = 0;
    memcpy(o + pos, data, at);
    pos += at;
    memcpy(o + pos, head, 4);
    pos += 4;
    memcpy(o + pos, xmp_ns, sizeof xmp_ns);
    pos += sizeof xmp_ns;
    memcpy(o + pos, xmp, xmp_len);
    pos += xmp_len;
    memcpy(o + pos, data + at, size - at);
    *out = o;
    *out_size = total;
    return 1;
}
