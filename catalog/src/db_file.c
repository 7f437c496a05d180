/* Files around the database: reading a CSV whole, making the cache folder, temporary names
 * and the rename that puts a finished file in place. */
#include "db_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

cat_db_result catdb_read_file(const char *path, size_t max_bytes, unsigned char **data,
                              size_t *size, char *err, size_t err_size)
{
    *data = NULL;
    *size = 0;
    /* O_NONBLOCK: a FIFO must not hang the import; it is refused below. */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot open: %s", path,
                          strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot read: %s", path, strerror(e));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot read: not a regular file",
                          path);
    }
    if (st.st_size < 0 || (unsigned long long)st.st_size > max_bytes) {
        close(fd);
        return catdb_fail(err, err_size, CAT_DB_ERR_TOO_LARGE,
                          "%s: the file has %lld bytes, the limit is %zu", path,
                          (long long)st.st_size, max_bytes);
    }
    size_t want = (size_t)st.st_size;
    unsigned char *buf = malloc(want + 1);
    if (!buf) {
        close(fd);
        return catdb_fail(err, err_size, CAT_DB_ERR_OUT_OF_MEMORY,
                          "%s: out of memory reading %zu bytes", path, want);
    }
    size_t got = 0;
    while (got < want) {
        ssize_t n = read(fd, buf + got, want - got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            int e = n < 0 ? errno : 0;
            close(fd);
            free(buf);
            return catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot read: %s", path,
                              e ? strerror(e) : "the file shrank while being read");
        }
        got += (size_t)n;
    }
    close(fd);
    buf[want] = 0;
    *data = buf;
    *size = want;
    return CAT_DB_OK;
}

cat_db_result catdb_make_parent_dirs(const char *path, char *err, size_t err_size)
{
    size_t n = strlen(path);
    char *dir = malloc(n + 1);
    if (!dir)
        return catdb_fail(err, err_size, CAT_DB_ERR_OUT_OF_MEMORY, "%s: out of memory", path);
    memcpy(dir, path, n + 1);
    char *slash = strrchr(dir, '/');
    if (!slash || slash == dir) {
        free(dir);
        return CAT_DB_OK; /* the current folder or the root */
    }
    *slash = 0;
    for (char *p = dir + 1;; p++) {
        if (*p != '/' && *p != 0)
            continue;
        char keep = *p;
        *p = 0;
        if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
            int e = errno;
            cat_db_result r = catdb_fail(err, err_size, CAT_DB_ERR_IO,
                                         "%s: cannot make folder %s: %s", path, dir, strerror(e));
            free(dir);
            return r;
        }
        *p = keep;
        if (!keep)
            break;
    }
    struct stat st;
    int ok = stat(dir, &st) == 0 && S_ISDIR(st.st_mode);
    cat_db_result r = ok ? CAT_DB_OK
                         : catdb_fail(err, err_size, CAT_DB_ERR_IO,
                                      "%s: cannot make folder %s: not a folder", path, dir);
    free(dir);
    return r;
}

void catdb_temp_name(const char *path, char *buf, size_t size)
{
    static unsigned counter;
    snprintf(buf, size, "%s.tmp-%ld-%u", path, (long)getpid(), counter++);
}

static void sync_folder(const char *path);

cat_db_result catdb_rename_into_place(const char *tmp, const char *path, char *err, size_t err_size)
{
    if (rename(tmp, path) != 0)
        return catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot rename %s into place: %s", path,
                          tmp, strerror(errno));
    sync_folder(path);
    return CAT_DB_OK;
}

/* Syncs the folder that holds path: without it a crash can lose a rename or a link although the
 * data is on disk. */
static void sync_folder(const char *path)
{
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (slash)
        *(slash == dir ? slash + 1 : slash) = 0;
    else
        snprintf(dir, sizeof dir, ".");
    int fd = open(dir, O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
        fsync(fd);
        close(fd);
    }
}

cat_db_result catdb_link_into_place(const char *tmp, const char *path, char *err, size_t err_size)
{
    if (link(tmp, path) == 0 || errno == EEXIST) {
        sync_folder(path);
        return CAT_DB_OK;
    }
    if (errno != EPERM && errno != ENOSYS && errno != EOPNOTSUPP && errno != EXDEV)
        return catdb_fail(err, err_size, CAT_DB_ERR_IO, "%s: cannot link %s into place: %s", path,
                          tmp, strerror(errno));
    /* A file system without hard links: rename, unless a catalog appeared meanwhile (the small
     * window between the check and the rename is the price of such a file system). */
    struct stat st;
    if (stat(path, &st) == 0)
        return CAT_DB_OK;
    return catdb_rename_into_place(tmp, path, err, err_size);
}

void catdb_remove_db_file(const char *path)
{
    char journal[4200];
    remove(path);
    snprintf(journal, sizeof journal, "%s-journal", path);
    remove(journal);
    snprintf(journal, sizeof journal, "%s-wal", path);
    remove(journal);
    snprintf(journal, sizeof journal, "%s-shm", path);
    remove(journal);
}
