/* $.cameras: named viewpoints; a project has at least one. */
#include "project_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const pj_range FOV = {1.0, 179.0, 1, 1, 1};

/* Unit vector of v scaled first, so huge or tiny finite vectors do not overflow; 0 if zero. */
static int unit(const double v[3], double out[3])
{
    double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (m == 0)
        return 0;
    double x = v[0] / m, y = v[1] / m, z = v[2] / m;
    double len = sqrt(x * x + y * y + z * z);
    out[0] = x / len;
    out[1] = y / len;
    out[2] = z / len;
    return 1;
}

static app_result check_view(pj_ctx *c, app_camera *cam)
{
    double dir[3] = {cam->target_mm[0] - cam->position_mm[0],
                     cam->target_mm[1] - cam->position_mm[1],
                     cam->target_mm[2] - cam->position_mm[2]};
    double d[3], u[3];
    if (!isfinite(dir[0]) || !isfinite(dir[1]) || !isfinite(dir[2]) || !unit(dir, d)) {
        pj_path_key(c, "target");
        return pj_fail(c, APP_ERR_SCHEMA,
                       "must differ from position (and be a finite distance away)");
    }
    if (!unit(cam->up, u)) {
        pj_path_key(c, "up");
        return pj_fail(c, APP_ERR_SCHEMA, "must not be the zero vector");
    }
    double cx = d[1] * u[2] - d[2] * u[1];
    double cy = d[2] * u[0] - d[0] * u[2];
    double cz = d[0] * u[1] - d[1] * u[0];
    if (sqrt(cx * cx + cy * cy + cz * cz) < 1e-6) {
        pj_path_key(c, "up");
        return pj_fail(c, APP_ERR_SCHEMA, "must not be parallel to the viewing direction");
    }
    return APP_OK;
}

static app_result read_camera(pj_ctx *c, const cJSON *item, int index, app_camera *cam)
{
    if (!cJSON_IsObject(item))
        return pj_fail(c, APP_ERR_SCHEMA, "expected an object, got %s", pj_type_name(item));
    pj_default_camera(cam);
    snprintf(cam->name, sizeof cam->name, "camera-%d", index);
    app_result r;
    if ((r = pj_get_string(c, item, "name", 0, 0, cam->name, sizeof cam->name)) != APP_OK ||
        (r = pj_get_vec(c, item, "position", 1, 3, PJ_ANY, cam->position_mm)) != APP_OK ||
        (r = pj_get_vec(c, item, "target", 1, 3, PJ_ANY, cam->target_mm)) != APP_OK ||
        (r = pj_get_vec(c, item, "up", 0, 3, PJ_ANY, cam->up)) != APP_OK ||
        (r = pj_get_number(c, item, "fov", 0, FOV, &cam->fov_deg)) != APP_OK)
        return r;
    return check_view(c, cam);
}

typedef struct named {
    const char *name;
    int index;
} named;

static int compare_named(const void *a, const void *b)
{
    const named *x = a, *y = b;
    int k = strcmp(x->name, y->name);
    return k ? k : (x->index > y->index) - (x->index < y->index);
}

/* Names pick a camera on the command line, so they must be unique. Sorting keeps this
 * O(n log n) for hostile files with 100 000 cameras. */
static app_result check_unique_names(pj_ctx *c, const app_camera *cams, int count)
{
    named *v = pj_malloc((size_t)count * sizeof *v);
    if (!v)
        return pj_fail(c, APP_ERR_OUT_OF_MEMORY, "out of memory");
    for (int i = 0; i < count; i++)
        v[i] = (named){cams[i].name, i};
    qsort(v, (size_t)count, sizeof *v, compare_named);
    int dup = -1, first = -1;
    for (int i = 1; i < count; i++) {
        if (strcmp(v[i].name, v[i - 1].name) == 0 && (dup < 0 || v[i].index < dup)) {
            dup = v[i].index;
            first = v[i - 1].index;
        }
    }
    free(v);
    if (dup < 0)
        return APP_OK;
    pj_path_index(c, dup);
    pj_path_key(c, "name");
    return pj_fail(c, APP_ERR_SCHEMA, "duplicate camera name \"%s\" (also $.cameras[%d])",
                   cams[dup].name, first);
}

app_result pj_read_cameras(pj_ctx *c, const cJSON *root)
{
    const cJSON *list;
    app_result r = pj_member(c, root, "cameras", cJSON_Array, 1, &list);
    if (r != APP_OK)
        return r;
    size_t mark = pj_path_key(c, "cameras");
    int count;
    if ((r = pj_check_count(c, list, "cameras", &count)) != APP_OK)
        return r;
    if (count == 0)
        return pj_fail(c, APP_ERR_SCHEMA, "at least one camera is required");
    app_project *p = c->p;
    p->cameras = pj_calloc((size_t)count, sizeof *p->cameras);
    if (!p->cameras)
        return pj_fail(c, APP_ERR_OUT_OF_MEMORY, "out of memory (%d cameras)", count);
    int i = 0;
    for (const cJSON *item = list->child; item; item = item->next, i++) {
        size_t c_mark = pj_path_index(c, i);
        if ((r = read_camera(c, item, i, &p->cameras[i])) != APP_OK)
            return r;
        p->camera_count = i + 1;
        pj_path_restore(c, c_mark);
    }
    if ((r = check_unique_names(c, p->cameras, count)) != APP_OK)
        return r;
    pj_path_restore(c, mark);
    return APP_OK;
}
