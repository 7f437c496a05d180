/* app_project_read: a file -> app_project_parse, with the size limit and clear messages for
 * the file-level failures (missing, a directory, unreadable, too large). */
#include "project_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Reads all of fd, up to the size limit. */
static app_result read_all(pj_ctx *c, int fd, size_t hint, char **out, size_t *out_len)
{
    size_t cap = hint + 1 > 4096 ? hint + 1 : 4096;
    size_t len = 0;
    char *buf = pj_malloc(cap);
    if (!buf)
        return pj_fail_file(c, APP_ERR_OUT_OF_MEMORY, "out of memory reading the file");
    for (;;) {
        if (len == cap) {
            if (cap > (size_t)APP_PROJECT_MAX_FILE_BYTES) {
                free(buf);
                return pj_fail_file(c, APP_ERR_IO, "too large (more than 64 MiB)");
            }
            size_t grown_cap = cap * 2;
            char *grown = pj_realloc(buf, grown_cap);
            if (!grown) {
                free(buf);
                return pj_fail_file(c, APP_ERR_OUT_OF_MEMORY, "out of memory reading the file");
            }
            buf = grown;
            cap = grown_cap;
        }
        ssize_t n = read(fd, buf + len, cap - len);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            int e = errno;
            free(buf);
            return pj_fail_file(c, APP_ERR_IO, "cannot read: %s", strerror(e));
        }
        if (n == 0)
            break;
        len += (size_t)n;
    }
    if (len > (size_t)APP_PROJECT_MAX_FILE_BYTES) {
        free(buf);
        return pj_fail_file(c, APP_ERR_IO, "too large (%zu bytes, the limit is 64 MiB)", len);
    }
    *out = buf;
    *out_len = len;
    return APP_OK;
}

app_result pj_read_file(pj_ctx *c, const char *path, char **text, size_t *len)
{
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return pj_fail_file(c, APP_ERR_IO, "cannot open: %s", strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return pj_fail_file(c, APP_ERR_IO, "cannot open: %s", strerror(e));
    }
    if (S_ISDIR(st.st_mode)) {
        close(fd);
        return pj_fail_file(c, APP_ERR_IO, "is a directory, not a project file");
    }
    if (S_ISREG(st.st_mode) && st.st_size > APP_PROJECT_MAX_FILE_BYTES) {
        close(fd);
        return pj_fail_file(c, APP_ERR_IO, "too large (%lld bytes, the limit is 64 MiB)",
                            (long long)st.st_size);
    }
    app_result r = read_all(c, fd, S_ISREG(st.st_mode) ? (size_t)st.st_size : 0, text, len);
    close(fd);
    return r;
}

app_result app_project_read(const char *path, app_project *out, char *err, size_t err_size)
{
    pj_ctx c;
    pj_ctx_init(&c, path, path, err, err_size);
    if (out)
        memset(out, 0, sizeof *out);
    if (!path || !path[0])
        return pj_fail_file(&c, APP_ERR_IO, "no file name given");
    if (!out)
        return pj_fail_file(&c, APP_ERR_IO, "no project to read into (out is NULL)");
    char *text = NULL;
    size_t len = 0;
    app_result r = pj_read_file(&c, path, &text, &len);
    if (r != APP_OK)
        return r;
    r = app_project_parse(text, len, path, out, err, err_size);
    free(text);
    return r;
}
