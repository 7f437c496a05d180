/* Phase timing for the print speed work (phase_timer.h). */
#include "phase_timer.h"

#include "gl_funcs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAX_PHASES 16

static int enabled = -1;
static double last_ms;
static int phase_count;
static const char *phase_name[MAX_PHASES];
static double phase_ms[MAX_PHASES];

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

int rd_phase_enabled(void)
{
    if (enabled < 0) {
        const char *v = getenv("TESSERA_PHASES");
        enabled = v && v[0] && strcmp(v, "0") != 0;
    }
    return enabled;
}

void rd_phase_restart(void)
{
    if (!rd_phase_enabled())
        return;
    glFinish();
    last_ms = now_ms();
}

void rd_phase_mark(const char *name)
{
    if (!rd_phase_enabled())
        return;
    glFinish(); /* llvmpipe runs a draw when it is flushed: wait, so it counts here */
    double t = now_ms();
    int i = 0;
    while (i < phase_count && strcmp(phase_name[i], name) != 0)
        i++;
    if (i == phase_count && phase_count < MAX_PHASES) {
        phase_name[i] = name;
        phase_ms[i] = 0.0;
        phase_count++;
    }
    if (i < phase_count)
        phase_ms[i] += t - last_ms;
    last_ms = t;
}

void rd_phase_report(const char *title)
{
    if (!rd_phase_enabled() || phase_count == 0)
        return;
    fprintf(stderr, "phases (%s):", title);
    for (int i = 0; i < phase_count; i++)
        fprintf(stderr, "%s %s %.0f ms", i ? "," : "", phase_name[i], phase_ms[i]);
    fprintf(stderr, "\n");
    phase_count = 0;
}
