/* A file written whole or not at all: the bytes go to a temporary file beside the target
 * (TARGET.tmp-XXXXXX, through symbolic links to the file they name: render/write_target.h),
 * every write is checked, and the temporary file is synced and renamed over the target only
 * when all of it was written. On any failure (a full disk, a read-only folder, a file size
 * limit) the temporary file is removed, the old target is left as it was, and the message
 * names the target and the system's reason ("No space left on device"). */
#ifndef APP_OUTPUT_SAFE_FILE_H
#define APP_OUTPUT_SAFE_FILE_H

#include "app/project/project.h"

#include <cairo.h>
#include <stdio.h>

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct app_safe_file {
    char *target; /* the file replaced at the end (malloc'd) */
    char *temp;   /* the temporary file (malloc'd) */
    int fd;
    int error; /* the errno of the first failed write; 0 = none */
} app_safe_file;

/* Creates the temporary file. On failure *f owns nothing and err says why. */
app_result app_safe_file_open(app_safe_file *f, const char *path, char *err, size_t err_size);

/* Writes all n bytes (retrying short writes); after a failure it writes nothing more and
 * returns -1, as every later call does. 0 on success. */
int app_safe_file_write(app_safe_file *f, const void *data, size_t n);

/* A cairo_write_func_t over app_safe_file_write (closure: the app_safe_file): for
 * cairo_pdf_surface_create_for_stream and cairo_svg_surface_create_for_stream. */
cairo_status_t app_safe_file_cairo_write(void *closure, const unsigned char *data,
                                         unsigned int length);

/* Syncs, closes and renames the temporary file over the target; on failure (a write failed
 * before, or now) removes it and writes "TARGET: cannot write: REASON" into err. Frees what
 * *f owns either way. */
app_result app_safe_file_commit(app_safe_file *f, char *err, size_t err_size);

/* Removes the temporary file and frees what *f owns (after another failure). */
void app_safe_file_discard(app_safe_file *f);

/* The same through stdio, for tables written with fprintf (the benchmarks' CSV and Markdown). */
typedef struct app_safe_stream {
    app_safe_file file;
    FILE *f; /* write to this; NULL when the open failed */
} app_safe_stream;

/* Opens the temporary file as a stream; NULL with err set on failure. */
FILE *app_safe_stream_open(app_safe_stream *s, const char *path, char *err, size_t err_size);

/* Flushes and checks the stream, then app_safe_file_commit. Safe on a stream whose open
 * failed (returns APP_ERR_IO without touching err). */
app_result app_safe_stream_commit(app_safe_stream *s, char *err, size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
