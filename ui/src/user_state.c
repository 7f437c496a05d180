/* The state folder, atomic writes, the recent-files list and autosave names (user_state.h). */
#define _DEFAULT_SOURCE /* mkstemp, fsync, realpath */

#include "user_state.h"

#include <errno.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* mkdir -p, mode 0700: the state folder is the user's own (XDG Base Directory Specification). */
static int make_dirs(char *path)
{
    for (char *s = path + 1; *s; s++) {
        if (*s != '/')
            continue;
        *s = 0;
        int bad = mkdir(path, 0700) != 0 && errno != EEXIST;
        *s = '/';
        if (bad)
            return 1;
    }
    return mkdir(path, 0700) != 0 && errno != EEXIST;
}

int ui_state_dir(char *out, size_t size)
{
    const char *xdg = getenv("XDG_STATE_HOME"), *home = getenv("HOME");
    int n;
    /* The specification: a relative XDG_STATE_HOME is invalid and is ignored. */
    if (xdg && xdg[0] == '/')
        n = snprintf(out, size, "%s/tessera", xdg);
    else if (home && *home)
        n = snprintf(out, size, "%s/.local/state/tessera", home);
    else {
        snprintf(out, size, "neither XDG_STATE_HOME nor HOME is set");
        return 1;
    }
    if (n < 0 || (size_t)n >= size) {
        snprintf(out, size, "the state folder's path is too long");
        return 1;
    }
    if (make_dirs(out)) {
        int e = errno;
        char dir[1024];
        snprintf(dir, sizeof dir, "%s", out);
        snprintf(out, size, "cannot make the state folder %.900s: %s", dir, strerror(e));
        return 1;
    }
    return 0;
}

int ui_write_atomic(const char *path, const char *data, size_t len, char *err, size_t err_size)
{
    char tmp[PATH_MAX];
    if (snprintf(tmp, sizeof tmp, "%s.tmp-XXXXXX", path) >= (int)sizeof tmp) {
        snprintf(err, err_size, "%s: the path is too long", path);
        return 1;
    }
    int fd = mkstemp(tmp);
    if (fd < 0) {
        snprintf(err, err_size, "%s: cannot create a temporary file: %s", path, strerror(errno));
        return 1;
    }
    size_t done = 0;
    while (done < len) {
        ssize_t w = write(fd, data + done, len - done);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            break;
        done += (size_t)w;
    }
    int ok = done == len && fsync(fd) == 0;
    int e = errno;
    ok = close(fd) == 0 && ok;
    if (!ok || rename(tmp, path) != 0) {
        if (ok)
            e = errno;
        unlink(tmp);
        snprintf(err, err_size, "%s: cannot write: %s", path, strerror(e));
        return 1;
    }
    return 0;
}

int ui_recent_load(ui_recent *r, const char *file)
{
    memset(r, 0, sizeof *r);
    FILE *f = fopen(file, "r");
    if (!f)
        return errno != ENOENT;
    char line[2048];
    while (r->count < UI_RECENT_MAX && fgets(line, sizeof line, f)) {
        size_t n = strcspn(line, "\r\n");
        if (n == 0 || n >= sizeof r->paths[0] || line[n] == 0)
            continue; /* empty, or too long for a path (its rest would follow as a line) */
        line[n] = 0;
        int seen = 0;
        for (int i = 0; i < r->count; i++)
            seen |= !strcmp(r->paths[i], line);
        if (!seen) /* the file is newest first: keep its order */
            memcpy(r->paths[r->count++], line, n + 1);
    }
    fclose(f);
    return 0;
}

void ui_recent_add(ui_recent *r, const char *path)
{
    if (!path || !*path || strlen(path) >= sizeof r->paths[0])
        return;
    int at = r->count < UI_RECENT_MAX ? r->count : UI_RECENT_MAX - 1;
    for (int i = 0; i < r->count; i++)
        if (!strcmp(r->paths[i], path))
            at = i;
    memmove(r->paths[1], r->paths[0], (size_t)at * sizeof r->paths[0]);
    snprintf(r->paths[0], sizeof r->paths[0], "%s", path);
    if (at == r->count)
        r->count++;
}

int ui_recent_save(const ui_recent *r, const char *file, char *err, size_t err_size)
{
    char buf[UI_RECENT_MAX * 1025 + 1];
    size_t len = 0;
    for (int i = 0; i < r->count; i++)
        len += (size_t)snprintf(buf + len, sizeof buf - len, "%s\n", r->paths[i]);
    return ui_write_atomic(file, buf, len, err, err_size);
}

int ui_recent_file(char *out, size_t size)
{
    char dir[1024];
    if (ui_state_dir(dir, sizeof dir)) {
        snprintf(out, size, "%s", dir);
        return 1;
    }
    return snprintf(out, size, "%s/recent-files", dir) >= (int)size;
}

int ui_project_state_file(const char *folder, const char *project_path, char *out, size_t size)
{
    char dir[1024], abs[PATH_MAX];
    if (ui_state_dir(dir, sizeof dir)) {
        snprintf(out, size, "%s", dir);
        return 1;
    }
    size_t dl = strlen(dir);
    if (snprintf(dir + dl, sizeof dir - dl, "/%s", folder) >= (int)(sizeof dir - dl)) {
        snprintf(out, size, "the state folder's path is too long");
        return 1;
    }
    if (make_dirs(dir)) {
        snprintf(out, size, "cannot make %s: %s", dir, strerror(errno));
        return 1;
    }
    if (!project_path || !*project_path)
        return snprintf(out, size, "%s/untitled.json", dir) >= (int)size;
    if (!realpath(project_path, abs))
        snprintf(abs, sizeof abs, "%s", project_path);
    uint64_t h = 14695981039346656037ull; /* FNV-1a offset basis and prime (Fowler, Noll, Vo) */
    for (const unsigned char *s = (const unsigned char *)abs; *s; s++)
        h = (h ^ *s) * 1099511628211ull;
    const char *base = strrchr(abs, '/');
    base = base ? base + 1 : abs;
    size_t bl = strlen(base);
    if (bl > 5 && !strcmp(base + bl - 5, ".json"))
        bl -= 5;
    if (bl > 100)
        bl = 100;
    return snprintf(out, size, "%s/%.*s-%016llx.json", dir, (int)bl, base, (unsigned long long)h) >=
           (int)size;
}
