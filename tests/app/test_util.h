/* Helpers of the app tests: text and file handling, temporary folders. The assertions are
 * tests/common/check.h's; the test's main returns check_report(). */
#ifndef TESSERA_TEST_UTIL_H
#define TESSERA_TEST_UTIL_H

#ifndef _XOPEN_SOURCE
#define _XOPEN_SOURCE 700 /* mkdtemp, realpath */
#endif

#include "../common/check.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static inline int tu_contains(const char *hay, const char *needle)
{
    return hay && needle && strstr(hay, needle) != NULL;
}

/* Whole file, NUL-terminated; NULL on failure. */
static inline char *tu_read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);
    size_t got;
    while (buf && (got = fread(buf + n, 1, cap - n - 1, f)) > 0) {
        n += got;
        if (cap - n - 1 == 0) {
            char *grown = realloc(buf, cap * 2);
            if (!grown) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = grown;
            cap *= 2;
        }
    }
    fclose(f);
    if (buf) {
        buf[n] = '\0';
        if (len)
            *len = n;
    }
    return buf;
}

static inline int tu_write_file(const char *path, const char *data, size_t len)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    int ok = fwrite(data, 1, len, f) == len;
    return fclose(f) == 0 && ok;
}

/* text with the first occurrence of find replaced; NULL when find does not occur. */
static inline char *tu_replace(const char *text, const char *find, const char *replace)
{
    const char *at = strstr(text, find);
    if (!at)
        return NULL;
    size_t head = (size_t)(at - text), flen = strlen(find), rlen = strlen(replace);
    size_t tail = strlen(at + flen);
    char *out = malloc(head + rlen + tail + 1);
    if (!out)
        return NULL;
    memcpy(out, text, head);
    memcpy(out + head, replace, rlen);
    memcpy(out + head + rlen, at + flen, tail + 1);
    return out;
}

/* A fresh folder under $TMPDIR or /tmp; the caller frees the name. */
static inline char *tu_make_temp_dir(void)
{
    const char *base = getenv("TMPDIR");
    if (!base || !base[0])
        base = "/tmp";
    size_t n = strlen(base) + 64;
    char *tmpl = malloc(n);
    if (!tmpl)
        return NULL;
    snprintf(tmpl, n, "%s/tessera-project-test-XXXXXX", base);
    if (!mkdtemp(tmpl)) {
        free(tmpl);
        return NULL;
    }
    return tmpl;
}

/* Removes a folder and everything under it (no symbolic links are followed). */
static inline void tu_remove_tree(const char *dir)
{
    DIR *d = opendir(dir);
    if (d) {
        struct dirent *e;
        while ((e = readdir(d)) != NULL) {
            if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
                continue;
            size_t n = strlen(dir) + strlen(e->d_name) + 2;
            char *path = malloc(n);
            if (!path)
                break;
            snprintf(path, n, "%s/%s", dir, e->d_name);
            struct stat st;
            if (lstat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
                chmod(path, 0700);
                tu_remove_tree(path);
            } else {
                unlink(path);
            }
            free(path);
        }
        closedir(d);
    }
    rmdir(dir);
}

/* The number of entries in a folder whose name contains `part`. */
static inline int tu_count_entries(const char *dir, const char *part)
{
    DIR *d = opendir(dir);
    int n = 0;
    if (!d)
        return -1;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (strstr(e->d_name, part))
            n++;
    }
    closedir(d);
    return n;
}

#endif
