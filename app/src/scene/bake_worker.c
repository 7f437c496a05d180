/* The bake on its own thread (bake_worker.h). The window's thread and the worker share three
 * things under one mutex: the job waiting (the newest list), the finished job, and the quit
 * flag; the newest generation and the progress are atomics, read by the bake's own threads
 * between points (progress_fn) to know they were superseded. */
#define _GNU_SOURCE /* gettid */
#include "app/scene/bake_worker.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

/* The window draws while the bake runs on both cores: the bake yields to it (nice 0 -> 10
 * halves its share against a busy window thread several times over; Linux nice weights). */
#define WORKER_NICE 10

typedef struct bake_job {
    unsigned generation;
    app_render_list list;
} bake_job;

struct app_bake_worker {
    app_bake_settings settings;
    void (*wake)(void *user);
    void *wake_user;
    pthread_t thread;
    pthread_mutex_t lock;
    pthread_cond_t work;
    /* under lock */
    bake_job *waiting;
    app_bake_done *done;
    int running, quit;
    /* atomics */
    atomic_uint newest; /* generations older than this stop */
    atomic_uint running_generation;
    atomic_llong points_done, points_total;
};

static void job_free(bake_job *j)
{
    if (j) {
        app_render_list_free(&j->list);
        free(j);
    }
}

void app_bake_done_free(app_bake_done *d)
{
    if (!d)
        return;
    app_render_list_free(&d->list);
    ref_bake_free(&d->bake);
    free(d->keys);
    memset(d, 0, sizeof *d);
}

/* Called by the bake's threads between points: store the progress, stop when superseded. */
static int progress(void *user, long long done, long long total)
{
    app_bake_worker *w = user;
    atomic_store(&w->points_done, done);
    atomic_store(&w->points_total, total);
    unsigned mine = atomic_load(&w->running_generation);
    return atomic_load(&w->newest) != mine;
}

static app_bake_done *run_job(app_bake_worker *w, bake_job *j)
{
    app_bake_done *d = calloc(1, sizeof *d);
    if (!d)
        return NULL;
    d->generation = j->generation;
    d->list = j->list;
    memset(&j->list, 0, sizeof j->list);
    d->keys = calloc((size_t)d->list.item_count + 1, sizeof *d->keys);
    if (!d->keys) {
        d->result = APP_ERR_OUT_OF_MEMORY;
        snprintf(d->error, sizeof d->error, "%s: bake: out of memory", d->list.path);
        return d;
    }
    app_bake_settings s = w->settings;
    app_bake_item_keys(&d->list, &s, d->keys);
    d->result = app_bake_list(&d->list, &s, &d->bake, &d->stats, d->error, sizeof d->error);
    return d;
}

static void *worker_main(void *arg)
{
    app_bake_worker *w = arg;
    /* Per thread on Linux, and inherited by the threads the bake starts. */
    if (setpriority(PRIO_PROCESS, (id_t)gettid(), WORKER_NICE) != 0)
        perror("tessera: bake worker: setpriority");
    pthread_mutex_lock(&w->lock);
    for (;;) {
        while (!w->quit && !w->waiting)
            pthread_cond_wait(&w->work, &w->lock);
        if (w->quit)
            break;
        bake_job *j = w->waiting;
        w->waiting = NULL;
        w->running = 1;
        atomic_store(&w->running_generation, j->generation);
        atomic_store(&w->points_done, 0);
        atomic_store(&w->points_total, 0);
        pthread_mutex_unlock(&w->lock);

        app_bake_done *d = run_job(w, j);
        job_free(j);

        pthread_mutex_lock(&w->lock);
        w->running = 0;
        int current = d && d->result != APP_ERR_CANCELLED &&
                      d->generation == atomic_load(&w->newest) && !w->quit;
        if (current) {
            if (w->done)
                app_bake_done_free(w->done);
            free(w->done);
            w->done = d;
        } else if (d) {
            app_bake_done_free(d);
            free(d);
        }
        pthread_mutex_unlock(&w->lock);
        if (w->wake)
            w->wake(w->wake_user);
        pthread_mutex_lock(&w->lock);
    }
    pthread_mutex_unlock(&w->lock);
    return NULL;
}

app_bake_worker *app_bake_worker_create(const app_bake_settings *s, void (*wake)(void *user),
                                        void *wake_user)
{
    app_bake_worker *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    w->settings = s ? *s : (app_bake_settings){0};
    w->settings.on = 1;
    w->settings.progress = 0; /* the window shows it; no bar on its terminal */
    w->settings.progress_fn = progress;
    w->settings.progress_user = w;
    w->wake = wake;
    w->wake_user = wake_user;
    atomic_init(&w->newest, 0);
    atomic_init(&w->running_generation, 0);
    atomic_init(&w->points_done, 0);
    atomic_init(&w->points_total, 0);
    if (pthread_mutex_init(&w->lock, NULL) != 0) {
        free(w);
        return NULL;
    }
    if (pthread_cond_init(&w->work, NULL) != 0 ||
        pthread_create(&w->thread, NULL, worker_main, w) != 0) {
        pthread_mutex_destroy(&w->lock);
        free(w);
        return NULL;
    }
    return w;
}

void app_bake_worker_destroy(app_bake_worker *w)
{
    if (!w)
        return;
    pthread_mutex_lock(&w->lock);
    w->quit = 1;
    atomic_fetch_add(&w->newest, 1); /* the running bake stops at its next points */
    pthread_cond_signal(&w->work);
    pthread_mutex_unlock(&w->lock);
    pthread_join(w->thread, NULL);
    job_free(w->waiting);
    if (w->done)
        app_bake_done_free(w->done);
    free(w->done);
    pthread_cond_destroy(&w->work);
    pthread_mutex_destroy(&w->lock);
    free(w);
}

void app_bake_worker_supersede(app_bake_worker *w, unsigned generation)
{
    pthread_mutex_lock(&w->lock);
    if (generation > atomic_load(&w->newest))
        atomic_store(&w->newest, generation);
    bake_job *stale = NULL;
    if (w->waiting && w->waiting->generation < generation) {
        stale = w->waiting;
        w->waiting = NULL;
    }
    if (w->done && w->done->generation < generation) {
        app_bake_done_free(w->done);
        free(w->done);
        w->done = NULL;
    }
    pthread_mutex_unlock(&w->lock);
    job_free(stale); /* a list's models are freed outside the lock */
}

void app_bake_worker_submit(app_bake_worker *w, app_render_list *list, unsigned generation)
{
    bake_job *j = calloc(1, sizeof *j);
    if (!j) {
        app_render_list_free(list);
        return;
    }
    j->generation = generation;
    j->list = *list;
    memset(list, 0, sizeof *list);
    app_bake_worker_supersede(w, generation);
    pthread_mutex_lock(&w->lock);
    bake_job *stale = w->waiting;
    w->waiting = j;
    pthread_cond_signal(&w->work);
    pthread_mutex_unlock(&w->lock);
    job_free(stale);
}

int app_bake_worker_busy(app_bake_worker *w, float *fraction)
{
    pthread_mutex_lock(&w->lock);
    int busy = w->running || w->waiting || w->done; /* done: not taken yet */
    int running = w->running;
    pthread_mutex_unlock(&w->lock);
    if (fraction) {
        long long done = atomic_load(&w->points_done), total = atomic_load(&w->points_total);
        *fraction = running && total > 0 ? (float)((double)done / (double)total) : 0.0f;
    }
    return busy;
}

int app_bake_worker_take(app_bake_worker *w, app_bake_done *out)
{
    pthread_mutex_lock(&w->lock);
    app_bake_done *d = w->done;
    if (d && d->generation != atomic_load(&w->newest)) {
        app_bake_done_free(d);
        free(d);
        d = NULL;
    }
    w->done = NULL;
    pthread_mutex_unlock(&w->lock);
    if (!d)
        return 0;
    *out = *d;
    free(d);
    return 1;
}
