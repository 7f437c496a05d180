/* kill -9 during save: a child process saves a project of 150 objects over and over,
 * the parent kills it with SIGKILL after a random delay, and then PATH must read back as a
 * complete project (the old one or a new one, all objects present) and PATH.bak, when there,
 * too (every 4th time, to keep the test short). Repeated many times with delays spread over the
 * length of one save, so kills land in every phase: building the text, writing the temporary file,
 * fsync, the backup link, the rename. */
#ifndef _XOPEN_SOURCE
#define _XOPEN_SOURCE 700
#endif
#include "app/project/project.h"
#include "test_util.h"

#include <signal.h>
#include <sys/wait.h>
#include <math.h>
#include <time.h>

#define DATA TESSERA_PROJECT_TEST_DATA
#define ITERATIONS 200
#define OBJECTS 150

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

static void sleep_ms(double ms)
{
    struct timespec ts = {(time_t)(ms / 1000), (long)(fmod(ms, 1000.0) * 1e6)};
    nanosleep(&ts, NULL);
}

/* Whether path holds a complete project of ours: it parses, and has every object. */
static int complete(const char *path, char *err, size_t err_size)
{
    app_project q;
    if (app_project_read(path, &q, err, err_size) != APP_OK)
        return 0;
    int ok = q.object_count == OBJECTS && !strncmp(q.name, "save-", 5) &&
             !strcmp(q.objects[OBJECTS - 1].name, "part-last");
    if (!ok)
        snprintf(err, err_size, "%s: parsed, but %d objects, name \"%s\"", path, q.object_count,
                 q.name);
    app_project_free(&q);
    return ok;
}

int main(void)
{
    app_project p;
    char err[1024];
    if (app_project_read(DATA "/v2_l_room.json", &p, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return check_report("project_kill_save");
    }
    /* A project large enough that one save takes milliseconds, so that it can be killed in the
     * middle of each phase (the delays below scale with it). */
    app_object *objects = calloc(OBJECTS, sizeof *objects);
    CHECK(objects != NULL);
    if (!objects)
        return check_report("project_kill_save");
    for (int i = 0; i < OBJECTS; i++) {
        objects[i] = p.objects[0];
        snprintf(objects[i].name, sizeof objects[i].name, "part-%d", i);
        objects[i].position_mm[0] = 100 + (i % 97) * 13.25;
    }
    snprintf(objects[OBJECTS - 1].name, sizeof objects[0].name, "part-last");
    free(p.objects);
    p.objects = objects;
    p.object_count = OBJECTS;

    char *dir = tu_make_temp_dir();
    CHECK(dir != NULL);
    if (!dir)
        return check_report("project_kill_save");
    char path[1024], bak[1100];
    snprintf(path, sizeof path, "%s/big.json", dir);
    snprintf(bak, sizeof bak, "%s.bak", path);
    snprintf(p.name, sizeof p.name, "save-initial");
    /* The fastest of three saves: the first one alone is slowed by cold caches and would
     * spread the kills past the saves they are meant to land in. */
    double save_ms = INFINITY;
    for (int k = 0; k < 3; k++) {
        double t0 = now_ms();
        CHECK(app_project_write(path, &p, err, sizeof err) == APP_OK);
        save_ms = fmin(save_ms, now_ms() - t0);
    }
    if (save_ms < 1)
        save_ms = 1;

    srand(12345);
    int killed_mid_save = 0, broken = 0;
    double start = now_ms();
    for (int it = 0; it < ITERATIONS; it++) {
        fflush(NULL);
        pid_t child = fork();
        if (child == 0) {
            for (int k = 0;; k++) {
                snprintf(p.name, sizeof p.name, "save-%d-%d", it, k);
                if (app_project_write(path, &p, err, sizeof err) != APP_OK)
                    _exit(2);
            }
        }
        CHECK(child > 0);
        if (child <= 0)
            break;
        /* Up to one and a half saves' worth, so the kill may land anywhere in the first save
         * or in the second. */
        sleep_ms(save_ms * 1.5 * rand() / (double)RAND_MAX);
        kill(child, SIGKILL);
        int status = 0;
        waitpid(child, &status, 0);
        if (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
            killed_mid_save++;
        else
            CHECK_MSG(0, "the saving child ended by itself (a save failed)");
        if (!complete(path, err, sizeof err)) {
            CHECK_MSG(0, "%s", err);
            broken++;
        }
        if (it % 4 == 0 && access(bak, F_OK) == 0 && !complete(bak, err, sizeof err)) {
            CHECK_MSG(0, "%s", err);
            broken++;
        }
    }
    double total = now_ms() - start;
    int leftovers = tu_count_entries(dir, ".tmp-");
    printf("project_kill_save: %d kills during saves of %d objects (one save %.1f ms), %d broken "
           "files, %d temporary files left by killed saves, %.1f s\n",
           killed_mid_save, OBJECTS, save_ms, broken, leftovers, total / 1000);
    CHECK(broken == 0);
    tu_remove_tree(dir);
    free(dir);
    app_project_free(&p);
    return check_report("project_kill_save");
}
