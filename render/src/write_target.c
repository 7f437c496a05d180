/* rd_write_target: follow a symbolic link to the file a save should replace. */
#define _XOPEN_SOURCE 700 /* realpath, readlink, lstat */

#include "render/write_target.h"

#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A link's text is relative to the folder holding the link, not to the working folder. */
static char *join_link(const char *link_path, const char *text)
{
    if (text[0] == '/')
        return strdup(text);
    const char *slash = strrchr(link_path, '/');
    size_t dir_len = slash ? (size_t)(slash - link_path) + 1 : 0;
    char *joined = malloc(dir_len + strlen(text) + 1);
    if (joined) {
        memcpy(joined, link_path, dir_len);
        strcpy(joined + dir_len, text);
    }
    return joined;
}

char *rd_write_target(const char *path)
{
    struct stat st;
    if (path == NULL || lstat(path, &st) != 0 || !S_ISLNK(st.st_mode))
        return path ? strdup(path) : NULL;
    char *resolved = realpath(path, NULL);
    if (resolved)
        return resolved;
    /* A dangling link: the save creates the file it names. */
    char *current = strdup(path);
    for (int depth = 0; current && depth < 40; depth++) {
        if (lstat(current, &st) != 0 || !S_ISLNK(st.st_mode))
            return current;
        char text[PATH_MAX];
        ssize_t n = readlink(current, text, sizeof text - 1);
        if (n < 0)
            return current; /* the write itself will report the reason */
        text[n] = '\0';
        char *next = join_link(current, text);
        free(current);
        current = next;
    }
    return current;
}

void rd_sync_parent_folder(const char *path)
{
    const char *slash = strrchr(path, '/');
    char dir[4096];
    if (!slash)
        snprintf(dir, sizeof dir, ".");
    else if ((size_t)(slash - path) < sizeof dir)
        snprintf(dir, sizeof dir, "%.*s", slash == path ? 1 : (int)(slash - path), path);
    else
        return;
    int fd = open(dir, O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
        (void)fsync(fd);
        close(fd);
    }
}
