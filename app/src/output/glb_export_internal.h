/* Shared between the glb_export*.c files: the scene being assembled for export. */
#ifndef APP_GLB_EXPORT_INTERNAL_H
#define APP_GLB_EXPORT_INTERNAL_H

#include "app/project/project.h"
#include "app/output/project_glb.h"
#include "catalog/scene_write.h"
#include "scene/scene_build_internal.h"

typedef struct pg_build {
    const app_project *p;      /* the project as read */
    const app_project *q;      /* the same with products resolved (scene_products.c) */
    app_lazy_catalog *catalog; /* q's catalog, for the product lookups */
    cat_scene_node *nodes;
    int node_count, node_cap;
    cat_material *materials;
    cat_material_extras *extras;
    int material_count, material_cap;
    unsigned char *model_material; /* 1: the material came from a model file (shared) */
    int *project_material;         /* q's material index -> scene material, -1 = not added yet */
    cat_model *owned;              /* meshes the nodes point into, freed with cat_model_free */
    int owned_count, owned_cap;
    app_glb_stats *stats;
    char *err;
    size_t err_size;
} pg_build;

/* A new node (zero parts, identity matrix) or NULL when out of memory (err set). */
cat_scene_node *pg_add_node(pg_build *b, const char *name, int parent);
/* Keeps m (moved: *m is zeroed) until the build ends; returns the kept model, NULL when out of
 * memory (m freed, err set). Pointers to its meshes stay valid. */
cat_model *pg_keep_model(pg_build *b, cat_model *m);

/* The scene material of q's project material `index`, added on first use; -1 when out of
 * memory (err set). */
int pg_project_material(pg_build *b, int index);
/* Adds a material given as a project material (room panels, tiles); -1 when out of memory. */
int pg_add_app_material(pg_build *b, const app_material *m);
/* Adds a model file's material, with its Tessera extras when it has them; -1 = no memory. */
int pg_add_model_material(pg_build *b, const cat_material *m, const cat_material_extras *x);

/* The node of q's object `index` under node `parent`; APP_OK also when the object is left
 * out (a product the catalog does not know: a warning on stderr). */
app_result pg_add_object(pg_build *b, int index, int parent);

#endif
