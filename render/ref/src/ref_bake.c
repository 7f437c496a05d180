/* The bake's driver (ref_bake.h): which meshes take a lightmap, vertices or nothing; the points
 * to compute (all, or those within reach of what changed); the passes of gathering, each
 * filtered; the result. */
#include "ref_bake_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

void ref_bake_free(ref_bake *b)
{
    if (!b)
        return;
    for (int m = 0; m < b->mesh_count; m++) {
        free(b->meshes[m].vertex);
        free(b->meshes[m].lightmap_uv);
    }
    free(b->meshes);
    free(b->atlas);
    free(b->cover);
    free(b->charts);
    memset(b, 0, sizeof *b);
}

static void layout_free(bake_layout *l, int mesh_count)
{
    if (l->tri_chart)
        for (int m = 0; m < mesh_count; m++)
            free(l->tri_chart[m]);
    free(l->tri_chart);
    free(l->vertex_base);
}

static float box_distance(const float box[6], const float p[3])
{
    float d2 = 0.0f;
    for (int k = 0; k < 3; k++) {
        float e = fmaxf(fmaxf(box[k] - p[k], p[k] - box[3 + k]), 0.0f);
        d2 += e * e;
    }
    return sqrtf(d2);
}

static float box_box_distance(const float a[6], const float bmin[3], const float bmax[3])
{
    float d2 = 0.0f;
    for (int k = 0; k < 3; k++) {
        float e = fmaxf(fmaxf(a[k] - bmax[k], bmin[k] - a[3 + k]), 0.0f);
        d2 += e * e;
    }
    return sqrtf(d2);
}

static int near_dirty(const ref_bake_desc *d, const float p[3])
{
    for (int i = 0; i < d->dirty_box_count; i++)
        if (box_distance(d->dirty_boxes[i], p) <= d->reach_m)
            return 1;
    return 0;
}

static int mesh_near_dirty(const ref_bake_desc *d, const ref_bake_mesh *m)
{
    for (int i = 0; i < d->dirty_box_count; i++)
        if (box_box_distance(d->dirty_boxes[i], m->bounds_min, m->bounds_max) <= d->reach_m)
            return 1;
    return 0;
}

static ref_bake_kind kind_of(const ref_mesh *m, int lightmapped)
{
    const float *e = m->material.emissive;
    if (m->glass || e[0] > 0.0f || e[1] > 0.0f || e[2] > 0.0f || m->triangle_count == 0)
        return REF_BAKE_NONE;
    return lightmapped ? REF_BAKE_LIGHTMAP : REF_BAKE_VERTEX;
}

static ref_result check_previous(const ref_bake_desc *d, const ref_bake *b)
{
    const ref_bake *prev = d->previous;
    if (prev->mesh_count != b->mesh_count || prev->atlas_width != b->atlas_width ||
        prev->atlas_height != b->atlas_height ||
        (b->atlas_width > 0 && b->atlas_height > 0 && !prev->atlas))
        return ref_fail(REF_ERR_INVALID_ARGUMENT,
                        "ref_bake: the previous bake has another layout (%d meshes, atlas %dx%d; "
                        "now %d, %dx%d)",
                        prev->mesh_count, prev->atlas_width, prev->atlas_height, b->mesh_count,
                        b->atlas_width, b->atlas_height);
    for (int m = 0; m < b->mesh_count; m++)
        if ((!d->keep || d->keep[m]) &&
            (prev->meshes[m].kind != b->meshes[m].kind ||
             (b->meshes[m].kind == REF_BAKE_VERTEX &&
              (!prev->meshes[m].vertex ||
               prev->meshes[m].vertex_count != b->meshes[m].vertex_count))))
            return ref_fail(REF_ERR_INVALID_ARGUMENT,
                            "ref_bake: the previous bake's mesh %d differs from the scene's", m);
    return REF_OK;
}

/* Fills b's meshes (kinds, bounds), charts and the slot layout. */
static ref_result make_layout(const ref_scene *s, const ref_bake_desc *d, float texel, ref_bake *b,
                              bake_layout *l)
{
    b->mesh_count = s->mesh_count;
    b->meshes = calloc((size_t)s->mesh_count + 1, sizeof *b->meshes);
    l->tri_chart = calloc((size_t)s->mesh_count + 1, sizeof *l->tri_chart);
    l->vertex_base = calloc((size_t)s->mesh_count + 1, sizeof *l->vertex_base);
    if (!b->meshes || !l->tri_chart || !l->vertex_base)
        return ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_bake: out of memory");
    for (int m = 0; m < s->mesh_count; m++) {
        const ref_mesh *mesh = &s->meshes[m];
        ref_bake_mesh *bm = &b->meshes[m];
        bm->kind = kind_of(mesh, d->lightmapped && d->lightmapped[m]);
        bm->vertex_count = mesh->vertex_count;
        for (int k = 0; k < 3; k++) {
            bm->bounds_min[k] = INFINITY;
            bm->bounds_max[k] = -INFINITY;
        }
        for (int v = 0; v < mesh->vertex_count; v++)
            for (int k = 0; k < 3; k++) {
                bm->bounds_min[k] = fminf(bm->bounds_min[k], mesh->positions[3 * v + k]);
                bm->bounds_max[k] = fmaxf(bm->bounds_max[k], mesh->positions[3 * v + k]);
            }
    }
    ref_result r = ref_bake_charts_make(s, d->lightmapped, texel, b, l);
    if (r != REF_OK)
        return r;
    l->texels = b->atlas_width * b->atlas_height;
    long long slots = l->texels;
    for (int m = 0; m < s->mesh_count; m++) {
        l->vertex_base[m] = -1;
        if (b->meshes[m].kind == REF_BAKE_VERTEX) {
            l->vertex_base[m] = (int)slots;
            slots += s->meshes[m].vertex_count;
        }
    }
    if (slots > (1LL << 28))
        return ref_fail(REF_ERR_TOO_LARGE, "ref_bake: %lld points are too many", slots);
    l->slots = (int)slots;
    return REF_OK;
}

/* The points to compute; recomputed (per slot, may be NULL) marks them, changed marks meshes. */
static bake_point *collect_points(const ref_scene *s, const ref_bake_desc *d, const ref_bake *b,
                                  const bake_layout *l, int *count, unsigned char *recomputed,
                                  unsigned char *changed)
{
    bake_point *pts = malloc(((size_t)l->slots + 1) * sizeof *pts);
    if (!pts)
        return NULL;
    int n = 0;
    for (int ci = 0; ci < b->chart_count; ci++) {
        const ref_bake_chart *c = &b->charts[ci];
        int partial = d->previous && (!d->keep || d->keep[c->mesh]);
        for (int y = c->y; y < c->y + c->height; y++)
            for (int x = c->x; x < c->x + c->width; x++) {
                int slot = y * b->atlas_width + x;
                if (!b->cover[slot])
                    continue;
                bake_point *pt = &pts[n];
                ref_bake_texel_point(c, x, y, pt->p);
                if (partial && !near_dirty(d, pt->p))
                    continue;
                memcpy(pt->n, c->normal, sizeof pt->n);
                pt->slot = slot;
                recomputed[slot] = 1;
                changed[c->mesh] = 1;
                n++;
            }
    }
    for (int m = 0; m < s->mesh_count; m++) {
        if (b->meshes[m].kind != REF_BAKE_VERTEX)
            continue;
        int kept = d->previous && (!d->keep || d->keep[m]);
        if (kept && !mesh_near_dirty(d, &b->meshes[m]))
            continue;
        changed[m] = 1;
        const ref_mesh *mesh = &s->meshes[m];
        for (int v = 0; v < mesh->vertex_count; v++) {
            bake_point *pt = &pts[n];
            const float *nv = mesh->normals + 3 * (size_t)v;
            float len = sqrtf(ref_dot(nv, nv));
            memcpy(pt->p, mesh->positions + 3 * (size_t)v, sizeof pt->p);
            for (int k = 0; k < 3; k++)
                pt->n[k] = len > 0.0f ? nv[k] / len : (k == 2 ? 1.0f : 0.0f);
            pt->slot = l->vertex_base[m] + v;
            recomputed[pt->slot] = 1;
            n++;
        }
    }
    *count = n;
    return pts;
}

static double seconds_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static ref_result bake(ref_scene *s, const ref_bake_desc *d, ref_bake *b)
{
    double t0 = seconds_now();
    int samples = d->samples > 0 ? d->samples : 64;
    int passes = d->passes > 0 ? d->passes : REF_DEFAULT_BOUNCES;
    float texel = d->texel_m > 0.0f ? d->texel_m : 0.03f;
    float ao = d->ao_distance_m > 0.0f ? d->ao_distance_m : 0.5f;
    bake_layout l = {0};
    ref_result r = make_layout(s, d, texel, b, &l);
    if (r == REF_OK && d->previous)
        r = check_previous(d, b);
    float *cur = NULL, *next = NULL;
    unsigned char *recomputed = NULL, *changed = NULL, *buried = NULL;
    bake_point *pts = NULL;
    int point_count = 0;
    if (r == REF_OK) {
        cur = calloc(4 * (size_t)l.slots + 4, sizeof *cur);
        next = calloc(4 * (size_t)l.slots + 4, sizeof *next);
        recomputed = calloc((size_t)l.slots + 1, 1);
        changed = calloc((size_t)s->mesh_count + 1, 1);
        buried = calloc((size_t)l.slots + 1, 1);
        if (!cur || !next || !recomputed || !changed || !buried)
            r = ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_bake: out of memory");
    }
    if (r == REF_OK && d->previous) {
        if (l.texels)
            memcpy(cur, d->previous->atlas, 4 * (size_t)l.texels * sizeof *cur);
        for (int m = 0; m < s->mesh_count; m++)
            if (l.vertex_base[m] >= 0 && (!d->keep || d->keep[m]))
                memcpy(cur + 4 * (size_t)l.vertex_base[m], d->previous->meshes[m].vertex,
                       4 * (size_t)b->meshes[m].vertex_count * sizeof *cur);
    }
    if (r == REF_OK) {
        pts = collect_points(s, d, b, &l, &point_count, recomputed, changed);
        if (!pts)
            r = ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_bake: out of memory");
    }
    bake_gather_job job = {.scene = s,
                           .bake = b,
                           .layout = &l,
                           .points = pts,
                           .point_count = point_count,
                           .buried = buried,
                           .samples = samples,
                           .ao_distance = ao,
                           .threads = d->threads,
                           .progress = d->progress && isatty(2),
                           .progress_total = (long long)point_count * passes,
                           .progress_fn = d->progress_fn,
                           .progress_user = d->progress_user};
    if (r == REF_OK && point_count > 0)
        r = ref_scene_commit(s);
    for (int pass = 0; r == REF_OK && point_count > 0 && pass < passes; pass++) {
        memcpy(next, cur, 4 * (size_t)l.slots * sizeof *cur);
        job.prev = cur;
        job.out = next;
        job.pass = pass;
        r = ref_bake_gather(&job);
        if (r != REF_OK)
            break;
        ref_bake_filter_atlas(b, next, buried);
        /* Texels that were not computed keep what they had (filtered once already). */
        for (int i = 0; i < l.texels; i++)
            if (b->cover[i] && !recomputed[i])
                memcpy(next + 4 * (size_t)i, cur + 4 * (size_t)i, 4 * sizeof *cur);
        ref_bake_filter_vertices(s, b, &l, next, changed);
        float *t = cur;
        cur = next;
        next = t;
    }
    if (job.progress && point_count > 0)
        fputc('\n', stderr);
    if (r == REF_OK) {
        b->atlas = malloc(4 * (size_t)l.texels * sizeof *b->atlas + 4);
        if (!b->atlas)
            r = ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_bake: out of memory");
        else if (l.texels)
            memcpy(b->atlas, cur, 4 * (size_t)l.texels * sizeof *cur);
    }
    for (int m = 0; r == REF_OK && m < s->mesh_count; m++) {
        ref_bake_mesh *bm = &b->meshes[m];
        if (bm->kind != REF_BAKE_VERTEX)
            continue;
        bm->vertex = malloc(4 * (size_t)bm->vertex_count * sizeof *bm->vertex + 4);
        if (!bm->vertex) {
            r = ref_fail(REF_ERR_OUT_OF_MEMORY, "ref_bake: out of memory");
            break;
        }
        memcpy(bm->vertex, cur + 4 * (size_t)l.vertex_base[m],
               4 * (size_t)bm->vertex_count * sizeof *cur);
        b->total_vertices += bm->vertex_count;
    }
    if (r == REF_OK) {
        for (int i = 0; i < l.texels; i++) {
            b->total_texels += b->cover[i];
            if (recomputed[i])
                b->baked_texels++;
        }
        b->baked_vertices = point_count - b->baked_texels;
        b->rays = job.rays;
        b->seconds = seconds_now() - t0;
    }
    free(cur);
    free(next);
    free(recomputed);
    free(changed);
    free(buried);
    free(pts);
    layout_free(&l, s->mesh_count);
    return r;
}

ref_result ref_bake_run(ref_scene *s, const ref_bake_desc *d, ref_bake *out)
{
    if (!out)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_bake_run: no result");
    memset(out, 0, sizeof *out);
    if (!s || !d)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_bake_run: scene and desc required");
    if (d->dirty_box_count > 0 && !d->dirty_boxes)
        return ref_fail(REF_ERR_INVALID_ARGUMENT, "ref_bake_run: dirty boxes missing");
    ref_result r = bake(s, d, out);
    if (r != REF_OK)
        ref_bake_free(out);
    return r;
}
