/* The "share" export: a self-contained folder a customer opens in any browser
 * from the file system: index.html with the plan, the renders, an interactive 360-degree
 * panorama (assets/share/pano-viewer.js, no network) and the part list with prices. This
 * header writes the page from what the caller made (app/src/cli/cli_share.c renders and prints). */
#ifndef APP_SHARE_H
#define APP_SHARE_H

#include "app/project/project.h"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct app_share_image {
    const char *file;  /* relative to the folder, e.g. "renders/door.jpg" */
    const char *title; /* caption */
} app_share_image;

typedef struct app_share_page {
    const char *title;            /* the project's name */
    const char *subtitle;         /* customer, date; may be NULL */
    const app_share_image *plans; /* plan and elevation drawings (SVG or PNG) */
    int plan_count;
    const app_share_image *renders;
    int render_count;
    const char *pdf_file; /* the print set, linked; NULL = none */
    int has_panorama;     /* 1: panorama.js and pano-viewer.js are in the folder */
    /* The part list: `columns` header cells, then rows x columns cells, then the totals
     * lines (label, value) under the table. Any may be NULL/0. */
    const char *const *table;
    int columns, rows;
    const char *const *totals;
    int total_count;
} app_share_page;

/* Writes DIR/index.html (atomically). Every text is HTML-escaped; file names are checked to
 * stay inside the folder (no "..", no absolute paths). */
app_result app_share_write_page(const char *dir, const app_share_page *page, char *err,
                                size_t err_size);

/* Writes DIR/panorama.js: the panorama image as a data: URI in window.TESSERA_PANORAMA, so the
 * viewer can hand it to WebGL from a file:// page. mime is "image/jpeg" or "image/png". */
app_result app_share_write_panorama(const char *dir, const uint8_t *image, size_t size,
                                    const char *mime, char *err, size_t err_size);

/* Copies the viewer script (assets_dir/share/pano-viewer.js) into DIR. */
app_result app_share_copy_viewer(const char *dir, const char *assets_dir, char *err,
                                 size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
