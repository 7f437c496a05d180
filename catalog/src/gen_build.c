/* The generator's builder: parts (one mesh and one material each), vertices and triangles,
 * the materials of parts, and the last step every product shares: scale to the catalog row's
 * exact bounding box with the origin at the bottom centre of the back face, then normals. */
#include "gen_internal.h"
#include "catalog/mesh_lod.h"
#include "model_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GREY3(x)                                                                                   \
    {                                                                                              \
        x, x, x                                                                                    \
    }

/* Fixed part materials, with the values of the catalog's own variants (make_catalog_csv.c). */
static const cat_render_material fixed[] = {
    [GEN_MAT_FINISH] = {GREY3(0.05f), GREY3(0.05f), GREY3(0.95f), GREY3(0), 2000, 0.8f, 0.9f,
                        CAT_BLEND_MIX, 0, 1.5f, CAT_PATTERN_NONE, 0},
    [GEN_MAT_CHROME] = {GREY3(0.05f), GREY3(0.05f), GREY3(0.95f), GREY3(0), 2000, 0.8f, 0.9f,
                        CAT_BLEND_MIX, 0, 1.5f, CAT_PATTERN_NONE, 0},
    [GEN_MAT_CERAMIC] = {{0.92f, 0.92f, 0.9f},
                         {0.92f, 0.92f, 0.9f},
                         GREY3(0.6f),
                         GREY3(0),
                         256,
                         0.1f,
                         0.6f,
                         CAT_BLEND_FRESNEL,
                         0,
                         1.5f,
                         CAT_PATTERN_NONE,
                         0},
    [GEN_MAT_GLASS] = {{0.9f, 0.95f, 0.93f},
                       {0.9f, 0.95f, 0.93f},
                       GREY3(0.9f),
                       GREY3(0),
                       1000,
                       0.1f,
                       1,
                       CAT_BLEND_FRESNEL,
                       0.9f,
                       1.5f,
                       CAT_PATTERN_NONE,
                       0},
    [GEN_MAT_MIRROR] = {GREY3(0.02f), GREY3(0.02f), GREY3(1), GREY3(0), 5000, 0.95f, 1,
                        CAT_BLEND_MIX, 0, 1.5f, CAT_PATTERN_NONE, 0},
    [GEN_MAT_LIGHT] = {GREY3(0.95f),
                       GREY3(0.95f),
                       GREY3(0.3f),
                       {4, 3.6f, 3},
                       64,
                       0,
                       0.5f,
                       CAT_BLEND_MIX,
                       0,
                       1.5f,
                       CAT_PATTERN_NONE,
                       0},
    [GEN_MAT_BLACK] = {GREY3(0.03f), GREY3(0.03f), GREY3(0.15f), GREY3(0), 40, 0.04f, 0.3f,
                       CAT_BLEND_FRESNEL, 0, 1.5f, CAT_PATTERN_NONE, 0},
    [GEN_MAT_STEEL] = {{0.35f, 0.35f, 0.36f},
                       {0.35f, 0.35f, 0.36f},
                       GREY3(0.6f),
                       GREY3(0),
                       300,
                       0.45f,
                       0.55f,
                       CAT_BLEND_MIX,
                       0,
                       1.5f,
                       CAT_PATTERN_NONE,
                       0},
    [GEN_MAT_WOOD] = {{0.55f, 0.4f, 0.26f},
                      {0.55f, 0.4f, 0.26f},
                      GREY3(0.15f),
                      GREY3(0),
                      30,
                      0.03f,
                      0.3f,
                      CAT_BLEND_FRESNEL,
                      0,
                      1.5f,
                      CAT_PATTERN_NONE,
                      0},
};

static int grow(void **p, int *cap, int need, size_t elem)
{
    if (need <= *cap)
        return 1;
    int n = *cap ? *cap : 64;
    while (n < need)
        n *= 2;
    void *q = realloc(*p, (size_t)n * elem);
    if (!q)
        return 0;
    *p = q;
    *cap = n;
    return 1;
}

int gen_part(gen_ctx *c, const char *name, gen_mat mat)
{
    gen_builder *b = c->b;
    if (b->failed)
        return -1;
    cat_gen_model *gm = b->gm;
    int i = gm->model.mesh_count;
    if (i >= b->part_cap) {
        int n = b->part_cap ? b->part_cap * 2 : 8;
        cat_mesh *meshes = realloc(gm->model.meshes, (size_t)n * sizeof *meshes);
        if (meshes)
            gm->model.meshes = meshes;
        cat_material *mats = realloc(gm->model.materials, (size_t)n * sizeof *mats);
        if (mats)
            gm->model.materials = mats;
        cat_material_extras *ex = realloc(gm->extras, (size_t)n * sizeof *ex);
        if (ex)
            gm->extras = ex;
        int *vcap = realloc(b->vcap, (size_t)n * sizeof *vcap);
        if (vcap)
            b->vcap = vcap;
        int *icap = realloc(b->icap, (size_t)n * sizeof *icap);
        if (icap)
            b->icap = icap;
        if (!meshes || !mats || !ex || !vcap || !icap) {
            b->failed = 1;
            return -1;
        }
        b->part_cap = n;
    }
    memset(&gm->model.meshes[i], 0, sizeof gm->model.meshes[i]);
    gm->model.meshes[i].material = i;
    const cat_render_material *r = mat == GEN_MAT_FINISH ? &c->finish : &fixed[mat];
    gm->extras[i].present = 1;
    gm->extras[i].variant_slot = mat == GEN_MAT_FINISH;
    gm->extras[i].params = *r;
    cat_material_from_render(r, name, &gm->model.materials[i]);
    b->vcap[i] = b->icap[i] = 0;
    gm->model.mesh_count = gm->model.material_count = i + 1;
    return i;
}

unsigned gen_vertex(gen_builder *b, int part, double x, double y, double z)
{
    if (b->failed || part < 0)
        return 0;
    cat_mesh *m = &b->gm->model.meshes[part];
    if (!grow((void **)&m->positions, &b->vcap[part], 3 * (m->vertex_count + 1), sizeof(float))) {
        b->failed = 1;
        return 0;
    }
    float *p = m->positions + 3 * (size_t)m->vertex_count;
    p[0] = (float)x;
    p[1] = (float)y;
    p[2] = (float)z;
    return (unsigned)m->vertex_count++;
}

void gen_triangle(gen_builder *b, int part, unsigned i0, unsigned i1, unsigned i2)
{
    if (b->failed || part < 0)
        return;
    cat_mesh *m = &b->gm->model.meshes[part];
    if (!grow((void **)&m->indices, &b->icap[part], m->index_count + 3, sizeof(unsigned))) {
        b->failed = 1;
        return;
    }
    m->indices[m->index_count++] = i0;
    m->indices[m->index_count++] = i1;
    m->indices[m->index_count++] = i2;
}

void cat_gen_model_free(cat_gen_model *m)
{
    if (!m)
        return;
    cat_model_free(&m->model);
    free(m->extras);
    memset(m, 0, sizeof *m);
}

int gen_has(const gen_ctx *c, const char *word)
{
    const char *s = c->req->name;
    size_t n = strlen(word);
    if (!s)
        return 0;
    for (; *s; s++) {
        size_t i = 0;
        while (i < n && s[i] &&
               (s[i] | 0x20) == (word[i] | 0x20)) /* ASCII letters; digits and '-' match too */
            i++;
        if (i == n)
            return 1;
    }
    return 0;
}

int gen_count(const gen_ctx *c)
{
    const char *s = c->req->name;
    for (; s && *s; s++) /* "2 doors", "3 drawers": the digit before " d" */
        if (*s >= '2' && *s <= '6' && s[1] == ' ' && s[2] == 'd')
            return *s - '0';
    return 1;
}

/* Series whose bodies are square-edged (make_catalog_csv.c's series names). */
static int square_series(const char *s)
{
    static const char *const names[] = {"Quadro", "Kubik", "Piano", "Plan", "Stone", "Nivo"};
    if (!s)
        return 0;
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(s, names[i]))
            return 1;
    return 0;
}

/* Scales every part so that the bounding box is exactly w x d x h with x centred, y and z from
 * 0, then computes smooth vertex normals per part. The generators build at about the final
 * size, so the scale factors are close to 1 and shapes keep their proportions. */
static int finish(cat_gen_model *gm, double w, double d, double h)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < gm->model.mesh_count; i++) {
        const cat_mesh *m = &gm->model.meshes[i];
        for (int v = 0; v < m->vertex_count; v++)
            for (int k = 0; k < 3; k++) {
                double x = m->positions[3 * v + k];
                lo[k] = x < lo[k] ? x : lo[k];
                hi[k] = x > hi[k] ? x : hi[k];
            }
    }
    double size[3] = {w, d, h}, s[3], t[3];
    for (int k = 0; k < 3; k++) {
        double ext = hi[k] - lo[k];
        if (!(ext > 1e-9))
            return 0;
        s[k] = size[k] / ext;
    }
    t[0] = -(lo[0] + hi[0]) / 2 * s[0];
    t[1] = -lo[1] * s[1];
    t[2] = -lo[2] * s[2];
    for (int i = 0; i < gm->model.mesh_count; i++) {
        cat_mesh *m = &gm->model.meshes[i];
        for (int v = 0; v < m->vertex_count; v++)
            for (int k = 0; k < 3; k++)
                m->positions[3 * v + k] = (float)(m->positions[3 * v + k] * s[k] + t[k]);
        m->normals = malloc((size_t)m->vertex_count * 3 * sizeof(float) + 1);
        if (!m->normals || !cat_normals_generate(m->positions, m->vertex_count, m->indices,
                                                 m->index_count, NULL, m->normals))
            return 0;
    }
    gm->model.bounds_min[0] = (float)(-w / 2);
    gm->model.bounds_max[0] = (float)(w / 2);
    gm->model.bounds_min[1] = gm->model.bounds_min[2] = 0;
    gm->model.bounds_max[1] = (float)d;
    gm->model.bounds_max[2] = (float)h;
    return 1;
}

/* The finish a category's parts default to when the row has no variant. */
static cat_render_material default_finish(cat_category cat)
{
    switch (cat) {
    case CAT_CATEGORY_BASINS:
    case CAT_CATEGORY_WCS_BIDETS:
    case CAT_CATEGORY_BATHS:
    case CAT_CATEGORY_SHOWER_TRAYS:
        return fixed[GEN_MAT_CERAMIC];
    case CAT_CATEGORY_SHOWER_SCREENS:
        return fixed[GEN_MAT_GLASS];
    case CAT_CATEGORY_MIRRORS:
    case CAT_CATEGORY_MIRROR_CABINETS:
        return fixed[GEN_MAT_MIRROR];
    case CAT_CATEGORY_LAMPS:
        return fixed[GEN_MAT_LIGHT];
    case CAT_CATEGORY_VANITY_UNITS:
        return fixed[GEN_MAT_WOOD];
    default:
        return fixed[GEN_MAT_CHROME];
    }
}

cat_result cat_gen_product(const cat_gen_request *req, cat_gen_model *out, char *err,
                           size_t err_size)
{
    cat_msg msg = {"model generator", err, err_size};
    if (!out)
        return cat_fail(&msg, CAT_ERR_INVALID, "no output model");
    memset(out, 0, sizeof *out);
    if (!req)
        return cat_fail(&msg, CAT_ERR_INVALID, "no request");
    if (req->name)
        msg.path = req->name;
    double dims[3] = {req->width_mm, req->depth_mm, req->height_mm};
    for (int k = 0; k < 3; k++)
        if (!(dims[k] >= 1 && dims[k] <= 20000))
            return cat_fail(&msg, CAT_ERR_INVALID,
                            "size %g x %g x %g mm: each must be in 1 .. 20000 mm", dims[0], dims[1],
                            dims[2]);
    void (*make)(gen_ctx *) = NULL;
    switch (req->category) {
    case CAT_CATEGORY_TAPS_MIXERS:
        make = gen_tap;
        break;
    case CAT_CATEGORY_SHOWER_SETS:
        make = gen_shower;
        break;
    case CAT_CATEGORY_BASINS:
        make = gen_basin;
        break;
    case CAT_CATEGORY_WCS_BIDETS:
        make = gen_wc;
        break;
    case CAT_CATEGORY_BATHS:
        make = gen_bath;
        break;
    case CAT_CATEGORY_SHOWER_TRAYS:
        make = gen_tray;
        break;
    case CAT_CATEGORY_SHOWER_SCREENS:
        make = gen_screen;
        break;
    case CAT_CATEGORY_MIRRORS:
        make = gen_mirror;
        break;
    case CAT_CATEGORY_MIRROR_CABINETS:
        make = gen_cabinet;
        break;
    case CAT_CATEGORY_LAMPS:
        make = gen_lamp;
        break;
    case CAT_CATEGORY_TOWEL_RADIATORS:
        make = gen_radiator;
        break;
    case CAT_CATEGORY_VANITY_UNITS:
        make = gen_vanity;
        break;
    case CAT_CATEGORY_ACCESSORIES:
        make = gen_accessory;
        break;
    default:
        break;
    }
    if (!make)
        return cat_fail(&msg, CAT_ERR_UNSUPPORTED, "no model generator for category \"%s\"",
                        cat_category_name(req->category));
    gen_builder b = {out, NULL, NULL, 0, 0, ""};
    gen_ctx c = {&b, req, default_finish(req->category), square_series(req->series)};
    if (req->finish)
        c.finish = *req->finish;
    make(&c);
    int ok = !b.failed && out->model.mesh_count > 0;
    if (ok)
        for (int i = 0; i < out->model.mesh_count; i++)
            if (out->model.meshes[i].index_count == 0)
                ok = 0;
    if (ok)
        ok = finish(out, dims[0], dims[1], dims[2]);
    /* Lathe poles, closed sweeps and subdivided rims leave zero-area triangles (85 426 of
     * them over the shipped models before this): they draw nothing but cost vertex work in
     * every pass and trip decimators, so they are dropped here (docs/catalog.md). */
    if (ok &&
        cat_model_validate(&out->model, req->name, 1, NULL, b.error, sizeof b.error) != CAT_OK)
        ok = 0;
    for (int i = 0; ok && i < out->model.mesh_count; i++)
        if (out->model.meshes[i].index_count == 0)
            ok = 0;
    free(b.vcap);
    free(b.icap);
    if (!ok) {
        cat_gen_model_free(out);
        if (b.error[0])
            return cat_fail(&msg, CAT_ERR_INVALID, "%s", b.error);
        return cat_fail(&msg, b.failed ? CAT_ERR_OUT_OF_MEMORY : CAT_ERR_INVALID,
                        b.failed ? "out of memory" : "the generator made an empty part");
    }
    return CAT_OK;
}
