/* The lightmap's layout: each plane of a lightmapped mesh becomes a chart (a rectangle of
 * texels on the plane, with a texel of gutter around it), the charts are shelf-packed into one
 * atlas, and every vertex gets the atlas coordinate of its place on its chart. A room surface
 * is a planar polygon, so its chart is its bounding rectangle in the plane: no UV unwrapping. */
#include "ref_bake_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A chart side never exceeds this many texels: a larger plane takes coarser texels. */
#define CHART_MAX_TEXELS 1024
/* The atlas is at most this wide; it grows downward. */
#define ATLAS_MAX_WIDTH 4096

typedef struct rect_order {
    int index, w, h;
} rect_order;

static int by_height_desc(const void *a, const void *b)
{
    const rect_order *x = a, *y = b;
    if (x->h != y->h)
        return y->h - x->h;
    if (x->w != y->w)
        return y->w - x->w;
    return x->index - y->index;
}

int ref_atlas_pack(const int *w, const int *h, int n, int max_width, int *x, int *y, int *atlas_w,
                   int *atlas_h)
{
    *atlas_w = *atlas_h = 0;
    rect_order *order = malloc((size_t)(n > 0 ? n : 1) * sizeof *order);
    if (!order)
        return 0;
    for (int i = 0; i < n; i++) {
        if (w[i] <= 0 || h[i] <= 0 || w[i] > max_width) {
            free(order);
            return 0;
        }
        order[i] = (rect_order){i, w[i], h[i]};
    }
    qsort(order, (size_t)n, sizeof *order, by_height_desc);
    /* Aim for a square: the shelf width is the square root of the total area, at least the
     * widest rectangle and at most max_width. */
    double area = 0.0;
    int widest = 1;
    for (int i = 0; i < n; i++) {
        area += (double)w[i] * h[i];
        widest = w[i] > widest ? w[i] : widest;
    }
    int shelf = (int)ceil(sqrt(area) * 1.1);
    shelf = shelf < widest ? widest : shelf > max_width ? max_width : shelf;
    int cx = 0, cy = 0, row_h = 0, used_w = 0;
    for (int k = 0; k < n; k++) {
        const rect_order *r = &order[k];
        if (cx + r->w > shelf) {
            cy += row_h;
            cx = 0;
            row_h = 0;
        }
        x[r->index] = cx;
        y[r->index] = cy;
        cx += r->w;
        used_w = cx > used_w ? cx : used_w;
        row_h = r->h > row_h ? r->h : row_h; /* the first of a row is its tallest */
    }
    free(order);
    *atlas_w = (used_w + 3) / 4 * 4;
    *atlas_h = cy + row_h;
    if (*atlas_w == 0)
        *atlas_w = 4;
    if (*atlas_h == 0)
        *atlas_h = 1;
    return 1;
}

/* An orthonormal basis around unit a (Duff et al. 2017, "Building an orthonormal basis,
 * revisited"). */
static void basis(const float a[3], float t[3], float b[3])
{
    float sign = a[2] >= 0.0f ? 1.0f : -1.0f;
    float p = -1.0f / (sign + a[2]);
    float q = a[0] * a[1] * p;
    t[0] = 1.0f + sign * a[0] * a[0] * p;
    t[1] = sign * q;
    t[2] = -sign * a[0];
    b[0] = q;
    b[1] = sign + a[1] * a[1] * p;
    b[2] = -a[1];
}

typedef struct plane {
    float n[3], d;
    float amin, amax, bmin, bmax;
} plane;

/* Two triangles share a chart when their planes agree to these tolerances. */
#define PLANE_COS 0.9995f
#define PLANE_DIST_M 0.002f

static int find_plane(const plane *planes, int count, const float n[3], float d)
{
    for (int i = 0; i < count; i++)
        if (ref_dot(planes[i].n, n) > PLANE_COS && fabsf(planes[i].d - d) < PLANE_DIST_M)
            return i;
    return -1;
}

void ref_bake_texel_point(const ref_bake_chart *c, int x, int y, float p[3])
{
    float a = ((float)(x - c->x) - 0.5f) * c->texel_m, b = ((float)(y - c->y) - 0.5f) * c->texel_m;
    for (int k = 0; k < 3; k++)
        p[k] = c->origin[k] + a * c->u[k] + b * c->v[k];
}

/* Marks the texels of chart c whose centres lie inside triangle (p0, p1, p2) (in the plane). */
static void cover_triangle(ref_bake *b, const ref_bake_chart *c, const float *p0, const float *p1,
                           const float *p2)
{
    float q[3][2];
    const float *ps[3] = {p0, p1, p2};
    for (int i = 0; i < 3; i++) {
        float d[3] = {ps[i][0] - c->origin[0], ps[i][1] - c->origin[1], ps[i][2] - c->origin[2]};
        q[i][0] = ref_dot(d, c->u) / c->texel_m + 0.5f; /* in chart texels, centre at i + 0.5 */
        q[i][1] = ref_dot(d, c->v) / c->texel_m + 0.5f;
    }
    float area =
        (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[2][0] - q[0][0]) * (q[1][1] - q[0][1]);
    if (!(fabsf(area) > 1e-12f))
        return;
    int x0 = (int)floorf(fminf(q[0][0], fminf(q[1][0], q[2][0]))) - 1;
    int x1 = (int)ceilf(fmaxf(q[0][0], fmaxf(q[1][0], q[2][0]))) + 1;
    int y0 = (int)floorf(fminf(q[0][1], fminf(q[1][1], q[2][1]))) - 1;
    int y1 = (int)ceilf(fmaxf(q[0][1], fmaxf(q[1][1], q[2][1]))) + 1;
    x0 = x0 < 0 ? 0 : x0;
    y0 = y0 < 0 ? 0 : y0;
    x1 = x1 > c->width ? c->width : x1;
    y1 = y1 > c->height ? c->height : y1;
    const float tol = 1e-4f * fabsf(area);
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            float px = (float)x, py = (float)y; /* texel x's centre is at x + 0.5 - 0.5 */
            float w0 = (q[1][0] - px) * (q[2][1] - py) - (q[2][0] - px) * (q[1][1] - py);
            float w1 = (q[2][0] - px) * (q[0][1] - py) - (q[0][0] - px) * (q[2][1] - py);
            float w2 = (q[0][0] - px) * (q[1][1] - py) - (q[1][0] - px) * (q[0][1] - py);
            if (area < 0.0f) {
                w0 = -w0;
                w1 = -w1;
                w2 = -w2;
            }
            if (w0 >= -tol && w1 >= -tol && w2 >= -tol)
                b->cover[(size_t)(c->y + y) * (size_t)b->atlas_width + (size_t)(c->x + x)] = 1;
        }
}

/* The planes of mesh m: fills planes (grown as needed) and tri_plane. */
static ref_result mesh_planes(const ref_mesh *m, plane **planes, int first, int *count,
                              int *capacity, int *tri_plane)
{
    for (int t = 0; t < m->triangle_count; t++) {
        const float *ng = m->tri_normals + 3 * (size_t)t;
        float len = sqrtf(ref_dot(ng, ng));
        if (!(len > 1e-12f)) {
            tri_plane[t] = -1;
            continue;
        }
        float n[3] = {ng[0] / len, ng[1] / len, ng[2] / len};
        const float *p0 = m->positions + 3 * (size_t)m->indices[3 * t];
        float d = ref_dot(n, p0);
        int i = find_plane(*planes + first, *count - first, n, d);
        i = i < 0 ? -1 : first + i;
        if (i < 0) {
            if (*count == *capacity) {
                int cap = *capacity ? 2 * *capacity : 16;
                plane *np = realloc(*planes, (size_t)cap * sizeof *np);
                if (!np)
                    return ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_bake: out of memory");
                *planes = np;
                *capacity = cap;
            }
            i = (*count)++;
            plane *pl = &(*planes)[i];
            memcpy(pl->n, n, sizeof n);
            pl->d = d;
            pl->amin = pl->bmin = INFINITY;
            pl->amax = pl->bmax = -INFINITY;
        }
        tri_plane[t] = i;
        plane *pl = &(*planes)[i];
        float u[3], v[3];
        basis(pl->n, u, v);
        for (int k = 0; k < 3; k++) {
            const float *p = m->positions + 3 * (size_t)m->indices[3 * t + (unsigned)k];
            float a = ref_dot(p, u), b = ref_dot(p, v);
            pl->amin = fminf(pl->amin, a);
            pl->amax = fmaxf(pl->amax, a);
            pl->bmin = fminf(pl->bmin, b);
            pl->bmax = fmaxf(pl->bmax, b);
        }
    }
    return REF_OK;
}

ref_result ref_bake_charts_make(const ref_scene *s, const unsigned char *lightmapped, float texel_m,
                                ref_bake *b, bake_layout *layout)
{
    plane *planes = NULL;
    int plane_count = 0, plane_capacity = 0;
    int *chart_plane_first = calloc((size_t)s->mesh_count + 1, sizeof *chart_plane_first);
    if (!chart_plane_first)
        return ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_bake: out of memory");
    ref_result r = REF_OK;
    /* Planes are found per mesh; a mesh's charts are consecutive. */
    for (int m = 0; r == REF_OK && m < s->mesh_count; m++) {
        chart_plane_first[m] = plane_count;
        if (!lightmapped || !lightmapped[m] || b->meshes[m].kind != REF_BAKE_LIGHTMAP)
            continue;
        const ref_mesh *mesh = &s->meshes[m];
        layout->tri_chart[m] = malloc((size_t)(mesh->triangle_count + 1) * sizeof(int));
        if (!layout->tri_chart[m])
            r = ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_bake: out of memory");
        else
            r = mesh_planes(mesh, &planes, plane_count, &plane_count, &plane_capacity,
                            layout->tri_chart[m]);
    }
    chart_plane_first[s->mesh_count] = plane_count;
    int *w = NULL, *h = NULL, *x = NULL, *y = NULL;
    if (r == REF_OK) {
        b->charts = calloc((size_t)plane_count + 1, sizeof *b->charts);
        w = calloc((size_t)plane_count + 1, sizeof *w);
        h = calloc((size_t)plane_count + 1, sizeof *h);
        x = calloc((size_t)plane_count + 1, sizeof *x);
        y = calloc((size_t)plane_count + 1, sizeof *y);
        if (!b->charts || !w || !h || !x || !y)
            r = ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_bake: out of memory");
    }
    for (int m = 0; r == REF_OK && m < s->mesh_count; m++)
        for (int i = chart_plane_first[m]; i < chart_plane_first[m + 1]; i++) {
            const plane *pl = &planes[i];
            ref_bake_chart *c = &b->charts[i];
            c->mesh = m;
            float ea = pl->amax - pl->amin, eb = pl->bmax - pl->bmin;
            float t = texel_m;
            float longest = fmaxf(ea, eb);
            if (longest / t > (float)(CHART_MAX_TEXELS - 3))
                t = longest / (float)(CHART_MAX_TEXELS - 3);
            c->texel_m = t;
            c->width = (int)ceilf(ea / t) + 2;
            c->height = (int)ceilf(eb / t) + 2;
            basis(pl->n, c->u, c->v);
            memcpy(c->normal, pl->n, sizeof c->normal);
            for (int k = 0; k < 3; k++)
                c->origin[k] = pl->amin * c->u[k] + pl->bmin * c->v[k] + pl->d * pl->n[k];
            w[i] = c->width;
            h[i] = c->height;
        }
    if (r == REF_OK && !ref_atlas_pack(w, h, plane_count, ATLAS_MAX_WIDTH, x, y, &b->atlas_width,
                                       &b->atlas_height))
        r = ref_fail(REF_ERR_TOO_LARGE, "ref_bake: the lightmap charts do not fit an atlas");
    if (r == REF_OK) {
        b->chart_count = plane_count;
        for (int i = 0; i < plane_count; i++) {
            b->charts[i].x = x[i];
            b->charts[i].y = y[i];
        }
        size_t texels = (size_t)b->atlas_width * (size_t)b->atlas_height;
        b->cover = calloc(texels, 1);
        if (!b->cover)
            r = ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_bake: out of memory");
    }
    /* Per vertex: the atlas coordinate on the chart of the first triangle that uses it (room
     * meshes give each plane its own vertices, so there is only one). */
    for (int m = 0; r == REF_OK && m < s->mesh_count; m++) {
        if (!layout->tri_chart[m])
            continue;
        const ref_mesh *mesh = &s->meshes[m];
        ref_bake_mesh *bm = &b->meshes[m];
        bm->lightmap_uv = calloc(2 * (size_t)mesh->vertex_count + 1, sizeof(float));
        unsigned char *done = calloc((size_t)mesh->vertex_count + 1, 1);
        if (!bm->lightmap_uv || !done) {
            free(done);
            r = ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_bake: out of memory");
            break;
        }
        for (int t = 0; t < mesh->triangle_count; t++) {
            int ci = layout->tri_chart[m][t];
            if (ci < 0)
                continue;
            ref_bake_chart *c = &b->charts[ci];
            const uint32_t *tri = mesh->indices + 3 * (size_t)t;
            cover_triangle(b, c, mesh->positions + 3 * tri[0], mesh->positions + 3 * tri[1],
                           mesh->positions + 3 * tri[2]);
            for (int k = 0; k < 3; k++) {
                uint32_t vi = tri[k];
                if (done[vi])
                    continue;
                done[vi] = 1;
                const float *p = mesh->positions + 3 * (size_t)vi;
                float d[3] = {p[0] - c->origin[0], p[1] - c->origin[1], p[2] - c->origin[2]};
                float ax = (float)c->x + 1.0f + ref_dot(d, c->u) / c->texel_m;
                float ay = (float)c->y + 1.0f + ref_dot(d, c->v) / c->texel_m;
                bm->lightmap_uv[2 * vi] = ax / (float)b->atlas_width;
                bm->lightmap_uv[2 * vi + 1] = ay / (float)b->atlas_height;
            }
        }
        free(done);
    }
    free(planes);
    free(chart_plane_first);
    free(w);
    free(h);
    free(x);
    free(y);
    return r;
}
