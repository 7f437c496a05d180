/* The GLB writer and the procedural generators: write a model, load it back with the real
 * loader (cat_model_load) and compare everything: vertex and index counts, positions, normals,
 * uvs, materials and the Tessera extras; the writer's errors; and the generator's invariants for
 * every category (exact bounding box, origin at the bottom centre of the back face, normals,
 * one material per part). */
#include "test_util.h" /* first: it sets _XOPEN_SOURCE */
#include "catalog/model_gen.h"
#include "catalog/model_write.h"

#include <dirent.h>

static int open_edges(const cat_mesh *m, double *volume);

static int same_extras(const cat_material_extras *a, const cat_material_extras *b)
{
    const cat_render_material *x = &a->params, *y = &b->params;
    int ok = a->present == b->present && a->variant_slot == b->variant_slot;
    for (int k = 0; k < 3; k++)
        ok &= fabsf(x->ambient[k] - y->ambient[k]) < 1e-6f &&
              fabsf(x->diffuse[k] - y->diffuse[k]) < 1e-6f &&
              fabsf(x->specular[k] - y->specular[k]) < 1e-6f &&
              fabsf(x->emissive[k] - y->emissive[k]) < 1e-6f;
    return ok && x->shininess == y->shininess && x->reflectivity == y->reflectivity &&
           x->glossiness == y->glossiness && x->blend == y->blend &&
           x->transparency == y->transparency && x->ior == y->ior;
}

/* A hand-made two-part model: one part with uvs and a plain glTF material (no extras), one with
 * Tessera extras and a transparent, emissive material. */
static void hand_made(void)
{
    float pos0[] = {0, 0, 0, 100, 0, 0, 0, 200, 50};
    float nrm0[] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    float uv0[] = {0, 0, 1, 0, 0, 1};
    unsigned idx0[] = {0, 1, 2};
    float pos1[] = {-10, -20, -30, 10, -20, -30, 10, 20, -30, -10, 20, -30};
    float nrm1[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    unsigned idx1[] = {0, 1, 2, 0, 2, 3};
    cat_mesh meshes[2] = {{pos0, nrm0, uv0, idx0, 3, 3, 0}, {pos1, nrm1, NULL, idx1, 4, 6, 1}};
    cat_material mats[2];
    memset(mats, 0, sizeof mats);
    snprintf(mats[0].name, sizeof mats[0].name, "plain");
    mats[0].base_color[0] = 0.5f, mats[0].base_color[1] = 0.25f, mats[0].base_color[2] = 1;
    mats[0].base_color[3] = 1;
    mats[0].metallic = 0.25f, mats[0].roughness = 0.75f;
    cat_render_material glass = {{0.1f, 0.2f, 0.3f},
                                 {0.4f, 0.5f, 0.6f},
                                 {0.7f, 0.8f, 0.9f},
                                 {4, 3.5f, 3},
                                 77,
                                 0.33f,
                                 0.66f,
                                 CAT_BLEND_FRESNEL,
                                 0.9f,
                                 1.52f,
                                 CAT_PATTERN_NONE,
                                 0};
    cat_material_from_render(&glass, "glass", &mats[1]);
    CHECK_NEAR(mats[1].base_color[3], 0.1, 1e-6); /* alpha = 1 - transparency */
    CHECK_NEAR(mats[1].emissive[0], 1, 1e-6);     /* divided by the largest, 4 */
    CHECK_NEAR(mats[1].emissive[2], 0.75, 1e-6);
    CHECK_NEAR(mats[1].roughness, 0.34, 1e-6);
    cat_model m = {meshes, 2, mats, 2, {-10, -20, -30}, {100, 200, 50}};
    cat_material_extras ex[2];
    memset(ex, 0, sizeof ex);
    ex[1].present = ex[1].variant_slot = 1;
    ex[1].params = glass;
    char err[2048];
    const char *path = tmp_path("hand.glb");
    CHECK(cat_model_write_glb(path, &m, ex, err, sizeof err) == CAT_OK);
    cat_model back;
    cat_result r = cat_model_load(path, &back, err, sizeof err);
    CHECK(r == CAT_OK);
    if (r != CAT_OK) {
        fprintf(stderr, "%s\n", err);
        return;
    }
    CHECK(!model_broken(&back));
    CHECK(back.mesh_count == 2 && back.material_count == 2);
    for (int i = 0; i < 2 && back.mesh_count == 2; i++) {
        const cat_mesh *a = &meshes[i], *b = &back.meshes[i];
        CHECK(a->vertex_count == b->vertex_count && a->index_count == b->index_count);
        CHECK(b->material == i);
        if (a->vertex_count != b->vertex_count || a->index_count != b->index_count)
            continue;
        for (int k = 0; k < 3 * a->vertex_count; k++) {
            CHECK_NEAR(a->positions[k], b->positions[k], 1e-3);
            CHECK_NEAR(a->normals[k], b->normals[k], 1e-6);
        }
        for (int k = 0; k < a->index_count; k++)
            CHECK(a->indices[k] == b->indices[k]);
        CHECK((a->uvs == NULL) == (b->uvs == NULL));
        for (int k = 0; a->uvs && b->uvs && k < 2 * a->vertex_count; k++)
            CHECK(a->uvs[k] == b->uvs[k]);
    }
    for (int i = 0; i < 2 && back.material_count == 2; i++) {
        CHECK(!strcmp(mats[i].name, back.materials[i].name));
        for (int k = 0; k < 4; k++)
            CHECK_NEAR(mats[i].base_color[k], back.materials[i].base_color[k], 1e-6);
        for (int k = 0; k < 3; k++)
            CHECK_NEAR(mats[i].emissive[k], back.materials[i].emissive[k], 1e-6);
        CHECK_NEAR(mats[i].metallic, back.materials[i].metallic, 1e-6);
        CHECK_NEAR(mats[i].roughness, back.materials[i].roughness, 1e-6);
    }
    for (int k = 0; k < 3; k++) {
        CHECK_NEAR(back.bounds_min[k], m.bounds_min[k], 1e-3);
        CHECK_NEAR(back.bounds_max[k], m.bounds_max[k], 1e-3);
    }
    cat_material_extras got[4];
    int n = -1;
    CHECK(cat_model_read_extras(path, got, 4, &n, err, sizeof err) == CAT_OK);
    CHECK(n == 2);
    CHECK(n == 2 && got[0].present == 0);
    CHECK(n == 2 && same_extras(&got[1], &ex[1]));
    cat_model_free(&back);
    double vol;
    CHECK(open_edges(&meshes[1], &vol) == 4); /* the closedness check sees an open quad */

    /* Reading extras refuses what the loader refuses, before tinygltf sees it: a missing file,
     * an empty one, JSON nested 100 000 deep (a stack overflow in a recursive parser), junk. */
    char *deep = malloc(200001);
    if (deep) {
        memset(deep, '[', 100000);
        memset(deep + 100000, ']', 100000);
        deep[200000] = 0;
        const char *bad_files[] = {tmp_path("missing.glb"), write_text("empty.gltf", ""),
                                   write_text("deep.gltf", deep),
                                   write_text("junk.glb", "glTF\2\0\0 not a container")};
        for (int i = 0; i < 4; i++) {
            int count = 7;
            err[0] = 0;
            CHECK(cat_model_read_extras(bad_files[i], got, 4, &count, err, sizeof err) != CAT_OK);
            CHECK(count == 0);
            CHECK(strncmp(err, bad_files[i], strlen(bad_files[i])) == 0);
        }
        free(deep);
    }

    /* Errors: a missing folder (and no temporary file left anywhere), a bad index. */
    const char *nowhere = tmp_path("no/such/folder/x.glb");
    CHECK(cat_model_write_glb(nowhere, &m, ex, err, sizeof err) == CAT_ERR_IO);
    CHECK(strncmp(err, nowhere, strlen(nowhere)) == 0);
    idx1[5] = 4;
    const char *bad = tmp_path("bad.glb");
    CHECK(cat_model_write_glb(bad, &m, NULL, err, sizeof err) == CAT_ERR_INVALID);
    CHECK(strstr(err, "out of range") != NULL);
    CHECK(access(bad, F_OK) != 0);
    idx1[5] = 3;
    meshes[1].material = 7;
    CHECK(cat_model_write_glb(bad, &m, NULL, err, sizeof err) == CAT_ERR_INVALID);
    m.mesh_count = 0;
    CHECK(cat_model_write_glb(bad, &m, NULL, err, sizeof err) == CAT_ERR_INVALID);
}

typedef struct sample {
    cat_category category;
    const char *name, *series;
    double w, d, h;
} sample;

/* One request per product shape the generators tell apart (make_catalog_csv.c's types). */
static const sample samples[] = {
    {CAT_CATEGORY_TAPS_MIXERS, "Linea single-lever basin mixer 100", "Linea", 50, 135, 165},
    {CAT_CATEGORY_TAPS_MIXERS, "Quadro basin tap for cold water", "Quadro", 45, 110, 150},
    {CAT_CATEGORY_TAPS_MIXERS, "Orbis wall-mounted basin mixer, spout 195", "Orbis", 180, 195, 70},
    {CAT_CATEGORY_TAPS_MIXERS, "Kubik three-hole basin mixer", "Kubik", 160, 155, 95},
    {CAT_CATEGORY_TAPS_MIXERS, "Orbis thermostatic bath mixer, exposed", "Orbis", 300, 195, 110},
    {CAT_CATEGORY_TAPS_MIXERS, "Alster floor-standing bath mixer", "Alster", 220, 260, 900},
    {CAT_CATEGORY_TAPS_MIXERS, "Merano concealed thermostat trim, 2 valves", "Merano", 160, 75,
     160},
    {CAT_CATEGORY_SHOWER_SETS, "Linea shower rail set 900", "Linea", 120, 140, 950},
    {CAT_CATEGORY_SHOWER_SETS, "Kubik thermostatic shower system 300 square", "Kubik", 300, 480,
     1180},
    {CAT_CATEGORY_SHOWER_SETS, "Solano overhead shower 300 with wall arm 390", "Solano", 300, 410,
     60},
    {CAT_CATEGORY_SHOWER_SETS, "Quadro hand shower 120, 3 sprays", "Quadro", 120, 60, 270},
    {CAT_CATEGORY_BASINS, "Arco washbasin 600 x 480", "Arco", 600, 480, 165},
    {CAT_CATEGORY_BASINS, "Vela countertop bowl 420 round", "Vela", 420, 420, 140},
    {CAT_CATEGORY_BASINS, "Fjord double washbasin 1200 x 550", "Fjord", 1200, 550, 175},
    {CAT_CATEGORY_WCS_BIDETS, "Arco wall-hung WC, rimless", "Arco", 360, 530, 340},
    {CAT_CATEGORY_WCS_BIDETS, "Piano close-coupled WC with cistern", "Piano", 365, 670, 790},
    {CAT_CATEGORY_WCS_BIDETS, "Vela floor-standing bidet, back-to-wall", "Vela", 360, 560, 400},
    {CAT_CATEGORY_BATHS, "Fjord bath 1700 x 750", "Fjord", 1700, 750, 460},
    {CAT_CATEGORY_BATHS, "Stilla freestanding bath 1800 x 850, oval", "Stilla", 1800, 850, 620},
    {CAT_CATEGORY_BATHS, "Vela corner bath 1400 x 1400", "Vela", 1400, 1400, 480},
    {CAT_CATEGORY_SHOWER_TRAYS, "Plan shower tray 1200 x 900", "Plan", 1200, 900, 40},
    {CAT_CATEGORY_SHOWER_TRAYS, "Stone shower tray 900 x 900, quadrant R550", "Stone", 900, 900,
     40},
    {CAT_CATEGORY_SHOWER_SCREENS, "Clara walk-in screen 900", "Clara", 900, 40, 2000},
    {CAT_CATEGORY_SHOWER_SCREENS, "Nivo corner entry 800 x 800", "Nivo", 800, 800, 1950},
    {CAT_CATEGORY_SHOWER_SCREENS, "Clara quadrant enclosure 900 x 900", "Clara", 900, 900, 1950},
    {CAT_CATEGORY_SHOWER_SCREENS, "Nivo sliding door 1400", "Nivo", 1400, 60, 2000},
    {CAT_CATEGORY_SHOWER_SCREENS, "Clara pivot door 900 for a niche", "Clara", 900, 40, 1950},
    {CAT_CATEGORY_SHOWER_SCREENS, "Clara bath screen 800, two panels", "Clara", 800, 30, 1400},
    {CAT_CATEGORY_MIRRORS, "Clara round mirror 600 with black frame", "Clara", 600, 30, 600},
    {CAT_CATEGORY_MIRRORS, "Aura illuminated mirror 1200 x 700", "Aura", 1200, 45, 700},
    {CAT_CATEGORY_MIRROR_CABINETS, "Reflex mirror cabinet 1200, 3 doors, LED", "Reflex", 1200, 160,
     700},
    {CAT_CATEGORY_LAMPS, "Aura mirror light LED 600", "Aura", 600, 80, 40},
    {CAT_CATEGORY_LAMPS, "Luna ceiling light 300", "Luna", 300, 300, 90},
    {CAT_CATEGORY_LAMPS, "Luna pendant light, opal globe 200", "Luna", 200, 200, 1200},
    {CAT_CATEGORY_LAMPS, "Stella recessed downlight IP65", "Stella", 85, 85, 60},
    {CAT_CATEGORY_LAMPS, "Stella wall light cylinder, up and down", "Stella", 80, 100, 300},
    {CAT_CATEGORY_LAMPS, "Luna wall light, two lights", "Luna", 350, 110, 120},
    {CAT_CATEGORY_TOWEL_RADIATORS, "Ladder towel radiator 600 x 1775", "Ladder", 600, 90, 1775},
    {CAT_CATEGORY_TOWEL_RADIATORS, "Plano flat panel radiator 500 x 1500", "Plano", 500, 100, 1500},
    {CAT_CATEGORY_TOWEL_RADIATORS, "Tubo designer radiator 600 x 1800", "Tubo", 600, 100, 1800},
    {CAT_CATEGORY_TOWEL_RADIATORS, "Plano electric towel radiator 450 x 800", "Plano", 450, 110,
     800},
    {CAT_CATEGORY_VANITY_UNITS, "Arco vanity unit 800, 2 drawers", "Arco", 800, 460, 520},
    {CAT_CATEGORY_VANITY_UNITS, "Ashby tall cabinet 350", "Ashby", 350, 330, 1700},
    {CAT_CATEGORY_VANITY_UNITS, "Ashby washstand 1000 with metal frame", "Ashby", 1000, 500, 850},
    {CAT_CATEGORY_ACCESSORIES, "Linea toilet roll holder", "Linea", 150, 80, 80},
    {CAT_CATEGORY_ACCESSORIES, "Linea spare toilet roll holder", "Linea", 60, 100, 150},
    {CAT_CATEGORY_ACCESSORIES, "Linea towel ring", "Linea", 200, 60, 180},
    {CAT_CATEGORY_ACCESSORIES, "Linea robe hook", "Linea", 40, 50, 40},
    {CAT_CATEGORY_ACCESSORIES, "Orbis soap dispenser, glass", "Orbis", 90, 110, 180},
    {CAT_CATEGORY_ACCESSORIES, "Orbis glass shelf 600", "Orbis", 600, 130, 40},
    {CAT_CATEGORY_ACCESSORIES, "Orbis WC brush set, wall-mounted", "Orbis", 100, 130, 380},
    {CAT_CATEGORY_ACCESSORIES, "Orbis grab bar 600", "Orbis", 600, 80, 80},
    {CAT_CATEGORY_ACCESSORIES, "Orbis shower basket, corner", "Orbis", 230, 230, 60},
    {CAT_CATEGORY_ACCESSORIES, "Arco WC seat with soft close", "Arco", 370, 450, 50},
    {CAT_CATEGORY_ACCESSORIES, NULL, NULL, 100, 100, 100}, /* no name: still a model */
};

static int edge_cmp(const void *a, const void *b)
{
    const unsigned long long x = *(const unsigned long long *)a, y = *(const unsigned long long *)b;
    return x < y ? -1 : x > y;
}

static int edge_count(const unsigned long long *e, int n, unsigned long long key)
{
    const unsigned long long *hit = bsearch(&key, e, (size_t)n, sizeof *e, edge_cmp);
    if (!hit)
        return 0;
    int c = 1;
    for (const unsigned long long *p = hit - 1; p >= e && *p == key; p--)
        c++;
    for (const unsigned long long *p = hit + 1; p < e + n && *p == key; p++)
        c++;
    return c;
}

/* A smoothed ceramic part is one closed, consistently oriented surface: every edge is used
 * once in each direction, and the enclosed volume is positive (normals point out). */
static int open_edges(const cat_mesh *m, double *volume)
{
    int n = m->index_count, open = 0;
    unsigned long long *e = malloc((size_t)n * sizeof *e + 1);
    if (!e)
        return -1;
    for (int t = 0; t < n; t += 3) /* directed edges a -> b as one sortable number */
        for (int k = 0; k < 3; k++)
            e[t + k] = (unsigned long long)m->indices[t + k] << 32 | m->indices[t + (k + 1) % 3];
    qsort(e, (size_t)n, sizeof *e, edge_cmp);
    for (int i = 0; i < n; i++) {
        unsigned long long twin = (e[i] & 0xffffffffull) << 32 | e[i] >> 32;
        open += edge_count(e, n, e[i]) != 1 || edge_count(e, n, twin) != 1;
    }
    free(e);
    double vol = 0;
    for (int t = 0; t < n; t += 3) {
        const float *p = m->positions + 3 * m->indices[t],
                    *q = m->positions + 3 * m->indices[t + 1],
                    *r = m->positions + 3 * m->indices[t + 2];
        vol += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
                p[2] * (q[0] * r[1] - q[1] * r[0])) /
               6;
    }
    *volume = vol;
    return open;
}

static void check_closed(const cat_mesh *m, const char *what)
{
    double vol = 0;
    int open = open_edges(m, &vol);
    if (open || !(vol > 0))
        fprintf(stderr, "%s: %d open or doubled edges, volume %g mm3\n", what, open, vol);
    CHECK(open == 0);
    CHECK(vol > 0);
}

static void generators(void)
{
    char err[2048];
    for (size_t s = 0; s < sizeof samples / sizeof samples[0]; s++) {
        const sample *x = &samples[s];
        cat_gen_request req = {x->category, x->name, x->series, x->w, x->d, x->h, NULL};
        cat_gen_model gm;
        cat_result r = cat_gen_product(&req, &gm, err, sizeof err);
        CHECK(r == CAT_OK);
        if (r != CAT_OK) {
            fprintf(stderr, "%s: %s\n", x->name ? x->name : "(no name)", err);
            continue;
        }
        const cat_model *m = &gm.model;
        CHECK(!model_broken(m));
        CHECK(m->mesh_count >= 1 && m->mesh_count == m->material_count);
        int slots = 0;
        double lo[3] = {1e30, 1e30, 1e30}, hi[3] = {-1e30, -1e30, -1e30};
        for (int i = 0; i < m->mesh_count; i++) {
            CHECK(m->meshes[i].material == i);
            CHECK(gm.extras[i].present);
            slots += gm.extras[i].variant_slot;
            for (int v = 0; v < m->meshes[i].vertex_count; v++)
                for (int k = 0; k < 3; k++) {
                    double p = m->meshes[i].positions[3 * v + k];
                    lo[k] = p < lo[k] ? p : lo[k];
                    hi[k] = p > hi[k] ? p : hi[k];
                }
        }
        CHECK(slots >= 1);
        if (x->category == CAT_CATEGORY_BASINS || x->category == CAT_CATEGORY_WCS_BIDETS ||
            x->category == CAT_CATEGORY_BATHS)
            check_closed(&m->meshes[0], x->name);
        /* The origin convention: x centred, y from the back face (0), z from the floor (0). */
        CHECK_NEAR(lo[0], -x->w / 2, 0.01);
        CHECK_NEAR(hi[0], x->w / 2, 0.01);
        CHECK_NEAR(lo[1], 0, 0.01);
        CHECK_NEAR(hi[1], x->d, 0.01);
        CHECK_NEAR(lo[2], 0, 0.01);
        CHECK_NEAR(hi[2], x->h, 0.01);

        /* Write, load back, and compare. */
        const char *path = tmp_path("gen.glb");
        CHECK(cat_model_write_glb(path, m, gm.extras, err, sizeof err) == CAT_OK);
        cat_model back;
        r = cat_model_load(path, &back, err, sizeof err);
        CHECK(r == CAT_OK);
        if (r == CAT_OK) {
            CHECK(back.mesh_count == m->mesh_count && back.material_count == m->material_count);
            for (int i = 0; i < back.mesh_count && back.mesh_count == m->mesh_count; i++) {
                CHECK(back.meshes[i].vertex_count == m->meshes[i].vertex_count);
                CHECK(back.meshes[i].index_count == m->meshes[i].index_count);
                CHECK(!strcmp(back.materials[i].name, m->materials[i].name));
            }
            for (int k = 0; k < 3; k++) {
                CHECK_NEAR(back.bounds_min[k], lo[k], 0.01);
                CHECK_NEAR(back.bounds_max[k], hi[k], 0.01);
            }
            cat_material_extras got[64];
            int n = 0;
            CHECK(cat_model_read_extras(path, got, 64, &n, err, sizeof err) == CAT_OK);
            CHECK(n == m->material_count);
            for (int i = 0; i < n && i < m->material_count; i++)
                CHECK(same_extras(&got[i], &gm.extras[i]));
            cat_model_free(&back);
        }
        cat_gen_model_free(&gm);
    }
    /* Two Catmull-Clark steps on the round bowl's cage (8 rings of 8 points, 2 of them poles:
     * 50 vertices, 104 edges, 56 faces) give 50 + 104 + 56 = 210, then 210 + 416 + 208 = 834
     * vertices: the subdivision really ran. */
    cat_gen_request bowl = {
        CAT_CATEGORY_BASINS, "Vela countertop bowl 420 round", "Vela", 420, 420, 140, NULL};
    cat_gen_model gb;
    if (cat_gen_product(&bowl, &gb, err, sizeof err) == CAT_OK) {
        CHECK(gb.model.meshes[0].vertex_count == 834);
        cat_gen_model_free(&gb);
    } else {
        CHECK(!"bowl");
    }
    /* Refusals: no category, tiles, a size out of range. */
    cat_gen_request bad = {CAT_CATEGORY_TILES, "tile", NULL, 300, 600, 10, NULL};
    cat_gen_model gm;
    CHECK(cat_gen_product(&bad, &gm, err, sizeof err) == CAT_ERR_UNSUPPORTED);
    CHECK(gm.model.meshes == NULL && gm.extras == NULL);
    bad.category = CAT_CATEGORY_BASINS;
    bad.width_mm = 0;
    CHECK(cat_gen_product(&bad, &gm, err, sizeof err) == CAT_ERR_INVALID);
    bad.width_mm = NAN;
    CHECK(cat_gen_product(&bad, &gm, err, sizeof err) == CAT_ERR_INVALID);
    CHECK(cat_gen_product(NULL, &gm, err, sizeof err) == CAT_ERR_INVALID);
}

/* Any size in the accepted range gives a model (never a crash, a NaN or an empty part) with
 * the exact box: every shape at the extremes 1 mm and 20 m, and at odd aspect ratios. */
static void extremes(void)
{
    static const double sizes[][3] = {{1, 1, 1},         {20000, 20000, 20000}, {1, 20000, 20000},
                                      {20000, 1, 20000}, {20000, 20000, 1},     {3, 700, 45},
                                      {900, 12, 2}};
    char err[2048];
    int failures = 0;
    for (size_t s = 0; s < sizeof samples / sizeof samples[0]; s++)
        for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
            const double *z = sizes[k];
            cat_gen_request req = {
                samples[s].category, samples[s].name, samples[s].series, z[0], z[1], z[2], NULL};
            cat_gen_model gm;
            if (cat_gen_product(&req, &gm, err, sizeof err) != CAT_OK) {
                if (failures++ < 5)
                    fprintf(stderr, "%s at %g x %g x %g: %s\n",
                            samples[s].name ? samples[s].name : "(no name)", z[0], z[1], z[2], err);
                continue;
            }
            int bad = model_broken(&gm.model);
            for (int a = 0; a < 3; a++) {
                double lo = a == 0 ? -z[0] / 2 : 0, hi = a == 0 ? z[0] / 2 : z[a];
                bad += fabs(gm.model.bounds_min[a] - lo) > z[a] * 1e-4 + 1e-3;
                bad += fabs(gm.model.bounds_max[a] - hi) > z[a] * 1e-4 + 1e-3;
            }
            if (bad && failures++ < 5)
                fprintf(stderr, "%s at %g x %g x %g: %d broken invariants\n",
                        samples[s].name ? samples[s].name : "(no name)", z[0], z[1], z[2], bad);
            cat_gen_model_free(&gm);
        }
    CHECK(failures == 0);
}

static void names(void)
{
    char out[256];
    CHECK(cat_model_file_name("Aquavera", "31000000", out, sizeof out));
    CHECK(!strcmp(out, "models/aquavera/31000000.glb"));
    CHECK(cat_model_file_name("Terrazza Ceramiche", "NK-51200.00", out, sizeof out));
    CHECK(!strcmp(out, "models/terrazza-ceramiche/nk-51200-00.glb"));
    CHECK(!cat_model_file_name("", "x", out, sizeof out));
    CHECK(!cat_model_file_name("A", "--", out, sizeof out));
    CHECK(!cat_model_file_name("Aquavera", "31000000", out, 20));
    setenv("TESSERA_MODELS", "/opt/models", 1);
    CHECK(cat_model_resolve("models/a/b.glb", "/assets", out, sizeof out));
    CHECK(!strcmp(out, "/opt/models/a/b.glb"));
    CHECK(cat_model_resolve("other/c.glb", "/assets", out, sizeof out));
    CHECK(!strcmp(out, "/assets/other/c.glb"));
    CHECK(!cat_model_resolve("models/../x.glb", "/assets", out, sizeof out));
    CHECK(!cat_model_resolve("/etc/passwd", "/assets", out, sizeof out));
    CHECK(!cat_model_resolve("", "/assets", out, sizeof out));
    unsetenv("TESSERA_MODELS");
}

int main(void)
{
    tmp_make();
    hand_made();
    generators();
    extremes();
    names();
    /* No temporary files of the atomic writer are left behind. */
    DIR *d = opendir(g_tmp);
    struct dirent *e;
    while (d && (e = readdir(d)))
        CHECK(strstr(e->d_name, ".tmp-") == NULL);
    if (d)
        closedir(d);
    tmp_remove();
    return check_report("test_model_write");
}
