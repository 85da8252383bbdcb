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

static double **slot(void *owner, size_t member)
{
    return (double **)(void *)((char *)owner + member);
}

void bd_doubles_alloc(void *owner, const size_t *members, int count, size_t n)
{
    for (int k = 0; k < count; k++)
        *slot(owner, members[k]) = bd_xcalloc(n, sizeof(double));
}

void bd_doubles_dup(void *dst, const void *src, const size_t *members, int count, size_t n)
{
    for (int k = 0; k < count; k++)
        *slot(dst, members[k]) = NULL;
    for (int k = 0; k < count; k++) {
        const double *from = *(double *const *)(const void *)((const char *)src + members[k]);
        *slot(dst, members[k]) = bd_xdup(from, n, sizeof(double));
    }
}

void bd_doubles_free(void *owner, const size_t *members, int count)
{
    for (int k = 0; k < count; k++) {
        free(*slot(owner, members[k]));
        *slot(owner, members[k]) = NULL;
    }
}
