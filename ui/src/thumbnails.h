/* Product thumbnails for the catalog browser: rendered lazily in the window's
 * own context by the same studio as `tessera catalog thumbs` (app/src/scene/thumb_scene.c), a few
 * per frame so typing in the search field stays fluid, and kept as GL textures per product. */
#ifndef UI_THUMBNAILS_H
#define UI_THUMBNAILS_H

#include "catalog/catalog.h"
#include "render/render.h"

#define UI_THUMB_SIZE 64   /* pixels per side, rendered and shown */
#define UI_THUMB_CACHE 256 /* textures kept; the least recently shown one makes room */

typedef struct ui_thumb {
    long long product_id;
    unsigned texture; /* GL name, 0 until rendered */
    int state;        /* 0 wanted, 1 ready, 2 failed (not tried again) */
    long last_used;   /* frame it was last asked for */
} ui_thumb;

typedef struct ui_thumbnails {
    rd_context *ctx;
    void *studio; /* thumb_studio, made on the first render */
    int studio_failed;
    ui_thumb items[UI_THUMB_CACHE];
    int count;
    long frame;
    int rendered;    /* thumbnails rendered so far */
    double total_ms; /* their rendering time */
    char error[512]; /* the first failure */
} ui_thumbnails;

void ui_thumbnails_init(ui_thumbnails *t, rd_context *ctx);
void ui_thumbnails_free(ui_thumbnails *t);
/* The product's texture, 0 while it is not rendered yet; want = 1 queues it (it is shown). */
unsigned ui_thumbnails_get(ui_thumbnails *t, long long product_id, int want);
/* Renders up to max queued thumbnails from db (the renderer's targets are its own; the caller
 * binds the window again). Returns how many were rendered. */
int ui_thumbnails_update(ui_thumbnails *t, cat_db *db, int max);
/* Queued thumbnails not rendered yet. */
int ui_thumbnails_pending(const ui_thumbnails *t);

#endif
