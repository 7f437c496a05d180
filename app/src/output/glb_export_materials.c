/* Project materials as glTF materials for the export (app/output/project_glb.h): the product
 * writer's metallic-roughness approximation (cat_material_from_render, docs/catalog.md
 * "Materials") with Tessera's exact parameters in extras, so the mapping is the same for a
 * product exported alone and inside a project. */
#include "glb_export_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int grow(pg_build *b)
{
    if (b->material_count < b->material_cap)
        return 1;
    int cap = b->material_cap ? 2 * b->material_cap : 16;
    cat_material *m = realloc(b->materials, (size_t)cap * sizeof *m);
    if (m)
        b->materials = m;
    cat_material_extras *x = realloc(b->extras, (size_t)cap * sizeof *x);
    if (x)
        b->extras = x;
    unsigned char *f = realloc(b->model_material, (size_t)cap);
    if (f)
        b->model_material = f;
    if (!m || !x || !f) {
        snprintf(b->err, b->err_size, "%s: out of memory exporting materials", b->p->path);
        return 0;
    }
    b->material_cap = cap;
    return 1;
}

static cat_render_material render_of(const app_material *a)
{
    cat_render_material r;
    memset(&r, 0, sizeof r);
    memcpy(r.ambient, a->ambient, sizeof r.ambient);
    memcpy(r.diffuse, a->diffuse, sizeof r.diffuse);
    memcpy(r.specular, a->specular, sizeof r.specular);
    memcpy(r.emissive, a->emissive, sizeof r.emissive);
    r.shininess = a->shininess;
    r.reflectivity = a->reflectivity;
    r.glossiness = a->glossiness;
    r.blend = a->blend == APP_BLEND_ADD       ? CAT_BLEND_ADD
              : a->blend == APP_BLEND_FRESNEL ? CAT_BLEND_FRESNEL
                                              : CAT_BLEND_MIX;
    r.transparency = a->transparency;
    r.ior = a->ior;
    return r;
}

int pg_add_app_material(pg_build *b, const app_material *a)
{
    if (!grow(b))
        return -1;
    int i = b->material_count++;
    cat_render_material r = render_of(a);
    cat_material_from_render(&r, a->name, &b->materials[i]);
    /* Without reflections (k_r = 0) g says nothing and a project material's gloss is its
     * Blinn-Phong exponent n: Beckmann alpha = sqrt(2 / (n + 2)) (Walter et al. 2007,
     * "Microfacet models for refraction", section 5.2) and glTF's alpha = roughness^2. */
    if (!(a->reflectivity > 0.0f)) {
        double rough = pow(2.0 / (fmax(a->shininess, 0.0) + 2.0), 0.25);
        b->materials[i].roughness = (float)fmin(1.0, fmax(0.02, rough));
    }
    b->extras[i] = (cat_material_extras){.present = 1, .variant_slot = 0, .params = r};
    b->model_material[i] = 0;
    return i;
}

static int same_factors(const cat_material *a, const cat_material *b)
{
    return !strcmp(a->name, b->name) &&
           !memcmp(a->base_color, b->base_color, sizeof a->base_color) &&
           a->metallic == b->metallic && a->roughness == b->roughness &&
           !memcmp(a->emissive, b->emissive, sizeof a->emissive);
}

static int same_extras(const cat_material_extras *a, const cat_material_extras *b)
{
    const cat_render_material *p = &a->params, *q = &b->params;
    if (a->present != b->present)
        return 0;
    return !a->present ||
           (!memcmp(p->ambient, q->ambient, sizeof p->ambient) &&
            !memcmp(p->diffuse, q->diffuse, sizeof p->diffuse) &&
            !memcmp(p->specular, q->specular, sizeof p->specular) &&
            !memcmp(p->emissive, q->emissive, sizeof p->emissive) && p->shininess == q->shininess &&
            p->reflectivity == q->reflectivity && p->glossiness == q->glossiness &&
            p->blend == q->blend && p->transparency == q->transparency && p->ior == q->ior &&
            a->variant_slot == b->variant_slot);
}

int pg_add_model_material(pg_build *b, const cat_material *m, const cat_material_extras *x)
{
    /* the same fixed part material of several products (a chrome waste) is written once */
    cat_material_extras none;
    memset(&none, 0, sizeof none);
    for (int i = 0; i < b->material_count; i++)
        if (b->model_material[i] && same_factors(&b->materials[i], m) &&
            same_extras(&b->extras[i], x ? x : &none))
            return i;
    if (!grow(b))
        return -1;
    int i = b->material_count++;
    b->materials[i] = *m;
    b->materials[i].base_color_texture[0] = '\0'; /* textures are not exported */
    b->model_material[i] = 1;
    if (x)
        b->extras[i] = *x;
    else
        memset(&b->extras[i], 0, sizeof b->extras[i]);
    return i;
}

int pg_project_material(pg_build *b, int index)
{
    if (index < 0 || index >= b->q->material_count)
        return -1;
    if (b->project_material[index] < 0)
        b->project_material[index] = pg_add_app_material(b, &b->q->materials[index]);
    return b->project_material[index];
}
