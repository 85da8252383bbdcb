#include "base/alloc.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* the innermost armed guard of this thread */
static _Thread_local bd_alloc_guard *guard_top;

void bd_alloc_guard_push(bd_alloc_guard *g)
{
    g->prev = guard_top;
    guard_top = g;
}

void bd_alloc_guard_pop(bd_alloc_guard *g)
{
    guard_top = g->prev;
}

void *bd_xcalloc(size_t n, size_t size)
{
    void *p = NULL;
    /* calloc checks n·size for overflow itself; refuse the absurd early */
    if (size == 0 || n <= SIZE_MAX / size)
        p = calloc(n ? n : 1, size ? size : 1);
    if (p)
        return p;
    if (!guard_top)
        abort();
    longjmp(guard_top->env, 1);
}

void *bd_xdup(const void *src, size_t n, size_t size)
{
    void *d = bd_xcalloc(n, size);
    if (n > 0 && size > 0)
        memcpy(d, src, n * size);
    return d;
}
