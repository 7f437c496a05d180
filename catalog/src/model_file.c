/* Reading the model file and the external files it names. */
#include "model_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

cat_result cat_read_file(const cat_msg *msg, const char *label, const char *path, size_t max_bytes,
                         unsigned char **data, size_t *size)
{
    *data = NULL;
    *size = 0;
    /* O_NONBLOCK: a FIFO must not hang the loader; it is refused below as not a regular file. */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return cat_fail(msg, CAT_ERR_IO, "cannot open %s: %s", label, strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return cat_fail(msg, CAT_ERR_IO, "cannot read %s: %s", label, strerror(e));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return cat_fail(msg, CAT_ERR_IO, "cannot read %s: not a regular file", label);
    }
    if (st.st_size < 0 || (unsigned long long)st.st_size > max_bytes) {
        close(fd);
        return cat_fail(msg, CAT_ERR_TOO_LARGE, "%s has %lld bytes, the limit is %zu", label,
                        (long long)st.st_size, max_bytes);
    }
    size_t want = (size_t)st.st_size;
    unsigned char *buf = malloc(want ? want : 1);
    if (!buf) {
        close(fd);
        return cat_fail(msg, CAT_ERR_OUT_OF_MEMORY, "out of memory reading %s (%zu bytes)", label,
                        want);
    }
    size_t got = 0;
    while (got < want) {
        size_t chunk = want - got < (size_t)1 << 30 ? want - got : (size_t)1 << 30;
        ssize_t n = read(fd, buf + got, chunk);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            int e = n < 0 ? errno : 0;
            close(fd);
            free(buf);
            return cat_fail(msg, CAT_ERR_IO, "cannot read %s: %s", label,
                            e ? strerror(e) : "file shrank while reading");
        }
        got += (size_t)n;
    }
    close(fd);
    *data = buf;
    *size = want;
    return CAT_OK;
}

cat_result cat_gltf_read_external(cat_gltf_io *io, const char *uri, size_t uri_length,
                                  unsigned char **data, size_t *size)
{
    *data = NULL;
    *size = 0;
    char message[sizeof io->message];
    cat_msg m = {io->msg ? io->msg->path : NULL, message, sizeof message};
    char resolved[PATH_MAX];
    cat_result r =
        strlen(uri) != uri_length
            ? cat_fail(&m, CAT_ERR_INVALID, "buffer URI \"%s\" contains %%00", uri)
            : cat_uri_resolve(&m, "buffer", io->folder, uri, 0, resolved, sizeof resolved);
    if (r == CAT_OK) {
        char label[PATH_MAX + 64];
        snprintf(label, sizeof label, "buffer file \"%s\" (%s)", uri, resolved);
        r = cat_read_file(&m, label, resolved, CAT_MODEL_MAX_FILE_BYTES, data, size);
    }
    if (r != CAT_OK && io->result == CAT_OK) { /* keep the first failure: it is the cause */
        io->result = r;
        memcpy(io->message, message, sizeof message);
    }
    return r;
}
