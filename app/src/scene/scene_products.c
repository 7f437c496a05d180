/* Placed catalog products (app_object.has_product, project file version 2) made drawable for
 * the render list (render_list.h): a working copy of the project in which each product object is a
 * plain object: the product's model (the catalog's `model` column, relative to the assets folder)
 * when that file exists, else a box of the catalog's width x depth x height; with the
 * variant's render material unless the project gave the object a material of its own (any
 * but "default"). The product frame is app/design/placement.h's: the origin at the bottom centre of
 * the back face, depth along local +y, height along +z.
 *
 * The catalog is opened only when the project has products ($TESSERA_CATALOG or the default
 * place, built from the shipped data). A product the catalog does not know, or no catalog at
 * all, leaves the object as it was (a warning on stderr): a render must not fail for it. */
#include "scene_build_internal.h"

#include "app/design/placement.h"
#include "app/design/room_surfaces.h"
#include "catalog/catalog.h"
#include "catalog/model_gen.h"

#include <math.h>
#include <stdlib.h>
#include <unistd.h>

static int has_products(const app_project *p)
{
    for (int i = 0; i < p->object_count; i++)
        if (p->objects[i].has_product)
            return 1;
    return 0;
}

/* R = Rz * Ry * Rx of an object (app_object_transform's). */
static void rotation_of(const app_object *o, double r[3][3])
{
    const double deg = 3.14159265358979323846 / 180.0;
    double cx = cos(o->rotation_deg[0] * deg), sx = sin(o->rotation_deg[0] * deg);
    double cy = cos(o->rotation_deg[1] * deg), sy = sin(o->rotation_deg[1] * deg);
    double cz = cos(o->rotation_deg[2] * deg), sz = sin(o->rotation_deg[2] * deg);
    const double m[3][3] = {{cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx},
                            {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx},
                            {-sy, cy * sx, cy * cx}};
    memcpy(r, m, sizeof m);
}

/* o's position moved from the product origin to the centre of its box (R * (0, d/2, h/2)). */
static void box_centre(app_object *o, double depth, double height)
{
    double r[3][3];
    rotation_of(o, r);
    double local[3] = {0, 0.5 * depth * o->scale[1], 0.5 * height * o->scale[2]};
    for (int row = 0; row < 3; row++)
        o->position_mm[row] += r[row][1] * local[1] + r[row][2] * local[2];
}

static int material_from_info(const app_product_info *info, const app_object *o, app_material *m)
{
    if (!info->has_material)
        return 0;
    memset(m, 0, sizeof *m);
    snprintf(m->name, sizeof m->name, "%.24s %.24s %.12s", o->product.manufacturer,
             o->product.article, info->variant);
    memcpy(m->ambient, info->ambient, sizeof m->ambient);
    memcpy(m->diffuse, info->diffuse, sizeof m->diffuse);
    memcpy(m->specular, info->specular, sizeof m->specular);
    memcpy(m->emissive, info->emissive, sizeof m->emissive);
    m->shininess = info->shininess;
    m->reflectivity = info->reflectivity;
    m->glossiness = info->glossiness;
    m->transparency = info->transparency;
    m->ior = info->ior > 0 ? info->ior : 1.5f;
    m->blend = info->blend;
    m->pattern = info->pattern;
    m->grain_deg = info->grain_deg;
    m->texture_size_mm[0] = m->texture_size_mm[1] = 1000;
    return 1;
}

app_result app_scene_resolve_products(const app_project *p, app_scene_products *res, char *err,
                                      size_t err_size)
{
    memset(res, 0, sizeof *res);
    app_project *out = &res->q;
    int *resolved = &res->owns;
    *out = *p;
    if (!has_products(p))
        return APP_OK;
    res->covers = calloc((size_t)p->object_count, sizeof *res->covers);
    if (!res->covers) {
        snprintf(err, err_size, "%s: out of memory resolving products", p->path);
        return APP_ERR_OUT_OF_MEMORY;
    }
    out->objects = malloc((size_t)p->object_count * sizeof *out->objects);
    out->materials = malloc((size_t)(p->material_count + p->object_count) * sizeof *out->materials);
    if (!out->objects || !out->materials) {
        free(out->objects);
        free(out->materials);
        free(res->covers);
        memset(res, 0, sizeof *res);
        res->q = *p;
        snprintf(err, err_size, "%s: out of memory resolving products", p->path);
        return APP_ERR_OUT_OF_MEMORY;
    }
    memcpy(out->objects, p->objects, (size_t)p->object_count * sizeof *out->objects);
    memcpy(out->materials, p->materials, (size_t)p->material_count * sizeof *out->materials);
    *resolved = 1;
    app_lazy_catalog *cat = &res->catalog;
    for (int i = 0; i < out->object_count; i++) {
        app_object *o = &out->objects[i];
        if (!o->has_product)
            continue;
        app_product_info info;
        char lerr[1024];
        if (app_placement_lazy_lookup(cat, &o->product, &info, lerr, sizeof lerr) != APP_OK) {
            fprintf(stderr, "tessera: warning: %s: $.objects[%d] (\"%s\"): product %s %s: %s; %s\n",
                    p->path, i, o->name, o->product.manufacturer, o->product.article, lerr,
                    o->shape == APP_SHAPE_MODEL ? "drawn with its model" : "not drawn");
            if (o->shape != APP_SHAPE_MODEL)
                o->size_mm[0] = o->size_mm[1] = o->size_mm[2] = 0; /* nothing to draw */
            continue;
        }
        /* Baths and shower trays cover the wall behind them and the floor under them: no
         * tiles there (app/design/room_surfaces.h). */
        res->cover_count += app_room_fixture_box(o, &info, &res->covers[res->cover_count]);
        /* Generated models live in the build (or $TESSERA_MODELS), not the assets folder. */
        char model[2048] = "";
        if (info.model[0] &&
            !cat_model_resolve(info.model, app_placement_assets_dir(), model, sizeof model))
            model[0] = 0;
        if (model[0] && access(model, R_OK) == 0 && strlen(model) < sizeof o->model) {
            o->shape = APP_SHAPE_MODEL;
            memcpy(o->model, model, strlen(model) + 1); /* fits: checked above */
        } else {
            /* No model yet: the catalog's box, standing on the product's origin. */
            o->shape = APP_SHAPE_BOX;
            o->size_mm[0] = info.width_mm;
            o->size_mm[1] = info.depth_mm;
            o->size_mm[2] = info.height_mm;
            box_centre(o, info.depth_mm, info.height_mm);
        }
        int own = o->material >= 0 && o->material < p->material_count &&
                  strcmp(p->materials[o->material].name, "default") != 0;
        app_material m;
        if (!own && material_from_info(&info, o, &m)) {
            out->materials[out->material_count] = m;
            o->material = out->material_count++;
        }
    }
    return APP_OK;
}

void app_scene_resolved_free(app_scene_products *r)
{
    if (r->owns) {
        free(r->q.objects);
        free(r->q.materials);
    }
    free(r->covers);
    app_placement_lazy_close(&r->catalog);
    memset(r, 0, sizeof *r);
}
