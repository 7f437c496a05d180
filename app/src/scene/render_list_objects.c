/* Project objects -> render list items: primitives share one unit mesh per shape; a glTF/GLB
 * model is loaded through the catalog and listed part by part. */
#include "render_list_internal.h"

#include "catalog/mesh_lod.h"
#include "model_materials.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

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

/* The group of object `index`: objects sharing a group name get the id of the first of them
 * (+1); a model's parts share their object's id; 0 = alone. */
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

/* The probe settings of an object's material (RENDERING.md section 8); *map gets its static
 * map's index (-1 = none, -2 = out of memory). */
static rd_probe_desc probe_of(app_list_builder *b, const app_material *am, int *map)
{
    *map = am->probe_update == APP_PROBE_STATIC ? app_list_probe_map(b, am) : -1;
    if (*map == -1 && am->probe_update == APP_PROBE_STATIC)
        *map = -2;
    return (rd_probe_desc){.update = am->probe_update == APP_PROBE_STATIC
                                         ? RD_PROBE_STATIC
                                         : (rd_probe_update)am->probe_update,
                           .every_n = am->probe_every,
                           .resolution = am->probe_resolution,
                           .proxy_radius_m = am->proxy_radius_mm * 1e-3f};
}

/* The unit mesh of a shape; coarse = 1: the low-detail version drawn in probe captures (a
 * quarter of the segments). The index of its mesh, -1 when it cannot be made. */
static int unit_mesh(app_list_builder *b, app_shape shape, float torus_ratio, int coarse)
{
    if (shape != APP_SHAPE_TORUS && b->unit_mesh[coarse][shape])
        return b->unit_mesh[coarse][shape] - 1;
    app_render_list_store *s = b->list->store;
    if (!app_list_grow((void **)&s->units, &s->unit_capacity, s->unit_count + 1, sizeof *s->units))
        return -1;
    int seg = coarse ? 16 : 64;
    rd_mesh_data *d = &s->units[s->unit_count];
    rd_result r;
    switch (shape) {
    case APP_SHAPE_BOX:
        r = rd_mesh_data_box(d);
        break;
    case APP_SHAPE_SPHERE:
        r = rd_mesh_data_sphere(seg, seg / 2, d);
        break;
    case APP_SHAPE_CYLINDER:
        r = rd_mesh_data_cylinder(seg, d);
        break;
    case APP_SHAPE_PLANE:
        r = rd_mesh_data_plane(d);
        break;
    default:
        r = rd_mesh_data_torus(torus_ratio, seg, coarse ? 8 : 24, d);
        break;
    }
    if (r != RD_OK)
        return -1;
    s->unit_count++;
    int mesh = app_list_add_mesh(b, d->positions, d->normals, d->uvs, d->indices, d->vertex_count,
                                 d->index_count);
    if (mesh >= 0 && shape != APP_SHAPE_TORUS)
        b->unit_mesh[coarse][shape] = mesh + 1;
    return mesh;
}

/* The renderers' name of the unit shape (a lamp of one is reflected exactly: emitters.c). */
static rd_shape shape_of(app_shape s)
{
    return s == APP_SHAPE_BOX        ? RD_SHAPE_BOX
           : s == APP_SHAPE_SPHERE   ? RD_SHAPE_SPHERE
           : s == APP_SHAPE_CYLINDER ? RD_SHAPE_CYLINDER
           : s == APP_SHAPE_PLANE    ? RD_SHAPE_PLANE
                                     : RD_SHAPE_MESH;
}

static app_result add_primitive(app_list_builder *b, const app_project *p, int index,
                                const rd_material *m, int texture, char *err, size_t err_size)
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
    int curved = o->shape == APP_SHAPE_SPHERE || o->shape == APP_SHAPE_CYLINDER ||
                 o->shape == APP_SHAPE_TORUS;
    int mesh = unit_mesh(b, o->shape, ratio, 0), coarse = -1;
    if (mesh >= 0 && curved && (b->flags & APP_RENDER_LIST_PROBE_MESHES))
        coarse = unit_mesh(b, o->shape, ratio, 1);
    if (mesh < 0 || (curved && (b->flags & APP_RENDER_LIST_PROBE_MESHES) && coarse < 0)) {
        snprintf(err, err_size, "%s: $.objects[%d] (\"%s\"): cannot make its mesh: %s", p->path,
                 index, o->name, rd_last_error());
        return APP_ERR_SCHEMA;
    }
    char label[sizeof o->name + 32];
    snprintf(label, sizeof label, "$.objects[%d] (\"%s\")", index, o->name);
    app_render_item *it = app_list_add_item(b, mesh, label);
    if (!it)
        return APP_ERR_OUT_OF_MEMORY;
    const app_material *am = &p->materials[o->material];
    it->probe = probe_of(b, am, &it->probe_map);
    if (it->probe_map == -2)
        return APP_ERR_OUT_OF_MEMORY;
    it->object = index;
    it->probe_mesh = coarse;
    it->shape = shape_of(o->shape);
    it->material = *m;
    it->texture = texture;
    /* Closed shapes cull their back faces; a plane is a sheet seen from either side. */
    it->double_sided = o->shape == APP_SHAPE_PLANE;
    it->group = group_of(p, index);
    /* Unit-mesh UVs span the whole object: repeat the texture at its real-world size. A plane
     * maps u, v to its x, y; the other shapes wrap u around and run v along the height. */
    if (am->texture[0]) {
        double u_mm = o->size_mm[0] * o->scale[0];
        double v_mm =
            o->shape == APP_SHAPE_PLANE ? o->size_mm[1] * o->scale[1] : o->size_mm[2] * o->scale[2];
        if (curved)
            u_mm *= 3.14159265358979323846;
        it->material.uv_scale[0] = (float)(u_mm / am->texture_size_mm[0]);
        it->material.uv_scale[1] = (float)(v_mm / am->texture_size_mm[1]);
    }
    app_object_transform(o, size_m, it->transform);
    return APP_OK;
}

/* Models with at least this many triangles get a probe-capture copy at this fraction. */
#define LOD_MIN_TRIANGLES 1500
#define LOD_FRACTION 0.25f

/* Decimated copies for the life of the process, by model file: the planner rebuilds its scene
 * after every edit, and decimating a detailed model costs more than loading it. A file is known
 * by its path, size and modification time, so one rewritten on disk is decimated again. Scenes
 * are built on one thread. */
enum { LOD_CACHE_SIZE = 64 };
static struct lod_cache_entry {
    char path[sizeof((app_object *)0)->model];
    off_t size;
    struct timespec mtime;
    cat_model lod;
} lod_cache[LOD_CACHE_SIZE];
static int lod_cache_count;

static struct lod_cache_entry *lod_cache_find(const char *path, const struct stat *st)
{
    for (int i = 0; i < lod_cache_count; i++) {
        struct lod_cache_entry *e = &lod_cache[i];
        if (e->size == st->st_size && e->mtime.tv_sec == st->st_mtim.tv_sec &&
            e->mtime.tv_nsec == st->st_mtim.tv_nsec && !strcmp(e->path, path))
            return e;
    }
    return NULL;
}

/* The level of detail of m into *l, from the cache when it holds the file; st: the file as it
 * was before m was loaded from it (known 0: not cached). */
static cat_result make_lod(const char *path, int known, const struct stat *st, const cat_model *m,
                           cat_model *l)
{
    char lerr[256];
    known = known && strlen(path) < sizeof lod_cache[0].path;
    struct lod_cache_entry *e = known ? lod_cache_find(path, st) : NULL;
    if (e) /* fraction 1 copies */
        return cat_model_make_lod(&e->lod, 1.0f, l, lerr, sizeof lerr);
    cat_result r = cat_model_make_lod(m, LOD_FRACTION, l, lerr, sizeof lerr);
    if (r == CAT_OK && known && lod_cache_count < LOD_CACHE_SIZE) {
        e = &lod_cache[lod_cache_count];
        if (cat_model_make_lod(l, 1.0f, &e->lod, lerr, sizeof lerr) == CAT_OK) {
            snprintf(e->path, sizeof e->path, "%s", path);
            e->size = st->st_size;
            e->mtime = st->st_mtim;
            lod_cache_count++;
        }
    }
    return r;
}

/* The model's file loaded into the store (and, with probe meshes asked for, its decimated
 * copy: RENDERING.md section 8 lets probes draw lower-detail geometry; catalog/mesh_lod.h). A
 * model that cannot be decimated is captured as it is (*lod NULL). */
static app_result load_model(app_list_builder *b, const app_project *p, int index,
                             const cat_model **model, const cat_model **lod, char *err,
                             size_t err_size)
{
    app_render_list_store *s = b->list->store;
    if (!app_list_grow((void **)&s->models, &s->model_capacity, s->model_count + 2,
                       sizeof *s->models))
        return APP_ERR_OUT_OF_MEMORY;
    cat_model *m = &s->models[s->model_count], *l = &s->models[s->model_count + 1];
    char cerr[768];
    struct stat st;
    int known = stat(p->objects[index].model, &st) == 0;
    if (cat_model_load(p->objects[index].model, m, cerr, sizeof cerr) != CAT_OK) {
        snprintf(err, err_size, "%s: $.objects[%d].model: %s", p->path, index, cerr);
        return APP_ERR_IO;
    }
    s->model_count++;
    *model = m;
    *lod = NULL;
    memset(l, 0, sizeof *l);
    if (!(b->flags & APP_RENDER_LIST_PROBE_MESHES) ||
        cat_model_triangle_count(m) < LOD_MIN_TRIANGLES)
        return APP_OK;
    if (make_lod(p->objects[index].model, known, &st, m, l) != CAT_OK) {
        cat_model_free(l);
        return APP_OK;
    }
    s->model_count++;
    if (l->mesh_count == m->mesh_count)
        *lod = l;
    return APP_OK;
}

static int add_model_mesh(app_list_builder *b, const cat_mesh *cm)
{
    return app_list_add_mesh(b, cm->positions, cm->normals, cm->uvs, cm->indices, cm->vertex_count,
                             cm->index_count);
}

static app_result add_model(app_list_builder *b, const app_project *p, int index,
                            const rd_material *m, int texture, char *err, size_t err_size)
{
    const app_object *o = &p->objects[index];
    const cat_model *model, *lod;
    app_result r = load_model(b, p, index, &model, &lod, err, err_size);
    if (r != APP_OK)
        return r;
    app_model_materials parts;
    if (!app_model_materials_read(o->model, model, &parts)) {
        snprintf(err, err_size, "%s: $.objects[%d].model: out of memory", p->path, index);
        return APP_ERR_OUT_OF_MEMORY;
    }
    const double mm_to_m[3] = {1e-3, 1e-3, 1e-3};
    float transform[16];
    app_object_transform(o, mm_to_m, transform);
    int probe_map;
    rd_probe_desc probe = probe_of(b, &p->materials[o->material], &probe_map);
    r = probe_map == -2 ? APP_ERR_OUT_OF_MEMORY : APP_OK;
    for (int i = 0; r == APP_OK && i < model->mesh_count; i++) {
        const cat_mesh *cm = &model->meshes[i];
        char label[sizeof o->model + 64];
        snprintf(label, sizeof label, "$.objects[%d].model: %s: part %d", index, o->model, i);
        int mesh = add_model_mesh(b, cm);
        int coarse =
            lod && lod->meshes[i].index_count >= 3 ? add_model_mesh(b, &lod->meshes[i]) : -1;
        app_render_item *it = mesh >= 0 ? app_list_add_item(b, mesh, label) : NULL;
        if (!it) {
            r = APP_ERR_OUT_OF_MEMORY;
            break;
        }
        it->object = index;
        it->probe_mesh = coarse;
        it->probe = probe;
        it->probe_map = probe_map;
        /* A model may be open (glTF's doubleSided): both sides drawn. */
        it->double_sided = 1;
        it->group = group_of(p, index); /* one probe for the model */
        /* A fixed part keeps its own finish (model_materials.h), untextured. */
        int fixed = app_model_part_material(&parts, cm, &it->material);
        if (!fixed)
            it->material = *m;
        it->texture = fixed ? -1 : texture;
        memcpy(it->transform, transform, sizeof transform);
    }
    app_model_materials_free(&parts);
    return r;
}

app_result app_list_add_objects(app_list_builder *b, const app_project *p, char *err,
                                size_t err_size)
{
    app_render_list *l = b->list;
    l->object_count = p->object_count;
    l->object_offsets_mm =
        calloc((size_t)(p->object_count ? p->object_count : 1), sizeof *l->object_offsets_mm);
    if (!l->object_offsets_mm)
        return APP_ERR_OUT_OF_MEMORY;
    for (int i = 0; i < p->object_count; i++) {
        const app_object *o = &p->objects[i];
        for (int k = 0; k < 3; k++)
            l->object_offsets_mm[i][k] = o->position_mm[k] - b->document->objects[i].position_mm[k];
        if (APP_OBJECT_UNRESOLVED(o))
            continue; /* a product without a size: warned about in scene_products.c */
        rd_material m;
        int texture;
        app_result r = app_list_material(b, &p->materials[o->material], &m, &texture);
        if (r == APP_OK)
            r = o->shape == APP_SHAPE_MODEL ? add_model(b, p, i, &m, texture, err, err_size)
                                            : add_primitive(b, p, i, &m, texture, err, err_size);
        if (r != APP_OK)
            return r;
    }
    return APP_OK;
}
