/* The material of each part of a model, shared by the render list of both renderers
 * (render_list_objects.c) and the thumbnails (thumb_scene.c), so all of them
 * draw a product the same way. A generated product model carries Tessera's parameters per part
 * (catalog/model_write.h, "extras"): the parts its finish variant applies to (variant_slot)
 * take the object's material, the fixed parts (a basin's chrome waste, a WC's chrome flush
 * button, a tap's black aerator, a lamp's chrome housing) keep their own. A part without
 * extras (a plain glTF file) takes the object's material, as a whole model did before. */
#ifndef APP_MODEL_MATERIALS_H
#define APP_MODEL_MATERIALS_H

#include "catalog/catalog.h"
#include "catalog/model.h"
#include "catalog/model_write.h"
#include "render/render.h"

typedef struct app_model_materials {
    cat_material_extras *extras; /* one per material of the model, or NULL */
    int count;
} app_model_materials;

/* The catalog's material (RENDERING.md sections 1 and 6) as the renderer's. */
rd_material app_material_from_catalog(const cat_render_material *c);

/* Reads the extras of model file path (already loaded as *m). A file without extras, or one
 * they cannot be read from, gives count 0: every part then takes the object's material.
 * Returns 0 only when out of memory. */
int app_model_materials_read(const char *path, const cat_model *m, app_model_materials *out);
void app_model_materials_free(app_model_materials *mm);

/* 1 when part cm keeps a material of its own (*out gets it), 0 when it takes the object's. */
int app_model_part_material(const app_model_materials *mm, const cat_mesh *cm, rd_material *out);

#endif
