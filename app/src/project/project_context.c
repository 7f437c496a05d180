/* The reading context: the JSON path of the value being checked and the error message. */
#include "project_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void pj_ctx_init(pj_ctx *c, const char *file, const char *base, char *err, size_t err_size)
{
    memset(c, 0, sizeof *c);
    c->file = file ? file : "<memory>";
    c->base = base;
    c->err = err;
    c->err_size = err_size;
    c->json_path[0] = '$';
    c->json_path[1] = '\0';
    c->json_path_len = 1;
    if (err && err_size > 0)
        err[0] = '\0';
}

static void path_append(pj_ctx *c, const char *text, size_t len)
{
    size_t room = sizeof c->json_path - 1 - c->json_path_len;
    if (len > room) {
        len = room;
        c->path_truncated = 1;
    }
    memcpy(c->json_path + c->json_path_len, text, len);
    c->json_path_len += len;
    c->json_path[c->json_path_len] = '\0';
}

static int is_plain_key(const char *key)
{
    if (!((key[0] >= 'a' && key[0] <= 'z') || (key[0] >= 'A' && key[0] <= 'Z') || key[0] == '_'))
        return 0;
    for (const char *s = key; *s; s++) {
        char ch = *s;
        if (!((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
              ch == '_'))
            return 0;
    }
    return 1;
}

size_t pj_path_key(pj_ctx *c, const char *key)
{
    size_t mark = c->json_path_len;
    if (is_plain_key(key)) {
        path_append(c, ".", 1);
        path_append(c, key, strlen(key));
        return mark;
    }
    /* Keys such as "wall-tile" are shown as ["wall-tile"], escaped, cut at 64 bytes so a
     * hostile key cannot fill the message. */
    char buf[64 * 6 + 16];
    size_t n = 0;
    buf[n++] = '[';
    buf[n++] = '"';
    size_t i = 0;
    for (; key[i] && i < 64; i++) {
        unsigned char ch = (unsigned char)key[i];
        if (ch == '"' || ch == '\\') {
            buf[n++] = '\\';
            buf[n++] = (char)ch;
        } else if (ch < 0x20) {
            n += (size_t)snprintf(buf + n, sizeof buf - n, "\\u%04x", ch);
        } else {
            buf[n++] = (char)ch;
        }
    }
    if (key[i]) {
        memcpy(buf + n, "...", 3);
        n += 3;
    }
    buf[n++] = '"';
    buf[n++] = ']';
    path_append(c, buf, n);
    return mark;
}

size_t pj_path_index(pj_ctx *c, int index)
{
    size_t mark = c->json_path_len;
    char buf[32];
    int n = snprintf(buf, sizeof buf, "[%d]", index);
    path_append(c, buf, (size_t)n);
    return mark;
}

void pj_path_restore(pj_ctx *c, size_t mark)
{
    if (mark < c->json_path_len) {
        c->json_path_len = mark;
        c->json_path[mark] = '\0';
    }
}

static void vformat(pj_ctx *c, const char *path, const char *fmt, va_list ap)
{
    if (!c->err || c->err_size == 0)
        return;
    int n = path ? snprintf(c->err, c->err_size, "%s: %s%s: ", c->file, path,
                            c->path_truncated ? "..." : "")
                 : snprintf(c->err, c->err_size, "%s: ", c->file);
    if (n < 0 || (size_t)n >= c->err_size)
        return;
    vsnprintf(c->err + n, c->err_size - (size_t)n, fmt, ap);
}

app_result pj_fail(pj_ctx *c, app_result r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vformat(c, c->json_path, fmt, ap);
    va_end(ap);
    return r;
}

app_result pj_fail_file(pj_ctx *c, app_result r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vformat(c, NULL, fmt, ap);
    va_end(ap);
    return r;
}

const char *pj_type_name(const cJSON *item)
{
    if (!item)
        return "nothing";
    switch (item->type & 0xFF) {
    case cJSON_False:
    case cJSON_True:
        return "boolean";
    case cJSON_NULL:
        return "null";
    case cJSON_Number:
        return "number";
    case cJSON_String:
        return "string";
    case cJSON_Array:
        return "array";
    case cJSON_Object:
        return "object";
    case cJSON_Raw:
        return "raw";
    default:
        return "invalid";
    }
}

const char *app_result_name(app_result r)
{
    switch (r) {
    case APP_OK:
        return "APP_OK";
    case APP_ERR_IO:
        return "APP_ERR_IO";
    case APP_ERR_PARSE:
        return "APP_ERR_PARSE";
    case APP_ERR_SCHEMA:
        return "APP_ERR_SCHEMA";
    case APP_ERR_VERSION:
        return "APP_ERR_VERSION";
    case APP_ERR_OUT_OF_MEMORY:
        return "APP_ERR_OUT_OF_MEMORY";
    case APP_ERR_NOT_FOUND:
        return "APP_ERR_NOT_FOUND";
    case APP_ERR_CANCELLED:
        return "APP_ERR_CANCELLED";
    }
    return "APP_ERR_UNKNOWN";
}

void pj_ctx_release(pj_ctx *c)
{
    free(c->material_slots);
    c->material_slots = NULL;
    c->material_slot_count = 0;
}
