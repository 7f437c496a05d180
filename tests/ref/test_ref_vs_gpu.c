/* Both renderers see the same scene: the tracer's image of tests/data/scenes/small.json (camera
 * "main", 320x240, supersample 2, the settings of the GPU golden tests/golden/small-main.png)
 * matches that golden. The scene has no reflections, so only rasterising against ray casting
 * differs: pixels may differ by 1/255 (the rounding of llvmpipe's sRGB encoding), and by more
 * only on silhouettes, where a subpixel centre falls on the other side of an edge.
 *
 * Tolerance, measured (docs/reference.md): 4.8 % of the pixels differ by exactly 1/255 and 3
 * pixels (0.004 %) by more, all on silhouettes. Allowed: at most 0.05 % of the pixels (38) more
 * than 1/255 off, and at most 10 % off by 1/255. The same holds for the other camera and for
 * the glTF-model golden. Also: the scene builder refuses a missing model with the GPU builder's
 * message. */
#include "../common/check.h"
#include "../common/golden.h"
#include "app/scene/ref_scene_build.h"
#include "app/scene/scene_build.h"
#include "app/project/project.h"
#include "render/image_io.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Traces `camera` of `project` at 320x240, supersample 2, and compares with the GPU golden. */
static void compare_with_golden(const char *project, const char *camera, const char *golden_path)
{
    char err[2048];
    app_project p;
    CHECK_MSG(app_project_read(project, &p, err, sizeof err) == APP_OK, "%s", err);
    ref_scene *s = NULL;
    CHECK_MSG(app_ref_scene_build(&p, &s, err, sizeof err) == APP_OK, "%s", err);
    rd_view view;
    CHECK(app_view_from_camera(&p, camera, 320, 240, &view, err, sizeof err) == APP_OK);
    view.supersample = 2;
    ref_image img = {0};
    CHECK_MSG(ref_render(s, &(ref_render_desc){.view = view}, &img) == REF_OK, "%s",
              ref_last_error());
    rd_image golden = {0};
    CHECK_MSG(rd_image_read(golden_path, &golden, NULL, err, sizeof err) == RD_IMAGE_OK, "%s", err);
    if (img.rgba8 && golden.pixels && golden.width == 320 && golden.height == 240) {
        size_t n = 320 * 240;
        unsigned char *g8 = malloc(4 * n);
        float *g = malloc(4 * n * sizeof *g);
        rd_image_expand_rgba(&golden, g);
        for (size_t i = 0; i < 4 * n; i++)
            g8[i] = (unsigned char)(g[i] * 255.0f + 0.5f);
        long over1 = 0, over0 = 0;
        int wx, wy;
        int worst = golden_compare_rgba8(img.rgba8, g8, 320, 240, 1, &over1, &wx, &wy);
        golden_compare_rgba8(img.rgba8, g8, 320, 240, 0, &over0, NULL, NULL);
        printf("%s, camera %s: %ld pixels differ by 1/255, %ld by more (worst %d/255 at %d, "
               "%d)\n",
               project, camera, over0 - over1, over1, worst, wx, wy);
        CHECK_MSG(over1 <= (long)(n / 2000), "%ld pixels more than 1/255 off", over1);
        CHECK_MSG(over0 <= (long)(n / 10), "%ld pixels off at all", over0);
        if (over1 > (long)(n / 2000)) {
            rd_image_write_rgba8("test_ref_vs_gpu.actual.png", 320, 240, img.rgba8, NULL, 0);
            fprintf(stderr, "wrote test_ref_vs_gpu.actual.png\n");
        }
        free(g);
        free(g8);
    } else {
        CHECK_MSG(0, "%s is missing or not 320x240", golden_path);
    }
    rd_image_free(&golden);
    ref_image_free(&img);
    ref_scene_destroy(s);
    app_project_free(&p);
}

int main(void)
{
    compare_with_golden(TESSERA_SOURCE_DIR "/tests/data/scenes/small.json", "main",
                        TESSERA_SOURCE_DIR "/tests/golden/small-main.png");
    compare_with_golden(TESSERA_SOURCE_DIR "/tests/data/scenes/small.json", "corner",
                        TESSERA_SOURCE_DIR "/tests/golden/small-corner.png");
    /* glTF models (the golden test's own project and view). */
    compare_with_golden(TESSERA_SOURCE_DIR "/tests/cli/data/with-model.json", "front",
                        TESSERA_SOURCE_DIR "/tests/golden/with-model.png");

    /* A model that vanished after the project was read: the GPU builder's message (file, JSON
     * path, model name), and no scene. */
    char err[2048];
    app_project p;
    CHECK_MSG(app_project_read(TESSERA_SOURCE_DIR "/tests/cli/data/with-model.json", &p, err,
                               sizeof err) == APP_OK,
              "%s", err);
    int model = -1;
    for (int i = 0; i < p.object_count && model < 0; i++)
        if (p.objects[i].shape == APP_SHAPE_MODEL)
            model = i;
    CHECK(model >= 0);
    if (model >= 0) {
        snprintf(p.objects[model].model, sizeof p.objects[model].model, "%s",
                 "/no/such/folder/gone.glb");
        ref_scene *s = NULL;
        app_result r = app_ref_scene_build(&p, &s, err, sizeof err);
        char path[32];
        snprintf(path, sizeof path, "$.objects[%d].model", model);
        CHECK(r != APP_OK && s == NULL);
        CHECK_MSG(strstr(err, "with-model.json") && strstr(err, path) && strstr(err, "gone.glb"),
                  "%s", err);
        printf("missing model: %s\n", err);
    }
    app_project_free(&p);
    return check_report("test_ref_vs_gpu");
}
