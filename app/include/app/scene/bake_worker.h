/* The bake on a thread of its own (docs/rendering.md, "Baked indirect light", "In the window"):
 * the window hands it the render list its scene was built from and keeps drawing; the worker
 * bakes it through the cache (scene_bake.h) and hands back the list with its light. Each job
 * carries a generation: a newer one (an edit) stops an older job that is running (the bake is
 * cancelled between points) and replaces one that waits, and the result of an older job is
 * dropped, never handed back. One job runs at a time, at a lower priority than the window.
 * No GL here: the caller uploads the result on its own thread. */
#ifndef APP_SCENE_BAKE_WORKER_H
#define APP_SCENE_BAKE_WORKER_H

#include "app/scene/render_list.h"
#include "app/scene/scene_bake.h"
#include "ref/ref_bake.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct app_bake_worker app_bake_worker;

/* A finished job. */
typedef struct app_bake_done {
    unsigned generation;
    app_result result;    /* APP_OK: bake holds the light of list's items */
    app_render_list list; /* the list as it was submitted, back to the caller */
    ref_bake bake;
    uint64_t *keys; /* list.item_count keys (app_bake_item_keys), for app_bake_carry */
    app_bake_stats stats;
    char error[1200]; /* the list's path and why */
} app_bake_done;

/* A worker baking with settings s (samples, bounces; its own progress). wake(user) is called
 * from the worker's thread whenever a job ended (a window posts itself an event, so a window
 * waiting for input takes the light at once); NULL = none. NULL when the thread cannot
 * start. */
app_bake_worker *app_bake_worker_create(const app_bake_settings *s, void (*wake)(void *user),
                                        void *wake_user);
/* Stops the running job, waits for the thread and frees everything it holds. */
void app_bake_worker_destroy(app_bake_worker *w);

/* Jobs older than generation stop (running) or go (waiting); their results are dropped. Call
 * on every edit, before the new list is ready to submit. Generations only grow. */
void app_bake_worker_supersede(app_bake_worker *w, unsigned generation);
/* Bakes *list as job `generation` (>= every generation seen); the worker takes the list
 * (*list is zeroed). */
void app_bake_worker_submit(app_bake_worker *w, app_render_list *list, unsigned generation);

/* 1 while a job waits, runs or has finished without being taken, with the running job's
 * share done (0..1) in *fraction. */
int app_bake_worker_busy(app_bake_worker *w, float *fraction);
/* 1 when a job of the newest generation finished: *out takes it (app_bake_done_free). */
int app_bake_worker_take(app_bake_worker *w, app_bake_done *out);
void app_bake_done_free(app_bake_done *d);

#ifdef __cplusplus
}
#endif
#endif
