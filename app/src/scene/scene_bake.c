/* The bake through its cache (scene_bake.h). One file per room: its name is a hash of the room's
 * surfaces, the lights and the bake's settings; inside, the hash of the whole scene, the atlas,
 * and per element (render-list item) a hash of its geometry, placement and material with its
 * bounds and values. A scene whose hash matches is read back without a ray; otherwise the
 * elements whose hashes are found are kept, and only points within APP_BAKE_REACH_M of an
 * element that changed (where it is now, and where it was) are baked again. */
#include "app/scene/scene_bake.h"

#include "app/scene/ref_scene_build.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static app_bake_settings g_settings;
/* Per thread: a window bakes on a worker while its own thread may read a whole scene from the
 * cache. */
static _Thread_local app_bake_stats g_stats;

void app_bake_configure(const app_bake_settings *s)
{
    if (s)
        g_settings = *s;
}

const app_bake_settings *app_bake_current(void)
{
    return &g_settings;
}

const app_bake_stats *app_bake_last_stats(void)
{
    return &g_stats;
}

/* Bump when the bake's meaning or the file's layout changes: old files are then ignored. */
#define BAKE_FORMAT 6
static const char MAGIC[8] = "TSBAKE2";

/* FNV-1a, 64 bits (Fowler, Noll and Vo). */
static uint64_t fnv(uint64_t h, const void *data, size_t n)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < n; i++) {
        h ^= p[i];
        h *= 0x100000001B3ull;
    }
    return h;
}
#define FNV_START 0xCBF29CE484222325ull

static uint64_t settings_hash(const app_bake_settings *s, const app_render_list *l)
{
    int v[3] = {BAKE_FORMAT, s->samples, s->bounces > 0 ? s->bounces : REF_DEFAULT_BOUNCES};
    uint64_t h = fnv(FNV_START, v, sizeof v);
    for (int i = 0; i < l->light_count; i++)
        h = fnv(h, &l->lights[i].light, sizeof l->lights[i].light);
    return fnv(h, l->ambient, sizeof l->ambient);
}

static uint64_t item_hash(const app_render_list *l, int i, uint64_t base)
{
    const app_render_item *it = &l->items[i];
    const app_render_mesh *m = &l->meshes[it->mesh];
    uint64_t h = fnv(base, &m->vertex_count, sizeof m->vertex_count);
    h = fnv(h, &m->index_count, sizeof m->index_count);
    h = fnv(h, m->positions, 3 * sizeof(float) * (size_t)m->vertex_count);
    h = fnv(h, m->normals, 3 * sizeof(float) * (size_t)m->vertex_count);
    h = fnv(h, m->indices, sizeof(uint32_t) * (size_t)m->index_count);
    h = fnv(h, it->transform, sizeof it->transform);
    const rd_material *mat = &it->material;
    h = fnv(h, mat->ambient, sizeof mat->ambient);
    h = fnv(h, mat->diffuse, sizeof mat->diffuse);
    h = fnv(h, mat->emissive, sizeof mat->emissive);
    h = fnv(h, &mat->transparency, sizeof mat->transparency);
    int flags[4] = {it->double_sided, it->background, it->object < 0, it->light_stand_in};
    h = fnv(h, flags, sizeof flags);
    if (it->texture >= 0)
        h = fnv(h, l->textures[it->texture].path, strlen(l->textures[it->texture].path));
    return h;
}

static void item_bounds(const app_render_list *l, int i, float box[6])
{
    const app_render_item *it = &l->items[i];
    const app_render_mesh *m = &l->meshes[it->mesh];
    const float *t = it->transform;
    int identity = 1;
    for (int k = 0; k < 16; k++)
        identity &= t[k] == 0.0f;
    for (int k = 0; k < 3; k++) {
        box[k] = INFINITY;
        box[3 + k] = -INFINITY;
    }
    for (int v = 0; v < m->vertex_count; v++) {
        const float *p = m->positions + 3 * v;
        for (int r = 0; r < 3; r++) {
            float w = identity ? p[r] : t[r] * p[0] + t[4 + r] * p[1] + t[8 + r] * p[2] + t[12 + r];
            box[r] = fminf(box[r], w);
            box[3 + r] = fmaxf(box[3 + r], w);
        }
    }
}

/* ---- the file ------------------------------------------------------------------------------ */

typedef struct cache_entry {
    uint64_t key;
    float box[6];
    int kind, vertex_count;
    float *data; /* 4 (vertex) or 2 (lightmap) floats per vertex */
    int used;
} cache_entry;

typedef struct cache_file {
    uint64_t scene;
    long long total_texels;
    int atlas_width, atlas_height;
    float *atlas;
    int entry_count;
    cache_entry *entries;
} cache_file;

static void cache_free(cache_file *c)
{
    for (int i = 0; i < c->entry_count; i++)
        free(c->entries[i].data);
    free(c->entries);
    free(c->atlas);
    memset(c, 0, sizeof *c);
}

static int cache_dir(char *out, size_t n)
{
    const char *xdg = getenv("XDG_CACHE_HOME"), *home = getenv("HOME");
    int w = xdg && *xdg     ? snprintf(out, n, "%s/tessera", xdg)
            : home && *home ? snprintf(out, n, "%s/.cache/tessera", home)
                            : -1;
    return w > 0 && (size_t)w < n;
}

static int make_dirs(const char *path)
{
    char tmp[1024];
    snprintf(tmp, sizeof tmp, "%s", path);
    for (char *p = tmp + 1; *p; p++)
        if (*p == '/') {
            *p = 0;
            mkdir(tmp, 0755);
            *p = '/';
        }
    return mkdir(tmp, 0755) == 0 || errno == EEXIST;
}

static int read_all(FILE *f, void *p, size_t n)
{
    return fread(p, 1, n, f) == n;
}

/* 1 when the file exists and reads whole; a damaged file is treated as none. */
static int cache_read(const char *path, cache_file *c)
{
    memset(c, 0, sizeof *c);
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    char magic[8];
    int ok = read_all(f, magic, 8) && !memcmp(magic, MAGIC, 8) && read_all(f, &c->scene, 8) &&
             read_all(f, &c->total_texels, 8) && read_all(f, &c->atlas_width, 4) &&
             read_all(f, &c->atlas_height, 4) && c->atlas_width >= 0 && c->atlas_height >= 0 &&
             c->atlas_width <= 16384 && c->atlas_height <= 16384;
    size_t texels = ok ? (size_t)c->atlas_width * (size_t)c->atlas_height : 0;
    ok = ok && (c->atlas = malloc(4 * texels * sizeof(float) + 4)) &&
         read_all(f, c->atlas, 4 * texels * sizeof(float)) && read_all(f, &c->entry_count, 4) &&
         c->entry_count >= 0 && c->entry_count < (1 << 20) &&
         (c->entries = calloc((size_t)c->entry_count + 1, sizeof *c->entries));
    for (int i = 0; ok && i < c->entry_count; i++) {
        cache_entry *e = &c->entries[i];
        ok = read_all(f, &e->key, 8) && read_all(f, e->box, sizeof e->box) &&
             read_all(f, &e->kind, 4) && read_all(f, &e->vertex_count, 4) && e->vertex_count >= 0 &&
             e->vertex_count < (1 << 26);
        size_t floats = ok ? (size_t)e->vertex_count * (e->kind == REF_BAKE_VERTEX     ? 4
                                                        : e->kind == REF_BAKE_LIGHTMAP ? 2
                                                                                       : 0)
                           : 0;
        ok = ok && (e->data = malloc(floats * sizeof(float) + 4)) &&
             read_all(f, e->data, floats * sizeof(float));
    }
    fclose(f);
    if (!ok)
        cache_free(c);
    return ok;
}

/* Written to a temporary file in the same folder, then renamed: a reader never sees half. */
static int cache_write(const char *path, uint64_t scene, const uint64_t *keys, const ref_bake *b)
{
    char tmp[1100];
    snprintf(tmp, sizeof tmp, "%s.tmp-%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "wb");
    if (!f)
        return 0;
    size_t texels = (size_t)b->atlas_width * (size_t)b->atlas_height;
    int ok = fwrite(MAGIC, 1, 8, f) == 8 && fwrite(&scene, 8, 1, f) == 1 &&
             fwrite(&b->total_texels, 8, 1, f) == 1 && fwrite(&b->atlas_width, 4, 1, f) == 1 &&
             fwrite(&b->atlas_height, 4, 1, f) == 1 &&
             fwrite(b->atlas, sizeof(float), 4 * texels, f) == 4 * texels &&
             fwrite(&b->mesh_count, 4, 1, f) == 1;
    for (int i = 0; ok && i < b->mesh_count; i++) {
        const ref_bake_mesh *m = &b->meshes[i];
        float box[6];
        memcpy(box, m->bounds_min, 12);
        memcpy(box + 3, m->bounds_max, 12);
        int kind = (int)m->kind;
        size_t floats = (size_t)m->vertex_count * (kind == REF_BAKE_VERTEX     ? 4
                                                   : kind == REF_BAKE_LIGHTMAP ? 2
                                                                               : 0);
        const float *data = kind == REF_BAKE_VERTEX ? m->vertex : m->lightmap_uv;
        ok = fwrite(&keys[i], 8, 1, f) == 1 && fwrite(box, sizeof box, 1, f) == 1 &&
             fwrite(&kind, 4, 1, f) == 1 && fwrite(&m->vertex_count, 4, 1, f) == 1 &&
             (floats == 0 || fwrite(data, sizeof(float), floats, f) == floats);
    }
    ok = fclose(f) == 0 && ok;
    ok = ok && rename(tmp, path) == 0;
    if (!ok)
        unlink(tmp);
    return ok;
}

/* The whole bake from the file (an unchanged scene). */
static app_result bake_from_cache(const cache_file *c, ref_bake *out)
{
    memset(out, 0, sizeof *out);
    size_t texels = (size_t)c->atlas_width * (size_t)c->atlas_height;
    out->mesh_count = c->entry_count;
    out->meshes = calloc((size_t)c->entry_count + 1, sizeof *out->meshes);
    out->atlas = malloc(4 * texels * sizeof(float) + 4);
    if (!out->meshes || !out->atlas) {
        ref_bake_free(out);
        return APP_ERR_OUT_OF_MEMORY;
    }
    out->atlas_width = c->atlas_width;
    out->atlas_height = c->atlas_height;
    out->total_texels = c->total_texels;
    memcpy(out->atlas, c->atlas, 4 * texels * sizeof(float));
    for (int i = 0; i < c->entry_count; i++) {
        const cache_entry *e = &c->entries[i];
        ref_bake_mesh *m = &out->meshes[i];
        m->kind = (ref_bake_kind)e->kind;
        m->vertex_count = e->vertex_count;
        memcpy(m->bounds_min, e->box, 12);
        memcpy(m->bounds_max, e->box + 3, 12);
        int dim = e->kind == REF_BAKE_VERTEX ? 4 : e->kind == REF_BAKE_LIGHTMAP ? 2 : 0;
        if (!dim)
            continue;
        float *copy = malloc((size_t)dim * (size_t)e->vertex_count * sizeof(float) + 4);
        if (!copy) {
            ref_bake_free(out);
            return APP_ERR_OUT_OF_MEMORY;
        }
        memcpy(copy, e->data, (size_t)dim * (size_t)e->vertex_count * sizeof(float));
        if (dim == 4) {
            m->vertex = copy;
            out->total_vertices += e->vertex_count;
        } else {
            m->lightmap_uv = copy;
        }
    }
    return APP_OK;
}

/* `previous` for a partial bake: per item, the cached entry of the same key (kept), the dirty
 * boxes of what changed (new places and old ones). */
static app_result partial_setup(const app_render_list *l, const uint64_t *keys, cache_file *c,
                                ref_bake *prev, unsigned char *keep, float (*boxes)[6],
                                int *box_count, int *reused)
{
    memset(prev, 0, sizeof *prev);
    prev->mesh_count = l->item_count;
    prev->meshes = calloc((size_t)l->item_count + 1, sizeof *prev->meshes);
    if (!prev->meshes)
        return APP_ERR_OUT_OF_MEMORY;
    prev->atlas_width = c->atlas_width;
    prev->atlas_height = c->atlas_height;
    prev->atlas = c->atlas; /* borrowed */
    *box_count = 0;
    *reused = 0;
    for (int i = 0; i < l->item_count; i++) {
        keep[i] = 0;
        for (int e = 0; e < c->entry_count; e++) {
            cache_entry *ce = &c->entries[e];
            if (ce->used || ce->key != keys[i])
                continue;
            ce->used = 1;
            keep[i] = 1;
            (*reused)++;
            prev->meshes[i].kind = (ref_bake_kind)ce->kind;
            prev->meshes[i].vertex_count = ce->vertex_count;
            if (ce->kind == REF_BAKE_VERTEX)
                prev->meshes[i].vertex = ce->data; /* borrowed */
            break;
        }
        if (!keep[i])
            item_bounds(l, i, boxes[(*box_count)++]);
    }
    for (int e = 0; e < c->entry_count; e++)
        if (!c->entries[e].used && *box_count < l->item_count + c->entry_count)
            memcpy(boxes[(*box_count)++], c->entries[e].box, sizeof boxes[0]);
    return APP_OK;
}

app_result app_bake_list(const app_render_list *l, const app_bake_settings *s, ref_bake *out,
                         app_bake_stats *stats, char *err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    memset(stats, 0, sizeof *stats);
    stats->ran = 1;
    stats->elements = l->item_count;
    uint64_t base = settings_hash(s, l);
    uint64_t *keys = calloc((size_t)l->item_count + 1, sizeof *keys);
    unsigned char *lightmapped = calloc((size_t)l->item_count + 1, 1);
    unsigned char *keep = calloc((size_t)l->item_count + 1, 1);
    if (!keys || !lightmapped || !keep) {
        free(keys);
        free(lightmapped);
        free(keep);
        snprintf(err, err_size, "%s: bake: out of memory", l->path);
        return APP_ERR_OUT_OF_MEMORY;
    }
    uint64_t scene = fnv(base, "scene", 5), room = fnv(base, "room", 4);
    app_bake_item_keys(l, s, keys);
    for (int i = 0; i < l->item_count; i++) {
        /* Planar meshes get texels: the room's surfaces, and boxes and planes among the
         * objects (a bath panel, a vanity, a block), whose few vertices would stretch one
         * value over a whole face and lose the light bounced from the floor near its foot. */
        rd_shape shape = l->items[i].shape;
        lightmapped[i] = l->items[i].object < 0 || shape == RD_SHAPE_BOX || shape == RD_SHAPE_PLANE;
        scene = fnv(scene, &keys[i], 8);
        if (l->items[i].object < 0)
            room = fnv(room, &keys[i], 8);
    }
    char dir[900];
    int have_dir = cache_dir(dir, sizeof dir);
    if (have_dir)
        snprintf(stats->cache_path, sizeof stats->cache_path, "%s/bake-%016llx.bin", dir,
                 (unsigned long long)room);
    cache_file c = {0};
    int cached = have_dir && cache_read(stats->cache_path, &c);
    app_result r = APP_OK;
    if (cached && c.scene == scene && c.entry_count == l->item_count) {
        r = bake_from_cache(&c, out);
        stats->cache_hit = 1;
        stats->reused_elements = l->item_count;
        stats->total_vertices = out->total_vertices;
        stats->total_texels = out->total_texels;
        cache_free(&c);
        free(keys);
        free(lightmapped);
        free(keep);
        g_stats = *stats;
        if (r != APP_OK)
            snprintf(err, err_size, "%s: bake: out of memory", l->path);
        return r;
    }
    if (s->cache_only) {
        cache_free(&c);
        free(keys);
        free(lightmapped);
        free(keep);
        snprintf(err, err_size, "%s: bake: not in the cache", l->path);
        return APP_ERR_NOT_FOUND;
    }
    ref_scene *rs = NULL;
    r = app_ref_scene_from_list(l, &rs, err, err_size);
    if (r == APP_OK && s->progress_fn && s->progress_fn(s->progress_user, 0, 1))
        r = APP_ERR_CANCELLED; /* superseded while the tracer's scene was made */
    ref_bake prev = {0};
    float(*boxes)[6] = NULL;
    int box_count = 0;
    ref_bake_desc d = {.samples = s->samples,
                       .passes = s->bounces,
                       .progress = s->progress,
                       .lightmapped = lightmapped,
                       .reach_m = APP_BAKE_REACH_M,
                       .progress_fn = s->progress_fn,
                       .progress_user = s->progress_user};
    if (r == APP_OK && cached) {
        boxes = calloc((size_t)(l->item_count + c.entry_count) + 1, sizeof *boxes);
        if (!boxes || partial_setup(l, keys, &c, &prev, keep, boxes, &box_count,
                                    &stats->reused_elements) != APP_OK)
            r = APP_ERR_OUT_OF_MEMORY;
        d.previous = &prev;
        d.keep = keep;
        d.dirty_boxes = (const float(*)[6])boxes;
        d.dirty_box_count = box_count;
    }
    ref_result rr = REF_OK;
    if (r == APP_OK) {
        rr = ref_bake_run(rs, &d, out);
        if (rr == REF_ERR_INVALID_ARGUMENT && d.previous) { /* another layout: bake it all */
            d.previous = NULL;
            d.keep = NULL;
            d.dirty_box_count = 0;
            stats->reused_elements = 0;
            rr = ref_bake_run(rs, &d, out);
        }
        if (rr != REF_OK) {
            snprintf(err, err_size, "%s: bake: %s", l->path, ref_last_error());
            r = rr == REF_ERR_OUT_OF_MEMORY ? APP_ERR_OUT_OF_MEMORY
                : rr == REF_ERR_CANCELLED   ? APP_ERR_CANCELLED
                                            : APP_ERR_SCHEMA;
        }
    }
    if (r == APP_OK) {
        stats->baked_texels = out->baked_texels;
        stats->baked_vertices = out->baked_vertices;
        stats->total_texels = out->total_texels;
        stats->total_vertices = out->total_vertices;
        stats->rays = out->rays;
        stats->seconds = out->seconds;
        if (have_dir && (!make_dirs(dir) || !cache_write(stats->cache_path, scene, keys, out)))
            fprintf(stderr, "tessera: warning: %s: cannot write the bake cache: %s\n",
                    stats->cache_path, strerror(errno));
    }
    free(prev.meshes); /* its arrays are borrowed from the cache */
    free(boxes);
    cache_free(&c);
    ref_scene_destroy(rs);
    free(keys);
    free(lightmapped);
    free(keep);
    g_stats = *stats;
    return r;
}

void app_bake_item_keys(const app_render_list *l, const app_bake_settings *s, uint64_t *keys)
{
    uint64_t base = settings_hash(s, l);
    for (int i = 0; i < l->item_count; i++)
        keys[i] = item_hash(l, i, base);
}

static int carry_floats(const ref_bake_mesh *m)
{
    return m->kind == REF_BAKE_VERTEX ? 4 : m->kind == REF_BAKE_LIGHTMAP ? 2 : 0;
}

app_result app_bake_carry(const ref_bake *old, const uint64_t *old_keys, int new_count,
                          const uint64_t *keys, ref_bake *out)
{
    memset(out, 0, sizeof *out);
    size_t texels = (size_t)old->atlas_width * (size_t)old->atlas_height;
    unsigned char *taken = calloc((size_t)old->mesh_count + 1, 1);
    out->meshes = calloc((size_t)new_count + 1, sizeof *out->meshes);
    out->atlas = malloc(4 * texels * sizeof(float) + 4);
    if (!taken || !out->meshes || !out->atlas) {
        free(taken);
        ref_bake_free(out);
        return APP_ERR_OUT_OF_MEMORY;
    }
    out->mesh_count = new_count;
    out->atlas_width = old->atlas_width;
    out->atlas_height = old->atlas_height;
    if (texels)
        memcpy(out->atlas, old->atlas, 4 * texels * sizeof(float));
    int *source = malloc(((size_t)new_count + 1) * sizeof *source);
    if (!source) {
        free(taken);
        ref_bake_free(out);
        return APP_ERR_OUT_OF_MEMORY;
    }
    /* Same key first, for every item, so an item that only moved in the list is not taken by
     * the index rule of another. */
    for (int i = 0; i < new_count; i++) {
        source[i] = -1;
        for (int j = 0; j < old->mesh_count; j++)
            if (!taken[j] && old_keys[j] == keys[i] && carry_floats(&old->meshes[j])) {
                source[i] = j;
                taken[j] = 1;
                break;
            }
    }
    app_result r = APP_OK;
    for (int i = 0; i < new_count && r == APP_OK; i++) {
        int j = source[i];
        if (j < 0 && i < old->mesh_count && !taken[i] && carry_floats(&old->meshes[i])) {
            j = i;
            taken[i] = 1;
        }
        if (j < 0)
            continue;
        const ref_bake_mesh *from = &old->meshes[j];
        ref_bake_mesh *to = &out->meshes[i];
        size_t n = (size_t)carry_floats(from) * (size_t)from->vertex_count;
        float *copy = malloc(n * sizeof(float) + 4);
        if (!copy) {
            r = APP_ERR_OUT_OF_MEMORY;
            break;
        }
        memcpy(copy, from->kind == REF_BAKE_VERTEX ? from->vertex : from->lightmap_uv,
               n * sizeof(float));
        to->kind = from->kind;
        to->vertex_count = from->vertex_count;
        if (from->kind == REF_BAKE_VERTEX)
            to->vertex = copy;
        else
            to->lightmap_uv = copy;
        memcpy(to->bounds_min, from->bounds_min, sizeof to->bounds_min);
        memcpy(to->bounds_max, from->bounds_max, sizeof to->bounds_max);
    }
    free(source);
    free(taken);
    if (r != APP_OK)
        ref_bake_free(out);
    return r;
}
