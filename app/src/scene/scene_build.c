#include "scene_build_internal.h"

#include "render/cube_data.h"
#include "render/image_io.h"

#include <math.h>
#include <stdlib.h>

app_result app_scene_track_mesh(app_scene *s, rd_mesh mesh)
{
    if (s->mesh_count == s->mesh_capacity) {
        int cap = s->mesh_capacity ? s->mesh_capacity * 2 : 32;
        rd_mesh *m = realloc(s->meshes, (size_t)cap * sizeof *m);
        if (!m)
            return APP_ERR_OUT_OF_MEMORY;
        s->meshes = m;
        s->mesh_capacity = cap;
    }
    s->meshes[s->mesh_count++] = mesh;
    return APP_OK;
}

static app_result load_texture(rd_context *ctx, app_scene *s, const char *path, rd_texture *out,
                               char *err, size_t err_size)
{
    for (int i = 0; i < s->texture_count; i++)
        if (!strcmp(s->texture_paths[i], path)) {
            *out = s->textures[i];
            return APP_OK;
        }
    if (s->texture_count == s->texture_capacity) {
        int cap = s->texture_capacity ? s->texture_capacity * 2 : 8;
        rd_texture *t = realloc(s->textures, (size_t)cap * sizeof *t);
        if (!t)
            return APP_ERR_OUT_OF_MEMORY;
        s->textures = t;
        char(*paths)[1024] = realloc(s->texture_paths, (size_t)cap * sizeof *paths);
        if (!paths)
            return APP_ERR_OUT_OF_MEMORY;
        s->texture_paths = paths;
        s->texture_capacity = cap;
    }
    rd_image img = {0};
    int nonfinite = 0;
    char ierr[512];
    if (rd_image_read(path, &img, &nonfinite, ierr, sizeof ierr) != RD_IMAGE_OK) {
        snprintf(err, err_size, "%s", ierr);
        return APP_ERR_IO;
    }
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
    rd_texture tex = rd_texture_create(ctx, &(rd_texture_desc){.width = img.width,
                                                               .height = img.height,
                                                               .rgba = rgba,
                                                               .srgb_encoded = img.srgb_encoded});
    free(rgba);
    rd_image_free(&img);
    if (!tex.id) {
        snprintf(err, err_size, "%s: %s", path, rd_last_error());
        return APP_ERR_IO;
    }
    s->textures[s->texture_count] = tex;
    snprintf(s->texture_paths[s->texture_count], sizeof s->texture_paths[0], "%s", path);
    s->texture_count++;
    *out = tex;
    return APP_OK;
}

app_result app_scene_material(rd_context *ctx, const app_project *p, app_scene *s, int mi,
                              rd_material *out, char *err, size_t err_size)
{
    return app_scene_material_of(ctx, p, s, &p->materials[mi], out, err, err_size);
}

app_result app_scene_material_of(rd_context *ctx, const app_project *p, app_scene *s,
                                 const app_material *am, rd_material *out, char *err,
                                 size_t err_size)
{
    rd_material m = {.shininess = am->shininess,
                     .reflectivity = am->reflectivity,
                     .glossiness = am->glossiness,
                     .blend = (rd_reflection_blend)am->blend,
                     .correction = (rd_correction)am->correction,
                     .transparency = am->transparency,
                     .ior = am->ior,
                     .dispersion = am->dispersion,
                     .per_vertex_reflection = am->probe_per_vertex,
                     .sphere_map = am->probe_sphere_map};
    memcpy(m.ambient, am->ambient, sizeof m.ambient);
    memcpy(m.diffuse, am->diffuse, sizeof m.diffuse);
    memcpy(m.specular, am->specular, sizeof m.specular);
    memcpy(m.emissive, am->emissive, sizeof m.emissive);
    if (am->texture[0]) {
        app_result r = load_texture(ctx, s, am->texture, &m.diffuse_texture, err, err_size);
        if (r != APP_OK) {
            char inner[768];
            snprintf(inner, sizeof inner, "%s", err);
            snprintf(err, err_size, "%s: material \"%s\": %s", p->path, am->name, inner);
            return r;
        }
    }
    *out = m;
    return APP_OK;
}

static void add_light(const app_light *l, rd_light *out)
{
    rd_light r = {.type = l->type == APP_LIGHT_SPOT          ? RD_LIGHT_SPOT
                          : l->type == APP_LIGHT_DIRECTIONAL ? RD_LIGHT_DIRECTIONAL
                                                             : RD_LIGHT_POINT};
    for (int k = 0; k < 3; k++) {
        r.position[k] = (float)(l->position_mm[k] * 1e-3);
        r.direction[k] = (float)l->direction[k];
        r.diffuse[k] = l->color[k] * l->intensity;
        r.specular[k] = l->specular[k] * l->intensity;
        r.attenuation[k] = l->attenuation[k];
    }
    const double deg = 3.14159265358979323846 / 180.0;
    r.spot_inner_cos = (float)cos(l->inner_deg * deg);
    r.spot_outer_cos = (float)cos(l->outer_deg * deg);
    *out = r;
}

static app_result scene_build(rd_context *ctx, app_scene_products *q, app_scene *out, char *err,
                              size_t err_size);

app_result app_scene_build(rd_context *ctx, const app_project *p, app_scene *out, char *err,
                           size_t err_size)
{
    app_scene_products q;
    app_result r = app_scene_resolve_products(p, &q, err, err_size);
    if (r != APP_OK) {
        memset(out, 0, sizeof *out);
        return r;
    }
    r = scene_build(ctx, &q, out, err, err_size);
    app_scene_resolved_free(&q);
    return r;
}

static app_result scene_build(rd_context *ctx, app_scene_products *q, app_scene *out, char *err,
                              size_t err_size)
{
    const app_project *p = &q->q;
    memset(out, 0, sizeof *out);
    out->scene = rd_scene_create(ctx);
    if (!out->scene) {
        snprintf(err, err_size, "%s: %s", p->path, rd_last_error());
        return APP_ERR_OUT_OF_MEMORY;
    }
    rd_scene_set_ambient(out->scene, p->render.ambient);
    /* The box proxy of the corrected reflection vector is the room's interior: in a bathroom
     * the walls are what a fixture reflects (RENDERING.md section 4). */
    app_room_geometry room;
    app_result r = app_room_geometry_build(p, &room, err, err_size);
    if (r != APP_OK) {
        app_scene_release(ctx, out);
        return r;
    }
    app_room_add_tiles(p, q->covers, q->cover_count, &q->catalog, &room);
    /* The room's bounding box (the plan's, from the floor to the flat ceiling): for a
     * version 1 room exactly (0,0,0)-(width,depth,height) as before. */
    rd_reflection_defaults refl = {.ambient = p->render.ambient_model == 1 ? RD_AMBIENT_SH9
                                                                           : RD_AMBIENT_CONSTANT};
    for (int k = 0; k < 3; k++) {
        refl.proxy_min[k] = (float)room.bounds_min[k];
        refl.proxy_max[k] = (float)room.bounds_max[k];
    }
    rd_scene_set_reflection_defaults(out->scene, &refl);
    r = app_scene_add_room(ctx, p, &room, out, err, err_size);
    if (r == APP_OK)
        r = app_scene_add_objects(ctx, p, out, err, err_size);
    for (int i = 0; r == APP_OK && i < p->light_count; i++) {
        rd_light l;
        add_light(&p->lights[i], &l);
        if (rd_scene_add_light(out->scene, &l) != RD_OK) {
            snprintf(err, err_size, "%s: $.lights[%d]: %s", p->path, i, rd_last_error());
            r = APP_ERR_SCHEMA;
        }
    }
    /* Daylight through the windows (app/design/room_mesh.h), after the project's own lights. */
    for (int i = 0; r == APP_OK && i < room.light_count; i++) {
        rd_light l;
        add_light(&room.lights[i], &l);
        if (rd_scene_add_light(out->scene, &l) != RD_OK) {
            snprintf(err, err_size, "%s: window light \"%s\": %s", p->path, room.lights[i].name,
                     rd_last_error());
            r = APP_ERR_SCHEMA;
        }
    }
    app_room_geometry_free(&room);
    if (r != APP_OK)
        app_scene_release(ctx, out);
    return r;
}

app_result app_scene_cubemap(rd_context *ctx, app_scene *s, const char *pattern, rd_cubemap *out,
                             char *err, size_t err_size)
{
    for (int i = 0; i < s->cubemap_count; i++)
        if (!strcmp(s->cubemap_paths[i], pattern)) {
            *out = s->cubemaps[i];
            return APP_OK;
        }
    if (s->cubemap_count == s->cubemap_capacity) {
        int cap = s->cubemap_capacity ? s->cubemap_capacity * 2 : 4;
        rd_cubemap *m = realloc(s->cubemaps, (size_t)cap * sizeof *m);
        if (!m)
            return APP_ERR_OUT_OF_MEMORY;
        s->cubemaps = m;
        char(*paths)[1024] = realloc(s->cubemap_paths, (size_t)cap * sizeof *paths);
        if (!paths)
            return APP_ERR_OUT_OF_MEMORY;
        s->cubemap_paths = paths;
        s->cubemap_capacity = cap;
    }
    rd_cube_data cube = {0};
    if (rd_cube_data_load(pattern, &cube, err, err_size) != RD_OK)
        return APP_ERR_IO;
    rd_cubemap_desc desc = {.size = cube.size};
    for (int f = 0; f < 6; f++)
        desc.faces[f] = cube.faces[f];
    rd_cubemap map = rd_cubemap_create(ctx, &desc);
    rd_cube_data_free(&cube);
    if (!map.id) {
        snprintf(err, err_size, "%s: %s", pattern, rd_last_error());
        return APP_ERR_IO;
    }
    s->cubemaps[s->cubemap_count] = map;
    snprintf(s->cubemap_paths[s->cubemap_count], sizeof s->cubemap_paths[0], "%s", pattern);
    s->cubemap_count++;
    *out = map;
    return APP_OK;
}

void app_scene_release(rd_context *ctx, app_scene *s)
{
    if (!s)
        return;
    for (int i = 0; i < s->cubemap_count; i++)
        rd_cubemap_destroy(ctx, s->cubemaps[i]);
    free(s->cubemaps);
    free(s->cubemap_paths);
    for (int i = 0; i < s->mesh_count; i++)
        rd_mesh_destroy(ctx, s->meshes[i]);
    for (int i = 0; i < s->texture_count; i++)
        rd_texture_destroy(ctx, s->textures[i]);
    rd_scene_destroy(s->scene);
    free(s->meshes);
    free(s->object_parts);
    free(s->textures);
    free(s->texture_paths);
    memset(s, 0, sizeof *s);
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
                 .white = p->render.white};
    for (int k = 0; k < 3; k++) {
        v.eye[k] = (float)(c->position_mm[k] * 1e-3);
        v.target[k] = (float)(c->target_mm[k] * 1e-3);
        v.up[k] = (float)c->up[k];
    }
    *out = v;
    return APP_OK;
}
