/* $.customer and $.quote: whom a quotation is made out to, its number and how long it is valid
 * (docs/project-format.md "Customer and quote"). Both are optional. */
#include "project_internal.h"

#include <string.h>

static app_result read_customer(pj_ctx *c, const cJSON *o, app_customer *cu)
{
    app_result r;
    if ((r = pj_get_string(c, o, "name", 0, 1, cu->name, sizeof cu->name)) != APP_OK ||
        (r = pj_get_string(c, o, "email", 0, 1, cu->email, sizeof cu->email)) != APP_OK ||
        (r = pj_get_string(c, o, "phone", 0, 1, cu->phone, sizeof cu->phone)) != APP_OK)
        return r;
    const cJSON *addr = NULL;
    if ((r = pj_member(c, o, "address", cJSON_Array, 0, &addr)) != APP_OK || !addr)
        return r;
    size_t mark = pj_path_key(c, "address");
    int n = cJSON_GetArraySize(addr);
    if (n > APP_CUSTOMER_ADDRESS_LINES)
        return pj_fail(c, APP_ERR_SCHEMA, "at most %d address lines, got %d",
                       APP_CUSTOMER_ADDRESS_LINES, n);
    for (int i = 0; i < n; i++) {
        const cJSON *line = cJSON_GetArrayItem(addr, i);
        size_t im = pj_path_index(c, i);
        if (!cJSON_IsString(line))
            return pj_fail(c, APP_ERR_SCHEMA, "expected a string, got %s", pj_type_name(line));
        if (strlen(line->valuestring) >= sizeof cu->address[i])
            return pj_fail(c, APP_ERR_SCHEMA, "longer than %zu bytes", sizeof cu->address[i] - 1);
        strcpy(cu->address[i], line->valuestring);
        pj_path_restore(c, im);
    }
    cu->address_lines = n;
    pj_path_restore(c, mark);
    return APP_OK;
}

app_result pj_read_customer(pj_ctx *c, const cJSON *root)
{
    app_customer *cu = &c->p->customer;
    memset(cu, 0, sizeof *cu);
    const cJSON *o = NULL, *q = NULL;
    app_result r = pj_member(c, root, "customer", cJSON_Object, 0, &o);
    if (r == APP_OK)
        r = pj_member(c, root, "quote", cJSON_Object, 0, &q);
    if (r != APP_OK)
        return r;
    if (o) {
        size_t mark = pj_path_key(c, "customer");
        if ((r = read_customer(c, o, cu)) != APP_OK)
            return r;
        pj_path_restore(c, mark);
    }
    if (q) {
        size_t mark = pj_path_key(c, "quote");
        if ((r = pj_get_string(c, q, "number", 0, 1, cu->quote_number, sizeof cu->quote_number)) !=
                APP_OK ||
            (r = pj_get_int(c, q, "valid_days", 0, 1, 3650, &cu->valid_days)) != APP_OK)
            return r;
        pj_path_restore(c, mark);
    }
    cu->present = o || q;
    return APP_OK;
}
