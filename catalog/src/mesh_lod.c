/* Levels of detail (catalog/mesh_lod.h): weld, decimate with OpenMesh (mesh_openmesh.cpp),
 * then give each corner of the result the attributes of the input vertex that fits it. */
#include "catalog/mesh_lod.h"
#include "mesh_internal.h"
#include "model_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static cat_result lod_fail(char *err, size_t err_size, cat_result code, int mesh, const char *m)
{
    if (err && err_size)
        snprintf(err, err_size, "level of detail: mesh %d: %s", mesh, m);
    return code;
}

static int copy_mesh(const cat_mesh *in, cat_mesh *out)
{
    size_t nv = (size_t)in->vertex_count, ni = (size_t)in->index_count;
    out->vertex_count = in->vertex_count;
    out->index_count = in->index_count;
    out->material = in->material;
    out->positions = malloc(3 * nv * sizeof(float) + 1);
    out->normals = malloc(3 * nv * sizeof(float) + 1);
    out->indices = malloc(ni * sizeof(unsigned) + 1);
    out->uvs = in->uvs ? malloc(2 * nv * sizeof(float) + 1) : NULL;
    if (!out->positions || !out->normals || !out->indices || (in->uvs && !out->uvs))
        return 0;
    memcpy(out->positions, in->positions, 3 * nv * sizeof(float));
    memcpy(out->indices, in->indices, ni * sizeof(unsigned));
    if (in->uvs)
        memcpy(out->uvs, in->uvs, 2 * nv * sizeof(float));
    if (in->normals)
        memcpy(out->normals, in->normals, 3 * nv * sizeof(float));
    else if (!cat_normals_generate(out->positions, out->vertex_count, out->indices,
                                   out->index_count, NULL, out->normals))
        return 0;
    return 1;
}

static void face_normal(const float *p, const unsigned *c, double n[3])
{
    const float *A = p + 3 * (size_t)c[0], *B = p + 3 * (size_t)c[1], *C = p + 3 * (size_t)c[2];
    double e1[3] = {(double)B[0] - A[0], (double)B[1] - A[1], (double)B[2] - A[2]};
    double e2[3] = {(double)C[0] - A[0], (double)C[1] - A[1], (double)C[2] - A[2]};
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

typedef struct lod_work {
    int *map, *first, *offset, *members, *chosen_new;
    float *welded;
    unsigned *tris;
    cat_decimate_result dec;
} lod_work;

static void work_free(lod_work *w)
{
    free(w->map);
    free(w->first);
    free(w->offset);
    free(w->members);
    free(w->chosen_new);
    free(w->welded);
    free(w->tris);
    free(w->dec.triangles);
}

/* Decimates one valid mesh to about target triangles into *out. */
static cat_result lod_mesh(const cat_mesh *in, int index, int target, cat_mesh *out, char *err,
                           size_t err_size)
{
    lod_work w;
    memset(&w, 0, sizeof w);
    size_t nv = (size_t)in->vertex_count;
    int welded = 0, tri_count = 0;
    w.map = malloc((nv + 1) * sizeof *w.map);
    w.tris = malloc((size_t)in->index_count * sizeof *w.tris + 1);
    if (!w.map || !w.tris ||
        !cat_mesh_weld(in->positions, in->vertex_count, w.map, &w.first, &welded))
        goto oom;
    w.welded = malloc(3 * (size_t)welded * sizeof *w.welded + 1);
    w.offset = calloc((size_t)welded + 2, sizeof *w.offset);
    w.members = malloc((nv + 1) * sizeof *w.members);
    w.chosen_new = malloc((nv + 1) * sizeof *w.chosen_new);
    if (!w.welded || !w.offset || !w.members || !w.chosen_new)
        goto oom;
    for (int v = 0; v < welded; v++)
        memcpy(w.welded + 3 * (size_t)v, in->positions + 3 * (size_t)w.first[v], 3 * sizeof(float));
    /* the input vertices of each welded one, in index order (counting sort) */
    for (size_t v = 0; v < nv; v++)
        w.offset[w.map[v] + 1]++;
    for (int v = 0; v < welded; v++)
        w.offset[v + 1] += w.offset[v];
    for (size_t v = 0; v < nv; v++)
        w.members[w.offset[w.map[v]]++] = (int)v;
    for (int v = welded; v > 0; v--)
        w.offset[v] = w.offset[v - 1];
    w.offset[0] = 0;
    for (int t = 0; t < in->index_count / 3; t++) {
        const unsigned *c = in->indices + 3 * (size_t)t;
        unsigned a = (unsigned)w.map[c[0]], b = (unsigned)w.map[c[1]], d = (unsigned)w.map[c[2]];
        if (cat_triangle_degenerate(w.welded, a, b, d))
            continue; /* nothing to see; OpenMesh cannot hold it either */
        w.tris[3 * tri_count] = a;
        w.tris[3 * tri_count + 1] = b;
        w.tris[3 * tri_count + 2] = d;
        tri_count++;
    }
    char what[256] = "";
    if (cat_openmesh_decimate(w.welded, welded, w.tris, tri_count, target, &w.dec, what,
                              sizeof what)) {
        work_free(&w);
        return lod_fail(err, err_size, CAT_ERR_OUT_OF_MEMORY, index, what);
    }

    /* Each corner: the input vertex at that place whose normal is closest to the face's. */
    for (size_t v = 0; v < nv; v++)
        w.chosen_new[v] = -1;
    int out_vertices = 0;
    unsigned *corners = w.dec.triangles;
    for (int t = 0; t < w.dec.triangle_count; t++) {
        double n[3];
        face_normal(w.welded, corners + 3 * (size_t)t, n);
        for (int k = 0; k < 3; k++) {
            unsigned wv = corners[3 * (size_t)t + (size_t)k];
            int best = w.members[w.offset[wv]];
            double best_dot = -INFINITY;
            for (int j = w.offset[wv]; in->normals && j < w.offset[wv + 1]; j++) {
                const float *vn = in->normals + 3 * (size_t)w.members[j];
                double d = n[0] * vn[0] + n[1] * vn[1] + n[2] * vn[2];
                if (d > best_dot) {
                    best_dot = d;
                    best = w.members[j];
                }
            }
            if (w.chosen_new[best] < 0)
                w.chosen_new[best] = out_vertices++;
            corners[3 * (size_t)t + (size_t)k] = (unsigned)best; /* input numbering for now */
        }
    }
    out->material = in->material;
    out->vertex_count = out_vertices;
    out->index_count = 3 * w.dec.triangle_count;
    out->positions = malloc(3 * (size_t)out_vertices * sizeof(float) + 1);
    out->normals = malloc(3 * (size_t)out_vertices * sizeof(float) + 1);
    out->uvs = in->uvs ? malloc(2 * (size_t)out_vertices * sizeof(float) + 1) : NULL;
    out->indices = malloc((size_t)out->index_count * sizeof(unsigned) + 1);
    if (!out->positions || !out->normals || !out->indices || (in->uvs && !out->uvs))
        goto oom;
    for (size_t v = 0; v < nv; v++) {
        int o = w.chosen_new[v];
        if (o < 0)
            continue;
        memcpy(out->positions + 3 * (size_t)o, in->positions + 3 * v, 3 * sizeof(float));
        if (in->uvs)
            memcpy(out->uvs + 2 * (size_t)o, in->uvs + 2 * v, 2 * sizeof(float));
        if (in->normals)
            memcpy(out->normals + 3 * (size_t)o, in->normals + 3 * v, 3 * sizeof(float));
    }
    for (int i = 0; i < out->index_count; i++)
        out->indices[i] = (unsigned)w.chosen_new[corners[i]];
    if (!in->normals && !cat_normals_generate(out->positions, out->vertex_count, out->indices,
                                              out->index_count, NULL, out->normals))
        goto oom;
    work_free(&w);
    return CAT_OK;
oom:
    work_free(&w);
    return lod_fail(err, err_size, CAT_ERR_OUT_OF_MEMORY, index, "out of memory");
}

static void update_bounds(cat_model *m)
{
    int any = 0;
    for (int i = 0; i < m->mesh_count; i++) {
        const cat_mesh *me = &m->meshes[i];
        for (int t = 0; t < me->index_count; t++) {
            const float *p = me->positions + 3 * (size_t)me->indices[t];
            for (int k = 0; k < 3; k++) {
                if (!any || p[k] < m->bounds_min[k])
                    m->bounds_min[k] = p[k];
                if (!any || p[k] > m->bounds_max[k])
                    m->bounds_max[k] = p[k];
            }
            any = 1;
        }
    }
    if (!any)
        for (int k = 0; k < 3; k++)
            m->bounds_min[k] = m->bounds_max[k] = 0.0f;
}

cat_result cat_model_make_lod(const cat_model *in, float fraction, cat_model *out, char *err,
                              size_t err_size)
{
    if (err && err_size)
        err[0] = '\0';
    if (!out)
        return lod_fail(err, err_size, CAT_ERR_INVALID, 0, "no model to write into");
    memset(out, 0, sizeof *out);
    if (!in || in->mesh_count < 0 || (in->mesh_count && !in->meshes))
        return lod_fail(err, err_size, CAT_ERR_INVALID, 0, "no model to decimate");
    if (!(fraction > 0.0f && fraction <= 1.0f)) {
        if (err && err_size)
            snprintf(err, err_size, "level of detail: fraction %g is not in (0, 1]",
                     (double)fraction);
        return CAT_ERR_INVALID;
    }
    for (int i = 0; i < in->mesh_count; i++) {
        char what[64];
        snprintf(what, sizeof what, "level of detail: mesh %d", i);
        cat_result r = cat_mesh_validate(&in->meshes[i], what, NULL, err, err_size);
        if (r != CAT_OK)
            return r;
    }
    out->meshes = calloc((size_t)in->mesh_count + 1, sizeof *out->meshes);
    out->materials = malloc((size_t)in->material_count * sizeof *out->materials + 1);
    if (!out->meshes || !out->materials) {
        cat_model_free(out);
        return lod_fail(err, err_size, CAT_ERR_OUT_OF_MEMORY, 0, "out of memory");
    }
    out->mesh_count = in->mesh_count;
    out->material_count = in->material_count;
    if (in->material_count)
        memcpy(out->materials, in->materials, (size_t)in->material_count * sizeof *in->materials);
    for (int i = 0; i < in->mesh_count; i++) {
        const cat_mesh *m = &in->meshes[i];
        int tris = m->index_count / 3;
        int target = (int)ceil((double)fraction * tris);
        if (target < CAT_LOD_MIN_TRIANGLES)
            target = CAT_LOD_MIN_TRIANGLES;
        cat_result r = CAT_OK;
        if (target >= tris) {
            if (!copy_mesh(m, &out->meshes[i]))
                r = lod_fail(err, err_size, CAT_ERR_OUT_OF_MEMORY, i, "out of memory");
        } else {
            r = lod_mesh(m, i, target, &out->meshes[i], err, err_size);
        }
        if (r != CAT_OK) {
            cat_model_free(out);
            return r;
        }
    }
    update_bounds(out);
    return CAT_OK;
}
