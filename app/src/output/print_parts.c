/* The part list and quotation pages (DOMAIN.md "What the best planners print"): the tile part
 * list (tile swatch, type, brand and series, article and size, count with cut tiles, m2 or
 * running metres, amount to order with the surplus, unit price, total), the quotation of every
 * product with VAT and totals, and the offcut-reuse cut plan: which cut's remainder serves
 * which other cut. The rows flow over as many sheets as they need; the same flow counts the
 * sheets (draw = 0) and draws one of them. */
#include "print_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ROW_H 5.0
#define SWATCH_ROW_H 9.0
#define HEAD_H 9.0

typedef struct flow {
    pr_doc *d;
    int sheet; /* the sheet being drawn, -1 = only count */
    int at;    /* current sheet */
    double y;  /* current y on it */
    double top, bottom;
} flow;

static int drawing(const flow *f)
{
    return f->sheet == f->at;
}

/* Makes room for h mm; a new sheet when the current one is full. */
static void need(flow *f, double h)
{
    if (f->y + h > f->bottom) {
        f->at++;
        f->y = f->top;
    }
}

typedef struct col {
    const char *title;
    double width; /* fraction of the area's width */
    double align; /* 0 left, 1 right */
} col;

static void row_text(flow *f, const col *cols, int n, const char *const *cells, double h, int bold,
                     double x0)
{
    if (!drawing(f))
        return;
    cairo_t *cr = f->d->cr;
    double x = x0, w = f->d->area_w;
    pr_set_font(cr, PR_TEXT_SMALL, bold);
    cairo_set_source_rgb(cr, 0, 0, 0);
    for (int i = 0; i < n; i++) {
        double cw = cols[i].width * w;
        if (cells[i] && cells[i][0]) {
            /* Cut a cell's text that does not fit its column. */
            char buf[256];
            snprintf(buf, sizeof buf, "%s", cells[i]);
            while (strlen(buf) > 1 && pr_text_width(cr, buf) > cw - 2.0) {
                size_t l = strlen(buf);
                buf[l - 1] = 0;
                if (l >= 3)
                    memcpy(buf + l - 3, "..", 2);
            }
            double tx = cols[i].align > 0.5 ? x + cw - 1.0 : x + 1.0;
            pr_text(cr, tx, f->y + h / 2 + 0.9, cols[i].align, 1.0, buf);
        }
        x += cw;
    }
}

static void header(flow *f, const col *cols, int n)
{
    need(f, ROW_H * 3);
    if (drawing(f)) {
        cairo_t *cr = f->d->cr;
        cairo_rectangle(cr, f->d->area_x, f->y, f->d->area_w, ROW_H);
        cairo_set_source_rgb(cr, 0.88, 0.9, 0.93);
        cairo_fill(cr);
    }
    const char *cells[16];
    for (int i = 0; i < n && i < 16; i++)
        cells[i] = cols[i].title;
    row_text(f, cols, n, cells, ROW_H, 1, f->d->area_x);
    f->y += ROW_H;
}

static void rule(flow *f, double width)
{
    if (!drawing(f))
        return;
    cairo_t *cr = f->d->cr;
    cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
    cairo_set_line_width(cr, width);
    cairo_move_to(cr, f->d->area_x, f->y);
    cairo_line_to(cr, f->d->area_x + f->d->area_w, f->y);
    cairo_stroke(cr);
}

static void heading(flow *f, const char *text)
{
    need(f, HEAD_H + ROW_H * 3);
    if (drawing(f)) {
        pr_set_font(f->d->cr, PR_TEXT_LARGE + 0.5, 1);
        cairo_set_source_rgb(f->d->cr, 0, 0, 0);
        pr_text(f->d->cr, f->d->area_x, f->y + HEAD_H - 2.5, 0.0, 1.0, text);
    }
    f->y += HEAD_H;
}

static void note(flow *f, const char *text)
{
    need(f, ROW_H);
    if (drawing(f)) {
        pr_set_font(f->d->cr, PR_TEXT_SMALL, 0);
        cairo_set_source_rgb(f->d->cr, 0.3, 0.3, 0.3);
        pr_text(f->d->cr, f->d->area_x, f->y + ROW_H - 1.5, 0.0, 1.0, text);
        cairo_set_source_rgb(f->d->cr, 0, 0, 0);
    }
    f->y += ROW_H;
}

/* A tile's swatch: its texture (PNG) when the catalog names one that loads, else its colour. */
static void swatch(pr_doc *d, const app_tile_spec *spec, double x, double y, double size)
{
    cairo_t *cr = d->cr;
    int done = 0;
    if (spec->texture[0] && d->o->assets_dir) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", d->o->assets_dir, spec->texture);
        cairo_surface_t *img = cairo_image_surface_create_from_png(path);
        if (cairo_surface_status(img) == CAIRO_STATUS_SUCCESS) {
            int iw = cairo_image_surface_get_width(img), ih = cairo_image_surface_get_height(img);
            cairo_save(cr);
            cairo_rectangle(cr, x, y, size, size);
            cairo_clip(cr);
            double k = size / (iw < ih ? iw : ih);
            cairo_translate(cr, x, y);
            cairo_scale(cr, k, k);
            cairo_set_source_surface(cr, img, 0, 0);
            cairo_paint(cr);
            cairo_restore(cr);
            done = 1;
        }
        cairo_surface_destroy(img);
    }
    if (!done) {
        double rgb[3] = {0.85, 0.85, 0.85};
        cat_product prod;
        char err[256];
        if (d->db && cat_product_find(d->db, spec->product.manufacturer, spec->product.article,
                                      &prod, err, sizeof err) == CAT_DB_OK) {
            const cat_variant *var = prod.variant_count ? &prod.variants[0] : NULL;
            for (int i = 0; i < prod.variant_count; i++)
                if (spec->product.variant[0] &&
                    !strcmp(prod.variants[i].code, spec->product.variant))
                    var = &prod.variants[i];
            if (var)
                for (int k = 0; k < 3; k++)
                    rgb[k] = pow(fmin(fmax(var->material.diffuse[k], 0.0), 1.0), 1.0 / 2.2);
            cat_product_free(&prod);
        }
        cairo_rectangle(cr, x, y, size, size);
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_fill(cr);
    }
    cairo_rectangle(cr, x, y, size, size);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, PR_LINE_THIN);
    cairo_stroke(cr);
}

static const char *tile_type_name(app_tile_type t)
{
    static const char *const names[] = {"UNI", "BOR", "DEK", "EIN"};
    return t >= 0 && t <= APP_TILE_EIN ? names[t] : "";
}

static const app_bom_line *bom_line_of(const pr_doc *d, const app_product_ref *ref)
{
    if (!d->have_bom)
        return NULL;
    for (int i = 0; i < d->bom.line_count; i++)
        if (d->bom.lines[i].is_tile && app_product_ref_equal(&d->bom.lines[i].product, ref))
            return &d->bom.lines[i];
    return NULL;
}

static void tile_list(flow *f)
{
    pr_doc *d = f->d;
    static const col cols[] = {
        {"", 0.05, 0},        {"Type", 0.05, 0},       {"Brand / series", 0.15, 0},
        {"Article", 0.09, 0}, {"Size mm", 0.08, 0},    {"Tiles", 0.06, 1},
        {"cut", 0.05, 1},     {"reused", 0.06, 1},     {"Laid", 0.08, 1},
        {"Order", 0.16, 1},   {"Unit price", 0.08, 1}, {"Total", 0.09, 1}};
    const int nc = (int)(sizeof cols / sizeof cols[0]);
    heading(f, "Tile part list");
    if (!d->have_quantities || d->q.line_count == 0) {
        note(f, d->p->tiling_count ? "The tile quantities could not be computed (see stderr)."
                                   : "The project has no tiled surfaces.");
        return;
    }
    header(f, cols, nc);
    for (int i = 0; i < d->q.line_count; i++) {
        const app_tile_quantity *t = &d->q.lines[i];
        const app_bom_line *b = bom_line_of(d, &t->spec.product);
        need(f, SWATCH_ROW_H);
        char size[48], tiles[16], cut[16], reused[16], laid[32], order[64], unit[80], total[48],
            brand[160];
        snprintf(size, sizeof size, "%.0f x %.0f", t->spec.work_w_mm, t->spec.work_h_mm);
        snprintf(tiles, sizeof tiles, "%d", t->whole + t->cut);
        snprintf(cut, sizeof cut, "%d", t->cut);
        snprintf(reused, sizeof reused, "%d", t->reused);
        if (t->length_m > 0)
            snprintf(laid, sizeof laid, "%.2f m", t->length_m);
        else
            snprintf(laid, sizeof laid, "%.2f m2", t->area_m2);
        if (b && b->unit == CAT_UNIT_PIECE) /* sold loose: app_tile_billed_quantity */
            snprintf(order, sizeof order, "%d pcs +%.0f%%", t->pieces_with_surplus,
                     t->surplus_percent);
        else if (t->boxes > 0)
            snprintf(order, sizeof order, "%d box%s, %d pcs +%.0f%%", t->boxes,
                     t->boxes == 1 ? "" : "es", t->pieces_to_order, t->surplus_percent);
        else
            snprintf(order, sizeof order, "%d pcs +%.0f%%", t->pieces_to_order, t->surplus_percent);
        unit[0] = total[0] = 0;
        snprintf(brand, sizeof brand, "%s", t->spec.product.manufacturer);
        if (b) {
            char money[48];
            pr_format_money(b->unit_price_cents, money, sizeof money);
            snprintf(unit, sizeof unit, "%s/%s", money, cat_unit_name(b->unit));
            pr_format_money(b->net_cents, total, sizeof total);
            if (b->series[0])
                snprintf(brand, sizeof brand, "%s %s", t->spec.product.manufacturer, b->series);
        }
        if (drawing(f))
            swatch(d, &t->spec, d->area_x + 1.0, f->y + 1.0, SWATCH_ROW_H - 2.0);
        const char *cells[] = {"",    tile_type_name(t->spec.type),
                               brand, t->spec.product.article,
                               size,  tiles,
                               cut,   reused,
                               laid,  order,
                               unit,  total};
        row_text(f, cols, nc, cells, SWATCH_ROW_H, 0, d->area_x);
        f->y += SWATCH_ROW_H;
        rule(f, PR_LINE_THIN);
    }
    char text[256];
    snprintf(text, sizeof text,
             "Tiled %.2f m2 (grout %.2f m2). Order amounts include the surplus for cutting and "
             "breakage and are rounded up to whole boxes, except for products priced per piece, "
             "which are ordered and billed loose.",
             d->q.tiled_area_m2, d->q.grout_area_m2);
    note(f, text);
}

/* A logo (PNG) fitted into w x h mm at (x, y); nothing when it does not load. */
static void logo(cairo_t *cr, const char *path, double x, double y, double w, double h)
{
    cairo_surface_t *img = cairo_image_surface_create_from_png(path);
    if (cairo_surface_status(img) == CAIRO_STATUS_SUCCESS) {
        int iw = cairo_image_surface_get_width(img), ih = cairo_image_surface_get_height(img);
        double k = fmin(w / iw, h / ih);
        cairo_save(cr);
        cairo_translate(cr, x, y);
        cairo_scale(cr, k, k);
        cairo_set_source_surface(cr, img, 0, 0);
        cairo_paint(cr);
        cairo_restore(cr);
    }
    cairo_surface_destroy(img);
}

/* The quotation's head: the company (logo, name, address) on the left, the customer on the
 * right, then the quote number, date and validity. */
static void quote_head(flow *f)
{
    pr_doc *d = f->d;
    const app_quote *q = &d->quote;
    const app_customer *cu = &q->customer;
    int left = q->has_company ? 1 + q->company.line_count : 0;
    int right =
        (cu->name[0] ? 1 : 0) + cu->address_lines + (cu->email[0] != 0) + (cu->phone[0] != 0);
    double logo_h = q->has_company && q->company.logo[0] ? 12.0 : 0.0;
    double line = 3.4, h = fmax(logo_h + left * line, (right ? right + 1 : 0) * line) + 2 * line;
    need(f, h + ROW_H * 3);
    if (drawing(f)) {
        cairo_t *cr = d->cr;
        double x = d->area_x, y = f->y;
        cairo_set_source_rgb(cr, 0, 0, 0);
        if (logo_h > 0)
            logo(cr, q->company.logo, x, y, 40.0, logo_h - 1.0);
        double ly = y + logo_h + line;
        if (q->has_company) {
            pr_set_font(cr, PR_TEXT_NORMAL, 1);
            pr_text(cr, x, ly, 0.0, 1.0, q->company.name);
            pr_set_font(cr, PR_TEXT_SMALL, 0);
            for (int i = 0; i < q->company.line_count; i++)
                pr_text(cr, x, ly + (i + 1) * line, 0.0, 1.0, q->company.lines[i]);
        }
        double rx = d->area_x + d->area_w * 0.6, ry = y + line;
        if (right) {
            pr_set_font(cr, PR_TEXT_SMALL, 1);
            pr_text(cr, rx, ry, 0.0, 1.0, "Customer");
            ry += line;
            if (cu->name[0]) {
                pr_set_font(cr, PR_TEXT_NORMAL, 1);
                pr_text(cr, rx, ry, 0.0, 1.0, cu->name);
                ry += line;
            }
            pr_set_font(cr, PR_TEXT_SMALL, 0);
            for (int i = 0; i < cu->address_lines; i++, ry += line)
                pr_text(cr, rx, ry, 0.0, 1.0, cu->address[i]);
            if (cu->email[0])
                pr_text(cr, rx, ry, 0.0, 1.0, cu->email), ry += line;
            if (cu->phone[0])
                pr_text(cr, rx, ry, 0.0, 1.0, cu->phone), ry += line;
        }
    }
    f->y += h - line;
    char text[256];
    snprintf(text, sizeof text, "Quote no. %s      Date %s      Valid until %s (%d days)",
             q->number, q->date, q->valid_until, q->valid_days);
    need(f, ROW_H);
    if (drawing(f)) {
        pr_set_font(d->cr, PR_TEXT_NORMAL, 1);
        cairo_set_source_rgb(d->cr, 0, 0, 0);
        pr_text(d->cr, d->area_x, f->y + ROW_H - 1.5, 0.0, 1.0, text);
    }
    f->y += ROW_H + 1.0;
}

static void quotation(flow *f)
{
    pr_doc *d = f->d;
    static const col cols[] = {{"Pos", 0.05, 0},   {"Article", 0.11, 0},  {"Description", 0.37, 0},
                               {"Qty", 0.08, 1},   {"Unit", 0.06, 0},     {"Unit price", 0.11, 1},
                               {"VAT %", 0.07, 1}, {"Net total", 0.15, 1}};
    const int nc = (int)(sizeof cols / sizeof cols[0]);
    heading(f, "Quotation");
    quote_head(f);
    if (!d->have_bom || d->bom.line_count == 0) {
        note(f, d->have_bom ? "No catalog products are placed in this project."
                            : "No prices: the catalog could not be opened.");
        return;
    }
    header(f, cols, nc);
    for (int i = 0; i < d->bom.line_count; i++) {
        const app_bom_line *b = &d->bom.lines[i];
        double row_h = b->detail[0] ? ROW_H + 2.6 : ROW_H;
        int sheet = f->at;
        need(f, row_h);
        if (f->at != sheet) /* a continued list repeats its column heads */
            header(f, cols, nc);
        char pos[16], qty[32], unit_price[48], vat[16], net[48], desc[260], numbers[64];
        snprintf(pos, sizeof pos, "%d", i + 1);
        if (b->unit == CAT_UNIT_PIECE || b->unit == CAT_UNIT_BOX)
            snprintf(qty, sizeof qty, "%.0f", b->quantity);
        else
            snprintf(qty, sizeof qty, "%.2f", b->quantity);
        pr_format_money(b->unit_price_cents, unit_price, sizeof unit_price);
        app_format_percent(b->vat_percent, vat, sizeof vat);
        pr_format_money(b->net_cents, net, sizeof net);
        if (b->foreign_currency)
            snprintf(desc, sizeof desc, "ERROR priced in %s, not %s: not in the total. %s",
                     b->currency, d->bom.currency, b->name);
        else if (b->found && !b->is_tile &&
                 pr_fixture_numbers_text(d, &b->product, numbers, sizeof numbers) > 0)
            snprintf(desc, sizeof desc, "No. %s: %s", numbers, b->name); /* as on the plan */
        else if (b->found)
            snprintf(desc, sizeof desc, "%s", b->name);
        else
            snprintf(desc, sizeof desc, "(not in the catalog) %s", b->product.manufacturer);
        const char *cells[] = {
            pos, b->product.article, desc, qty, cat_unit_name(b->unit), unit_price, vat, net};
        row_text(f, cols, nc, cells, ROW_H, 0, d->area_x);
        if (b->detail[0] && drawing(f)) {
            /* How the amount came about, under the description. */
            pr_set_font(d->cr, 1.6, 0);
            cairo_set_source_rgb(d->cr, 0.35, 0.35, 0.35);
            double x = d->area_x + (cols[0].width + cols[1].width) * d->area_w + 1.0;
            pr_text(d->cr, x, f->y + ROW_H + 1.2, 0.0, 1.0, b->detail);
            cairo_set_source_rgb(d->cr, 0, 0, 0);
        }
        f->y += row_h;
        rule(f, PR_LINE_THIN);
    }
    /* Totals: net, VAT by rate, gross. */
    double rates[16];
    long long vat_by_rate[16];
    int nr = app_bom_vat_by_rate(&d->bom, rates, vat_by_rate, 16);
    static const col tcols[] = {{"", 0.70, 0}, {"", 0.15, 1}, {"", 0.15, 1}};
    const char *cur = d->bom.currency[0] ? d->bom.currency : "";
    char money[48], label[64];
    need(f, ROW_H * (2 + nr));
    pr_format_money(d->bom.net_cents, money, sizeof money);
    const char *c1[] = {"", "Net total", money};
    row_text(f, tcols, 3, c1, ROW_H, 0, d->area_x);
    f->y += ROW_H;
    for (int k = 0; k < nr; k++) {
        pr_format_money(vat_by_rate[k], money, sizeof money);
        char pc[16];
        snprintf(label, sizeof label, "VAT %s %%", app_format_percent(rates[k], pc, sizeof pc));
        const char *c2[] = {"", label, money};
        row_text(f, tcols, 3, c2, ROW_H, 0, d->area_x);
        f->y += ROW_H;
    }
    rule(f, PR_LINE_MEDIUM);
    pr_format_money(d->bom.gross_cents, money, sizeof money);
    snprintf(label, sizeof label, "Total %s", cur);
    const char *c3[] = {"", label, money};
    row_text(f, tcols, 3, c3, ROW_H + 1.0, 1, d->area_x);
    f->y += ROW_H + 1.0;
    if (d->bom.missing) {
        char text[128];
        snprintf(text, sizeof text, "%d product%s not in the catalog: priced at 0.", d->bom.missing,
                 d->bom.missing == 1 ? "" : "s");
        note(f, text);
    }
    if (d->bom.foreign) {
        char text[128];
        snprintf(text, sizeof text,
                 "%d line%s priced in another currency than %s: not in the totals (no exchange "
                 "rate).",
                 d->bom.foreign, d->bom.foreign == 1 ? "" : "s", d->bom.currency);
        note(f, text);
    }
    char text[200];
    snprintf(text, sizeof text,
             "Prices are list prices without discount. This quotation is valid for %d days, until "
             "%s.",
             d->quote.valid_days, d->quote.valid_until);
    note(f, text);
}

/* One offcut use as a small drawing: the source tile, the piece its first cut took (grey),
 * the remainder (tinted) and the piece cut from it for the other place (outlined). */
static void cut_diagram(pr_doc *d, const app_offcut_use *u, double x, double y, double box)
{
    cairo_t *cr = d->cr;
    const app_tile_quantity *t = &d->q.lines[u->product];
    double tw = t->spec.work_w_mm, th = t->spec.work_h_mm;
    double k = box / (tw > th ? tw : th);
    cairo_rectangle(cr, x, y, tw * k, th * k);
    cairo_set_source_rgb(cr, 0.82, 0.82, 0.82);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, PR_LINE_FINE);
    cairo_stroke(cr);
    /* The remainder at the tile's right or top, as the rest of a straight cut. */
    double rw = u->rest_w_mm * k, rh = u->rest_h_mm * k;
    double rx = x + tw * k - rw, ry = y;
    cairo_rectangle(cr, rx, ry, rw, rh);
    cairo_set_source_rgb(cr, 0.75, 0.88, 0.75);
    cairo_fill(cr);
    double pw = (u->rotated ? u->piece_h_mm : u->piece_w_mm) * k;
    double ph = (u->rotated ? u->piece_w_mm : u->piece_h_mm) * k;
    cairo_rectangle(cr, rx, ry, pw < rw ? pw : rw, ph < rh ? ph : rh);
    cairo_set_source_rgb(cr, 0.1, 0.45, 0.1);
    cairo_set_line_width(cr, PR_LINE_MEDIUM);
    cairo_stroke(cr);
}

/* The cut plan as a grid of cells, each one use: the diagram, the article, where the
 * remainder comes from and which cut it serves (tile numbers as printed on the elevations). */
static void offcut_plan(flow *f)
{
    pr_doc *d = f->d;
    heading(f, "Offcut reuse: cut plan");
    if (!d->have_quantities || d->q.offcut_count == 0) {
        note(f, d->have_quantities ? "No remainder of a cut tile serves another cut here."
                                   : "No tile quantities.");
        return;
    }
    note(f, "Each cell: the tile (grey), the remainder kept from its cut (green), the piece cut "
            "from that remainder for another place (outlined). Tile numbers as on the elevations.");
    const double cell_w = 52.0, cell_h = 13.0;
    int per_row = (int)(d->area_w / cell_w);
    if (per_row < 1)
        per_row = 1;
    for (int i = 0; i < d->q.offcut_count; i += per_row) {
        need(f, cell_h);
        for (int j = 0; j < per_row && i + j < d->q.offcut_count; j++) {
            const app_offcut_use *u = &d->q.offcuts[i + j];
            if (!drawing(f) || u->product < 0 || u->product >= d->q.line_count)
                continue;
            double x = d->area_x + j * cell_w, y = f->y;
            cut_diagram(d, u, x + 1.0, y + 1.5, cell_h - 3.0);
            const char *ss = u->source_layout >= 0 && u->source_layout < d->layout_count
                                 ? d->layouts[u->source_layout].surface
                                 : "?";
            const char *ts = u->target_layout >= 0 && u->target_layout < d->layout_count
                                 ? d->layouts[u->target_layout].surface
                                 : "?";
            char l1[96], l2[128], l3[128];
            snprintf(l1, sizeof l1, "%s%s", d->q.lines[u->product].spec.product.article,
                     u->rotated ? "  (turn 90)" : "");
            snprintf(l2, sizeof l2, "from %s #%d: rest %.0f x %.0f", ss, u->source_tile + 1,
                     u->rest_w_mm, u->rest_h_mm);
            snprintf(l3, sizeof l3, "to %s #%d: %.0f x %.0f", ts, u->target_tile + 1, u->piece_w_mm,
                     u->piece_h_mm);
            cairo_t *cr = d->cr;
            cairo_set_source_rgb(cr, 0, 0, 0);
            pr_set_font(cr, 1.8, 1);
            pr_text(cr, x + 12.0, y + 3.6, 0.0, 1.0, l1);
            pr_set_font(cr, 1.5, 0);
            pr_text(cr, x + 12.0, y + 7.0, 0.0, 1.0, l2);
            pr_text(cr, x + 12.0, y + 10.2, 0.0, 1.0, l3);
        }
        f->y += cell_h;
        rule(f, PR_LINE_THIN);
    }
}

static int run(pr_doc *d, int sheet)
{
    flow f = {.d = d, .sheet = sheet, .at = 0};
    /* The drawing area is the same on every sheet of one paper. */
    f.top = 14.0 + 0.0;
    f.bottom = d->page_h - 10.0 - 16.0 - 4.0;
    f.y = f.top;
    tile_list(&f);
    /* The quotation is the customer's document: it starts on a sheet of its own. */
    if (f.y > f.top) {
        f.at++;
        f.y = f.top;
    }
    quotation(&f);
    /* The cut plan is the tiler's: a sheet of its own, apart from the customer's quotation. */
    f.at++;
    f.y = f.top;
    offcut_plan(&f);
    return f.at + 1;
}

int pr_parts_page_count(pr_doc *d)
{
    return run(d, -1);
}

app_result pr_draw_parts(pr_doc *d, int sheet)
{
    app_result r = pr_page_begin(d, "Part list and quotation", 0);
    if (r != APP_OK)
        return r;
    run(d, sheet);
    if (d->report)
        d->report->partlist_pages++;
    return pr_page_end(d);
}
