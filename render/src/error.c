/* The thread's last error message (render.h) and the helpers render/ref shares
 * (render/error_text.h). */
#include "render/error_text.h"
#include "render_internal.h"

#include <stdio.h>

static _Thread_local char last_error[RD_ERROR_TEXT_SIZE];

void rd_error_vformat(char *buf, const char *fmt, va_list ap)
{
    vsnprintf(buf, RD_ERROR_TEXT_SIZE, fmt, ap);
}

const char *rd_error_name(const char *const *names, int count, int code)
{
    return code >= 0 && code < count && names[code] ? names[code] : "unknown";
}

void rd_set_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rd_error_vformat(last_error, fmt, ap);
    va_end(ap);
}

rd_result rd_fail(rd_result r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rd_error_vformat(last_error, fmt, ap);
    va_end(ap);
    return r;
}

const char *rd_last_error(void)
{
    return last_error;
}

static const char *const RESULT_NAMES[] = {
    [RD_OK] = "ok",
    [RD_ERR_INVALID_ARGUMENT] = "invalid argument",
    [RD_ERR_BACKEND_UNAVAILABLE] = "backend unavailable",
    [RD_ERR_GL] = "OpenGL error",
    [RD_ERR_SHADER] = "shader error",
    [RD_ERR_OUT_OF_MEMORY] = "out of memory",
    [RD_ERR_TOO_LARGE] = "too large",
    [RD_ERR_STALE_HANDLE] = "stale handle",
};

const char *rd_result_name(rd_result r)
{
    return rd_error_name(RESULT_NAMES, (int)(sizeof RESULT_NAMES / sizeof *RESULT_NAMES), (int)r);
}
