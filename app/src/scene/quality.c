/* The presets, each a point on (or next to) the Pareto front of the demo's sweep:
 *   build/app/tessera sweep assets/projects/demo-bathroom.json --size 640x360 --samples 64 \
 *       --frames 3 --warmup 1 --animate accent-band
 * (docs/benchmarks.md). Probes that stay still cost nothing after their first frame at the
 * same accuracy ("static"); box mips are as accurate as the prefilter for the demo's narrow
 * chrome lobes at a third of the cost; resolution is the accuracy knob (auto, then 128 for
 * +2 dB, 512 for +4 dB; 1024 loses again). Print also takes the "depth" correction (distance
 * impostors: demo print 25.75 -> 29.63 dB, mirror room 12.85 -> 26.49 dB on reflective
 * pixels) at about twice the frame time, which the faster presets do not buy
 * (docs/accuracy.md). Final and print take flat mirrors as planar reflections: on the Pareto
 * front of every sweep (at the baseline, demo 19.99 -> 25.53 dB in 130 instead of 170 ms, mirror
 * room 12.72 -> 30.39 dB; print demo 29.51 -> 32.14 dB; docs/accuracy.md, "Fifth round"), a
 * capture every frame that follows the eye: stills only, as a live view's frame budget holds
 * its probes still. Print's depth lookups then also searched the room probe, a capture of the
 * whole room from its centre, and covered the glazes too (demo print 32.40 -> 35.26 dB;
 * docs/accuracy.md, "Seventh round"). Print traces each fixture's reflections of itself and of the
 * fixtures beside it, three lobe directions a sample, which finds what the room probe was searched
 * for: print leaves the room probe out (designed demo 35.32 dB without it, 35.29 dB with it). Its
 * probes then hold only what lies beyond the fixtures, and 256 texels serve as well as 512
 * (designed 35.32 against 35.40 dB, demo 37.05 against 37.14; 128: 34.46 and 36.81 dB) at two
 * thirds of the 640 x 360 time and about the old preset's time for the 3840 x 2160 print (16.4 to
 * 17.1 s against 17.1 to 17.8 s; with 512 texels 20.2 s). Against the print
 * preset before: designed demo 21.73 -> 35.32 dB, demo 35.26 -> 37.05 dB, taps 20.80 -> 34.89
 * dB (docs/accuracy.md, "Ninth round"). */
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
        .use = "every probe complete at 128 texels, flat mirrors as planar reflections, 2x2 "
               "supersampling: stills",
        .update = RD_PROBE_EVERY_FRAME,
        .blur = RD_BLUR_PREFILTERED,
        .resolution = 128,
        .supersample = 2,
        .shadows = RD_SHADOWS_SOFT,
        .shadow_map_size = 1024,
        .shadow_taps = 12,
        .adaptive = RD_SWITCH_OFF,
        .planar_mirrors = RD_SWITCH_ON,
        .room_probe = RD_SWITCH_ON,
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
    rd_scene_set_reflection_defaults(scene, &d);
    /* Shadows by preset (issue 7): none in drafts and live walk-throughs (hard shadows cost
     * about 180 ns of CPU per sample on llvmpipe with the demo's three lights, some 80 ms a
     * 1280 x 720 frame on two cores; `--shadows hard` opts in), soft in stills, more taps on
     * finer maps for print. The taps per pixel are shared among its samples
     * (rd_shadow_taps_per_sample: at least 2 each), so supersampling turns them into more
     * differently placed taps rather than more work. */
    rd_shadow_settings sh = rd_scene_shadows(scene);
    sh.mode = q->shadows;
    sh.map_size = q->shadow_map_size;
    sh.taps = q->shadow_taps;
    rd_scene_set_shadows(scene, &sh);
}
