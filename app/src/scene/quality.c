/* The presets, each a point on (or next to) the speed/accuracy front of the demo's sweep
 * (`tessera sweep`, docs/accuracy.md "The speed/accuracy front"). Probes that stay still cost
 * nothing after their first frame at the same accuracy ("static"); box mips are as accurate as
 * the prefilter for the demo's narrow chrome lobes at a third of the cost; the probe resolution
 * is the accuracy knob, up to the point where finer texels stop paying. Print also takes the
 * "depth" correction (distance impostors), which places reflections far better than the box at
 * about twice the frame time, a price the faster presets do not pay. Final and print take flat
 * mirrors as planar reflections, on the front of every sweep: a capture every frame that
 * follows the eye, so stills only, as a live view's frame budget holds its probes still. Print
 * traces each fixture's reflections of itself and of the fixtures beside it (self_trace.c),
 * which finds what a search of the room probe would, so print leaves the room probe out; its
 * probes then hold only what lies beyond the fixtures, and 256 texels serve as well as 512 at
 * less time. Final sizes its probes automatically, by the reflection's size on screen (at most
 * 256 texels): at its 2x2 supersampling that is faster than a fixed 128 and as accurate in the
 * sweeps of both demos. Final and print show the room in glazed tiles by Fresnel (the room
 * probe, made only when a glaze is in view). Each preset's cost and accuracy, with the commands
 * that measure them: docs/accuracy.md and docs/benchmarks.md. */
#include "app/scene/quality.h"

#include <string.h>

static const app_quality presets[] = {
    {
        .name = "draft",
        .use = "probes captured once, box-mip blur: the fastest frames",
        .update = RD_PROBE_ONCE,
        .blur = RD_BLUR_BOX_MIPS,
        .max_resolution = 128,
        .supersample = 1,
        .shadows = RD_SHADOWS_OFF,
        .adaptive = RD_SWITCH_OFF,
        .planar_mirrors = RD_SWITCH_OFF,
        .room_probe = RD_SWITCH_ON,
    },
    {
        .name = "interactive",
        .use = "probes refreshed on change, one face a frame, prefiltered blur: live",
        .update = RD_PROBE_ON_CHANGE,
        .blur = RD_BLUR_PREFILTERED,
        .max_resolution = 256,
        .supersample = 1,
        .shadows = RD_SHADOWS_OFF,
        .shadow_map_size = 1024,
        .shadow_taps = 1,
        .probe_faces_per_frame = 1,
        .adaptive = RD_SWITCH_OFF,
        .planar_mirrors = RD_SWITCH_OFF,
        .room_probe = RD_SWITCH_ON,
    },
    {
        .name = "final",
        .use = "every probe complete every frame at the reflection's size on screen, flat "
               "mirrors as planar reflections, 2x2 supersampling: stills",
        .update = RD_PROBE_EVERY_FRAME,
        .blur = RD_BLUR_PREFILTERED,
        .supersample = 2,
        .shadows = RD_SHADOWS_SOFT,
        .shadow_map_size = 1024,
        .shadow_taps = 12,
        .adaptive = RD_SWITCH_OFF,
        .planar_mirrors = RD_SWITCH_ON,
        .room_probe = RD_SWITCH_ON,
        .glaze = RD_SWITCH_ON,
    },
    {
        .name = "print",
        .use = "probes at 256 texels, depth lookups, fixtures' reflections of themselves and their "
               "neighbours traced, flat mirrors as planar reflections, 4x4 supersampling "
               "(adaptive in large prints), soft shadows: print",
        .update = RD_PROBE_EVERY_FRAME,
        .blur = RD_BLUR_PREFILTERED,
        .resolution = 256,
        .supersample = 4,
        .shadows = RD_SHADOWS_SOFT,
        .shadow_map_size = 2048,
        .shadow_taps = 16,
        .correction = RD_CORRECTION_DEPTH,
        .adaptive = RD_SWITCH_ON,
        .planar_mirrors = RD_SWITCH_ON,
        .self_reflections = APP_SELF_REFLECTION_RAYS,
        .room_probe = RD_SWITCH_OFF,
        .glaze = RD_SWITCH_ON,
    },
};

const app_quality *app_quality_find(const char *name)
{
    for (size_t i = 0; name && i < sizeof presets / sizeof presets[0]; i++)
        if (!strcmp(presets[i].name, name))
            return &presets[i];
    return NULL;
}

const char *app_quality_names(void)
{
    return "draft, interactive, final, print";
}

int app_quality_supersample(const app_quality *q, int width, int height)
{
    int s = q->supersample > 1 ? q->supersample : 1;
    while (s > 1 && (long long)width * height * s * s > APP_QUALITY_MAX_SAMPLES)
        s--;
    return s;
}

int app_quality_adaptive(const app_quality *q, int width, int height)
{
    return q->adaptive == RD_SWITCH_ON &&
           app_quality_supersample(q, width, height) < q->supersample;
}

void app_quality_apply(const app_quality *q, rd_scene *scene)
{
    rd_reflection_defaults d = rd_scene_reflection_defaults(scene);
    d.update = q->update;
    d.blur = q->blur;
    d.resolution = q->resolution;
    d.max_resolution = q->max_resolution;
    if (q->correction != RD_CORRECTION_DEFAULT)
        d.correction = q->correction;
    d.max_faces_per_frame = q->probe_faces_per_frame;
    d.planar_mirrors = q->planar_mirrors;
    d.self_reflections = q->self_reflections;
    d.room_probe = q->room_probe;
    d.glaze = q->glaze;
    rd_scene_set_reflection_defaults(scene, &d);
    /* Shadows by preset: none in drafts and live walk-throughs (hard shadows are filtered per
     * sample on the CPU under llvmpipe, too dear for a live frame budget; `--shadows hard`
     * opts in; docs/benchmarks.md), soft in stills, more taps on
     * finer maps for print. The taps per pixel are shared among its samples
     * (rd_shadow_taps_per_sample: at least 2 each), so supersampling turns them into more
     * differently placed taps rather than more work. */
    rd_shadow_settings sh = rd_scene_shadows(scene);
    sh.mode = q->shadows;
    sh.map_size = q->shadow_map_size;
    sh.taps = q->shadow_taps;
    rd_scene_set_shadows(scene, &sh);
}
