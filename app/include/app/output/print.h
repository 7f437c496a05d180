/* Printed documents of a project (DOMAIN.md "What the best planners print"):
 * a floor plan at a true scale, wall elevations with the tile layout, render pages, and the
 * part list with a priced quotation, as one multi-page vector PDF or one SVG per page, drawn
 * with Cairo. docs/printing.md describes the pages and how scales are chosen.
 *
 * Paper coordinates are millimetres from the page's top-left corner; drawings at scale 1:N
 * map N model millimetres to one paper millimetre exactly (the PDF/SVG user unit is the point,
 * 72 per inch, so 1 mm = 72 / 25.4 pt).
 *
 * Every call that can fail returns an app_result and writes "FILE: what went wrong" into err.
 * Nothing here aborts; the functions keep no global state. */
#ifndef APP_PRINT_H
#define APP_PRINT_H

#include "app/project/project.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum app_paper { APP_PAPER_A4 = 0, APP_PAPER_A3 } app_paper;

/* ISO 216 sizes in mm: A4 210 x 297, A3 297 x 420 (portrait; landscape swaps them). */
void app_paper_size_mm(app_paper paper, int landscape, double *width_mm, double *height_mm);
/* "A4" / "A3" (any case); returns 1 and sets *out when known. */
int app_paper_parse(const char *text, app_paper *out);

/* The standard scales a drawing may take, largest first: 1:10, 1:20, 1:25, 1:50, 1:100, 1:200
 * (ISO 5455's building scales; 1:10 for details such as a pre-wall's unfolded faces). */
#define APP_PRINT_SCALE_COUNT 6
extern const int app_print_scales[APP_PRINT_SCALE_COUNT];

/* The largest standard scale (smallest N of 1:N) at which a drawing of extent_w x extent_h
 * model mm plus `border_mm` paper mm on every side fits into avail_w x avail_h paper mm;
 * the smallest scale (1:200) when none fits. */
int app_print_fit_scale(double extent_w_mm, double extent_h_mm, double border_mm, double avail_w_mm,
                        double avail_h_mm);

/* "1:20" or "20" -> 20 (any positive integer up to 10000); "fit" -> 0. Returns 1 when valid. */
int app_print_scale_parse(const char *text, int *denominator);

typedef struct app_print_options {
    app_paper paper;
    int landscape;
    int scale;                  /* 1:N for every drawing; 0 = fit each drawing kind to the page */
    const char *customer;       /* shown in the title block; NULL or "" = none */
    const char *date;           /* shown in the title block; NULL = today, UTC, YYYY-MM-DD */
    const char *catalog_db;     /* catalog file; NULL = cat_default_path() */
    const char *catalog_source; /* shipped CSV folder (assets/catalog) for a first build;
                                   NULL = none */
    const char *assets_dir;     /* where catalog model/texture paths resolve; NULL = none */
    const char *const *images;  /* PNG renders to include, one page each (may be NULL) */
    const char *const *image_titles; /* caption of each image (may be NULL) */
    int image_count;
    int no_clearances;   /* 1: leave out the clearance areas of the plan */
    const char *company; /* the quotation's company file (app/output/quote.h); NULL = the
                            default file when it exists */
    const char *xlsx;    /* app_print_pdf also writes the quotation there; NULL = no */
    int verbose;         /* 1: warnings (a drawing that does not fit its scale) on stderr */
    /* Debugging and tests: every text's ink box, one line each (page, x0, y0, x1, y1 in paper
     * mm from the page's top-left corner, the drawing, the text; tab-separated). NULL: none. */
    const char *text_boxes_path;
} app_print_options;

#define APP_PRINT_REPORT_MAX_ELEVATIONS 64

/* What was printed, for tests and the CLI's summary. */
typedef struct app_print_report {
    int pages;
    int plan_scale, elevation_scale; /* the 1:N used (elevations: the smallest, 1:largest N) */
    int elevation_pages;             /* pages holding elevations (one or two a page) */
    int elevations;                  /* elevations drawn: walls, then pre-walls */
    int tiles_whole, tiles_cut;      /* drawn on the elevations, summed over all walls */
    /* Per elevation (walls 0..n-1, then pre-wall fronts): the tiles of that face's own
     * layouts (a pre-wall's front seen on its wall's sheet is counted on its own sheet). */
    int elevation_whole[APP_PRINT_REPORT_MAX_ELEVATIONS];
    int elevation_cut[APP_PRINT_REPORT_MAX_ELEVATIONS];
    int fixtures; /* fixtures drawn on the plan */
    int render_pages;
    int partlist_pages;
} app_print_report;

/* Writes the print set (plan, elevations, renders, part list) to a PDF file. report may be
 * NULL. */
app_result app_print_pdf(const app_project *p, const app_print_options *o, const char *pdf_path,
                         app_print_report *report, char *err, size_t err_size);

/* A flat's print set: room i's set with opts[i] (its renders), one section a room, in one PDF;
 * title is the PDF's title. report (may be NULL) sums the rooms'; its scales are the smallest
 * (largest N) used. */
app_result app_print_flat_pdf(const app_project *rooms, const app_print_options *opts, int n,
                              const char *title, const char *pdf_path, app_print_report *report,
                              char *err, size_t err_size);

/* The same pages as SVG files DIR/page-01.svg, DIR/page-02.svg, ... (DIR must exist). */
app_result app_print_svg(const app_project *p, const app_print_options *o, const char *dir,
                         app_print_report *report, char *err, size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
