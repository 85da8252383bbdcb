/* What a case costs, to hand out the longest first (runner.h). The cost
 * estimate of sim/estimate.c for the case's own definition, without
 * building anything: (nodes + idlers) × steps ÷ the formulation's measured
 * rate, the step 0.8 × the stable step of its elements or the model's
 * own. Only the order matters: a wrong estimate costs time, never a
 * result. */
#include "study/study_case.h"

#include <math.h>

#include "belt/belt.h"
#include "model/path.h"
#include "sim/timestep.h"

double bd_study_case_cost(const bd_model_def *def, double duration)
{
    const bd_belt_ops *ops = bd_belt_ops_for(def->belt.formulation);
    bd_path path;
    bd_diag quiet;
    bd_diag_init(&quiet);
    int bad = !ops || bd_path_build(def, &path, &quiet);
    bd_diag_free(&quiet);
    if (bad)
        return duration;   /* the build will say what is wrong */
    bd_belt_estimate be;
    ops->estimate(def, &path, &be);
    bd_path_free(&path);
    double dt = def->simulation.time_step > 0.0 ? def->simulation.time_step
                                                : BD_TIME_STEP_SAFETY * be.stable_step;
    if (!(dt > 0.0) || !(be.rate > 0.0))
        return duration;
    return (be.nodes + be.idlers) * ceil(duration / dt) / be.rate;
}
