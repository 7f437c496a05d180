/* catalog/model.h: load glTF 2.0 (.gltf / .glb) models into plain mesh data.
 *
 * The loader bakes the default scene into model space: every node transform is applied, units
 * become millimetres and the axes Tessera's right-handed Z up. Nothing here knows about
 * rendering; the result is plain arrays the caller can hand to any consumer.
 *
 * Conventions of the result:
 * - glTF's Y-up metres become Z-up millimetres: (x, y, z)_gltf -> (x, -z, y) * 1000.
 * - Triangles are counter-clockwise seen from outside, also under mirroring node transforms.
 * - Triangle strips and fans become triangle lists; points and lines are skipped (no error);
 *   a primitive under a node scaled to zero is skipped too.
 * - Texture coordinates are copied as stored: origin at the image's top-left, v pointing down.
 * - Skins, morph targets, animations, cameras and lights are ignored: a skinned mesh is taken
 *   in its bind shape under its node's transform.
 * - A file that requires an extension other than KHR_mesh_quantization is refused
 *   (CAT_ERR_UNSUPPORTED); optional extensions are ignored.
 * - Images are never decoded or opened; an external image is only named (resolved path).
 *
 * Every call that can fail returns a cat_result and writes "FILE: what went wrong" into err
 * (when err is not NULL and err_size > 0). The loader never aborts; hostile input gives an
 * error, not a crash.
 */
#ifndef CATALOG_MODEL_H
#define CATALOG_MODEL_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cat_result {
    CAT_OK = 0,
    CAT_ERR_IO,            /* a file could not be opened or read */
    CAT_ERR_PARSE,         /* not a glTF file: bad JSON or bad GLB container */
    CAT_ERR_INVALID,       /* a glTF file that breaks the specification or a safety rule */
    CAT_ERR_UNSUPPORTED,   /* valid glTF that uses something this loader does not handle */
    CAT_ERR_OUT_OF_MEMORY, /* an allocation failed */
    CAT_ERR_TOO_LARGE      /* a size or count above one of the limits below */
} cat_result;

/* Limits. A file above any of them is refused with CAT_ERR_TOO_LARGE. */
#define CAT_MODEL_MAX_FILE_BYTES (1024u * 1024u * 1024u) /* .gltf, .glb and each .bin */
#define CAT_MODEL_MAX_JSON_BYTES (256u * 1024u * 1024u)  /* the JSON text of a model */
#define CAT_MODEL_MAX_JSON_VALUES (4u * 1024u * 1024u)   /* values in that JSON text */
#define CAT_MODEL_MAX_JSON_OBJECTS (256u * 1024u) /* objects in it (tinygltf: up to 2 KiB each) */
#define CAT_MODEL_MAX_JSON_DEPTH 64               /* nesting of arrays and objects */
#define CAT_MODEL_MAX_DATA_URI_BYTES (64u * 1024u * 1024u) /* decoded size of one data: URI */
#define CAT_MODEL_MAX_BUFFER_BYTES (1024u * 1024u * 1024u) /* sum of all buffers' byteLength */
#define CAT_MODEL_MAX_PRIMITIVE_VERTICES (16 * 1024 * 1024)
#define CAT_MODEL_MAX_TOTAL_VERTICES (64 * 1024 * 1024)
#define CAT_MODEL_MAX_PRIMITIVE_INDICES (3 * 16 * 1024 * 1024)
#define CAT_MODEL_MAX_TOTAL_INDICES (3 * 64 * 1024 * 1024)
#define CAT_MODEL_MAX_MESHES (1024 * 1024) /* baked primitive instances, skipped ones included */

typedef struct cat_material {
    char name[64];                 /* truncated to 63 bytes */
    float base_color[4];           /* linear, glTF baseColorFactor; default 1, 1, 1, 1 */
    float metallic, roughness;     /* glTF factors; default 1 and 1 */
    float emissive[3];             /* glTF emissiveFactor; default 0 */
    char base_color_texture[1024]; /* resolved absolute path of an external image (inside the
                                      model's folder, not checked to exist), "" if none or
                                      embedded (data: URI or buffer view) */
} cat_material;

typedef struct cat_mesh { /* one glTF primitive (triangles), already in the model's space */
    float *positions;     /* 3 per vertex, millimetres, Z up */
    float *normals;       /* 3 per vertex, unit; generated (area-weighted, per vertex) where the
                             file has none or a stored one is degenerate */
    float *uvs;           /* 2 per vertex (TEXCOORD_0) or NULL */
    unsigned *indices;    /* 3 per triangle (non-indexed primitives get 0..n-1) */
    int vertex_count, index_count;
    int material; /* index into cat_model.materials, -1 = default */
} cat_mesh;

typedef struct cat_model {
    cat_mesh *meshes; /* in depth-first order of the scene's nodes, primitives in file order */
    int mesh_count;
    cat_material *materials; /* all materials of the file, in file order */
    int material_count;
    float bounds_min[3], bounds_max[3]; /* mm, over all meshes; all zero when there are none */
} cat_model;

/* Loads a .gltf or .glb file (told apart by content, not by name) into *out, which is zeroed
 * first and left zeroed on failure. Walks the file's default scene, else scene 0, else every
 * root node. External files (.bin buffers) must lie inside the model's folder. */
cat_result cat_model_load(const char *path, cat_model *out, char *err, size_t err_size);

/* Frees everything *m owns and zeroes it. Safe on a zeroed model and on NULL. */
void cat_model_free(cat_model *m);

/* A short English name of a result, e.g. "invalid glTF"; never NULL. */
const char *cat_result_name(cat_result r);

#ifdef __cplusplus
}
#endif

#endif
