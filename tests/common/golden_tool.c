/* golden_tool NAME ACTUAL.png GOLDEN.png ARTIFACT_DIR: compares a rendered image with its
 * golden (STYLE.md tolerance), writing actual/expected/diff under ARTIFACT_DIR on failure.
 * TESSERA_UPDATE_GOLDEN=1 rewrites the golden instead. */
#include "golden.h"
#include "render/image_io.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: golden_tool NAME ACTUAL.png GOLDEN.png ARTIFACT_DIR\n");
        return 2;
    }
    rd_image img = {0};
    char err[1024];
    if (rd_image_read(argv[2], &img, NULL, err, sizeof err) != RD_IMAGE_OK) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    size_t n = (size_t)img.width * (size_t)img.height * 4;
    float *expanded = malloc(n * sizeof *expanded);
    unsigned char *rgba = malloc(n);
    if (!expanded || !rgba)
        return 1;
    rd_image_expand_rgba(&img, expanded);
    for (size_t i = 0; i < n; i++)
        rgba[i] = (unsigned char)(expanded[i] * 255.0f + 0.5f);
    free(expanded);
    int rc = golden_check(argv[1], rgba, img.width, img.height, argv[3], argv[4]);
    free(rgba);
    rd_image_free(&img);
    if (rc == 0)
        printf("golden %s: PASS\n", argv[1]);
    return rc ? 1 : 0;
}
