/* The one way an encoded image reaches its file name (image_write_file.c). Internal to render/. */
#ifndef RENDER_IMAGE_WRITE_FILE_H
#define RENDER_IMAGE_WRITE_FILE_H

#include "image_internal.h"
#include "image_io_oiio.h"
#include "render/image_io.h"

#include <stddef.h>

/* Encodes desc into a temporary file next to path's target (a symbolic link is followed, so
 * the link stays a link), with the XMP packet xmp spliced in when it is not NULL and the format
 * is JPEG; checks every write, the fsync and the close, checks the file ends as a complete
 * file of its format ends, and only then renames it over the target. On failure the temporary
 * file is removed, an existing file is untouched and err names path and the reason. */
rd_image_result rd_image_write_atomic(const char *path, rd_oiio_write_desc desc,
                                      const rd_image_format_info *fmt, const char *xmp, char *err,
                                      size_t err_size);

/* The fault set by rd_image_debug_set_fault on this thread (image_io.c). */
rd_image_fault rd_image_fault_injected(void);

#endif
