/* Per-part materials of a product model (app/src/scene/model_materials.c), as the GPU scene, the
 * reference tracer's scene and the thumbnails use them: a generated basin written as GLB and
 * loaded back keeps its chrome waste's own material while its ceramic body (the part the
 * finish variant applies to) takes the object's; the same model written without Tessera's
 * extras (a plain glTF file) gives every part the object's material. */
#include "test_util.h"

#include "catalog/model_gen.h"
#include "catalog/model_write.h"
#include "model_materials.h"

#include <math.h>

static int near(float a, float b)
{
    return fabsf(a - b) < 1e-6f;
}

/* Loads path and counts its parts that keep a material of their own; *chrome gets 1 when one
 * of them is the generator's chrome (specular 0.95, k_r 0.8). */
static int fixed_parts(const char *path, int *chrome, int *parts)
{
    cat_model m;
    char err[1024];
    *chrome = 0;
    *parts = 0;
    if (cat_model_load(path, &m, err, sizeof err) != CAT_OK) {
        CHECK_MSG(0, "%s", err);
        return -1;
    }
    app_model_materials mm;
    CHECK(app_model_materials_read(path, &m, &mm));
    int fixed = 0;
    for (int i = 0; i < m.mesh_count; i++) {
        rd_material own;
        memset(&own, 0x7f, sizeof own);
        if (!app_model_part_material(&mm, &m.meshes[i], &own))
            continue;
        fixed++;
        *chrome |= near(own.specular[0], 0.95f) && near(own.reflectivity, 0.8f) &&
                   own.blend == RD_REFLECT_MIX && own.diffuse_texture.id == 0;
    }
    *parts = m.mesh_count;
    app_model_materials_free(&mm);
    cat_model_free(&m);
    return fixed;
}

int main(void)
{
    char dir[] = "/tmp/tessera-model-materials-XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    cat_render_material pink = {{0.9f, 0.6f, 0.6f},
                                {0.9f, 0.6f, 0.6f},
                                {0.1f, 0.1f, 0.1f},
                                {0, 0, 0},
                                60,
                                0.05f,
                                0.5f,
                                CAT_BLEND_MIX,
                                0,
                                1.5f,
                                CAT_PATTERN_NONE,
                                0};
    cat_gen_request req = {CAT_CATEGORY_BASINS, "test basin", NULL, 600, 450, 160, &pink};
    cat_gen_model gm;
    char err[1024];
    cat_result r = cat_gen_product(&req, &gm, err, sizeof err);
    CHECK_MSG(r == CAT_OK, "%s", err);
    if (r != CAT_OK)
        return check_report("model_materials");
    CHECK(gm.model.mesh_count >= 2); /* the ceramic body and the chrome waste */

    char with[1200], plain[1200];
    snprintf(with, sizeof with, "%s/basin.glb", dir);
    snprintf(plain, sizeof plain, "%s/plain.glb", dir);
    CHECK_MSG(cat_model_write_glb(with, &gm.model, gm.extras, err, sizeof err) == CAT_OK, "%s",
              err);
    CHECK_MSG(cat_model_write_glb(plain, &gm.model, NULL, err, sizeof err) == CAT_OK, "%s", err);

    int chrome, parts;
    /* every part but the finish's keeps its own: here exactly the waste, in chrome */
    CHECK(fixed_parts(with, &chrome, &parts) == parts - 1);
    CHECK(chrome == 1);
    /* a plain glTF file: the object's material on every part, as before per-part materials */
    CHECK(fixed_parts(plain, &chrome, &parts) == 0);
    CHECK(chrome == 0);

    /* the catalog's blend names map onto the renderer's */
    cat_render_material c = pink;
    c.blend = CAT_BLEND_ADD;
    CHECK(app_material_from_catalog(&c).blend == RD_REFLECT_ADD);
    CHECK(near(app_material_from_catalog(&c).diffuse[1], 0.6f));

    cat_gen_model_free(&gm);
    remove(with);
    remove(plain);
    rmdir(dir);
    return check_report("model_materials");
}
