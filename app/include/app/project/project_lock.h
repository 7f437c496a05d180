/* Who has a project open for editing: a lock file beside the project (".NAME.lock" in the
 * project's folder, so that a second window sees it also from another machine on a shared
 * folder) holding the owner's pid, host and start time, and an flock(2) on it for as long as
 * the owner lives. A lock whose flock is free (its owner ended, or crashed) is stale and taken
 * over; a live one is refused with its owner named, and the caller opens the project read-only.
 * The file is removed when its owner releases it. */
#ifndef APP_PROJECT_PROJECT_LOCK_H
#define APP_PROJECT_PROJECT_LOCK_H

#include <stddef.h>

typedef enum app_lock_result {
    APP_LOCK_TAKEN = 0,   /* this process owns the project now */
    APP_LOCK_TAKEN_STALE, /* taken over from an owner that is gone (owner says who) */
    APP_LOCK_BUSY,        /* another live process owns it (owner says who) */
    APP_LOCK_UNAVAILABLE, /* the folder allows no lock file (read-only): nothing to own */
} app_lock_result;

typedef struct app_lock_owner {
    long pid;
    char host[256];
} app_lock_owner;

typedef struct app_project_lock {
    int held; /* 0 (a zeroed struct): nothing held */
    int fd;   /* the lock file, flock'ed, when held */
    char path[4200];
} app_project_lock;

/* The lock file's path for a project: "DIR/.NAME.lock". 0 ok, 1 too long. */
int app_project_lock_path(const char *project_path, char *out, size_t size);

/* Takes the project's lock into *lock (zeroed or released before). owner (may be NULL) gets
 * the previous or the current owner for TAKEN_STALE and BUSY. err gets a sentence for BUSY and
 * UNAVAILABLE. */
app_lock_result app_project_lock_take(const char *project_path, app_project_lock *lock,
                                      app_lock_owner *owner, char *err, size_t err_size);

/* Removes the lock file and lets go; safe on a lock that holds nothing. */
void app_project_lock_release(app_project_lock *lock);

/* 1 when lock holds a project. */
int app_project_lock_held(const app_project_lock *lock);

#endif
