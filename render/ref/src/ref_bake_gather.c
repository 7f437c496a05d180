/* One gathering pass of the bake: at each point, cosine-weighted hemisphere rays; at each hit the
 * radiance the GPU would draw there without highlights -- max(C_e, C_d sum(I_d att N.L vis) +
 * C_a I_prev) (RENDERING.md section 1, eq. 7) -- with vis from a shadow ray to every light
 * (next-event estimation) and I_prev the stored light of the previous pass at the hit. The mean
 * over cosine-weighted directions is the irradiance over pi (Pharr, Jakob and Humphreys,
 * "Physically Based Rendering", 4th ed., 13.6.3: p(w) = cos / pi), which is the ambient
 * intensity a Lambertian surface of the GPU's model takes in place of I_a. */
#include "ref_bake_internal.h"

#include "render/shade_ref.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

typedef struct bake_ctx {
    struct RTCIntersectContext rtc; /* first: Embree hands the filter a pointer to it */
    const ref_scene *scene;
    int shadow; /* shadow rays skip emitters (a lamp's own shade), as ref_shadow.c does */
} bake_ctx;

/* Glass passes light straight through (the bake has no refraction); shadow rays also pass
 * glowing fixtures, which hold their lights, and the room's surfaces, which cast no shadow in
 * the GPU's shadow pass nor in the tracer (ref_shadow.c): a directional light from above
 * reaches the floor through the ceiling there, and must here too. Back faces are kept: a ray
 * that meets one is inside a closed mesh (or under it) and brings back no light. */
static void bake_filter(const struct RTCFilterFunctionNArguments *a)
{
    const bake_ctx *c = (const bake_ctx *)a->context;
    const unsigned *hit = (const unsigned *)a->hit;
    unsigned n = a->N;
    for (unsigned i = 0; i < n; i++) {
        if (a->valid[i] == 0)
            continue;
        const ref_mesh *m = &c->scene->meshes[hit[6 * n + i]];
        const float *e = m->material.emissive;
        if (m->glass || (c->shadow && (m->background || e[0] > 0.0f || e[1] > 0.0f || e[2] > 0.0f)))
            a->valid[i] = 0;
    }
}

static void ray_setup(struct RTCRay *ray, const float org[3], const float dir[3], float tnear,
                      float tfar)
{
    memset(ray, 0, sizeof *ray);
    ray->org_x = org[0];
    ray->org_y = org[1];
    ray->org_z = org[2];
    ray->dir_x = dir[0];
    ray->dir_y = dir[1];
    ray->dir_z = dir[2];
    ray->tnear = tnear;
    ray->tfar = tfar;
    ray->mask = 0xFFFFFFFFu;
}

static int occluded(const ref_scene *s, const float org[3], const float dir[3], float tfar)
{
    bake_ctx c;
    rtcInitIntersectContext(&c.rtc);
    c.rtc.filter = bake_filter;
    c.scene = s;
    c.shadow = 1;
    struct RTCRay ray;
    ray_setup(&ray, org, dir, 0.0f, tfar);
    rtcOccluded1(s->rtc, &c.rtc, &ray);
    return ray.tfar < 0.0f;
}

/* splitmix64's finaliser. */
static uint64_t mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static float radical_inverse2(uint32_t i)
{
    i = (i << 16) | (i >> 16);
    i = ((i & 0x55555555u) << 1) | ((i & 0xAAAAAAAAu) >> 1);
    i = ((i & 0x33333333u) << 2) | ((i & 0xCCCCCCCCu) >> 2);
    i = ((i & 0x0F0F0F0Fu) << 4) | ((i & 0xF0F0F0F0u) >> 4);
    i = ((i & 0x00FF00FFu) << 8) | ((i & 0xFF00FF00u) >> 8);
    return (float)(i >> 8) * (1.0f / 16777216.0f);
}

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

/* Bilinear lookup of the stored light (rgb) in the atlas at (u, v) in [0, 1]. */
static void atlas_sample(const ref_bake *b, const float *values, float u, float v, float out[3])
{
    float x = u * (float)b->atlas_width - 0.5f, y = v * (float)b->atlas_height - 0.5f;
    int x0 = (int)floorf(x), y0 = (int)floorf(y);
    float fx = x - (float)x0, fy = y - (float)y0;
    out[0] = out[1] = out[2] = 0.0f;
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++) {
            int xi = x0 + i, yj = y0 + j;
            xi = xi < 0 ? 0 : xi >= b->atlas_width ? b->atlas_width - 1 : xi;
            yj = yj < 0 ? 0 : yj >= b->atlas_height ? b->atlas_height - 1 : yj;
            float w = (i ? fx : 1.0f - fx) * (j ? fy : 1.0f - fy);
            const float *t = values + 4 * ((size_t)yj * (size_t)b->atlas_width + (size_t)xi);
            for (int k = 0; k < 3; k++)
                out[k] += w * t[k];
        }
}

/* The stored light at barycentrics (b1, b2) of triangle prim of mesh m. */
static void stored_light(const bake_gather_job *job, unsigned m, unsigned prim, float b1, float b2,
                         float out[3])
{
    const ref_mesh *mesh = &job->scene->meshes[m];
    const ref_bake_mesh *bm = &job->bake->meshes[m];
    const uint32_t *tri = mesh->indices + 3 * (size_t)prim;
    float w[3] = {1.0f - b1 - b2, b1, b2};
    out[0] = out[1] = out[2] = 0.0f;
    if (bm->kind == REF_BAKE_LIGHTMAP) {
        float uv[2] = {0.0f, 0.0f};
        for (int k = 0; k < 3; k++) {
            uv[0] += w[k] * bm->lightmap_uv[2 * tri[k]];
            uv[1] += w[k] * bm->lightmap_uv[2 * tri[k] + 1];
        }
        atlas_sample(job->bake, job->prev, uv[0], uv[1], out);
    } else if (bm->kind == REF_BAKE_VERTEX) {
        int base = job->layout->vertex_base[m];
        for (int k = 0; k < 3; k++) {
            const float *v = job->prev + 4 * ((size_t)base + tri[k]);
            for (int c = 0; c < 3; c++)
                out[c] += w[k] * v[c];
        }
    } else {
        memcpy(out, job->scene->ambient, sizeof(float) * 3);
    }
}

/* The diffuse albedo of a mesh: its colour times its texture's mean (the last mip level). */
static void albedo_of(const ref_scene *s, const ref_mesh *m, float scale[3])
{
    scale[0] = scale[1] = scale[2] = 1.0f;
    if (m->texture) {
        const ref_texture *t = &s->textures[m->texture - 1];
        const ref_mip *top = &t->mips[t->levels - 1];
        memcpy(scale, top->rgb, 3 * sizeof(float));
    }
}

/* Radiance leaving hit (mesh m, triangle prim, barycentrics) toward the gathering point; 1 when
 * the ray met the back of a closed mesh (the point is inside it or under it). */
static int hit_radiance(const bake_gather_job *job, const struct RTCRayHit *rh, const float dir[3],
                        float out[3])
{
    const ref_scene *s = job->scene;
    const ref_mesh *m = &s->meshes[rh->hit.geomID];
    /* A window's exterior panel or a lamp's glowing shape: its glow reaches the room through
     * the lights of the list (the window's rectangle light and sun, the lamp's light), which the
     * GPU draws as direct light, so it brings back only the light it reflects, as the path
     * tracer's paths that reach it after a lobe sample do (ref_path.c): a lamp's diffuser lit by
     * its own rectangle light a centimetre away throws much of it on the wall beside it. */
    int stand_in = m->light_stand_in;
    const float *tn = m->tri_normals + 3 * (size_t)rh->hit.primID;
    float ng_dot = ref_dot(tn, dir);
    if (ng_dot >= 0.0f && !m->double_sided) {
        out[0] = out[1] = out[2] = 0.0f; /* inside a closed mesh */
        return 1;
    }
    float len = sqrtf(ref_dot(tn, tn));
    float flip = ng_dot < 0.0f ? 1.0f : -1.0f;
    float ng[3], p[3];
    for (int k = 0; k < 3; k++) {
        ng[k] = len > 0.0f ? flip * tn[k] / len : -dir[k];
        p[k] = (&rh->ray.org_x)[k] + rh->ray.tfar * dir[k];
    }
    float albedo[3];
    albedo_of(s, m, albedo);
    float prev[3];
    stored_light(job, rh->hit.geomID, rh->hit.primID, rh->hit.u, rh->hit.v, prev);
    float lift = 20.0f * s->epsilon;
    float org[3] = {p[0] + lift * ng[0], p[1] + lift * ng[1], p[2] + lift * ng[2]};
    float direct[3] = {0.0f, 0.0f, 0.0f};
    for (int i = 0; i < s->light_count; i++) {
        const rd_light *l = &s->lights[i];
        float to_l[3], factor;
        rd_ref_light_incidence(l, p, ng, to_l, &factor);
        /* A rectangle light by its clipped form factor, as the GPU's direct light and the tracer
         * shade it (shade_ref.c): near it, its centre is no stand-in for it (a lamp's diffuser
         * beside its strip light has the centre in its own plane, where N.L is 0). */
        int rect = l->type == RD_LIGHT_RECT;
        float ndl = ref_dot(ng, to_l);
        float irradiance = rect ? rd_ref_rect_form_factor(p, ng, l) : factor * ndl;
        if (!(irradiance > 0.0f) || (!rect && !(ndl > 0.0f)))
            continue;
        float tfar = INFINITY;
        if (l->type != RD_LIGHT_DIRECTIONAL) {
            float d[3] = {l->position[0] - org[0], l->position[1] - org[1],
                          l->position[2] - org[2]};
            tfar = sqrtf(ref_dot(d, d)) - 0.01f; /* a light set into a ceiling is not behind it */
            if (!(tfar > 0.0f) && !rect)
                continue;
        }
        if (tfar > 0.0f && occluded(s, org, to_l, tfar))
            continue;
        for (int k = 0; k < 3; k++)
            direct[k] += irradiance * l->diffuse[k];
    }
    /* The light arriving at the hit leaves it by the diffuse lobe and by the glossy one, as in
     * the path tracer (ref_path.c), and a reflective surface sends k_r of it on as a mirror
     * would, the lamps' direct light included (the light a bathroom mirror throws back into
     * the room, which the tracer's paths carry from the lamp by the mirror; spread here as a
     * Lambertian surface of albedo k_r would); I stands for that field's radiance. The tracer's
     * normalised Blinn-Phong lobe C_s (n + 8) / (8 pi) (N.H)^n reflects C_s A of a uniform field,
     * its directional albedo A close to (N.V)^2 for n >= 40 (numerical integration over the
     * hemisphere: 0.82, 0.50, 0.26, 0.10 at N.V = 0.9, 0.7, 0.5, 0.3 for n = 200;
     * docs/rendering.md, "Baked indirect light"). Direct light keeps section 1's terms without the
     * highlight, far narrower than a texel. */
    const rd_material *mat = &m->material;
    float kr = m->reflective ? fminf(fmaxf(mat->reflectivity, 0.0f), 1.0f) : 0.0f;
    float glossy = len > 0.0f ? fminf(ng_dot * ng_dot / (len * len), 1.0f) : 0.0f;
    for (int k = 0; k < 3; k++) {
        float bounce = albedo[k] * mat->ambient[k] + fmaxf(mat->specular[k], 0.0f) * glossy;
        float lit = albedo[k] * mat->diffuse[k] * direct[k] + bounce * prev[k];
        float reflected = (1.0f - kr) * lit + kr * (prev[k] + direct[k]);
        out[k] = stand_in ? reflected : fmaxf(mat->emissive[k], reflected);
    }
    return 0;
}

static void gather_point(const bake_gather_job *job, const bake_point *pt, long long *rays)
{
    const ref_scene *s = job->scene;
    float t[3], b[3];
    basis(pt->n, t, b);
    /* A per-point rotation of one Hammersley set (Cranley and Patterson 1976): stratified
     * directions, decorrelated between neighbours so the filter can average them out. */
    uint64_t key = mix64(((uint64_t)(uint32_t)pt->slot << 8) ^ (uint64_t)job->pass);
    float shift_u = (float)(key >> 40) * (1.0f / 16777216.0f);
    float shift_v = (float)((key >> 16) & 0xFFFFFF) * (1.0f / 16777216.0f);
    float lift = 20.0f * s->epsilon;
    float org[3] = {pt->p[0] + lift * pt->n[0], pt->p[1] + lift * pt->n[1],
                    pt->p[2] + lift * pt->n[2]};
    float sum[3] = {0.0f, 0.0f, 0.0f};
    int near_hits = 0, back_hits = 0;
    int n = job->samples;
    bake_ctx c;
    for (int i = 0; i < n; i++) {
        float u1 = ((float)i + 0.5f) / (float)n + shift_u;
        float u2 = radical_inverse2((uint32_t)i) + shift_v;
        u1 -= floorf(u1);
        u2 -= floorf(u2);
        /* Malley's method: a uniform disk point lifted to the hemisphere is cosine-distributed. */
        float r = sqrtf(u1), phi = 6.28318531f * u2;
        float x = r * cosf(phi), y = r * sinf(phi), z = sqrtf(fmaxf(0.0f, 1.0f - u1));
        float dir[3];
        for (int k = 0; k < 3; k++)
            dir[k] = x * t[k] + y * b[k] + z * pt->n[k];
        rtcInitIntersectContext(&c.rtc);
        c.rtc.filter = bake_filter;
        c.scene = s;
        c.shadow = 0;
        struct RTCRayHit rh;
        ray_setup(&rh.ray, org, dir, 0.0f, INFINITY);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(s->rtc, &c.rtc, &rh);
        (*rays)++;
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
            continue;
        if (rh.ray.tfar < job->ao_distance)
            near_hits++;
        float l[3];
        back_hits += hit_radiance(job, &rh, dir, l);
        *rays += s->light_count;
        for (int k = 0; k < 3; k++)
            sum[k] += l[k];
    }
    float *out = job->out + 4 * (size_t)pt->slot;
    for (int k = 0; k < 3; k++)
        out[k] = n > 0 ? sum[k] / (float)n : 0.0f;
    out[3] = n > 0 ? 1.0f - (float)near_hits / (float)n : 1.0f;
    /* A texel whose centre a fixture covers (a wall behind a mirror or a cabinet) sees mostly
     * that fixture's inside. Its darkness is no light of the surface: bilinear lookups beside
     * the fixture would carry it onto the visible texels next to it (a strip of wall between a
     * mirror and the lamp over it), so the filter fills it from its neighbours instead. */
    if (job->buried)
        job->buried[pt->slot] = (unsigned char)(2 * back_hits > n);
}

typedef struct worker {
    bake_gather_job *job;
    atomic_int *next;
    atomic_llong *done;
    atomic_int *stop; /* the caller's progress_fn asked to stop */
    long long rays;
    int index;
} worker;

#define CHUNK 16

static void progress_draw(const bake_gather_job *job, long long done)
{
    long long total = job->progress_total > 0 ? job->progress_total : 1;
    int width = 40, filled = (int)((double)done / (double)total * width);
    char bar[64];
    for (int i = 0; i < width; i++)
        bar[i] = i < filled ? '#' : '.';
    bar[width] = 0;
    fprintf(stderr, "\rbake: [%s] %3d%%  pass %d", bar, (int)(100.0 * (double)done / (double)total),
            job->pass + 1);
    fflush(stderr);
}

static void *work(void *arg)
{
    worker *w = arg;
    bake_gather_job *job = w->job;
    struct timespec last = {0, 0};
    for (;;) {
        if (atomic_load(w->stop))
            break;
        int start = atomic_fetch_add(w->next, CHUNK);
        if (start >= job->point_count)
            break;
        int end = start + CHUNK < job->point_count ? start + CHUNK : job->point_count;
        for (int i = start; i < end && !atomic_load_explicit(w->stop, memory_order_relaxed); i++)
            gather_point(job, &job->points[i], &w->rays);
        long long done = atomic_fetch_add(w->done, end - start) + (end - start);
        if (job->progress_fn &&
            job->progress_fn(job->progress_user, job->progress_done + done, job->progress_total))
            atomic_store(w->stop, 1);
        if (w->index == 0 && job->progress) {
            struct timespec now;
            clock_gettime(CLOCK_MONOTONIC, &now);
            if ((now.tv_sec - last.tv_sec) * 1000000000L + (now.tv_nsec - last.tv_nsec) >
                100000000L) {
                progress_draw(job, job->progress_done + done);
                last = now;
            }
        }
    }
    return NULL;
}

ref_result ref_bake_gather(bake_gather_job *job)
{
    int threads = job->threads > 0 ? job->threads : (int)sysconf(_SC_NPROCESSORS_ONLN);
    threads = threads < 1 ? 1 : threads > 64 ? 64 : threads;
    atomic_int next = 0;
    atomic_llong done = 0;
    atomic_int stop = 0;
    worker workers[64];
    pthread_t ids[64];
    int started = 0;
    for (int i = 0; i < threads; i++) {
        workers[i] = (worker){job, &next, &done, &stop, 0, i};
        if (i > 0 && pthread_create(&ids[i], NULL, work, &workers[i]) == 0)
            started++;
        else if (i > 0)
            workers[i].index = -1;
    }
    work(&workers[0]);
    for (int i = 1; i < threads; i++)
        if (workers[i].index >= 0)
            pthread_join(ids[i], NULL);
    (void)started;
    for (int i = 0; i < threads; i++)
        job->rays += workers[i].rays;
    job->progress_done += job->point_count;
    if (atomic_load(&stop))
        return ref_fail(REF_ERR_CANCELLED, "ref_bake: cancelled");
    if (job->progress)
        progress_draw(job, job->progress_done);
    return REF_OK;
}
