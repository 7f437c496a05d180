/* make_models: generates the GLB model of every product in the shipped catalog CSV files.
 *
 *   make_models OUT_DIR FILE.csv...
 *
 * For each product (manufacturer + article; the first of its rows) that has a category with a
 * model generator, builds the model from the row (model_gen.h: category, name, series, width,
 * depth, height and the first variant's material) and writes it as OUT_DIR/<model column>
 * (e.g. OUT_DIR/models/aquavera/31000000.glb; when the column is empty, the name
 * cat_model_file_name gives). Run at build time by catalog/CMakeLists.txt into
 * <build>/assets, so the models are not committed. Exit status 1 on any failure. */
#define _POSIX_C_SOURCE 200809L
#include "catalog/catalog.h"
#include "catalog/model_gen.h"
#include "catalog/model_write.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#define MAX_FIELDS 64

/* Reads one CSV record (RFC 4180 quotes) into fields; returns the field count, 0 at the end,
 * -1 on a malformed or oversized record. */
static int read_record(FILE *f, char *buf, size_t size, char **fields)
{
    size_t n = 0;
    int count = 0, quoted = 0, ch, any = 0;
    fields[count++] = buf;
    while ((ch = fgetc(f)) != EOF) {
        any = 1;
        if (quoted) {
            if (ch == '"') {
                int next = fgetc(f);
                if (next == '"') {
                    ch = '"';
                } else {
                    quoted = 0;
                    if (next != EOF)
                        ungetc(next, f);
                    continue;
                }
            }
        } else if (ch == '"') {
            quoted = 1;
            continue;
        } else if (ch == ',') {
            if (n + 1 >= size || count >= MAX_FIELDS)
                return -1;
            buf[n++] = 0;
            fields[count++] = buf + n;
            continue;
        } else if (ch == '\r') {
            continue;
        } else if (ch == '\n') {
            break;
        }
        if (n + 1 >= size)
            return -1;
        buf[n++] = (char)ch;
    }
    buf[n] = 0;
    return any ? count : 0;
}

static int column(char **header, int count, const char *name)
{
    for (int i = 0; i < count; i++)
        if (!strcmp(header[i], name))
            return i;
    return -1;
}

static void parse_rgb(const char *s, float out[3])
{
    sscanf(s, "%f %f %f", &out[0], &out[1], &out[2]);
}

static int mkdirs(char *path) /* makes every folder of path's parent */
{
    for (char *p = path + 1; *p; p++) {
        if (*p != '/')
            continue;
        *p = 0;
        int ok = mkdir(path, 0755) == 0 || errno == EEXIST;
        *p = '/';
        if (!ok)
            return 0;
    }
    return 1;
}

typedef struct seen {
    char key[CAT_MANUFACTURER_BYTES + CAT_ARTICLE_BYTES + 2];
} seen;

static int generate_file(const char *out_dir, const char *csv, seen **keys, int *nkeys,
                         int *written, size_t *bytes)
{
    FILE *f = fopen(csv, "rb");
    if (!f) {
        fprintf(stderr, "%s: %s\n", csv, strerror(errno));
        return 0;
    }
    static char hbuf[8192], buf[1 << 16];
    char *header[MAX_FIELDS], *v[MAX_FIELDS];
    int hn = read_record(f, hbuf, sizeof hbuf, header);
    const char *names[] = {"manufacturer", "article",  "category",     "series",    "name",
                           "width_mm",     "depth_mm", "height_mm",    "model",     "ambient",
                           "diffuse",      "specular", "emissive",     "shininess", "reflectivity",
                           "glossiness",   "blend",    "transparency", "ior"};
    enum {
        MAN,
        ART,
        CAT,
        SER,
        NAME,
        W,
        D,
        H,
        MODEL,
        AMB,
        DIF,
        SPEC,
        EMI,
        SHI,
        KR,
        G,
        BL,
        TR,
        IOR,
        NCOL
    };
    int col[NCOL];
    for (int i = 0; i < NCOL; i++)
        if ((col[i] = column(header, hn, names[i])) < 0) {
            fprintf(stderr, "%s: no column \"%s\"\n", csv, names[i]);
            fclose(f);
            return 0;
        }
    int line = 1, ok = 1, n;
    while ((n = read_record(f, buf, sizeof buf, v)) != 0) {
        line++;
        if (n < 0 || n != hn) {
            fprintf(stderr, "%s:%d: malformed record\n", csv, line);
            ok = 0;
            break;
        }
        cat_category category;
        if (!cat_category_parse(v[col[CAT]], &category) || category == CAT_CATEGORY_TILES)
            continue;
        char key[sizeof(*keys)->key];
        snprintf(key, sizeof key, "%s\n%s", v[col[MAN]], v[col[ART]]);
        int dup = 0;
        for (int i = 0; i < *nkeys && !dup; i++)
            dup = !strcmp((*keys)[i].key, key);
        if (dup)
            continue; /* a further variant row of the same product */
        seen *k = realloc(*keys, (size_t)(*nkeys + 1) * sizeof **keys);
        if (!k) {
            ok = 0;
            break;
        }
        *keys = k;
        snprintf(k[(*nkeys)++].key, sizeof k->key, "%s", key);

        char rel[CAT_PATH_BYTES + 1];
        if (*v[col[MODEL]])
            snprintf(rel, sizeof rel, "%s", v[col[MODEL]]);
        else if (!cat_model_file_name(v[col[MAN]], v[col[ART]], rel, sizeof rel)) {
            fprintf(stderr, "%s:%d: no model file name for this product\n", csv, line);
            ok = 0;
            continue;
        }
        cat_render_material finish;
        memset(&finish, 0, sizeof finish);
        int has_finish = *v[col[DIF]] != 0;
        if (has_finish) {
            parse_rgb(v[col[AMB]], finish.ambient);
            parse_rgb(v[col[DIF]], finish.diffuse);
            parse_rgb(v[col[SPEC]], finish.specular);
            parse_rgb(v[col[EMI]], finish.emissive);
            finish.shininess = strtof(v[col[SHI]], NULL);
            finish.reflectivity = strtof(v[col[KR]], NULL);
            finish.glossiness = strtof(v[col[G]], NULL);
            cat_blend_parse(v[col[BL]], &finish.blend);
            finish.transparency = strtof(v[col[TR]], NULL);
            finish.ior = strtof(v[col[IOR]], NULL);
        }
        cat_gen_request req = {category,
                               v[col[NAME]],
                               v[col[SER]],
                               strtod(v[col[W]], NULL),
                               strtod(v[col[D]], NULL),
                               strtod(v[col[H]], NULL),
                               has_finish ? &finish : NULL};
        cat_gen_model gm;
        char err[1024], path[4096];
        if (cat_gen_product(&req, &gm, err, sizeof err) != CAT_OK) {
            fprintf(stderr, "%s:%d: %s\n", csv, line, err);
            ok = 0;
            continue;
        }
        snprintf(path, sizeof path, "%s/%s", out_dir, rel);
        if (!mkdirs(path) ||
            cat_model_write_glb(path, &gm.model, gm.extras, err, sizeof err) != CAT_OK) {
            fprintf(stderr, "%s:%d: %s\n", csv, line, *err ? err : strerror(errno));
            ok = 0;
        } else {
            struct stat st;
            if (stat(path, &st) == 0)
                *bytes += (size_t)st.st_size;
            ++*written;
        }
        cat_gen_model_free(&gm);
    }
    fclose(f);
    return ok;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: make_models OUT_DIR FILE.csv...\n");
        return 2;
    }
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    seen *keys = NULL;
    int nkeys = 0, written = 0, ok = 1;
    size_t bytes = 0;
    for (int i = 2; i < argc; i++)
        ok &= generate_file(argv[1], argv[i], &keys, &nkeys, &written, &bytes);
    free(keys);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double s = (double)(t1.tv_sec - t0.tv_sec) + (double)(t1.tv_nsec - t0.tv_nsec) / 1e9;
    fprintf(stderr, "make_models: %d models, %.1f MB, in %.2f s\n", written, (double)bytes / 1e6,
            s);
    return ok ? 0 : 1;
}
