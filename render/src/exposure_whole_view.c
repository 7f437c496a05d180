/* One exposure for a picture drawn in parts (tiles, or the planner's strips): measured on a
 * small render of the whole view, so every part is exposed with the same EV. Each part
 * metering itself would expose a bright ceiling strip darker than a dim floor strip: bands. */
#include "render_internal.h"
#include "scene_internal.h"

#include <math.h>
#include <stdlib.h>

/* At most this many pixels a side: the meter reads at most 96 x 96 samples
 * (exposure_meter.c), so a larger render would not change the measure, only cost more. */
#define WHOLE_VIEW_SIDE 256.0f

rd_result rd_measure_view_exposure(rd_context *ctx, rd_scene *scene, const rd_view *view, float *ev)
{
    if (!ctx || !scene || !view || !ev)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_measure_view_exposure: missing argument");
    *ev = view->exposure_ev;
    if (!view->auto_exposure)
        return RD_OK;
    int full_w = view->full_width > 0 ? view->full_width : view->width;
    int full_h = view->full_height > 0 ? view->full_height : view->height;
    rd_view small = *view;
    float fit = WHOLE_VIEW_SIDE / (float)(full_w > full_h ? full_w : full_h);
    small.width = full_w;
    small.height = full_h;
    if (fit < 1.0f) {
        small.width = (int)fmaxf(1.0f, roundf((float)full_w * fit));
        small.height = (int)fmaxf(1.0f, roundf((float)full_h * fit));
    }
    small.supersample = 1;
    small.adaptive = 0;
    small.to_window = 0;
    small.jitter[0] = small.jitter[1] = 0.0f;
    small.crop_x = small.crop_y = small.full_width = small.full_height = 0;
    /* With keep_probes, probes captured already keep their sizes in the small render (a
     * reflection's average, what the meter reads, hardly depends on its texels), so a view
     * measured again (the planner's still view after a move) recaptures none of them, here or
     * after. Otherwise, and for probes it captured first, the next render makes them anew at
     * its own sizes, as a single render would. */
    int before = scene->probes_dirty || !view->keep_probes ? -1 : scene->probe_count;
    int *sizes = before > 0 ? malloc((size_t)before * sizeof *sizes) : NULL;
    for (int i = 0; sizes && i < before; i++)
        sizes[i] = scene->probes[i].size;
    scene->hold_probe_sizes = before >= 0;
    rd_result r = rd_render(ctx, scene, &small);
    scene->hold_probe_sizes = 0;
    if (r == RD_OK)
        *ev = ctx->stats.exposure_ev;
    int resized =
        before < 0 || scene->probes_dirty || scene->probe_count != before || (before > 0 && !sizes);
    for (int i = 0; !resized && sizes && i < before; i++)
        resized = scene->probes[i].size != sizes[i];
    free(sizes);
    if (resized)
        scene->probes_dirty = 1;
    return r;
}
