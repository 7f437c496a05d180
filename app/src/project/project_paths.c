/* File references in a project: relative "model"/"texture" paths resolve against the project
 * file's folder on read and are written relative to the destination's folder. */
#include "project_internal.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

char *pj_dirname(const char *path)
{
    const char *slash = path ? strrchr(path, '/') : NULL;
    if (!slash) {
        char *dot = pj_malloc(2);
        if (dot)
            memcpy(dot, ".", 2);
        return dot;
    }
    size_t len = (size_t)(slash - path);
    if (len == 0)
        len = 1; /* "/x" -> "/" */
    char *dir = pj_malloc(len + 1);
    if (dir) {
        memcpy(dir, path, len);
        dir[len] = '\0';
    }
    return dir;
}

/* "a/b" + "c" -> "a/b/c"; an absolute `rel` is returned as is. Relative results are made
 * absolute with the current directory so that messages show where we looked. */
static char *join_absolute(const char *dir, const char *rel)
{
    char cwd[4096];
    const char *parts[3] = {NULL, NULL, rel};
    if (rel[0] != '/') {
        parts[1] = dir;
        if (dir[0] != '/') {
            if (!getcwd(cwd, sizeof cwd))
                memcpy(cwd, ".", 2);
            parts[0] = cwd;
        }
    }
    size_t total = 1;
    for (int i = 0; i < 3; i++)
        total += parts[i] ? strlen(parts[i]) + 1 : 0;
    char *out = pj_malloc(total);
    if (!out)
        return NULL;
    size_t n = 0;
    for (int i = 0; i < 3; i++) {
        if (!parts[i])
            continue;
        size_t len = strlen(parts[i]);
        memcpy(out + n, parts[i], len);
        n += len;
        if (i < 2)
            out[n++] = '/';
    }
    out[n] = '\0';
    return out;
}

/* Removes "", "." and "x/.." components in place, lexically (for messages when the file is
 * missing; realpath gives the canonical name when it exists). */
static void normalise_lexically(char *path)
{
    int absolute = path[0] == '/';
    char *out = path;
    char *src = path;
    size_t n = 0;
    if (absolute)
        out[n++] = '/';
    while (*src) {
        while (*src == '/')
            src++;
        if (!*src)
            break;
        char *end = strchr(src, '/');
        size_t len = end ? (size_t)(end - src) : strlen(src);
        if (len == 1 && src[0] == '.') {
            /* skip */
        } else if (len == 2 && src[0] == '.' && src[1] == '.') {
            size_t floor = absolute ? 1 : 0;
            if (n > floor) {
                size_t k = n;
                if (k > floor && out[k - 1] == '/')
                    k--;
                while (k > floor && out[k - 1] != '/')
                    k--;
                n = k;
            }
        } else {
            if (n > 0 && out[n - 1] != '/')
                out[n++] = '/';
            memmove(out + n, src, len);
            n += len;
        }
        src += len;
    }
    if (n > 1 && out[n - 1] == '/')
        n--;
    if (n == 0)
        out[n++] = '.';
    out[n] = '\0';
}

app_result pj_resolve_file(pj_ctx *c, const char *value, char *out, size_t out_size)
{
    if (!c->check_files) {
        size_t len = strlen(value);
        if (len >= out_size)
            return pj_fail(c, APP_ERR_SCHEMA, "path too long (%zu bytes, the limit is %zu)", len,
                           out_size - 1);
        memcpy(out, value, len + 1);
        return APP_OK;
    }
    char *dir = pj_dirname(c->base);
    char *joined = dir ? join_absolute(dir, value) : NULL;
    free(dir);
    if (!joined)
        return pj_fail(c, APP_ERR_OUT_OF_MEMORY, "out of memory");

    /* realpath sees the path as written (symbolic links before ".."); the lexical form is
     * only for the message. */
    char *real = realpath(joined, NULL);
    if (!real) {
        int e = errno;
        normalise_lexically(joined);
        app_result r;
        if (e == ENOENT || e == ENOTDIR)
            r = pj_fail(c, APP_ERR_NOT_FOUND, "file not found: %s", joined);
        else if (e == ENOMEM)
            r = pj_fail(c, APP_ERR_OUT_OF_MEMORY, "out of memory");
        else
            r = pj_fail(c, APP_ERR_NOT_FOUND, "cannot access %s: %s", joined, strerror(e));
        free(joined);
        return r;
    }
    normalise_lexically(joined);
    struct stat st;
    app_result r = APP_OK;
    if (stat(real, &st) != 0)
        r = pj_fail(c, APP_ERR_NOT_FOUND, "cannot access %s: %s", joined, strerror(errno));
    else if (!S_ISREG(st.st_mode))
        r = pj_fail(c, APP_ERR_NOT_FOUND, "not a regular file: %s", joined);
    else if (strlen(real) >= out_size)
        r = pj_fail(c, APP_ERR_SCHEMA, "path too long (%zu bytes, the limit is %zu): %s",
                    strlen(real), out_size - 1, real);
    else
        memcpy(out, real, strlen(real) + 1);
    free(real);
    free(joined);
    return r;
}

char *pj_relative_path(const char *from_dir, const char *target)
{
    /* Common leading components, then one ".." per remaining component of from_dir. */
    size_t common = 0; /* length of the shared prefix, ending at a component boundary */
    size_t i = 0;
    for (;; i++) {
        char a = from_dir[i], b = target[i];
        if ((a == '/' || a == '\0') && (b == '/' || b == '\0'))
            common = i;
        if (a == '\0' || b == '\0' || a != b)
            break;
    }
    if (strcmp(from_dir, "/") == 0)
        common = 0;
    size_t ups = 0;
    const char *rest_dir = from_dir + common;
    for (const char *s = rest_dir; *s; s++) {
        if (*s != '/' && (s == rest_dir || s[-1] == '/'))
            ups++;
    }
    const char *rest = target + common;
    while (*rest == '/')
        rest++;
    size_t len = ups * 3 + strlen(rest) + 1;
    char *out = pj_malloc(len);
    if (!out)
        return NULL;
    size_t n = 0;
    for (size_t k = 0; k < ups; k++) {
        memcpy(out + n, "../", 3);
        n += 3;
    }
    memcpy(out + n, rest, strlen(rest) + 1);
    return out;
}
