/* Allocation for the build phase (the step loop allocates nothing).
 *
 * The library never exits: when memory runs out, bd_xcalloc jumps back to
 * the innermost armed guard, whose entry point (bd_sim_create,
 * bd_sim_create_from) frees what was built and returns an error. Arm a
 * guard with setjmp on its env, then push it; pop it before returning:
 *
 *     bd_alloc_guard g;
 *     if (setjmp(g.env)) { ...clean up, report... return 1; }
 *     bd_alloc_guard_push(&g);
 *     ... build ...
 *     bd_alloc_guard_pop(&g);
 *
 * Objects the entry point must free after the jump are held in volatile
 * variables (C11 7.13.2.1). Allocating with no guard armed is a
 * programmer error and aborts. */
#ifndef BD_ALLOC_H
#define BD_ALLOC_H

#include <setjmp.h>
#include <stddef.h>

typedef struct bd_alloc_guard {
    jmp_buf env;
    struct bd_alloc_guard *prev;
} bd_alloc_guard;

void bd_alloc_guard_push(bd_alloc_guard *g);
/* pops g (after a jump to it too) */
void bd_alloc_guard_pop(bd_alloc_guard *g);

/* zeroed array of n items (at least one); on failure jumps to the guard */
void *bd_xcalloc(size_t n, size_t size);

#endif
