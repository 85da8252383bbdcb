/* The run's pass/fail table (issue 15): each check of the design against
 * its limit, computed once from the finished run and the static
 * calculation; summary.json's "checks" holds it (outputs.c). */
#ifndef BD_IO_CHECKS_H
#define BD_IO_CHECKS_H

#include "beltdyn/standards.h"
#include "sim/engine.h"

#define BD_CHECK_MAX 24

typedef struct bd_check {
    char name[112];     /* what is checked, e.g. "belt strength, starts and stops" */
    char unit[12];      /* of value and limit */
    double value, limit;
    int upper;          /* 1: value must not exceed limit; 0: must reach it */
    int pass;
} bd_check;

/* the checks that apply to this run (st: the static calculation, or NULL
 * when the model has no design or it failed); how many, at most max */
int bd_run_checks(const bd_sim *sim, const bd_static_result *st, bd_check *out, int max);

#endif
