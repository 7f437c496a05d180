/* Project -> render list (render_list.h): the room's surfaces (app_room_geometry_build, with
 * the tiles), then the objects (render_list_objects.c), then the lights. */
#include "render_list_internal.h"

#include "catalog/model.h"

#include <math.h>
#include <stdlib.h>

int app_list_grow(void **array, int *capacity, int need, size_t size)
{
    if (need <= *capacity)
        return 1;
    int cap = *capacity ? *capacity : 8;
    while (cap < need)
        cap *= 2;
    void *a = realloc(*array, (size_t)cap * size);
    if (!a)
        return 0;
    *array = a;
    *capacity = cap;
    return 1;
}

/* The index of path in files, added (with the material naming it) when new; -1 when out of
 * memory. */
static int file_index(app_render_file **files, int *count, int *capacity, const char *path,
                      const char *material)
{
    for (int i = 0; i < *count; i++)
        if (!strcmp((*files)[i].path, path))
            return i;
    if (!app_list_grow((void **)files, capacity, *count + 1, sizeof **files))
        return -1;
    app_render_file *f = &(*files)[*count];
    snprintf(f->path, sizeof f->path, "%s", path);
    snprintf(f->material, sizeof f->material, "%s", material);
    return (*count)++;
}

app_result app_list_material(app_list_builder *b, const app_material *am, rd_material *out,
                             int *texture)
{
    rd_material m = {.shininess = am->shininess,
                     .reflectivity = am->reflectivity,
                     .glossiness = am->glossiness,
                     .blend = (rd_reflection_blend)am->blend,
                     .correction = (rd_correction)am->correction,
                     .transparency = am->transparency,
                     .ior = am->ior,
                     .dispersion = am->dispersion,
                     .pattern = (rd_pattern)am->pattern,
                     .grain_angle_deg = am->grain_deg,
                     .per_vertex_reflection = am->probe_per_vertex,
                     .sphere_map = am->probe_sphere_map};
    memcpy(m.ambient, am->ambient, sizeof m.ambient);
    memcpy(m.diffuse, am->diffuse, sizeof m.diffuse);
    memcpy(m.specular, am->specular, sizeof m.specular);
    memcpy(m.emissive, am->emissive, sizeof m.emissive);
    memcpy(m.joint_width, am->joint_width, sizeof m.joint_width);
    memcpy(m.joint_color, am->joint_color, sizeof m.joint_color);
    *texture = -1;
    if (am->texture[0]) {
        app_render_list *l = b->list;
        *texture = file_index(&l->textures, &l->texture_count, &b->texture_capacity, am->texture,
                              am->name);
        if (*texture < 0)
            return APP_ERR_OUT_OF_MEMORY;
    }
    *out = m;
    return APP_OK;
}

int app_list_probe_map(app_list_builder *b, const app_material *am)
{
    app_render_list *l = b->list;
    return file_index(&l->probe_maps, &l->probe_map_count, &b->probe_map_capacity, am->probe_map,
                      am->name);
}

int app_list_add_mesh(app_list_builder *b, const float *positions, const float *normals,
                      const float *uvs, const uint32_t *indices, int vertex_count, int index_count)
{
    app_render_list *l = b->list;
    if (!app_list_grow((void **)&l->meshes, &b->mesh_capacity, l->mesh_count + 1,
                       sizeof *l->meshes))
        return -1;
    l->meshes[l->mesh_count] =
        (app_render_mesh){positions, normals, uvs, indices, vertex_count, index_count};
    return l->mesh_count++;
}

app_render_item *app_list_add_item(app_list_builder *b, int mesh, const char *label)
{
    app_render_list *l = b->list;
    if (!app_list_grow((void **)&l->items, &b->item_capacity, l->item_count + 1, sizeof *l->items))
        return NULL;
    app_render_item *it = &l->items[l->item_count++];
    memset(it, 0, sizeof *it);
    it->mesh = mesh;
    it->probe_mesh = it->texture = it->probe_map = it->object = -1;
    snprintf(it->label, sizeof it->label, "%s", label);
    return it;
}

/* The room's surfaces: closed meshes at their place (identity transform), drawn last. */
static app_result add_room(app_list_builder *b, const app_project *p)
{
    const app_room_geometry *room = &b->list->store->room;
    for (int i = 0; i < room->mesh_count; i++) {
        const app_room_mesh *rm = &room->meshes[i];
        if (rm->index_count == 0)
            continue;
        rd_material m;
        int texture;
        const app_material *am =
            rm->material >= 0 ? &p->materials[rm->material] : &rm->inline_material;
        char label[sizeof rm->surface + 16];
        snprintf(label, sizeof label, "room surface %s", rm->surface);
        int mesh = app_list_add_mesh(b, rm->positions, rm->normals, rm->uvs, rm->indices,
                                     rm->vertex_count, rm->index_count);
        app_render_item *it = mesh >= 0 && app_list_material(b, am, &m, &texture) == APP_OK
                                  ? app_list_add_item(b, mesh, label)
                                  : NULL;
        if (!it)
            return APP_ERR_OUT_OF_MEMORY;
        it->material = m;
        it->texture = texture;
        it->background = 1;
        it->light_stand_in = rm->light_stand_in;
    }
    return APP_OK;
}

/* Millimetres to metres, intensity into the colours, cone angles to cosines. */
static rd_light light_of(const app_light *l)
{
    rd_light r = {.type = l->type == APP_LIGHT_SPOT          ? RD_LIGHT_SPOT
                          : l->type == APP_LIGHT_DIRECTIONAL ? RD_LIGHT_DIRECTIONAL
                          : l->type == APP_LIGHT_RECT        ? RD_LIGHT_RECT
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
    /* A rectangle (or a directional light's portal): half edges along its two axes. */
    if ((l->type == APP_LIGHT_RECT || l->type == APP_LIGHT_DIRECTIONAL) && l->width_mm > 0 &&
        l->height_mm > 0) {
        const double *a = l->axis, *b = l->height_axis;
        for (int k = 0; k < 3; k++) {
            r.half_width[k] = (float)(a[k] * l->width_mm * 0.5e-3);
            r.half_height[k] = (float)(b[k] * l->height_mm * 0.5e-3);
        }
    }
    return r;
}

/* The project's lights, then daylight through the windows (app/design/room_mesh.h). */
static app_result add_lights(app_render_list *l, const app_project *p)
{
    const app_room_geometry *room = &l->store->room;
    l->lights = calloc((size_t)(p->light_count + room->light_count + 1), sizeof *l->lights);
    if (!l->lights)
        return APP_ERR_OUT_OF_MEMORY;
    for (int i = 0; i < p->light_count; i++) {
        app_render_light *rl = &l->lights[l->light_count++];
        rl->light = light_of(&p->lights[i]);
        snprintf(rl->label, sizeof rl->label, "$.lights[%d]", i);
    }
    for (int i = 0; i < room->light_count; i++) {
        app_render_light *rl = &l->lights[l->light_count++];
        rl->light = light_of(&room->lights[i]);
        snprintf(rl->label, sizeof rl->label, "window light \"%s\"", room->lights[i].name);
    }
    return APP_OK;
}

static app_result build(app_list_builder *b, const app_project *p, char *err, size_t err_size)
{
    app_render_list *l = b->list;
    snprintf(l->path, sizeof l->path, "%s", p->path);
    memcpy(l->ambient, p->render.ambient, sizeof l->ambient);
    l->ambient_model = p->render.ambient_model == 1 ? RD_AMBIENT_SH9 : RD_AMBIENT_CONSTANT;
    app_room_geometry *room = &l->store->room;
    app_result r = app_room_geometry_build(p, room, err, err_size);
    if (r != APP_OK)
        return r;
    app_room_add_tiles(p, b->products->covers, b->products->cover_count, &b->products->catalog,
                       room);
    /* The box proxy of the corrected reflection vector is the room's interior: in a bathroom
     * the walls are what a fixture reflects (RENDERING.md section 4). */
    memcpy(l->room_min, room->bounds_min, sizeof l->room_min);
    memcpy(l->room_max, room->bounds_max, sizeof l->room_max);
    r = add_room(b, p);
    if (r == APP_OK)
        r = app_list_add_objects(b, p, err, err_size);
    if (r == APP_OK)
        r = add_lights(l, p);
    if (r == APP_OK)
        app_list_mark_lamp_glows(l, p);
    return r;
}

app_result app_render_list_build(const app_project *p, int flags, app_render_list *out, char *err,
                                 size_t err_size)
{
    memset(out, 0, sizeof *out);
    if (err && err_size)
        err[0] = 0;
    app_scene_products q;
    app_result r = app_scene_resolve_products(p, &q, err, err_size);
    if (r != APP_OK)
        return r;
    out->store = calloc(1, sizeof *out->store);
    app_list_builder b = {.list = out, .document = p, .products = &q, .flags = flags};
    r = out->store ? build(&b, &q.q, err, err_size) : APP_ERR_OUT_OF_MEMORY;
    app_scene_resolved_free(&q);
    if (r == APP_ERR_OUT_OF_MEMORY && err && err_size && !err[0])
        snprintf(err, err_size, "%s: out of memory", p->path);
    if (r != APP_OK)
        app_render_list_free(out);
    return r;
}

void app_render_list_free(app_render_list *l)
{
    if (!l)
        return;
    app_render_list_store *s = l->store;
    if (s) {
        app_room_geometry_free(&s->room);
        for (int i = 0; i < s->model_count; i++)
            cat_model_free(&s->models[i]);
        free(s->models);
        for (int i = 0; i < s->unit_count; i++)
            rd_mesh_data_free(&s->units[i]);
        free(s->units);
        free(s);
    }
    free(l->meshes);
    free(l->items);
    free(l->textures);
    free(l->probe_maps);
    free(l->lights);
    free(l->object_offsets_mm);
    memset(l, 0, sizeof *l);
}
