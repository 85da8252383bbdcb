/* Allocation for the build phase (the step loop allocates nothing).
 *
 * The library never exits: when memory runs out, bd_xcalloc jumps back to
 * the innermost armed guard, whose entry point (bd_sim_create,
 * bd_sim_create_from) frees what was built and returns an error. Push a
 * guard, then arm it with setjmp on its env; pop it before returning:
 *
 *     bd_alloc_guard g;
 *     bd_alloc_guard_push(&g);
 *     if (setjmp(g.env)) { bd_alloc_guard_pop(&g); ...clean up, report... }
 *     ... build ...
 *     bd_alloc_guard_pop(&g);
 *
 * Objects the entry point must free after the jump are held in volatile
 * variables (C11 7.13.2.1), and take each allocation as it is made.
 * Temporaries a builder holds only in its locals are lost on that path (a
 * few kilobytes, once per failed build). Allocating with no guard armed is
 * a programmer error and aborts. */
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
/* a copy of n items of src, as bd_xcalloc allocates */
void *bd_xdup(const void *src, size_t n, size_t size);

/* the arrays of doubles a struct owns, named once by their members'
 * offsets (offsetof), allocated (zeroed), copied and freed together; n
 * items each. A copy owns each array as soon as it is made. */
void bd_doubles_alloc(void *owner, const size_t *members, int count, size_t n);
void bd_doubles_dup(void *dst, const void *src, const size_t *members, int count, size_t n);
void bd_doubles_free(void *owner, const size_t *members, int count);

#endif
