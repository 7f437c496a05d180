/* The window's baked light, off the frame loop (docs/rendering.md, "Baked indirect light"):
 * an edit rebuilds the scene at once with the light it had (app_bake_carry: every unchanged
 * item keeps its values, a moved fixture the light of where it was), and once the edits have
 * settled for SETTLE_S the render list goes to the bake worker (app/scene/bake_worker.h). The
 * frames go on meanwhile; the status bar shows the share done. The finished light is swapped
 * into the scene on this (the GL) thread and the still view crossfades from the old picture
 * to the new over FADE_S. An edit while a bake runs stops it (a newer generation). */
#include "planner.h"

#include "app/scene/bake_worker.h"

#include <GLFW/glfw3.h>
#include <stdlib.h>
#include <string.h>

/* Edits in a row (a drag's steps, typing a length) bake once, after the last. */
#define SETTLE_S 0.4
#define FADE_S 0.5

struct planner_bake {
    app_bake_worker *worker;
    unsigned generation;
    /* The list of the scene on screen, not yet handed to the worker (settling). */
    app_render_list waiting;
    int has_waiting;
    double settle_at;
    /* The light on screen (what the next rebuild carries) and its items' keys. */
    ref_bake light;
    uint64_t *keys;
    int has_light;
    /* The crossfade: the picture with the old light, and when the new one arrived. */
    unsigned char *from;
    int from_w, from_h;
    double fade_start;
    int fading;
    unsigned char *mix;
    size_t mix_size;
    int hold; /* a script keeps the bake from starting */
};

static void wake_window(void *user)
{
    (void)user;
    glfwPostEmptyEvent(); /* GLFW: callable from any thread */
}

static void forget_light(struct planner_bake *b)
{
    if (b->has_light)
        ref_bake_free(&b->light);
    free(b->keys);
    b->keys = NULL;
    b->has_light = 0;
}

int planner_bake_start(planner *p)
{
    if (!app_bake_current()->on)
        return 0;
    struct planner_bake *b = calloc(1, sizeof *b);
    if (!b) {
        fprintf(stderr, "tessera: out of memory for the bake\n");
        return 1;
    }
    b->worker = app_bake_worker_create(app_bake_current(), wake_window, NULL);
    if (!b->worker) {
        fprintf(stderr, "tessera: the bake's thread did not start\n");
        free(b);
        return 1;
    }
    p->bake = b;
    return 0;
}

void planner_bake_free(planner *p)
{
    struct planner_bake *b = p->bake;
    if (!b)
        return;
    app_bake_worker_destroy(b->worker);
    if (b->has_waiting)
        app_render_list_free(&b->waiting);
    forget_light(b);
    free(b->from);
    free(b->mix);
    free(b);
    p->bake = NULL;
}

/* A document's first light, when the cache holds its whole scene: read on this thread without
 * a ray (a few milliseconds), so the window opens lit. 1 when it did. */
static int light_from_cache(struct planner_bake *b, const app_render_list *l)
{
    app_bake_settings s = *app_bake_current();
    s.cache_only = 1;
    s.progress = 0;
    app_bake_stats stats;
    char err[1100];
    uint64_t *keys = calloc((size_t)l->item_count + 1, sizeof *keys);
    if (!keys || app_bake_list(l, &s, &b->light, &stats, err, sizeof err) != APP_OK) {
        free(keys);
        return 0;
    }
    app_bake_item_keys(l, &s, keys);
    b->keys = keys;
    b->has_light = 1;
    fprintf(stderr, "tessera: light: %d elements from the cache\n", stats.elements);
    return 1;
}

void planner_bake_forget(planner *p)
{
    if (p->bake)
        forget_light(p->bake);
}

int planner_scene_build(planner *p, char *err, size_t err_size)
{
    struct planner_bake *b = p->bake;
    if (!b)
        return app_scene_build(p->ctx, &p->project, &p->scene, err, err_size) != APP_OK;
    /* A bake of an older document is of no use any more. */
    app_bake_worker_supersede(b->worker, ++b->generation);
    if (b->has_waiting) {
        app_render_list_free(&b->waiting);
        b->has_waiting = 0;
    }
    app_render_list l;
    if (app_render_list_build(&p->project, APP_RENDER_LIST_PROBE_MESHES, &l, err, err_size) !=
        APP_OK)
        return 1;
    ref_bake carried = {0};
    int carry = 0;
    int whole = !b->has_light && light_from_cache(b, &l); /* then nothing to bake */
    if (b->has_light) {
        uint64_t *keys = calloc((size_t)l.item_count + 1, sizeof *keys);
        if (keys) {
            app_bake_item_keys(&l, app_bake_current(), keys);
            carry = app_bake_carry(&b->light, b->keys, l.item_count, keys, &carried) == APP_OK;
        }
        free(keys);
    }
    int failed = app_scene_build_from_list(p->ctx, &l, carry ? &carried : NULL, &p->scene, err,
                                           err_size) != APP_OK;
    if (carry)
        ref_bake_free(&carried);
    if (failed) {
        app_render_list_free(&l);
        return 1;
    }
    if (whole) {
        app_render_list_free(&l);
        return 0;
    }
    b->waiting = l;
    b->has_waiting = 1;
    /* The first light of a document is baked at once; edits wait until they settle. */
    b->settle_at = glfwGetTime() + (b->has_light ? SETTLE_S : 0.0);
    return 0;
}

/* The still view's picture now, kept to fade from (none while the view moves). */
static void keep_fade_source(planner *p, struct planner_bake *b)
{
    const ui_accum *a = &p->live.accum;
    b->fading = 0;
    if (!p->live.still || !a->image || a->width <= 0 || a->height <= 0)
        return;
    size_t size = (size_t)a->width * (size_t)a->height * 4;
    if (b->from_w * b->from_h * 4 != (int)size) {
        free(b->from);
        b->from = malloc(size);
        b->from_w = b->from ? a->width : 0;
        b->from_h = b->from ? a->height : 0;
    }
    if (!b->from)
        return;
    memcpy(b->from, a->image, size);
    b->fading = 1;
    b->fade_start = glfwGetTime();
}

static void apply_done(planner *p, struct planner_bake *b, app_bake_done *d)
{
    char err[1100];
    if (d->result != APP_OK) {
        planner_status(p, "light: %s", d->error);
        return;
    }
    if (!p->scene_ready)
        return;
    keep_fade_source(p, b);
    if (app_scene_apply_bake(p->ctx, &p->scene, &d->list, &d->bake, err, sizeof err) != APP_OK) {
        b->fading = 0;
        planner_status(p, "light: %s", err);
        return;
    }
    /* The light on screen is this bake's: later edits carry it. */
    forget_light(b);
    b->light = d->bake;
    memset(&d->bake, 0, sizeof d->bake);
    b->keys = d->keys;
    d->keys = NULL;
    b->has_light = 1;
    fprintf(stderr,
            "tessera: light: baked %lld texels and %lld vertices (%d of %d elements from the "
            "cache) in %.2f s\n",
            d->stats.baked_texels, d->stats.baked_vertices, d->stats.reused_elements,
            d->stats.elements, d->stats.seconds);
    planner_live_restart(p);
}

void planner_bake_frame(planner *p)
{
    struct planner_bake *b = p->bake;
    if (!b)
        return;
    double now = glfwGetTime();
    if (b->has_waiting && now >= b->settle_at && !b->hold) {
        app_bake_worker_submit(b->worker, &b->waiting, b->generation);
        b->has_waiting = 0;
    }
    app_bake_done d;
    if (app_bake_worker_take(b->worker, &d)) {
        apply_done(p, b, &d);
        app_bake_done_free(&d);
    }
    if (b->fading && now - b->fade_start >= FADE_S)
        b->fading = 0;
}

int planner_bake_busy(const planner *p)
{
    const struct planner_bake *b = p->bake;
    return b && (b->has_waiting || app_bake_worker_busy(b->worker, NULL));
}

int planner_bake_settled(const planner *p)
{
    return !planner_bake_busy(p) && !(p->bake && p->bake->fading);
}

void planner_bake_hold(planner *p, int hold)
{
    if (p->bake)
        p->bake->hold = hold;
}

int planner_bake_status(const planner *p, char *out, size_t size)
{
    const struct planner_bake *b = p->bake;
    float done = 0;
    if (!b)
        return 0;
    if (b->has_waiting)
        snprintf(out, size, "Light: waiting for the edits to settle");
    else if (app_bake_worker_busy(b->worker, &done))
        snprintf(out, size, "Light: baking %.0f %%", 100.0f * done);
    else
        return 0;
    return 1;
}

int planner_bake_fading(const planner *p)
{
    return p->bake && p->bake->fading;
}

void planner_bake_fade_stop(planner *p)
{
    if (p->bake)
        p->bake->fading = 0;
}

const unsigned char *planner_bake_fade(planner *p, const unsigned char *image, int w, int h)
{
    struct planner_bake *b = p->bake;
    if (!b || !b->fading || b->from_w != w || b->from_h != h)
        return image;
    /* The old picture's weight falls from 1 to 0 (a linear crossfade in display values). */
    float t = (float)((glfwGetTime() - b->fade_start) / FADE_S);
    int old = (int)(256.0f * (1.0f - (t < 0 ? 0 : t > 1 ? 1 : t)));
    size_t size = (size_t)w * (size_t)h * 4;
    if (size > b->mix_size) {
        free(b->mix);
        b->mix = malloc(size);
        b->mix_size = b->mix ? size : 0;
    }
    if (!b->mix)
        return image;
    for (size_t i = 0; i < size; i++)
        b->mix[i] = (unsigned char)((b->from[i] * old + image[i] * (256 - old)) >> 8);
    return b->mix;
}
