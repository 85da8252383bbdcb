/* The cases of a sweep (sweep.c): the values its keys take, one row of
 * nkeys values per case. */
#ifndef BD_STUDY_SWEEP_H
#define BD_STUDY_SWEEP_H

#include "beltdyn/study.h"

#define BD_SWEEP_MAX_CASES 100000

/* the grid: every combination, the first key slowest, the last fastest;
 * malloc'ed [*ncases][nkeys], NULL out of memory or too many */
double *bd_sweep_grid(const bd_study_range *keys, int nkeys, int *ncases);

/* n cases of a Latin hypercube over the keys' [lo, hi] from seed;
 * malloc'ed [n][nkeys], NULL out of memory */
double *bd_sweep_lhs(const bd_study_range *keys, int nkeys, int n, unsigned long long seed);

#endif
