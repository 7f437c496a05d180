/* Phase timing for the print speed work (phase_timer.h). */
#include "phase_timer.h"

#include "gl_funcs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAX_PHASES 16

static int enabled = -1;
static double last_ms, last_cpu_ms;
static int phase_count;
static const char *phase_name[MAX_PHASES];
static double phase_ms[MAX_PHASES], phase_cpu_ms[MAX_PHASES];

static double clock_ms(clockid_t clock)
{
    struct timespec t;
    clock_gettime(clock, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* The wall clock, and the CPU time of every thread of the process (llvmpipe's rasteriser
 * threads included), which moves far less than the wall clock on a shared machine. */
static double now_ms(void)
{
    return clock_ms(CLOCK_MONOTONIC);
}

static double cpu_ms(void)
{
    return clock_ms(CLOCK_PROCESS_CPUTIME_ID);
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
    last_cpu_ms = cpu_ms();
}

void rd_phase_mark(const char *name)
{
    if (!rd_phase_enabled())
        return;
    glFinish(); /* llvmpipe runs a draw when it is flushed: wait, so it counts here */
    double t = now_ms(), c = cpu_ms();
    int i = 0;
    while (i < phase_count && strcmp(phase_name[i], name) != 0)
        i++;
    if (i == phase_count && phase_count < MAX_PHASES) {
        phase_name[i] = name;
        phase_ms[i] = 0.0;
        phase_cpu_ms[i] = 0.0;
        phase_count++;
    }
    if (i < phase_count) {
        phase_ms[i] += t - last_ms;
        phase_cpu_ms[i] += c - last_cpu_ms;
    }
    last_ms = t;
    last_cpu_ms = c;
}

void rd_phase_report(const char *title)
{
    if (!rd_phase_enabled() || phase_count == 0)
        return;
    fprintf(stderr, "phases (%s):", title);
    for (int i = 0; i < phase_count; i++)
        fprintf(stderr, "%s %s %.0f ms (cpu %.0f)", i ? "," : "", phase_name[i], phase_ms[i],
                phase_cpu_ms[i]);
    fprintf(stderr, "\n");
    phase_count = 0;
}
