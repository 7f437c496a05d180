/* A folder replaced whole (app/output/folder_swap.h): the folder counterpart of
 * app/src/output/safe_file.c. */
#define _GNU_SOURCE /* renameat2, RENAME_EXCHANGE; nftw's FTW_DEPTH and FTW_PHYS */
#include "app/output/folder_swap.h"

#include "render/write_target.h"

#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static void release(app_folder_swap *s)
{
    free(s->target);
    free(s->temp);
    memset(s, 0, sizeof *s);
}

static int remove_entry(const char *path, const struct stat *st, int type, struct FTW *ftw)
{
    (void)st;
    (void)ftw;
    return (type == FTW_DP ? rmdir(path) : unlink(path)) == 0 ? 0 : -1;
}

int app_remove_tree(const char *path)
{
    /* FTW_DEPTH: a folder's entries before the folder; FTW_PHYS: a link is removed, never
     * followed. */
    return nftw(path, remove_entry, 16, FTW_DEPTH | FTW_PHYS) == 0 ? 0 : -1;
}

app_result app_folder_swap_begin(app_folder_swap *s, const char *path, char *err, size_t err_size)
{
    memset(s, 0, sizeof *s);
    s->target = path && *path ? rd_write_target(path) : NULL;
    if (!s->target) {
        snprintf(err, err_size, "%s: cannot write: %s", path ? path : "(no folder name)",
                 path && *path ? "out of memory" : "no folder name given");
        release(s);
        return path && *path ? APP_ERR_OUT_OF_MEMORY : APP_ERR_IO;
    }
    /* A new folder gets the permissions mkdir would give it (mkdtemp alone gives 0700). */
    mode_t mask = umask(022);
    umask(mask);
    mode_t mode = 0777 & ~mask;
    struct stat st;
    if (stat(s->target, &st) == 0) {
        if (!S_ISDIR(st.st_mode)) {
            snprintf(err, err_size, "%s: cannot write the folder: a file of that name is there",
                     path);
            release(s);
            return APP_ERR_IO;
        }
        mode = st.st_mode & 07777; /* keep the old folder's permissions */
    }
    size_t len = strlen(s->target);
    while (len > 1 && s->target[len - 1] == '/') /* "out/" names the folder "out" */
        s->target[--len] = 0;
    s->temp = malloc(len + sizeof ".tmp-XXXXXX");
    if (!s->temp) {
        snprintf(err, err_size, "%s: cannot write: out of memory", path);
        release(s);
        return APP_ERR_OUT_OF_MEMORY;
    }
    memcpy(s->temp, s->target, len);
    memcpy(s->temp + len, ".tmp-XXXXXX", sizeof ".tmp-XXXXXX");
    if (!mkdtemp(s->temp)) {
        snprintf(err, err_size, "%s: cannot write (a temporary folder beside it): %s", path,
                 strerror(errno));
        release(s);
        return APP_ERR_IO;
    }
    (void)chmod(s->temp, mode);
    return APP_OK;
}

/* Where the exchange is not supported (a file system without RENAME_EXCHANGE): the old folder
 * is moved aside, the new one renamed into place, and the old one moved back if that fails.
 * For the moment between the two renames the target is missing, never mixed. *aside gets the
 * old folder's name (malloc'd) on success. */
static int swap_by_two_renames(const char *temp, const char *target, char **aside)
{
    size_t len = strlen(target);
    *aside = malloc(len + sizeof ".old-XXXXXX");
    if (!*aside) {
        errno = ENOMEM;
        return -1;
    }
    memcpy(*aside, target, len);
    memcpy(*aside + len, ".old-XXXXXX", sizeof ".old-XXXXXX");
    /* rename(2) replaces an empty folder: mkdtemp reserves a name nobody else takes. */
    if (!mkdtemp(*aside) || rename(target, *aside) != 0) {
        int e = errno;
        rmdir(*aside);
        free(*aside);
        *aside = NULL;
        errno = e;
        return -1;
    }
    if (rename(temp, target) != 0) {
        int e = errno;
        (void)rename(*aside, target);
        free(*aside);
        *aside = NULL;
        errno = e;
        return -1;
    }
    return 0;
}

app_result app_folder_swap_commit(app_folder_swap *s, char *err, size_t err_size)
{
    if (!s->temp) {
        snprintf(err, err_size, "(no folder): cannot replace the folder: nothing was written");
        return APP_ERR_IO;
    }
    int e = 0;
    char *old = NULL; /* where the old folder is after the swap */
    struct stat st;
    if (lstat(s->target, &st) != 0) {
        if (rename(s->temp, s->target) != 0)
            e = errno;
    } else if (renameat2(AT_FDCWD, s->temp, AT_FDCWD, s->target, RENAME_EXCHANGE) == 0) {
        old = s->temp; /* the exchange left the old folder under the temporary name */
        s->temp = NULL;
    } else if (errno == EINVAL || errno == ENOSYS) {
        if (swap_by_two_renames(s->temp, s->target, &old) != 0)
            e = errno;
    } else {
        e = errno;
    }
    if (e) {
        snprintf(err, err_size, "%s: cannot replace the folder: %s", s->target, strerror(e));
        app_folder_swap_discard(s);
        return APP_ERR_IO;
    }
    rd_sync_parent_folder(s->target);
    if (old)
        (void)app_remove_tree(old); /* the new folder is in place whatever is left of it */
    free(old);
    release(s);
    return APP_OK;
}

void app_folder_swap_discard(app_folder_swap *s)
{
    if (s->temp)
        (void)app_remove_tree(s->temp);
    release(s);
}
