/* The catalog's enumerations by name, as they are written in CSV files, in the database and on
 * the command line. */
#include "db_internal.h"

#include <strings.h>

static const char *const category_names[CAT_CATEGORY_COUNT] = {
    "",      "taps_mixers",     "shower_sets",    "basins",      "wcs_bidets",
    "baths", "shower_trays",    "shower_screens", "mirrors",     "mirror_cabinets",
    "lamps", "towel_radiators", "vanity_units",   "accessories", "tiles"};
static const char *const unit_names[CAT_UNIT_COUNT] = {"piece", "m2", "box", "m"};
static const char *const blend_names[CAT_BLEND_COUNT] = {"mix", "add", "fresnel"};
static const char *const pattern_names[CAT_PATTERN_COUNT] = {"none", "wood"};
static const char *const surface_names[CAT_SURFACE_COUNT] = {"glossy", "matt", "structured"};
static const char *const tile_type_names[CAT_TILE_TYPE_COUNT] = {"UNI", "BOR", "DEK", "EIN"};
static const char *const mount_to_names[CAT_MOUNT_COUNT] = {"", "bottom", "top", "rim", "seat"};

static const char *name_of(const char *const *names, int count, int v)
{
    return v >= 0 && v < count ? names[v] : "";
}

/* Index of text in names[first .. count-1], any case, or -1. */
static int index_of(const char *const *names, int first, int count, const char *text)
{
    if (!text)
        return -1;
    for (int i = first; i < count; i++)
        if (!strcasecmp(text, names[i]))
            return i;
    return -1;
}

const char *cat_category_name(cat_category c)
{
    return name_of(category_names, CAT_CATEGORY_COUNT, (int)c);
}

const char *cat_unit_name(cat_unit u)
{
    return name_of(unit_names, CAT_UNIT_COUNT, (int)u);
}

const char *cat_blend_name(cat_blend b)
{
    return name_of(blend_names, CAT_BLEND_COUNT, (int)b);
}

const char *cat_pattern_name(cat_pattern p)
{
    return name_of(pattern_names, CAT_PATTERN_COUNT, (int)p);
}

const char *cat_surface_name(cat_tile_surface s)
{
    return name_of(surface_names, CAT_SURFACE_COUNT, (int)s);
}

const char *cat_tile_type_name(cat_tile_type t)
{
    return name_of(tile_type_names, CAT_TILE_TYPE_COUNT, (int)t);
}

const char *cat_mount_to_name(cat_mount_to m)
{
    return name_of(mount_to_names, CAT_MOUNT_COUNT, (int)m);
}

int cat_category_parse(const char *text, cat_category *out)
{
    int i = index_of(category_names, 1, CAT_CATEGORY_COUNT, text);
    if (i < 0)
        return 0;
    *out = (cat_category)i;
    return 1;
}

int cat_unit_parse(const char *text, cat_unit *out)
{
    int i = index_of(unit_names, 0, CAT_UNIT_COUNT, text);
    if (i < 0)
        return 0;
    *out = (cat_unit)i;
    return 1;
}

int cat_blend_parse(const char *text, cat_blend *out)
{
    int i = index_of(blend_names, 0, CAT_BLEND_COUNT, text);
    if (i < 0)
        return 0;
    *out = (cat_blend)i;
    return 1;
}

int cat_pattern_parse(const char *text, cat_pattern *out)
{
    int i = index_of(pattern_names, 0, CAT_PATTERN_COUNT, text);
    if (i < 0)
        return 0;
    *out = (cat_pattern)i;
    return 1;
}

int cat_surface_parse(const char *text, cat_tile_surface *out)
{
    int i = index_of(surface_names, 0, CAT_SURFACE_COUNT, text);
    if (i < 0)
        return 0;
    *out = (cat_tile_surface)i;
    return 1;
}

int cat_tile_type_parse(const char *text, cat_tile_type *out)
{
    int i = index_of(tile_type_names, 0, CAT_TILE_TYPE_COUNT, text);
    if (i < 0)
        return 0;
    *out = (cat_tile_type)i;
    return 1;
}

int cat_mount_to_parse(const char *text, cat_mount_to *out)
{
    int i = index_of(mount_to_names, 1, CAT_MOUNT_COUNT, text);
    if (i < 0)
        return 0;
    *out = (cat_mount_to)i;
    return 1;
}

/* GS1 General Specifications 7.9.1: weights 3 and 1 alternate from the digit next to the
 * check digit leftwards; the check digit brings the sum to a multiple of 10. */
int cat_gtin_valid(const char *text)
{
    if (!text)
        return 0;
    size_t n = 0;
    while (text[n]) {
        if (text[n] < '0' || text[n] > '9')
            return 0;
        n++;
    }
    if (n != 8 && n != 12 && n != 13 && n != 14)
        return 0;
    int sum = 0;
    for (size_t i = 0; i + 1 < n; i++) {
        int weight = (n - 1 - i) % 2 == 1 ? 3 : 1;
        sum += (text[i] - '0') * weight;
    }
    return (10 - sum % 10) % 10 == text[n - 1] - '0';
}
