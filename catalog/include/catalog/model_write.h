/* catalog/model_write.h: write a multi-part model (cat_model) as a GLB file with tinygltf.
 *
 * The file is glTF 2.0, binary container, Y up, metres: a Tessera point (x, y, z) in mm, Z up,
 * is written as (x, z, -y) / 1000, which cat_model_load turns back into (x, y, z) exactly
 * (up to float rounding). One glTF mesh and one node per cat_mesh (part), one glTF material per
 * cat_material (metallic-roughness, see docs/catalog.md "Models" for the mapping), with
 * Tessera's own renderer parameters in the material's "extras" so that a round trip keeps
 * them. The file is written to a temporary name in the same folder and renamed into place, so
 * a reader never sees half a file.
 *
 * Every call that can fail returns a cat_result and writes "FILE: what went wrong" into err.
 */
#ifndef CATALOG_MODEL_WRITE_H
#define CATALOG_MODEL_WRITE_H

#include "catalog/catalog.h"
#include "catalog/model.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Tessera's parameters of one material, kept in glTF "extras" as
 * {"tessera": {"ambient": [..], "diffuse": [..], "specular": [..], "emissive": [..],
 *  "shininess": n, "k_r": k, "g": g, "blend": "mix", "transparency": t, "ior": i,
 *  "variant_slot": true}}. */
typedef struct cat_material_extras {
    int present;      /* 0: the material has no Tessera parameters (plain glTF) */
    int variant_slot; /* 1: this part takes the product's chosen finish variant */
    cat_render_material params;
} cat_material_extras;

/* Fills a glTF metallic-roughness material approximating Tessera's parameters r:
 * metallic = clamp((|specular| - |diffuse|) / 0.6, 0, 1) (a metal reflects with its specular
 * colour and has little diffuse), base colour = mix(diffuse, specular, metallic), alpha =
 * 1 - transparency, roughness = clamp(1 - g, 0.02, 1) (g is RENDERING.md's glossiness),
 * emissive = the emissive colour divided by its largest component when above 1 (glTF factors
 * stop at 1; the real value stays in the extras). name is copied (truncated). */
void cat_material_from_render(const cat_render_material *r, const char *name, cat_material *out);

/* Writes m as GLB to path. extras may be NULL (no extras written) or hold m->material_count
 * entries. Every mesh needs positions and indices; normals and uvs are written when present.
 * A mesh's material index must be -1 or < material_count. */
cat_result cat_model_write_glb(const char *path, const cat_model *m,
                               const cat_material_extras *extras, char *err, size_t err_size);

/* Reads back the Tessera extras of every material of a .glb/.gltf file (as written above) into
 * out[0 .. *count - 1] (at most max entries; materials without extras get present = 0). The
 * file passes cat_model_load's size, container and JSON checks first (hostile files are
 * refused the same way); external buffers are not read. */
cat_result cat_model_read_extras(const char *path, cat_material_extras *out, int max, int *count,
                                 char *err, size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
