#ifndef APP_SCENE_BUILD_INTERNAL_H
#define APP_SCENE_BUILD_INTERNAL_H

#include "app/design/room_mesh.h"
#include "app/design/placement.h"
#include "app/design/room_surfaces.h"
#include "app/scene/render_list.h"
#include "app/scene/scene_build.h"

#include <stdio.h>
#include <string.h>

/* The map from renderer objects to project objects for app_scene_move_object (scene_move.c). */
app_result app_scene_parts_make(const app_render_list *l, app_scene *s);
void app_scene_parts_free(app_scene *s);
/* A copy q of p whose catalog products are drawable objects (scene_products.c); owns = 1 when
 * q has its own objects and materials arrays. covers: the boxes of the baths and shower trays
 * (app/design/room_surfaces.h), for the tile layouts. Free with app_scene_resolved_free. */
typedef struct app_scene_products {
    app_project q;
    int owns;
    app_fixture_box *covers;
    int cover_count;
    app_lazy_catalog catalog; /* opened on the first product, kept for the tiles */
} app_scene_products;
app_result app_scene_resolve_products(const app_project *p, app_scene_products *out, char *err,
                                      size_t err_size);
void app_scene_resolved_free(app_scene_products *r);
/* The tiles of p's tilings as meshes added to the room geometry (room_tiles.c): each tile a
 * textured polygon a few mm in front of its surface, over a backing in the grout colour.
 * Problems (no catalog, an unknown tile) are warnings: the room is drawn without those tiles. */
void app_room_add_tiles(const app_project *p, const app_fixture_box *covers, int cover_count,
                        app_lazy_catalog *catalog, app_room_geometry *g);
/* A product the catalog could not give a size or model to: nothing to draw. */
#define APP_OBJECT_UNRESOLVED(o)                                                                   \
    ((o)->has_product && (o)->shape != APP_SHAPE_MODEL && !((o)->size_mm[0] > 0))
/* M = T(position) * Rz * Ry * Rx * S(scale * size), column-major, metres. */
void app_object_transform(const app_object *o, const double size_m[3], float out[16]);

/* How far inside the room a camera on a wall, the floor or the flat ceiling is moved (mm):
 * enough to keep the surfaces it stands on beyond the near plane of rooms up to about 3 m
 * high (render/src/depth_range.h: near <= 1/250 of the room's smallest side). */
#define APP_CAMERA_WALL_CLEARANCE_MM 25.0
/* Moves eye_mm off a wall (within the clearance of a wall segment, on either side), the floor
 * or the flat ceiling, to the clearance inside the room (camera_inside.c). */
void app_camera_keep_inside(const app_project *p, double eye_mm[3]);

#endif
