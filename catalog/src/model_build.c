/* Baking a parsed glTF document into a cat_model: the scene walk, node transforms, primitive
 * assembly, normals, materials and bounds. Everything read from the document is checked here
 * before it is used; tinygltf only parsed the JSON and loaded the buffers. */
#include "model_internal.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Deepest node hierarchy walked; real files stay far below it. It bounds the walk's stack. */
#define MAX_NODE_DEPTH 1024

/* Largest magnitude accepted for a material factor (they are 0..1 by the spec, emissive can be
 * brighter with extensions); it keeps the conversion to float defined. */
#define MAX_FACTOR 1.0e6

/* glTF's Y-up metres to Tessera's Z-up millimetres, (x, y, z) -> (x, -z, y) * 1000, as a
 * column-major matrix. A rotation times 1000: determinant > 0, winding is kept. */
static const double yup_m_to_zup_mm[16] = {1000, 0,     0, 0, 0, 0, 1000, 0,
                                           0,    -1000, 0, 0, 0, 0, 0,    1};

/* Extensions a file may require: those whose data this loader reads correctly. */
static const char *const supported_required_extensions[] = {"KHR_mesh_quantization"};

typedef struct builder {
    const cat_msg *msg;
    const cat_gltf_doc *doc;
    const char *folder;
    cat_model *out;
    int mesh_capacity;
    long long vertices, indices, instances;
    int have_bounds;
} builder;

typedef struct frame {
    int node, next_child;
    double world[16];
} frame;

static cat_result check_extensions(builder *b)
{
    for (int i = 0; i < b->doc->extensions_required_count; i++) {
        const char *name = b->doc->extensions_required[i] ? b->doc->extensions_required[i] : "";
        int ok = 0;
        for (size_t k = 0;
             k < sizeof supported_required_extensions / sizeof supported_required_extensions[0];
             k++)
            ok |= strcmp(name, supported_required_extensions[k]) == 0;
        if (!ok)
            return cat_fail(b->msg, CAT_ERR_UNSUPPORTED,
                            "the file requires extension \"%.200s\", which is not supported", name);
    }
    return CAT_OK;
}

/* Copies a name, cut to fit at a UTF-8 character boundary. */
static void copy_name(char *dst, size_t size, const char *src)
{
    size_t n = src ? strlen(src) : 0;
    if (n >= size) {
        n = size - 1;
        while (n > 0 && ((unsigned char)src[n] & 0xC0) == 0x80)
            n--;
    }
    if (n)
        memcpy(dst, src, n);
    dst[n] = '\0';
}

static cat_result read_factors(builder *b, int material, const char *what, const double *src,
                               int count, int expected, float *dst)
{
    if (count == 0)
        return CAT_OK; /* keep the default */
    if (count != expected)
        return cat_fail(b->msg, CAT_ERR_INVALID, "material %d: %s has %d numbers, expected %d",
                        material, what, count, expected);
    for (int k = 0; k < count; k++) {
        if (!isfinite(src[k]) || fabs(src[k]) > MAX_FACTOR)
            return cat_fail(b->msg, CAT_ERR_INVALID, "material %d: %s has an invalid number",
                            material, what);
        dst[k] = (float)src[k];
    }
    return CAT_OK;
}

static cat_result build_materials(builder *b)
{
    const cat_gltf_doc *doc = b->doc;
    char path[sizeof b->out->materials[0].base_color_texture];
    char what[64];
    for (int i = 0; i < doc->image_count; i++) {
        const char *uri = doc->images[i].uri;
        if (!uri || !uri[0])
            continue; /* embedded */
        snprintf(what, sizeof what, "image %d", i);
        cat_result r = cat_uri_resolve(b->msg, what, b->folder, uri, 1, path, sizeof path);
        if (r != CAT_OK)
            return r;
    }
    if (doc->material_count <= 0)
        return CAT_OK;
    b->out->materials = calloc((size_t)doc->material_count, sizeof *b->out->materials);
    if (!b->out->materials)
        return cat_fail(b->msg, CAT_ERR_OUT_OF_MEMORY, "out of memory for %d materials",
                        doc->material_count);
    b->out->material_count = doc->material_count;
    for (int i = 0; i < doc->material_count; i++) {
        const cat_gltf_material *m = &doc->materials[i];
        cat_material *cm = &b->out->materials[i];
        copy_name(cm->name, sizeof cm->name, m->name);
        for (int k = 0; k < 4; k++)
            cm->base_color[k] = 1.0f;
        cm->metallic = 1.0f;
        cm->roughness = 1.0f;
        double mr[2] = {m->metallic, m->roughness};
        float mrf[2] = {1.0f, 1.0f};
        cat_result r = read_factors(b, i, "baseColorFactor", m->base_color, m->base_color_count, 4,
                                    cm->base_color);
        if (r == CAT_OK)
            r = read_factors(b, i, "emissiveFactor", m->emissive, m->emissive_count, 3,
                             cm->emissive);
        if (r == CAT_OK)
            r = read_factors(b, i, "metallicFactor and roughnessFactor", mr, 2, 2, mrf);
        if (r != CAT_OK)
            return r;
        cm->metallic = mrf[0];
        cm->roughness = mrf[1];
        int t = m->base_color_texture;
        if (t < 0)
            continue;
        if (t >= doc->texture_count)
            return cat_fail(b->msg, CAT_ERR_INVALID,
                            "material %d: base colour texture %d does not exist", i, t);
        int image = doc->textures[t].source;
        if (image < 0)
            continue; /* the image is given by an extension (e.g. KHR_texture_basisu) */
        if (image >= doc->image_count)
            return cat_fail(b->msg, CAT_ERR_INVALID, "texture %d: image %d does not exist", t,
                            image);
        const char *uri = doc->images[image].uri;
        if (!uri || !uri[0])
            continue; /* embedded */
        snprintf(what, sizeof what, "image %d", image);
        r = cat_uri_resolve(b->msg, what, b->folder, uri, 1, cm->base_color_texture,
                            sizeof cm->base_color_texture);
        if (r != CAT_OK)
            return r;
    }
    return CAT_OK;
}

static int all_finite(const double *v, int n)
{
    for (int k = 0; k < n; k++)
        if (!isfinite(v[k]))
            return 0;
    return 1;
}

static cat_result local_matrix(builder *b, int index, double out[16])
{
    const cat_gltf_node *n = &b->doc->nodes[index];
    if (n->matrix_count) {
        if (n->matrix_count != 16 || !n->matrix)
            return cat_fail(b->msg, CAT_ERR_INVALID, "node %d: matrix has %d numbers, expected 16",
                            index, n->matrix_count);
        if (!all_finite(n->matrix, 16))
            return cat_fail(b->msg, CAT_ERR_INVALID, "node %d: matrix has a non-finite number",
                            index);
        memcpy(out, n->matrix, 16 * sizeof out[0]);
        if (fabs(out[3]) > 1e-6 || fabs(out[7]) > 1e-6 || fabs(out[11]) > 1e-6 ||
            fabs(out[15] - 1.0) > 1e-6)
            return cat_fail(b->msg, CAT_ERR_UNSUPPORTED,
                            "node %d: matrix is projective (its last row is not 0 0 0 1)", index);
        out[3] = out[7] = out[11] = 0.0;
        out[15] = 1.0;
        return CAT_OK;
    }
    double t[3] = {0, 0, 0}, q[4] = {0, 0, 0, 1}, s[3] = {1, 1, 1};
    struct {
        const char *name;
        const double *src;
        int count, expected;
        double *dst;
    } parts[3] = {{"translation", n->translation, n->translation_count, 3, t},
                  {"rotation", n->rotation, n->rotation_count, 4, q},
                  {"scale", n->scale, n->scale_count, 3, s}};
    for (int p = 0; p < 3; p++) {
        if (parts[p].count == 0)
            continue;
        if (parts[p].count != parts[p].expected || !parts[p].src)
            return cat_fail(b->msg, CAT_ERR_INVALID, "node %d: %s has %d numbers, expected %d",
                            index, parts[p].name, parts[p].count, parts[p].expected);
        if (!all_finite(parts[p].src, parts[p].count))
            return cat_fail(b->msg, CAT_ERR_INVALID, "node %d: %s has a non-finite number", index,
                            parts[p].name);
        memcpy(parts[p].dst, parts[p].src, (size_t)parts[p].count * sizeof(double));
    }
    double qlen = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(qlen > 1e-12) || !isfinite(qlen))
        return cat_fail(b->msg, CAT_ERR_INVALID,
                        "node %d: rotation quaternion has zero or non-finite length", index);
    cat_mat4_from_trs(t, q, s, out);
    return CAT_OK;
}

static cat_result append_mesh(builder *b, cat_mesh **mesh)
{
    cat_model *out = b->out;
    if (out->mesh_count == b->mesh_capacity) {
        int cap = b->mesh_capacity ? b->mesh_capacity * 2 : 16;
        if (cap > CAT_MODEL_MAX_MESHES)
            cap = CAT_MODEL_MAX_MESHES;
        cat_mesh *grown = realloc(out->meshes, (size_t)cap * sizeof *grown);
        if (!grown)
            return cat_fail(b->msg, CAT_ERR_OUT_OF_MEMORY, "out of memory for %d meshes", cap);
        out->meshes = grown;
        b->mesh_capacity = cap;
    }
    *mesh = &out->meshes[out->mesh_count++];
    memset(*mesh, 0, sizeof **mesh);
    return CAT_OK;
}

static void grow_bounds(builder *b, const float p[3])
{
    cat_model *out = b->out;
    if (!b->have_bounds) {
        memcpy(out->bounds_min, p, 3 * sizeof p[0]);
        memcpy(out->bounds_max, p, 3 * sizeof p[0]);
        b->have_bounds = 1;
        return;
    }
    for (int k = 0; k < 3; k++) {
        if (p[k] < out->bounds_min[k])
            out->bounds_min[k] = p[k];
        if (p[k] > out->bounds_max[k])
            out->bounds_max[k] = p[k];
    }
}

/* Corner k (0..2) of triangle t of a primitive, as a position in its index list. Strips and
 * fans are converted to triangle lists (glTF 2.0, section 3.7.2.1 "Topology Types"). */
static size_t corner(int mode, size_t t, int k)
{
    switch (mode) {
    case CAT_GLTF_TRIANGLE_STRIP:
        return k == 0 ? t : k == 1 ? t + 1 + t % 2 : t + 2 - t % 2;
    case CAT_GLTF_TRIANGLE_FAN:
        return k == 0 ? t + 1 : k == 1 ? t + 2 : 0;
    default:
        return 3 * t + (size_t)k;
    }
}

typedef struct prim_attributes {
    int position, normal, uv;
} prim_attributes;

static cat_result check_primitive(builder *b, const char *where, const cat_gltf_primitive *p,
                                  prim_attributes *at, size_t *list_length, size_t *triangles)
{
    const cat_gltf_doc *doc = b->doc;
    at->position = at->normal = at->uv = -1;
    for (int i = 0; i < p->attribute_count; i++) {
        const char *name = p->attributes[i].name ? p->attributes[i].name : "";
        if (strcmp(name, "POSITION") == 0)
            at->position = p->attributes[i].accessor;
        else if (strcmp(name, "NORMAL") == 0)
            at->normal = p->attributes[i].accessor;
        else if (strcmp(name, "TEXCOORD_0") == 0)
            at->uv = p->attributes[i].accessor;
    }
    if (at->position < 0)
        return cat_fail(b->msg, CAT_ERR_INVALID, "%sno POSITION attribute", where);
    cat_result r = cat_accessor_check(b->msg, where, doc, at->position, 3);
    if (r != CAT_OK)
        return r;
    size_t count = doc->accessors[at->position].count;
    if (count > (size_t)CAT_MODEL_MAX_PRIMITIVE_VERTICES)
        return cat_fail(b->msg, CAT_ERR_TOO_LARGE, "%s%zu vertices, the limit per primitive is %d",
                        where, count, CAT_MODEL_MAX_PRIMITIVE_VERTICES);
    if (b->vertices + (long long)count > CAT_MODEL_MAX_TOTAL_VERTICES)
        return cat_fail(b->msg, CAT_ERR_TOO_LARGE, "%sthe model has more than %d vertices in all",
                        where, CAT_MODEL_MAX_TOTAL_VERTICES);
    int extra[2] = {at->normal, at->uv};
    const char *extra_name[2] = {"NORMAL", "TEXCOORD_0"};
    for (int k = 0; k < 2; k++) {
        if (extra[k] < 0)
            continue;
        r = cat_accessor_check(b->msg, where, doc, extra[k], k == 0 ? 3 : 2);
        if (r != CAT_OK)
            return r;
        if (doc->accessors[extra[k]].count != count)
            return cat_fail(b->msg, CAT_ERR_INVALID,
                            "%s%s accessor %d has %zu elements, POSITION has %zu", where,
                            extra_name[k], extra[k], doc->accessors[extra[k]].count, count);
    }
    if (p->material < -1 || p->material >= doc->material_count)
        return cat_fail(b->msg, CAT_ERR_INVALID, "%smaterial %d does not exist", where,
                        p->material);
    *list_length = count;
    if (p->indices >= 0) {
        r = cat_accessor_check(b->msg, where, doc, p->indices, 1);
        if (r != CAT_OK)
            return r;
        *list_length = doc->accessors[p->indices].count;
        if (*list_length > (size_t)CAT_MODEL_MAX_PRIMITIVE_INDICES)
            return cat_fail(b->msg, CAT_ERR_TOO_LARGE,
                            "%s%zu indices, the limit per primitive is %d", where, *list_length,
                            CAT_MODEL_MAX_PRIMITIVE_INDICES);
    }
    if (p->mode == CAT_GLTF_TRIANGLES) {
        if (*list_length % 3 != 0)
            return cat_fail(b->msg, CAT_ERR_INVALID, "%s%zu %s do not make whole triangles", where,
                            *list_length, p->indices >= 0 ? "indices" : "vertices");
        *triangles = *list_length / 3;
    } else {
        *triangles = *list_length < 3 ? 0 : *list_length - 2;
    }
    if (*triangles > (size_t)CAT_MODEL_MAX_PRIMITIVE_INDICES / 3)
        return cat_fail(b->msg, CAT_ERR_TOO_LARGE, "%s%zu triangles, the limit per primitive is %d",
                        where, *triangles, CAT_MODEL_MAX_PRIMITIVE_INDICES / 3);
    if (b->indices + 3 * (long long)*triangles > CAT_MODEL_MAX_TOTAL_INDICES)
        return cat_fail(b->msg, CAT_ERR_TOO_LARGE, "%sthe model has more than %d indices in all",
                        where, CAT_MODEL_MAX_TOTAL_INDICES);
    return CAT_OK;
}

/* Positions: read, refuse NaN/Inf, transform by f, refuse what leaves the float range. */
static cat_result bake_positions(builder *b, const char *where, int node, int accessor,
                                 const double f[16], cat_mesh *m)
{
    cat_result r = cat_accessor_read_floats(b->msg, where, b->doc, accessor, 3, m->positions);
    if (r != CAT_OK)
        return r;
    for (int v = 0; v < m->vertex_count; v++) {
        float *p = m->positions + 3 * (size_t)v;
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
            return cat_fail(b->msg, CAT_ERR_INVALID,
                            "%sPOSITION accessor %d: vertex %d is not a finite number (NaN or Inf)",
                            where, accessor, v);
        double x = p[0], y = p[1], z = p[2];
        for (int k = 0; k < 3; k++) {
            double d = f[k] * x + f[4 + k] * y + f[8 + k] * z + f[12 + k];
            if (!isfinite(d) || fabs(d) > FLT_MAX)
                return cat_fail(b->msg, CAT_ERR_INVALID,
                                "%svertex %d under node %d lies outside the float range", where, v,
                                node);
            p[k] = (float)d;
        }
    }
    for (int v = 0; v < m->vertex_count; v++)
        grow_bounds(b, m->positions + 3 * (size_t)v);
    return CAT_OK;
}

/* Normals: the file's, by the inverse transpose (cofactor matrix, sign-corrected), or generated
 * where the file has none or gives a vector that does not survive the transform. */
static cat_result bake_normals(builder *b, const char *where, int accessor, const double f[16],
                               double det, cat_mesh *m)
{
    unsigned char *bad = NULL;
    if (accessor >= 0) {
        cat_result r = cat_accessor_read_floats(b->msg, where, b->doc, accessor, 3, m->normals);
        if (r != CAT_OK)
            return r;
        double cof[9];
        cat_mat3_cofactor(f, cof);
        double sign = det < 0 ? -1.0 : 1.0;
        int any_bad = 0;
        bad = calloc((size_t)m->vertex_count, 1);
        if (!bad)
            return cat_fail(b->msg, CAT_ERR_OUT_OF_MEMORY, "%sout of memory", where);
        for (int v = 0; v < m->vertex_count; v++) {
            float *n = m->normals + 3 * (size_t)v;
            double t[3];
            for (int k = 0; k < 3; k++)
                t[k] = sign * (cof[k * 3] * n[0] + cof[k * 3 + 1] * n[1] + cof[k * 3 + 2] * n[2]);
            double len = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
            if (isfinite(len) && len > 1e-30) {
                for (int k = 0; k < 3; k++)
                    n[k] = (float)(t[k] / len);
            } else {
                bad[v] = 1;
                any_bad = 1;
            }
        }
        if (!any_bad) {
            free(bad);
            return CAT_OK;
        }
    }
    int ok = cat_normals_generate(m->positions, m->vertex_count, m->indices, m->index_count, bad,
                                  m->normals);
    free(bad);
    if (!ok)
        return cat_fail(b->msg, CAT_ERR_OUT_OF_MEMORY, "%sout of memory generating normals", where);
    return CAT_OK;
}

static cat_result bake_primitive(builder *b, int node, int mesh, int prim, const double world[16])
{
    const cat_gltf_doc *doc = b->doc;
    const cat_gltf_primitive *p = &doc->meshes[mesh].primitives[prim];
    char where[96];
    snprintf(where, sizeof where, "mesh %d primitive %d: ", mesh, prim);
    if (++b->instances > CAT_MODEL_MAX_MESHES)
        return cat_fail(b->msg, CAT_ERR_TOO_LARGE, "the scene places more than %d primitives",
                        CAT_MODEL_MAX_MESHES);
    /* Points and lines are not surfaces: skipped without error. */
    if (p->mode >= CAT_GLTF_POINTS && p->mode <= CAT_GLTF_LINE_STRIP)
        return CAT_OK;
    if (p->mode < 0 || p->mode > CAT_GLTF_TRIANGLE_FAN)
        return cat_fail(b->msg, CAT_ERR_INVALID, "%sunknown primitive mode %d", where, p->mode);
    prim_attributes at;
    size_t list_length = 0, triangles = 0;
    cat_result r = check_primitive(b, where, p, &at, &list_length, &triangles);
    if (r != CAT_OK)
        return r;
    double det = cat_mat3_det(world);
    if (isnan(det))
        return cat_fail(b->msg, CAT_ERR_INVALID, "node %d: transform is out of range", node);
    if (triangles == 0 || det == 0.0)
        return CAT_OK; /* nothing to draw, or flattened by a zero scale */

    double f[16];
    cat_mat4_mul(yup_m_to_zup_mm, world, f);
    cat_mesh *m = NULL;
    r = append_mesh(b, &m);
    if (r != CAT_OK)
        return r;
    int vc = (int)doc->accessors[at.position].count;
    m->material = p->material;
    m->vertex_count = vc;
    m->index_count = (int)(3 * triangles);
    m->positions = malloc(3 * (size_t)vc * sizeof(float));
    m->normals = malloc(3 * (size_t)vc * sizeof(float));
    m->indices = malloc(3 * triangles * sizeof(unsigned));
    if (at.uv >= 0)
        m->uvs = malloc(2 * (size_t)vc * sizeof(float));
    unsigned *list = p->indices >= 0 ? malloc(list_length * sizeof(unsigned)) : NULL;
    if (!m->positions || !m->normals || !m->indices || (at.uv >= 0 && !m->uvs) ||
        (p->indices >= 0 && !list)) {
        free(list);
        return cat_fail(b->msg, CAT_ERR_OUT_OF_MEMORY, "%sout of memory for %d vertices", where,
                        vc);
    }
    r = bake_positions(b, where, node, at.position, f, m);
    if (r == CAT_OK && list) {
        r = cat_accessor_read_indices(b->msg, where, doc, p->indices, list);
        for (size_t i = 0; r == CAT_OK && i < list_length; i++)
            if (list[i] >= (unsigned)vc)
                r = cat_fail(b->msg, CAT_ERR_INVALID,
                             "%sindex %u (element %zu of accessor %d) is out of range: POSITION "
                             "has %d vertices",
                             where, list[i], i, p->indices, vc);
    }
    if (r == CAT_OK) {
        /* A mirroring transform turns counter-clockwise into clockwise: swap two corners. */
        int flip = det < 0;
        for (size_t t = 0; t < triangles; t++)
            for (int k = 0; k < 3; k++) {
                int kk = flip && k > 0 ? 3 - k : k;
                size_t c = corner(p->mode, t, kk);
                m->indices[3 * t + (size_t)k] = list ? list[c] : (unsigned)c;
            }
    }
    free(list);
    if (r == CAT_OK)
        r = bake_normals(b, where, at.normal, f, det, m);
    if (r == CAT_OK && at.uv >= 0) {
        r = cat_accessor_read_floats(b->msg, where, doc, at.uv, 2, m->uvs);
        for (int v = 0; r == CAT_OK && v < vc; v++)
            if (!isfinite(m->uvs[2 * v]) || !isfinite(m->uvs[2 * v + 1]))
                r = cat_fail(b->msg, CAT_ERR_INVALID,
                             "%sTEXCOORD_0 accessor %d: vertex %d is not a finite number", where,
                             at.uv, v);
    }
    if (r == CAT_OK) {
        b->vertices += vc;
        b->indices += m->index_count;
    }
    return r;
}

/* Enters a node: its world matrix from the parent's, its primitives baked, a frame pushed. */
static cat_result enter(builder *b, unsigned char *seen, frame *stack, int *depth, int node,
                        const double parent[16])
{
    const cat_gltf_doc *doc = b->doc;
    if (node < 0 || node >= doc->node_count)
        return cat_fail(b->msg, CAT_ERR_INVALID, "node %d does not exist", node);
    if (seen[node])
        return cat_fail(b->msg, CAT_ERR_INVALID,
                        "node %d is reached twice; the node hierarchy must be a tree", node);
    if (*depth == MAX_NODE_DEPTH)
        return cat_fail(b->msg, CAT_ERR_TOO_LARGE, "node hierarchy deeper than %d levels",
                        MAX_NODE_DEPTH);
    seen[node] = 1;
    frame *fr = &stack[(*depth)++];
    fr->node = node;
    fr->next_child = 0;
    double local[16];
    cat_result r = local_matrix(b, node, local);
    if (r != CAT_OK)
        return r;
    cat_mat4_mul(parent, local, fr->world);
    if (!all_finite(fr->world, 16))
        return cat_fail(b->msg, CAT_ERR_INVALID, "node %d: the combined transform overflows", node);
    int mesh = doc->nodes[node].mesh;
    if (mesh < 0)
        return CAT_OK;
    if (mesh >= doc->mesh_count)
        return cat_fail(b->msg, CAT_ERR_INVALID, "node %d: mesh %d does not exist", node, mesh);
    for (int p = 0; p < doc->meshes[mesh].primitive_count; p++) {
        r = bake_primitive(b, node, mesh, p, fr->world);
        if (r != CAT_OK)
            return r;
    }
    return CAT_OK;
}

/* Depth-first, parents before children, children in file order; no recursion. */
static cat_result walk(builder *b, const int *roots, int root_count)
{
    const cat_gltf_doc *doc = b->doc;
    unsigned char *seen = calloc((size_t)doc->node_count + 1, 1);
    frame *stack = malloc(MAX_NODE_DEPTH * sizeof *stack);
    cat_result r = CAT_OK;
    if (!seen || !stack)
        r = cat_fail(b->msg, CAT_ERR_OUT_OF_MEMORY, "out of memory walking %d nodes",
                     doc->node_count);
    double identity[16];
    cat_mat4_identity(identity);
    for (int i = 0; r == CAT_OK && i < root_count; i++) {
        int depth = 0;
        r = enter(b, seen, stack, &depth, roots[i], identity);
        while (r == CAT_OK && depth > 0) {
            frame *top = &stack[depth - 1];
            const cat_gltf_node *n = &doc->nodes[top->node];
            if (top->next_child < n->child_count)
                r = enter(b, seen, stack, &depth, n->children[top->next_child++], top->world);
            else
                depth--;
        }
    }
    free(seen);
    free(stack);
    return r;
}

cat_result cat_model_build(const cat_msg *msg, const cat_gltf_doc *doc, const char *folder,
                           cat_model *out)
{
    builder b = {msg, doc, folder, out, 0, 0, 0, 0, 0};
    cat_result r = check_extensions(&b);
    if (r == CAT_OK)
        r = build_materials(&b);
    if (r != CAT_OK)
        return r;
    if (doc->scene_count > 0 || doc->default_scene >= 0) {
        int s = doc->default_scene >= 0 ? doc->default_scene : 0;
        if (s >= doc->scene_count)
            return cat_fail(msg, CAT_ERR_INVALID, "scene %d does not exist", s);
        r = walk(&b, doc->scenes[s].nodes, doc->scenes[s].node_count);
    } else {
        /* No scene: every node without a parent is a root. */
        int *roots = malloc(((size_t)doc->node_count + 1) * sizeof *roots);
        unsigned char *child = calloc((size_t)doc->node_count + 1, 1);
        int root_count = 0;
        if (!roots || !child)
            r = cat_fail(msg, CAT_ERR_OUT_OF_MEMORY, "out of memory for %d nodes", doc->node_count);
        for (int i = 0; r == CAT_OK && i < doc->node_count; i++)
            for (int k = 0; r == CAT_OK && k < doc->nodes[i].child_count; k++) {
                int c = doc->nodes[i].children[k];
                if (c < 0 || c >= doc->node_count)
                    r = cat_fail(msg, CAT_ERR_INVALID, "node %d: child %d does not exist", i, c);
                else
                    child[c] = 1;
            }
        for (int i = 0; r == CAT_OK && i < doc->node_count; i++)
            if (!child[i])
                roots[root_count++] = i;
        if (r == CAT_OK)
            r = walk(&b, roots, root_count);
        free(roots);
        free(child);
    }
    return r;
}
