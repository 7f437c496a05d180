/* Numbers for the writer, printed with the fewest significant digits that read back to the
 * very same value, so that read -> write -> read is exact. cJSON's own printer accepts a
 * 15-digit form that is only within an ulp or two, which is why the writer uses raw items. */
#include "project_internal.h"

#include <float.h>
#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* snprintf follows LC_NUMERIC; JSON wants a '.' whatever the locale. */
static void to_json_decimal_point(char *s)
{
    const char *dp = localeconv()->decimal_point;
    if (!dp || (dp[0] == '.' && dp[1] == '\0'))
        return;
    size_t dlen = strlen(dp);
    char *at = strstr(s, dp);
    if (!at)
        return;
    *at = '.';
    memmove(at + 1, at + dlen, strlen(at + dlen) + 1);
}

cJSON *pj_json_double(double v)
{
    char buf[40];
    for (int digits = 15; digits <= 17; digits++) {
        snprintf(buf, sizeof buf, "%.*g", digits, v);
        if (strtod(buf, NULL) == v)
            break;
    }
    to_json_decimal_point(buf);
    return cJSON_CreateRaw(buf);
}

cJSON *pj_json_float(float v)
{
    char buf[40];
    int found = 0;
    /* The reader turns the decimal into a double, refuses it beyond FLT_MAX, and then makes
     * it a float; check that path (9 digits of FLT_MAX round up beyond it). */
    for (int digits = 6; digits <= 9 && !found; digits++) {
        snprintf(buf, sizeof buf, "%.*g", digits, (double)v);
        double d = strtod(buf, NULL);
        found = fabs(d) <= FLT_MAX && (float)d == v;
    }
    if (!found)
        snprintf(buf, sizeof buf, "%.17g", (double)v);
    to_json_decimal_point(buf);
    return cJSON_CreateRaw(buf);
}
