/* Allocation for the project module, with a test hook that makes it fail after N
 * allocations so every out-of-memory path runs in the tests (the SQLite habit, STYLE.md). */
#include "project_internal.h"

#include <stdlib.h>

static _Thread_local long fail_after = -1;

void app_project_test_fail_alloc_after(long count)
{
    fail_after = count;
}

static int should_fail(void)
{
    if (fail_after < 0)
        return 0;
    if (fail_after == 0)
        return 1;
    fail_after--;
    return 0;
}

void *pj_malloc(size_t size)
{
    return should_fail() ? NULL : malloc(size ? size : 1);
}

void *pj_calloc(size_t count, size_t size)
{
    return should_fail() ? NULL : calloc(count ? count : 1, size ? size : 1);
}

void *pj_realloc(void *ptr, size_t size)
{
    return should_fail() ? NULL : realloc(ptr, size ? size : 1);
}
