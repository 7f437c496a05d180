/* The bake on its own thread (app/scene/bake_worker.h) and the light carried across an edit
 * (app_bake_carry), on a small room (tests/cli/data/minimal.json: walls, a ball, a lamp) at a
 * few rays a point: a job's light comes back with its list; a newer job replaces one that
 * waits and only the newest result is handed back; a running bake stops soon after it is
 * superseded (within 5 s, where the whole bake takes minutes) and hands nothing back; destroying a
 * worker in the middle of a bake returns. No GL: runs in the sanitizer build (and under
 * ThreadSanitizer by hand, docs/rendering.md). */
#define _GNU_SOURCE /* mkdtemp, setenv */
#include "app/project/commands.h"
#include "app/project/project.h"
#include "app/scene/bake_worker.h"
#include "app/scene/render_list.h"
#include "app/scene/scene_bake.h"
#include "../common/check.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define MINIMAL TESSERA_SOURCE_DIR "/tests/cli/data/minimal.json"

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int build_list(const app_project *p, app_render_list *l)
{
    char err[1024];
    app_result r = app_render_list_build(p, APP_RENDER_LIST_PROBE_MESHES, l, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    return r == APP_OK;
}

/* Waits up to `seconds` for a finished job; 1 when one was taken. */
static int wait_take(app_bake_worker *w, app_bake_done *d, double seconds)
{
    double end = now_s() + seconds;
    while (now_s() < end) {
        if (app_bake_worker_take(w, d))
            return 1;
        usleep(5000);
    }
    return 0;
}

static int wait_idle(app_bake_worker *w, double seconds)
{
    double end = now_s() + seconds;
    while (now_s() < end) {
        if (!app_bake_worker_busy(w, NULL))
            return 1;
        usleep(5000);
    }
    return 0;
}

static int ball_index(const app_project *p)
{
    for (int i = 0; i < p->object_count; i++)
        if (!strcmp(p->objects[i].name, "ball"))
            return i;
    return -1;
}

/* Every value of a job's light is finite and the lit items have some. */
static void check_light(const app_bake_done *d)
{
    CHECK(d->result == APP_OK);
    CHECK(d->bake.mesh_count == d->list.item_count);
    CHECK(d->keys != NULL);
    int lit = 0, finite = 1;
    for (int i = 0; i < d->bake.mesh_count; i++) {
        const ref_bake_mesh *m = &d->bake.meshes[i];
        lit += m->kind != REF_BAKE_NONE;
        for (int v = 0; m->kind == REF_BAKE_VERTEX && v < 4 * m->vertex_count; v++)
            finite &= isfinite(m->vertex[v]) && m->vertex[v] >= 0.0f;
    }
    double sum = 0;
    for (long t = 0; t < 4L * d->bake.atlas_width * d->bake.atlas_height; t++) {
        finite &= isfinite(d->bake.atlas[t]) != 0;
        sum += d->bake.atlas[t];
    }
    CHECK(lit > 0);
    CHECK(finite);
    CHECK(sum > 0.0);
}

/* The ball moved: every other item keeps its values exactly, the ball keeps its own (the same
 * mesh), and an item the old bake never saw gets none. */
static void check_carry(const app_bake_done *d, app_project *p)
{
    int ball = ball_index(p);
    CHECK(ball >= 0);
    if (ball < 0)
        return;
    p->objects[ball].position_mm[0] += 300.0;
    app_render_list moved;
    if (!build_list(p, &moved))
        return;
    uint64_t *keys = calloc((size_t)moved.item_count + 1, sizeof *keys);
    app_bake_settings s = {.on = 1, .samples = 8, .bounces = 1};
    app_bake_item_keys(&moved, &s, keys);
    int changed = 0, same = 0;
    for (int i = 0; i < moved.item_count && i < d->list.item_count; i++) {
        changed += keys[i] != d->keys[i];
        same += keys[i] == d->keys[i];
    }
    CHECK_MSG(changed >= 1 && same >= 1, "%d items changed, %d kept", changed, same);
    ref_bake carried;
    CHECK(app_bake_carry(&d->bake, d->keys, moved.item_count, keys, &carried) == APP_OK);
    CHECK(carried.mesh_count == moved.item_count);
    CHECK(carried.atlas_width == d->bake.atlas_width);
    CHECK(!memcmp(carried.atlas, d->bake.atlas,
                  4 * sizeof(float) * (size_t)d->bake.atlas_width * (size_t)d->bake.atlas_height));
    for (int i = 0; i < carried.mesh_count; i++) {
        const ref_bake_mesh *a = &carried.meshes[i], *b = &d->bake.meshes[i];
        CHECK(a->kind == b->kind && a->vertex_count == b->vertex_count);
        if (a->kind == REF_BAKE_VERTEX)
            CHECK(!memcmp(a->vertex, b->vertex, 4 * sizeof(float) * (size_t)a->vertex_count));
        if (a->kind == REF_BAKE_LIGHTMAP)
            CHECK(!memcmp(a->lightmap_uv, b->lightmap_uv,
                          2 * sizeof(float) * (size_t)a->vertex_count));
    }
    ref_bake_free(&carried);
    /* One more item than the old bake had: it gets nothing. */
    uint64_t *more = calloc((size_t)moved.item_count + 2, sizeof *more);
    memcpy(more, keys, sizeof *keys * (size_t)moved.item_count);
    more[moved.item_count] = 12345;
    CHECK(app_bake_carry(&d->bake, d->keys, moved.item_count + 1, more, &carried) == APP_OK);
    CHECK(carried.meshes[moved.item_count].kind == REF_BAKE_NONE);
    ref_bake_free(&carried);
    free(more);
    free(keys);
    app_render_list_free(&moved);
    p->objects[ball].position_mm[0] -= 300.0;
}

int main(void)
{
    char dir[] = "/tmp/tessera-bake-worker-XXXXXX";
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    setenv("XDG_CACHE_HOME", dir, 1);
    app_project p;
    char err[1024];
    if (app_project_read(MINIMAL, &p, err, sizeof err) != APP_OK) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }

    /* A job's light comes back with its list. */
    app_bake_worker *w =
        app_bake_worker_create(&(app_bake_settings){.samples = 8, .bounces = 1}, NULL, NULL);
    CHECK(w != NULL);
    app_render_list l;
    if (!w || !build_list(&p, &l))
        return check_report("bake_worker");
    int items = l.item_count;
    app_bake_worker_submit(w, &l, 1);
    CHECK(l.items == NULL); /* taken */
    CHECK(app_bake_worker_busy(w, NULL));
    app_bake_done d;
    CHECK(wait_take(w, &d, 60.0));
    CHECK(d.generation == 1);
    CHECK(d.list.item_count == items);
    check_light(&d);
    check_carry(&d, &p);
    app_bake_done_free(&d);

    /* Two jobs in a row: the second replaces the first, only its result comes back. */
    app_render_list a, b;
    if (build_list(&p, &a) && build_list(&p, &b)) {
        app_bake_worker_submit(w, &a, 2);
        app_bake_worker_submit(w, &b, 3);
        CHECK(wait_take(w, &d, 60.0));
        CHECK(d.generation == 3);
        app_bake_done_free(&d);
        CHECK(wait_idle(w, 60.0));
        CHECK(!app_bake_worker_take(w, &d));
    }
    app_bake_worker_destroy(w);

    /* A long bake (many rays a point, not in the cache) stops soon after an edit supersedes it,
     * and hands nothing back. */
    w = app_bake_worker_create(&(app_bake_settings){.samples = 4096, .bounces = 4}, NULL, NULL);
    CHECK(w != NULL);
    if (w && build_list(&p, &l)) {
        app_bake_worker_submit(w, &l, 1);
        float done = 0;
        double end = now_s() + 60.0;
        while (now_s() < end && app_bake_worker_busy(w, &done) && done <= 0.0f)
            usleep(2000);
        CHECK_MSG(done > 0.0f && done < 1.0f, "the bake's share done: %.3f", done);
        double t0 = now_s();
        app_bake_worker_supersede(w, 2);
        CHECK(wait_idle(w, 10.0));
        double stop_s = now_s() - t0;
        printf("a superseded bake stopped in %.3f s (at %.0f %% done)\n", stop_s, 100.0 * done);
        CHECK_MSG(stop_s < 5.0, "%.3f s to stop", stop_s);
        CHECK(!app_bake_worker_take(w, &d));
    }
    /* Destroyed in the middle of a bake: it stops and returns. */
    if (w && build_list(&p, &l)) {
        app_bake_worker_submit(w, &l, 3);
        float done = 0;
        double end = now_s() + 60.0;
        while (now_s() < end && app_bake_worker_busy(w, &done) && done <= 0.0f)
            usleep(2000);
        double t0 = now_s();
        app_bake_worker_destroy(w);
        CHECK_MSG(now_s() - t0 < 5.0, "%.3f s to destroy", now_s() - t0);
    } else {
        app_bake_worker_destroy(w);
    }
    app_project_free_all(&p);
    char cmd[256];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
    return check_report("bake_worker");
}
