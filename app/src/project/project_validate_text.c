/* Every string of a project file, member names included, must be valid UTF-8: names end up in
 * the PDF print (cairo refuses invalid text), in glTF files (JSON requires UTF-8) and on the
 * screen. Checking the parsed tree once, before any section is read, gives one message with the
 * JSON path for every command instead of a failure deep in one writer. */
#include "project_internal.h"

#include <stdint.h>
#include <string.h>

/* Byte offset of the first byte that breaks UTF-8 (RFC 3629, section 4: no overlong forms, no
 * surrogates D800-DFFF, nothing above U+10FFFF), or -1 when s is valid. */
long pj_utf8_invalid_at(const char *s)
{
    const unsigned char *u = (const unsigned char *)s;
    size_t i = 0;
    while (u[i]) {
        unsigned char b = u[i];
        int extra;
        unsigned char lo = 0x80, hi = 0xBF; /* the allowed range of the second byte */
        if (b < 0x80) {
            i++;
            continue;
        } else if (b >= 0xC2 && b <= 0xDF) {
            extra = 1;
        } else if (b >= 0xE0 && b <= 0xEF) {
            extra = 2;
            if (b == 0xE0)
                lo = 0xA0; /* overlong */
            else if (b == 0xED)
                hi = 0x9F; /* surrogates */
        } else if (b >= 0xF0 && b <= 0xF4) {
            extra = 3;
            if (b == 0xF0)
                lo = 0x90; /* overlong */
            else if (b == 0xF4)
                hi = 0x8F; /* above U+10FFFF */
        } else {
            return (long)i;
        }
        for (int k = 1; k <= extra; k++) {
            unsigned char c = u[i + (size_t)k];
            unsigned char min = k == 1 ? lo : 0x80, max = k == 1 ? hi : 0xBF;
            if (c < min || c > max)
                return (long)i;
        }
        i += (size_t)extra + 1;
    }
    return -1;
}

static app_result check_item(pj_ctx *c, const cJSON *item)
{
    if (cJSON_IsString(item) && item->valuestring) {
        long at = pj_utf8_invalid_at(item->valuestring);
        if (at >= 0)
            return pj_fail(c, APP_ERR_SCHEMA,
                           "not valid UTF-8 text (byte %ld of the string); save the file as UTF-8",
                           at + 1);
        return APP_OK;
    }
    if (!cJSON_IsObject(item) && !cJSON_IsArray(item))
        return APP_OK;
    int index = 0;
    for (const cJSON *e = item->child; e; e = e->next, index++) {
        size_t mark;
        if (cJSON_IsObject(item)) {
            const char *key = e->string ? e->string : "";
            long at = pj_utf8_invalid_at(key);
            if (at >= 0)
                return pj_fail(c, APP_ERR_SCHEMA,
                               "the name of member %d is not valid UTF-8 text (byte %ld); save "
                               "the file as UTF-8",
                               index + 1, at + 1);
            mark = pj_path_key(c, key);
        } else {
            mark = pj_path_index(c, index);
        }
        app_result r = check_item(c, e);
        if (r != APP_OK)
            return r;
        pj_path_restore(c, mark);
    }
    return APP_OK;
}

app_result pj_check_text(pj_ctx *c, const cJSON *root)
{
    return check_item(c, root);
}
