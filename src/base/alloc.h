/* Allocation for the build phase (the step loop allocates nothing). */
#ifndef BD_ALLOC_H
#define BD_ALLOC_H

#include <stddef.h>

/* zeroed array of n items (at least one); stops the program when memory
 * is exhausted */
void *bd_xcalloc(size_t n, size_t size);

#endif
