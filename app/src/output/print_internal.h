/* Shared by the print_*.c files: the document being drawn, the fixtures gathered from the
 * project, and the drawing helpers (dimension lines, text, title block). Paper units are mm
 * from the page's top-left corner (the cairo context is scaled to millimetres). */
#ifndef APP_PRINT_INTERNAL_H
#define APP_PRINT_INTERNAL_H

#include "app/output/print.h"
#include "app/output/safe_file.h"
#include "app/project/project.h"
#include "app/design/quantities.h"
#include "app/design/tile_layout.h"
#include "catalog/catalog.h"

#include <cairo.h>
#include <stddef.h>

#define PR_PI 3.14159265358979323846

/* ---- fixtures: the project's objects grouped as the trade sees them ------------------------ */

/* One part's points in world mm (corners of a box, rings of a cylinder, a model's vertices). */
typedef struct pr_part {
    double (*pts)[3];
    int count;
} pr_part;

typedef struct pr_fixture {
    char name[64];   /* the group name, else the object's name */
    char label[96];  /* the article number of a catalog product, else the name */
    int has_product; /* 1: product and catalog data below are valid */
    app_product_ref ref;
    cat_product product; /* from the catalog (zeroed when not found) */
    int found;           /* 1: product was found in the catalog */
    int first_object;    /* index of its first object in the project */
    pr_part *parts;
    int part_count;
    double min[3], max[3]; /* world bounds over all parts */
} pr_fixture;

/* ---- the document ------------------------------------------------------------------------- */

typedef enum pr_page_kind {
    PR_PAGE_PLAN,
    PR_PAGE_ELEVATION,
    PR_PAGE_IMAGE,
    PR_PAGE_PARTS
} pr_page_kind;

typedef struct pr_page {
    pr_page_kind kind;
    int index; /* elevation: the elevation's index; image: the image; parts: the sheet */
} pr_page;

typedef struct pr_doc {
    const app_project *p;
    const app_print_options *o;
    app_room_plan plan;        /* the project's plan, or the room box as 4 corners */
    app_point2 box_corners[4]; /* storage for that fallback */
    cat_db *db;                /* NULL when the catalog cannot be opened (labels = names) */
    pr_fixture *fixtures;
    int fixture_count;
    app_tile_layout *layouts; /* one per tiling of the project (NULL: none could be made) */
    int layout_count;
    int have_quantities; /* q is valid */
    app_quantities q;
    int have_bom; /* bom is valid */
    app_bom bom;

    pr_page *pages;
    int page_count;

    cairo_surface_t *surface; /* PDF: one for all pages; SVG: the current page's */
    cairo_t *cr;
    const char *svg_dir;
    app_safe_file svg_file; /* SVG: the current page's file, renamed into place at its end */
    const char *pdf_path;
    int page; /* 0-based index of the page being drawn */
    double page_w, page_h;
    double area_x, area_y, area_w, area_h; /* the drawing area above the title block */
    char date[32];
    app_print_report *report;
    char *err;
    size_t err_size;
} pr_doc;

/* print_fixtures.c: groups objects into fixtures, looks up their catalog products, samples
 * their geometry (models through cat_model_load). */
app_result pr_fixtures_collect(pr_doc *d);
void pr_fixtures_free(pr_doc *d);
/* Convex hull of pts (in place order not kept); returns the hull's count, CCW, in out. */
int pr_convex_hull(const app_point2 *pts, int n, app_point2 *out);

/* print_page.c */
app_result pr_page_begin(pr_doc *d, const char *title, int scale);
app_result pr_page_end(pr_doc *d);

/* print_draw.c: line weights in paper mm (ISO 128: 0.13 / 0.18 / 0.25 / 0.35 / 0.5 / 0.7). */
#define PR_LINE_THIN 0.13
#define PR_LINE_FINE 0.18
#define PR_LINE_MEDIUM 0.25
#define PR_LINE_WIDE 0.35
#define PR_LINE_HEAVY 0.5
#define PR_TEXT_SMALL 2.0
#define PR_TEXT_NORMAL 2.5
#define PR_TEXT_LARGE 3.5
#define PR_TEXT_TITLE 5.0

void pr_set_font(cairo_t *cr, double size_mm, int bold);
/* Text with its anchor: ax 0 left, 0.5 centre, 1 right; ay 0 top, 0.5 middle, 1 baseline. */
void pr_text(cairo_t *cr, double x, double y, double ax, double ay, const char *text);
/* The same, turned by angle (radians, counter-clockwise on paper) about (x, y). */
void pr_text_rotated(cairo_t *cr, double x, double y, double angle, double ax, double ay,
                     const char *text);
double pr_text_width(cairo_t *cr, const char *text);
/* A dimension line between paper points a and b, drawn offset by `offset` mm to the left of
 * a->b (negative: to the right), with extension lines from a and b, architectural ticks and
 * the value (model mm, rounded) centred above the line. */
void pr_dimension(cairo_t *cr, double ax, double ay, double bx, double by, double offset,
                  double value_mm);
/* Fills the current path with 45-degree hatching, spacing in mm, keeping the path. */
void pr_hatch_path(cairo_t *cr, double spacing, double angle_deg);
/* A height mark (level triangle with +value) at paper (x, y), text to the right (or to the
 * left when text_left). */
void pr_level_mark(cairo_t *cr, double x, double y, const char *text, int text_left);
/* A graphic scale bar (1 m, or 2 m at 1:100 and smaller) whose right end is at (x, y). */
void pr_scale_bar(cairo_t *cr, double x, double y, int scale);
/* Formats cents as "1.234,56"-free plain "1234.56" with thousands separators: "1,234.56". */
void pr_format_money(long long cents, char *out, size_t size);

/* print_plan.c, print_elevation.c, print_images.c, print_parts.c */
app_result pr_draw_plan(pr_doc *d);
int pr_elevation_count(const pr_doc *d);
int pr_elevation_scale(pr_doc *d);
app_result pr_draw_elevation(pr_doc *d, int index);
app_result pr_draw_image(pr_doc *d, int index);
int pr_parts_page_count(pr_doc *d);
app_result pr_draw_parts(pr_doc *d, int sheet);

/* The plan polygon's outward-offset corners (miter joins) by `distance` mm; out has the
 * plan's corner count. */
void pr_offset_polygon(const app_point2 *c, int n, double distance, app_point2 *out);

#endif
