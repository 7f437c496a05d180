/* Whole-or-nothing files (app/output/safe_file.h); the same steps as the project writer
 * (app/src/project/project_write.c) and the image writer (render/src/image_write_file.c). */
#include "app/output/safe_file.h"

#include "render/write_target.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static void release(app_safe_file *f)
{
    free(f->target);
    free(f->temp);
    memset(f, 0, sizeof *f);
    f->fd = -1;
}

app_result app_safe_file_open(app_safe_file *f, const char *path, char *err, size_t err_size)
{
    memset(f, 0, sizeof *f);
    f->fd = -1;
    f->target = path ? rd_write_target(path) : NULL;
    if (!f->target) {
        snprintf(err, err_size, "%s: cannot write: %s", path ? path : "(no file name)",
                 path ? "out of memory" : "no file name given");
        release(f);
        return path ? APP_ERR_OUT_OF_MEMORY : APP_ERR_IO;
    }
    struct stat st;
    mode_t mode = 0644; /* a new file: rw-r--r-- (mkstemp alone would give 0600) */
    if (stat(f->target, &st) == 0) {
        if (S_ISDIR(st.st_mode)) {
            snprintf(err, err_size, "%s: cannot write: is a folder", path);
            release(f);
            return APP_ERR_IO;
        }
        if (S_ISREG(st.st_mode))
            mode = st.st_mode & 07777; /* keep the old file's permissions */
    }
    size_t len = strlen(f->target);
    f->temp = malloc(len + sizeof ".tmp-XXXXXX");
    if (!f->temp) {
        snprintf(err, err_size, "%s: cannot write: out of memory", path);
        release(f);
        return APP_ERR_OUT_OF_MEMORY;
    }
    memcpy(f->temp, f->target, len);
    memcpy(f->temp + len, ".tmp-XXXXXX", sizeof ".tmp-XXXXXX");
    f->fd = mkstemp(f->temp);
    if (f->fd < 0) {
        snprintf(err, err_size, "%s: cannot write (a temporary file beside it): %s", path,
                 strerror(errno));
        release(f);
        return APP_ERR_IO;
    }
    (void)fchmod(f->fd, mode);
    return APP_OK;
}

int app_safe_file_write(app_safe_file *f, const void *data, size_t n)
{
    const char *p = data;
    if (f->error || f->fd < 0) {
        if (!f->error)
            f->error = EBADF;
        return -1;
    }
    while (n > 0) {
        ssize_t w = write(f->fd, p, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0) {
            f->error = w < 0 ? errno : EIO;
            return -1;
        }
        p += w;
        n -= (size_t)w;
    }
    return 0;
}

cairo_status_t app_safe_file_cairo_write(void *closure, const unsigned char *data,
                                         unsigned int length)
{
    return app_safe_file_write(closure, data, length) == 0 ? CAIRO_STATUS_SUCCESS
                                                           : CAIRO_STATUS_WRITE_ERROR;
}

app_result app_safe_file_commit(app_safe_file *f, char *err, size_t err_size)
{
    int e = f->error;
    if (!e && f->fd >= 0 && fsync(f->fd) != 0)
        e = errno;
    if (f->fd >= 0 && close(f->fd) != 0 && !e)
        e = errno;
    f->fd = -1;
    if (!e && rename(f->temp, f->target) != 0)
        e = errno;
    if (e) {
        snprintf(err, err_size, "%s: cannot write: %s", f->target, strerror(e));
        unlink(f->temp);
        release(f);
        return APP_ERR_IO;
    }
    rd_sync_parent_folder(f->target);
    release(f);
    return APP_OK;
}

void app_safe_file_discard(app_safe_file *f)
{
    if (f->fd >= 0)
        close(f->fd);
    if (f->temp)
        unlink(f->temp);
    release(f);
}

FILE *app_safe_stream_open(app_safe_stream *s, const char *path, char *err, size_t err_size)
{
    s->f = NULL;
    if (app_safe_file_open(&s->file, path, err, err_size) != APP_OK)
        return NULL;
    s->f = fdopen(s->file.fd, "w");
    if (!s->f) {
        snprintf(err, err_size, "%s: cannot write: %s", path, strerror(errno));
        app_safe_file_discard(&s->file);
    }
    return s->f;
}

app_result app_safe_stream_commit(app_safe_stream *s, char *err, size_t err_size)
{
    if (!s->f)
        return APP_ERR_IO;
    /* The flush first: after a failed write it tries again and leaves the reason in errno. */
    errno = 0;
    int e = 0;
    if (fflush(s->f) != 0 || ferror(s->f))
        e = errno ? errno : EIO;
    if (!e && fsync(fileno(s->f)) != 0)
        e = errno;
    if (fclose(s->f) != 0 && !e)
        e = errno;
    s->f = NULL;
    s->file.fd = -1; /* closed with the stream */
    if (e && !s->file.error)
        s->file.error = e;
    return app_safe_file_commit(&s->file, err, err_size);
}
