#include "elevation_header.h"

#include <string.h>

void ui_elide_text(const char *text, float max_w, ui_text_width_fn width, char *out, int cap)
{
    if (cap <= 0)
        return;
    int n = (int)strlen(text);
    if (n > cap - 1)
        n = cap - 1;
    memcpy(out, text, (size_t)n);
    out[n] = 0;
    if (n == (int)strlen(text) && width(out) <= max_w)
        return;
    /* Drop characters from the end until the text and the ellipsis fit; a UTF-8 continuation
     * byte (10xxxxxx) is never left as the last byte kept. */
    static const char dots[] = "...";
    while (n > 0) {
        n--;
        while (n > 0 && ((unsigned char)text[n] & 0xC0) == 0x80)
            n--;
        if (n + (int)sizeof dots > cap)
            continue;
        memcpy(out, text, (size_t)n);
        memcpy(out + n, dots, sizeof dots);
        if (width(out) <= max_w)
            return;
    }
    /* Not even "..." fits: draw nothing rather than past the edge. */
    out[0] = 0;
    if (width(dots) <= max_w && (int)sizeof dots <= cap)
        memcpy(out, dots, sizeof dots);
}

void ui_elev_header_layout(float x, float y, float w, float line_h, ui_text_width_fn width,
                           const char *title, const char *summary, const char *readout,
                           ui_elev_header *out)
{
    const float margin = 10.0f, gap = 2.0f;
    const char *texts[UI_ELEV_HEADER_LINES] = {title, summary, readout};
    float max_w = w - 2 * margin;
    float line_y = y + 8.0f;
    memset(out, 0, sizeof *out);
    out->bottom = line_y;
    for (int i = 0; i < UI_ELEV_HEADER_LINES; i++) {
        ui_elev_header_line *l = &out->line[i];
        if (!texts[i] || !texts[i][0] || max_w <= 0)
            continue;
        ui_elide_text(texts[i], max_w, width, l->text, (int)sizeof l->text);
        if (!l->text[0])
            continue;
        l->x = x + margin;
        l->y = line_y;
        l->w = width(l->text);
        l->h = line_h;
        line_y += line_h + gap;
        out->bottom = line_y;
    }
}

int ui_elev_header_lines_overlap(const ui_elev_header_line *a, const ui_elev_header_line *b)
{
    if (!a->text[0] || !b->text[0])
        return 0;
    return a->x < b->x + b->w && b->x < a->x + a->w && a->y < b->y + b->h && b->y < a->y + a->h;
}
