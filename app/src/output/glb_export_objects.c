/* The project's objects as nodes of the exported GLB (app/output/project_glb.h): primitives as the
 * renderer's unit meshes (render/primitives.h, the segment counts of render_list_objects.c) scaled
 * to their size, glTF models and catalog products as their files' parts with their own materials.
 * The node's matrix is the object's placement T(position) * Rz * Ry * Rx * S(scale) in mm
 * (app_object_transform's, without the size, which is baked into a primitive's vertices). */
#include "glb_export_internal.h"

#include "app/design/placement.h"
#include "catalog/model_gen.h"
#include "render/primitives.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void placement_matrix(const app_object *o, double out[16])
{
    const double deg = 3.14159265358979323846 / 180.0;
    double cx = cos(o->rotation_deg[0] * deg), sx = sin(o->rotation_deg[0] * deg);
    double cy = cos(o->rotation_deg[1] * deg), sy = sin(o->rotation_deg[1] * deg);
    double cz = cos(o->rotation_deg[2] * deg), sz = sin(o->rotation_deg[2] * deg);
    const double r[3][3] = {{cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx},
                            {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx},
                            {-sy, cy * sx, cy * cx}};
    for (int col = 0; col < 3; col++) {
        for (int row = 0; row < 3; row++)
            out[col * 4 + row] = r[row][col] * o->scale[col];
        out[col * 4 + 3] = 0;
    }
    for (int row = 0; row < 3; row++)
        out[12 + row] = o->position_mm[row];
    out[15] = 1;
}

/* Counts and world bounds of the parts of a node placed by matrix m. */
static void account(pg_build *b, const cat_mesh *parts, int count, const double m[16])
{
    app_glb_stats *s = b->stats;
    for (int i = 0; i < count; i++) {
        const cat_mesh *c = &parts[i];
        s->part_count++;
        s->vertex_count += c->vertex_count;
        s->triangle_count += c->index_count / 3;
        for (int v = 0; v < c->vertex_count; v++) {
            const float *q = c->positions + 3 * v;
            for (int k = 0; k < 3; k++) {
                double w = m[k] * q[0] + m[4 + k] * q[1] + m[8 + k] * q[2] + m[12 + k];
                s->bounds_min_mm[k] = fmin(s->bounds_min_mm[k], w);
                s->bounds_max_mm[k] = fmax(s->bounds_max_mm[k], w);
            }
        }
    }
}

static app_result no_memory(pg_build *b, int index)
{
    snprintf(b->err, b->err_size, "%s: $.objects[%d] (\"%s\"): out of memory exporting it",
             b->p->path, index, b->q->objects[index].name);
    return APP_ERR_OUT_OF_MEMORY;
}

/* The unit mesh of a primitive, with its size baked in (mm). */
static app_result primitive_model(const app_object *o, int material, cat_model *out)
{
    rd_mesh_data d;
    rd_result r;
    double size[3] = {o->size_mm[0], o->size_mm[1], o->size_mm[2]};
    switch (o->shape) {
    case APP_SHAPE_BOX:
        r = rd_mesh_data_box(&d);
        break;
    case APP_SHAPE_SPHERE:
        r = rd_mesh_data_sphere(64, 32, &d);
        break;
    case APP_SHAPE_CYLINDER:
        r = rd_mesh_data_cylinder(64, &d);
        break;
    case APP_SHAPE_PLANE:
        r = rd_mesh_data_plane(&d);
        size[2] = 1;
        break;
    default: /* the unit torus is 1 across and `ratio` thick: z scales like x
                (render_list_objects.c) */
        r = rd_mesh_data_torus((float)fmin(o->size_mm[2] / o->size_mm[0], 0.5), 64, 24, &d);
        size[2] = size[0];
        break;
    }
    if (r != RD_OK)
        return APP_ERR_OUT_OF_MEMORY;
    memset(out, 0, sizeof *out);
    cat_mesh *m = calloc(1, sizeof *m);
    size_t nv = (size_t)d.vertex_count, ni = (size_t)d.index_count;
    if (m) {
        m->positions = malloc(nv * 3 * sizeof(float));
        m->normals = malloc(nv * 3 * sizeof(float));
        m->indices = malloc(ni * sizeof(unsigned));
    }
    out->meshes = m;
    out->mesh_count = m ? 1 : 0;
    if (!m || !m->positions || !m->normals || !m->indices) {
        rd_mesh_data_free(&d);
        cat_model_free(out);
        return APP_ERR_OUT_OF_MEMORY;
    }
    for (size_t v = 0; v < nv; v++) {
        double n[3], len = 0;
        for (int k = 0; k < 3; k++) {
            m->positions[3 * v + k] = (float)(d.positions[3 * v + k] * size[k]);
            /* normals of a scaled shape: the inverse transpose, i.e. divided by the scale */
            n[k] = d.normals[3 * v + k] / fmax(size[k], 1e-9);
            len += n[k] * n[k];
        }
        len = sqrt(len);
        for (int k = 0; k < 3; k++)
            m->normals[3 * v + k] = len > 0 ? (float)(n[k] / len) : (k == 2 ? 1.0f : 0.0f);
    }
    for (size_t i = 0; i < ni; i++)
        m->indices[i] = d.indices[i];
    m->vertex_count = d.vertex_count;
    m->index_count = d.index_count;
    m->material = material;
    rd_mesh_data_free(&d);
    return APP_OK;
}

/* A model file's parts, their materials added to the scene: a part the file marks as the
 * product's variant slot, or one without a material, takes the object's project material
 * (for a product: its variant, or the project's own choice; scene_products.c). */
static app_result file_model(pg_build *b, int index, const char *path, cat_model *out)
{
    char cerr[1024];
    cat_result cr = cat_model_load(path, out, cerr, sizeof cerr);
    if (cr != CAT_OK) {
        snprintf(b->err, b->err_size, "%s: $.objects[%d] (\"%s\"): model: %s", b->p->path, index,
                 b->q->objects[index].name, cerr);
        return cr == CAT_ERR_OUT_OF_MEMORY ? APP_ERR_OUT_OF_MEMORY : APP_ERR_IO;
    }
    cat_material_extras *x = calloc((size_t)(out->material_count + 1), sizeof *x);
    int *map = calloc((size_t)(out->material_count + 1), sizeof *map);
    int xcount = 0;
    if (!x || !map) {
        free(x);
        free(map);
        cat_model_free(out);
        return no_memory(b, index);
    }
    if (out->material_count > 0 &&
        cat_model_read_extras(path, x, out->material_count, &xcount, cerr, sizeof cerr) != CAT_OK)
        xcount = 0; /* a plain glTF file: its materials as they are */
    int own = pg_project_material(b, b->q->objects[index].material);
    for (int i = 0; i < out->material_count; i++) {
        int slot = i < xcount && x[i].present && x[i].variant_slot;
        map[i] = slot ? own
                      : pg_add_model_material(b, &out->materials[i],
                                              i < xcount && x[i].present ? &x[i] : NULL);
    }
    int m_own = b->q->objects[index].material;
    int oom = own < 0 && m_own >= 0 && m_own < b->q->material_count;
    for (int i = 0; i < out->material_count; i++)
        oom = oom || map[i] < 0;
    for (int i = 0; i < out->mesh_count; i++) {
        int m = out->meshes[i].material;
        out->meshes[i].material = m >= 0 && m < out->material_count ? map[m] : own;
    }
    free(x);
    free(map);
    if (oom) {
        cat_model_free(out);
        return no_memory(b, index);
    }
    return APP_OK;
}

/* The model file of a placed product: the catalog's `model` resolved with cat_model_resolve
 * (generated models live in the build, not under assets/); "" when there is none. */
static void product_model_path(pg_build *b, const app_object *o, char *out, size_t size,
                               char *variant, size_t variant_size)
{
    out[0] = '\0';
    app_product_info info;
    char lerr[1024];
    if (app_placement_lazy_lookup(b->catalog, &o->product, &info, lerr, sizeof lerr) != APP_OK)
        return; /* warned about by app_scene_resolve_products */
    if (!o->product.variant[0])
        snprintf(variant, variant_size, "%s", info.variant);
    if (info.model[0] && cat_model_resolve(info.model, app_placement_assets_dir(), out, size) &&
        access(out, R_OK) != 0)
        out[0] = '\0';
}

app_result pg_add_object(pg_build *b, int index, int parent)
{
    const app_object *o = &b->q->objects[index];
    if (APP_OBJECT_UNRESOLVED(o)) {
        b->stats->skipped_count++;
        return APP_OK; /* the product is unknown: warned about by app_scene_resolve_products */
    }
    char name[96], path[2048] = "", variant[16];
    snprintf(variant, sizeof variant, "%s", o->product.variant);
    if (o->has_product)
        product_model_path(b, o, path, sizeof path, variant, sizeof variant);
    if (!path[0] && o->shape == APP_SHAPE_MODEL)
        snprintf(path, sizeof path, "%s", o->model);
    if (o->has_product)
        snprintf(name, sizeof name, "%.40s (%.20s %.20s%s%.8s)", o->name, o->product.manufacturer,
                 o->product.article, variant[0] ? " " : "", variant);
    else
        snprintf(name, sizeof name, "%s", o->name);

    cat_model model;
    app_result r;
    if (path[0]) {
        r = file_model(b, index, path, &model);
    } else {
        int mat = pg_project_material(b, o->material);
        r = mat < 0 ? APP_ERR_OUT_OF_MEMORY : primitive_model(o, mat, &model);
        if (r != APP_OK)
            return no_memory(b, index);
    }
    if (r != APP_OK)
        return r;
    if (model.mesh_count == 0) {
        cat_model_free(&model);
        fprintf(stderr,
                "tessera: warning: %s: $.objects[%d] (\"%s\"): its model has no "
                "triangles; left out\n",
                b->p->path, index, o->name);
        b->stats->skipped_count++;
        return APP_OK;
    }
    cat_model *kept = pg_keep_model(b, &model);
    cat_scene_node *n = kept ? pg_add_node(b, name, parent) : NULL;
    if (!n)
        return APP_ERR_OUT_OF_MEMORY;
    placement_matrix(o, n->matrix);
    n->parts = kept->meshes;
    n->part_count = kept->mesh_count;
    account(b, n->parts, n->part_count, n->matrix);
    b->stats->object_count++;
    return APP_OK;
}
