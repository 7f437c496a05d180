/* A synthetic flat for tests and benchmarks: N rooms (bathroom, kitchen, WC, hall, shower room,
 * utility room, en-suite, guest WC, then again), each tiled and furnished with shipped catalog
 * products (assets/catalog), about 300 fixtures and 40 000 tiles at 8 rooms. The same rooms
 * and seed give the same file. docs/benchmarks.md "A whole flat". */
#ifndef APP_FLAT_GENERATE_H
#define APP_FLAT_GENERATE_H

#include "app/project/project.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct app_flat_generate_report {
    int rooms;
    int fixtures; /* objects that are catalog products */
    int tilings;
} app_flat_generate_report;

/* Writes the flat to path (through a temporary file and a rename: the project writer's
 * rules). rooms in 1..APP_FLAT_MAX_ROOMS. report may be NULL. */
app_result app_flat_generate(int rooms, unsigned long long seed, const char *path,
                             app_flat_generate_report *report, char *err, size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
