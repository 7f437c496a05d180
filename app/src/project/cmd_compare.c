/* Deep comparison, copy and release of whole documents: what the undo tests compare, and
 * what a UI needs to keep a saved copy. Numbers compare bit for bit (an undo restores the
 * exact value, not a close one); padding bytes never take part. */
#include "app/project/commands.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct cmp {
    char *diff;
    size_t size;
    char path[160];
} cmp;

static int differ(cmp *c, const char *field)
{
    if (c->diff && c->size)
        snprintf(c->diff, c->size, "%s%s differs", c->path, field);
    return 0;
}

static void at(cmp *c, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void at(cmp *c, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->path, sizeof c->path, fmt, ap);
    va_end(ap);
}

#define SAME_NUM(a, b) (memcmp(&(a), &(b), sizeof(a)) == 0)
#define NUM(field)                                                                                 \
    do {                                                                                           \
        if (!SAME_NUM(x->field, y->field))                                                         \
            return differ(c, "." #field);                                                          \
    } while (0)
#define VEC(field, n)                                                                              \
    do {                                                                                           \
        for (int k_ = 0; k_ < (n); k_++)                                                           \
            if (!SAME_NUM(x->field[k_], y->field[k_]))                                             \
                return differ(c, "." #field);                                                      \
    } while (0)
#define STR(field)                                                                                 \
    do {                                                                                           \
        if (strncmp(x->field, y->field, sizeof x->field) != 0)                                     \
            return differ(c, "." #field);                                                          \
    } while (0)

static int product_eq(cmp *c, const app_product_ref *x, const app_product_ref *y)
{
    STR(manufacturer);
    STR(article);
    STR(variant);
    return 1;
}

static int material_eq(cmp *c, const app_material *x, const app_material *y)
{
    STR(name);
    VEC(ambient, 3);
    VEC(diffuse, 3);
    VEC(specular, 3);
    VEC(emissive, 3);
    NUM(shininess);
    STR(texture);
    VEC(texture_size_mm, 2);
    NUM(reflectivity);
    NUM(glossiness);
    NUM(blend);
    NUM(correction);
    NUM(probe_update);
    NUM(probe_every);
    NUM(probe_resolution);
    NUM(proxy_radius_mm);
    STR(probe_map);
    NUM(probe_sphere_map);
    NUM(probe_per_vertex);
    NUM(transparency);
    NUM(ior);
    NUM(dispersion);
    NUM(pattern);
    NUM(grain_deg);
    return 1;
}

static int object_eq(cmp *c, const app_object *x, const app_object *y)
{
    STR(name);
    NUM(shape);
    STR(model);
    VEC(position_mm, 3);
    VEC(rotation_deg, 3);
    VEC(scale, 3);
    VEC(size_mm, 3);
    NUM(material);
    STR(group);
    STR(parent);
    NUM(has_product);
    return product_eq(c, &x->product, &y->product);
}

static int light_eq(cmp *c, const app_light *x, const app_light *y)
{
    STR(name);
    NUM(type);
    VEC(position_mm, 3);
    VEC(direction, 3);
    VEC(color, 3);
    NUM(intensity);
    VEC(specular, 3);
    VEC(attenuation, 3);
    NUM(inner_deg);
    NUM(outer_deg);
    STR(emitter);
    NUM(emitter_named);
    return 1;
}

static int camera_eq(cmp *c, const app_camera *x, const app_camera *y)
{
    STR(name);
    VEC(position_mm, 3);
    VEC(target_mm, 3);
    VEC(up, 3);
    NUM(fov_deg);
    return 1;
}

static int corner_eq(cmp *c, const app_point2 *x, const app_point2 *y)
{
    NUM(x);
    NUM(y);
    return 1;
}

static int opening_eq(cmp *c, const app_opening *x, const app_opening *y)
{
    STR(name);
    NUM(type);
    NUM(wall);
    NUM(offset_mm);
    NUM(width_mm);
    NUM(height_mm);
    NUM(sill_mm);
    NUM(swing);
    VEC(light, 3);
    return 1;
}

static int prewall_eq(cmp *c, const app_prewall *x, const app_prewall *y)
{
    STR(name);
    NUM(wall);
    NUM(offset_mm);
    NUM(width_mm);
    NUM(depth_mm);
    NUM(height_mm);
    return 1;
}

static int niche_eq(cmp *c, const app_niche *x, const app_niche *y)
{
    STR(name);
    NUM(wall);
    NUM(offset_mm);
    NUM(width_mm);
    NUM(sill_mm);
    NUM(height_mm);
    NUM(depth_mm);
    return 1;
}

static int tiling_eq(cmp *c, const app_tiling *x, const app_tiling *y)
{
    STR(name);
    STR(surface);
    if (!product_eq(c, &x->product, &y->product))
        return 0;
    NUM(pattern);
    NUM(grout_mm);
    VEC(grout_color, 3);
    NUM(align);
    VEC(origin_mm, 2);
    NUM(rotation_deg);
    NUM(from_mm);
    NUM(to_mm);
    NUM(border_count);
    for (int k = 0; k < x->border_count && k < APP_TILING_MAX_BORDERS; k++) {
        if (!product_eq(c, &x->borders[k].product, &y->borders[k].product))
            return 0;
        NUM(borders[k].bottom_mm);
    }
    return 1;
}

static int head_eq(cmp *c, const app_project *x, const app_project *y)
{
    NUM(version);
    NUM(file_version);
    STR(name);
    STR(path);
    NUM(room.width_mm);
    NUM(room.depth_mm);
    NUM(room.height_mm);
    NUM(room.floor_material);
    NUM(room.wall_material);
    NUM(room.ceiling_material);
    NUM(plan.corner_count);
    NUM(plan.height_mm);
    NUM(plan.wall_thickness_mm);
    NUM(plan.opening_count);
    NUM(plan.prewall_count);
    NUM(plan.niche_count);
    NUM(plan.slope.present);
    NUM(plan.slope.wall);
    NUM(plan.slope.knee_mm);
    NUM(plan.slope.run_mm);
    NUM(tiling_count);
    NUM(material_count);
    NUM(object_count);
    NUM(light_count);
    NUM(camera_count);
    VEC(render.ambient, 3);
    NUM(render.exposure_ev);
    NUM(render.white);
    NUM(render.width);
    NUM(render.height);
    NUM(render.supersample);
    NUM(render.ambient_model);
    return 1;
}

#define EACH(count, arr, fn, label)                                                                \
    do {                                                                                           \
        for (int i = 0; i < a->count; i++) {                                                       \
            at(&c, label "[%d]", i);                                                               \
            if (!fn(&c, &a->arr[i], &b->arr[i]))                                                   \
                return 0;                                                                          \
        }                                                                                          \
    } while (0)

int app_project_equal(const app_project *a, const app_project *b, char *diff, size_t diff_size)
{
    cmp c = {diff, diff_size, ""};
    if (diff && diff_size)
        diff[0] = 0;
    if (!head_eq(&c, a, b))
        return 0;
    EACH(plan.corner_count, plan.corners, corner_eq, "plan.corners");
    EACH(plan.opening_count, plan.openings, opening_eq, "plan.openings");
    EACH(plan.prewall_count, plan.prewalls, prewall_eq, "plan.prewalls");
    EACH(plan.niche_count, plan.niches, niche_eq, "plan.niches");
    EACH(tiling_count, tilings, tiling_eq, "tilings");
    EACH(material_count, materials, material_eq, "materials");
    EACH(object_count, objects, object_eq, "objects");
    EACH(light_count, lights, light_eq, "lights");
    EACH(camera_count, cameras, camera_eq, "cameras");
    return 1;
}

static int dup_array(void **dst, const void *src, int count, size_t elem)
{
    *dst = NULL;
    if (!src || count <= 0)
        return 1;
    *dst = malloc((size_t)count * elem);
    if (!*dst)
        return 0;
    memcpy(*dst, src, (size_t)count * elem);
    return 1;
}

app_result app_project_copy(app_project *dst, const app_project *src, char *err, size_t err_size)
{
    *dst = *src;
    void *corners, *openings, *prewalls, *niches, *tilings, *materials, *objects, *lights, *cameras;
    int ok = dup_array(&corners, src->plan.corners, src->plan.corner_count, sizeof(app_point2));
    ok &= dup_array(&openings, src->plan.openings, src->plan.opening_count, sizeof(app_opening));
    ok &= dup_array(&prewalls, src->plan.prewalls, src->plan.prewall_count, sizeof(app_prewall));
    ok &= dup_array(&niches, src->plan.niches, src->plan.niche_count, sizeof(app_niche));
    ok &= dup_array(&tilings, src->tilings, src->tiling_count, sizeof(app_tiling));
    ok &= dup_array(&materials, src->materials, src->material_count, sizeof(app_material));
    ok &= dup_array(&objects, src->objects, src->object_count, sizeof(app_object));
    ok &= dup_array(&lights, src->lights, src->light_count, sizeof(app_light));
    ok &= dup_array(&cameras, src->cameras, src->camera_count, sizeof(app_camera));
    dst->plan.corners = corners;
    dst->plan.openings = openings;
    dst->plan.prewalls = prewalls;
    dst->plan.niches = niches;
    dst->tilings = tilings;
    dst->materials = materials;
    dst->objects = objects;
    dst->lights = lights;
    dst->cameras = cameras;
    if (!ok) {
        app_project_free_all(dst);
        if (err && err_size)
            snprintf(err, err_size, "out of memory copying the project");
        return APP_ERR_OUT_OF_MEMORY;
    }
    return APP_OK;
}

void app_project_free_all(app_project *p)
{
    if (!p)
        return;
    free(p->plan.corners);
    free(p->plan.openings);
    free(p->plan.prewalls);
    free(p->plan.niches);
    free(p->tilings);
    p->plan.corners = NULL;
    p->plan.openings = NULL;
    p->plan.prewalls = NULL;
    p->plan.niches = NULL;
    p->tilings = NULL;
    app_project_free(p);
}
