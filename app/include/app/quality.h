/* Quality presets: named points of the speed/accuracy front measured by `tessera sweep`
 * (docs/benchmarks.md, "The trade"), so a user picks a trade, not six settings. */
#ifndef APP_QUALITY_H
#define APP_QUALITY_H

#include "render/render.h"

typedef struct app_quality {
    const char *name;
    const char *use; /* one line for --help and the docs */
    rd_probe_update update;
    rd_blur_method blur;
    int resolution;     /* 0 = auto */
    int max_resolution; /* cap of auto; 0 = the renderer's */
    int supersample;
} app_quality;

/* NULL for an unknown name. */
const app_quality *app_quality_find(const char *name);
/* "draft, interactive, final, print" */
const char *app_quality_names(void);
/* Applies the preset's probe settings to the scene's defaults. */
void app_quality_apply(const app_quality *q, rd_scene *scene);

#endif
