/* An XMP packet in a JPEG: the APP1 segment of the XMP specification part 3 (1.1.3): marker
 * FFE1, a big-endian length, the namespace "http://ns.adobe.com/xap/1.0/" with its NUL, then
 * the packet. Written after the JFIF APP0 segment, where readers (Google's panorama viewers,
 * exiftool) look for it. OpenImageIO writes XMP only for tags it knows, and GPano is not one. */
#include "render/image_io.h"

#include "image_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char xmp_ns[] = "http://ns.adobe.com/xap/1.0/"; /* written with its NUL */

rd_image_result rd_image_jpeg_add_xmp(const char *path, const char *xmp, char *err, size_t err_size)
{
    if (!path || !xmp)
        return RD_IMAGE_ERR_INVALID;
    size_t xmp_len = strlen(xmp), seg_len = 2 + sizeof xmp_ns + xmp_len;
    if (seg_len > 65535) {
        rd_image_set_error(err, err_size, "%s: XMP packet of %zu bytes is over the 64 KB limit",
                           path, xmp_len);
        return RD_IMAGE_ERR_INVALID;
    }
    FILE *f = fopen(path, "rb");
    if (!f) {
        rd_image_set_error(err, err_size, "%s: cannot open to add XMP", path);
        return RD_IMAGE_ERR_IO;
    }
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *data = size > 4 ? malloc((size_t)size) : NULL;
    int ok = data && fread(data, 1, (size_t)size, f) == (size_t)size;
    fclose(f);
    if (!ok || data[0] != 0xFF || data[1] != 0xD8) {
        free(data);
        rd_image_set_error(err, err_size, "%s: not a JPEG file, cannot add XMP", path);
        return RD_IMAGE_ERR_FORMAT;
    }
    size_t at = 2;
    if (data[2] == 0xFF && data[3] == 0xE0 && size > 6) /* after JFIF APP0 */
        at = 4 + ((size_t)data[4] << 8 | data[5]);
    if (at > (size_t)size)
        at = 2;
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.xmp-%ld", path, (long)getpid());
    FILE *o = fopen(tmp, "wb");
    if (!o) {
        free(data);
        rd_image_set_error(err, err_size, "%s: cannot write %s", path, tmp);
        return RD_IMAGE_ERR_IO;
    }
    unsigned char head[4] = {0xFF, 0xE1, (unsigned char)(seg_len >> 8),
                             (unsigned char)(seg_len & 0xFF)};
    ok = fwrite(data, 1, at, o) == at && fwrite(head, 1, 4, o) == 4 &&
         fwrite(xmp_ns, 1, sizeof xmp_ns, o) == sizeof xmp_ns &&
         fwrite(xmp, 1, xmp_len, o) == xmp_len &&
         fwrite(data + at, 1, (size_t)size - at, o) == (size_t)size - at;
    ok = fclose(o) == 0 && ok;
    free(data);
    if (!ok || rename(tmp, path) != 0) {
        remove(tmp);
        rd_image_set_error(err, err_size, "%s: writing the XMP segment failed", path);
        return RD_IMAGE_ERR_IO;
    }
    return RD_IMAGE_OK;
}
