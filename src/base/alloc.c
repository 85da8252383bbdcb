#include "base/alloc.h"

#include <stdio.h>
#include <stdlib.h>

void *bd_xcalloc(size_t n, size_t size)
{
    void *p = calloc(n ? n : 1, size);
    if (!p) {
        fprintf(stderr, "beltdyn: out of memory\n");
        exit(1);
    }
    return p;
}
