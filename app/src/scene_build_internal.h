#ifndef APP_SCENE_BUILD_INTERNAL_H
#define APP_SCENE_BUILD_INTERNAL_H

#include "app/scene_build.h"

#include <stdio.h>
#include <string.h>

app_result app_scene_track_mesh(app_scene *s, rd_mesh mesh);
/* The renderer's material for project material index mi, loading its texture once. */
app_result app_scene_material(rd_context *ctx, const app_project *p, app_scene *s, int mi,
                              rd_material *out, char *err, size_t err_size);
app_result app_scene_add_room(rd_context *ctx, const app_project *p, app_scene *s, char *err,
                              size_t err_size);
app_result app_scene_add_objects(rd_context *ctx, const app_project *p, app_scene *s, char *err,
                                 size_t err_size);
/* A static probe map (RENDERING.md section 8) from six files, loaded once per pattern. */
app_result app_scene_cubemap(rd_context *ctx, app_scene *s, const char *pattern, rd_cubemap *out,
                             char *err, size_t err_size);
void app_object_transform(const app_object *o, const double size_m[3], float out[16]);

#endif
