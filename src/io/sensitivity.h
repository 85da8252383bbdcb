/* How much a sweep's output depends on each varied key (sensitivity.c). */
#ifndef BD_IO_SENSITIVITY_H
#define BD_IO_SENSITIVITY_H

#include <stddef.h>

/* Spearman's rank correlation of y with x over the n pairs where both are
 * finite: +1 y rises with x wherever x rises, -1 it falls, 0 no monotone
 * relation. Ties take their mean rank. NaN with fewer than 3 pairs or
 * when x or y is the same in all of them (nothing to rank). */
double bd_spearman(const double *x, const double *y, size_t n);

#endif
