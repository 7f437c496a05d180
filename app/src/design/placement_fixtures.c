/* Fixture footprints from the objects of a project: catalog products from their catalog box
 * (origin at the bottom centre of the back face, placement.h), primitives from their size,
 * scale and rotation, parts of one group merged into one fixture. */
#include "placement_internal.h"

#include "catalog/catalog.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static app_fixture_role role_of_category(int category)
{
    switch (category) {
    case CAT_CATEGORY_TAPS_MIXERS:
    case CAT_CATEGORY_SHOWER_SETS:
    case CAT_CATEGORY_ACCESSORIES:
    case CAT_CATEGORY_LAMPS:
        return APP_ROLE_ATTACHMENT;
    default:
        return APP_ROLE_FIXTURE;
    }
}

/* The 8 corners of a primitive's box in world coordinates (R = Rz*Ry*Rx, project.h). */
static void primitive_corners(const app_object *o, double out[8][3])
{
    double s[3];
    for (int k = 0; k < 3; k++)
        s[k] = o->size_mm[k] * (o->scale[k] != 0 ? fabs(o->scale[k]) : 1.0);
    if (o->shape == APP_SHAPE_PLANE)
        s[2] = 0; /* a sheet: its size z is unused (app/project/project.h) */
    double rx = o->rotation_deg[0] * M_PI / 180, ry = o->rotation_deg[1] * M_PI / 180,
           rz = o->rotation_deg[2] * M_PI / 180;
    double cx = cos(rx), sx = sin(rx), cy = cos(ry), sy = sin(ry), cz = cos(rz), sz = sin(rz);
    /* Rz * Ry * Rx */
    double m[3][3] = {{cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx},
                      {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx},
                      {-sy, cy * sx, cy * cx}};
    for (int i = 0; i < 8; i++) {
        double l[3] = {(i & 1 ? 0.5 : -0.5) * s[0], (i & 2 ? 0.5 : -0.5) * s[1],
                       (i & 4 ? 0.5 : -0.5) * s[2]};
        for (int r = 0; r < 3; r++)
            out[i][r] = o->position_mm[r] + m[r][0] * l[0] + m[r][1] * l[1] + m[r][2] * l[2];
    }
}

/* Extends the fixture f (frame angle f->angle_deg, bounds in *b: xmin,xmax,ymin,ymax in that
 * frame, zmin, zmax) by the corners of a primitive. */
static void extend_bounds(double angle_deg, const double corners[8][3], double b[6])
{
    double a = angle_deg * M_PI / 180, ca = cos(a), sa = sin(a);
    for (int i = 0; i < 8; i++) {
        double u = corners[i][0] * ca + corners[i][1] * sa;
        double v = -corners[i][0] * sa + corners[i][1] * ca;
        b[0] = fmin(b[0], u);
        b[1] = fmax(b[1], u);
        b[2] = fmin(b[2], v);
        b[3] = fmax(b[3], v);
        b[4] = fmin(b[4], corners[i][2]);
        b[5] = fmax(b[5], corners[i][2]);
    }
}

static void fixture_from_bounds(app_fixture *f, const double b[6])
{
    double a = f->angle_deg * M_PI / 180, ca = cos(a), sa = sin(a);
    double u = 0.5 * (b[0] + b[1]), v = 0.5 * (b[2] + b[3]);
    f->centre[0] = u * ca - v * sa;
    f->centre[1] = u * sa + v * ca;
    f->half[0] = 0.5 * (b[1] - b[0]);
    f->half[1] = 0.5 * (b[3] - b[2]);
    f->z0 = b[4];
    f->z1 = b[5];
}

/* Products already looked up in this call: rooms repeat products (a row of basins), and a
 * catalog lookup costs a query. */
typedef struct product_cache {
    app_product_ref ref;
    double w, d, h;
    int category;
} product_cache;

static app_result product_fixture(const app_object *o, int index, app_product_lookup lookup,
                                  void *user, product_cache *cache, int *cached, app_fixture *f,
                                  char *err, size_t err_size)
{
    app_product_info info;
    memset(&info, 0, sizeof info);
    char msg[512] = "";
    app_result r = APP_ERR_NOT_FOUND;
    for (int k = 0; k < *cached; k++) {
        const app_product_ref *c = &cache[k].ref;
        if (!strcmp(c->manufacturer, o->product.manufacturer) &&
            !strcmp(c->article, o->product.article) && !strcmp(c->variant, o->product.variant)) {
            info.width_mm = cache[k].w;
            info.depth_mm = cache[k].d;
            info.height_mm = cache[k].h;
            info.category = cache[k].category;
            r = APP_OK;
            break;
        }
    }
    if (r != APP_OK) {
        r = lookup ? lookup(user, &o->product, &info, msg, sizeof msg) : APP_ERR_NOT_FOUND;
        if (r == APP_OK) {
            product_cache *c = &cache[(*cached)++];
            c->ref = o->product;
            c->w = info.width_mm;
            c->d = info.depth_mm;
            c->h = info.height_mm;
            c->category = info.category;
        }
    }
    if (r != APP_OK) {
        if (err && err_size)
            snprintf(err, err_size, "object \"%s\": product %s %s: %s", o->name,
                     o->product.manufacturer, o->product.article,
                     msg[0] ? msg : "no catalog to look it up in");
        return r;
    }
    double sx = o->scale[0] != 0 ? fabs(o->scale[0]) : 1,
           sy = o->scale[1] != 0 ? fabs(o->scale[1]) : 1,
           sz = o->scale[2] != 0 ? fabs(o->scale[2]) : 1;
    double w = info.width_mm * sx, d = info.depth_mm * sy, h = info.height_mm * sz;
    double a = o->rotation_deg[2] * M_PI / 180;
    memset(f, 0, sizeof *f);
    f->object = index;
    snprintf(f->name, sizeof f->name, "%s", o->name);
    f->category = info.category;
    f->has_product = 1;
    f->role = role_of_category(info.category);
    f->angle_deg = o->rotation_deg[2];
    /* The origin is the back face's bottom centre; the box reaches depth d along local +y. */
    f->centre[0] = o->position_mm[0] - sin(a) * 0.5 * d;
    f->centre[1] = o->position_mm[1] + cos(a) * 0.5 * d;
    f->half[0] = 0.5 * w;
    f->half[1] = 0.5 * d;
    f->z0 = o->position_mm[2];
    f->z1 = o->position_mm[2] + h;
    f->width_mm = w;
    f->depth_mm = d;
    return APP_OK;
}

app_result app_placement_fixtures(const app_project *p, app_product_lookup lookup, void *user,
                                  app_fixture **out, int *count, char *err, size_t err_size)
{
    *out = NULL;
    *count = 0;
    int n = p->object_count > 0 ? p->object_count : 0;
    app_fixture *fx = calloc((size_t)(n ? n : 1), sizeof *fx);
    double(*bounds)[6] = calloc((size_t)(n ? n : 1), sizeof *bounds);
    product_cache *cache = calloc((size_t)(n ? n : 1), sizeof *cache);
    int cached = 0;
    if (!fx || !bounds || !cache) {
        free(fx);
        free(bounds);
        free(cache);
        if (err && err_size)
            snprintf(err, err_size, "out of memory for %d fixtures", n);
        return APP_ERR_OUT_OF_MEMORY;
    }
    int m = 0;
    for (int i = 0; i < n; i++) {
        const app_object *o = &p->objects[i];
        if (o->has_product) {
            app_result r =
                product_fixture(o, i, lookup, user, cache, &cached, &fx[m], err, err_size);
            if (r != APP_OK) {
                free(fx);
                free(bounds);
                free(cache);
                return r;
            }
            if (fx[m].category != CAT_CATEGORY_TILES)
                m++;
            continue;
        }
        if (o->shape == APP_SHAPE_MODEL)
            continue; /* a model's size is in its file, not known here */
        double corners[8][3];
        primitive_corners(o, corners);
        int into = -1;
        if (o->group[0]) {
            for (int k = 0; k < m; k++)
                if (fx[k].category == 0 && fx[k].object >= 0 &&
                    !p->objects[fx[k].object].has_product &&
                    !strcmp(p->objects[fx[k].object].group, o->group))
                    into = k;
        }
        if (into < 0) {
            into = m++;
            memset(&fx[into], 0, sizeof fx[into]);
            fx[into].object = i;
            snprintf(fx[into].name, sizeof fx[into].name, "%s", o->group[0] ? o->group : o->name);
            fx[into].angle_deg = o->rotation_deg[2];
            fx[into].role = APP_ROLE_FIXTURE;
            bounds[into][0] = bounds[into][2] = bounds[into][4] = INFINITY;
            bounds[into][1] = bounds[into][3] = bounds[into][5] = -INFINITY;
        }
        extend_bounds(fx[into].angle_deg, corners, bounds[into]);
        fixture_from_bounds(&fx[into], bounds[into]);
    }
    free(bounds);
    free(cache);
    *out = fx;
    *count = m;
    return APP_OK;
}
