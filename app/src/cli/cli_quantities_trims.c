/* The trim section of `tessera quantities`: per profile the edges it runs along, their metres,
 * the 2.5 m lengths to buy and the metres billed (app/design/trims.h). */
#include "cli_quantities_trims.h"

#include <stdio.h>
#include <string.h>

static const app_bom_line *line_of(const app_bom *b, const app_product_ref *ref)
{
    for (int k = b->line_count - 1; k >= 0; k--) /* trims are appended last */
        if (app_product_ref_equal(&b->lines[k].product, ref))
            return &b->lines[k];
    return NULL;
}

static void price(char *buf, size_t size, double cents)
{
    snprintf(buf, size, "%.2f", cents / 100.0);
}

void cli_print_trims(const app_trim_quantity *trims, int count, const app_bom *b, int csv)
{
    if (count <= 0)
        return;
    double piece_m = APP_TRIM_PIECE_MM / 1000.0;
    if (csv)
        puts("section,manufacturer,article,variant,name,edges,metres,piece_m,pieces,billed_m,"
             "piece_price,price_per_m,currency");
    else
        printf("\nTrim profiles (sold in %.1f m lengths)\n%-20s %-14s %-40s %5s %8s %6s %8s %10s "
               "%10s\n",
               piece_m, "manufacturer", "article", "name", "edges", "needed", "pieces", "billed",
               "per piece", "per m");
    for (int i = 0; i < count; i++) {
        const app_trim_quantity *t = &trims[i];
        const app_bom_line *l = line_of(b, &t->product);
        const char *name = l ? l->name : "";
        char each[32] = "", per_m[32] = "";
        if (l && l->found) {
            /* the catalog prices a metre (unit m) or one length (unit piece) */
            double length_cents =
                l->unit == CAT_UNIT_M ? l->unit_price_cents * piece_m : (double)l->unit_price_cents;
            price(each, sizeof each, length_cents);
            price(per_m, sizeof per_m, length_cents / piece_m);
        }
        double billed = app_trim_billed_metres(t);
        if (csv) {
            /* names come from the catalog: quote them as the other sections do */
            printf("trims,%s,%s,%s,\"", t->product.manufacturer, t->product.article,
                   t->product.variant);
            for (const char *s = name; *s; s++)
                printf(*s == '"' ? "\"\"" : "%c", *s);
            printf("\",%d,%.3f,%.1f,%d,%.3f,%s,%s,%s\n", t->edges, t->metres, piece_m, t->pieces,
                   billed, each, per_m, l ? l->currency : "");
        } else {
            printf("%-20.20s %-14.14s %-40.40s %5d %6.2f m %6d %6.2f m %10s %10s\n",
                   t->product.manufacturer, t->product.article, name, t->edges, t->metres,
                   t->pieces, billed, each, per_m);
        }
    }
}
