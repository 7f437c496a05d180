/* The window's heap over time, for the soak (tests/ui/soak_session.sh): with
 * TESSERA_HEAP_LOG=SECONDS set, a line every that many seconds with glibc's mallinfo2(3)
 * figures and the planner's caches, so resident growth can be told apart as memory in use
 * (a leak or a cache that grows) or memory freed but kept by the allocator (fragmentation).
 * After each scene rebuild the free heap pages go back to the system (malloc_trim(3)): a
 * rebuild frees and allocates the scene in many pieces, and glibc keeps the freed pages, so
 * repeated rebuilds raised the resident size while the memory in use stayed flat.
 * TESSERA_HEAP_TRIM=0 turns that off, to measure what the allocator keeps. */
#define _GNU_SOURCE
#include "planner.h"
#include "tiles.h"

#include <malloc.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static double heap_log_period(void)
{
    static double period = -1;
    if (period < 0) {
        const char *s = getenv("TESSERA_HEAP_LOG");
        period = s && *s ? atof(s) : 0;
        if (!(period > 0))
            period = 0;
    }
    return period;
}

void planner_heap_after_rebuild(void)
{
    static int enabled = -1;
    if (enabled < 0) {
        const char *s = getenv("TESSERA_HEAP_TRIM");
        enabled = !(s && *s == '0');
    }
    if (enabled)
        malloc_trim(0);
}

static long rss_kb(void)
{
    FILE *f = fopen("/proc/self/statm", "r");
    long pages = 0, resident = 0;
    if (!f)
        return 0;
    if (fscanf(f, "%ld %ld", &pages, &resident) != 2)
        resident = 0;
    fclose(f);
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

void planner_heap_log_tick(planner *p, double now)
{
    double period = heap_log_period();
    if (period <= 0 || now - p->heap_logged_at < period)
        return;
    p->heap_logged_at = now;
    struct mallinfo2 m = mallinfo2();
    const ui_tiles *t = p->tiles;
    /* arena: the heaps' size; in_use: what is allocated there; free: freed but kept by the
     * allocator; top: what malloc_trim could give back at the heap's end; mmap: large blocks
     * mapped on their own (returned when freed). */
    fprintf(stderr,
            "tessera: heap %.0f s rss_kb %ld arena_kb %zu in_use_kb %zu free_kb %zu "
            "top_kb %zu mmap_kb %zu thumbs %d layouts %d\n",
            now, rss_kb(), m.arena / 1024, m.uordblks / 1024, m.fordblks / 1024, m.keepcost / 1024,
            m.hblkhd / 1024, p->thumbs.count, t ? t->layout_count : 0);
}
