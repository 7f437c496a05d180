/* The thread's last error message. */
#include "ref_internal.h"

#include <stdarg.h>
#include <stdio.h>

static _Thread_local char last_error[1024];

ref_result ref_fail(ref_result r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(last_error, sizeof last_error, fmt, ap);
    va_end(ap);
    return r;
}

const char *ref_last_error(void)
{
    return last_error;
}

const char *ref_result_name(ref_result r)
{
    switch (r) {
    case REF_OK:
        return "ok";
    case REF_ERR_INVALID_ARGUMENT:
        return "invalid argument";
    case REF_ERR_OUT_OF_MEMORY:
        return "out of memory";
    case REF_ERR_TOO_LARGE:
        return "too large";
    case REF_ERR_EMBREE:
        return "Embree error";
    }
    return "unknown";
}
