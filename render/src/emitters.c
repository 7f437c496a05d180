/* Lamps in sharp reflections (docs/rendering.md, "Lamps in sharp reflections").
 *
 * A probe shows a lamp where its centre sees it, and a proxy puts it on the proxy: a pendant
 * hanging in the room lands on the ceiling behind it, a strip light beside a mirror on the
 * wall. Bright as they are (radiance several times a wall's), those misplaced lamps carry most
 * of a mirror's error against the tracer (docs/accuracy.md, "Exact lamps"). A lamp
 * whose mesh is one of primitives.h's unit shapes is intersected exactly instead: the probes of
 * mirrors and glass (every reader sharp, g = 1) are captured without it, and their lookups
 * (lit.frag's emitter_reflection) intersect the reflected ray with its shape and shade the hit as
 * the capture would have (RENDERING.md section 1, eq. 7). Blurred lookups keep the lamp in their
 * probes, where the lobe spreads it anyway. */
#include "emitters.h"
#include "gl_funcs.h"
#include "probe.h"

#include <cglm/cglm.h>
#include <stdlib.h>
#include <string.h>

static int analytic_shape(rd_shape s)
{
    return s == RD_SHAPE_SPHERE || s == RD_SHAPE_BOX || s == RD_SHAPE_PLANE ||
           s == RD_SHAPE_CYLINDER;
}

/* A lamp the lookups can intersect: it emits, has a known shape, no texture (the lookup
 * shades it untextured) and no reflection of its own (a capture draws reflective objects
 * plain; a lamp's shading is eq. 7 alone). */
static int is_emitter(const rd_object_desc *o)
{
    const rd_material *m = &o->material;
    float e = fmaxf(m->emissive[0], fmaxf(m->emissive[1], m->emissive[2]));
    return e > 0.0f && analytic_shape(o->shape) && !o->material.diffuse_texture.id &&
           !(m->reflectivity > 0.0f) && !(m->transparency > 0.0f) && !o->background;
}

rd_result rd_emitters_update(rd_scene *s)
{
    unsigned char *flags =
        realloc(s->object_emitter, (size_t)(s->object_count ? s->object_count : 1));
    if (!flags)
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "out of memory");
    s->object_emitter = flags;
    memset(flags, 0, (size_t)s->object_count);
    s->emitter_count = 0;
    if (s->reflection.exact_lamps == RD_SWITCH_OFF)
        return RD_OK;
    for (int i = 0; i < s->object_count && s->emitter_count < RD_MAX_EMITTERS; i++) {
        const rd_object_desc *o = &s->objects[i];
        if (!is_emitter(o))
            continue;
        mat4 model, inv;
        memcpy(model, o->transform, sizeof model);
        /* A flat shape's unit z is 0 in its scale: give the inverse a z to divide by. */
        if (o->shape == RD_SHAPE_PLANE && glm_mat4_det(model) == 0.0f)
            glm_vec4_copy((vec4){0.0f, 0.0f, 1e-6f, 0.0f}, model[2]);
        if (!(fabsf(glm_mat4_det(model)) > 0.0f))
            continue; /* a lamp of zero size reflects nothing */
        glm_mat4_inv(model, inv);
        rd_emitter *e = &s->emitters[s->emitter_count++];
        e->object = i;
        e->shape = o->shape;
        e->two_sided = o->double_sided;
        memcpy(e->to_local, inv, sizeof e->to_local);
        /* The unit shapes lie in the unit box (a plane in its z = 0 face): the sphere through
         * its corners, a little larger for rounding. */
        float half = 0.0f;
        for (int a = 0; a < (o->shape == RD_SHAPE_PLANE ? 2 : 3); a++)
            half += 0.25f * glm_vec3_norm2(model[a]);
        memcpy(e->sphere, model[3], 3 * sizeof(float));
        e->sphere[3] = sqrtf(half) * 1.001f + 1e-6f;
        flags[i] = 1;
    }
    return RD_OK;
}

int rd_probe_wants_leave_emitters(const rd_scene *s, const rd_probe *p)
{
    if (!s->emitter_count || p->planar || !(p->gloss_min >= 1.0f))
        return 0;
    const rd_object_desc *owner = &s->objects[p->owner];
    return owner->probe.update != RD_PROBE_STATIC;
}

void rd_set_emitter_uniforms(const rd_program *p, const rd_scene *s, int active)
{
    int n = active ? s->emitter_count : 0;
    glUniform1i(p->u_emitter_count, n);
    if (!n)
        return;
    int shape[RD_MAX_EMITTERS];
    float to_local[RD_MAX_EMITTERS][16], amb[RD_MAX_EMITTERS][3], dif[RD_MAX_EMITTERS][3],
        spec[RD_MAX_EMITTERS][3], emis[RD_MAX_EMITTERS][3], shin[RD_MAX_EMITTERS],
        sphere[RD_MAX_EMITTERS][4];
    for (int i = 0; i < n; i++) {
        const rd_emitter *e = &s->emitters[i];
        const rd_material *m = &s->objects[e->object].material;
        /* The sign says whether a plane is lit from both sides (lit.frag). */
        shape[i] = e->two_sided ? -(int)e->shape : (int)e->shape;
        memcpy(to_local[i], e->to_local, sizeof to_local[i]);
        memcpy(amb[i], m->ambient, sizeof amb[i]);
        memcpy(dif[i], m->diffuse, sizeof dif[i]);
        memcpy(spec[i], m->specular, sizeof spec[i]);
        memcpy(emis[i], m->emissive, sizeof emis[i]);
        shin[i] = m->shininess;
        memcpy(sphere[i], e->sphere, sizeof sphere[i]);
    }
    glUniform1iv(p->u_emitter_shape, n, shape);
    glUniformMatrix4fv(p->u_emitter_to_local, n, GL_FALSE, &to_local[0][0]);
    glUniform3fv(p->u_emitter_ambient, n, &amb[0][0]);
    glUniform3fv(p->u_emitter_diffuse, n, &dif[0][0]);
    glUniform3fv(p->u_emitter_specular, n, &spec[0][0]);
    glUniform3fv(p->u_emitter_emissive, n, &emis[0][0]);
    glUniform1fv(p->u_emitter_shininess, n, shin);
    glUniform4fv(p->u_emitter_sphere, n, &sphere[0][0]);
}
