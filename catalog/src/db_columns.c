/* The import format's columns by header name (docs/catalog.md lists what each holds). */
#include "db_internal.h"

#include <string.h>
#include <strings.h>

static const char *const names[COL_COUNT] = {
    [COL_MANUFACTURER] = "manufacturer",
    [COL_ARTICLE] = "article",
    [COL_GTIN] = "gtin",
    [COL_CATEGORY] = "category",
    [COL_SERIES] = "series",
    [COL_NAME] = "name",
    [COL_SHORT_TEXT] = "short_text",
    [COL_LONG_TEXT] = "long_text",
    [COL_WIDTH] = "width_mm",
    [COL_DEPTH] = "depth_mm",
    [COL_HEIGHT] = "height_mm",
    [COL_LIST_PRICE] = "list_price",
    [COL_CURRENCY] = "currency",
    [COL_VAT] = "vat_percent",
    [COL_UNIT] = "unit",
    [COL_DISCOUNT_GROUP] = "discount_group",
    [COL_MODEL] = "model",
    [COL_MOUNTING_HEIGHT] = "mounting_height_mm",
    [COL_MOUNTING_TO] = "mounting_to",
    [COL_COMPANIONS] = "companions",
    [COL_VARIANT_CODE] = "variant_code",
    [COL_VARIANT_NAME] = "variant_name",
    [COL_VARIANT_SURCHARGE] = "variant_surcharge",
    [COL_AMBIENT] = "ambient",
    [COL_DIFFUSE] = "diffuse",
    [COL_SPECULAR] = "specular",
    [COL_EMISSIVE] = "emissive",
    [COL_SHININESS] = "shininess",
    [COL_REFLECTIVITY] = "reflectivity",
    [COL_GLOSSINESS] = "glossiness",
    [COL_BLEND] = "blend",
    [COL_TRANSPARENCY] = "transparency",
    [COL_IOR] = "ior",
    [COL_PATTERN] = "pattern",
    [COL_GRAIN] = "grain",
    [COL_TILE_TYPE] = "tile_type",
    [COL_NOMINAL_W] = "nominal_w_mm",
    [COL_NOMINAL_H] = "nominal_h_mm",
    [COL_WORK_W] = "work_w_mm",
    [COL_WORK_H] = "work_h_mm",
    [COL_GROUT] = "grout_mm",
    [COL_THICKNESS] = "thickness_mm",
    [COL_CALIBRE] = "calibre",
    [COL_SURFACE] = "surface",
    [COL_M2_PER_BOX] = "m2_per_box",
    [COL_PIECES_PER_BOX] = "pieces_per_box",
    [COL_TEXTURE] = "texture",
};

const char *catdb_col_name(catdb_col c)
{
    return (int)c >= 0 && c < COL_COUNT ? names[c] : "";
}

int catdb_col_find(const char *text)
{
    while (*text == ' ' || *text == '\t')
        text++;
    size_t n = strlen(text);
    while (n > 0 && (text[n - 1] == ' ' || text[n - 1] == '\t'))
        n--;
    for (int c = 0; c < COL_COUNT; c++)
        if (strlen(names[c]) == n && !strncasecmp(text, names[c], n))
            return c;
    return -1;
}
