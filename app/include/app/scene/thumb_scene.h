/* Product thumbnails (tessera catalog thumbs): one small studio scene per product, rendered
 * with the real renderer into the caller's pixels. The studio's meshes live as long as the
 * context; each product's scene, meshes and texture are made and freed per call. */
#ifndef APP_THUMB_SCENE_H
#define APP_THUMB_SCENE_H

#include "catalog/catalog.h"
#include "render/render.h"

#include <stddef.h>
#include <stdint.h>

typedef struct thumb_studio {
    rd_context *ctx;
    rd_mesh plane, box;     /* unit plane (floor, tile panel) and unit box (backdrop, fallback) */
    const char *assets_dir; /* tile textures and non-generated models are relative to it */
    int supersample;        /* 1..4 */
    const char *variant;    /* preferred variant code (e.g. "CP"), NULL = each one's first */
} thumb_studio;

/* What a thumbnail showed. */
typedef enum thumb_source {
    THUMB_MODEL = 0, /* the product's GLB model */
    THUMB_BOX,       /* no model (yet): a box of the catalog's width, depth and height */
    THUMB_TILE,      /* a tile: a small square of it with its texture */
} thumb_source;

/* Makes the studio's meshes in ctx. Returns 0 and writes err on failure. */
int thumb_studio_init(thumb_studio *st, rd_context *ctx, const char *assets_dir, char *err,
                      size_t err_size);
void thumb_studio_free(thumb_studio *st);

/* Renders product p in its variant (st->variant, else its first) at size x size into rgba (size *
 * size * 4 bytes, sRGB, top row first). *source says what was drawn; *note (may be NULL) gets why a
 * model fell back to a box ("" when it did not). Returns 0 and writes err on failure. */
int thumb_render(thumb_studio *st, const cat_product *p, int size, uint8_t *rgba,
                 thumb_source *source, char *note, size_t note_size, char *err, size_t err_size);

#endif
