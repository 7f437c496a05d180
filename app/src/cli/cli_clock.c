/* The commands' stopwatch, apart from the render session so that the lean `tessera` (the
 * catalog commands) has it too. */
#include "cli_options.h"

#include <time.h>

double cli_now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}
