/* Baked indirect light on the CPU (docs/rendering.md, "Baked indirect light"): the irradiance
 * that reaches each surface after one or more diffuse bounces, and its ambient occlusion, stored
 * where the GPU can read it back in place of the constant or SH9 ambient term:
 *
 * - planar meshes (the room's walls, floor, ceiling, pre-walls, reveals) in one lightmap atlas:
 *   each plane of such a mesh gets its own rectangle of texels, so no UV unwrapper is needed;
 * - every other mesh per vertex.
 *
 * The bake runs on the reference tracer's scene (ref.h) and its Embree rays. A point gathers
 * `samples` cosine-weighted hemisphere rays; at each hit it adds that surface's direct light
 * (next-event estimation: a shadow ray to every light) times its diffuse albedo, its emission,
 * and its ambient albedo times the irradiance the previous pass stored there (the lightmap or
 * the hit triangle's vertices), so pass k carries k bounces. Units: metres; the stored value is
 * the ambient intensity I (the GPU's I_a) = irradiance / pi, linear RGB. */
#ifndef REF_REF_BAKE_H
#define REF_REF_BAKE_H

#include "ref/ref.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum ref_bake_kind {
    REF_BAKE_NONE = 0,     /* not baked: glass, emitters; keeps the scene's ambient */
    REF_BAKE_VERTEX = 1,   /* per-vertex values */
    REF_BAKE_LIGHTMAP = 2, /* texels of the atlas, reached through per-vertex lightmap UVs */
} ref_bake_kind;

/* One plane of a lightmapped mesh: a rectangle of the atlas, with one texel of gutter on each
 * side. Texel (i, j) of the chart is centred at origin + (i - 0.5) * texel * u + (j - 0.5) *
 * texel * v (u, v unit, in the plane; normal = u x v). */
typedef struct ref_bake_chart {
    int mesh;
    int x, y, width, height; /* in atlas texels, gutter included */
    float origin[3], u[3], v[3], normal[3];
    float texel_m;
} ref_bake_chart;

typedef struct ref_bake_mesh {
    ref_bake_kind kind;
    int vertex_count;
    /* REF_BAKE_VERTEX: 4 floats per vertex: I (rgb), ambient occlusion (1 open, 0 closed). */
    float *vertex;
    /* REF_BAKE_LIGHTMAP: 2 floats per vertex, atlas coordinates in [0, 1] (GL convention: the
     * first row of `atlas` is v = 0). */
    float *lightmap_uv;
    float bounds_min[3], bounds_max[3]; /* world bounds of the mesh */
} ref_bake_mesh;

typedef struct ref_bake {
    int mesh_count; /* the scene's meshes, in the order they were added */
    ref_bake_mesh *meshes;
    int atlas_width, atlas_height;
    float *atlas;         /* 4 floats per texel: I (rgb), occlusion; row 0 first */
    unsigned char *cover; /* per texel: 1 where the texel's centre lies on its chart's polygon */
    int chart_count;
    ref_bake_chart *charts;
    /* What the last ref_bake_run computed, against what it holds. */
    long long baked_texels, baked_vertices, total_texels, total_vertices;
    long long rays;
    double seconds;
} ref_bake;

typedef struct ref_bake_desc {
    int samples;         /* hemisphere rays per point and pass; 0 = 64 */
    int passes;          /* gathering passes (bounces); 0 = REF_DEFAULT_BOUNCES */
    float texel_m;       /* lightmap texel side; 0 = 0.03 m */
    float ao_distance_m; /* hits nearer than this occlude; 0 = 0.5 m */
    int threads;         /* 0 = the online processors */
    int progress;        /* 1: a progress bar on stderr when it is a terminal */
    /* Per scene mesh (NULL = none): 1 = lightmap it (a planar room surface). Meshes with
     * transparency > 0 or emission are never baked. */
    const unsigned char *lightmapped;
    /* Partial re-bake: with `previous` (the same scene layout: same meshes, same lightmapped
     * set, same atlas), only points within reach_m of one of the boxes (min xyz, max xyz) are
     * computed; the rest is copied from `previous`, and the computed points see it as the
     * light of their surroundings. NULL = bake everything. `keep` (per mesh, NULL = all): the
     * meshes whose values in `previous` hold; the others are computed whole. */
    const ref_bake *previous;
    const float (*dirty_boxes)[6];
    int dirty_box_count;
    float reach_m;
    const unsigned char *keep;
    /* Called from the bake's threads after every few points with the points done and to do
     * over all passes (so it must be cheap and thread-safe); a non-zero return stops the bake,
     * which then fails with REF_ERR_CANCELLED (a window's bake superseded by a newer edit).
     * NULL = none. */
    int (*progress_fn)(void *user, long long done, long long total);
    void *progress_user;
} ref_bake_desc;

/* Bakes scene s (committed here if needed). On success *out owns its arrays (ref_bake_free);
 * on failure it is zeroed and ref_last_error() says why. */
ref_result ref_bake_run(ref_scene *s, const ref_bake_desc *d, ref_bake *out);
void ref_bake_free(ref_bake *b);

/* Shelf packing of n rectangles (w[i] x h[i] texels) into an atlas at most max_width wide:
 * tallest first, left to right, rows top to bottom; no two rectangles overlap. Writes each
 * rectangle's corner to x[i], y[i] and the atlas size (the width rounded up to a multiple of 4).
 * Returns 0 when a rectangle is wider than max_width or a size is not positive. */
int ref_atlas_pack(const int *w, const int *h, int n, int max_width, int *x, int *y, int *atlas_w,
                   int *atlas_h);

#ifdef __cplusplus
}
#endif
#endif
