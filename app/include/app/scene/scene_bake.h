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
    /* ref_bake_desc's: called from the bake's threads with the points done and to do; a
     * non-zero return stops the bake (APP_ERR_CANCELLED, nothing cached). NULL = none. */
    int (*progress_fn)(void *user, long long done, long long total);
    void *progress_user;
    /* 1: only a whole scene from the cache, without a ray (else APP_ERR_NOT_FOUND): what a
     * window can afford on its own thread. */
    int cache_only;
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

/* The statistics of the last app_bake_list on this thread (zero before any). */
const app_bake_stats *app_bake_last_stats(void);

/* How far a change reaches: points within this many metres of a changed element's bounding box
 * are baked again, the rest comes from the cache. */
#define APP_BAKE_REACH_M 0.6f

/* Bakes list l (its items are the bake's meshes, in order), through the cache. On success *out
 * owns the result (ref_bake_free). */
app_result app_bake_list(const app_render_list *l, const app_bake_settings *s, ref_bake *out,
                         app_bake_stats *stats, char *err, size_t err_size);

/* The cache's key of each item of l under settings s (l->item_count values): equal keys, equal
 * geometry, placement, material and light. */
void app_bake_item_keys(const app_render_list *l, const app_bake_settings *s, uint64_t *keys);

/* An earlier bake's light for a newer list (the window shows it until the newer list's own bake
 * arrives): item i of the new list (key keys[i]) takes the values of the old item with the same
 * key, or else of the old item at index i when it holds the same kind of data for as many
 * vertices (a moved fixture keeps the light of where it was); other items get none (the plain
 * ambient). The atlas is copied whole, as the carried lightmap coordinates point into it. On
 * success *out owns its arrays (ref_bake_free). */
app_result app_bake_carry(const ref_bake *old, const uint64_t *old_keys, int new_count,
                          const uint64_t *keys, ref_bake *out);

#ifdef __cplusplus
}
#endif
#endif
