/* libFuzzer target for the image reader (rd_image_read, render/image_io.h): each input is
 * written to a file in a private temporary folder, named by the format its first bytes claim
 * (PNG, JPEG, TIFF, OpenEXR, Radiance HDR; anything else as .png), and read back. The read
 * must succeed with a sane image or fail with a message; it must never crash. */
#define _XOPEN_SOURCE 700 /* mkdtemp */
#include "render/image_io.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char g_dir[4096];
static char g_path[4200];

static void remove_dir(void)
{
    if (g_path[0])
        unlink(g_path);
    rmdir(g_dir);
}

static const char *extension_for(const uint8_t *d, size_t n)
{
    if (n >= 4 && d[0] == 0xFF && d[1] == 0xD8)
        return ".jpg";
    if (n >= 4 && ((d[0] == 'I' && d[1] == 'I') || (d[0] == 'M' && d[1] == 'M')))
        return ".tif";
    if (n >= 4 && d[0] == 0x76 && d[1] == 0x2F && d[2] == 0x31 && d[3] == 0x01)
        return ".exr";
    if (n >= 2 && d[0] == '#' && d[1] == '?')
        return ".hdr";
    return ".png";
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!g_dir[0]) {
        const char *base = getenv("TMPDIR");
        snprintf(g_dir, sizeof g_dir, "%s/tessera-fuzz-image-XXXXXX",
                 base && *base ? base : "/tmp");
        if (!mkdtemp(g_dir))
            abort();
        atexit(remove_dir);
    }
    if (g_path[0])
        unlink(g_path);
    snprintf(g_path, sizeof g_path, "%s/input%s", g_dir, extension_for(data, size));
    FILE *f = fopen(g_path, "wb");
    if (!f)
        abort();
    if (size && fwrite(data, 1, size, f) != size)
        abort();
    fclose(f);
    rd_image img;
    char err[1024] = "";
    int nonfinite = 0;
    if (rd_image_read(g_path, &img, &nonfinite, err, sizeof err) == RD_IMAGE_OK) {
        if (img.width <= 0 || img.height <= 0 || img.channels < 1 || img.channels > 4 ||
            !img.pixels)
            abort(); /* a read that succeeds returns pixels */
        rd_image_free(&img);
    } else if (!err[0]) {
        abort(); /* a read that fails says why */
    }
    return 0;
}
