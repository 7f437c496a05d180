/* Turns a project document into the renderer's scene and views (app joins catalog and render;
 * ARCHITECTURE.md). Millimetres become metres here and nowhere else. */
#ifndef APP_SCENE_BUILD_H
#define APP_SCENE_BUILD_H

#include "app/project/project.h"
#include "app/scene/render_list.h"
#include "ref/ref_bake.h"
#include "render/render.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct app_scene_parts app_scene_parts;

/* A project's GPU scene: the adapter of render_list.h. */
typedef struct app_scene {
    rd_scene *scene;
    rd_mesh *meshes; /* per list mesh (id 0: not drawn), destroyed by app_scene_release */
    int mesh_count;
    rd_texture *textures;
    int texture_count;
    rd_cubemap *cubemaps; /* static probe maps */
    int cubemap_count;
    app_scene_parts *parts; /* which project object each renderer object draws */
    rd_mesh *baked_meshes;  /* per list item: its own mesh with baked light (id 0: none) */
    int baked_mesh_count;
} app_scene;

/* Uploads the room, the objects (primitives and glTF/GLB models), the textures and the
 * lights of p's render list (app/scene/render_list.h), with their baked indirect light when
 * app_bake_configure turned the bake on (app/scene/scene_bake.h). On failure nothing stays
 * allocated and err names the file and the object. */
app_result app_scene_build(rd_context *ctx, const app_project *p, app_scene *out, char *err,
                           size_t err_size);
void app_scene_release(rd_context *ctx, app_scene *s);

/* The GPU scene of a render list already built (app_render_list_build with
 * APP_RENDER_LIST_PROBE_MESHES), with the baked light `bake` (its meshes in the list's item
 * order; NULL = none: the plain ambient) and no bake of its own; the list stays the caller's.
 * The window builds so, and bakes the list on another thread (docs/rendering.md). */
app_result app_scene_build_from_list(rd_context *ctx, const app_render_list *l,
                                     const ref_bake *bake, app_scene *out, char *err,
                                     size_t err_size);

/* Gives scene s, built from list l, the light of bake (of the same list; NULL = none) in place
 * of what it drew: new meshes carrying it and the atlas, swapped in object by object; the old
 * ones are destroyed. On failure s draws as before. */
app_result app_scene_apply_bake(rd_context *ctx, app_scene *s, const app_render_list *l,
                                const ref_bake *bake, char *err, size_t err_size);

/* Moves project object `object` to position_mm (its document position, millimetres): in the
 * document p and in the scene s built from p, whose renderer objects for it take the
 * transform a fresh build would give them (probes that see it are captured again under their
 * policies). The one way to move a built object without rebuilding the scene.
 * APP_ERR_NOT_FOUND when p has no such object or s was not built from p. */
app_result app_scene_move_object(app_scene *s, app_project *p, int object,
                                 const double position_mm[3]);

/* The room's geometry, the same for the GPU scene and the reference tracer's scene, is
 * app_room_geometry_build (app/design/room_mesh.h). */

/* The renderer's tone curve for a project's $.render.tone. */
rd_tonemap app_tone_to_rd(app_tone t);

/* The view of a named camera (NULL = the first) at a size (0 = the project's render size), with
 * the project's exposure ("auto": rd_view.auto_exposure), tone curve and white balance. */
app_result app_view_from_camera(const app_project *p, const char *camera, int width, int height,
                                rd_view *out, char *err, size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
