/* Shared by the quantities' files: appending a priced line to a bill of materials. */
#ifndef APP_QUANTITIES_INTERNAL_H
#define APP_QUANTITIES_INTERNAL_H

#include "app/design/quantities.h"

/* Appends a line for ref (priced from db, its kind and detail set) when quantity > 0; *cap is
 * the capacity of b->lines (line_count is always safe: it grows from there). */
app_result qty_bom_add_priced(cat_db *db, app_bom *b, int *cap, const app_product_ref *ref,
                              app_bom_kind kind, double quantity, const char *detail, char *err,
                              size_t err_size);

#endif
