/* Images larger than one render target: the view cut into tiles, each rendered with an
 * off-centre projection (rd_view.crop_*, camera.c) and copied into place. Every tile sees the
 * same camera, near/far, probes and shadow maps, so the stitched image equals an untiled render
 * of the same size (tests/render/test_print_render.c). */
#include "phase_timer.h"
#include "render_internal.h"
#include "scene_internal.h"

#include <math.h>
#include <stdlib.h>

/* Output pixels per side of the largest tile: the context's limit over the supersampling, and
 * at most 8192 samples a side, so that a tile's radiance and depth targets stay under 1 GB
 * (8192^2 x (8 + 4) bytes) whatever the image's size. A tile repeats the whole draw list and
 * its fixed costs, so the fewer and larger the tiles the faster the print (a 4K print at 2 x 2
 * fits in one tile; docs/benchmarks.md). */
static int tile_side(const rd_context *ctx, int supersample, int tile_max)
{
    int s = supersample > 1 ? supersample : 1;
    int side = ctx->max_size / s;
    if (side > 8192 / s)
        side = 8192 / s;
    if (tile_max > 0 && tile_max < side)
        side = tile_max;
    return side > 0 ? side : 1;
}

void rd_scene_hold_probes(rd_scene *scene, int hold)
{
    if (scene)
        scene->hold_probes = hold != 0;
}

/* A tiled image's statistics: the work of every tile summed, the scene's state (probes, lamps,
 * traced triangles) as the tile that saw most of it. */
static void add_tile_stats(rd_frame_stats *total, const rd_frame_stats *t)
{
    total->faces_captured += t->faces_captured;
    total->prefiltered += t->prefiltered;
    total->refined_pixels += t->refined_pixels;
    total->planar_mirrors += t->planar_mirrors;
#define KEEP_MAX(f) total->f = t->f > total->f ? t->f : total->f
    KEEP_MAX(probes);
    KEEP_MAX(adaptive);
    KEEP_MAX(room_probe);
    KEEP_MAX(glazed);
    KEEP_MAX(emitters);
    KEEP_MAX(emitter_probes);
    KEEP_MAX(self_traced_probes);
    KEEP_MAX(self_triangles);
#undef KEEP_MAX
}

rd_result rd_render_tiled(rd_context *ctx, rd_scene *scene, const rd_view *view, int tile_max,
                          uint8_t *rgba8, float *linear,
                          void (*progress)(void *user, int done, int total), void *user)
{
    if (!ctx || !scene || !view || !rgba8)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_render_tiled: missing argument");
    if (view->width <= 0 || view->height <= 0 || view->width > 16384 || view->height > 16384)
        return rd_fail(RD_ERR_TOO_LARGE, "image size %dx%d: each side must be 1 to 16384",
                       view->width, view->height);
    int side = tile_side(ctx, view->supersample, tile_max);
    int cols = (view->width + side - 1) / side, rows = (view->height + side - 1) / side;
    size_t tile_px = (size_t)side * (size_t)side;
    uint8_t *tile8 = malloc(tile_px * 4);
    float *tilef = linear ? malloc(tile_px * 4 * sizeof(float)) : NULL;
    if (!tile8 || (linear && !tilef)) {
        free(tile8);
        free(tilef);
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "out of memory for a %dx%d tile", side, side);
    }
    /* After the first tile the probes hold what every tile needs: keep them (a policy that
     * would capture again each frame would only repeat the same work). */
    rd_view whole = *view;
    if (view->auto_exposure && (cols > 1 || rows > 1)) {
        rd_result mr = rd_measure_view_exposure(ctx, scene, view, &whole.exposure_ev);
        if (mr != RD_OK) {
            free(tile8);
            free(tilef);
            return mr;
        }
        whole.auto_exposure = 0;
    }
    view = &whole;
    rd_probe_update saved_update = scene->reflection.update;
    if (scene->hold_probes)
        scene->reflection.update = RD_PROBE_ONCE;
    rd_result r = RD_OK;
    rd_frame_stats total = {0};
    rd_phase_restart();
    for (int ty = 0; ty < rows && r == RD_OK; ty++)
        for (int tx = 0; tx < cols && r == RD_OK; tx++) {
            rd_view t = *view;
            t.crop_x = tx * side;
            t.crop_y = ty * side;
            t.width = view->width - t.crop_x < side ? view->width - t.crop_x : side;
            t.height = view->height - t.crop_y < side ? view->height - t.crop_y : side;
            t.full_width = view->width;
            t.full_height = view->height;
            t.to_window = 0;
            if (cols == 1 && rows == 1)
                t.full_width = t.full_height = 0; /* one tile: the plain projection */
            r = rd_render(ctx, scene, &t);
            if (r == RD_OK)
                add_tile_stats(&total, &ctx->stats);
            rd_phase_mark("main pass and tone map");
            if (r == RD_OK)
                r = rd_read_rgba8(ctx, tile8, tile_px * 4);
            if (r == RD_OK && linear)
                r = rd_read_linear(ctx, tilef, tile_px * 4);
            rd_phase_mark("readback");
            if (r != RD_OK)
                break;
            for (int y = 0; y < t.height; y++) {
                size_t dst = ((size_t)(t.crop_y + y) * (size_t)view->width + (size_t)t.crop_x) * 4;
                size_t src = (size_t)y * (size_t)t.width * 4;
                memcpy(rgba8 + dst, tile8 + src, (size_t)t.width * 4);
                if (linear)
                    memcpy(linear + dst, tilef + src, (size_t)t.width * 4 * sizeof(float));
            }
            rd_phase_mark("tile copy");
            scene->reflection.update = RD_PROBE_ONCE;
            if (progress)
                progress(user, ty * cols + tx + 1, rows * cols);
        }
    rd_phase_report("rd_render_tiled");
    total.exposure_ev = ctx->stats.exposure_ev;
    ctx->stats = total;
    scene->reflection.update = saved_update;
    free(tile8);
    free(tilef);
    return r;
}
