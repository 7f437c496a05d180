/* A product lookup for the placement and command tests that reads the shipped catalog data
 * (assets/catalog/fixtures.csv) directly, so the tests use real product sizes without
 * building the SQLite catalog. The CLI tests go through the real catalog. */
#ifndef PLACEMENT_TEST_CATALOG_H
#define PLACEMENT_TEST_CATALOG_H

#include "app/design/placement.h"
#include "catalog/catalog.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* Splits one CSV record (quotes, doubled quotes) into at most max fields in place. */
static int ptc_split(char *line, char **fields, int max)
{
    int n = 0;
    char *r = line, *w = line;
    while (n < max) {
        fields[n++] = w;
        int quoted = *r == '"';
        if (quoted)
            r++;
        for (;;) {
            if (!*r || *r == '\n' || *r == '\r') {
                *w = 0;
                return n;
            }
            if (quoted && *r == '"') {
                if (r[1] == '"') {
                    *w++ = '"';
                    r += 2;
                    continue;
                }
                quoted = 0;
                r++;
                continue;
            }
            if (!quoted && *r == ',') {
                *w++ = 0;
                r++;
                break;
            }
            *w++ = *r++;
        }
    }
    return n;
}

static int ptc_category(const char *name)
{
    static const char *const names[] = {
        "",      "taps_mixers",     "shower_sets",    "basins",      "wcs_bidets",
        "baths", "shower_trays",    "shower_screens", "mirrors",     "mirror_cabinets",
        "lamps", "towel_radiators", "vanity_units",   "accessories", "tiles"};
    for (int i = 1; i < (int)(sizeof names / sizeof names[0]); i++)
        if (!strcmp(names[i], name))
            return i;
    return 0;
}

/* user: the CSV path. */
static app_result ptc_lookup(void *user, const app_product_ref *ref, app_product_info *out,
                             char *err, size_t err_size)
{
    FILE *f = fopen((const char *)user, "r");
    if (!f) {
        snprintf(err, err_size, "%s: cannot open", (const char *)user);
        return APP_ERR_IO;
    }
    static char line[65536];
    app_result r = APP_ERR_NOT_FOUND;
    int product_seen = 0;
    while (fgets(line, sizeof line, f)) {
        char *fld[48];
        int n = ptc_split(line, fld, 48);
        if (n < 18 || strcasecmp(fld[0], ref->manufacturer) || strcasecmp(fld[1], ref->article))
            continue;
        product_seen = 1;
        /* One row per variant: the one asked for, or the first. */
        if (ref->variant[0] && strcmp(fld[17], ref->variant))
            continue;
        memset(out, 0, sizeof *out);
        snprintf(out->variant, sizeof out->variant, "%.15s", fld[17]);
        out->width_mm = atof(fld[8]);
        out->depth_mm = atof(fld[9]);
        out->height_mm = atof(fld[10]);
        out->category = ptc_category(fld[3]);
        snprintf(out->model, sizeof out->model, "%s", fld[16]);
        /* mounting_height_mm, mounting_to, companions: the last three columns. */
        if (n >= 45 && fld[43][0]) {
            out->has_mounting = 1;
            out->mounting_height_mm = atof(fld[42]);
            out->mounting_of = strcmp(fld[43], "bottom") ? APP_MOUNT_TOP : APP_MOUNT_BOTTOM;
        }
        if (n >= 45)
            snprintf(out->companions, sizeof out->companions, "%s", fld[44]);
        r = APP_OK;
        break;
    }
    fclose(f);
    if (r != APP_OK && product_seen)
        snprintf(err, err_size, "%s %s has no variant \"%s\"", ref->manufacturer, ref->article,
                 ref->variant);
    else if (r != APP_OK)
        snprintf(err, err_size, "no product %s %s", ref->manufacturer, ref->article);
    return r;
}

#endif
