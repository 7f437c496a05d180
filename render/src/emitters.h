/* Lamps of known shape, reflected exactly by sharp lookups (emitters.c). */
#ifndef RENDER_EMITTERS_H
#define RENDER_EMITTERS_H

#include "render_internal.h"
#include "scene_internal.h"

/* This frame's emitters (s->emitters, s->object_emitter), after the objects' transforms. */
rd_result rd_emitters_update(rd_scene *s);
/* Whether probe p should be captured without them: every reader sharp, a captured cube. */
int rd_probe_wants_leave_emitters(const rd_scene *s, const rd_probe *p);
/* The lookup's emitter uniforms; active 0 sets none (the probe keeps its lamps). */
void rd_set_emitter_uniforms(const rd_program *p, const rd_scene *s, int active);

#endif
