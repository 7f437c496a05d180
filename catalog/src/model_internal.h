/* Internals of the glTF loader, shared by the C side (model_*.c) and the C++ adapter
 * (gltf_load.cpp). The adapter only copies tinygltf's parse into the plain cat_gltf_doc below;
 * every check and every computation happens in C. */
#ifndef CATALOG_MODEL_INTERNAL_H
#define CATALOG_MODEL_INTERNAL_H

#include "catalog/model.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- error reporting ---------------------------------------------------------------------- */

/* Where a message goes: "PATH: " is put in front of every message. */
typedef struct cat_msg {
    const char *path;
    char *buf;
    size_t size;
} cat_msg;

#if defined(__GNUC__)
#define CAT_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define CAT_PRINTF(a, b)
#endif

/* Writes "PATH: <formatted>" into msg and returns code. */
cat_result cat_fail(const cat_msg *msg, cat_result code, const char *fmt, ...) CAT_PRINTF(3, 4);

/* ---- the parsed document, as plain C ------------------------------------------------------ */
/* Indices are as in the file (-1 = absent) and not yet checked; counts are as parsed. Arrays
 * point into memory owned by the adapter and live until cat_gltf_release. */

enum {
    CAT_GLTF_BYTE = 5120,
    CAT_GLTF_UNSIGNED_BYTE = 5121,
    CAT_GLTF_SHORT = 5122,
    CAT_GLTF_UNSIGNED_SHORT = 5123,
    CAT_GLTF_UNSIGNED_INT = 5125,
    CAT_GLTF_FLOAT = 5126
};

enum {
    CAT_GLTF_POINTS = 0,
    CAT_GLTF_LINES = 1,
    CAT_GLTF_LINE_LOOP = 2,
    CAT_GLTF_LINE_STRIP = 3,
    CAT_GLTF_TRIANGLES = 4,
    CAT_GLTF_TRIANGLE_STRIP = 5,
    CAT_GLTF_TRIANGLE_FAN = 6
};

typedef struct cat_gltf_buffer {
    const unsigned char *data;
    size_t size;
} cat_gltf_buffer;

typedef struct cat_gltf_view {
    int buffer;
    size_t offset, length, stride; /* stride 0 = tightly packed */
} cat_gltf_view;

typedef struct cat_gltf_accessor {
    int view; /* -1: all zeros (sparse values may replace some) */
    size_t offset;
    int component_type; /* CAT_GLTF_BYTE ... CAT_GLTF_FLOAT */
    int normalized;
    int components; /* 1 SCALAR, 2 VEC2, 3 VEC3, 4 VEC4, 4/9/16 matrices; < 1 unknown */
    int is_matrix;
    size_t count;
    int sparse; /* nonzero: the fields below apply (tinygltf keeps them as int) */
    long long sparse_count;
    int sparse_indices_view;
    long long sparse_indices_offset;
    int sparse_indices_type;
    int sparse_values_view;
    long long sparse_values_offset;
} cat_gltf_accessor;

typedef struct cat_gltf_attribute {
    const char *name; /* "POSITION", "NORMAL", "TEXCOORD_0", ... */
    int accessor;
} cat_gltf_attribute;

typedef struct cat_gltf_primitive {
    const cat_gltf_attribute *attributes;
    int attribute_count;
    int indices;
    int material;
    int mode;
} cat_gltf_primitive;

typedef struct cat_gltf_mesh {
    const cat_gltf_primitive *primitives;
    int primitive_count;
} cat_gltf_mesh;

typedef struct cat_gltf_node {
    int mesh;
    const int *children;
    int child_count;
    const double *matrix; /* column-major; matrix_count is 0 or (if valid) 16 */
    int matrix_count;
    const double *translation;
    int translation_count;
    const double *rotation; /* quaternion x, y, z, w */
    int rotation_count;
    const double *scale;
    int scale_count;
} cat_gltf_node;

typedef struct cat_gltf_scene {
    const int *nodes;
    int node_count;
} cat_gltf_scene;

typedef struct cat_gltf_material {
    const char *name;
    const double *base_color;
    int base_color_count;
    double metallic, roughness;
    const double *emissive;
    int emissive_count;
    int base_color_texture; /* texture index or -1 */
} cat_gltf_material;

typedef struct cat_gltf_texture {
    int source; /* image index or -1 */
} cat_gltf_texture;

typedef struct cat_gltf_image {
    const char *uri; /* "" for embedded images (data: URI or buffer view) */
} cat_gltf_image;

typedef struct cat_gltf_doc {
    const cat_gltf_buffer *buffers;
    int buffer_count;
    const cat_gltf_view *views;
    int view_count;
    const cat_gltf_accessor *accessors;
    int accessor_count;
    const cat_gltf_mesh *meshes;
    int mesh_count;
    const cat_gltf_node *nodes;
    int node_count;
    const cat_gltf_scene *scenes;
    int scene_count;
    int default_scene; /* -1 when the file has no "scene" */
    const cat_gltf_material *materials;
    int material_count;
    const cat_gltf_texture *textures;
    int texture_count;
    const cat_gltf_image *images;
    int image_count;
    const char *const *extensions_required;
    int extensions_required_count;
} cat_gltf_doc;

/* ---- external files ----------------------------------------------------------------------- */

/* What the adapter needs to read a buffer's external file. The first failure is kept here so
 * that it is reported instead of tinygltf's generic message. */
typedef struct cat_gltf_io {
    const char *folder; /* absolute folder of the model, no trailing slash (except "/") */
    const cat_msg *msg;
    cat_result result;
    char message[1536];
} cat_gltf_io;

/* Reads the external file a (percent-decoded) buffer URI names, relative to io->folder. uri is
 * NUL-terminated and uri_length long (a decoded %00 makes them differ: refused). On success
 * *data is malloc'ed (free it). On failure the error is recorded in io. */
cat_result cat_gltf_read_external(cat_gltf_io *io, const char *uri, size_t uri_length,
                                  unsigned char **data, size_t *size);

/* ---- the adapter (gltf_load.cpp) ---------------------------------------------------------- */

/* Parses a glTF JSON text (is_glb == 0) or a whole GLB file whose container cat_glb_check has
 * accepted. Fills *doc and *handle; release with cat_gltf_release (also after a failure). On
 * failure writes tinygltf's own text (no file name) into detail. */
cat_result cat_gltf_parse(const unsigned char *bytes, size_t size, int is_glb, cat_gltf_io *io,
                          cat_gltf_doc *doc, void **handle, char *detail, size_t detail_size);
void cat_gltf_release(void *handle);

/* ---- C helpers ---------------------------------------------------------------------------- */

/* Reads a whole file (at most max_bytes) into a malloc'ed buffer; label names it in messages. */
cat_result cat_read_file(const cat_msg *msg, const char *label, const char *path, size_t max_bytes,
                         unsigned char **data, size_t *size);

/* Checks a GLB container (header, JSON chunk, optional BIN chunk) and finds its JSON text. */
cat_result cat_glb_check(const cat_msg *msg, const unsigned char *bytes, size_t size,
                         const unsigned char **json, size_t *json_size);

/* Checks that text is well-formed JSON within the CAT_MODEL_MAX_JSON_* limits and that no
 * string in it is longer than a data: URI of CAT_MODEL_MAX_DATA_URI_BYTES. */
cat_result cat_json_scan(const cat_msg *msg, const unsigned char *text, size_t size);

/* Turns a relative URI reference into a path below folder: percent-decodes it (unless tinygltf
 * already did: decode == 0), refuses absolute paths, schemes and anything that climbs out of
 * the folder with "..". what names the reference in messages, e.g. "image 2". */
cat_result cat_uri_resolve(const cat_msg *msg, const char *what, const char *folder,
                           const char *uri, int decode, char *out, size_t out_size);

/* Reads accessor values as floats (normalized integers mapped to -1..1 / 0..1, sparse
 * substitution applied). out holds count * components floats. where prefixes messages. */
cat_result cat_accessor_read_floats(const cat_msg *msg, const char *where, const cat_gltf_doc *doc,
                                    int accessor, int components, float *out);
/* Reads an index accessor (unsigned byte, short or int scalars). */
cat_result cat_accessor_read_indices(const cat_msg *msg, const char *where, const cat_gltf_doc *doc,
                                     int accessor, unsigned *out);
/* Checks accessor's index, type and that every byte it reads lies inside its buffer. */
cat_result cat_accessor_check(const cat_msg *msg, const char *where, const cat_gltf_doc *doc,
                              int accessor, int components);

/* 4x4 column-major double matrices. */
void cat_mat4_identity(double m[16]);
void cat_mat4_mul(const double a[16], const double b[16], double out[16]);
/* Local matrix of a node from T * R * S (rotation quaternion normalized first). */
void cat_mat4_from_trs(const double t[3], const double q[4], const double s[3], double out[16]);
double cat_mat3_det(const double m[16]); /* of the upper-left 3x3 */
/* Cofactor matrix of the upper-left 3x3 (= det * inverse transpose), row-major 3x3. */
void cat_mat3_cofactor(const double m[16], double out[9]);

/* Area-weighted vertex normals of a triangle list, unit length, (0, 0, 1) where undefined.
 * Only vertices with replace[v] != 0 are written (all when replace is NULL). Indices must be
 * < vertex_count. Returns 0 when out of memory. */
int cat_normals_generate(const float *positions, int vertex_count, const unsigned *indices,
                         int index_count, const unsigned char *replace, float *normals);

/* Bakes the chosen scene of doc into out (the C side of cat_model_load). */
cat_result cat_model_build(const cat_msg *msg, const cat_gltf_doc *doc, const char *folder,
                           cat_model *out);

#ifdef __cplusplus
}
#endif

#endif
