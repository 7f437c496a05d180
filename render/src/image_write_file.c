/* rd_image_write_atomic: temporary file, checked writes, completeness check, then rename.
 * The encoder runs into memory where its writer allows (OpenImageIO's IOProxy): libpng and
 * libjpeg then never see a failing write, which OIIO 2.4's PNG writer would ignore (a file cut
 * short reported as written) and libjpeg's default error_exit would answer by ending the
 * process. The bytes are written here with write(2), each result checked, so a full disk or a
 * file size limit gives its own errno ("No space left on device", "File too large"). */
#include "image_write_file.h"

#include "render/write_target.h"

#include <errno.h>
#include <fcntl.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static atomic_uint temp_counter;

/* Creates TARGET.tmp-<pid>-<n> exclusively with mode; returns its name (malloc'd) and an open
 * descriptor in *fd, or NULL with errno set. */
static char *create_temp_file(const char *target, mode_t mode, int *fd)
{
    size_t cap = strlen(target) + 64;
    char *temp = malloc(cap);
    if (temp == NULL) {
        errno = ENOMEM;
        return NULL;
    }
    for (int attempt = 0; attempt < 16; attempt++) {
        unsigned n = atomic_fetch_add(&temp_counter, 1u);
        snprintf(temp, cap, "%s.tmp-%ld-%u", target, (long)getpid(), n);
        *fd =
            open(temp, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, mode); /* read back: ends_complete */
        if (*fd >= 0)
            return temp;
        if (errno != EEXIST)
            break;
    }
    int saved = errno;
    free(temp);
    errno = saved;
    return NULL;
}

/* 0, or the errno of the write that failed. */
static int write_all(int fd, const unsigned char *data, size_t len)
{
    size_t done = 0;
    while (done < len) {
        ssize_t n = write(fd, data + done, len - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return n < 0 ? errno : EIO;
        done += (size_t)n;
    }
    return 0;
}

/* Whether the file behind fd ends as a complete file of its format ends: a PNG with its IEND
 * chunk (PNG specification 11.2.5: length 0, "IEND", CRC AE 42 60 82), a JPEG with its EOI
 * marker FF D9 (ITU T.81 B.2.1), any other format with at least one byte. Cheap: one fstat
 * and one read of the last 12 bytes. */
static int ends_complete(int fd, const rd_image_format_info *fmt, char *detail, size_t size)
{
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
    struct stat st;
    if (fstat(fd, &st) != 0) {
        snprintf(detail, size, "%s", strerror(errno));
        return 0;
    }
    unsigned char tail[12];
    if (st.st_size >= 12 && pread(fd, tail, 12, st.st_size - 12) != 12) {
        snprintf(detail, size, "cannot read the file back: %s", strerror(errno));
        return 0;
    }
    int ok = st.st_size > 0;
    if (strcmp(fmt->oiio_name, "png") == 0)
        ok = st.st_size >= 12 && memcmp(tail, iend, 12) == 0;
    else if (strcmp(fmt->oiio_name, "jpeg") == 0)
        ok = st.st_size >= 12 && tail[10] == 0xFF && tail[11] == 0xD9;
    if (!ok)
        snprintf(detail, size, "the file written is incomplete (%lld bytes, no %s end marker)",
                 (long long)st.st_size, fmt->name);
    return ok;
}

/* Encodes into the open temporary file fd (or, for a writer without memory output, lets
 * OpenImageIO write temp itself and reopens it into *fd). 0 on success, else the message. */
static rd_image_result encode_into(int *fd, const char *temp, rd_oiio_write_desc desc,
                                   const rd_image_format_info *fmt, const char *xmp, char *detail,
                                   size_t size)
{
    desc.path = temp;
    rd_oiio_bytes bytes = {NULL, 0};
    /* OIIO 2.4's TIFF writer makes a file without its ImageLength tag through an IOProxy, so
     * TIFF (and HDR) are written by OIIO itself; their writers report a failed write. */
    rd_oiio_status st = RD_OIIO_ERR_NO_PROXY;
    if (strcmp(fmt->oiio_name, "tiff") != 0 && strcmp(fmt->oiio_name, "hdr") != 0)
        st = rd_oiio_write_memory(&desc, &bytes, detail, size);
    if (st == RD_OIIO_ERR_NO_PROXY) {
        close(*fd);
        *fd = -1;
        errno = 0;
        st = rd_oiio_write(&desc, detail, size);
        int cause = errno;
        /* The library's message rarely says why; the failed write's errno, still set, does. */
        if (st != RD_OIIO_OK && (cause == ENOSPC || cause == EFBIG || cause == EDQUOT ||
                                 cause == EIO || cause == EROFS)) {
            size_t used = strlen(detail);
            snprintf(detail + used, size - used, " (%s)", strerror(cause));
        }
        if (st == RD_OIIO_OK && (*fd = open(temp, O_RDONLY | O_CLOEXEC)) < 0) {
            snprintf(detail, size, "%s", strerror(errno));
            return RD_IMAGE_ERR_IO;
        }
    }
    if (st != RD_OIIO_OK)
        return st == RD_OIIO_ERR_NOMEM ? RD_IMAGE_ERR_OUT_OF_MEMORY : RD_IMAGE_ERR_IO;
    if (bytes.data == NULL)
        return RD_IMAGE_OK; /* written by OpenImageIO itself */
    rd_image_result result = RD_IMAGE_OK;
    unsigned char *with_xmp = NULL;
    size_t with_xmp_size = 0;
    if (xmp != NULL && strcmp(fmt->oiio_name, "jpeg") == 0 &&
        !rd_image_jpeg_insert_xmp(bytes.data, bytes.size, xmp, &with_xmp, &with_xmp_size, detail,
                                  size))
        result = RD_IMAGE_ERR_INVALID;
    int werr = 0;
    if (result == RD_IMAGE_OK)
        werr = with_xmp ? write_all(*fd, with_xmp, with_xmp_size)
                        : write_all(*fd, bytes.data, bytes.size);
    if (werr != 0) {
        snprintf(detail, size, "%s", strerror(werr));
        result = RD_IMAGE_ERR_IO;
    }
    free(with_xmp);
    free(bytes.data);
    return result;
}

rd_image_result rd_image_write_atomic(const char *path, rd_oiio_write_desc desc,
                                      const rd_image_format_info *fmt, const char *xmp, char *err,
                                      size_t err_size)
{
    char *target = rd_write_target(path);
    if (target == NULL) {
        rd_image_set_error(err, err_size, "%s: cannot write: out of memory", path);
        return RD_IMAGE_ERR_OUT_OF_MEMORY;
    }
    struct stat st;
    mode_t mode = 0666; /* less the umask, as a plain new file */
    if (stat(target, &st) == 0 && S_ISREG(st.st_mode))
        mode = st.st_mode & 07777; /* a replaced file keeps its permissions */
    int fd = -1;
    char *temp = create_temp_file(target, mode, &fd);
    if (temp == NULL) {
        int saved = errno;
        rd_image_set_error(err, err_size, "%s: cannot write: %s", path, strerror(saved));
        free(target);
        return saved == ENOMEM ? RD_IMAGE_ERR_OUT_OF_MEMORY : RD_IMAGE_ERR_IO;
    }
    char detail[512] = "";
    rd_image_result result = encode_into(&fd, temp, desc, fmt, xmp, detail, sizeof detail);
    if (result == RD_IMAGE_OK && fsync(fd) != 0) {
        snprintf(detail, sizeof detail, "%s (fsync)", strerror(errno));
        result = RD_IMAGE_ERR_IO;
    }
    if (result == RD_IMAGE_OK && !ends_complete(fd, fmt, detail, sizeof detail))
        result = RD_IMAGE_ERR_IO;
    if (fd >= 0 && close(fd) != 0 && result == RD_IMAGE_OK) {
        snprintf(detail, sizeof detail, "%s (close)", strerror(errno));
        result = RD_IMAGE_ERR_IO;
    }
    if (result != RD_IMAGE_OK)
        rd_image_set_error(err, err_size, "%s: cannot write %s: %s", path, fmt->name, detail);
    else if (rd_image_fault_injected() == RD_IMAGE_FAULT_AFTER_TEMP_WRITE) {
        rd_image_set_error(err, err_size, "%s: cannot write: injected fault after writing %s", path,
                           temp);
        result = RD_IMAGE_ERR_IO;
    } else if (rename(temp, target) != 0) {
        rd_image_set_error(err, err_size, "%s: cannot replace: %s", path, strerror(errno));
        result = RD_IMAGE_ERR_IO;
    }
    if (result != RD_IMAGE_OK)
        unlink(temp);
    else
        rd_sync_parent_folder(target);
    free(temp);
    free(target);
    return result;
}
