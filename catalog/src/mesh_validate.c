/* Mesh validation (catalog/mesh_lod.h): refuse what no mesh may hold, count what a renderer
 * and a decimator trip over, and optionally drop degenerate triangles. */
#include "catalog/mesh_lod.h"
#include "mesh_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static cat_result fail(char *err, size_t err_size, cat_result code, const char *what,
                       const char *fmt, ...)
{
    if (err && err_size) {
        int n = snprintf(err, err_size, "%s: ", what ? what : "mesh");
        if (n >= 0 && (size_t)n < err_size) {
            va_list ap;
            va_start(ap, fmt);
            vsnprintf(err + n, err_size - (size_t)n, fmt, ap);
            va_end(ap);
        }
    }
    return code;
}

int cat_triangle_degenerate(const float *p, unsigned a, unsigned b, unsigned c)
{
    if (a == b || b == c || a == c)
        return 1;
    const float *A = p + 3 * (size_t)a, *B = p + 3 * (size_t)b, *C = p + 3 * (size_t)c;
    double e1[3] = {(double)B[0] - A[0], (double)B[1] - A[1], (double)B[2] - A[2]};
    double e2[3] = {(double)C[0] - A[0], (double)C[1] - A[1], (double)C[2] - A[2]};
    double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    double l1 = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    double l2 = sqrt(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]);
    double area2 = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return !(area2 > 1e-7 * l1 * l2);
}

static int by_key(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static int all_finite(const float *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

cat_result cat_mesh_validate(const cat_mesh *m, const char *what, cat_mesh_report *rep, char *err,
                             size_t err_size)
{
    if (!m || m->vertex_count < 0 || m->index_count < 0)
        return fail(err, err_size, CAT_ERR_INVALID, what, "no mesh, or a negative count");
    if (m->index_count % 3)
        return fail(err, err_size, CAT_ERR_INVALID, what, "%d indices do not make whole triangles",
                    m->index_count);
    if ((m->vertex_count && !m->positions) || (m->index_count && !m->indices))
        return fail(err, err_size, CAT_ERR_INVALID, what, "missing vertex or index data");
    size_t nv = (size_t)m->vertex_count;
    if (!all_finite(m->positions, 3 * nv))
        return fail(err, err_size, CAT_ERR_INVALID, what,
                    "a position is not a finite number (NaN or Inf)");
    if (m->normals && !all_finite(m->normals, 3 * nv))
        return fail(err, err_size, CAT_ERR_INVALID, what,
                    "a normal is not a finite number (NaN or Inf)");
    if (m->uvs && !all_finite(m->uvs, 2 * nv))
        return fail(err, err_size, CAT_ERR_INVALID, what,
                    "a texture coordinate is not a finite number (NaN or Inf)");
    for (int i = 0; i < m->index_count; i++)
        if (m->indices[i] >= (unsigned)m->vertex_count)
            return fail(err, err_size, CAT_ERR_INVALID, what,
                        "index %u (element %d) is out of range (%d vertices)", m->indices[i], i,
                        m->vertex_count);

    cat_mesh_report local;
    memset(&local, 0, sizeof local);
    int tris = m->index_count / 3;
    local.triangles = tris;
    int *map = malloc((nv + 1) * sizeof *map), *first = NULL, welded = 0;
    uint64_t *edges = malloc((3 * (size_t)tris + 1) * sizeof *edges);
    if (!map || !edges || !cat_mesh_weld(m->positions, m->vertex_count, map, &first, &welded)) {
        free(map);
        free(edges);
        return fail(err, err_size, CAT_ERR_OUT_OF_MEMORY, what, "out of memory");
    }
    size_t ne = 0;
    for (int t = 0; t < tris; t++) {
        const unsigned *c = m->indices + 3 * (size_t)t;
        if (cat_triangle_degenerate(m->positions, c[0], c[1], c[2])) {
            local.degenerate_triangles++;
            continue;
        }
        for (int k = 0; k < 3; k++) {
            uint64_t a = (uint64_t)map[c[k]], b = (uint64_t)map[c[(k + 1) % 3]];
            edges[ne++] = a < b ? a << 32 | b : b << 32 | a;
        }
    }
    qsort(edges, ne, sizeof *edges, by_key);
    for (size_t i = 0; i < ne;) {
        size_t j = i;
        while (j < ne && edges[j] == edges[i])
            j++;
        if (j - i == 1)
            local.open_edges++;
        else if (j - i > 2)
            local.non_manifold_edges++;
        i = j;
    }
    free(edges);
    free(first);
    free(map);
    if (rep) {
        rep->triangles += local.triangles;
        rep->degenerate_triangles += local.degenerate_triangles;
        rep->non_manifold_edges += local.non_manifold_edges;
        rep->open_edges += local.open_edges;
    }
    return CAT_OK;
}

cat_result cat_model_validate(cat_model *model, const char *what, int repair,
                              cat_mesh_report *report, char *err, size_t err_size)
{
    cat_mesh_report local;
    memset(&local, 0, sizeof local);
    if (!model || model->mesh_count < 0 || (model->mesh_count && !model->meshes))
        return fail(err, err_size, CAT_ERR_INVALID, what, "no model");
    for (int i = 0; i < model->mesh_count; i++) {
        char name[512];
        snprintf(name, sizeof name, "%s: mesh %d", what ? what : "model", i);
        cat_mesh *m = &model->meshes[i];
        cat_result r = cat_mesh_validate(m, name, &local, err, err_size);
        if (r != CAT_OK)
            return r;
        if (!repair)
            continue;
        int kept = 0;
        for (int t = 0; t < m->index_count / 3; t++) {
            const unsigned *c = m->indices + 3 * (size_t)t;
            if (cat_triangle_degenerate(m->positions, c[0], c[1], c[2])) {
                local.removed_triangles++;
                continue;
            }
            memmove(m->indices + 3 * (size_t)kept++, c, 3 * sizeof *c);
        }
        m->index_count = 3 * kept;
    }
    if (report)
        *report = local;
    return CAT_OK;
}

long cat_model_triangle_count(const cat_model *m)
{
    long n = 0;
    for (int i = 0; m && m->meshes && i < m->mesh_count; i++)
        n += m->meshes[i].index_count / 3;
    return n;
}
