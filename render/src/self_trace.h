/* A fixture's reflections of its own parts and its nearest neighbours, traced against their
 * triangles (self_trace.c). */
#ifndef RENDER_SELF_TRACE_H
#define RENDER_SELF_TRACE_H

#include "render_internal.h"
#include "scene_internal.h"

/* Builds (or rebuilds, after a part moved) the triangle hierarchy of every probe that wants
 * one, and frees those of probes that no longer do. */
rd_result rd_self_trace_update(rd_context *ctx, rd_scene *s);
/* Whether object `index`'s lookups trace its probe's parts (the lit variant's bit). */
int rd_self_traced(const rd_scene *s, const rd_probe *p);
/* The lookup's uniforms for object `index`, whose probe p is self-traced. */
void rd_set_self_trace_uniforms(rd_context *ctx, const rd_program *prog, const rd_scene *s,
                                const rd_probe *p, int index, int sample_grid);
/* Whether object `index` is one of the hierarchy's parts (left out of its probe's capture). */
int rd_self_bvh_holds(const rd_self_bvh *b, int index);
/* Frees the hierarchy's GL buffers. */
void rd_self_trace_free(rd_self_bvh *b);

#endif
