/* Names and places of generated model files (model_gen.h). The models are generated at build
 * time into <build>/assets/models (catalog/CMakeLists.txt), so the default folder is compiled
 * in as CAT_MODELS_DEFAULT_DIR; $TESSERA_MODELS overrides it (an installed copy, tests). */
#include "catalog/model_gen.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef CAT_MODELS_DEFAULT_DIR
#define CAT_MODELS_DEFAULT_DIR "assets/models"
#endif

static int slug(const char *s, char *out, size_t size, size_t *len)
{
    size_t n = *len;
    int dash = 0, any = 0;
    for (; s && *s; s++) {
        char ch = *s;
        if (ch >= 'A' && ch <= 'Z')
            ch = (char)(ch - 'A' + 'a');
        if ((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9')) {
            if (dash && any) {
                if (n + 1 >= size)
                    return 0;
                out[n++] = '-';
            }
            if (n + 1 >= size)
                return 0;
            out[n++] = ch;
            dash = 0;
            any = 1;
        } else {
            dash = 1;
        }
    }
    out[n] = 0;
    *len = n;
    return any;
}

int cat_model_file_name(const char *manufacturer, const char *article, char *out, size_t size)
{
    if (!out || size < 16)
        return 0;
    size_t n = 7;
    memcpy(out, "models/", 8);
    if (!slug(manufacturer, out, size, &n) || n + 2 >= size)
        return 0;
    out[n++] = '/';
    if (!slug(article, out, size, &n) || n + 5 >= size)
        return 0;
    memcpy(out + n, ".glb", 5);
    return 1;
}

int cat_models_dir(char *out, size_t size)
{
    const char *env = getenv("TESSERA_MODELS");
    const char *dir = env && *env ? env : CAT_MODELS_DEFAULT_DIR;
    int n = snprintf(out, size, "%s", dir);
    return n > 0 && (size_t)n < size;
}

int cat_model_resolve(const char *model, const char *assets_dir, char *out, size_t size)
{
    if (!model || !*model || model[0] == '/' || strstr(model, ".."))
        return 0;
    int n;
    if (!strncmp(model, "models/", 7)) {
        char dir[4096];
        if (!cat_models_dir(dir, sizeof dir))
            return 0;
        n = snprintf(out, size, "%s/%s", dir, model + 7);
    } else if (assets_dir && *assets_dir) {
        n = snprintf(out, size, "%s/%s", assets_dir, model);
    } else {
        n = snprintf(out, size, "%s", model);
    }
    return n > 0 && (size_t)n < size;
}
