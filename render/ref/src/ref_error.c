/* The thread's last error message, in a buffer of its own (render/error_text.h). */
#include "ref_internal.h"
#include "render/error_text.h"

static _Thread_local char last_error[RD_ERROR_TEXT_SIZE];

ref_result ref_fail(ref_result r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rd_error_vformat(last_error, fmt, ap);
    va_end(ap);
    return r;
}

const char *ref_last_error(void)
{
    return last_error;
}

static const char *const RESULT_NAMES[] = {
    [REF_OK] = "ok",
    [REF_ERR_INVALID_ARGUMENT] = "invalid argument",
    [REF_ERR_OUT_OF_MEMORY] = "out of memory",
    [REF_ERR_TOO_LARGE] = "too large",
    [REF_ERR_EMBREE] = "Embree error",
    [REF_ERR_CANCELLED] = "cancelled",
};

const char *ref_result_name(ref_result r)
{
    return rd_error_name(RESULT_NAMES, (int)(sizeof RESULT_NAMES / sizeof *RESULT_NAMES), (int)r);
}
