/* The project lock file (project_lock.h). Ownership is the flock(2) on the file, which the
 * kernel drops when its owner exits or crashes, so a lock left behind is recognised as stale
 * without guessing; the pid, host and start time written in it name the owner for the message
 * and guard the one case flock cannot see (a file system where flock is a no-op): a lock whose
 * pid still runs on this host with the same start time is live. */
#define _GNU_SOURCE /* gethostname, flock */
#include "app/project/project_lock.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

int app_project_lock_path(const char *project_path, char *out, size_t size)
{
    const char *slash = strrchr(project_path, '/');
    int dir_len = slash ? (int)(slash - project_path) + 1 : 0;
    const char *base = slash ? slash + 1 : project_path;
    int n = snprintf(out, size, "%.*s.%s.lock", dir_len, project_path, base);
    return n < 0 || (size_t)n >= size;
}

/* The process's start time in clock ticks after boot (field 22 of /proc/PID/stat, proc(5)),
 * so that a recycled pid is not taken for the owner; 0 when unknown. */
static unsigned long long start_ticks(long pid)
{
    char path[64], buf[1024];
    snprintf(path, sizeof path, "/proc/%ld/stat", pid);
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    const char *p = strrchr(buf, ')'); /* the command name may hold spaces and parentheses */
    if (!p)
        return 0;
    unsigned long long ticks = 0;
    /* after ")": state (field 3) ... starttime (field 22) */
    if (sscanf(p + 1,
               " %*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %*u %*u %*d %*d %*d %*d %*d "
               "%*d %llu",
               &ticks) != 1)
        return 0;
    return ticks;
}

static void this_host(char *host, size_t size)
{
    if (gethostname(host, size) != 0)
        snprintf(host, size, "unknown");
    host[size - 1] = 0;
}

/* The owner written in the file; 0 when it holds none. */
static int read_owner(int fd, app_lock_owner *owner, unsigned long long *ticks)
{
    char buf[512];
    ssize_t n = pread(fd, buf, sizeof buf - 1, 0);
    memset(owner, 0, sizeof *owner);
    *ticks = 0;
    if (n <= 0)
        return 0;
    buf[n] = 0;
    return sscanf(buf, "%ld %255s %llu", &owner->pid, owner->host, ticks) >= 2 && owner->pid > 0;
}

/* A live process on this host that is the one the file names. */
static int owner_alive_here(const app_lock_owner *owner, unsigned long long ticks)
{
    char host[256];
    this_host(host, sizeof host);
    if (strcmp(host, owner->host) != 0 || owner->pid == (long)getpid())
        return 0;
    if (kill((pid_t)owner->pid, 0) != 0 && errno == ESRCH)
        return 0;
    return ticks != 0 && start_ticks(owner->pid) == ticks;
}

static void set_err(char *err, size_t err_size, const char *fmt, const char *a, const char *b)
{
    if (err && err_size)
        snprintf(err, err_size, fmt, a, b);
}

app_lock_result app_project_lock_take(const char *project_path, app_project_lock *lock,
                                      app_lock_owner *owner, char *err, size_t err_size)
{
    app_lock_owner scratch;
    if (!owner)
        owner = &scratch;
    memset(owner, 0, sizeof *owner);
    lock->held = 0;
    lock->fd = -1;
    if (err && err_size)
        err[0] = 0;
    if (app_project_lock_path(project_path, lock->path, sizeof lock->path)) {
        set_err(err, err_size, "%s: the path is too long for a lock file%s", project_path, "");
        return APP_LOCK_UNAVAILABLE;
    }
    /* A few rounds: the file can be released (unlinked) between our open and our flock. */
    for (int round = 0; round < 8; round++) {
        int fd = open(lock->path, O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
        if (fd < 0) {
            set_err(err, err_size, "cannot make the lock file %s: %s", lock->path, strerror(errno));
            return APP_LOCK_UNAVAILABLE;
        }
        unsigned long long ticks;
        if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
            read_owner(fd, owner, &ticks);
            close(fd);
            char who[400];
            if (owner->pid > 0)
                snprintf(who, sizeof who, "pid %ld on %s", owner->pid, owner->host);
            else
                snprintf(who, sizeof who, "a process that is starting");
            set_err(err, err_size, "%s is open in another window (%s)", project_path, who);
            return APP_LOCK_BUSY;
        }
        struct stat held, named;
        if (fstat(fd, &held) != 0 || stat(lock->path, &named) != 0 || held.st_ino != named.st_ino ||
            held.st_dev != named.st_dev) {
            close(fd); /* released and removed meanwhile: try the file that is there now */
            continue;
        }
        int had_owner = read_owner(fd, owner, &ticks);
        if (had_owner && owner_alive_here(owner, ticks)) {
            close(fd);
            char who[400];
            snprintf(who, sizeof who, "pid %ld on %s", owner->pid, owner->host);
            set_err(err, err_size, "%s is open in another window (%s)", project_path, who);
            return APP_LOCK_BUSY;
        }
        char host[256], text[512];
        this_host(host, sizeof host);
        int n = snprintf(text, sizeof text, "%ld %s %llu\n", (long)getpid(), host,
                         start_ticks((long)getpid()));
        if (ftruncate(fd, 0) != 0 || pwrite(fd, text, (size_t)n, 0) != n) {
            set_err(err, err_size, "cannot write the lock file %s: %s", lock->path,
                    strerror(errno));
            close(fd);
            return APP_LOCK_UNAVAILABLE;
        }
        lock->fd = fd;
        lock->held = 1;
        return had_owner ? APP_LOCK_TAKEN_STALE : APP_LOCK_TAKEN;
    }
    set_err(err, err_size, "%s: the lock file %s keeps changing", project_path, lock->path);
    return APP_LOCK_UNAVAILABLE;
}

void app_project_lock_release(app_project_lock *lock)
{
    if (!lock || !lock->held)
        return;
    /* Unlinked while still flock'ed: a process that opened it meanwhile finds, once it gets the
     * flock, that the name no longer leads to this file, and starts again. */
    unlink(lock->path);
    close(lock->fd);
    lock->fd = -1;
    lock->held = 0;
}

int app_project_lock_held(const app_project_lock *lock)
{
    return lock && lock->held;
}
