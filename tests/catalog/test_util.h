/* Small helpers shared by the catalog tests: a temporary folder, file writing, base64 and GLB
 * assembly, and the invariants every loaded model keeps. The assertions are
 * tests/common/check.h's (CHECK_LOAD_FAILS below counts with them). */
#ifndef TESSERA_TESTS_CATALOG_TEST_UTIL_H
#define TESSERA_TESTS_CATALOG_TEST_UTIL_H

#define _XOPEN_SOURCE 700 /* mkdtemp, nftw, realpath */
#include "../common/check.h"
#include "catalog/model.h"

#include <ftw.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Checks a load's result code and that the message names the file and contains needle. */
#define CHECK_LOAD_FAILS(path, code, needle)                                                       \
    check_load_fails(__FILE__, __LINE__, path, code, needle)

static inline void check_load_fails(const char *file, int line, const char *path, cat_result code,
                                    const char *needle)
{
    cat_model m;
    char err[2048];
    memset(&m, 0xAB, sizeof m);
    cat_result r = cat_model_load(path, &m, err, sizeof err);
    int ok = r == code && strncmp(err, path, strlen(path)) == 0 && strstr(err, needle) &&
             m.meshes == NULL && m.mesh_count == 0 && m.materials == NULL;
    check_count++;
    if (!ok) {
        fprintf(stderr, "%s:%d: load of %s: expected %s with \"%s\", got %s: %s\n", file, line,
                path, cat_result_name(code), needle, cat_result_name(r), err);
        check_failures++;
    }
    if (r == CAT_OK)
        cat_model_free(&m);
}

static char g_tmp[4096];

static inline void tmp_make(void)
{
    const char *base = getenv("TMPDIR");
    snprintf(g_tmp, sizeof g_tmp, "%s/tessera-gltf-XXXXXX", base && *base ? base : "/tmp");
    if (!mkdtemp(g_tmp)) {
        perror("mkdtemp");
        exit(2);
    }
}

static inline int rm_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st;
    (void)flag;
    (void)ftw;
    return remove(path);
}

static inline void tmp_remove(void)
{
    nftw(g_tmp, rm_entry, 16, FTW_DEPTH | FTW_PHYS);
}

/* Path of name inside the temporary folder (a rotating set of buffers). */
static inline const char *tmp_path(const char *name)
{
    static char buf[8][4200];
    static int next;
    char *p = buf[next++ % 8];
    snprintf(p, sizeof buf[0], "%s/%s", g_tmp, name);
    return p;
}

static inline const char *write_file(const char *name, const void *data, size_t size)
{
    const char *path = tmp_path(name);
    FILE *f = fopen(path, "wb");
    if (!f || (size && fwrite(data, 1, size, f) != size) || fclose(f) != 0) {
        perror(path);
        exit(2);
    }
    return path;
}

static inline const char *write_text(const char *name, const char *text)
{
    return write_file(name, text, strlen(text));
}

/* Base64 (RFC 4648) of size bytes into a malloc'ed string. */
static inline char *base64(const void *data, size_t size)
{
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const unsigned char *s = data;
    char *out = malloc((size + 2) / 3 * 4 + 1), *o = out;
    for (size_t i = 0; i < size; i += 3) {
        unsigned v = (unsigned)s[i] << 16;
        if (i + 1 < size)
            v |= (unsigned)s[i + 1] << 8;
        if (i + 2 < size)
            v |= s[i + 2];
        *o++ = digits[v >> 18 & 63];
        *o++ = digits[v >> 12 & 63];
        *o++ = i + 1 < size ? digits[v >> 6 & 63] : '=';
        *o++ = i + 2 < size ? digits[v & 63] : '=';
    }
    *o = '\0';
    return out;
}

static inline void put_u32(unsigned char *p, unsigned v)
{
    p[0] = (unsigned char)v;
    p[1] = (unsigned char)(v >> 8);
    p[2] = (unsigned char)(v >> 16);
    p[3] = (unsigned char)(v >> 24);
}

/* Assembles a GLB (glTF 2.0, 4.4): header, JSON chunk padded with spaces, BIN chunk padded with
 * zeros (left out when bin_size is 0). Returns a malloc'ed buffer of *size bytes. */
static inline unsigned char *make_glb(const char *json, const void *bin, size_t bin_size,
                                      size_t *size)
{
    size_t jlen = strlen(json), jpad = (jlen + 3) / 4 * 4;
    size_t bpad = (bin_size + 3) / 4 * 4;
    size_t total = 12 + 8 + jpad + (bin_size ? 8 + bpad : 0);
    unsigned char *g = calloc(1, total);
    memcpy(g, "glTF", 4);
    put_u32(g + 4, 2);
    put_u32(g + 8, (unsigned)total);
    put_u32(g + 12, (unsigned)jpad);
    put_u32(g + 16, 0x4E4F534Au);
    memcpy(g + 20, json, jlen);
    memset(g + 20 + jlen, ' ', jpad - jlen);
    if (bin_size) {
        put_u32(g + 20 + jpad, (unsigned)bpad);
        put_u32(g + 24 + jpad, 0x004E4942u);
        memcpy(g + 28 + jpad, bin, bin_size);
    }
    *size = total;
    return g;
}

/* One triangle (0,0,0), (1,0,0), (0,1,0) with u16 indices 0 1 2: 36 + 6 bytes (+2 padding). */
static const char one_triangle_json[] =
    "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
    "\"nodes\":[{\"mesh\":0}],"
    "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,"
    "\"material\":0}]}],"
    "\"materials\":[{\"name\":\"glb red\",\"pbrMetallicRoughness\":{\"baseColorFactor\":"
    "[0.5,0.25,1,1],\"metallicFactor\":0.0,\"roughnessFactor\":0.5}}],"
    "\"buffers\":[{\"byteLength\":44}],"
    "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},"
    "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6}],"
    "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
    "\"min\":[0,0,0],\"max\":[1,1,0]},"
    "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]}";

static inline void one_triangle_bin(unsigned char bin[44])
{
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const unsigned short idx[4] = {0, 1, 2, 0};
    memcpy(bin, pos, sizeof pos); /* little-endian host, as glTF */
    memcpy(bin + 36, idx, sizeof idx);
}

static inline unsigned char *one_triangle_glb(size_t *size)
{
    unsigned char bin[44];
    one_triangle_bin(bin);
    return make_glb(one_triangle_json, bin, sizeof bin, size);
}

/* Invariants of any successfully loaded model. Returns the number of broken ones. */
static inline int model_broken(const cat_model *m)
{
    int bad = 0;
    for (int i = 0; i < m->mesh_count; i++) {
        const cat_mesh *me = &m->meshes[i];
        bad += me->vertex_count <= 0 || me->index_count <= 0 || me->index_count % 3 != 0;
        bad += !me->positions || !me->normals || !me->indices;
        bad += me->material < -1 || me->material >= m->material_count;
        if (bad)
            return bad;
        for (int k = 0; k < me->index_count; k++)
            bad += me->indices[k] >= (unsigned)me->vertex_count;
        for (int v = 0; v < me->vertex_count; v++) {
            const float *p = me->positions + 3 * v, *n = me->normals + 3 * v;
            double len = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
            bad += fabs(len - 1.0) > 1e-4;
            for (int k = 0; k < 3; k++) {
                bad += !isfinite(p[k]);
                bad += p[k] < m->bounds_min[k] || p[k] > m->bounds_max[k];
            }
            if (me->uvs)
                bad += !isfinite(me->uvs[2 * v]) || !isfinite(me->uvs[2 * v + 1]);
        }
    }
    return bad;
}

#endif
