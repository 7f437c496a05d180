/* A product's companions text: "ARTICLE" or "MANUFACTURER:ARTICLE" entries separated by ";"
 * (docs/catalog.md "Mounting heights and companions"). */
#include "catalog/catalog.h"

#include <stdio.h>
#include <string.h>

/* Copies [s, s + n) without the blanks around it; 0 when empty or too long. */
static int copy_trimmed(const char *s, size_t n, char *out, size_t size)
{
    while (n > 0 && (*s == ' ' || *s == '\t'))
        s++, n--;
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t'))
        n--;
    if (n == 0 || n >= size)
        return 0;
    memcpy(out, s, n);
    out[n] = 0;
    return 1;
}

int cat_companion_get(const char *companions, int k, char *manufacturer, size_t manufacturer_size,
                      char *article, size_t article_size)
{
    if (manufacturer_size)
        manufacturer[0] = 0;
    if (article_size)
        article[0] = 0;
    const char *s = companions ? companions : "";
    while (*s == ' ' || *s == '\t')
        s++;
    if (!*s || k < 0)
        return 0;
    for (int i = 0; i < k; i++) {
        s = strchr(s, ';');
        if (!s)
            return 0;
        s++;
    }
    const char *end = strchr(s, ';');
    size_t n = end ? (size_t)(end - s) : strlen(s);
    const char *colon = memchr(s, ':', n);
    if (!colon)
        return copy_trimmed(s, n, article, article_size) ? 1 : -1;
    if (!copy_trimmed(s, (size_t)(colon - s), manufacturer, manufacturer_size) ||
        !copy_trimmed(colon + 1, n - (size_t)(colon - s) - 1, article, article_size))
        return -1;
    return 1;
}
