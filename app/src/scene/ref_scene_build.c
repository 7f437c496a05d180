/* Project -> the tracer's scene. Mirrors scene_build.c, scene_room.c and scene_objects.c line for
 * line where they decide geometry, materials and lights; what differs is only where the data goes
 * (CPU arrays instead of GL buffers) and that textures stay float, decoded from sRGB here the way
 * the GPU's GL_SRGB8_ALPHA8 sampler decodes them. */
#include "app/scene/ref_scene_build.h"

#include "app/measure/image_compare.h"
#include "app/design/room_mesh.h"
#include "catalog/model.h"
#include "model_materials.h"
#include "render/image_io.h"
#include "render/primitives.h"
#include "scene_build_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct texture_cache {
    char (*paths)[1024];
    int *ids;
    int count, capacity;
} texture_cache;

static app_result ref_error(app_result r, const char *where, char *err, size_t err_size)
{
    snprintf(err, err_size, "%s: %s", where, ref_last_error());
    return r;
}

/* Loads a texture once per path. sRGB files are quantised to 8 bits as rd_texture_create does
 * and decoded with the exact curve; linear files stay as read. */
static app_result load_texture(ref_scene *s, texture_cache *c, const char *path, int *out,
                               char *err, size_t err_size)
{
    for (int i = 0; i < c->count; i++)
        if (!strcmp(c->paths[i], path)) {
            *out = c->ids[i];
            return APP_OK;
        }
    if (c->count == c->capacity) {
        int cap = c->capacity ? 2 * c->capacity : 8;
        char(*paths)[1024] = realloc(c->paths, (size_t)cap * sizeof *paths);
        if (!paths)
            return APP_ERR_OUT_OF_MEMORY;
        c->paths = paths;
        int *ids = realloc(c->ids, (size_t)cap * sizeof *ids);
        if (!ids)
            return APP_ERR_OUT_OF_MEMORY;
        c->ids = ids;
        c->capacity = cap;
    }
    rd_image img = {0};
    int nonfinite = 0;
    char ierr[512];
    if (rd_image_read(path, &img, &nonfinite, ierr, sizeof ierr) != RD_IMAGE_OK) {
        snprintf(err, err_size, "%s", ierr);
        return APP_ERR_IO;
    }
    if (nonfinite)
        fprintf(stderr, "tessera: warning: %s: %d NaN or infinite texel values were set to 0\n",
                path, nonfinite);
    size_t n = (size_t)img.width * (size_t)img.height * 4;
    float *rgba = malloc(n * sizeof *rgba);
    if (!rgba) {
        rd_image_free(&img);
        return APP_ERR_OUT_OF_MEMORY;
    }
    rd_image_expand_rgba(&img, rgba);
    if (img.srgb_encoded)
        for (size_t i = 0; i < n; i++) {
            float x = isfinite(rgba[i]) ? fminf(fmaxf(rgba[i], 0.0f), 1.0f) : 0.0f;
            float byte = floorf(x * 255.0f + 0.5f);
            rgba[i] = i % 4 == 3 ? byte / 255.0f : app_srgb_to_linear(byte / 255.0f);
        }
    int id = ref_scene_add_texture(s, &(ref_texture_desc){img.width, img.height, rgba});
    free(rgba);
    rd_image_free(&img);
    if (!id) {
        snprintf(err, err_size, "%s: %s", path, ref_last_error());
        return APP_ERR_OUT_OF_MEMORY;
    }
    snprintf(c->paths[c->count], sizeof c->paths[0], "%s", path);
    c->ids[c->count++] = id;
    *out = id;
    return APP_OK;
}

/* app_scene_material_of's mapping; *texture gets the texture id (0 = none). */
static app_result material_from(const app_project *p, ref_scene *s, texture_cache *c,
                                const app_material *am, rd_material *out, int *texture, char *err,
                                size_t err_size)
{
    rd_material m = {.shininess = am->shininess,
                     .reflectivity = am->reflectivity,
                     .glossiness = am->glossiness,
                     .blend = (rd_reflection_blend)am->blend,
                     .correction = (rd_correction)am->correction,
                     .transparency = am->transparency,
                     .ior = am->ior,
                     .dispersion = am->dispersion};
    memcpy(m.ambient, am->ambient, sizeof m.ambient);
    memcpy(m.diffuse, am->diffuse, sizeof m.diffuse);
    memcpy(m.specular, am->specular, sizeof m.specular);
    memcpy(m.emissive, am->emissive, sizeof m.emissive);
    *texture = 0;
    if (am->texture[0]) {
        app_result r = load_texture(s, c, am->texture, texture, err, err_size);
        if (r != APP_OK) {
            char inner[768];
            snprintf(inner, sizeof inner, "%s", err);
            snprintf(err, err_size, "%s: material \"%s\": %s", p->path, am->name, inner);
            return r;
        }
    }
    *out = m;
    return APP_OK;
}

static app_result material_of(const app_project *p, ref_scene *s, texture_cache *c, int mi,
                              rd_material *out, int *texture, char *err, size_t err_size)
{
    return material_from(p, s, c, &p->materials[mi], out, texture, err, err_size);
}

/* app_scene_add_room's meshes (app_room_geometry_build: the same geometry for both
 * renderers), closed (back faces culled). */
static app_result add_room(const app_project *p, const app_room_geometry *room, ref_scene *s,
                           texture_cache *c, char *err, size_t err_size)
{
    for (int i = 0; i < room->mesh_count; i++) {
        const app_room_mesh *rm = &room->meshes[i];
        if (rm->index_count == 0)
            continue;
        rd_material m;
        int texture;
        app_result r =
            rm->material >= 0
                ? material_of(p, s, c, rm->material, &m, &texture, err, err_size)
                : material_from(p, s, c, &rm->inline_material, &m, &texture, err, err_size);
        if (r != APP_OK)
            return r;
        ref_mesh_desc d = {.positions = rm->positions,
                           .normals = rm->normals,
                           .uvs = rm->uvs,
                           .indices = rm->indices,
                           .vertex_count = rm->vertex_count,
                           .index_count = rm->index_count,
                           .material = m,
                           .texture = texture,
                           .background = 1}; /* as scene_room.c: casts no shadow */
        if (ref_scene_add_mesh(s, &d) != REF_OK) {
            char where[1200];
            snprintf(where, sizeof where, "%s: room surface %s", p->path, rm->surface);
            return ref_error(APP_ERR_OUT_OF_MEMORY, where, err, err_size);
        }
    }
    return APP_OK;
}

static rd_result unit_mesh_data(app_shape shape, float torus_ratio, rd_mesh_data *d)
{
    const int seg = 64; /* scene_objects.c's full-detail meshes (the coarse ones are for probes) */
    switch (shape) {
    case APP_SHAPE_BOX:
        return rd_mesh_data_box(d);
    case APP_SHAPE_SPHERE:
        return rd_mesh_data_sphere(seg, seg / 2, d);
    case APP_SHAPE_CYLINDER:
        return rd_mesh_data_cylinder(seg, d);
    case APP_SHAPE_PLANE:
        return rd_mesh_data_plane(d);
    default:
        return rd_mesh_data_torus(torus_ratio, seg, 24, d);
    }
}

/* scene_objects.c's add_primitive. */
static app_result add_primitive(const app_project *p, ref_scene *s, int index, const rd_material *m,
                                int texture, char *err, size_t err_size)
{
    const app_object *o = &p->objects[index];
    double size_m[3] = {o->size_mm[0] * 1e-3, o->size_mm[1] * 1e-3, o->size_mm[2] * 1e-3};
    float ratio = 0.0f;
    if (o->shape == APP_SHAPE_PLANE)
        size_m[2] = 1.0;
    if (o->shape == APP_SHAPE_TORUS) {
        ratio = (float)fmin(o->size_mm[2] / o->size_mm[0], 0.5);
        size_m[2] = size_m[0];
    }
    rd_mesh_data data;
    if (unit_mesh_data(o->shape, ratio, &data) != RD_OK) {
        snprintf(err, err_size, "%s: $.objects[%d] (\"%s\"): cannot make its mesh: %s", p->path,
                 index, o->name, rd_last_error());
        return APP_ERR_SCHEMA;
    }
    ref_mesh_desc d = {.positions = data.positions,
                       .normals = data.normals,
                       .uvs = data.uvs,
                       .indices = data.indices,
                       .vertex_count = data.vertex_count,
                       .index_count = data.index_count,
                       .material = *m,
                       .texture = texture,
                       .double_sided = o->shape == APP_SHAPE_PLANE};
    const app_material *am = &p->materials[o->material];
    if (am->texture[0]) {
        double u_mm = o->size_mm[0] * o->scale[0];
        double v_mm =
            o->shape == APP_SHAPE_PLANE ? o->size_mm[1] * o->scale[1] : o->size_mm[2] * o->scale[2];
        if (o->shape == APP_SHAPE_SPHERE || o->shape == APP_SHAPE_CYLINDER ||
            o->shape == APP_SHAPE_TORUS)
            u_mm *= 3.14159265358979323846;
        d.material.uv_scale[0] = (float)(u_mm / am->texture_size_mm[0]);
        d.material.uv_scale[1] = (float)(v_mm / am->texture_size_mm[1]);
    }
    app_object_transform(o, size_m, d.transform);
    ref_result r = ref_scene_add_mesh(s, &d);
    rd_mesh_data_free(&data);
    if (r != REF_OK) {
        snprintf(err, err_size, "%s: $.objects[%d] (\"%s\"): %s", p->path, index, o->name,
                 ref_last_error());
        return r == REF_ERR_OUT_OF_MEMORY ? APP_ERR_OUT_OF_MEMORY : APP_ERR_SCHEMA;
    }
    return APP_OK;
}

/* scene_objects.c's add_model: every part double-sided (a model may be open). */
static app_result add_model(const app_project *p, ref_scene *s, int index, const rd_material *m,
                            int texture, char *err, size_t err_size)
{
    const app_object *o = &p->objects[index];
    cat_model model = {0};
    char cerr[768];
    if (cat_model_load(o->model, &model, cerr, sizeof cerr) != CAT_OK) {
        snprintf(err, err_size, "%s: $.objects[%d].model: %s", p->path, index, cerr);
        return APP_ERR_IO;
    }
    app_model_materials parts;
    if (!app_model_materials_read(o->model, &model, &parts)) {
        cat_model_free(&model);
        snprintf(err, err_size, "%s: $.objects[%d].model: out of memory", p->path, index);
        return APP_ERR_OUT_OF_MEMORY;
    }
    const double mm_to_m[3] = {1e-3, 1e-3, 1e-3};
    float transform[16];
    app_object_transform(o, mm_to_m, transform);
    app_result r = APP_OK;
    for (int i = 0; r == APP_OK && i < model.mesh_count; i++) {
        const cat_mesh *cm = &model.meshes[i];
        rd_material own;
        int fixed = app_model_part_material(&parts, cm, &own); /* as scene_objects.c */
        ref_mesh_desc d = {.positions = cm->positions,
                           .normals = cm->normals,
                           .uvs = cm->uvs,
                           .indices = cm->indices,
                           .vertex_count = cm->vertex_count,
                           .index_count = cm->index_count,
                           .material = fixed ? own : *m,
                           .texture = fixed ? 0 : texture,
                           .double_sided = 1};
        memcpy(d.transform, transform, sizeof transform);
        ref_result rr = ref_scene_add_mesh(s, &d);
        if (rr != REF_OK) {
            snprintf(err, err_size, "%s: $.objects[%d].model: %s: part %d: %s", p->path, index,
                     o->model, i, ref_last_error());
            r = rr == REF_ERR_OUT_OF_MEMORY ? APP_ERR_OUT_OF_MEMORY : APP_ERR_IO;
        }
    }
    app_model_materials_free(&parts);
    cat_model_free(&model);
    return r;
}

/* scene_build.c's add_light: millimetres to metres, intensity into the colours. */
static void light_of(const app_light *l, rd_light *out)
{
    rd_light r = {.type = l->type == APP_LIGHT_SPOT          ? RD_LIGHT_SPOT
                          : l->type == APP_LIGHT_DIRECTIONAL ? RD_LIGHT_DIRECTIONAL
                                                             : RD_LIGHT_POINT};
    for (int k = 0; k < 3; k++) {
        r.position[k] = (float)(l->position_mm[k] * 1e-3);
        r.direction[k] = (float)l->direction[k];
        r.diffuse[k] = l->color[k] * l->intensity;
        r.specular[k] = l->specular[k] * l->intensity;
        r.attenuation[k] = l->attenuation[k];
    }
    const double deg = 3.14159265358979323846 / 180.0;
    r.spot_inner_cos = (float)cos(l->inner_deg * deg);
    r.spot_outer_cos = (float)cos(l->outer_deg * deg);
    *out = r;
}

static app_result ref_scene_build(app_scene_products *q, ref_scene **out, char *err,
                                  size_t err_size);

/* Products resolved through the catalog as for the GPU scene (scene_products.c). */
app_result app_ref_scene_build(const app_project *p, ref_scene **out, char *err, size_t err_size)
{
    app_scene_products q;
    *out = NULL;
    app_result r = app_scene_resolve_products(p, &q, err, err_size);
    if (r != APP_OK)
        return r;
    r = ref_scene_build(&q, out, err, err_size);
    app_scene_resolved_free(&q);
    return r;
}

static app_result ref_scene_build(app_scene_products *q, ref_scene **out, char *err,
                                  size_t err_size)
{
    const app_project *p = &q->q;
    *out = NULL;
    if (err && err_size)
        err[0] = 0;
    ref_scene *s = ref_scene_create();
    if (!s)
        return ref_error(APP_ERR_OUT_OF_MEMORY, p->path, err, err_size);
    ref_scene_set_ambient(s, p->render.ambient);
    texture_cache cache = {0};
    app_room_geometry room;
    app_result r = app_room_geometry_build(p, &room, err, err_size);
    if (r != APP_OK) {
        ref_scene_destroy(s);
        return r;
    }
    app_room_add_tiles(p, q->covers, q->cover_count, &q->catalog, &room); /* as scene_build.c */
    r = add_room(p, &room, s, &cache, err, err_size);
    if (p->render.ambient_model == 1) {
        /* SH9 ambient from a capture at the box proxy's centre, the room's interior box as
         * scene_build.c makes it (render/src/ambient_sh.c places its probe there). */
        float centre[3];
        for (int k = 0; k < 3; k++)
            centre[k] = (float)(0.5 * (room.bounds_min[k] + room.bounds_max[k]));
        ref_scene_set_ambient_sh9(s, centre);
    }
    for (int i = 0; r == APP_OK && i < p->object_count; i++) {
        if (APP_OBJECT_UNRESOLVED(&p->objects[i]))
            continue; /* as scene_objects.c */
        rd_material m;
        int texture;
        r = material_of(p, s, &cache, p->objects[i].material, &m, &texture, err, err_size);
        if (r == APP_OK)
            r = p->objects[i].shape == APP_SHAPE_MODEL
                    ? add_model(p, s, i, &m, texture, err, err_size)
                    : add_primitive(p, s, i, &m, texture, err, err_size);
    }
    for (int i = 0; r == APP_OK && i < p->light_count; i++) {
        rd_light l;
        light_of(&p->lights[i], &l);
        if (ref_scene_add_light(s, &l) != REF_OK) {
            snprintf(err, err_size, "%s: $.lights[%d]: %s", p->path, i, ref_last_error());
            r = APP_ERR_SCHEMA;
        }
    }
    /* scene_build.c's daylight through the windows, after the project's lights. */
    for (int i = 0; r == APP_OK && i < room.light_count; i++) {
        rd_light l;
        light_of(&room.lights[i], &l);
        if (ref_scene_add_light(s, &l) != REF_OK) {
            snprintf(err, err_size, "%s: window light \"%s\": %s", p->path, room.lights[i].name,
                     ref_last_error());
            r = APP_ERR_SCHEMA;
        }
    }
    app_room_geometry_free(&room);
    free(cache.paths);
    free(cache.ids);
    if (r == APP_ERR_OUT_OF_MEMORY && err && err_size && !err[0])
        snprintf(err, err_size, "%s: out of memory", p->path);
    if (r != APP_OK) {
        ref_scene_destroy(s);
        return r;
    }
    *out = s;
    return APP_OK;
}
