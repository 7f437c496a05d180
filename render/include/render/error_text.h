/* The last-error convention of render and of render/ref (a separate library that links
 * render): each keeps one message per thread in a buffer of its own, so that a failure in one
 * does not overwrite the other's message, and names its result codes from a table. */
#ifndef RENDER_ERROR_TEXT_H
#define RENDER_ERROR_TEXT_H

#include <stdarg.h>

#ifdef __cplusplus
extern "C" {
#endif

#define RD_ERROR_TEXT_SIZE 1024

/* fmt and ap formatted into buf (RD_ERROR_TEXT_SIZE bytes, truncated to fit). */
void rd_error_vformat(char *buf, const char *fmt, va_list ap);
/* names[code] when code is one of the count names, else "unknown". */
const char *rd_error_name(const char *const *names, int count, int code);

#ifdef __cplusplus
}
#endif
#endif
