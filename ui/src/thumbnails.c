/* Lazy product thumbnails (ui/src/thumbnails.h). */
#include "thumbnails.h"

/* The studio of `tessera catalog thumbs`; app keeps its header beside its sources. */
#include "app/scene/thumb_scene.h"
#include "app/design/placement.h"
#include "render/ui_texture.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void ui_thumbnails_init(ui_thumbnails *t, rd_context *ctx)
{
    memset(t, 0, sizeof *t);
    t->ctx = ctx;
}

void ui_thumbnails_free(ui_thumbnails *t)
{
    for (int i = 0; i < t->count; i++)
        rd_ui_texture_delete(t->ctx, t->items[i].texture);
    if (t->studio) {
        thumb_studio_free(t->studio);
        free(t->studio);
    }
    memset(t, 0, sizeof *t);
}

static ui_thumb *slot(ui_thumbnails *t, long long id)
{
    for (int i = 0; i < t->count; i++)
        if (t->items[i].product_id == id)
            return &t->items[i];
    if (t->count < UI_THUMB_CACHE) {
        ui_thumb *s = &t->items[t->count++];
        memset(s, 0, sizeof *s);
        s->product_id = id;
        return s;
    }
    /* Full: reuse the one shown longest ago (never one asked for this frame). */
    ui_thumb *old = NULL;
    for (int i = 0; i < t->count; i++)
        if (t->items[i].last_used < t->frame && (!old || t->items[i].last_used < old->last_used))
            old = &t->items[i];
    if (!old)
        return NULL;
    rd_ui_texture_delete(t->ctx, old->texture);
    memset(old, 0, sizeof *old);
    old->product_id = id;
    return old;
}

unsigned ui_thumbnails_get(ui_thumbnails *t, long long product_id, int want)
{
    if (!t || !t->ctx)
        return 0;
    for (int i = 0; i < t->count; i++)
        if (t->items[i].product_id == product_id) {
            t->items[i].last_used = t->frame;
            return t->items[i].state == 1 ? t->items[i].texture : 0;
        }
    if (!want || t->studio_failed)
        return 0;
    ui_thumb *s = slot(t, product_id);
    if (s)
        s->last_used = t->frame;
    return 0;
}

int ui_thumbnails_pending(const ui_thumbnails *t)
{
    int n = 0;
    for (int i = 0; i < t->count; i++)
        n += t->items[i].state == 0;
    return n;
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

static void fail(ui_thumbnails *t, ui_thumb *s, const char *why)
{
    s->state = 2;
    if (!t->error[0])
        snprintf(t->error, sizeof t->error, "%.500s", why);
}

int ui_thumbnails_update(ui_thumbnails *t, cat_db *db, int max)
{
    t->frame++;
    if (!t->ctx || !db || t->studio_failed)
        return 0;
    int done = 0;
    char err[1024];
    for (int i = 0; i < t->count && done < max; i++) {
        ui_thumb *s = &t->items[i];
        if (s->state != 0)
            continue;
        if (!t->studio) {
            thumb_studio *st = calloc(1, sizeof *st);
            if (!st ||
                !thumb_studio_init(st, t->ctx, app_placement_assets_dir(), err, sizeof err)) {
                snprintf(t->error, sizeof t->error, "%.500s",
                         st ? err : "thumbnails: out of memory");
                free(st);
                t->studio_failed = 1;
                return done;
            }
            st->supersample = 2;
            t->studio = st;
        }
        double t0 = now_ms();
        cat_product p;
        uint8_t rgba[UI_THUMB_SIZE * UI_THUMB_SIZE * 4];
        thumb_source source;
        if (cat_product_get(db, s->product_id, &p, err, sizeof err) != CAT_DB_OK) {
            fail(t, s, err);
            continue;
        }
        int ok =
            thumb_render(t->studio, &p, UI_THUMB_SIZE, rgba, &source, NULL, 0, err, sizeof err);
        cat_product_free(&p);
        if (!ok) {
            fail(t, s, err);
            continue;
        }
        if (rd_ui_texture_upload(t->ctx, UI_THUMB_SIZE, UI_THUMB_SIZE, rgba, &s->texture) !=
            RD_OK) {
            fail(t, s, rd_last_error());
            continue;
        }
        s->state = 1;
        t->rendered++;
        t->total_ms += now_ms() - t0;
        done++;
    }
    return done;
}
