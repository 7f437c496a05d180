/* Error messages of the model loader: every message starts with the file it is about. */
#include "model_internal.h"

#include <stdarg.h>
#include <stdio.h>

cat_result cat_fail(const cat_msg *msg, cat_result code, const char *fmt, ...)
{
    if (!msg || !msg->buf || msg->size == 0)
        return code;
    int n = snprintf(msg->buf, msg->size, "%s: ", msg->path ? msg->path : "(no file)");
    if (n < 0 || (size_t)n >= msg->size)
        return code;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg->buf + n, msg->size - (size_t)n, fmt, ap);
    va_end(ap);
    return code;
}

const char *cat_result_name(cat_result r)
{
    switch (r) {
    case CAT_OK:
        return "ok";
    case CAT_ERR_IO:
        return "input/output error";
    case CAT_ERR_PARSE:
        return "parse error";
    case CAT_ERR_INVALID:
        return "invalid data";
    case CAT_ERR_UNSUPPORTED:
        return "unsupported feature";
    case CAT_ERR_OUT_OF_MEMORY:
        return "out of memory";
    case CAT_ERR_TOO_LARGE:
        return "too large";
    }
    return "unknown result";
}
