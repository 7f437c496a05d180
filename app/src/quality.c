/* The presets, each a point on (or next to) the Pareto front of the demo's sweep:
 *   build/app/tessera sweep assets/projects/demo-bathroom.json --size 640x360 --samples 64 \
 *       --frames 3 --warmup 1 --animate accent-band
 * (docs/benchmarks.md). Probes that stay still cost nothing after their first frame at the
 * same accuracy ("static"); box mips are as accurate as the prefilter for the demo's narrow
 * chrome lobes at a third of the cost; resolution is the accuracy knob (auto, then 128 for
 * +2 dB, 512 for +4 dB; 1024 loses again to aliasing in the mirror lookup). */
#include "app/quality.h"

#include <string.h>

static const app_quality presets[] = {
    {"draft", "probes captured once, box-mip blur: the fastest frames", RD_PROBE_ONCE,
     RD_BLUR_BOX_MIPS, 0, 128, 1},
    {"interactive", "one probe face per frame, prefiltered blur: a live walk-through",
     RD_PROBE_TIME_SLICED, RD_BLUR_PREFILTERED, 0, 256, 1},
    {"final", "every probe complete at 128 texels, 2x2 supersampling: stills", RD_PROBE_EVERY_FRAME,
     RD_BLUR_PREFILTERED, 128, 0, 2},
    {"print", "probes at 512 texels, 4x4 supersampling: print renders", RD_PROBE_EVERY_FRAME,
     RD_BLUR_PREFILTERED, 512, 0, 4},
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

void app_quality_apply(const app_quality *q, rd_scene *scene)
{
    rd_reflection_defaults d = rd_scene_reflection_defaults(scene);
    d.update = q->update;
    d.blur = q->blur;
    d.resolution = q->resolution;
    d.max_resolution = q->max_resolution;
    rd_scene_set_reflection_defaults(scene, &d);
}
