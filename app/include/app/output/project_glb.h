/* Exporting a whole project as one GLB file, so users can open it in other tools; `tessera
 * export-glb PROJECT -o OUT.glb`.
 *
 * The file holds one scene: a root node named after the project with
 *  - a node "room" whose children are the room's surfaces as app_room_geometry_build makes
 *    them (floor, ceiling, walls with their openings, reveals, pre-walls, window panels, door
 *    leaves) plus the tiles and grout of the tilings (room_tiles.c), each a node named after
 *    the surface ("floor", "wall:2", "tiles:floor:0", ...);
 *  - one node per object, named after the object ("wc", or for a placed catalog product
 *    "wc (Cerana CE412901 WH)"), whose transform is the object's position, rotation and
 *    scale; its mesh has one primitive per part. Primitives are the renderer's unit meshes
 *    scaled to their size; glTF models and catalog products are their GLB files
 *    (cat_model_load), each part keeping its own material; the product's variant (or the
 *    object's own project material) goes to the parts the model marks as variant slots.
 * The project's cameras become glTF perspective cameras (nodes under the root, named after
 * the camera). Materials: metallic-roughness approximations of Tessera's parameters with the exact
 * ones in "extras" (catalog/model_write.h, docs/catalog.md "Exporting a project"). Tessera's Z-up
 * millimetres become glTF's Y-up metres (catalog/scene_write.h). Lights and textures are not
 * exported. */
#ifndef APP_PROJECT_GLB_H
#define APP_PROJECT_GLB_H

#include "app/project/project.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct app_glb_stats {
    int node_count, mesh_count, part_count, material_count;
    int object_count;  /* objects written (primitives, models, products) */
    int camera_count;  /* the project's cameras, as glTF cameras under the root node */
    int skipped_count; /* objects left out (a product the catalog does not know, ...) */
    long vertex_count, triangle_count;
    double bounds_min_mm[3], bounds_max_mm[3]; /* of everything written, Tessera space */
} app_glb_stats;

/* Writes p as GLB to out_path. Products are looked up in the catalog ($TESSERA_CATALOG or the
 * default place; opened only when the project has products or tilings); their models are
 * found with cat_model_resolve. A product the catalog does not know is left out with a warning
 * on stderr (as in a render); a model file that cannot be loaded is an error. stats may be
 * NULL. */
app_result app_project_export_glb(const app_project *p, const char *out_path, app_glb_stats *stats,
                                  char *err, size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
