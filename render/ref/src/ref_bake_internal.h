/* Internals of the bake (ref_bake*.c); nothing here is public. */
#ifndef REF_BAKE_INTERNAL_H
#define REF_BAKE_INTERNAL_H

#include "ref/ref_bake.h"
#include "ref_internal.h"

/* A point the bake computes: a texel centre or a vertex, lifted off its surface. */
typedef struct bake_point {
    float p[3], n[3];
    int slot; /* index into the value arrays: texels first (atlas order), then vertices */
} bake_point;

/* The values of one pass: 4 floats (I rgb, occlusion) per atlas texel, then per vertex of every
 * vertex-baked mesh (mesh m's vertices start at vertex_base[m]). */
typedef struct bake_layout {
    int texels;       /* atlas_width * atlas_height */
    int *vertex_base; /* per mesh: first slot of its vertices, -1 when not vertex-baked */
    int slots;        /* texels + every baked vertex */
    int **tri_chart;  /* per mesh: NULL, or per triangle of a lightmapped mesh: its chart */
} bake_layout;

/* Charts of the lightmapped meshes, their atlas, per-vertex lightmap UVs and texel coverage
 * (ref_bake_atlas.c). Fills b's charts, atlas size, cover and meshes[m].lightmap_uv. */
ref_result ref_bake_charts_make(const ref_scene *s, const unsigned char *lightmapped, float texel_m,
                                ref_bake *b, bake_layout *layout);

/* The world point and normal at the centre of atlas texel (x, y) of chart c. */
void ref_bake_texel_point(const ref_bake_chart *c, int x, int y, float p[3]);

/* Gathers one pass over points (ref_bake_gather.c): values[slot] (4 floats) from prev. */
typedef struct bake_gather_job {
    const ref_scene *scene;
    const ref_bake *bake;
    const bake_layout *layout;
    const bake_point *points;
    int point_count;
    const float *prev;     /* the stored light the hits look up (4 per slot) */
    float *out;            /* written at the points' slots */
    unsigned char *buried; /* per slot: 1 where the point lies inside a closed mesh */
    int samples;
    float ao_distance;
    int pass;
    int threads;
    int progress;                            /* a bar on stderr */
    long long progress_done, progress_total; /* over every pass */
    long long rays;
    int (*progress_fn)(void *user, long long done, long long total); /* ref_bake_desc's */
    void *progress_user;
} bake_gather_job;

ref_result ref_bake_gather(bake_gather_job *job);

/* Noise filters (ref_bake_filter.c): an edge-avoiding a-trous filter of the atlas inside each
 * chart, then the gutter and uncovered texels filled from covered neighbours; a smoothing of the
 * per-vertex values across a mesh's edges between vertices of like normals. */
void ref_bake_filter_atlas(ref_bake *b, float *values, const unsigned char *buried);
void ref_bake_filter_vertices(const ref_scene *s, const ref_bake *b, const bake_layout *layout,
                              float *values, const unsigned char *changed);

#endif
