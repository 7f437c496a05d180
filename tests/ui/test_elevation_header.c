/* The elevation pane's header (ui/src/elevation_header.h): the title, the tile summary and the
 * pointer's readout never share a pixel, stay inside the pane (elided with "..."), and a cut
 * never splits a UTF-8 character. Widths come from a 7-pixel monospace font, the window's
 * default font (ProggyClean, 13 px). */
#include "check.h"
#include "elevation_header.h"

#include <string.h>

static float mono7(const char *text)
{
    float w = 0;
    for (const unsigned char *c = (const unsigned char *)text; *c; c++)
        if ((*c & 0xC0) != 0x80) /* one glyph per UTF-8 character */
            w += 7.0f;
    return w;
}

static int ends_with(const char *s, const char *tail)
{
    size_t n = strlen(s), m = strlen(tail);
    return n >= m && !strcmp(s + n - m, tail);
}

static void check_inside_and_apart(const ui_elev_header *h, float x, float w)
{
    for (int i = 0; i < UI_ELEV_HEADER_LINES; i++) {
        const ui_elev_header_line *a = &h->line[i];
        if (!a->text[0])
            continue;
        CHECK_MSG(a->x >= x && a->x + a->w <= x + w,
                  "line %d \"%s\" spans %.0f..%.0f, pane %.0f..%.0f", i, a->text, a->x, a->x + a->w,
                  x, x + w);
        CHECK(a->y + a->h <= h->bottom);
        for (int j = i + 1; j < UI_ELEV_HEADER_LINES; j++)
            CHECK_MSG(!ui_elev_header_lines_overlap(a, &h->line[j]), "\"%s\" overlaps \"%s\"",
                      a->text, h->line[j].text);
    }
}

int main(void)
{
    const char *title = "Elevation of wall 0 (wall:0), seen from the room";
    const char *summary = "15 whole, 37 cut tiles (layouts: 272.3 ms); a click starts the grid";
    const char *readout = "s 1907  t 1572 mm";

    /* The split window's elevation pane at 1280 x 720: 334 pixels wide at x 280. */
    ui_elev_header h;
    ui_elev_header_layout(280, 52, 334, 14, mono7, title, summary, readout, &h);
    check_inside_and_apart(&h, 280, 334);
    CHECK(ends_with(h.line[0].text, "..."));
    CHECK(!strncmp(h.line[0].text, "Elevation of wall 0", 19));
    CHECK(ends_with(h.line[1].text, "..."));
    CHECK(!strcmp(h.line[2].text, readout));
    CHECK(h.line[0].y < h.line[1].y && h.line[1].y < h.line[2].y);
    CHECK(h.line[0].w > 334 - 20 - 7 && h.line[0].w <= 334 - 20); /* as much as fits */

    /* A wide pane draws every text whole, still one line each. */
    ui_elev_header_layout(0, 0, 1200, 14, mono7, title, summary, readout, &h);
    check_inside_and_apart(&h, 0, 1200);
    CHECK(!strcmp(h.line[0].text, title));
    CHECK(!strcmp(h.line[1].text, summary));
    CHECK(!strcmp(h.line[2].text, readout));

    /* Without the pointer over the surface the readout's line is not shown. */
    ui_elev_header_layout(0, 0, 1200, 14, mono7, title, summary, "", &h);
    CHECK(!h.line[2].text[0]);
    CHECK(h.bottom <= h.line[1].y + 14 + 2);

    /* Every width down to nothing: never past the edge, never on top of each other. */
    for (int w = 0; w <= 700; w += 3) {
        ui_elev_header_layout(100, 40, (float)w, 14, mono7, title, summary, readout, &h);
        check_inside_and_apart(&h, 100, (float)w);
    }

    /* A cut lands between characters: "é" is two bytes, the cut never keeps only one. */
    char out[64];
    ui_elide_text("Wand Küche éééé", 7 * 9, mono7, out, sizeof out);
    CHECK(ends_with(out, "..."));
    CHECK(mono7(out) <= 7 * 9);
    for (const char *c = out; *c; c++)
        if (((unsigned char)*c & 0xE0) == 0xC0) /* a two-byte lead is followed by its tail */
            CHECK(((unsigned char)c[1] & 0xC0) == 0x80);
    /* A buffer smaller than the text still gets a terminated, fitting text. */
    ui_elide_text(title, 1000, mono7, out, 12);
    CHECK(strlen(out) < 12 && ends_with(out, "..."));
    return check_report("ui_elevation_header");
}
