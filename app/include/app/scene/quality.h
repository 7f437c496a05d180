/* Quality presets: named points of the speed/accuracy front measured by `tessera sweep`
 * (docs/accuracy.md, "The presets"), so a user picks a trade, not six settings. */
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
    /* Shadows (docs/rendering.md, "Shadows"): mode, texels per map face, soft taps. */
    rd_shadow_mode shadows;
    int shadow_map_size, shadow_taps;
    /* Where reflected rays end (RENDERING.md section 4); DEFAULT = the scene's (box). */
    rd_correction correction;
    /* Probe faces refreshed a frame at most (the live frame budget); 0 = no limit. */
    int probe_faces_per_frame;
    /* ON: adaptive supersampling (rd_view.adaptive): the s x s samples only where a pixel
     * differs from its neighbours, at the sizes app_quality_adaptive names; else every pixel
     * s x s. */
    rd_switch adaptive;
    /* ON: flat mirrors reflect from the eye's mirror image (rd_reflection_defaults); their
     * captures follow the eye, so only stills take them. */
    rd_switch planar_mirrors;
    /* Lobe directions a sample the self-reflection trace takes; 0 off
     * (rd_reflection_defaults.self_reflections). */
    int self_reflections;
    /* OFF: "depth" lookups leave the room probe out (rd_reflection_defaults.room_probe): the
     * self-reflection trace finds what it was searched for, at less cost. */
    rd_switch room_probe;
    /* ON: glazed tiles reflect the room probe (rd_reflection_defaults.glaze). */
    rd_switch glaze;
} app_quality;

/* The print preset's self-reflection rays, which --self-reflections on gives the others. */
#define APP_SELF_REFLECTION_RAYS 3

/* NULL for an unknown name. */
const app_quality *app_quality_find(const char *name);
/* "draft, interactive, final, print" */
const char *app_quality_names(void);
/* The preset's supersampling for a width x height image: its s x s, lowered while the image
 * would hold more than APP_QUALITY_MAX_SAMPLES samples (never below 1). Large prints have
 * small pixels: 2 x 2 at 3840 x 2160 samples the view as densely as 4 x 4 at 1920 x 1080. */
#define APP_QUALITY_MAX_SAMPLES (70LL * 1000 * 1000)
int app_quality_supersample(const app_quality *q, int width, int height);
/* Whether a width x height image takes the preset's samples adaptively (rd_view.adaptive): for
 * an adaptive preset, at the sizes where its supersampling was lowered. There pixels are small
 * against what they show (a 3 mm tile joint is 1.5 to 3 pixels at 3840 x 2160), so the centre
 * sample of each pixel sees every feature the mask must find; in smaller images joints are
 * thinner than a pixel, centre samples miss them and only full supersampling shows them. */
int app_quality_adaptive(const app_quality *q, int width, int height);
/* Applies the preset's probe and shadow settings to the scene's defaults. */
void app_quality_apply(const app_quality *q, rd_scene *scene);

#endif
