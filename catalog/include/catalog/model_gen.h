/* catalog/model_gen.h: procedural 3D models of catalog products.
 *
 * Every product of the catalog gets a model built from its row: category, name (which picks the
 * shape: "wall-mounted", "round", "corner", "freestanding", ...), series (square series get
 * square bodies) and its width, depth and height. The generators build parts from three
 * primitives (gen_internal.h): lofts of rounded rectangles (a lathe when the rectangle is a
 * circle), sweeps of a profile along a path (spouts, tubes, rims) and boxes; ceramic shapes are
 * coarse cages smoothed by Catmull-Clark subdivision (OpenMesh, mesh_subdivide.cpp).
 *
 * Conventions of a generated model (docs/catalog.md, "Models"):
 * - millimetres, Z up, like everything in Tessera;
 * - the bounding box is exactly width (x) x depth (y) x height (z) of the catalog row;
 * - the origin is the bottom centre of the back face, the face that goes against the wall:
 *   x in [-w/2, w/2], y in [0, d] (the front is +y), z in [0, h];
 * - one cat_mesh per part, and mesh i uses material i; every mesh has normals;
 * - the parts that take the product's finish variant are marked (extras[i].variant_slot).
 */
#ifndef CATALOG_MODEL_GEN_H
#define CATALOG_MODEL_GEN_H

#include "catalog/catalog.h"
#include "catalog/model.h"
#include "catalog/model_write.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cat_gen_model {
    cat_model model;             /* parts: meshes[i] uses materials[i] */
    cat_material_extras *extras; /* model.material_count entries */
} cat_gen_model;

typedef struct cat_gen_request {
    cat_category category;                /* not CAT_CATEGORY_ANY nor CAT_CATEGORY_TILES */
    const char *name;                     /* the product's name; may be NULL */
    const char *series;                   /* may be NULL */
    double width_mm, depth_mm, height_mm; /* each in [1, 20000] */
    const cat_render_material *finish;    /* the first variant's material; NULL = a default */
} cat_gen_request;

/* Builds the model of one product into *out (zeroed first, left zeroed on failure). */
cat_result cat_gen_product(const cat_gen_request *req, cat_gen_model *out, char *err,
                           size_t err_size);

/* Frees what *m owns and zeroes it; safe on a zeroed model and on NULL. */
void cat_gen_model_free(cat_gen_model *m);

/* The shipped model path of a product, relative to the assets folder:
 * "models/<manufacturer>/<article>.glb" with both lower-cased and every run of characters other
 * than a-z and 0-9 turned into one '-'. Returns 0 when it does not fit or a part is empty. */
int cat_model_file_name(const char *manufacturer, const char *article, char *out, size_t size);

/* Where generated models live: $TESSERA_MODELS when set and non-empty, else the folder the
 * build generated them into (compiled in: <build>/assets/models). Returns 0 when it does not
 * fit. */
int cat_models_dir(char *out, size_t size);

/* Resolves a product's `model` value: "models/REST" becomes cat_models_dir()/REST; anything
 * else is joined to assets_dir (NULL or "" = the current folder). Returns 0 when the value is
 * empty, absolute, contains "..", or the result does not fit. */
int cat_model_resolve(const char *model, const char *assets_dir, char *out, size_t size);

#ifdef __cplusplus
}
#endif

#endif
