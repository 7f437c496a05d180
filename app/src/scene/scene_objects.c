/* Project objects -> renderer objects: primitives share one unit mesh per shape; a glTF/GLB
 * model is loaded through the catalog and uploaded part by part. */
#include "scene_build_internal.h"

#include "catalog/mesh_lod.h"
#include "catalog/model.h"
#include "model_materials.h"
#include "render/primitives.h"

#include <math.h>
#include <stdlib.h>

/* M = T(position) * Rz * Ry * Rx * S(scale * size), column-major, metres. */
void app_object_transform(const app_object *o, const double size_m[3], float out[16])
{
    const double deg = 3.14159265358979323846 / 180.0;
    double cx = cos(o->rotation_deg[0] * deg), sx = sin(o->rotation_deg[0] * deg);
    double cy = cos(o->rotation_deg[1] * deg), sy = sin(o->rotation_deg[1] * deg);
    double cz = cos(o->rotation_deg[2] * deg), sz = sin(o->rotation_deg[2] * deg);
    double r[3][3] = {/* row-major Rz*Ry*Rx */
                      {cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx},
                      {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx},
                      {-sy, cy * sx, cy * cx}};
    for (int col = 0; col < 3; col++) {
        double s = o->scale[col] * size_m[col];
        for (int row = 0; row < 3; row++)
            out[col * 4 + row] = (float)(r[row][col] * s);
        out[col * 4 + 3] = 0.0f;
    }
    for (int row = 0; row < 3; row++)
        out[12 + row] = (float)(o->position_mm[row] * 1e-3);
    out[15] = 1.0f;
}

/* The renderer's group of object `index`: objects sharing a group name get the id of the
 * first of them (+1); a model's parts share their object's id; 0 = alone. */
static int group_of(const app_project *p, int index)
{
    const char *g = p->objects[index].group;
    if (!g[0])
        return p->objects[index].shape == APP_SHAPE_MODEL ? index + 1 : 0;
    for (int i = 0; i < index; i++)
        if (!strcmp(p->objects[i].group, g))
            return i + 1;
    return index + 1;
}

/* The probe settings of a project material (RENDERING.md section 8). */
static rd_probe_desc probe_of(const app_material *am)
{
    return (rd_probe_desc){.update = am->probe_update == APP_PROBE_STATIC
                                         ? RD_PROBE_STATIC
                                         : (rd_probe_update)am->probe_update,
                           .every_n = am->probe_every,
                           .resolution = am->probe_resolution,
                           .proxy_radius_m = am->proxy_radius_mm * 1e-3f};
}

/* probe_of, with the static map loaded when the material names one. */
static app_result probe_for(rd_context *ctx, const app_project *p, app_scene *s, int index,
                            rd_probe_desc *out, char *err, size_t err_size)
{
    const app_material *am = &p->materials[p->objects[index].material];
    *out = probe_of(am);
    if (am->probe_update != APP_PROBE_STATIC)
        return APP_OK;
    char inner[768];
    app_result r = app_scene_cubemap(ctx, s, am->probe_map, &out->static_map, inner, sizeof inner);
    if (r != APP_OK)
        snprintf(err, err_size, "%s: material \"%s\": probe map: %s", p->path, am->name, inner);
    return r;
}

/* coarse = 1: the low-detail version drawn in probe captures (a quarter of the segments). */
static app_result unit_mesh(rd_context *ctx, app_scene *s, app_shape shape, float torus_ratio,
                            int coarse, rd_mesh *out)
{
    if (shape != APP_SHAPE_TORUS && s->unit_meshes[coarse][shape].id) {
        *out = s->unit_meshes[coarse][shape];
        return APP_OK;
    }
    int seg = coarse ? 16 : 64;
    rd_mesh_data d;
    rd_result r;
    switch (shape) {
    case APP_SHAPE_BOX:
        r = rd_mesh_data_box(&d);
        break;
    case APP_SHAPE_SPHERE:
        r = rd_mesh_data_sphere(seg, seg / 2, &d);
        break;
    case APP_SHAPE_CYLINDER:
        r = rd_mesh_data_cylinder(seg, &d);
        break;
    case APP_SHAPE_PLANE:
        r = rd_mesh_data_plane(&d);
        break;
    default:
        r = rd_mesh_data_torus(torus_ratio, seg, coarse ? 8 : 24, &d);
        break;
    }
    if (r != RD_OK)
        return APP_ERR_SCHEMA;
    rd_mesh_desc desc = rd_mesh_data_desc(&d);
    rd_mesh m = rd_mesh_create(ctx, &desc);
    rd_mesh_data_free(&d);
    if (!m.id || app_scene_track_mesh(s, m) != APP_OK)
        return APP_ERR_OUT_OF_MEMORY;
    if (shape != APP_SHAPE_TORUS)
        s->unit_meshes[coarse][shape] = m;
    *out = m;
    return APP_OK;
}

static app_result add_primitive(rd_context *ctx, const app_project *p, app_scene *s, int index,
                                const rd_material *m, char *err, size_t err_size)
{
    const app_object *o = &p->objects[index];
    double size_m[3] = {o->size_mm[0] * 1e-3, o->size_mm[1] * 1e-3, o->size_mm[2] * 1e-3};
    float ratio = 0.0f;
    if (o->shape == APP_SHAPE_PLANE)
        size_m[2] = 1.0;
    if (o->shape == APP_SHAPE_TORUS) {
        /* The unit torus is 1 across and `ratio` thick; scale z back to the outer diameter. */
        ratio = (float)fmin(o->size_mm[2] / o->size_mm[0], 0.5);
        size_m[2] = size_m[0];
    }
    rd_probe_desc probe;
    app_result pr = probe_for(ctx, p, s, index, &probe, err, err_size);
    if (pr != APP_OK)
        return pr;
    rd_mesh mesh, coarse = {0};
    int curved = o->shape == APP_SHAPE_SPHERE || o->shape == APP_SHAPE_CYLINDER ||
                 o->shape == APP_SHAPE_TORUS;
    if (unit_mesh(ctx, s, o->shape, ratio, 0, &mesh) != APP_OK ||
        (curved && unit_mesh(ctx, s, o->shape, ratio, 1, &coarse) != APP_OK)) {
        snprintf(err, err_size, "%s: $.objects[%d] (\"%s\"): cannot make its mesh: %s", p->path,
                 index, o->name, rd_last_error());
        return APP_ERR_SCHEMA;
    }
    /* Closed shapes cull their back faces; a plane is a sheet seen from either side. */
    /* The unit shape the mesh approximates: a lamp of one is reflected exactly (emitters.c). */
    rd_shape shape = o->shape == APP_SHAPE_BOX        ? RD_SHAPE_BOX
                     : o->shape == APP_SHAPE_SPHERE   ? RD_SHAPE_SPHERE
                     : o->shape == APP_SHAPE_CYLINDER ? RD_SHAPE_CYLINDER
                     : o->shape == APP_SHAPE_PLANE    ? RD_SHAPE_PLANE
                                                      : RD_SHAPE_MESH;
    rd_object_desc d = {.mesh = mesh,
                        .shape = shape,
                        .material = *m,
                        .double_sided = o->shape == APP_SHAPE_PLANE,
                        .probe = probe,
                        .probe_mesh = coarse,
                        .group = group_of(p, index)};
    /* Unit-mesh UVs span the whole object: repeat the texture at its real-world size. A plane
     * maps u, v to its x, y; the other shapes wrap u around and run v along the height. */
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
    if (rd_scene_add_object(s->scene, &d) != RD_OK) {
        snprintf(err, err_size, "%s: $.objects[%d] (\"%s\"): %s", p->path, index, o->name,
                 rd_last_error());
        return APP_ERR_SCHEMA;
    }
    return APP_OK;
}

/* Models with at least this many triangles get a probe-capture copy at this fraction. */
#define LOD_MIN_TRIANGLES 1500
#define LOD_FRACTION 0.25f

static app_result add_model(rd_context *ctx, const app_project *p, app_scene *s, int index,
                            const rd_material *m, char *err, size_t err_size)
{
    const app_object *o = &p->objects[index];
    cat_model model = {0};
    char cerr[768];
    if (cat_model_load(o->model, &model, cerr, sizeof cerr) != CAT_OK) {
        snprintf(err, err_size, "%s: $.objects[%d].model: %s", p->path, index, cerr);
        return APP_ERR_IO;
    }
    rd_probe_desc probe;
    app_result pr = probe_for(ctx, p, s, index, &probe, err, err_size);
    app_model_materials parts;
    if (pr == APP_OK && !app_model_materials_read(o->model, &model, &parts)) {
        snprintf(err, err_size, "%s: $.objects[%d].model: out of memory", p->path, index);
        pr = APP_ERR_OUT_OF_MEMORY;
    }
    if (pr != APP_OK) {
        cat_model_free(&model);
        return pr;
    }
    const double mm_to_m[3] = {1e-3, 1e-3, 1e-3};
    float transform[16];
    app_object_transform(o, mm_to_m, transform);
    /* Probe captures draw a decimated copy of a detailed model (RENDERING.md section 8: probes
     * may draw lower-detail geometry; catalog/mesh_lod.h). A model that cannot be decimated
     * is captured as it is. */
    cat_model lod = {0};
    char lerr[256];
    int has_lod = cat_model_triangle_count(&model) >= LOD_MIN_TRIANGLES &&
                  cat_model_make_lod(&model, LOD_FRACTION, &lod, lerr, sizeof lerr) == CAT_OK &&
                  lod.mesh_count == model.mesh_count;
    app_result r = APP_OK;
    for (int i = 0; r == APP_OK && i < model.mesh_count; i++) {
        const cat_mesh *cm = &model.meshes[i];
        rd_mesh coarse = {0};
        if (has_lod && lod.meshes[i].index_count >= 3) {
            const cat_mesh *lm = &lod.meshes[i];
            coarse = rd_mesh_create(ctx, &(rd_mesh_desc){.positions = lm->positions,
                                                         .normals = lm->normals,
                                                         .uvs = lm->uvs,
                                                         .indices = lm->indices,
                                                         .vertex_count = lm->vertex_count,
                                                         .index_count = lm->index_count});
            if (coarse.id && app_scene_track_mesh(s, coarse) != APP_OK)
                coarse.id = 0;
        }
        rd_mesh mesh = rd_mesh_create(ctx, &(rd_mesh_desc){.positions = cm->positions,
                                                           .normals = cm->normals,
                                                           .uvs = cm->uvs,
                                                           .indices = cm->indices,
                                                           .vertex_count = cm->vertex_count,
                                                           .index_count = cm->index_count});
        if (!mesh.id || app_scene_track_mesh(s, mesh) != APP_OK) {
            snprintf(err, err_size, "%s: $.objects[%d].model: %s: part %d: %s", p->path, index,
                     o->model, i, rd_last_error());
            r = APP_ERR_IO;
            break;
        }
        /* A model may be open (glTF's doubleSided): draw both sides. */
        rd_object_desc d = {.mesh = mesh,
                            .material = *m,
                            .double_sided = 1,
                            .group = group_of(p, index), /* one probe for the model */
                            .probe = probe,
                            .probe_mesh = coarse};
        app_model_part_material(&parts, cm, &d.material); /* a fixed part's own finish */
        memcpy(d.transform, transform, sizeof transform);
        if (rd_scene_add_object(s->scene, &d) != RD_OK) {
            snprintf(err, err_size, "%s: $.objects[%d]: %s", p->path, index, rd_last_error());
            r = APP_ERR_SCHEMA;
        }
    }
    app_model_materials_free(&parts);
    cat_model_free(&lod);
    cat_model_free(&model);
    return r;
}

app_result app_scene_add_objects(rd_context *ctx, const app_project *p, app_scene *s, char *err,
                                 size_t err_size)
{
    s->object_parts =
        calloc((size_t)(p->object_count ? p->object_count : 1), sizeof *s->object_parts);
    if (!s->object_parts)
        return APP_ERR_OUT_OF_MEMORY;
    for (int i = 0; i < p->object_count; i++) {
        rd_material m;
        s->object_parts[i][0] = rd_scene_object_count(s->scene);
        if (APP_OBJECT_UNRESOLVED(&p->objects[i]))
            continue; /* a product without a size: warned about in scene_products.c */
        app_result r = app_scene_material(ctx, p, s, p->objects[i].material, &m, err, err_size);
        if (r == APP_OK)
            r = p->objects[i].shape == APP_SHAPE_MODEL
                    ? add_model(ctx, p, s, i, &m, err, err_size)
                    : add_primitive(ctx, p, s, i, &m, err, err_size);
        if (r != APP_OK)
            return r;
        s->object_parts[i][1] = rd_scene_object_count(s->scene) - s->object_parts[i][0];
    }
    return APP_OK;
}
