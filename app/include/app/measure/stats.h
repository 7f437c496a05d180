/* Summary statistics of timing samples for the benchmark commands. */
#ifndef APP_STATS_H
#define APP_STATS_H

typedef struct app_stats {
    int count;
    double median, p10, p90, min, max, mad; /* mad: median absolute deviation */
} app_stats;

/* Sorts `values` in place. count 0 gives all zeros. */
app_stats app_stats_of(double *values, int count);

#endif
