/* The project's objects as fixtures: objects sharing a group name are one fixture (the parts of
 * a WC, a basin with its bowl), an object alone is its own. A catalog product gives the label
 * (its article number) and, when it has a model, the geometry (catalog/model.h); otherwise the
 * object's primitive is sampled (box corners, rings of a cylinder, a sphere's latitude rings).
 * Drawings take outlines from these points: the convex hull of each part, projected on the
 * plan (top-down) or on a wall (elevation). */
#include "print_internal.h"
#include "scene/scene_build_internal.h"

#include "catalog/model_gen.h"
#include "catalog/model.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int cmp_point(const void *a, const void *b)
{
    const app_point2 *p = a, *q = b;
    if (p->x != q->x)
        return p->x < q->x ? -1 : 1;
    if (p->y != q->y)
        return p->y < q->y ? -1 : 1;
    return 0;
}

static double cross(app_point2 o, app_point2 a, app_point2 b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/* Andrew's monotone chain; out needs room for n + 1 points. */
int pr_convex_hull(const app_point2 *pts, int n, app_point2 *out)
{
    if (n <= 0)
        return 0;
    app_point2 *s = malloc((size_t)n * sizeof *s);
    if (!s)
        return 0;
    memcpy(s, pts, (size_t)n * sizeof *s);
    qsort(s, (size_t)n, sizeof *s, cmp_point);
    int k = 0;
    for (int i = 0; i < n; i++) {
        while (k >= 2 && cross(out[k - 2], out[k - 1], s[i]) <= 0)
            k--;
        out[k++] = s[i];
    }
    for (int i = n - 2, t = k + 1; i >= 0; i--) {
        while (k >= t && cross(out[k - 2], out[k - 1], s[i]) <= 0)
            k--;
        out[k++] = s[i];
    }
    free(s);
    return k > 1 ? k - 1 : k;
}

/* Unit-shape sample points in [-0.5, 0.5]^3 (the renderer's primitives). */
static int unit_samples(app_shape shape, double (*out)[3], int cap)
{
    int n = 0;
    const int seg = 32;
    switch (shape) {
    case APP_SHAPE_BOX:
        for (int i = 0; i < 8 && n < cap; i++, n++) {
            out[n][0] = (i & 1) ? 0.5 : -0.5;
            out[n][1] = (i & 2) ? 0.5 : -0.5;
            out[n][2] = (i & 4) ? 0.5 : -0.5;
        }
        break;
    case APP_SHAPE_PLANE:
        for (int i = 0; i < 4 && n < cap; i++, n++) {
            out[n][0] = (i & 1) ? 0.5 : -0.5;
            out[n][1] = (i & 2) ? 0.5 : -0.5;
            out[n][2] = 0.0;
        }
        break;
    case APP_SHAPE_CYLINDER:
    case APP_SHAPE_TORUS:
        for (int r = 0; r < 2; r++)
            for (int i = 0; i < seg && n < cap; i++, n++) {
                double a = 2 * PR_PI * i / seg;
                out[n][0] = 0.5 * cos(a);
                out[n][1] = 0.5 * sin(a);
                out[n][2] = r ? 0.5 : -0.5;
            }
        break;
    case APP_SHAPE_SPHERE:
        for (int r = 0; r <= 8; r++) {
            double phi = PR_PI * r / 8 - PR_PI / 2, rr = 0.5 * cos(phi), z = 0.5 * sin(phi);
            for (int i = 0; i < seg && n < cap; i++, n++) {
                double a = 2 * PR_PI * i / seg;
                out[n][0] = rr * cos(a);
                out[n][1] = rr * sin(a);
                out[n][2] = z;
            }
        }
        break;
    default:
        break;
    }
    return n;
}

static void apply(const float m[16], const double in[3], double out[3])
{
    for (int r = 0; r < 3; r++)
        out[r] = (m[r] * in[0] + m[4 + r] * in[1] + m[8 + r] * in[2] + m[12 + r]) * 1000.0;
}

static app_result add_part(pr_fixture *f, int count, pr_part **part)
{
    pr_part *parts = realloc(f->parts, (size_t)(f->part_count + 1) * sizeof *parts);
    if (!parts)
        return APP_ERR_OUT_OF_MEMORY;
    f->parts = parts;
    pr_part *pp = &parts[f->part_count];
    pp->count = count;
    pp->pts = malloc((size_t)(count > 0 ? count : 1) * sizeof *pp->pts);
    if (!pp->pts)
        return APP_ERR_OUT_OF_MEMORY;
    f->part_count++;
    *part = pp;
    return APP_OK;
}

/* A model's meshes as parts, placed by the object's transform. */
static app_result add_model_parts(pr_doc *d, pr_fixture *f, const app_object *o, const char *path)
{
    cat_model model = {0};
    char cerr[768];
    if (cat_model_load(path, &model, cerr, sizeof cerr) != CAT_OK) {
        if (d->o->verbose)
            fprintf(stderr, "tessera print: %s: %s (drawn as its box)\n", o->name, cerr);
        return APP_ERR_NOT_FOUND;
    }
    const double mm_to_m[3] = {1e-3, 1e-3, 1e-3};
    float m[16];
    app_object_transform(o, mm_to_m, m);
    app_result r = APP_OK;
    for (int i = 0; r == APP_OK && i < model.mesh_count; i++) {
        const cat_mesh *cm = &model.meshes[i];
        pr_part *part;
        r = add_part(f, cm->vertex_count, &part);
        for (int v = 0; r == APP_OK && v < cm->vertex_count; v++) {
            double in[3] = {cm->positions[3 * v], cm->positions[3 * v + 1],
                            cm->positions[3 * v + 2]};
            apply(m, in, part->pts[v]);
        }
    }
    cat_model_free(&model);
    return r;
}

static app_result add_object_parts(pr_doc *d, pr_fixture *f, const app_object *o)
{
    if (o->shape == APP_SHAPE_MODEL && o->model[0] && add_model_parts(d, f, o, o->model) == APP_OK)
        return APP_OK;
    char path[4096];
    /* Generated models live in the build (or $TESSERA_MODELS): cat_model_resolve finds them. */
    if (f->found && f->product.model[0] &&
        cat_model_resolve(f->product.model, d->o->assets_dir, path, sizeof path) &&
        add_model_parts(d, f, o, path) == APP_OK)
        return APP_OK;
    double size_m[3];
    app_shape shape = o->shape;
    int product_box = 0;
    if (o->has_product && f->found) {
        /* No model: the catalog's bounding box in the product frame (app/design/placement.h: origin
         * at the bottom centre of the back face, depth along +y, height along +z). */
        shape = APP_SHAPE_BOX;
        product_box = 1;
        size_m[0] = f->product.width_mm * 1e-3;
        size_m[1] = f->product.depth_mm * 1e-3;
        size_m[2] = f->product.height_mm * 1e-3;
    } else {
        for (int k = 0; k < 3; k++)
            size_m[k] = o->size_mm[k] * 1e-3;
    }
    if (shape == APP_SHAPE_MODEL)
        return APP_OK; /* a model that could not be read and has no box: nothing to draw */
    double unit[300][3];
    int n = unit_samples(shape, unit, 300);
    for (int i = 0; product_box && i < n; i++) {
        unit[i][1] += 0.5;
        unit[i][2] += 0.5;
    }
    float m[16];
    app_object_transform(o, size_m, m);
    pr_part *part;
    app_result r = add_part(f, n, &part);
    for (int i = 0; r == APP_OK && i < n; i++)
        apply(m, unit[i], part->pts[i]);
    return r;
}

static pr_fixture *fixture_for(pr_doc *d, int index)
{
    const app_object *o = &d->p->objects[index];
    if (o->group[0])
        for (int i = 0; i < d->fixture_count; i++)
            if (!strcmp(d->fixtures[i].name, o->group))
                return &d->fixtures[i];
    return NULL;
}

app_result pr_fixtures_collect(pr_doc *d)
{
    const app_project *p = d->p;
    d->fixtures = calloc((size_t)(p->object_count > 0 ? p->object_count : 1), sizeof *d->fixtures);
    if (!d->fixtures)
        return APP_ERR_OUT_OF_MEMORY;
    for (int i = 0; i < p->object_count; i++) {
        const app_object *o = &p->objects[i];
        pr_fixture *f = fixture_for(d, i);
        if (!f) {
            f = &d->fixtures[d->fixture_count++];
            snprintf(f->name, sizeof f->name, "%s", o->group[0] ? o->group : o->name);
            snprintf(f->label, sizeof f->label, "%s", f->name);
            f->first_object = i;
            for (int k = 0; k < 3; k++) {
                f->min[k] = 1e300;
                f->max[k] = -1e300;
            }
        }
        if (o->has_product && !f->has_product) {
            f->has_product = 1;
            f->ref = o->product;
            snprintf(f->label, sizeof f->label, "%s", o->product.article);
            if (d->db) {
                char cerr[512];
                f->found = cat_product_find(d->db, o->product.manufacturer, o->product.article,
                                            &f->product, cerr, sizeof cerr) == CAT_DB_OK;
                if (!f->found && d->o->verbose)
                    fprintf(stderr, "tessera print: %s: %s\n", o->name, cerr);
            }
        }
        int before = f->part_count;
        app_result r = add_object_parts(d, f, o);
        if (r != APP_OK) {
            snprintf(d->err, d->err_size, "%s: $.objects[%d]: out of memory", p->path, i);
            return r;
        }
        for (int q = before; q < f->part_count; q++)
            for (int v = 0; v < f->parts[q].count; v++)
                for (int k = 0; k < 3; k++) {
                    double x = f->parts[q].pts[v][k];
                    f->min[k] = x < f->min[k] ? x : f->min[k];
                    f->max[k] = x > f->max[k] ? x : f->max[k];
                }
    }
    return APP_OK;
}

void pr_fixtures_free(pr_doc *d)
{
    for (int i = 0; i < d->fixture_count; i++) {
        for (int q = 0; q < d->fixtures[i].part_count; q++)
            free(d->fixtures[i].parts[q].pts);
        free(d->fixtures[i].parts);
        cat_product_free(&d->fixtures[i].product);
    }
    free(d->fixtures);
    d->fixtures = NULL;
    d->fixture_count = 0;
}
