/* Turns a project document into the renderer's scene and views (app joins catalog and render;
 * ARCHITECTURE.md). Millimetres become metres here and nowhere else. */
#ifndef APP_SCENE_BUILD_H
#define APP_SCENE_BUILD_H

#include "app/project/project.h"
#include "render/render.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct app_scene {
    rd_scene *scene;
    rd_mesh *meshes; /* every mesh this scene uploaded, destroyed by app_scene_release */
    int mesh_count, mesh_capacity;
    rd_texture *textures;
    char (*texture_paths)[1024];
    int texture_count, texture_capacity;
    rd_cubemap *cubemaps; /* static probe maps, loaded once per file pattern */
    char (*cubemap_paths)[1024];
    int cubemap_count, cubemap_capacity;
    rd_mesh unit_meshes[2][5];
    /* Per project object: its first renderer object and how many parts it has (to move it). */
    int (*object_parts)[2]; /* shared primitives: [coarse][app_shape] (models excluded) */
} app_scene;

/* Uploads the room, the objects (primitives and glTF/GLB models), the textures and the
 * lights. On failure nothing stays allocated and err names the file and the object. */
app_result app_scene_build(rd_context *ctx, const app_project *p, app_scene *out, char *err,
                           size_t err_size);
void app_scene_release(rd_context *ctx, app_scene *s);

/* The room's geometry, the same for the GPU scene and the reference tracer's scene, is
 * app_room_geometry_build (app/design/room_mesh.h). */

/* The view of a named camera (NULL = the first) at a size (0 = the project's render size). */
app_result app_view_from_camera(const app_project *p, const char *camera, int width, int height,
                                rd_view *out, char *err, size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
