/* cat_model_load: file, container and JSON checks in C, parsing by tinygltf (gltf_load.cpp),
 * baking in model_build.c. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "model_internal.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Absolute folder of path (symbolic links resolved), malloc'ed; NULL on failure. */
static char *model_folder(const char *path)
{
    size_t n = strlen(path);
    char *dir = malloc(n + 2);
    if (!dir)
        return NULL;
    memcpy(dir, path, n + 1);
    char *slash = strrchr(dir, '/');
    if (!slash)
        strcpy(dir, ".");
    else if (slash == dir)
        dir[1] = '\0';
    else
        *slash = '\0';
    char *abs = realpath(dir, NULL);
    int e = errno;
    free(dir);
    errno = e;
    return abs;
}

/* tinygltf's messages end in newlines and may hold several lines: make them one line. */
static void one_line(char *s)
{
    size_t n = strlen(s);
    while (n > 0 && (s[n - 1] == '\n' || s[n - 1] == '\r' || s[n - 1] == ' '))
        s[--n] = '\0';
    for (size_t i = 0; i < n; i++)
        if (s[i] == '\n' || s[i] == '\r')
            s[i] = ';';
}

cat_result cat_model_load(const char *path, cat_model *out, char *err, size_t err_size)
{
    if (err && err_size)
        err[0] = '\0';
    cat_msg msg = {path ? path : "(no file)", err, err_size};
    if (!out)
        return cat_fail(&msg, CAT_ERR_INVALID, "no model to load into");
    memset(out, 0, sizeof *out);
    if (!path || !path[0])
        return cat_fail(&msg, CAT_ERR_IO, "no file name given");

    unsigned char *bytes = NULL;
    size_t size = 0;
    cat_result r = cat_read_file(&msg, "the file", path, CAT_MODEL_MAX_FILE_BYTES, &bytes, &size);
    if (r != CAT_OK)
        return r;
    char *folder = NULL;
    void *handle = NULL;
    int is_glb = size >= 4 && memcmp(bytes, "glTF", 4) == 0;
    const unsigned char *json = bytes;
    size_t json_size = size;
    if (size == 0)
        r = cat_fail(&msg, CAT_ERR_PARSE, "not a glTF file (the file is empty)");
    if (r == CAT_OK && is_glb)
        r = cat_glb_check(&msg, bytes, size, &json, &json_size);
    if (r == CAT_OK)
        r = cat_json_scan(&msg, json, json_size);
    if (r == CAT_OK) {
        folder = model_folder(path);
        if (!folder)
            r = cat_fail(&msg, errno == ENOMEM ? CAT_ERR_OUT_OF_MEMORY : CAT_ERR_IO,
                         "cannot resolve the model's folder: %s", strerror(errno));
    }
    if (r == CAT_OK) {
        cat_gltf_io io = {folder, &msg, CAT_OK, ""};
        cat_gltf_doc doc;
        char detail[1024] = "";
        memset(&doc, 0, sizeof doc);
        r = cat_gltf_parse(bytes, size, is_glb, &io, &doc, &handle, detail, sizeof detail);
        if (r != CAT_OK && io.result != CAT_OK) {
            r = io.result; /* the external file's own, precise message */
            if (err && err_size)
                snprintf(err, err_size, "%s", io.message);
        } else if (r != CAT_OK) {
            one_line(detail);
            if (strncmp(detail, "[json.exception.", 16) == 0)
                r = cat_fail(&msg, CAT_ERR_PARSE, "not a glTF file (JSON error: %s)", detail);
            else
                r = cat_fail(&msg, r, "%s: %s",
                             r == CAT_ERR_OUT_OF_MEMORY ? "out of memory" : "invalid glTF", detail);
        } else {
            r = cat_model_build(&msg, &doc, folder, out);
        }
    }
    cat_gltf_release(handle);
    free(folder);
    free(bytes);
    if (r != CAT_OK)
        cat_model_free(out);
    return r;
}
