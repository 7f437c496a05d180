/* `tessera quantities --json` (cli_quantities_json.h). Amounts of money are integers in cents
 * with the currency beside them, so no reader rounds them again. */
#include "cli_quantities_json.h"

#include <cjson/cJSON.h>

#include <stdlib.h>

static const char *tile_type(app_tile_type t)
{
    static const char *const n[] = {"UNI", "BOR", "DEK", "EIN"};
    return (int)t >= 0 && (int)t < 4 ? n[t] : "?";
}

static const char *kind_name(app_bom_kind k)
{
    return k == APP_BOM_CONSUMABLE ? "consumable" : k == APP_BOM_LABOUR ? "labour" : "product";
}

static cJSON *ref_json(const app_product_ref *r)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "manufacturer", r->manufacturer);
    cJSON_AddStringToObject(o, "article", r->article);
    cJSON_AddStringToObject(o, "variant", r->variant);
    return o;
}

static cJSON *tiles_json(const app_quantities *q, const app_tile_layout *layouts)
{
    cJSON *o = cJSON_CreateObject(), *lines = cJSON_AddArrayToObject(o, "lines");
    for (int i = 0; i < q->line_count; i++) {
        const app_tile_quantity *t = &q->lines[i];
        cJSON *l = cJSON_CreateObject();
        cJSON_AddItemToObject(l, "product", ref_json(&t->spec.product));
        cJSON_AddStringToObject(l, "type", tile_type(t->spec.type));
        cJSON_AddNumberToObject(l, "work_w_mm", t->spec.work_w_mm);
        cJSON_AddNumberToObject(l, "work_h_mm", t->spec.work_h_mm);
        cJSON_AddNumberToObject(l, "whole", t->whole);
        cJSON_AddNumberToObject(l, "cut", t->cut);
        cJSON_AddNumberToObject(l, "reused", t->reused);
        cJSON_AddNumberToObject(l, "pieces_needed", t->pieces_needed);
        cJSON_AddNumberToObject(l, "area_m2", t->area_m2);
        cJSON_AddNumberToObject(l, "length_m", t->length_m);
        cJSON_AddNumberToObject(l, "surplus_percent", t->surplus_percent);
        cJSON_AddNumberToObject(l, "pieces_with_surplus", t->pieces_with_surplus);
        cJSON_AddNumberToObject(l, "boxes", t->boxes);
        cJSON_AddNumberToObject(l, "pieces_to_order", t->pieces_to_order);
        cJSON_AddNumberToObject(l, "order_m2", t->order_m2);
        cJSON_AddItemToArray(lines, l);
    }
    cJSON_AddNumberToObject(o, "region_m2", q->region_area_m2);
    cJSON_AddNumberToObject(o, "tiled_m2", q->tiled_area_m2);
    cJSON_AddNumberToObject(o, "grout_m2", q->grout_area_m2);
    if (layouts) {
        cJSON *uses = cJSON_AddArrayToObject(o, "offcuts");
        for (int i = 0; i < q->offcut_count; i++) {
            const app_offcut_use *u = &q->offcuts[i];
            cJSON *j = cJSON_CreateObject();
            cJSON_AddStringToObject(j, "article", q->lines[u->product].spec.product.article);
            cJSON_AddStringToObject(j, "source", layouts[u->source_layout].surface);
            cJSON_AddNumberToObject(j, "source_tile", u->source_tile + 1);
            cJSON_AddStringToObject(j, "target", layouts[u->target_layout].surface);
            cJSON_AddNumberToObject(j, "target_tile", u->target_tile + 1);
            cJSON_AddNumberToObject(j, "piece_w_mm", u->piece_w_mm);
            cJSON_AddNumberToObject(j, "piece_h_mm", u->piece_h_mm);
            cJSON_AddBoolToObject(j, "rotated", u->rotated);
            cJSON_AddItemToArray(uses, j);
        }
    }
    return o;
}

static cJSON *consumables_json(const app_consumables *c)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "floor_m2", c->floor_m2);
    cJSON_AddNumberToObject(o, "wall_m2", c->wall_m2);
    cJSON_AddNumberToObject(o, "adhesive_kg", c->adhesive_kg);
    cJSON_AddNumberToObject(o, "adhesive_bags", c->adhesive_bags);
    cJSON_AddNumberToObject(o, "joint_length_m", c->joint_length_m);
    cJSON_AddNumberToObject(o, "grout_dm3", c->grout_dm3);
    cJSON_AddNumberToObject(o, "grout_kg", c->grout_kg);
    cJSON_AddNumberToObject(o, "grout_bags", c->grout_bags);
    cJSON_AddNumberToObject(o, "edge_joint_m", c->edge_joint_m);
    cJSON_AddNumberToObject(o, "silicone_ml", c->silicone_ml);
    cJSON_AddNumberToObject(o, "silicone_cartridges", c->silicone_cartridges);
    cJSON_AddNumberToObject(o, "waterproofing_m2", c->waterproofing_m2);
    cJSON_AddNumberToObject(o, "shower_zones", c->shower_zones);
    cJSON_AddNumberToObject(o, "fixtures", c->fixtures);
    return o;
}

static cJSON *quote_json(const app_quote *q)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "number", q->number);
    cJSON_AddStringToObject(o, "date", q->date);
    cJSON_AddNumberToObject(o, "valid_days", q->valid_days);
    cJSON_AddStringToObject(o, "valid_until", q->valid_until);
    if (q->has_company) {
        cJSON *c = cJSON_AddObjectToObject(o, "company");
        cJSON_AddStringToObject(c, "name", q->company.name);
        cJSON *lines = cJSON_AddArrayToObject(c, "lines");
        for (int i = 0; i < q->company.line_count; i++)
            cJSON_AddItemToArray(lines, cJSON_CreateString(q->company.lines[i]));
        cJSON_AddStringToObject(c, "logo", q->company.logo);
    }
    const app_customer *cu = &q->customer;
    cJSON *c = cJSON_AddObjectToObject(o, "customer");
    cJSON_AddStringToObject(c, "name", cu->name);
    cJSON *addr = cJSON_AddArrayToObject(c, "address");
    for (int i = 0; i < cu->address_lines; i++)
        cJSON_AddItemToArray(addr, cJSON_CreateString(cu->address[i]));
    cJSON_AddStringToObject(c, "email", cu->email);
    cJSON_AddStringToObject(c, "phone", cu->phone);
    return o;
}

static cJSON *bom_json(const app_bom *b)
{
    cJSON *o = cJSON_CreateObject(), *lines = cJSON_AddArrayToObject(o, "lines");
    cJSON_AddStringToObject(o, "currency", b->currency);
    for (int i = 0; i < b->line_count; i++) {
        const app_bom_line *l = &b->lines[i];
        cJSON *j = cJSON_CreateObject();
        cJSON_AddNumberToObject(j, "position", i + 1);
        cJSON_AddStringToObject(j, "kind", kind_name(l->kind));
        cJSON_AddItemToObject(j, "product", ref_json(&l->product));
        cJSON_AddStringToObject(j, "name", l->name);
        cJSON_AddStringToObject(j, "detail", l->detail);
        cJSON_AddBoolToObject(j, "found", l->found);
        cJSON_AddNumberToObject(j, "quantity", l->quantity);
        cJSON_AddStringToObject(j, "unit", cat_unit_name(l->unit));
        cJSON_AddNumberToObject(j, "unit_price_cents", (double)l->unit_price_cents);
        cJSON_AddNumberToObject(j, "vat_percent", l->vat_percent);
        cJSON_AddNumberToObject(j, "net_cents", (double)l->net_cents);
        cJSON_AddNumberToObject(j, "vat_cents", (double)l->vat_cents);
        cJSON_AddNumberToObject(j, "gross_cents", (double)l->gross_cents);
        cJSON_AddStringToObject(j, "currency", l->currency);
        cJSON_AddBoolToObject(j, "in_total", !l->foreign_currency && !l->out_of_range);
        cJSON_AddItemToArray(lines, j);
    }
    cJSON_AddNumberToObject(o, "net_cents", (double)b->net_cents);
    double rates[16];
    long long vat[16];
    int nr = app_bom_vat_by_rate(b, rates, vat, 16);
    cJSON *by_rate = cJSON_AddArrayToObject(o, "vat_by_rate");
    for (int k = 0; k < nr; k++) {
        cJSON *r = cJSON_CreateObject();
        cJSON_AddNumberToObject(r, "percent", rates[k]);
        cJSON_AddNumberToObject(r, "vat_cents", (double)vat[k]);
        cJSON_AddItemToArray(by_rate, r);
    }
    cJSON_AddNumberToObject(o, "vat_cents", (double)b->vat_cents);
    cJSON_AddNumberToObject(o, "gross_cents", (double)b->gross_cents);
    cJSON_AddNumberToObject(o, "missing", b->missing);
    cJSON_AddNumberToObject(o, "foreign", b->foreign);
    return o;
}

static cJSON *trims_json(const cli_room_quantities *r)
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; i < r->trim_count; i++) {
        const app_trim_quantity *t = &r->trims[i];
        cJSON *j = cJSON_CreateObject();
        cJSON_AddItemToObject(j, "product", ref_json(&t->product));
        cJSON_AddNumberToObject(j, "edges", t->edges);
        cJSON_AddNumberToObject(j, "metres", t->metres);
        cJSON_AddNumberToObject(j, "piece_m", APP_TRIM_PIECE_MM / 1000.0);
        cJSON_AddNumberToObject(j, "pieces", t->pieces);
        cJSON_AddNumberToObject(j, "billed_m", app_trim_billed_metres(t));
        cJSON_AddItemToArray(a, j);
    }
    return a;
}

/* The members of one room's (or the flat total's) document. */
static void add_room(cJSON *o, const cli_room_quantities *r, int offcuts)
{
    cJSON_AddItemToObject(o, "tiles", tiles_json(&r->q, offcuts ? r->layouts : NULL));
    cJSON_AddItemToObject(o, "trims", trims_json(r));
    cJSON_AddItemToObject(o, "consumables", consumables_json(&r->cons));
}

static int write_doc(FILE *f, cJSON *root)
{
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text)
        return 0;
    int ok = fputs(text, f) >= 0 && fputc('\n', f) != EOF;
    free(text);
    return ok;
}

int cli_quantities_json(FILE *f, const app_project *p, const cli_room_quantities *r,
                        const app_quote *quote, int offcuts)
{
    cJSON *root = cJSON_CreateObject();
    if (!root)
        return 0;
    cJSON_AddStringToObject(root, "project", p->name);
    add_room(root, r, offcuts);
    cJSON_AddItemToObject(root, "quote", quote_json(quote));
    cJSON_AddItemToObject(root, "bom", bom_json(&r->bom));
    return write_doc(f, root);
}

int cli_quantities_json_flat(FILE *f, const app_flat *fl, const cli_room_quantities *rooms,
                             const cli_room_quantities *total, const app_quote *quote,
                             const app_bom *quotation, int offcuts)
{
    cJSON *root = cJSON_CreateObject();
    if (!root)
        return 0;
    cJSON_AddStringToObject(root, "flat", fl->name);
    cJSON *list = cJSON_AddArrayToObject(root, "rooms");
    for (int i = 0; i < fl->room_count; i++) {
        cJSON *room = cJSON_CreateObject();
        cJSON_AddStringToObject(room, "project", fl->rooms[i].name);
        add_room(room, &rooms[i], offcuts);
        cJSON_AddItemToObject(room, "bom", bom_json(&rooms[i].bom));
        cJSON_AddItemToArray(list, room);
    }
    cJSON *t = cJSON_AddObjectToObject(root, "total");
    add_room(t, total, 0);
    cJSON_AddItemToObject(t, "bom", bom_json(&total->bom));
    cJSON_AddItemToObject(root, "quote", quote_json(quote));
    cJSON_AddItemToObject(root, "quotation", bom_json(quotation));
    return write_doc(f, root);
}
