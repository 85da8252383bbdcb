/* What a case costs, to hand out the longest first (runner.h): the run
 * estimate of sim/estimate.c (bd_cost_from_def) for the case's own
 * definition and duration, without building anything. Only the order
 * matters: a wrong estimate costs time, never a result. */
#include "study/study_case.h"

#include "sim/engine.h"

double bd_study_case_cost(const bd_model_def *def, double duration)
{
    bd_cost c;
    if (bd_cost_from_def(def, duration, &c, NULL) != 0 || !(c.dt > 0.0) || !(c.rate > 0.0))
        return duration;   /* the build will say what is wrong */
    return c.seconds;
}
