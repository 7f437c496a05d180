/* An array member of the project read item by item (pj_read_array), with the reader's path
 * and error conventions: absent is empty, the count is checked, each item is read under its
 * index in the path ("$.lights[2].color"). */
#include "project_internal.h"

app_result pj_read_array(pj_ctx *c, const cJSON *root, const char *key, pj_array *a)
{
    a->items = NULL;
    a->count = 0;
    const cJSON *list;
    app_result r = pj_member(c, root, key, cJSON_Array, 0, &list);
    if (r != APP_OK || !list)
        return r;
    size_t mark = pj_path_key(c, key);
    int count;
    if ((r = pj_check_count(c, list, key, &count)) != APP_OK)
        return r;
    a->items = pj_calloc((size_t)count, a->size);
    if (!a->items)
        return pj_fail(c, APP_ERR_OUT_OF_MEMORY, "out of memory (%d %s)", count, key);
    int i = 0;
    for (const cJSON *item = list->child; item; item = item->next, i++) {
        size_t item_mark = pj_path_index(c, i);
        if ((r = a->read(c, item, i, (char *)a->items + (size_t)i * a->size)) != APP_OK)
            return r;
        a->count = i + 1;
        pj_path_restore(c, item_mark);
    }
    pj_path_restore(c, mark);
    return APP_OK;
}
