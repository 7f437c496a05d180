/* Per-part materials of a model (model_materials.h). */
#include "model_materials.h"

#include <stdlib.h>
#include <string.h>

rd_material app_material_from_catalog(const cat_render_material *c)
{
    rd_material m;
    memset(&m, 0, sizeof m);
    memcpy(m.ambient, c->ambient, sizeof m.ambient);
    memcpy(m.diffuse, c->diffuse, sizeof m.diffuse);
    memcpy(m.specular, c->specular, sizeof m.specular);
    memcpy(m.emissive, c->emissive, sizeof m.emissive);
    m.shininess = c->shininess;
    m.reflectivity = c->reflectivity;
    m.glossiness = c->glossiness;
    m.blend = c->blend == CAT_BLEND_ADD       ? RD_REFLECT_ADD
              : c->blend == CAT_BLEND_FRESNEL ? RD_REFLECT_FRESNEL
                                              : RD_REFLECT_MIX;
    m.transparency = c->transparency;
    m.ior = c->ior;
    m.pattern = c->pattern == CAT_PATTERN_WOOD ? RD_PATTERN_WOOD : RD_PATTERN_NONE;
    m.grain_angle_deg = c->grain_deg >= 0.0f ? c->grain_deg : 0.0f;
    return m;
}

int app_model_materials_read(const char *path, const cat_model *m, app_model_materials *out)
{
    memset(out, 0, sizeof *out);
    if (m->material_count <= 0)
        return 1;
    out->extras = calloc((size_t)m->material_count, sizeof *out->extras);
    if (!out->extras)
        return 0;
    char err[512];
    if (cat_model_read_extras(path, out->extras, m->material_count, &out->count, err, sizeof err) !=
        CAT_OK)
        out->count = 0; /* a plain glTF file: the object's material everywhere */
    return 1;
}

void app_model_materials_free(app_model_materials *mm)
{
    free(mm->extras);
    memset(mm, 0, sizeof *mm);
}

int app_model_part_material(const app_model_materials *mm, const cat_mesh *cm, rd_material *out)
{
    int mi = cm->material;
    if (!mm || mi < 0 || mi >= mm->count || !mm->extras[mi].present || mm->extras[mi].variant_slot)
        return 0;
    *out = app_material_from_catalog(&mm->extras[mi].params);
    return 1;
}
