/* A batch command reading a project while the window saves it: one process saves two versions
 * of a project (20 and 150 objects) over the same file in a loop while this one reads it in a
 * loop with the reader every command uses (tessera check, print, render); every read must give
 * one whole version, never a parse error or a mix. Saves are a temporary file renamed into place
 * (project_write.c). */
#ifndef _XOPEN_SOURCE
#define _XOPEN_SOURCE 700
#endif
#include "app/project/project.h"
#include "test_util.h"

#include <signal.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define DATA TESSERA_PROJECT_TEST_DATA
#define SMALL 20
#define BIG 150
#define SAVES 300

int main(void)
{
    app_project p;
    char err[1024];
    if (app_project_read(DATA "/v2_l_room.json", &p, err, sizeof err) != APP_OK) {
        CHECK_MSG(0, "%s", err);
        return check_report("project_save_read");
    }
    app_object *objects = calloc(BIG, sizeof *objects);
    CHECK(objects != NULL);
    if (!objects)
        return check_report("project_save_read");
    for (int i = 0; i < BIG; i++) {
        objects[i] = p.objects[0];
        snprintf(objects[i].name, sizeof objects[i].name, "part-%d", i);
        objects[i].position_mm[0] = 100 + (i % 97) * 13.25;
    }
    free(p.objects);
    p.objects = objects;

    char *dir = tu_make_temp_dir();
    CHECK(dir != NULL);
    if (!dir)
        return check_report("project_save_read");
    char path[1024];
    snprintf(path, sizeof path, "%s/shared.json", dir);
    p.object_count = SMALL;
    snprintf(p.name, sizeof p.name, "version-small");
    CHECK(app_project_write(path, &p, err, sizeof err) == APP_OK);

    fflush(NULL);
    pid_t saver = fork();
    if (saver == 0) {
        for (int k = 0; k < SAVES; k++) {
            p.object_count = k % 2 ? BIG : SMALL;
            snprintf(p.name, sizeof p.name, "version-%s", k % 2 ? "big" : "small");
            if (app_project_write(path, &p, err, sizeof err) != APP_OK) {
                fprintf(stderr, "save %d: %s\n", k, err);
                _exit(1);
            }
        }
        _exit(0);
    }
    int reads = 0, failed = 0, mixed = 0, saw_small = 0, saw_big = 0, status = 0;
    for (int done = 0; !done;) {
        done = waitpid(saver, &status, WNOHANG) == saver;
        app_project q;
        char e[1024];
        reads++;
        if (app_project_read(path, &q, e, sizeof e) != APP_OK) {
            if (failed++ < 5)
                fprintf(stderr, "read %d: %s\n", reads, e);
            continue;
        }
        int small = q.object_count == SMALL && !strcmp(q.name, "version-small");
        int big = q.object_count == BIG && !strcmp(q.name, "version-big") &&
                  !strcmp(q.objects[BIG - 1].name, "part-149");
        if (!small && !big && mixed++ < 5)
            fprintf(stderr, "read %d: %d objects, name \"%s\"\n", reads, q.object_count, q.name);
        saw_small += small;
        saw_big += big;
        app_project_free(&q);
    }
    printf("%d reads during %d saves: %d of the small version, %d of the big one\n", reads, SAVES,
           saw_small, saw_big);
    CHECK_MSG(WIFEXITED(status) && WEXITSTATUS(status) == 0, "the saver ended with %d", status);
    CHECK_MSG(failed == 0, "%d of %d reads failed", failed, reads);
    CHECK_MSG(mixed == 0, "%d of %d reads were neither version", mixed, reads);
    CHECK_MSG(saw_small > 0 && saw_big > 0, "the reads did not overlap the saves (%d/%d)",
              saw_small, saw_big);

    char bak[1100];
    snprintf(bak, sizeof bak, "%s.bak", path);
    unlink(bak);
    unlink(path);
    rmdir(dir);
    free(dir);
    app_project_free(&p);
    return check_report("project_save_read");
}
