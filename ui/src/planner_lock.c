/* The document's lock file (app/project/project_lock.h): a project open in one window opens
 * read-only in a second one, which cannot save over it but may save as another file. */
#include "planner.h"

#include <string.h>

static int is_shipped(const char *path)
{
    const char *assets = TESSERA_SOURCE_DIR "/assets/";
    return !strncmp(path, assets, strlen(assets));
}

void planner_unlock_document(planner *p)
{
    app_project_lock_release(&p->lock);
    p->read_only = 0;
}

void planner_lock_document(planner *p)
{
    planner_unlock_document(p);
    if (!p->project.path[0] || is_shipped(p->project.path))
        return;
    char err[1024];
    app_lock_owner owner;
    switch (app_project_lock_take(p->project.path, &p->lock, &owner, err, sizeof err)) {
    case APP_LOCK_TAKEN:
        break;
    case APP_LOCK_TAKEN_STALE:
        fprintf(stderr, "tessera: took over the stale lock of %s (pid %ld on %s is gone)\n",
                p->project.path, owner.pid, owner.host);
        break;
    case APP_LOCK_BUSY:
        p->read_only = 1;
        planner_status(p, "%s: read-only here; Save As keeps your changes", err);
        break;
    case APP_LOCK_UNAVAILABLE:
        fprintf(stderr, "tessera: %s (the project is not locked)\n", err);
        break;
    }
}

int planner_lock_for_save_as(planner *p, const char *path, app_project_lock *out)
{
    memset(out, 0, sizeof *out);
    if (is_shipped(path))
        return 0;
    char err[1024];
    if (app_project_lock_take(path, out, NULL, err, sizeof err) == APP_LOCK_BUSY) {
        planner_status(p, "save as: %s; not saved", err);
        return 1;
    }
    return 0;
}
