/* The quotation as a spreadsheet (app/output/quote.h app_quote_write_xlsx), written with
 * libxlsxwriter: the header (company, customer, number, date, validity), one row per position
 * with formulas for its net and VAT, the net total, the VAT per rate and the gross total, in the
 * project's currency. Every formula carries its value as computed here, so a reader that does
 * not recalculate shows the same figures as the PDF. Written beside the target and renamed over
 * it when complete. */
#include "app/output/quote.h"

#include <xlsxwriter.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum {
    COL_POS,
    COL_ARTICLE,
    COL_DESC,
    COL_QTY,
    COL_UNIT,
    COL_PRICE,
    COL_VAT_RATE,
    COL_NET,
    COL_VAT
};

static const char *kind_name(app_bom_kind k)
{
    return k == APP_BOM_LABOUR ? "Labour: " : "";
}

static void cell(lxw_row_t r, lxw_col_t c, char *buf, size_t size)
{
    lxw_rowcol_to_cell(buf, r, c);
    (void)size;
}

app_result app_quote_write_xlsx(const char *path, const app_project *p, const app_quote *q,
                                const app_bom *b, char *err, size_t err_size)
{
    if (!path || !p || !q || !b) {
        snprintf(err, err_size, "xlsx: nothing to write");
        return APP_ERR_SCHEMA;
    }
    char tmp[4200];
    if ((size_t)snprintf(tmp, sizeof tmp, "%s.part-%ld", path, (long)getpid()) >= sizeof tmp) {
        snprintf(err, err_size, "%s: path too long", path);
        return APP_ERR_IO;
    }
    /* The folder is checked first: libxlsxwriter only finds out when it closes the workbook,
     * and then prints its own message. */
    char dir[4200];
    const char *slash = strrchr(path, '/');
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path) + (slash == path) : 1,
             slash ? path : ".");
    if (access(dir, W_OK) != 0) {
        snprintf(err, err_size, "%s: cannot write: %s", path, strerror(errno));
        return APP_ERR_IO;
    }
    lxw_workbook *wb = workbook_new(tmp);
    if (!wb) {
        snprintf(err, err_size, "%s: cannot start the workbook (out of memory)", path);
        return APP_ERR_OUT_OF_MEMORY;
    }
    lxw_worksheet *ws = workbook_add_worksheet(wb, "Quotation");
    lxw_format *bold = workbook_add_format(wb);
    format_set_bold(bold);
    lxw_format *title = workbook_add_format(wb);
    format_set_bold(title);
    format_set_font_size(title, 16);
    lxw_format *head = workbook_add_format(wb);
    format_set_bold(head);
    format_set_bg_color(head, 0xE0E6EE);
    format_set_bottom(head, LXW_BORDER_THIN);
    /* Amounts in the project's currency: 1,234.50 EUR. */
    char money_fmt[64];
    snprintf(money_fmt, sizeof money_fmt, "#,##0.00 \"%s\"", b->currency[0] ? b->currency : "");
    lxw_format *money = workbook_add_format(wb);
    format_set_num_format(money, money_fmt);
    lxw_format *money_bold = workbook_add_format(wb);
    format_set_num_format(money_bold, money_fmt);
    format_set_bold(money_bold);
    format_set_top(money_bold, LXW_BORDER_THIN);
    lxw_format *qty_int = workbook_add_format(wb);
    format_set_num_format(qty_int, "0");
    lxw_format *qty_dec = workbook_add_format(wb);
    format_set_num_format(qty_dec, "0.00");
    lxw_format *pct = workbook_add_format(wb);
    format_set_num_format(pct, "0.0#");

    worksheet_set_column(ws, COL_POS, COL_POS, 5, NULL);
    worksheet_set_column(ws, COL_ARTICLE, COL_ARTICLE, 16, NULL);
    worksheet_set_column(ws, COL_DESC, COL_DESC, 52, NULL);
    worksheet_set_column(ws, COL_QTY, COL_QTY, 9, NULL);
    worksheet_set_column(ws, COL_UNIT, COL_UNIT, 6, NULL);
    worksheet_set_column(ws, COL_PRICE, COL_VAT, 14, NULL);

    lxw_row_t row = 0;
    if (q->has_company) {
        if (q->company.logo[0]) {
            lxw_image_options io = {.x_scale = 0.5, .y_scale = 0.5};
            worksheet_insert_image_opt(ws, 0, COL_NET, q->company.logo, &io);
        }
        worksheet_write_string(ws, row++, 0, q->company.name, title);
        for (int i = 0; i < q->company.line_count; i++)
            worksheet_write_string(ws, row++, 0, q->company.lines[i], NULL);
        row++;
    }
    const app_customer *cu = &q->customer;
    if (cu->name[0])
        worksheet_write_string(ws, row++, 0, cu->name, bold);
    for (int i = 0; i < cu->address_lines; i++)
        worksheet_write_string(ws, row++, 0, cu->address[i], NULL);
    if (cu->email[0])
        worksheet_write_string(ws, row++, 0, cu->email, NULL);
    if (cu->phone[0])
        worksheet_write_string(ws, row++, 0, cu->phone, NULL);
    row++;
    worksheet_write_string(ws, row++, 0, "Quotation", title);
    const char *labels[] = {"Quote number", "Date", "Valid until", "Project"};
    const char *values[] = {q->number, q->date, q->valid_until, p->name};
    for (int i = 0; i < 4; i++) {
        worksheet_write_string(ws, row, COL_POS, labels[i], bold);
        worksheet_write_string(ws, row++, COL_DESC, values[i], NULL);
    }
    row++;
    const char *heads[] = {"Pos",        "Article", "Description", "Quantity", "Unit",
                           "Unit price", "VAT %",   "Net",         "VAT"};
    for (int c = 0; c <= COL_VAT; c++)
        worksheet_write_string(ws, row, (lxw_col_t)c, heads[c], head);
    row++;
    lxw_row_t first = row;
    char f[256], bq[16], bp[16], bn[16], br[16];
    int pos = 0;
    for (int i = 0; i < b->line_count; i++) {
        const app_bom_line *l = &b->lines[i];
        if (l->foreign_currency || l->out_of_range)
            continue;
        char desc[300];
        snprintf(desc, sizeof desc, "%s%s%s%s", kind_name(l->kind), l->name,
                 l->detail[0] ? " (" : "", l->detail);
        if (l->detail[0])
            strncat(desc, ")", sizeof desc - strlen(desc) - 1);
        worksheet_write_number(ws, row, COL_POS, ++pos, NULL);
        worksheet_write_string(ws, row, COL_ARTICLE, l->product.article, NULL);
        worksheet_write_string(ws, row, COL_DESC, desc, NULL);
        int whole = l->unit != CAT_UNIT_M2 && fabs(l->quantity - round(l->quantity)) < 1e-9;
        worksheet_write_number(ws, row, COL_QTY, l->quantity, whole ? qty_int : qty_dec);
        worksheet_write_string(ws, row, COL_UNIT, cat_unit_name(l->unit), NULL);
        worksheet_write_number(ws, row, COL_PRICE, l->unit_price_cents / 100.0, money);
        worksheet_write_number(ws, row, COL_VAT_RATE, l->vat_percent, pct);
        cell(row, COL_QTY, bq, sizeof bq);
        cell(row, COL_PRICE, bp, sizeof bp);
        cell(row, COL_NET, bn, sizeof bn);
        cell(row, COL_VAT_RATE, br, sizeof br);
        snprintf(f, sizeof f, "=ROUND(%s*%s,2)", bq, bp);
        worksheet_write_formula_num(ws, row, COL_NET, f, money, l->net_cents / 100.0);
        snprintf(f, sizeof f, "=ROUND(%s*%s/100,2)", bn, br);
        worksheet_write_formula_num(ws, row, COL_VAT, f, money, l->vat_cents / 100.0);
        row++;
    }
    lxw_row_t last = row > first ? row - 1 : first;
    row++;
    char n0[16], n1[16], v0[16], v1[16];
    cell(first, COL_NET, n0, sizeof n0);
    cell(last, COL_NET, n1, sizeof n1);
    cell(first, COL_VAT, v0, sizeof v0);
    cell(last, COL_VAT, v1, sizeof v1);
    char r0[16], r1[16];
    cell(first, COL_VAT_RATE, r0, sizeof r0);
    cell(last, COL_VAT_RATE, r1, sizeof r1);
    lxw_row_t net_row = row;
    worksheet_write_string(ws, row, COL_PRICE, "Net total", bold);
    snprintf(f, sizeof f, "=SUM(%s:%s)", n0, n1);
    worksheet_write_formula_num(ws, row++, COL_NET, f, money, b->net_cents / 100.0);
    double rates[16];
    long long vat_by_rate[16];
    int nr = app_bom_vat_by_rate(b, rates, vat_by_rate, 16);
    lxw_row_t vat_first = row;
    for (int k = 0; k < nr; k++) {
        char label[48], pc[16];
        snprintf(label, sizeof label, "VAT %s %%", app_format_percent(rates[k], pc, sizeof pc));
        worksheet_write_string(ws, row, COL_PRICE, label, NULL);
        worksheet_write_number(ws, row, COL_VAT_RATE, rates[k], pct);
        char rc[16];
        cell(row, COL_VAT_RATE, rc, sizeof rc);
        snprintf(f, sizeof f, "=SUMIF(%s:%s,%s,%s:%s)", r0, r1, rc, v0, v1);
        worksheet_write_formula_num(ws, row++, COL_NET, f, money, vat_by_rate[k] / 100.0);
    }
    char nc[16], vc0[16], vc1[16];
    cell(net_row, COL_NET, nc, sizeof nc);
    cell(vat_first, COL_NET, vc0, sizeof vc0);
    cell(row > vat_first ? row - 1 : vat_first, COL_NET, vc1, sizeof vc1);
    char label[48];
    snprintf(label, sizeof label, "Total %s", b->currency);
    worksheet_write_string(ws, row, COL_PRICE, label, bold);
    if (nr > 0)
        snprintf(f, sizeof f, "=%s+SUM(%s:%s)", nc, vc0, vc1);
    else
        snprintf(f, sizeof f, "=%s", nc);
    worksheet_write_formula_num(ws, row++, COL_NET, f, money_bold, b->gross_cents / 100.0);
    row++;
    for (int i = 0; i < b->line_count; i++) {
        const app_bom_line *l = &b->lines[i];
        if (!l->foreign_currency && !l->out_of_range)
            continue;
        char why[400];
        snprintf(why, sizeof why, "Not in the total: %s %s (%s) is priced in %s, the quote in %s",
                 l->product.manufacturer, l->product.article, l->name, l->currency, b->currency);
        worksheet_write_string(ws, row++, COL_ARTICLE, why, NULL);
    }
    char valid[160];
    snprintf(valid, sizeof valid,
             "Prices are list prices without discount. This quotation is valid for %d days, until "
             "%s.",
             q->valid_days, q->valid_until);
    worksheet_write_string(ws, row++, COL_ARTICLE, valid, NULL);
    lxw_error e = workbook_close(wb);
    if (e != LXW_NO_ERROR) {
        snprintf(err, err_size, "%s: cannot write: %s%s%s", path, lxw_strerror(e),
                 errno ? ": " : "", errno ? strerror(errno) : "");
        unlink(tmp);
        return APP_ERR_IO;
    }
    if (rename(tmp, path) != 0) {
        snprintf(err, err_size, "%s: cannot write: %s", path, strerror(errno));
        unlink(tmp);
        return APP_ERR_IO;
    }
    return APP_OK;
}
