/* A PNG's chunk list is checked before OpenImageIO sees the file. OIIO 2.4's PNG reader
 * handles a short read by longjmp-ing out of libpng past a live std::string (a leak ASan
 * reports) and libpng prints to stderr; walking the chunks first turns a truncated file into a
 * clean RD_IMAGE_ERR_FORMAT with a message that says where it ends. */
#include "image_internal.h"

#include <stdio.h>
#include <string.h>

static const unsigned char png_signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

static unsigned long long be32(const unsigned char *p)
{
    return ((unsigned long long)p[0] << 24) | ((unsigned long long)p[1] << 16) |
           ((unsigned long long)p[2] << 8) | (unsigned long long)p[3];
}

static int is_chunk_letter(unsigned char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

int rd_image_png_chunks_complete(FILE *f, long long file_size, char *detail, size_t detail_size)
{
    unsigned char head[8];
    if (fseek(f, 0, SEEK_SET) != 0 || fread(head, 1, 8, f) != 8 ||
        memcmp(head, png_signature, 8) != 0) {
        return 1; /* not a PNG: someone else's business */
    }
    long long pos = 8;
    while (pos + 8 <= file_size) {
        if (fseek(f, (long)pos, SEEK_SET) != 0 || fread(head, 1, 8, f) != 8) {
            break;
        }
        unsigned long long length = be32(head);
        char type[5] = {(char)head[4], (char)head[5], (char)head[6], (char)head[7], '\0'};
        if (!is_chunk_letter(head[4]) || !is_chunk_letter(head[5]) || !is_chunk_letter(head[6]) ||
            !is_chunk_letter(head[7])) {
            rd_image_set_error(detail, detail_size, "corrupt PNG: no valid chunk at byte %lld",
                               pos);
            return 0;
        }
        if (length > 0x7fffffffULL) {
            rd_image_set_error(detail, detail_size,
                               "corrupt PNG: chunk %s at byte %lld claims %llu bytes", type, pos,
                               length);
            return 0;
        }
        long long end = pos + 12 + (long long)length; /* length, type, data, CRC */
        if (end > file_size) {
            rd_image_set_error(detail, detail_size,
                               "truncated PNG: chunk %s at byte %lld needs %lld bytes, the file "
                               "has %lld",
                               type, pos, end, file_size);
            return 0;
        }
        if (strcmp(type, "IEND") == 0) {
            return 1;
        }
        pos = end;
    }
    rd_image_set_error(detail, detail_size,
                       "truncated PNG: %lld bytes and no IEND chunk (the end of the image)",
                       file_size);
    return 0;
}
