/* The customer print set of both shipped projects (the demo bathroom and the designed bathroom),
 * A4 landscape, scales fitted, with two render pages: no two texts overlap on any page (the ink
 * boxes every drawn text records, app_print_options.text_boxes_path), the demo's plan is at 1:20
 * and says so in its title block, each elevation stands at the largest standard scale that fits
 * it, renders go two a page captioned by view name, and the plan's legend gives each catalog
 * fixture the position its product has in the quotation. Needs poppler-utils (pdftotext). */
#define _POSIX_C_SOURCE 200809L
#include "app/output/print.h"
#include "app/project/project.h"
#include "test_util.h"

#include <cairo.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

typedef struct box {
    int page;
    double x0, y0, x1, y1;
    char text[64];
} box;

static char *run_capture(const char *cmd)
{
    FILE *f = popen(cmd, "r");
    if (!f)
        return NULL;
    size_t cap = 1 << 16, n = 0, got;
    char *buf = malloc(cap);
    while (buf && (got = fread(buf + n, 1, cap - n - 1, f)) > 0) {
        n += got;
        if (n + 1 >= cap) {
            char *nb = realloc(buf, cap * 2);
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
    }
    if (buf)
        buf[n] = 0;
    pclose(f);
    return buf;
}

/* Reads the text boxes; returns their count (boxes grows as needed). */
static int read_boxes(const char *path, box **boxes)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    int n = 0, cap = 0;
    char line[512];
    while (fgets(line, sizeof line, f)) {
        if (n == cap) {
            cap = cap ? cap * 2 : 512;
            box *b = realloc(*boxes, (size_t)cap * sizeof *b);
            if (!b)
                break;
            *boxes = b;
        }
        box *b = &(*boxes)[n];
        char drawing[256] = "";
        int fields = sscanf(line, "%d\t%lf\t%lf\t%lf\t%lf\t%255[^\t]\t%63[^\n]", &b->page, &b->x0,
                            &b->y0, &b->x1, &b->y1, drawing, b->text);
        if (fields >= 6)
            n++;
    }
    fclose(f);
    return n;
}

/* Pairs of texts on one page whose boxes share more than a hair (0.01 mm each way). */
static int count_overlaps(const box *b, int n, const char *project)
{
    int overlaps = 0;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            if (b[i].page != b[j].page)
                continue;
            if (b[i].x0 < b[j].x1 - 0.01 && b[j].x0 < b[i].x1 - 0.01 && b[i].y0 < b[j].y1 - 0.01 &&
                b[j].y0 < b[i].y1 - 0.01) {
                if (overlaps < 20)
                    fprintf(stderr, "%s page %d: \"%s\" overlaps \"%s\"\n", project, b[i].page,
                            b[i].text, b[j].text);
                overlaps++;
            }
        }
    return overlaps;
}

static void write_png(const char *path)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 160, 90);
    cairo_t *cr = cairo_create(s);
    cairo_set_source_rgb(cr, 0.6, 0.7, 0.8);
    cairo_paint(cr);
    cairo_destroy(cr);
    CHECK(cairo_surface_write_to_png(s, path) == CAIRO_STATUS_SUCCESS);
    cairo_surface_destroy(s);
}

/* The number at the end of the first line of `text` holding `word` (the legend's "Pos."), or at
 * its start (the quotation's "Pos"); -1 when there is none. */
static int number_on_line(const char *text, const char *word, int at_end)
{
    const char *hit = strstr(text, word);
    if (!hit)
        return -1;
    const char *start = hit, *end = hit;
    while (start > text && start[-1] != '\n')
        start--;
    while (*end && *end != '\n')
        end++;
    if (at_end) {
        const char *q = end;
        while (q > start && q[-1] == ' ')
            q--;
        const char *digits = q;
        while (digits > start && digits[-1] >= '0' && digits[-1] <= '9')
            digits--;
        return digits < q ? atoi(digits) : -1;
    }
    while (*start == ' ')
        start++;
    return *start >= '0' && *start <= '9' ? atoi(start) : -1;
}

static void print_project(const char *dir, const char *file, const char *name, int expect_plan,
                          int expect_elevations)
{
    char path[1024], pdf[1024], boxes_path[1024], db[1024], png[2][1024], err[2048] = "";
    snprintf(path, sizeof path, "%s/assets/projects/%s", TESSERA_SOURCE_DIR, file);
    snprintf(pdf, sizeof pdf, "%s/%s.pdf", dir, name);
    snprintf(boxes_path, sizeof boxes_path, "%s/%s.tsv", dir, name);
    snprintf(db, sizeof db, "%s/catalog.sqlite", dir);
    for (int k = 0; k < 2; k++) {
        snprintf(png[k], sizeof png[k], "%s/view-%d.png", dir, k);
        write_png(png[k]);
    }
    app_project p;
    app_result r = app_project_read(path, &p, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r != APP_OK)
        return;
    const char *images[2] = {png[0], png[1]};
    const char *titles[2] = {"door", "basin"};
    app_print_options o = {.paper = APP_PAPER_A4,
                           .landscape = 1,
                           .date = "2026-12-05",
                           .catalog_db = db,
                           .catalog_source = TESSERA_SOURCE_DIR "/assets/catalog",
                           .assets_dir = TESSERA_SOURCE_DIR "/assets",
                           .images = images,
                           .image_titles = titles,
                           .image_count = 2,
                           .text_boxes_path = boxes_path};
    app_print_report rep;
    r = app_print_pdf(&p, &o, pdf, &rep, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s: %s", name, err);
    fprintf(stderr, "%s: %d pages, plan 1:%d, %d elevations on %d pages, %d render pages\n", name,
            rep.pages, rep.plan_scale, rep.elevations, rep.elevation_pages, rep.render_pages);
    if (expect_plan)
        CHECK_MSG(rep.plan_scale == expect_plan, "%s: plan at 1:%d", name, rep.plan_scale);
    CHECK_MSG(rep.elevation_scale == expect_elevations, "%s: elevations down to 1:%d", name,
              rep.elevation_scale);
    CHECK(rep.render_pages == 1); /* two renders, one page */
    CHECK(rep.elevation_pages >= 1 && rep.elevation_pages <= rep.elevations);

    box *boxes = NULL;
    int n = read_boxes(boxes_path, &boxes);
    CHECK_MSG(n > 50, "%s: %d text boxes", name, n);
    int pages_with_text = 0;
    for (int page = 1; page <= rep.pages; page++) {
        int any = 0;
        for (int i = 0; i < n && !any; i++)
            any = boxes[i].page == page;
        pages_with_text += any;
    }
    CHECK_MSG(pages_with_text == rep.pages, "%s: %d of %d pages list texts", name, pages_with_text,
              rep.pages);
    int overlaps = count_overlaps(boxes, n, name);
    fprintf(stderr, "%s: %d text boxes, %d overlapping pairs\n", name, n, overlaps);
    CHECK_MSG(overlaps == 0, "%s: %d overlapping texts", name, overlaps);
    free(boxes);

    /* The title block of page 1 shows the plan's scale; the render page its views' names. */
    char cmd[2200];
    snprintf(cmd, sizeof cmd, "pdftotext -layout -f 1 -l 1 '%s' -", pdf);
    char *plan = run_capture(cmd);
    char scale[16];
    snprintf(scale, sizeof scale, "1:%d", rep.plan_scale);
    CHECK_MSG(plan && strstr(plan, scale), "%s: no %s on the plan", name, scale);
    snprintf(cmd, sizeof cmd, "pdftotext -layout '%s' -", pdf);
    char *all = run_capture(cmd);
    CHECK(all && strstr(all, "View: door") && strstr(all, "View: basin"));
    CHECK(all && !strstr(all, "pixels"));
    /* Catalog fixtures: the legend's position is the quotation line of the same article. */
    if (plan && all && strstr(plan, "CE415701")) {
        int pos = number_on_line(plan, "CE415701", 1);
        const char *quote = strstr(all, "Quotation");
        int line = quote ? number_on_line(quote, "CE415701", 0) : -1;
        CHECK_MSG(pos > 0 && pos == line, "%s: legend Pos. %d, quotation line %d", name, pos, line);
        /* The quotation names the fixture's plan number, the legend's line starts with it. */
        const char *q = quote ? strstr(quote, "CE415701") : NULL;
        const char *no = q ? strstr(q, "No. ") : NULL;
        int number = no ? atoi(no + 4) : -1;
        const char *legend = strstr(plan, "CE415701");
        const char *line_start = legend;
        while (line_start > plan && line_start[-1] != '\n')
            line_start--;
        char token[16], segment[512];
        snprintf(token, sizeof token, " %d ", number);
        snprintf(segment, sizeof segment, "%.*s", (int)(legend - line_start), line_start);
        CHECK_MSG(number > 0 && strstr(segment, token), "%s: quotation No. %d, legend \"%s\"", name,
                  number, segment);
    }
    free(plan);
    free(all);
    app_project_free(&p);
}

int main(void)
{
    char dir[] = "/tmp/tessera-print-layout-XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    /* The demo (2400 x 3000 inside, 120 mm walls) fits A4 landscape at 1:20 turned a quarter;
     * the designed bathroom (2600 x 3200, 175 mm walls, chains on all sides) at 1:25. Their
     * walls (2500 and 2600 high) fit at 1:20 one a page. */
    print_project(dir, "demo-bathroom.json", "demo", 20, 20);
    print_project(dir, "designed-bathroom.json", "designed", 25, 20);
    if (!getenv("TESSERA_TEST_KEEP")) {
        char cmd[1200];
        snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
        CHECK(system(cmd) == 0);
    } else {
        fprintf(stderr, "kept %s\n", dir);
    }
    return check_report("print_layout");
}
