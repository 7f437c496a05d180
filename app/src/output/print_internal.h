/* Shared by the print_*.c files: the document being drawn, the fixtures gathered from the
 * project, and the drawing helpers (dimension lines, text, title block). Paper units are mm
 * from the page's top-left corner (the cairo context is scaled to millimetres). */
#ifndef APP_PRINT_INTERNAL_H
#define APP_PRINT_INTERNAL_H

#include "app/output/print.h"
#include "app/output/quote.h"
#include "app/output/safe_file.h"
#include "app/project/project.h"
#include "app/design/quantities.h"
#include "app/design/tile_layout.h"
#include "catalog/catalog.h"

#include <cairo.h>
#include <stddef.h>
#include <stdio.h>

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
    int number;            /* its number on the plan, elevations and part list; 0: not drawn */
    int number_placed;     /* 1: the plan found room for the number (else only the legend) */
} pr_fixture;

typedef struct pr_doc pr_doc;

/* print_fixture_numbers.c: numbers by position, clockwise around the room from the door. */
void pr_fixtures_number(pr_doc *d);
/* Where the numbering starts, for the legend: "the door", "the window" or "corner 1". */
const char *pr_numbering_start(const pr_doc *d);
/* The 1-based position of a product in the quotation (the bill of materials), 0: none. */
int pr_quotation_position(const pr_doc *d, const app_product_ref *ref);
/* The plan numbers of the fixtures of that product, "3, 7"; returns how many. */
int pr_fixture_numbers_text(const pr_doc *d, const app_product_ref *ref, char *out, size_t size);

/* ---- the texts drawn on a page (print_text_boxes.c) ----------------------------------------- */

/* A box on the page in paper mm, x right, y down. */
typedef struct pr_box {
    double x0, y0, x1, y1;
} pr_box;

typedef struct pr_text_box {
    pr_box box;
    char text[48];
} pr_text_box;

typedef struct pr_text_boxes {
    pr_text_box *items;
    int count, cap;
    int suspended;     /* 1: pr_text draws without recording (a balloon records its circle) */
    pr_box *obstacles; /* places labels keep off that are no texts (the legend's block) */
    int obstacle_count, obstacle_cap;
} pr_text_boxes;

void pr_text_boxes_attach(cairo_t *cr, pr_text_boxes *b);
pr_text_boxes *pr_text_boxes_of(cairo_t *cr);
void pr_text_boxes_clear(pr_text_boxes *b);
void pr_text_boxes_free(pr_text_boxes *b);
/* The ink box, in paper mm, of text drawn as pr_text_rotated would draw it (nothing drawn). */
pr_box pr_text_measure(cairo_t *cr, double x, double y, double angle, double ax, double ay,
                       const char *text);
/* A rectangle in the current user space as a box in paper mm. */
pr_box pr_box_to_paper(cairo_t *cr, double x0, double y0, double x1, double y1);
int pr_boxes_overlap(pr_box a, pr_box b, double margin);
/* 1 when b (paper mm) keeps `margin` mm from every text recorded on the page. */
int pr_box_is_free(cairo_t *cr, pr_box b, double margin);
void pr_box_record(cairo_t *cr, pr_box b, const char *text);
/* Keeps later labels off b (paper mm) without counting it as a text. */
void pr_box_reserve(cairo_t *cr, pr_box b);
/* One line a box: page, x0, y0, x1, y1 (paper mm from the top-left), drawing, text; tabs. */
void pr_text_boxes_write(const pr_text_boxes *b, FILE *out, int page, const char *drawing);

/* ---- the document ------------------------------------------------------------------------- */

typedef enum pr_page_kind {
    PR_PAGE_PLAN,
    PR_PAGE_ELEVATION,
    PR_PAGE_IMAGE,
    PR_PAGE_PARTS
} pr_page_kind;

typedef struct pr_page {
    pr_page_kind kind;
    int index;  /* elevation: the elevation's index; image: the image; parts: the sheet */
    int second; /* elevation, image: the second one on the page, -1: none */
} pr_page;

/* A cut tile's number on an elevation, drawn after everything else where it is free. */
typedef struct pr_cut_label {
    double x, y; /* paper mm */
    int number;
} pr_cut_label;

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
    app_consumables cons; /* the amounts behind the consumables and labour lines of bom */
    app_quote quote;      /* company, customer, number, date, validity */

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
    pr_text_boxes text_boxes; /* the texts of the page being drawn */
    FILE *text_boxes_out;     /* o->text_boxes_path, open while drawing; NULL: not asked */
    char page_title[160];     /* the drawing's name in the title block, for that list */
    int clearances_drawn;     /* free areas drawn on the plan (the legend explains the hatch) */
    pr_cut_label *cut_labels; /* the elevation page's cut numbers waiting to be placed */
    int cut_label_count, cut_label_cap;
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
/* The same, the value moved (beyond an end, a line further out) when texts already on the page
 * are in its way; returns 1 when it found a free place. draw = 0 draws nothing and only records
 * the value's box (a chain tries its members; pr_text_boxes_rollback undoes the try). */
int pr_dimension_placed(cairo_t *cr, double ax, double ay, double bx, double by, double offset,
                        double value_mm, int draw);
int pr_text_boxes_mark(cairo_t *cr);
void pr_text_boxes_rollback(cairo_t *cr, int mark);
/* Fills the current path with 45-degree hatching, spacing in mm, keeping the path. */
void pr_hatch_path(cairo_t *cr, double spacing, double angle_deg);
/* A height mark (level triangle with +value) at paper (x, y), text to the right (or to the
 * left when text_left). */
void pr_level_mark(cairo_t *cr, double x, double y, const char *text, int text_left);
/* A graphic scale bar (1 m, or 2 m at 1:100 and smaller) whose right end is at (x, y). */
void pr_scale_bar(cairo_t *cr, double x, double y, int scale);
/* Formats cents as "1.234,56"-free plain "1234.56" with thousands separators: "1,234.56". */
void pr_format_money(long long cents, char *out, size_t size);
/* A fixture's number in a circle centred at (x, y) (paper mm); the circle is its text box. */
#define PR_BALLOON_RADIUS 1.8
void pr_balloon(cairo_t *cr, double x, double y, int number);
/* Puts fixture number `number` at the anchor (x, y), or, when texts are in the way, on a leader
 * moved out from it, keeping inside `within`; returns 0 (and draws nothing) when no place is
 * free. */
int pr_place_balloon(cairo_t *cr, double x, double y, int number, pr_box within);

/* print_plan.c, print_elevation.c, print_images.c, print_parts.c */
app_result pr_draw_plan(pr_doc *d);
int pr_elevation_count(const pr_doc *d);
/* The largest standard scale at which elevation `index` fits a page alone (or the forced one). */
int pr_elevation_scale(pr_doc *d, int index);
/* The elevation pages: one elevation a page, two when both fit side by side (or one above the
 * other) at the scale each has alone. Fills pages[] (index, second) and returns their count. */
int pr_elevation_pages(pr_doc *d, pr_page *pages);
app_result pr_draw_elevation(pr_doc *d, int index, int second);
/* Render pages hold two images each (the second may be -1). */
int pr_image_page_count(const pr_doc *d);
app_result pr_draw_image(pr_doc *d, int index, int second);
int pr_parts_page_count(pr_doc *d);
app_result pr_draw_parts(pr_doc *d, int sheet);

/* print_legend.c: the plan's legend (fixtures by number, notes, scale bar), its size measured
 * with cr (any context: the page's may not exist yet) and drawn with its top-left at (x, y). */
void pr_legend_size(pr_doc *d, cairo_t *cr, double *width, double *height);
void pr_legend_draw(pr_doc *d, double x, double y, int scale);

/* The plan polygon's outward-offset corners (miter joins) by `distance` mm; out has the
 * plan's corner count. */
void pr_offset_polygon(const app_point2 *c, int n, double distance, app_point2 *out);

#endif
