/* app_project_write: check, build the JSON text, read it back to apply every value rule of
 * the reader, then replace the file atomically. */
#include "project_internal.h"

#include "render/write_target.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static _Thread_local long fail_write_after = -1;

void app_project_test_fail_write_after(long bytes)
{
    fail_write_after = bytes;
}

static app_result write_fully(pj_ctx *c, int fd, const char *data, size_t len)
{
    size_t done = 0;
    while (done < len) {
        size_t chunk = len - done;
        if (fail_write_after >= 0) {
            if ((long)done >= fail_write_after)
                return pj_fail_file(c, APP_ERR_IO,
                                    "cannot write: simulated failure after %ld bytes (test hook)",
                                    fail_write_after);
            if (chunk > (size_t)(fail_write_after - (long)done))
                chunk = (size_t)(fail_write_after - (long)done);
        }
        ssize_t n = write(fd, data + done, chunk);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return pj_fail_file(c, APP_ERR_IO, "cannot write: %s",
                                n < 0 ? strerror(errno) : "no progress");
        done += (size_t)n;
    }
    return APP_OK;
}

/* The folder entry of the renamed file is durable only once the folder itself is synced. */
static void sync_folder(const char *path)
{
    char *dir = pj_dirname(path);
    if (!dir)
        return;
    int fd = open(dir, O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
        (void)fsync(fd);
        close(fd);
    }
    free(dir);
}

/* Keeps the file about to be replaced as PATH.bak: a second hard link to it, so PATH itself
 * is never missing or partial (the rename that follows replaces PATH's entry in one step).
 * The old backup is removed first; a kill in between leaves no backup but an intact PATH.
 * Where hard links are impossible (some network and FAT file systems) the backup is skipped:
 * the save itself must not fail for it. */
static void keep_backup(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return;
    size_t plen = strlen(path);
    char *bak = malloc(plen + sizeof ".bak");
    if (!bak)
        return;
    memcpy(bak, path, plen);
    memcpy(bak + plen, ".bak", sizeof ".bak");
    if (unlink(bak) != 0 && errno != ENOENT) {
        free(bak);
        return;
    }
    (void)link(path, bak);
    free(bak);
}

app_result pj_write_atomic(pj_ctx *c, const char *path, const char *data, size_t len)
{
    struct stat st;
    mode_t mode = 0644; /* a new file: rw-r--r-- (mkstemp alone would give 0600) */
    if (stat(path, &st) == 0) {
        if (S_ISDIR(st.st_mode))
            return pj_fail_file(c, APP_ERR_IO, "cannot write: is a directory");
        if (S_ISREG(st.st_mode))
            mode = st.st_mode & 07777; /* keep the old file's permissions */
    }
    size_t plen = strlen(path);
    char *tmp = pj_malloc(plen + sizeof ".tmp-XXXXXX");
    if (!tmp)
        return pj_fail_file(c, APP_ERR_OUT_OF_MEMORY, "out of memory");
    memcpy(tmp, path, plen);
    memcpy(tmp + plen, ".tmp-XXXXXX", sizeof ".tmp-XXXXXX");
    int fd = mkstemp(tmp);
    if (fd < 0) {
        app_result r = pj_fail_file(c, APP_ERR_IO, "cannot create a temporary file next to it: %s",
                                    strerror(errno));
        free(tmp);
        return r;
    }
    (void)fchmod(fd, mode);
    app_result r = write_fully(c, fd, data, len);
    if (r == APP_OK && fsync(fd) != 0)
        r = pj_fail_file(c, APP_ERR_IO, "cannot write (fsync): %s", strerror(errno));
    if (close(fd) != 0 && r == APP_OK)
        r = pj_fail_file(c, APP_ERR_IO, "cannot write (close): %s", strerror(errno));
    if (r == APP_OK)
        keep_backup(path);
    if (r == APP_OK && rename(tmp, path) != 0)
        r = pj_fail_file(c, APP_ERR_IO, "cannot replace the file: %s", strerror(errno));
    if (r != APP_OK)
        unlink(tmp);
    else
        sync_folder(path);
    free(tmp);
    return r;
}

app_result app_project_write(const char *path, const app_project *p, char *err, size_t err_size)
{
    pj_ctx c;
    pj_ctx_init(&c, path, path, err, err_size);
    if (!path || !path[0])
        return pj_fail_file(&c, APP_ERR_IO, "no file name given");
    if (!p)
        return pj_fail_file(&c, APP_ERR_IO, "no project to write (p is NULL)");

    /* Through a symbolic link the file it names is replaced and the link stays a link; the
     * relative paths inside are then relative to that file's folder. */
    char *target = rd_write_target(path);
    char *dir = target ? pj_dirname(target) : NULL;
    if (!dir) {
        free(target);
        return pj_fail_file(&c, APP_ERR_OUT_OF_MEMORY, "out of memory");
    }
    char *dest_dir = realpath(dir, NULL); /* NULL: paths are written absolute */
    free(dir);
    cJSON *root = NULL;
    app_result r = pj_project_to_json(&c, p, dest_dir, &root);
    free(dest_dir);
    char *text = NULL;
    if (r == APP_OK) {
        text = cJSON_Print(root);
        cJSON_Delete(root);
        if (!text)
            r = pj_fail_file(&c, APP_ERR_OUT_OF_MEMORY, "out of memory");
    }
    if (r != APP_OK) {
        free(target);
        return r;
    }

    /* The reader's rules are the format's rules: a project the reader would refuse is not
     * written. Files named inside are not checked, so a vanished texture cannot block a save. */
    app_project check;
    r = pj_parse_text(text, strlen(text), path, 0, &check, err, err_size);
    app_project_free(&check);
    if (r == APP_OK) {
        size_t len = strlen(text);
        text[len] = '\n'; /* the terminator's byte becomes the final newline */
        r = pj_write_atomic(&c, target, text, len + 1);
    }
    cJSON_free(text);
    free(target);
    return r;
}
