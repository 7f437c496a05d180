/* catalog/scene_write.h: write a scene of named nodes (a whole project: the room's surfaces and
 * every placed object) as one GLB file with tinygltf, so that other tools can open it.
 *
 * The counterpart of model_write.h for more than one object: where cat_model_write_glb bakes a
 * product into one flat list of parts, a scene keeps one glTF node per object, with its name
 * and its transform, and one glTF mesh per node whose primitives are the object's parts, each
 * with its own material. Units and axes as model_write.h: Tessera's millimetres, Z up, become
 * glTF's metres, Y up, by the map C: (x, y, z) -> (x, z, -y) / 1000 applied to every vertex;
 * a node's matrix M (Tessera space, mm) becomes C * M * C^-1, so that cat_model_load, which
 * applies C^-1, gives back the placed positions. Materials as model_write.h (metallic-roughness
 * approximation plus Tessera's parameters in "extras"). Textures are not written, and so
 * neither are texture coordinates (cat_mesh.uvs is ignored).
 *
 * Every call that can fail returns a cat_result and writes "FILE: what went wrong" into err.
 */
#ifndef CATALOG_SCENE_WRITE_H
#define CATALOG_SCENE_WRITE_H

#include "catalog/model.h"
#include "catalog/model_write.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cat_scene_node {
    char name[96];         /* the glTF node's (and its mesh's) name */
    int parent;            /* index of the parent node (< this node's index), -1 = a scene root */
    double matrix[16];     /* column-major local-to-parent transform, Tessera space (mm, Z up) */
    const cat_mesh *parts; /* in the node's local frame (mm, Z up); each part's material
                              indexes cat_scene.materials (-1 = glTF's default material) */
    int part_count;        /* 0: a node without a mesh (a group) */
} cat_scene_node;

typedef struct cat_scene_camera { /* a perspective view, written as a glTF camera */
    char name[64];
    double eye_mm[3], target_mm[3], up[3]; /* Tessera space; up need not be unit */
    double yfov_deg;                       /* vertical field of view, in (0, 180) */
    double aspect;                         /* width / height, 0 = left to the viewer */
    double zfar_mm; /* the far clipping plane (glTF's zfar), > 10 mm (znear); 0 = 100 m */
} cat_scene_camera;

typedef struct cat_scene {
    const cat_scene_node *nodes;
    int node_count;
    const cat_material *materials;
    const cat_material_extras *extras; /* NULL or material_count entries */
    int material_count;
    const cat_scene_camera *cameras; /* each a node under node 0 (glTF cameras look along the
                                        node's -Z with +Y up); a degenerate one is refused */
    int camera_count;
} cat_scene;

/* Sets m to the identity matrix. */
void cat_scene_identity(double m[16]);

/* Writes s as GLB to path (a temporary file renamed into place: a reader never sees half a
 * file). Refuses a scene without nodes, a part without triangles, an index, material or
 * parent out of range and a vertex or matrix entry that is not finite. */
cat_result cat_scene_write_glb(const char *path, const cat_scene *s, char *err, size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
