/* The reference tracer's adapter: a render list (render_list.h) handed to render/ref, the
 * same items, transforms, materials and lights the GPU scene gets (scene_build.c). Only the
 * textures are loaded differently: as floats, sRGB files decoded here the way the GPU's
 * GL_SRGB8_ALPHA8 sampler decodes them. The tracer has no probes: probe meshes, probe maps,
 * shapes and groups are the GPU's business. */
#include "app/scene/ref_scene_build.h"

#include "app/measure/image_compare.h"
#include "app/scene/render_list.h"
#include "render/image_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A texture file as the tracer's texture id (0 on failure). sRGB files are quantised to 8 bits
 * as rd_texture_create does and decoded with the exact curve; linear files stay as read. */
static app_result load_texture(ref_scene *s, const char *path, int *out, char *err, size_t err_size)
{
    rd_image img = {0};
    int nonfinite = 0;
    if (rd_image_read(path, &img, &nonfinite, err, err_size) != RD_IMAGE_OK)
        return APP_ERR_IO;
    if (nonfinite)
        fprintf(stderr, "tessera: warning: %s: %d NaN or infinite texel values were set to 0\n",
                path, nonfinite);
    size_t n = (size_t)img.width * (size_t)img.height * 4;
    float *rgba = malloc(n * sizeof *rgba);
    if (!rgba) {
        rd_image_free(&img);
        return APP_ERR_OUT_OF_MEMORY;
    }
    rd_image_expand_rgba(&img, rgba);
    if (img.srgb_encoded)
        for (size_t i = 0; i < n; i++) {
            float x = isfinite(rgba[i]) ? fminf(fmaxf(rgba[i], 0.0f), 1.0f) : 0.0f;
            float byte = floorf(x * 255.0f + 0.5f);
            rgba[i] = i % 4 == 3 ? byte / 255.0f : app_srgb_to_linear(byte / 255.0f);
        }
    *out = ref_scene_add_texture(s, &(ref_texture_desc){img.width, img.height, rgba});
    free(rgba);
    rd_image_free(&img);
    if (!*out) {
        snprintf(err, err_size, "%s: %s", path, ref_last_error());
        return APP_ERR_OUT_OF_MEMORY;
    }
    return APP_OK;
}

static app_result add_items(const app_render_list *l, ref_scene *s, const int *textures, char *err,
                            size_t err_size)
{
    for (int i = 0; i < l->item_count; i++) {
        const app_render_item *it = &l->items[i];
        const app_render_mesh *m = &l->meshes[it->mesh];
        ref_mesh_desc d = {.positions = m->positions,
                           .normals = m->normals,
                           .uvs = m->uvs,
                           .indices = m->indices,
                           .vertex_count = m->vertex_count,
                           .index_count = m->index_count,
                           .material = it->material,
                           .texture = it->texture >= 0 ? textures[it->texture] : 0,
                           .double_sided = it->double_sided,
                           .background = it->background,
                           .light_stand_in = it->light_stand_in};
        memcpy(d.transform, it->transform, sizeof d.transform);
        ref_result r = ref_scene_add_mesh(s, &d);
        if (r != REF_OK) {
            snprintf(err, err_size, "%s: %s: %s", l->path, it->label, ref_last_error());
            return r == REF_ERR_OUT_OF_MEMORY ? APP_ERR_OUT_OF_MEMORY : APP_ERR_SCHEMA;
        }
    }
    return APP_OK;
}

static app_result scene_from_list(const app_render_list *l, ref_scene *s, char *err,
                                  size_t err_size)
{
    ref_scene_set_ambient(s, l->ambient);
    if (l->ambient_model == RD_AMBIENT_SH9) {
        /* SH9 ambient from a capture at the box proxy's centre, as the GPU places its probe
         * (render/src/ambient_sh.c). */
        float centre[3];
        for (int k = 0; k < 3; k++)
            centre[k] = (float)(0.5 * (l->room_min[k] + l->room_max[k]));
        ref_scene_set_ambient_sh9(s, centre);
    }
    int *textures = calloc((size_t)l->texture_count + 1, sizeof *textures);
    if (!textures)
        return APP_ERR_OUT_OF_MEMORY;
    app_result r = APP_OK;
    char inner[2048];
    for (int i = 0; r == APP_OK && i < l->texture_count; i++) {
        r = load_texture(s, l->textures[i].path, &textures[i], inner, sizeof inner);
        if (r != APP_OK)
            snprintf(err, err_size, "%s: material \"%s\": %s", l->path, l->textures[i].material,
                     inner);
    }
    if (r == APP_OK)
        r = add_items(l, s, textures, err, err_size);
    free(textures);
    for (int i = 0; r == APP_OK && i < l->light_count; i++)
        if (ref_scene_add_light(s, &l->lights[i].light) != REF_OK) {
            snprintf(err, err_size, "%s: %s: %s", l->path, l->lights[i].label, ref_last_error());
            r = APP_ERR_SCHEMA;
        }
    return r;
}

app_result app_ref_scene_from_list(const app_render_list *l, ref_scene **out, char *err,
                                   size_t err_size)
{
    *out = ref_scene_create();
    if (!*out) {
        snprintf(err, err_size, "%s: %s", l->path, ref_last_error());
        return APP_ERR_OUT_OF_MEMORY;
    }
    app_result r = scene_from_list(l, *out, err, err_size);
    if (r != APP_OK) {
        ref_scene_destroy(*out);
        *out = NULL;
    }
    return r;
}

app_result app_ref_scene_build(const app_project *p, ref_scene **out, char *err, size_t err_size)
{
    *out = NULL;
    app_render_list l;
    app_result r = app_render_list_build(p, 0, &l, err, err_size);
    if (r != APP_OK)
        return r;
    ref_scene *s = ref_scene_create();
    if (!s) {
        snprintf(err, err_size, "%s: %s", p->path, ref_last_error());
        r = APP_ERR_OUT_OF_MEMORY;
    } else {
        r = scene_from_list(&l, s, err, err_size);
    }
    if (r == APP_ERR_OUT_OF_MEMORY && err && err_size && !err[0])
        snprintf(err, err_size, "%s: out of memory", p->path);
    app_render_list_free(&l);
    if (r != APP_OK) {
        ref_scene_destroy(s);
        return r;
    }
    *out = s;
    return APP_OK;
}
