/* Turns a project document into the ground-truth tracer's scene (render/ref), the way
 * app_scene_build turns it into the GPU's: the same room rectangles with real-size UVs, the same
 * unit primitives and transforms, the same glTF/GLB models, materials, textures and lights, so
 * that both renderers see identical geometry (RENDERING.md section 10). */
#ifndef APP_REF_SCENE_BUILD_H
#define APP_REF_SCENE_BUILD_H

#include "app/project/project.h"
#include "ref/ref.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* On success *out owns a scene to free with ref_scene_destroy. On failure *out is NULL and err
 * names the file and the object, as app_scene_build's messages do. */
app_result app_ref_scene_build(const app_project *p, ref_scene **out, char *err, size_t err_size);

typedef struct app_render_list app_render_list;
/* The same from a render list already built: the tracer's mesh i is the list's item i. */
app_result app_ref_scene_from_list(const app_render_list *l, ref_scene **out, char *err,
                                   size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
