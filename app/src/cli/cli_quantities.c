/* tessera quantities PROJECT [--csv] [--surplus PCT] [--db PATH] [--offcuts] [--bench N]
 * tessera quantities --bench-mosaic [--bench N]
 * The tile part list (DOMAIN.md "What the best planners print": type, article and size, whole
 * and cut tiles, m2 / m / pieces, the amount to order with the surplus, offcut reuse) and the
 * priced bill of materials of a project; --bench times the re-layout of the project's tilings,
 * --bench-mosaic a large synthetic room (10 surfaces, 30 x 30 mm mosaic). docs/tiling.md.
 * The surfaces' regions come from the room model (app/design/room_surfaces.h: openings, niches,
 * pre-walls, the sloped ceiling). */
#include "app/cli/cli.h"
#include "app/design/quantities.h"
#include "app/design/room_surfaces.h"
#include "app/output/quote.h"
#include "cli_commands.h"
#include "cli_quantities.h"
#include "cli_quantities_json.h"
#include "cli_quantities_trims.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int cli_quantities_open_catalog(const char *db_path, cat_db **db)
{
    char path[4096], src[4096], err[4096];
    if (db_path)
        snprintf(path, sizeof path, "%s", db_path);
    else if (!cat_default_path(path, sizeof path)) {
        fprintf(stderr, "tessera quantities: no place for the catalog: set TESSERA_CATALOG or "
                        "HOME, or give --db PATH\n");
        return CLI_FAILED;
    }
    const char *env = getenv("TESSERA_ASSETS");
    snprintf(src, sizeof src, "%s/catalog", env && *env ? env : TESSERA_SOURCE_DIR "/assets");
    if (cat_catalog_open(path, src, db, err, sizeof err) != CAT_DB_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_FAILED;
    }
    return CLI_OK;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static void progress(int done, int total)
{
    if (total < 20 || !isatty(2))
        return;
    int w = 30, f = (int)((long)w * done / total);
    fprintf(stderr, "\r[%.*s%*s] %d/%d", f, "##############################", w - f, "", done,
            total);
    if (done == total)
        fputc('\n', stderr);
}

/* Prints "median (min..max) ms" of n timings. */
static void print_times(const char *what, double *ms, int n, long tiles)
{
    qsort(ms, (size_t)n, sizeof *ms, cmp_double);
    printf("%s: %ld tiles, median %.2f ms (min %.2f, max %.2f) over %d runs\n", what, tiles,
           ms[n / 2], ms[0], ms[n - 1], n);
}

/* A large room: an 8-corner plan (8 walls, floor, ceiling: 10 surfaces, 58.6 m2 of walls and
 * 2 x 18.5 m2) with a door and a window, tiled with a 27 x 27 mm mosaic on a 3 mm joint. */
static int bench_mosaic(int runs)
{
    app_point2 corners[8] = {{0, 0},       {5000, 0},    {5000, 2000}, {4000, 2000},
                             {4000, 3500}, {2000, 3500}, {2000, 4500}, {0, 4500}};
    app_opening op[2];
    memset(op, 0, sizeof op);
    snprintf(op[0].name, sizeof op[0].name, "door");
    op[0].type = APP_OPENING_DOOR, op[0].wall = 0, op[0].offset_mm = 800;
    op[0].width_mm = 900, op[0].height_mm = 2100;
    snprintf(op[1].name, sizeof op[1].name, "window");
    op[1].type = APP_OPENING_WINDOW, op[1].wall = 5, op[1].offset_mm = 500;
    op[1].width_mm = 1000, op[1].height_mm = 1200, op[1].sill_mm = 900;
    app_room_plan plan;
    memset(&plan, 0, sizeof plan);
    plan.corners = corners;
    plan.corner_count = 8;
    plan.height_mm = 2600;
    plan.wall_thickness_mm = 120;
    plan.openings = op;
    plan.opening_count = 2;
    app_tile_spec spec;
    memset(&spec, 0, sizeof spec);
    snprintf(spec.product.manufacturer, sizeof spec.product.manufacturer, "bench");
    snprintf(spec.product.article, sizeof spec.product.article, "mosaic-30");
    spec.work_w_mm = spec.work_h_mm = 27;
    spec.grout_mm = 3;
    spec.reusable_offcuts = spec.rotatable = 1;
    app_tiling t;
    memset(&t, 0, sizeof t);
    t.pattern = APP_PATTERN_STRAIGHT;
    t.align = APP_ALIGN_CORNER;
    t.grout_mm = 3;
    char err[1024];
    double *ms = malloc(sizeof *ms * (size_t)runs);
    if (!ms)
        return CLI_FAILED;
    long tiles = 0;
    app_tile_layout layouts[10];
    for (int r = 0; r < runs; r++) {
        double t0 = cli_now_ms();
        tiles = 0;
        for (int s = 0; s < 10; s++) {
            char name[32];
            if (s < 8)
                snprintf(name, sizeof name, "wall:%d", s);
            else
                snprintf(name, sizeof name, "%s", s == 8 ? "floor" : "ceiling");
            app_surface_region reg;
            app_tile_layout_desc d = {&reg, &t, &spec, NULL, 0};
            if (app_surface_region_from_plan(&plan, name, &reg, err, sizeof err) != APP_OK ||
                app_tile_layout_compute(&d, &layouts[s], err, sizeof err) != APP_OK) {
                fprintf(stderr, "tessera: %s\n", err);
                app_surface_region_free(&reg);
                free(ms);
                return CLI_FAILED;
            }
            app_surface_region_free(&reg);
            tiles += layouts[s].tile_count;
        }
        double t1 = cli_now_ms();
        ms[r] = t1 - t0;
        if (r + 1 < runs)
            for (int s = 0; s < 10; s++)
                app_tile_layout_free(&layouts[s]);
        progress(r + 1, runs);
    }
    print_times("mosaic layout, 10 surfaces", ms, runs, tiles);
    app_quantities q;
    double t0 = cli_now_ms();
    app_result res = app_quantities_compute(layouts, 10, NULL, &q, err, sizeof err);
    double qms = cli_now_ms() - t0;
    if (res == APP_OK) {
        printf("quantities: %d whole, %d cut, %d served by offcuts, %.2f m2 tiled; %.2f ms\n",
               q.lines[0].whole, q.lines[0].cut, q.lines[0].reused, q.tiled_area_m2, qms);
        app_quantities_free(&q);
    }
    for (int s = 0; s < 10; s++)
        app_tile_layout_free(&layouts[s]);
    free(ms);
    return res == APP_OK ? CLI_OK : CLI_FAILED;
}

static void money(char *buf, size_t size, long long cents)
{
    snprintf(buf, size, "%s%lld.%02lld", cents < 0 ? "-" : "", llabs(cents) / 100,
             llabs(cents) % 100);
}

/* CSV field: quoted when it holds a comma, quote or line break. */
static void csv_field(const char *s, int last)
{
    if (strpbrk(s, ",\"\n\r")) {
        putchar('"');
        for (; *s; s++) {
            if (*s == '"')
                putchar('"');
            putchar(*s);
        }
        putchar('"');
    } else
        fputs(s, stdout);
    putchar(last ? '\n' : ',');
}

static const char *type_name(app_tile_type t)
{
    static const char *const n[] = {"UNI", "BOR", "DEK", "EIN"};
    return (int)t >= 0 && (int)t < 4 ? n[t] : "?";
}

void cli_print_tiles(const app_quantities *q, const app_bom *b, int csv)
{
    if (csv) {
        puts("section,type,manufacturer,article,variant,name,work_w_mm,work_h_mm,whole,cut,"
             "reused,pieces_needed,area_m2,length_m,surplus_percent,pieces_with_surplus,boxes,"
             "pieces_to_order,order_m2");
        for (int i = 0; i < q->line_count; i++) {
            const app_tile_quantity *t = &q->lines[i];
            char num[512];
            csv_field("tiles", 0);
            csv_field(type_name(t->spec.type), 0);
            csv_field(t->spec.product.manufacturer, 0);
            csv_field(t->spec.product.article, 0);
            csv_field(t->spec.product.variant, 0);
            csv_field(i < b->line_count ? b->lines[i].name : "", 0);
            snprintf(num, sizeof num, "%g,%g,%d,%d,%d,%d,%.4f,%.3f,%g,%d,%d,%d,%.4f",
                     t->spec.work_w_mm, t->spec.work_h_mm, t->whole, t->cut, t->reused,
                     t->pieces_needed, t->area_m2, t->length_m, t->surplus_percent,
                     t->pieces_with_surplus, t->boxes, t->pieces_to_order, t->order_m2);
            puts(num);
        }
        return;
    }
    printf("Tile part list (surplus %g %%)\n", q->line_count ? q->lines[0].surplus_percent : 0);
    printf("%-4s %-20s %-12s %-34s %-11s %6s %5s %6s %8s %7s %7s %6s %8s\n", "type", "manufacturer",
           "article", "name", "work size", "whole", "cut", "reused", "laid", "needed", "+surpl",
           "boxes", "order");
    for (int i = 0; i < q->line_count; i++) {
        const app_tile_quantity *t = &q->lines[i];
        char size[32], laid[32], order[32];
        snprintf(size, sizeof size, "%gx%g", t->spec.work_w_mm, t->spec.work_h_mm);
        if (t->spec.type == APP_TILE_UNI)
            snprintf(laid, sizeof laid, "%.2f m2", t->area_m2);
        else
            snprintf(laid, sizeof laid, "%.2f m", t->length_m);
        int loose = i < b->line_count && b->lines[i].unit == CAT_UNIT_PIECE; /* sold per piece */
        snprintf(order, sizeof order, "%d pc", loose ? t->pieces_with_surplus : t->pieces_to_order);
        printf("%-4s %-20.20s %-12.12s %-34.34s %-11s %6d %5d %6d %8s %7d %7d %6d %8s",
               type_name(t->spec.type), t->spec.product.manufacturer, t->spec.product.article,
               i < b->line_count ? b->lines[i].name : "", size, t->whole, t->cut, t->reused, laid,
               t->pieces_needed, t->pieces_with_surplus, t->boxes, order);
        if (t->order_m2 > 0 && !loose)
            printf(" = %.2f m2", t->order_m2);
        putchar('\n');
    }
    printf("Tiled %.2f m2 of %.2f m2 (grout %.2f m2); %d cuts served by offcuts\n",
           q->tiled_area_m2, q->region_area_m2, q->grout_area_m2, q->offcut_count);
}

void cli_print_offcuts(const app_quantities *q, const app_tile_layout *layouts, int csv)
{
    if (csv)
        puts("section,article,source_surface,source_row,source_col,target_surface,target_row,"
             "target_col,piece_w_mm,piece_h_mm,rest_w_mm,rest_h_mm,rotated,piece_triangle,"
             "rest_triangle");
    else
        printf("\nOffcut reuse (the remainder of a cut tile serves another cut)\n");
    for (int i = 0; i < q->offcut_count; i++) {
        const app_offcut_use *u = &q->offcuts[i];
        const app_tile_layout *a = &layouts[u->source_layout], *b = &layouts[u->target_layout];
        const app_placed_tile *s = &a->tiles[u->source_tile], *t = &b->tiles[u->target_tile];
        const char *art = q->lines[u->product].spec.product.article;
        if (csv)
            printf("offcuts,%s,%s,%d,%d,%s,%d,%d,%.1f,%.1f,%.1f,%.1f,%d,%d,%d\n", art, a->surface,
                   s->row, s->col, b->surface, t->row, t->col, u->piece_w_mm, u->piece_h_mm,
                   u->rest_w_mm, u->rest_h_mm, u->rotated, u->piece_triangle, u->rest_triangle);
        else
            printf("  %-12s %s row %d col %d: rest %.0f x %.0f%s -> %s row %d col %d: piece %.0f x "
                   "%.0f%s%s\n",
                   art, a->surface, s->row, s->col, u->rest_w_mm, u->rest_h_mm,
                   u->rest_triangle ? " (half tile, legs)" : "", b->surface, t->row, t->col,
                   u->piece_w_mm, u->piece_h_mm, u->piece_triangle ? " (triangle, legs)" : "",
                   u->rotated ? " (turned)" : "");
    }
}

static const char *kind_name(app_bom_kind k)
{
    return k == APP_BOM_CONSUMABLE ? "consumable" : k == APP_BOM_LABOUR ? "labour" : "product";
}

void cli_print_consumables(const app_consumables *c, int csv)
{
    if (csv) {
        puts("section,what,amount,unit");
        printf("consumables,floor tiled,%.4f,m2\nconsumables,walls tiled,%.4f,m2\n", c->floor_m2,
               c->wall_m2);
        printf("consumables,adhesive,%.3f,kg\nconsumables,adhesive bags,%d,piece\n", c->adhesive_kg,
               c->adhesive_bags);
        printf("consumables,joint length,%.3f,m\nconsumables,joint volume,%.4f,dm3\n",
               c->joint_length_m, c->grout_dm3);
        printf("consumables,grout,%.3f,kg\nconsumables,grout bags,%d,piece\n", c->grout_kg,
               c->grout_bags);
        printf("consumables,edge joint,%.3f,m\nconsumables,silicone,%.1f,ml\n", c->edge_joint_m,
               c->silicone_ml);
        printf("consumables,silicone cartridges,%d,piece\n", c->silicone_cartridges);
        printf("consumables,waterproofing,%.4f,m2\nconsumables,fixtures,%d,piece\n",
               c->waterproofing_m2, c->fixtures);
        return;
    }
    printf("\nConsumables and labour (docs/tiling.md \"Consumables and labour\")\n");
    printf("  tiled: floor %.2f m2, walls %.2f m2\n", c->floor_m2, c->wall_m2);
    printf("  adhesive %.2f kg (%d bag%s)\n", c->adhesive_kg, c->adhesive_bags,
           c->adhesive_bags == 1 ? "" : "s");
    printf("  grout %.2f kg: %.3f dm3 of joint, %.1f m of joint (%d bag%s)\n", c->grout_kg,
           c->grout_dm3, c->joint_length_m, c->grout_bags, c->grout_bags == 1 ? "" : "s");
    printf("  edge joint %.2f m: silicone %.0f ml (%d cartridge%s)\n", c->edge_joint_m,
           c->silicone_ml, c->silicone_cartridges, c->silicone_cartridges == 1 ? "" : "s");
    printf("  waterproofing %.2f m2 (%d shower zone%s); %d product%s to install\n",
           c->waterproofing_m2, c->shower_zones, c->shower_zones == 1 ? "" : "s", c->fixtures,
           c->fixtures == 1 ? "" : "s");
}

void cli_print_quote_head(const app_quote *q, int csv)
{
    const app_customer *cu = &q->customer;
    if (csv) {
        puts("section,field,value");
        printf("quote,number,");
        csv_field(q->number, 1);
        printf("quote,date,%s\nquote,valid_days,%d\nquote,valid_until,%s\n", q->date, q->valid_days,
               q->valid_until);
        if (q->has_company) {
            printf("quote,company,");
            csv_field(q->company.name, 1);
        }
        if (cu->name[0]) {
            printf("quote,customer,");
            csv_field(cu->name, 1);
        }
        for (int i = 0; i < cu->address_lines; i++) {
            printf("quote,customer_address,");
            csv_field(cu->address[i], 1);
        }
        return;
    }
    printf("\nQuotation %s, %s, valid until %s (%d days)\n", q->number, q->date, q->valid_until,
           q->valid_days);
    if (q->has_company) {
        printf("  from: %s", q->company.name);
        for (int i = 0; i < q->company.line_count; i++)
            printf(", %s", q->company.lines[i]);
        putchar('\n');
    }
    if (cu->name[0] || cu->address_lines) {
        printf("  for: %s", cu->name);
        for (int i = 0; i < cu->address_lines; i++)
            printf(", %s", cu->address[i]);
        putchar('\n');
    }
}

void cli_print_bom(const app_bom *b, int csv)
{
    char up[32], net[32], vat[32], gross[32];
    if (csv)
        puts("section,manufacturer,article,variant,name,quantity,unit,unit_price,currency,"
             "vat_percent,net,vat,gross,position,kind,detail");
    else
        printf("\nBill of materials\n%3s %-20s %-14s %-40s %9s %-5s %10s %5s %11s %11s\n", "pos",
               "manufacturer", "article", "name", "quantity", "unit", "unit price", "VAT %", "net",
               "gross");
    for (int i = 0; i < b->line_count; i++) {
        const app_bom_line *l = &b->lines[i];
        money(up, sizeof up, l->unit_price_cents);
        money(net, sizeof net, l->net_cents);
        money(vat, sizeof vat, l->vat_cents);
        money(gross, sizeof gross, l->gross_cents);
        if (csv) {
            char q[64];
            csv_field("bom", 0);
            csv_field(l->product.manufacturer, 0);
            csv_field(l->product.article, 0);
            csv_field(l->product.variant, 0);
            csv_field(l->name, 0);
            snprintf(q, sizeof q, "%g", l->quantity);
            csv_field(q, 0);
            csv_field(cat_unit_name(l->unit), 0);
            csv_field(up, 0);
            csv_field(l->currency, 0);
            csv_field(app_format_percent(l->vat_percent, q, sizeof q), 0);
            csv_field(net, 0);
            csv_field(vat, 0);
            csv_field(gross, 0);
            snprintf(q, sizeof q, "%d", i + 1);
            csv_field(q, 0);
            csv_field(kind_name(l->kind), 0);
            csv_field(l->detail, 1);
        } else {
            char pc[16];
            printf("%3d %-20.20s %-14.14s %-40.40s %9.2f %-5s %10s %5s %11s %11s%s\n", i + 1,
                   l->product.manufacturer, l->product.article, l->name, l->quantity,
                   cat_unit_name(l->unit), up, app_format_percent(l->vat_percent, pc, sizeof pc),
                   net, gross, l->foreign_currency ? " (not in the total)" : "");
            if (l->detail[0])
                printf("%3s %s\n", "", l->detail);
        }
    }
    /* A line in another currency is refused, not converted (no rates): it is named with both
     * currencies, on stdout in the table and on stderr for scripts. */
    for (int i = 0; i < b->line_count; i++) {
        const app_bom_line *l = &b->lines[i];
        if (!l->foreign_currency)
            continue;
        char why[512];
        snprintf(why, sizeof why,
                 "%s %s (%s) is priced in %s, the project in %s: left out of the total",
                 l->product.manufacturer, l->product.article, l->name, l->currency, b->currency);
        if (csv) {
            csv_field("error", 0);
            csv_field(l->product.manufacturer, 0);
            csv_field(l->product.article, 0);
            csv_field(l->product.variant, 0);
            csv_field(why, 1);
        } else
            printf("error: %s\n", why);
        fprintf(stderr, "quantities: %s\n", why);
    }
    money(net, sizeof net, b->net_cents);
    money(vat, sizeof vat, b->vat_cents);
    money(gross, sizeof gross, b->gross_cents);
    if (csv)
        printf("total,,,,,,,,%s,,%s,%s,%s\n", b->currency, net, vat, gross);
    else {
        printf("Total net %s %s, VAT %s, gross %s %s\n", net, b->currency, vat, gross, b->currency);
        double rates[16];
        long long by_rate[16];
        int nr = app_bom_vat_by_rate(b, rates, by_rate, 16);
        for (int k = 0; k < nr; k++) {
            char pc[16], amount[32];
            money(amount, sizeof amount, by_rate[k]);
            printf("  VAT %s %%: %s %s\n", app_format_percent(rates[k], pc, sizeof pc), amount,
                   b->currency);
        }
        if (b->foreign)
            printf("%d line(s) in another currency than %s, not in the total\n", b->foreign,
                   b->currency);
        if (b->missing)
            printf("%d product(s) not in the catalog, priced 0\n", b->missing);
    }
}

/* Times the re-layout of a project: (1) everything from the project (catalog look-ups,
 * regions, layouts, quantities), as a first open does; (2) layouts and quantities alone with
 * the specs and regions kept, as after an edit in the UI. */
static int bench_project(const app_project *p, cat_db *db, int runs)
{
    char err[1024];
    double *ms = malloc(sizeof *ms * (size_t)runs * 2);
    int n = p->tiling_count;
    app_tile_spec *specs =
        calloc((size_t)(n > 0 ? n : 1) * (1 + APP_TILING_MAX_BORDERS), sizeof *specs);
    app_surface_region *regs = calloc((size_t)(n > 0 ? n : 1), sizeof *regs);
    app_tile_layout *ls = calloc((size_t)(n > 0 ? n : 1), sizeof *ls);
    int rc = CLI_FAILED;
    long tiles = 0;
    if (!ms || !specs || !regs || !ls)
        goto done;
    for (int r = 0; r < runs; r++) {
        app_tile_layout *l = NULL;
        int count = 0;
        app_quantities q;
        double t0 = cli_now_ms();
        app_result res = app_room_tile_layouts(p, db, &l, &count, err, sizeof err);
        if (res == APP_OK)
            res = app_quantities_compute(l, count, NULL, &q, err, sizeof err);
        ms[r] = cli_now_ms() - t0;
        if (res != APP_OK) {
            fprintf(stderr, "tessera: %s\n", err);
            goto done;
        }
        tiles = 0;
        for (int i = 0; i < count; i++)
            tiles += l[i].tile_count;
        app_quantities_free(&q);
        app_tile_layouts_free(l, count);
        progress(r + 1, 2 * runs);
    }
    print_times("from the project (catalog look-ups, regions, layouts, quantities)", ms, runs,
                tiles);
    for (int i = 0; i < n; i++) {
        const app_tiling *t = &p->tilings[i];
        app_tile_spec *s = &specs[i * (1 + APP_TILING_MAX_BORDERS)];
        if (app_tile_spec_from_catalog(db, &t->product, &s[0], NULL, err, sizeof err) != APP_OK)
            goto fail;
        for (int b = 0; b < t->border_count && b < APP_TILING_MAX_BORDERS; b++)
            if (app_tile_spec_from_catalog(db, &t->borders[b].product, &s[1 + b], NULL, err,
                                           sizeof err) != APP_OK)
                goto fail;
        if (app_room_region_provider(NULL, p, t->surface, &regs[i], err, sizeof err) != APP_OK)
            goto fail;
    }
    for (int r = 0; r < runs; r++) {
        double t0 = cli_now_ms();
        app_quantities q;
        for (int i = 0; i < n; i++) {
            app_tile_spec *s = &specs[i * (1 + APP_TILING_MAX_BORDERS)];
            app_tile_layout_desc d = {&regs[i], &p->tilings[i], &s[0], &s[1], 0};
            if (app_tile_layout_compute(&d, &ls[i], err, sizeof err) != APP_OK)
                goto fail;
        }
        if (app_quantities_compute(ls, n, NULL, &q, err, sizeof err) != APP_OK)
            goto fail;
        ms[runs + r] = cli_now_ms() - t0;
        app_quantities_free(&q);
        for (int i = 0; i < n; i++)
            app_tile_layout_free(&ls[i]);
        progress(runs + r + 1, 2 * runs);
    }
    print_times("re-layout after an edit (layouts + quantities, specs and regions kept)", ms + runs,
                runs, tiles);
    rc = CLI_OK;
    goto done;
fail:
    fprintf(stderr, "tessera: %s\n", err);
done:
    for (int i = 0; regs && i < n; i++)
        app_surface_region_free(&regs[i]);
    for (int i = 0; ls && i < n; i++)
        app_tile_layout_free(&ls[i]);
    free(regs);
    free(ls);
    free(specs);
    free(ms);
    return rc;
}

void cli_defaults_quantities(cli_options *o)
{
    o->surplus = 10.0;
}

int cli_cmd_quantities(const cli_options *o)
{
    int rc = CLI_OK;
    if (o->bench_mosaic)
        return bench_mosaic(o->bench_repeats > 0 ? o->bench_repeats : 5);
    if (!o->project)
        return cli_usage_error(o);
    if (o->csv_table && o->json_table) {
        fprintf(stderr, "tessera quantities: give --csv or --json, not both\n");
        return CLI_USAGE;
    }
    char err[2048];
    app_project p;
    app_flat flat;
    if (app_flat_read(o->project, &flat, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        return CLI_USAGE;
    }
    cat_db *db = NULL;
    if ((rc = cli_quantities_open_catalog(o->db, &db)) != CLI_OK) {
        app_flat_free(&flat);
        return rc;
    }
    if (flat.is_flat && o->bench_repeats <= 0) {
        rc = cli_quantities_flat(o, &flat, db);
        cat_db_close(db);
        app_flat_free(&flat);
        return rc;
    }
    app_flat_take_room(&flat, 0, &p); /* a single room (--bench times the first of a flat) */
    if (o->bench_repeats > 0) {
        rc = bench_project(&p, db, o->bench_repeats);
        cat_db_close(db);
        app_project_free(&p);
        return rc;
    }
    cli_room_quantities rq;
    app_result res = cli_room_quantities_compute(&p, db, o->surplus, &rq, err, sizeof err);
    app_quote quote;
    memset(&quote, 0, sizeof quote);
    if (res == APP_OK &&
        app_quote_make(&p, o->company, o->date, &quote, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        rc = CLI_USAGE;
        goto done;
    }
    if (res == APP_OK && o->xlsx &&
        app_quote_write_xlsx(o->xlsx, &p, &quote, &rq.bom, err, sizeof err) != APP_OK) {
        fprintf(stderr, "tessera: %s\n", err);
        rc = CLI_FAILED;
        goto done;
    }
    if (res == APP_OK && o->json_table) {
        rc = cli_quantities_json(stdout, &p, &rq, &quote, o->offcuts) ? CLI_OK : CLI_FAILED;
        goto done;
    }
    if (res != APP_OK) {
        fprintf(stderr, "tessera: %s: %s\n", o->project, err);
        rc = res == APP_ERR_OUT_OF_MEMORY || res == APP_ERR_IO ? CLI_FAILED : CLI_USAGE;
    } else {
        if (p.tiling_count == 0)
            fprintf(o->csv_table ? stderr : stdout,
                    "%s: no tilings yet (no surface of this project is tiled)\n", o->project);
        else
            cli_print_tiles(&rq.q, &rq.bom, o->csv_table);
        if (o->offcuts && p.tiling_count > 0)
            cli_print_offcuts(&rq.q, rq.layouts, o->csv_table);
        cli_print_trims(rq.trims, rq.trim_count, &rq.bom, o->csv_table);
        cli_print_consumables(&rq.cons, o->csv_table);
        cli_print_quote_head(&quote, o->csv_table);
        cli_print_bom(&rq.bom, o->csv_table);
    }
done:
    cli_room_quantities_free(&rq);
    cat_db_close(db);
    app_project_free(&p);
    return rc;
}
