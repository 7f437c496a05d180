#include "gl_funcs.h"
#include "probe.h"
#include "shadow.h"
#include "render_internal.h"
#include "scene_internal.h"

#include <math.h>
#include <stdlib.h>

rd_scene *rd_scene_create(rd_context *ctx)
{
    if (!ctx) {
        rd_set_error("rd_scene_create: no context");
        return NULL;
    }
    rd_scene *s = calloc(1, sizeof *s);
    if (!s) {
        rd_set_error("rd_scene_create: out of memory");
        return NULL;
    }
    s->ctx = ctx;
    return s;
}

void rd_scene_destroy(rd_scene *s)
{
    if (!s)
        return;
    rd_probes_destroy(s);
    rd_shadow_maps_destroy(s);
    if (s->ambient_probe.capture)
        glDeleteTextures(1, &s->ambient_probe.capture);
    if (s->lightmap)
        glDeleteTextures(1, &s->lightmap);
    free(s->objects);
    free(s->object_stamps);
    free(s->object_probe);
    free(s->object_spheres);
    free(s->object_emitter);
    free(s);
}

static int is_zero_matrix(const float m[16])
{
    for (int i = 0; i < 16; i++)
        if (m[i] != 0.0f)
            return 0;
    return 1;
}

rd_result rd_scene_add_object(rd_scene *s, const rd_object_desc *desc)
{
    if (!s || !desc)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_add_object: scene and desc are required");
    if (!rd_mesh_lookup(s->ctx, desc->mesh))
        return rd_fail(RD_ERR_STALE_HANDLE, "rd_scene_add_object: mesh %u is not a live mesh",
                       desc->mesh.id);
    if (desc->probe_mesh.id && !rd_mesh_lookup(s->ctx, desc->probe_mesh))
        return rd_fail(RD_ERR_STALE_HANDLE, "rd_scene_add_object: probe mesh %u is not live",
                       desc->probe_mesh.id);
    if (desc->material.diffuse_texture.id &&
        !rd_texture_lookup(s->ctx, desc->material.diffuse_texture))
        return rd_fail(RD_ERR_STALE_HANDLE, "rd_scene_add_object: texture %u is not live",
                       desc->material.diffuse_texture.id);
    for (int i = 0; i < 16; i++)
        if (!isfinite(desc->transform[i]))
            return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_add_object: transform is not finite");
    if (s->object_count == s->object_capacity) {
        int cap = s->object_capacity ? s->object_capacity * 2 : 32;
        rd_object_desc *p = realloc(s->objects, (size_t)cap * sizeof *p);
        if (!p)
            return rd_fail(RD_ERR_OUT_OF_MEMORY, "rd_scene_add_object: out of memory");
        s->objects = p;
        long long *st = realloc(s->object_stamps, (size_t)cap * sizeof *st);
        if (!st)
            return rd_fail(RD_ERR_OUT_OF_MEMORY, "rd_scene_add_object: out of memory");
        s->object_stamps = st;
        s->object_capacity = cap;
    }
    s->object_stamps[s->object_count] = ++s->change_counter;
    s->probes_dirty = 1;
    rd_object_desc *o = &s->objects[s->object_count++];
    *o = *desc;
    if (is_zero_matrix(o->transform))
        for (int i = 0; i < 4; i++)
            o->transform[i * 5] = 1.0f;
    return RD_OK;
}

int rd_scene_has_area_lights(const rd_scene *s)
{
    for (int i = 0; i < s->light_count; i++) {
        const rd_light *l = &s->lights[i];
        int portal =
            l->half_width[0] != 0.0f || l->half_width[1] != 0.0f || l->half_width[2] != 0.0f;
        if (l->type == RD_LIGHT_RECT || (l->type == RD_LIGHT_DIRECTIONAL && portal))
            return 1;
    }
    return 0;
}

rd_result rd_scene_add_light(rd_scene *s, const rd_light *light)
{
    if (!s || !light)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_add_light: scene and light are required");
    if (s->light_count >= RD_MAX_LIGHTS)
        return rd_fail(RD_ERR_TOO_LARGE, "a scene holds at most %d lights", RD_MAX_LIGHTS);
    rd_light l = *light;
    if (l.type != RD_LIGHT_POINT) {
        float len = sqrtf(l.direction[0] * l.direction[0] + l.direction[1] * l.direction[1] +
                          l.direction[2] * l.direction[2]);
        if (!(len > 0.0f) || !isfinite(len))
            return rd_fail(RD_ERR_INVALID_ARGUMENT,
                           "a spot or directional light needs a direction");
        for (int k = 0; k < 3; k++)
            l.direction[k] /= len;
    }
    if (l.type == RD_LIGHT_RECT) {
        float uu = 0.0f, vv = 0.0f;
        for (int k = 0; k < 3; k++) {
            uu += l.half_width[k] * l.half_width[k];
            vv += l.half_height[k] * l.half_height[k];
        }
        if (!(uu > 0.0f) || !(vv > 0.0f) || !isfinite(uu) || !isfinite(vv))
            return rd_fail(RD_ERR_INVALID_ARGUMENT,
                           "a rectangle light needs a width and a height (non-zero half edges)");
    }
    s->lights[s->light_count++] = l;
    s->change_counter++; /* probes and shadow maps that saw the scene without it are stale */
    return RD_OK;
}

void rd_scene_set_ambient(rd_scene *s, const float intensity[3])
{
    if (s && intensity && memcmp(s->ambient, intensity, sizeof s->ambient) != 0) {
        memcpy(s->ambient, intensity, sizeof s->ambient);
        s->change_counter++; /* the probes captured the old ambient term */
    }
}

int rd_scene_object_count(const rd_scene *s)
{
    return s ? s->object_count : 0;
}

rd_result rd_scene_object_desc(const rd_scene *s, int index, rd_object_desc *out)
{
    if (!s || !out || index < 0 || index >= s->object_count)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_object_desc: no object %d", index);
    *out = s->objects[index];
    return RD_OK;
}

rd_result rd_scene_set_transform(rd_scene *s, int index, const float transform[16])
{
    if (!s || !transform || index < 0 || index >= s->object_count)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_set_transform: no object %d", index);
    for (int i = 0; i < 16; i++)
        if (!isfinite(transform[i]))
            return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_set_transform: not finite");
    if (memcmp(s->objects[index].transform, transform, 16 * sizeof(float)) != 0) {
        memcpy(s->objects[index].transform, transform, 16 * sizeof(float));
        s->object_stamps[index] = ++s->change_counter;
    }
    return RD_OK;
}

rd_result rd_scene_set_object_mesh(rd_scene *s, int index, rd_mesh mesh)
{
    if (!s || index < 0 || index >= s->object_count)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_set_object_mesh: no object %d", index);
    if (!rd_mesh_lookup(s->ctx, mesh))
        return rd_fail(RD_ERR_STALE_HANDLE, "rd_scene_set_object_mesh: mesh %u is not live",
                       mesh.id);
    if (s->objects[index].mesh.id != mesh.id) {
        s->objects[index].mesh = mesh;
        s->object_stamps[index] = ++s->change_counter;
    }
    return RD_OK;
}

void rd_scene_set_reflection_defaults(rd_scene *s, const rd_reflection_defaults *d)
{
    if (s && d) {
        s->reflection = *d;
        s->change_counter++; /* a new proxy or resolution: capture again */
        s->probes_dirty = 1;
    }
}

void rd_scene_set_capture_budget(rd_scene *s, int max_faces_per_frame, int split_captures)
{
    if (s) {
        s->reflection.max_faces_per_frame = max_faces_per_frame > 0 ? max_faces_per_frame : 0;
        s->reflection.split_captures = split_captures;
    }
}

void rd_scene_set_capture_time(rd_scene *s, float ms)
{
    if (s)
        s->capture_ms = ms > 0.0f ? ms : 0.0f;
}

rd_reflection_defaults rd_scene_reflection_defaults(const rd_scene *s)
{
    rd_reflection_defaults none = {0};
    return s ? s->reflection : none;
}

int rd_scene_probe_count(const rd_scene *s)
{
    if (!s)
        return 0;
    if (s->probes_dirty)
        rd_probes_sync((rd_scene *)s);
    return s->probe_count;
}

rd_result rd_scene_set_lightmap(rd_scene *s, int width, int height, const float *rgba)
{
    if (!s)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_set_lightmap: no scene");
    if (s->lightmap) {
        glDeleteTextures(1, &s->lightmap);
        s->lightmap = 0;
    }
    if (!rgba)
        return RD_OK;
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
        return rd_fail(RD_ERR_INVALID_ARGUMENT, "rd_scene_set_lightmap: %d x %d texels", width,
                       height);
    /* Bilinear, clamped and without mips: a mip level would mix neighbouring charts. */
    glGenTextures(1, &s->lightmap);
    glBindTexture(GL_TEXTURE_2D, s->lightmap);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, width, height, 0, GL_RGBA, GL_FLOAT, rgba);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    if (rd_gl_drain_errors() != GL_NO_ERROR) {
        glDeleteTextures(1, &s->lightmap);
        s->lightmap = 0;
        return rd_fail(RD_ERR_OUT_OF_MEMORY, "rd_scene_set_lightmap: OpenGL could not store it");
    }
    return RD_OK;
}
