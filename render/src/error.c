#include "render_internal.h"

#include <stdio.h>

static _Thread_local char last_error[1024];

void rd_set_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(last_error, sizeof last_error, fmt, ap);
    va_end(ap);
}

rd_result rd_fail(rd_result r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(last_error, sizeof last_error, fmt, ap);
    va_end(ap);
    return r;
}

const char *rd_last_error(void)
{
    return last_error;
}

const char *rd_result_name(rd_result r)
{
    switch (r) {
    case RD_OK:
        return "ok";
    case RD_ERR_INVALID_ARGUMENT:
        return "invalid argument";
    case RD_ERR_BACKEND_UNAVAILABLE:
        return "backend unavailable";
    case RD_ERR_GL:
        return "OpenGL error";
    case RD_ERR_SHADER:
        return "shader error";
    case RD_ERR_OUT_OF_MEMORY:
        return "out of memory";
    case RD_ERR_TOO_LARGE:
        return "too large";
    case RD_ERR_STALE_HANDLE:
        return "stale handle";
    }
    return "unknown";
}
