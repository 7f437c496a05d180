/* The bake of a project's indirect light (render/ref's ref_bake.h) with its cache
 * (docs/rendering.md, "Baked indirect light"): a file per room in $XDG_CACHE_HOME/tessera (or
 * ~/.cache/tessera), keyed by a hash of the geometry, materials and lights, so an unchanged
 * scene never bakes twice and a changed fixture re-bakes only what lies within reach of it. */
#ifndef APP_SCENE_BAKE_H
#define APP_SCENE_BAKE_H

#include "app/scene/render_list.h"
#include "ref/ref_bake.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What the GPU adapter bakes: off by default; the CLI turns it on (--bake, TESSERA_BAKE). */
typedef struct app_bake_settings {
    int on;
    int progress; /* a progress bar on stderr */
    int samples;  /* hemisphere rays per point and pass; 0 = ref_bake's default */
    int bounces;  /* gathering passes; 0 = REF_DEFAULT_BOUNCES, the reference's default */
} app_bake_settings;

void app_bake_configure(const app_bake_settings *s);
const app_bake_settings *app_bake_current(void);

typedef struct app_bake_stats {
    int ran;       /* a bake was asked for */
    int cache_hit; /* the whole scene came from the cache */
    long long baked_texels, baked_vertices, total_texels, total_vertices, rays;
    int reused_elements, elements;
    double seconds;
    char cache_path[1024];
} app_bake_stats;

/* The statistics of the last app_bake_list in this process (zero before any). */
const app_bake_stats *app_bake_last_stats(void);

/* How far a change reaches: points within this many metres of a changed element's bounding box
 * are baked again, the rest comes from the cache. */
#define APP_BAKE_REACH_M 0.6f

/* Bakes list l (its items are the bake's meshes, in order), through the cache. On success *out
 * owns the result (ref_bake_free). */
app_result app_bake_list(const app_render_list *l, const app_bake_settings *s, ref_bake *out,
                         app_bake_stats *stats, char *err, size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
