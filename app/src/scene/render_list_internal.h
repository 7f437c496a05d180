/* Between render_list.c and render_list_objects.c: the list being built and what owns its
 * mesh data. */
#ifndef APP_RENDER_LIST_INTERNAL_H
#define APP_RENDER_LIST_INTERNAL_H

#include "app/scene/render_list.h"
#include "catalog/model.h"
#include "render/primitives.h"
#include "scene_build_internal.h"

struct app_render_list_store {
    app_room_geometry room;
    cat_model *models; /* loaded models and their probe-capture copies */
    int model_count, model_capacity;
    rd_mesh_data *units; /* unit primitives */
    int unit_count, unit_capacity;
};

typedef struct app_list_builder {
    app_render_list *list;
    const app_project *document; /* as given; products->q is it with its products resolved */
    app_scene_products *products;
    int flags;
    int mesh_capacity, item_capacity, texture_capacity, probe_map_capacity;
    int unit_mesh[2][5]; /* shared unit meshes + 1 per [coarse][app_shape] (0 = not made) */
} app_list_builder;

/* Grows *array of *capacity elements of `size` bytes to hold `need`; 0 when out of memory. */
int app_list_grow(void **array, int *capacity, int need, size_t size);
/* The renderers' material for a project material; *texture gets its file's index, -1 = none. */
app_result app_list_material(app_list_builder *b, const app_material *am, rd_material *out,
                             int *texture);
/* The index of am's static probe map in the list; -1 when out of memory. */
int app_list_probe_map(app_list_builder *b, const app_material *am);
/* A mesh over arrays the store owns; its index, or -1 when out of memory. */
int app_list_add_mesh(app_list_builder *b, const float *positions, const float *normals,
                      const float *uvs, const uint32_t *indices, int vertex_count, int index_count);
/* A new item of that mesh (no texture, probe map or probe mesh; object -1); NULL when out of
 * memory. */
app_render_item *app_list_add_item(app_list_builder *b, int mesh, const char *label);
/* The project's objects, in order (render_list_objects.c). */
app_result app_list_add_objects(app_list_builder *b, const app_project *p, char *err,
                                size_t err_size);
/* Marks the glowing parts of each project light's lamp as stand-ins: they show the light, the
 * light lights (render_list_glow.c). */
void app_list_mark_lamp_glows(app_render_list *list, const app_project *p);

#endif
