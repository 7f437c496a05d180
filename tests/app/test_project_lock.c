/* The project lock file (app/project/project_lock.h): a free project is taken and its lock file
 * names this process; a second taker (another open in this process, or another process) is
 * refused with the owner's pid and host; a lock whose owner was killed is stale and taken over;
 * releasing removes the file. */
#ifndef _XOPEN_SOURCE
#define _XOPEN_SOURCE 700
#endif
#include "app/project/project_lock.h"
#include "test_util.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

static long pid_in(const char *lock_path)
{
    FILE *f = fopen(lock_path, "r");
    long pid = 0;
    if (f) {
        if (fscanf(f, "%ld", &pid) != 1)
            pid = 0;
        fclose(f);
    }
    return pid;
}

int main(void)
{
    char *dir = tu_make_temp_dir();
    CHECK(dir != NULL);
    if (!dir)
        return check_report("project_lock");
    char project[1024], lock_path[1200], err[1024];
    snprintf(project, sizeof project, "%s/bath.json", dir);
    CHECK(app_project_lock_path(project, lock_path, sizeof lock_path) == 0);
    CHECK(strstr(lock_path, "/.bath.json.lock") != NULL);

    /* Free: taken, the file names this process. */
    app_project_lock a = {0}, b = {0};
    app_lock_owner owner;
    CHECK(!app_project_lock_held(&a));
    CHECK(app_project_lock_take(project, &a, &owner, err, sizeof err) == APP_LOCK_TAKEN);
    CHECK(app_project_lock_held(&a));
    CHECK(pid_in(lock_path) == (long)getpid());

    /* A second window in this process is refused, with the owner named. */
    CHECK(app_project_lock_take(project, &b, &owner, err, sizeof err) == APP_LOCK_BUSY);
    CHECK(!app_project_lock_held(&b));
    CHECK(owner.pid == (long)getpid());
    CHECK_MSG(strstr(err, "is open in another window (pid") != NULL, "%s", err);
    app_project_lock_release(&a);
    CHECK(access(lock_path, F_OK) != 0);
    app_project_lock_release(&a); /* twice is harmless */

    /* Another process owns it: refused while it lives; killed (a crash), its lock file stays and
     * is stale, and taken over. */
    int ready[2], hold[2];
    CHECK(pipe(ready) == 0 && pipe(hold) == 0);
    fflush(NULL);
    pid_t child = fork();
    if (child == 0) {
        app_project_lock c = {0};
        char e[1024];
        char ok = app_project_lock_take(project, &c, NULL, e, sizeof e) == APP_LOCK_TAKEN;
        if (write(ready[1], &ok, 1) != 1)
            _exit(2);
        char x;
        if (read(hold[0], &x, 1) < 0) /* until killed */
            _exit(3);
        _exit(0);
    }
    char ok = 0;
    CHECK(read(ready[0], &ok, 1) == 1 && ok);
    CHECK(app_project_lock_take(project, &b, &owner, err, sizeof err) == APP_LOCK_BUSY);
    CHECK_MSG(owner.pid == (long)child, "owner pid %ld, child %ld", owner.pid, (long)child);
    kill(child, SIGKILL);
    waitpid(child, NULL, 0);
    CHECK(access(lock_path, F_OK) == 0); /* left behind by the crash */
    CHECK(pid_in(lock_path) == (long)child);
    CHECK(app_project_lock_take(project, &b, &owner, err, sizeof err) == APP_LOCK_TAKEN_STALE);
    CHECK(owner.pid == (long)child);
    CHECK(pid_in(lock_path) == (long)getpid());
    app_project_lock_release(&b);
    CHECK(access(lock_path, F_OK) != 0);

    /* A lock file written by hand for a pid that is gone (no flock: its owner is dead). */
    fflush(NULL);
    pid_t gone = fork();
    if (gone == 0)
        _exit(0);
    waitpid(gone, NULL, 0);
    char host[256] = "";
    gethostname(host, sizeof host);
    FILE *f = fopen(lock_path, "w");
    CHECK(f != NULL);
    if (f) {
        fprintf(f, "%ld %s 12345\n", (long)gone, host);
        fclose(f);
    }
    CHECK(app_project_lock_take(project, &a, &owner, err, sizeof err) == APP_LOCK_TAKEN_STALE);
    CHECK(owner.pid == (long)gone && !strcmp(owner.host, host));
    app_project_lock_release(&a);

    /* The folder allows no lock file: nothing to own, said why. */
    char missing[1200];
    snprintf(missing, sizeof missing, "%s/no-such-folder/bath.json", dir);
    CHECK(app_project_lock_take(missing, &a, NULL, err, sizeof err) == APP_LOCK_UNAVAILABLE);
    CHECK_MSG(strstr(err, "cannot make the lock file") != NULL, "%s", err);
    CHECK(!app_project_lock_held(&a));

    rmdir(dir);
    free(dir);
    return check_report("project_lock");
}
