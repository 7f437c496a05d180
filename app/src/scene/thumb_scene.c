/* The thumbnail studio (thumb_scene.h): a light grey backdrop all around (emissive, so it is
 * even and gives chrome and glass something to reflect), a floor, a key, a fill and a rim
 * light, and the product on the floor in its first variant; the camera frames the product's
 * bounding sphere from the front right, a little above (products face +Y, docs/catalog.md
 * "Models"). Lengths in the catalog are millimetres, the renderer's metres. */
#include "app/scene/thumb_scene.h"

#include "model_materials.h"

#include "catalog/mesh_lod.h"
#include "catalog/model.h"
#include "catalog/model_gen.h"
#include "catalog/model_write.h"
#include "render/image_io.h"
#include "render/primitives.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define MAX_PARTS 256

#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static void
say(char *buf, size_t size, const char *fmt, ...)
{
    if (!buf || !size)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, size, fmt, ap);
    va_end(ap);
}

static rd_mesh upload(rd_context *ctx, rd_result (*make)(rd_mesh_data *))
{
    rd_mesh_data d;
    rd_mesh m = {0};
    if (make(&d) != RD_OK)
        return m;
    rd_mesh_desc desc = rd_mesh_data_desc(&d);
    m = rd_mesh_create(ctx, &desc);
    rd_mesh_data_free(&d);
    return m;
}

int thumb_studio_init(thumb_studio *st, rd_context *ctx, const char *assets_dir, char *err,
                      size_t err_size)
{
    memset(st, 0, sizeof *st);
    st->ctx = ctx;
    st->assets_dir = assets_dir;
    st->supersample = 2;
    st->plane = upload(ctx, rd_mesh_data_plane);
    st->box = upload(ctx, rd_mesh_data_box);
    if (!st->plane.id || !st->box.id) {
        say(err, err_size, "thumbnails: cannot make the studio's meshes: %s", rd_last_error());
        thumb_studio_free(st);
        return 0;
    }
    return 1;
}

void thumb_studio_free(thumb_studio *st)
{
    if (st->ctx) {
        if (st->plane.id)
            rd_mesh_destroy(st->ctx, st->plane);
        if (st->box.id)
            rd_mesh_destroy(st->ctx, st->box);
    }
    memset(st, 0, sizeof *st);
}

/* Column-major: the linear part's columns x, y, z, then the translation (metres). */
static void affine(float m[16], const float x[3], const float y[3], const float z[3],
                   const float t[3])
{
    memset(m, 0, 16 * sizeof *m);
    for (int k = 0; k < 3; k++) {
        m[k] = x[k];
        m[4 + k] = y[k];
        m[8 + k] = z[k];
        m[12 + k] = t[k];
    }
    m[15] = 1;
}

static void scale_translate(float m[16], float sx, float sy, float sz, float tx, float ty, float tz)
{
    affine(m, (float[3]){sx, 0, 0}, (float[3]){0, sy, 0}, (float[3]){0, 0, sz},
           (float[3]){tx, ty, tz});
}

/* A plain glTF material (no Tessera extras): metallic-roughness, roughly inverted from
 * cat_material_from_render (catalog/model_write.h). */
static rd_material from_gltf(const cat_material *g)
{
    cat_render_material c;
    memset(&c, 0, sizeof c);
    float metal = fminf(fmaxf(g->metallic, 0), 1), rough = fminf(fmaxf(g->roughness, 0), 1);
    for (int k = 0; k < 3; k++) {
        c.diffuse[k] = g->base_color[k] * (1 - metal);
        c.ambient[k] = c.diffuse[k];
        c.specular[k] = 0.04f + (g->base_color[k] - 0.04f) * metal;
        c.emissive[k] = g->emissive[k];
    }
    c.glossiness = 1 - rough;
    c.shininess = fminf(2 / fmaxf(rough * rough * rough * rough, 1e-4f) - 2, 4096);
    c.reflectivity = 0.8f * metal;
    c.blend = CAT_BLEND_FRESNEL;
    c.transparency = 1 - fminf(fmaxf(g->base_color[3], 0), 1);
    c.ior = 1.5f;
    return app_material_from_catalog(&c);
}

typedef struct product_parts {
    rd_mesh meshes[MAX_PARTS];
    int count;
    rd_texture texture;
    float lo[3], hi[3]; /* metres */
} product_parts;

static void parts_free(rd_context *ctx, product_parts *pp)
{
    for (int i = 0; i < pp->count; i++)
        if (pp->meshes[i].id)
            rd_mesh_destroy(ctx, pp->meshes[i]);
    if (pp->texture.id)
        rd_texture_destroy(ctx, pp->texture);
    memset(pp, 0, sizeof *pp);
}

/* The finish drawn: the studio's preferred variant code where the product has it (any case),
 * else its first variant (by code); NULL for a product without variants. */
static const cat_render_material *finish_of(const thumb_studio *st, const cat_product *p)
{
    for (int i = 0; st->variant && i < p->variant_count; i++)
        if (!strcasecmp(p->variants[i].code, st->variant))
            return &p->variants[i].material;
    return p->variant_count ? &p->variants[0].material : NULL;
}

static rd_material default_material(void)
{
    cat_render_material c = {{0.7f, 0.7f, 0.7f},
                             {0.7f, 0.7f, 0.7f},
                             {0.2f, 0.2f, 0.2f},
                             {0, 0, 0},
                             32,
                             0,
                             0.5f,
                             CAT_BLEND_MIX,
                             0,
                             1.5f,
                             CAT_PATTERN_NONE,
                             0};
    return app_material_from_catalog(&c);
}

/* The product's GLB, its parts in the materials of the file, the finish parts in the variant.
 * Returns 0 with a note when there is no usable model (the caller draws a box). */
static int add_model(thumb_studio *st, rd_scene *scene, const cat_product *p, product_parts *pp,
                     char *note, size_t note_size)
{
    char path[4096], err[1024];
    if (!p->model[0]) {
        say(note, note_size, "no model in the catalog");
        return 0;
    }
    if (!cat_model_resolve(p->model, st->assets_dir, path, sizeof path)) {
        say(note, note_size, "model path \"%s\" cannot be resolved", p->model);
        return 0;
    }
    cat_model m;
    if (cat_model_load(path, &m, err, sizeof err) != CAT_OK) {
        say(note, note_size, "%s", err);
        return 0;
    }
    /* Check before drawing: refuse what would break the renderer, drop degenerate triangles. */
    if (cat_model_validate(&m, path, 1, NULL, err, sizeof err) != CAT_OK ||
        m.mesh_count > MAX_PARTS) {
        say(note, note_size, "%s", m.mesh_count > MAX_PARTS ? "too many parts" : err);
        cat_model_free(&m);
        return 0;
    }
    cat_material_extras extras[MAX_PARTS];
    int extra_count = 0;
    memset(extras, 0, sizeof extras);
    if (cat_model_read_extras(path, extras, MAX_PARTS, &extra_count, err, sizeof err) != CAT_OK)
        extra_count = 0; /* a plain glTF file: its own materials */
    for (int i = 0; i < m.mesh_count; i++) {
        const cat_mesh *cm = &m.meshes[i];
        if (cm->index_count == 0)
            continue;
        rd_mesh_desc d = {.positions = cm->positions,
                          .normals = cm->normals,
                          .uvs = cm->uvs,
                          .indices = cm->indices,
                          .vertex_count = cm->vertex_count,
                          .index_count = cm->index_count};
        rd_mesh mesh = rd_mesh_create(st->ctx, &d);
        if (!mesh.id)
            continue;
        pp->meshes[pp->count++] = mesh;
        rd_material mat = default_material();
        int mi = cm->material;
        if (mi >= 0 && mi < extra_count && extras[mi].present)
            /* without --variant the model's own finish parts show its main finish (the first
             * variant of the CSV rows, docs/catalog.md "Models"), not the first by code */
            mat = extras[mi].variant_slot && st->variant && finish_of(st, p)
                      ? app_material_from_catalog(finish_of(st, p))
                      : app_material_from_catalog(&extras[mi].params);
        else if (mi >= 0 && mi < m.material_count)
            mat = from_gltf(&m.materials[mi]);
        else if (finish_of(st, p))
            mat = app_material_from_catalog(finish_of(st, p));
        rd_object_desc o;
        memset(&o, 0, sizeof o);
        o.mesh = mesh;
        o.material = mat;
        o.group = 1;        /* one probe for all parts */
        o.double_sided = 1; /* generated sheets (screens, mirrors) may be open */
        scale_translate(o.transform, 1e-3f, 1e-3f, 1e-3f, 0, 0, 0);
        rd_scene_add_object(scene, &o);
    }
    for (int k = 0; k < 3; k++) {
        pp->lo[k] = m.bounds_min[k] * 1e-3f;
        pp->hi[k] = m.bounds_max[k] * 1e-3f;
    }
    cat_model_free(&m);
    if (pp->count == 0) {
        say(note, note_size, "%s: no triangles", path);
        return 0;
    }
    return 1;
}

/* No model: a box of the catalog's size, in the origin convention of generated models (the
 * bottom centre of the back face). */
static void add_box(thumb_studio *st, rd_scene *scene, const cat_product *p, product_parts *pp)
{
    float w = (float)p->width_mm * 1e-3f, d = (float)p->depth_mm * 1e-3f,
          h = (float)p->height_mm * 1e-3f;
    rd_object_desc o;
    memset(&o, 0, sizeof o);
    o.mesh = st->box;
    o.material =
        finish_of(st, p) ? app_material_from_catalog(finish_of(st, p)) : default_material();
    scale_translate(o.transform, w, d, h, 0, d / 2, h / 2);
    rd_scene_add_object(scene, &o);
    float lo[3] = {-w / 2, 0, 0}, hi[3] = {w / 2, d, h};
    memcpy(pp->lo, lo, sizeof lo);
    memcpy(pp->hi, hi, sizeof hi);
}

/* A tile: a square two tiles (of the longer side) wide, standing like a piece of wall, tiled
 * with the tile's texture (app/tools/make_tile_textures.c: one nominal cell per image). */
static int add_tile(thumb_studio *st, rd_scene *scene, const cat_product *p, product_parts *pp,
                    char *err, size_t err_size)
{
    char path[4096], msg[1024];
    snprintf(path, sizeof path, "%s/%s", st->assets_dir, p->tile.texture);
    rd_image img;
    if (rd_image_read(path, &img, NULL, msg, sizeof msg) != RD_IMAGE_OK) {
        say(err, err_size, "%s", msg);
        return 0;
    }
    float *rgba = malloc((size_t)img.width * (size_t)img.height * 4 * sizeof *rgba);
    if (rgba) {
        rd_image_expand_rgba(&img, rgba);
        rd_texture_desc td = {img.width, img.height, rgba, img.srgb_encoded};
        pp->texture = rd_texture_create(st->ctx, &td);
    }
    free(rgba);
    rd_image_free(&img);
    if (!pp->texture.id) {
        say(err, err_size, "%s: cannot make a texture of it: %s", path, rd_last_error());
        return 0;
    }
    float nw = (float)p->tile.nominal_w_mm * 1e-3f, nh = (float)p->tile.nominal_h_mm * 1e-3f;
    float side = 2 * fmaxf(nw, nh);
    rd_object_desc o;
    memset(&o, 0, sizeof o);
    o.mesh = st->plane;
    const cat_render_material *f = finish_of(st, p);
    o.material = f ? app_material_from_catalog(f) : default_material();
    /* the texture carries the glaze's colour: the diffuse factor is white */
    for (int k = 0; k < 3; k++)
        o.material.diffuse[k] = 1.0f;
    o.material.diffuse_texture = pp->texture;
    o.material.uv_scale[0] = side / nw;
    o.material.uv_scale[1] = side / nh;
    o.material.transparency = 0; /* glass inserts: show the glaze, not what is behind */
    /* the unit plane (normal +Z, v along +Y) turned to face +Y with v pointing down */
    affine(o.transform, (float[3]){side, 0, 0}, (float[3]){0, 0, -side}, (float[3]){0, side, 0},
           (float[3]){0, 0.002f, side / 2});
    rd_scene_add_object(scene, &o);
    float lo[3] = {-side / 2, 0, 0}, hi[3] = {side / 2, 0.004f, side};
    memcpy(pp->lo, lo, sizeof lo);
    memcpy(pp->hi, hi, sizeof hi);
    return 1;
}

/* Backdrop, floor and lights around the product's bounds. */
static void add_studio(thumb_studio *st, rd_scene *scene, const product_parts *pp, float radius,
                       const float *view_dir)
{
    float room = fmaxf(40 * radius, 4.0f);
    rd_object_desc o;
    memset(&o, 0, sizeof o);
    o.mesh = st->box;
    o.background = 1;
    o.double_sided = 1;
    float grey[3] = {0.82f, 0.82f, 0.84f};
    memcpy(o.material.emissive, grey, sizeof grey);
    o.material.shininess = 1;
    float cx = 0.5f * (pp->lo[0] + pp->hi[0]), cy = 0.5f * (pp->lo[1] + pp->hi[1]);
    scale_translate(o.transform, room, room, room, cx, cy,
                    0.49f * room); /* floor above its bottom */
    rd_scene_add_object(scene, &o);

    memset(&o, 0, sizeof o);
    o.mesh = st->plane;
    o.background = 1;
    for (int k = 0; k < 3; k++) {
        o.material.ambient[k] = 0.5f; /* darker than the backdrop: mirrors show it */
        o.material.diffuse[k] = 0.5f;
        o.material.specular[k] = 0.05f;
    }
    o.material.shininess = 8;
    scale_translate(o.transform, room * 0.999f, room * 0.999f, 1, cx, cy, -0.0005f);
    rd_scene_add_object(scene, &o);

    /* A darker panel behind the camera: mirrors and chrome, which face the camera, reflect it
     * and stand out from the even backdrop. */
    memset(&o, 0, sizeof o);
    o.mesh = st->plane;
    o.background = 1;
    o.double_sided = 1;
    float panel[3] = {0.38f, 0.38f, 0.40f};
    memcpy(o.material.emissive, panel, sizeof panel);
    o.material.shininess = 1;
    affine(o.transform, (float[3]){room, 0, 0}, (float[3]){0, 0, room}, (float[3]){0, -1, 0},
           (float[3]){cx, pp->hi[1] + 0.3f * room, 0.5f * room});
    rd_scene_add_object(scene, &o);

    /* Two black cards beside the camera, out of its view, as in product photography: chrome
     * shows them as dark bands along its edges, which is what makes it read as metal. The
     * camera looks from the horizontal direction (dx, dy); the cards stand 3 r to either side
     * of that line, 2 r towards the camera, parallel to it. */
    float r = radius; /* the camera frames the bounding sphere: this keeps the cards out */
    int cards = view_dir != NULL; /* none for tile panels: their glaze would mirror them */
    float h = pp->hi[2] - pp->lo[2] + 2 * r, black[3] = {0.03f, 0.03f, 0.03f};
    float dl = cards ? sqrtf(view_dir[0] * view_dir[0] + view_dir[1] * view_dir[1]) : 1;
    float dx = cards ? view_dir[0] / dl : 0, dy = cards ? view_dir[1] / dl : 1;
    for (int side = -1; cards && side <= 1; side += 2) {
        memset(&o, 0, sizeof o);
        o.mesh = st->plane;
        o.background = 1;
        o.double_sided = 1;
        memcpy(o.material.emissive, black, sizeof black);
        o.material.shininess = 1;
        float px = (float)side * dy, py = -(float)side * dx; /* perpendicular, horizontal */
        /* columns x, y, normal form a right-handed frame; the card is double-sided */
        affine(o.transform, (float[3]){3 * r * dx, 3 * r * dy, 0}, (float[3]){0, 0, h},
               (float[3]){dy, -dx, 0},
               (float[3]){cx + 2 * r * dx + 3 * r * px, cy + 2 * r * dy + 3 * r * py, 0.5f * h});
        rd_scene_add_object(scene, &o);
    }

    /* key from the front left above, fill from the right, rim from behind */
    const struct {
        float dir[3], level;
    } lights[] = {{{0.45f, -0.75f, -0.85f}, 0.7f},
                  {{-0.8f, -0.45f, -0.3f}, 0.35f},
                  {{0.1f, 0.8f, -0.6f}, 0.3f}};
    for (size_t i = 0; i < sizeof lights / sizeof lights[0]; i++) {
        rd_light l;
        memset(&l, 0, sizeof l);
        l.type = RD_LIGHT_DIRECTIONAL;
        memcpy(l.direction, lights[i].dir, sizeof l.direction);
        for (int k = 0; k < 3; k++)
            l.diffuse[k] = l.specular[k] = lights[i].level;
        l.attenuation[0] = 1;
        rd_scene_add_light(scene, &l);
    }
    float ambient[3] = {0.3f, 0.3f, 0.31f};
    rd_scene_set_ambient(scene, ambient);
    rd_reflection_defaults rd = rd_scene_reflection_defaults(scene);
    rd.update = RD_PROBE_ONCE;
    rd.max_resolution = 64; /* a thumbnail's reflections need no more */
    rd_scene_set_reflection_defaults(scene, &rd);
}

int thumb_render(thumb_studio *st, const cat_product *p, int size, uint8_t *rgba,
                 thumb_source *source, char *note, size_t note_size, char *err, size_t err_size)
{
    if (note && note_size)
        note[0] = '\0';
    rd_scene *scene = rd_scene_create(st->ctx);
    if (!scene) {
        say(err, err_size, "thumbnails: cannot make a scene: %s", rd_last_error());
        return 0;
    }
    product_parts pp;
    memset(&pp, 0, sizeof pp);
    int ok = 1;
    if (p->has_tile && p->tile.texture[0]) {
        *source = THUMB_TILE;
        ok = add_tile(st, scene, p, &pp, err, err_size);
    } else if (add_model(st, scene, p, &pp, note, note_size)) {
        *source = THUMB_MODEL;
    } else {
        *source = THUMB_BOX;
        add_box(st, scene, p, &pp);
    }
    if (ok) {
        float c[3], radius = 0;
        for (int k = 0; k < 3; k++) {
            c[k] = 0.5f * (pp.lo[k] + pp.hi[k]);
            radius += 0.25f * (pp.hi[k] - pp.lo[k]) * (pp.hi[k] - pp.lo[k]);
        }
        radius = fmaxf(sqrtf(radius), 0.01f);
        /* the camera: front right and above for products, nearly square-on for tile panels */
        float dir[3] = {0.55f, 1.0f, 0.55f};
        if (*source == THUMB_TILE) {
            dir[0] = 0.12f;
            dir[2] = 0.18f;
        } else if (p->category == CAT_CATEGORY_MIRRORS ||
                   p->category == CAT_CATEGORY_MIRROR_CABINETS) {
            dir[2] = 0.04f; /* level with the glass, which then shows the panel, not the floor */
        }
        add_studio(st, scene, &pp, radius, *source == THUMB_TILE ? NULL : dir);
        float len = sqrtf(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        float fov = 30.0f, dist = radius / sinf(0.5f * fov * 3.14159265f / 180.0f) * 1.02f;
        rd_view v;
        memset(&v, 0, sizeof v);
        for (int k = 0; k < 3; k++) {
            v.target[k] = c[k];
            v.eye[k] = c[k] + dir[k] / len * dist;
        }
        v.fov_y_deg = fov;
        v.near_m = fmaxf(dist - 2 * radius, dist * 0.02f);
        v.far_m = dist + 60 * radius + 10;
        v.width = v.height = size;
        v.supersample = st->supersample;
        v.tonemap = RD_TONEMAP_CLAMP;
        rd_result r = rd_render(st->ctx, scene, &v);
        if (r == RD_OK)
            r = rd_read_rgba8(st->ctx, rgba, (size_t)size * (size_t)size * 4);
        if (r != RD_OK) {
            say(err, err_size, "thumbnails: rendering failed: %s", rd_last_error());
            ok = 0;
        }
    }
    rd_scene_destroy(scene);
    parts_free(st->ctx, &pp);
    return ok;
}
