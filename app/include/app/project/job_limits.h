/* The size limits of every job, from one table (docs/limits.md): the project reader checks
 * $.render.size against it, and every command that makes an image, a panorama, a video or a
 * reference render checks its job against it up front, before any rendering, together with
 * the memory the job will need. A job outside the table is refused with a message that names
 * the limit; nothing is truncated. */
#ifndef APP_JOB_LIMITS_H
#define APP_JOB_LIMITS_H

#include "app/project/project.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum app_job_kind {
    APP_JOB_IMAGE,     /* render: one image (PNG, JPEG, TIFF; EXR adds a float copy) */
    APP_JOB_PANORAMA,  /* panorama: six cube faces of width/4 and an equirectangular image */
    APP_JOB_VIDEO,     /* video: one frame buffer, frames written one by one */
    APP_JOB_REFERENCE, /* reference: the CPU path tracer, float accumulation */
} app_job_kind;

typedef struct app_job {
    app_job_kind kind;
    int width, height; /* the image written, pixels */
    int float_copy;    /* 1: a linear float copy is kept too (EXR output) */
    long frames;       /* APP_JOB_VIDEO: frames rendered */
    long samples;      /* APP_JOB_REFERENCE: paths a pixel (0 = none) */
} app_job;

/* One row of the table. */
typedef struct app_limit {
    const char *name; /* "image side", "image pixels", ... */
    double value;     /* the largest value allowed */
    const char *unit; /* "pixels", "frames", ... */
    const char *why;  /* what sets the limit */
} app_limit;

enum {
    APP_LIMIT_IMAGE_SIDE,
    APP_LIMIT_IMAGE_PIXELS,
    APP_LIMIT_PANORAMA_PIXELS,
    APP_LIMIT_VIDEO_FRAMES,
    APP_LIMIT_SAMPLES,
    APP_LIMIT_LIGHTS,
    APP_LIMIT_COUNT
};

/* The table (APP_LIMIT_COUNT rows, in the order of the enum). */
const app_limit *app_limits(void);

/* The memory the job will need at its peak, bytes (an estimate from measured bytes a pixel,
 * docs/limits.md "Memory"). */
double app_job_memory_bytes(const app_job *j);

/* The memory a job may use, bytes: the machine's physical memory, lowered by RLIMIT_AS and
 * RLIMIT_DATA when they are set, and by TESSERA_MEMORY_LIMIT_MB when it is set. */
double app_memory_available_bytes(void);

/* Checks j against the table and the memory; on failure writes "what: problem" into err (what
 * names the input, e.g. "--size 20000x20000") and returns APP_ERR_SCHEMA. */
app_result app_job_check(const app_job *j, const char *what, char *err, size_t err_size);

/* Checks an image size against the side and pixel limits only (no memory), for files: the
 * reader's $.render.size. Returns 0 when it fits, else writes the broken limit into err. */
int app_image_size_fits(long width, long height, char *err, size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
