/* Resolving the relative URIs a glTF file uses for buffers and images.
 *
 * Only plain relative references are accepted: a model may read files in its own folder and
 * below it, nothing else. The check is lexical (symbolic links inside the folder are followed
 * by the operating system when the file is opened). */
#include "model_internal.h"

#include <stdlib.h>
#include <string.h>

static int hex_value(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

/* Length of a URI scheme ("http" in "http://x"), 0 when there is none. */
static size_t scheme_length(const char *s)
{
    size_t i = 0;
    if (!((s[0] >= 'a' && s[0] <= 'z') || (s[0] >= 'A' && s[0] <= 'Z')))
        return 0;
    for (i = 1; s[i]; i++) {
        char c = s[i];
        if (c == ':')
            return i;
        int ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                 c == '+' || c == '-' || c == '.';
        if (!ok)
            return 0;
    }
    return 0;
}

cat_result cat_uri_resolve(const cat_msg *msg, const char *what, const char *folder,
                           const char *uri, int decode, char *out, size_t out_size)
{
    size_t n = strlen(uri);
    if (n == 0)
        return cat_fail(msg, CAT_ERR_INVALID, "%s has an empty URI", what);
    if (n > 4096)
        return cat_fail(msg, CAT_ERR_INVALID, "%s has a URI of %zu bytes, longer than any path",
                        what, n);
    char path[4097];
    size_t len = 0;
    for (size_t i = 0; i < n; i++) {
        char c = uri[i];
        if (decode && c == '%') {
            /* uri is NUL-terminated and hex_value('\0') < 0: no read past its end */
            int hi = hex_value(uri[i + 1]);
            int lo = hi >= 0 ? hex_value(uri[i + 2]) : -1;
            if (hi < 0 || lo < 0)
                return cat_fail(msg, CAT_ERR_INVALID, "%s URI \"%s\" has a bad %% escape", what,
                                uri);
            c = (char)(hi * 16 + lo);
            i += 2;
            if (c == '\0')
                return cat_fail(msg, CAT_ERR_INVALID, "%s URI \"%s\" contains %%00", what, uri);
        }
        path[len++] = c;
    }
    path[len] = '\0';

    size_t scheme = scheme_length(path);
    if (scheme > 0)
        return cat_fail(msg, CAT_ERR_UNSUPPORTED,
                        "%s URI \"%s\" has a scheme (%.*s:); only relative file references are "
                        "allowed",
                        what, uri, (int)scheme, path);
    if (path[0] == '/')
        return cat_fail(msg, CAT_ERR_INVALID,
                        "%s URI \"%s\" is an absolute path; only files in the model's folder may "
                        "be referenced",
                        what, uri);
    if (strchr(path, '\\'))
        return cat_fail(msg, CAT_ERR_INVALID,
                        "%s URI \"%s\" contains a backslash; glTF URIs use '/' only", what, uri);

    /* Rebuild the path from its segments, dropping "." and resolving "..": a ".." that would
     * leave the folder is refused. */
    size_t flen = strlen(folder);
    if (flen + 1 >= out_size)
        return cat_fail(msg, CAT_ERR_INVALID, "the model's folder path is too long");
    memcpy(out, folder, flen);
    size_t base = flen;
    if (base > 0 && out[base - 1] == '/')
        base--; /* folder "/" */
    size_t o = base;
    const char *p = path;
    while (*p) {
        const char *slash = strchr(p, '/');
        size_t seg = slash ? (size_t)(slash - p) : strlen(p);
        if (seg == 0 || (seg == 1 && p[0] == '.')) {
            /* empty or "." segment */
        } else if (seg == 2 && p[0] == '.' && p[1] == '.') {
            if (o == base)
                return cat_fail(msg, CAT_ERR_INVALID,
                                "%s URI \"%s\" climbs out of the model's folder with \"..\"", what,
                                uri);
            while (o > base && out[o - 1] != '/')
                o--;
            o--; /* the slash */
        } else {
            if (o + 1 + seg + 1 > out_size)
                return cat_fail(msg, CAT_ERR_INVALID, "%s URI \"%s\" gives a path that is too long",
                                what, uri);
            out[o++] = '/';
            memcpy(out + o, p, seg);
            o += seg;
        }
        p += seg;
        if (*p == '/')
            p++;
    }
    if (o == base)
        return cat_fail(msg, CAT_ERR_INVALID, "%s URI \"%s\" names the model's folder, not a file",
                        what, uri);
    out[o] = '\0';
    return CAT_OK;
}
