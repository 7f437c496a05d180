#include "app/measure/stats.h"

#include <math.h>
#include <stdlib.h>

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Linear interpolation between closest ranks on sorted data. */
static double quantile(const double *sorted, int n, double q)
{
    double pos = q * (double)(n - 1);
    int lo = (int)floor(pos);
    int hi = lo + 1 < n ? lo + 1 : lo;
    return sorted[lo] + (pos - (double)lo) * (sorted[hi] - sorted[lo]);
}

app_stats app_stats_of(double *v, int n)
{
    app_stats s = {0};
    if (n <= 0 || !v)
        return s;
    qsort(v, (size_t)n, sizeof *v, compare_doubles);
    s.count = n;
    s.min = v[0];
    s.max = v[n - 1];
    s.median = quantile(v, n, 0.5);
    s.p10 = quantile(v, n, 0.1);
    s.p90 = quantile(v, n, 0.9);
    double *dev = malloc((size_t)n * sizeof *dev);
    if (dev) {
        for (int i = 0; i < n; i++)
            dev[i] = fabs(v[i] - s.median);
        qsort(dev, (size_t)n, sizeof *dev, compare_doubles);
        s.mad = quantile(dev, n, 0.5);
        free(dev);
    }
    return s;
}
