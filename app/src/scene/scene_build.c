/* The GPU adapter: a render list (render_list.h) uploaded as the renderer's scene -- textures
 * and static probe maps loaded once per file, each mesh once, one renderer object per item in
 * the list's order, then the lights. */
#include "scene_build_internal.h"

#include "app/scene/render_list.h"
#include "app/scene/scene_bake.h"
#include "render/cube_data.h"
#include "render/image_io.h"

#include <stdlib.h>

static app_result load_texture(rd_context *ctx, const char *path, rd_texture *out, char *err,
                               size_t err_size)
{
    rd_image img = {0};
    int nonfinite = 0;
    if (rd_image_read(path, &img, &nonfinite, err, err_size) != RD_IMAGE_OK)
        return APP_ERR_IO;
    if (nonfinite)
        fprintf(stderr, "tessera: warning: %s: %d NaN or infinite texel values were set to 0\n",
                path, nonfinite);
    float *rgba = malloc((size_t)img.width * (size_t)img.height * 4 * sizeof *rgba);
    if (rgba)
        rd_image_expand_rgba(&img, rgba);
    if (!rgba) {
        rd_image_free(&img);
        return APP_ERR_OUT_OF_MEMORY;
    }
    *out = rd_texture_create(ctx, &(rd_texture_desc){.width = img.width,
                                                     .height = img.height,
                                                     .rgba = rgba,
                                                     .srgb_encoded = img.srgb_encoded});
    free(rgba);
    rd_image_free(&img);
    if (!out->id) {
        snprintf(err, err_size, "%s: %s", path, rd_last_error());
        return APP_ERR_IO;
    }
    return APP_OK;
}

/* A static probe map (RENDERING.md section 8) from six files. */
static app_result load_cubemap(rd_context *ctx, const char *pattern, rd_cubemap *out, char *err,
                               size_t err_size)
{
    rd_cube_data cube = {0};
    if (rd_cube_data_load(pattern, &cube, err, err_size) != RD_OK)
        return APP_ERR_IO;
    rd_cubemap_desc desc = {.size = cube.size};
    for (int f = 0; f < 6; f++)
        desc.faces[f] = cube.faces[f];
    *out = rd_cubemap_create(ctx, &desc);
    rd_cube_data_free(&cube);
    if (!out->id) {
        snprintf(err, err_size, "%s: %s", pattern, rd_last_error());
        return APP_ERR_IO;
    }
    return APP_OK;
}

/* Every texture and probe map of the list; err names the material that wants a bad file. */
static app_result load_files(rd_context *ctx, const app_render_list *l, app_scene *s, char *err,
                             size_t err_size)
{
    s->textures = calloc((size_t)l->texture_count + 1, sizeof *s->textures);
    s->cubemaps = calloc((size_t)l->probe_map_count + 1, sizeof *s->cubemaps);
    if (!s->textures || !s->cubemaps)
        return APP_ERR_OUT_OF_MEMORY;
    char inner[2048];
    for (; s->texture_count < l->texture_count; s->texture_count++) {
        const app_render_file *f = &l->textures[s->texture_count];
        app_result r =
            load_texture(ctx, f->path, &s->textures[s->texture_count], inner, sizeof inner);
        if (r != APP_OK) {
            snprintf(err, err_size, "%s: material \"%s\": %s", l->path, f->material, inner);
            return r;
        }
    }
    for (; s->cubemap_count < l->probe_map_count; s->cubemap_count++) {
        const app_render_file *f = &l->probe_maps[s->cubemap_count];
        app_result r =
            load_cubemap(ctx, f->path, &s->cubemaps[s->cubemap_count], inner, sizeof inner);
        if (r != APP_OK) {
            snprintf(err, err_size, "%s: material \"%s\": probe map: %s", l->path, f->material,
                     inner);
            return r;
        }
    }
    return APP_OK;
}

/* The GPU mesh of list mesh i, uploaded on first use. */
static rd_mesh mesh_of(rd_context *ctx, const app_render_list *l, app_scene *s, int i)
{
    if (i < 0 || s->meshes[i].id)
        return i < 0 ? (rd_mesh){0} : s->meshes[i];
    const app_render_mesh *m = &l->meshes[i];
    s->meshes[i] = rd_mesh_create(ctx, &(rd_mesh_desc){.positions = m->positions,
                                                       .normals = m->normals,
                                                       .uvs = m->uvs,
                                                       .indices = m->indices,
                                                       .vertex_count = m->vertex_count,
                                                       .index_count = m->index_count});
    return s->meshes[i];
}

/* Item i's own mesh carrying its baked light (per vertex or lightmap coordinates), id 0 when
 * the bake has none for it (or failed to upload: rd_last_error says). */
static rd_mesh new_baked_mesh(rd_context *ctx, const app_render_list *l, const ref_bake *bake,
                              int i, int *failed)
{
    const app_render_item *it = &l->items[i];
    const ref_bake_mesh *bm = bake && i < bake->mesh_count ? &bake->meshes[i] : NULL;
    const app_render_mesh *m = &l->meshes[it->mesh];
    *failed = 0;
    if (!bm || bm->kind == REF_BAKE_NONE || bm->vertex_count != m->vertex_count ||
        (bm->kind == REF_BAKE_LIGHTMAP && !bake->atlas_width))
        return (rd_mesh){0};
    rd_mesh mesh = rd_mesh_create(
        ctx,
        &(rd_mesh_desc){.positions = m->positions,
                        .normals = m->normals,
                        .uvs = m->uvs,
                        .indices = m->indices,
                        .vertex_count = m->vertex_count,
                        .index_count = m->index_count,
                        .baked_light = bm->kind == REF_BAKE_VERTEX ? bm->vertex : NULL,
                        .lightmap_uvs = bm->kind == REF_BAKE_LIGHTMAP ? bm->lightmap_uv : NULL});
    *failed = !mesh.id;
    return mesh;
}

/* Item i's baked mesh, or the list mesh when the item has no baked light. */
static rd_mesh baked_mesh_of(rd_context *ctx, const app_render_list *l, app_scene *s,
                             const ref_bake *bake, int i)
{
    int failed;
    rd_mesh m = new_baked_mesh(ctx, l, bake, i, &failed);
    if (failed)
        return m;
    if (!m.id)
        return mesh_of(ctx, l, s, l->items[i].mesh);
    return s->baked_meshes[i] = m;
}

static app_result add_items(rd_context *ctx, const app_render_list *l, app_scene *s,
                            const ref_bake *bake, char *err, size_t err_size)
{
    for (int i = 0; i < l->item_count; i++) {
        const app_render_item *it = &l->items[i];
        rd_object_desc d = {.mesh = baked_mesh_of(ctx, l, s, bake, i),
                            .shape = it->shape,
                            .material = it->material,
                            .background = it->background,
                            .double_sided = it->double_sided,
                            .group = it->group,
                            .probe = it->probe,
                            .probe_mesh = mesh_of(ctx, l, s, it->probe_mesh)};
        if (!d.mesh.id) {
            snprintf(err, err_size, "%s: %s: %s", l->path, it->label, rd_last_error());
            return APP_ERR_OUT_OF_MEMORY;
        }
        if (it->texture >= 0)
            d.material.diffuse_texture = s->textures[it->texture];
        if (it->probe_map >= 0)
            d.probe.static_map = s->cubemaps[it->probe_map];
        memcpy(d.transform, it->transform, sizeof d.transform);
        if (rd_scene_add_object(s->scene, &d) != RD_OK) {
            snprintf(err, err_size, "%s: %s: %s", l->path, it->label, rd_last_error());
            return APP_ERR_SCHEMA;
        }
    }
    return APP_OK;
}

static app_result scene_from_list(rd_context *ctx, const app_render_list *l, app_scene *out,
                                  const ref_bake *bake, char *err, size_t err_size)
{
    out->scene = rd_scene_create(ctx);
    if (!out->scene) {
        snprintf(err, err_size, "%s: %s", l->path, rd_last_error());
        return APP_ERR_OUT_OF_MEMORY;
    }
    rd_scene_set_ambient(out->scene, l->ambient);
    rd_reflection_defaults refl = {.ambient = l->ambient_model};
    for (int k = 0; k < 3; k++) {
        refl.proxy_min[k] = (float)l->room_min[k];
        refl.proxy_max[k] = (float)l->room_max[k];
    }
    rd_scene_set_reflection_defaults(out->scene, &refl);
    out->mesh_count = l->mesh_count;
    out->meshes = calloc((size_t)l->mesh_count + 1, sizeof *out->meshes);
    if (!out->meshes)
        return APP_ERR_OUT_OF_MEMORY;
    /* Every scene has room for baked meshes: a bake may be applied later. */
    out->baked_mesh_count = l->item_count;
    out->baked_meshes = calloc((size_t)l->item_count + 1, sizeof *out->baked_meshes);
    if (!out->baked_meshes)
        return APP_ERR_OUT_OF_MEMORY;
    if (bake) {
        if (bake->atlas_width && bake->atlas_height &&
            rd_scene_set_lightmap(out->scene, bake->atlas_width, bake->atlas_height, bake->atlas) !=
                RD_OK) {
            snprintf(err, err_size, "%s: %s", l->path, rd_last_error());
            return APP_ERR_OUT_OF_MEMORY;
        }
    }
    app_result r = load_files(ctx, l, out, err, err_size);
    if (r == APP_OK)
        r = add_items(ctx, l, out, bake, err, err_size);
    for (int i = 0; r == APP_OK && i < l->light_count; i++)
        if (rd_scene_add_light(out->scene, &l->lights[i].light) != RD_OK) {
            snprintf(err, err_size, "%s: %s: %s", l->path, l->lights[i].label, rd_last_error());
            r = APP_ERR_SCHEMA;
        }
    if (r == APP_OK)
        r = app_scene_parts_make(l, out);
    return r;
}

app_result app_scene_build(rd_context *ctx, const app_project *p, app_scene *out, char *err,
                           size_t err_size)
{
    memset(out, 0, sizeof *out);
    if (!ctx) { /* no scene without a context: say so before every model is loaded and decimated */
        snprintf(err, err_size, "%s: rd_scene_create: no context", p->path);
        return APP_ERR_OUT_OF_MEMORY;
    }
    app_render_list l;
    app_result r = app_render_list_build(p, APP_RENDER_LIST_PROBE_MESHES, &l, err, err_size);
    if (r != APP_OK)
        return r;
    ref_bake bake = {0};
    int baked = 0;
    if (app_bake_current()->on) {
        app_bake_stats stats;
        r = app_bake_list(&l, app_bake_current(), &bake, &stats, err, err_size);
        baked = r == APP_OK;
    }
    if (r == APP_OK)
        r = scene_from_list(ctx, &l, out, baked ? &bake : NULL, err, err_size);
    ref_bake_free(&bake);
    if (r == APP_ERR_OUT_OF_MEMORY && err && err_size && !err[0])
        snprintf(err, err_size, "%s: out of memory", p->path);
    app_render_list_free(&l);
    if (r != APP_OK)
        app_scene_release(ctx, out);
    return r;
}

app_result app_scene_build_from_list(rd_context *ctx, const app_render_list *l,
                                     const ref_bake *bake, app_scene *out, char *err,
                                     size_t err_size)
{
    memset(out, 0, sizeof *out);
    if (!ctx) {
        snprintf(err, err_size, "%s: rd_scene_create: no context", l->path);
        return APP_ERR_OUT_OF_MEMORY;
    }
    app_result r = scene_from_list(ctx, l, out, bake, err, err_size);
    if (r == APP_ERR_OUT_OF_MEMORY && err && err_size && !err[0])
        snprintf(err, err_size, "%s: out of memory", l->path);
    if (r != APP_OK)
        app_scene_release(ctx, out);
    return r;
}

app_result app_scene_apply_bake(rd_context *ctx, app_scene *s, const app_render_list *l,
                                const ref_bake *bake, char *err, size_t err_size)
{
    if (!s->scene || rd_scene_object_count(s->scene) != l->item_count ||
        s->baked_mesh_count != l->item_count || s->mesh_count != l->mesh_count) {
        snprintf(err, err_size, "%s: the baked light is of another scene", l->path);
        return APP_ERR_SCHEMA;
    }
    rd_mesh *next = calloc((size_t)l->item_count + 1, sizeof *next);
    if (!next) {
        snprintf(err, err_size, "%s: out of memory", l->path);
        return APP_ERR_OUT_OF_MEMORY;
    }
    app_result r = APP_OK;
    for (int i = 0; i < l->item_count && r == APP_OK; i++) {
        int failed;
        next[i] = new_baked_mesh(ctx, l, bake, i, &failed);
        if (failed || (!next[i].id && !mesh_of(ctx, l, s, l->items[i].mesh).id)) {
            snprintf(err, err_size, "%s: %s: %s", l->path, l->items[i].label, rd_last_error());
            r = APP_ERR_OUT_OF_MEMORY;
        }
    }
    /* The atlas first: a lightmapped mesh drawn without one would read none. */
    if (r == APP_OK && bake && bake->atlas_width && bake->atlas_height &&
        rd_scene_set_lightmap(s->scene, bake->atlas_width, bake->atlas_height, bake->atlas) !=
            RD_OK) {
        snprintf(err, err_size, "%s: %s", l->path, rd_last_error());
        r = APP_ERR_OUT_OF_MEMORY;
    }
    if (r != APP_OK) {
        for (int i = 0; i < l->item_count; i++)
            if (next[i].id)
                rd_mesh_destroy(ctx, next[i]);
        free(next);
        return r;
    }
    for (int i = 0; i < l->item_count; i++) {
        rd_mesh m = next[i].id ? next[i] : s->meshes[l->items[i].mesh];
        rd_scene_set_object_mesh(s->scene, i, m);
    }
    if (!bake || !bake->atlas_width || !bake->atlas_height)
        rd_scene_set_lightmap(s->scene, 0, 0, NULL);
    for (int i = 0; i < s->baked_mesh_count; i++)
        if (s->baked_meshes[i].id)
            rd_mesh_destroy(ctx, s->baked_meshes[i]);
    free(s->baked_meshes);
    s->baked_meshes = next;
    return APP_OK;
}

void app_scene_release(rd_context *ctx, app_scene *s)
{
    if (!s)
        return;
    for (int i = 0; i < s->cubemap_count; i++)
        rd_cubemap_destroy(ctx, s->cubemaps[i]);
    for (int i = 0; i < s->mesh_count; i++)
        if (s->meshes[i].id)
            rd_mesh_destroy(ctx, s->meshes[i]);
    for (int i = 0; i < s->texture_count; i++)
        rd_texture_destroy(ctx, s->textures[i]);
    for (int i = 0; i < s->baked_mesh_count; i++)
        if (s->baked_meshes[i].id)
            rd_mesh_destroy(ctx, s->baked_meshes[i]);
    free(s->baked_meshes);
    rd_scene_destroy(s->scene);
    free(s->cubemaps);
    free(s->meshes);
    free(s->textures);
    app_scene_parts_free(s);
    memset(s, 0, sizeof *s);
}

rd_tonemap app_tone_to_rd(app_tone t)
{
    switch (t) {
    case APP_TONE_AGX:
        return RD_TONEMAP_AGX;
    case APP_TONE_REINHARD:
        return RD_TONEMAP_PHOTOGRAPHIC;
    case APP_TONE_CLAMP:
        return RD_TONEMAP_CLAMP;
    default:
        return RD_TONEMAP_NEUTRAL;
    }
}

app_result app_view_from_camera(const app_project *p, const char *camera, int width, int height,
                                rd_view *out, char *err, size_t err_size)
{
    const app_camera *c = app_project_find_camera(p, camera);
    if (!c) {
        int n = 0;
        char names[512] = "";
        for (int i = 0; i < p->camera_count; i++)
            n += snprintf(names + n, n < (int)sizeof names ? sizeof names - (size_t)n : 0,
                          "%s\"%s\"", i ? ", " : "", p->cameras[i].name);
        snprintf(err, err_size, "%s: $.cameras: no camera named \"%s\" (the project has %s)",
                 p->path, camera ? camera : "", p->camera_count ? names : "none");
        return APP_ERR_NOT_FOUND;
    }
    rd_view v = {.fov_y_deg = (float)c->fov_deg,
                 .width = width > 0 ? width : p->render.width,
                 .height = height > 0 ? height : p->render.height,
                 .supersample = p->render.supersample,
                 .exposure_ev = p->render.exposure_ev,
                 .auto_exposure = p->render.exposure_auto,
                 .tonemap = app_tone_to_rd(p->render.tone),
                 .white_balance_k = p->render.white_balance_k,
                 .white = p->render.white};
    double eye_mm[3] = {c->position_mm[0], c->position_mm[1], c->position_mm[2]};
    app_camera_keep_inside(p, eye_mm);
    for (int k = 0; k < 3; k++) {
        v.eye[k] = (float)(eye_mm[k] * 1e-3);
        v.target[k] = (float)(c->target_mm[k] * 1e-3);
        v.up[k] = (float)c->up[k];
    }
    *out = v;
    return APP_OK;
}
