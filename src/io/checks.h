/* The run's pass/fail table (issue 15): each check of the design against
 * its limit, computed once from the finished run and the static
 * calculation; summary.json's "checks" holds it (outputs.c). */
#ifndef BD_IO_CHECKS_H
#define BD_IO_CHECKS_H

#include "beltdyn/standards.h"
#include "sim/engine.h"

/* how value must stand to limit; pass follows from it alone */
typedef enum bd_check_rule {
    BD_CHECK_AT_MOST = 0,   /* value <= limit */
    BD_CHECK_AT_LEAST,      /* value >= limit */
    BD_CHECK_BELOW,         /* value < limit: reaching it fails (a torque
                               clipped at its limit, a slip that lasted, a
                               takeup held at the end of its travel) */
    BD_CHECK_ABOVE          /* value > limit: reaching it fails */
} bd_check_rule;

typedef struct bd_check {
    char name[112];     /* what is checked, e.g. "belt strength, starts and stops" */
    char unit[12];      /* of value and limit */
    double value, limit;
    bd_check_rule rule;
    int pass;
} bd_check;

/* "at most", "at least", "below", "above": summary.json's limit_is */
const char *bd_check_rule_name(bd_check_rule rule);

/* the checks that apply to this run (st: the static calculation, or NULL
 * when the model has no design or it failed); how many, at most max */
int bd_run_checks(const bd_sim *sim, const bd_static_result *st, bd_check *out, int max);
/* the most checks a run of this model can have (the size of out) */
int bd_run_checks_max(const bd_sim *sim);

#endif
