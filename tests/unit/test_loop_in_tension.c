/* Issue 10's known answer, "the undamped frictionless loop from rest
 * conserves energy", on every belt.
 *
 * The loop (tests/data/loop_from_rest.yaml: gravity-free,
 * frictionless, undamped, a constant-force takeup, laid unstretched) gets
 * its 20 kN as a step. Undamped, its tension then swings from 0 to twice
 * the static value and its waves take the belt into compression every
 * swing (−5 kN on the discrete belt; the run warns "the belt is in
 * compression: raise the takeup force"). A 2D belt in compression lifts
 * off its wraps and lands again when the tension returns, and a landing
 * is inelastic: the discrete belt lost 15.0, 18.5 and 3.0 J at the first
 * three returns (42 J of 421 J in 10 s, docs/physics.md §10; the rfe belt,
 * on the same contacts, 254 J). The axial belt carries compression as a
 * negative tension and loses nothing; the moving-node belt's arc nodes
 * stay on their arcs (test_mn_undamped).
 *
 * Here the takeup force rises from 0 to 20 kN over the first second, so
 * the belt stays in tension and nothing may land. Over 10 s every belt
 * must then book as dissipated less than 0.1 % of the work the takeup
 * put in (about 424 J; measured: discrete 0.0006 J, axial 0 J,
 * moving_node 0.0002 J, rfe 10⁻⁶ J), and balance its energy at the end
 * within 0.1 % of it (measured 0.0006, 0.0007, 0.0002 and 10⁻⁶ J). The
 * 0.1 % is the issue's; what it allows for here is the contacts' and the
 * transport's numerical work, which measures 10⁻⁶ of it. The rfe belt
 * runs a second time at 0.999 of its stable step: what its limit promises
 * must hold. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "belt/belt.h"
#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "testlib.h"

/* the loop on a belt, at its automatic step (fraction 0) or at that
 * fraction of its stable step */
static void run(const char *formulation, double fraction)
{
    char *text = bd_test_read_data("loop_from_rest.yaml");
    char *ramped = text ? bd_test_replaced(text, "force: 20000,", "force: [[0, 0], [1, 20000]],")
                        : NULL;
    char to[128];
    snprintf(to, sizeof to, "damping_ratio: 0, formulation: %s}", formulation);
    char *model = ramped ? bd_test_replaced(ramped, "damping_ratio: 0}", to) : NULL;
    free(text);
    free(ramped);
    CHECK(model != NULL);
    if (!model)
        return;
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(model, &def, &sim);
    if (fraction > 0.0) {
        char step[96];
        snprintf(step, sizeof step, "initial_state: rest, time_step: %.9g}",
                 fraction * sim->model->dt_limit);
        bd_sim_free(sim);
        bd_model_def_free(&def);
        char *fixed = bd_test_replaced(model, "initial_state: rest}", step);
        free(model);
        model = fixed;
        CHECK(model != NULL && bd_test_make_sim(model, &def, &sim) == 0);
        if (!model)
            return;
    }
    free(model);
    double err;
    int ok = bd_test_run_balanced(sim, 10.0, &err) == 0;
    bd_energy_state en;
    bd_sim_energy(sim, &en);
    /* the takeup's work is booked as input −∫q·dF: negative, its force
     * rising while the carriage stands out */
    double scale = fabs(en.input_J);
    printf("%s (step %.4g ms): %s at t = %.3f s; takeup work %.1f J, dissipated %.4f J "
           "(%.2g %%), balance %.2g J (%.2g %%)\n", formulation, 1e3 * sim->model->dt,
           ok ? "completed" : "failed", bd_sim_time(sim), en.input_J, en.dissipated_J,
           100.0 * en.dissipated_J / scale, err, 100.0 * err / scale);
    CHECK(ok);
    CHECK(scale > 300.0);
    CHECK(fabs(en.dissipated_J) < 1e-3 * scale);
    CHECK(fabs(err) < 1e-3 * scale);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

int main(void)
{
    run("discrete", 0.0);
    run("axial", 0.0);
    run("moving_node", 0.0);
    run("rfe", 0.0);
    /* the rfe belt at 0.999 of the stable step its build derived for the
     * implicit rotations (belt/rfe/build.c): a law that promised a longer
     * step than the scheme takes would let the centres' zigzag grow.
     * Measured: balance 2e-5 J of 424 J; with the law's step raised by 5 %
     * the run diverged within 0.007 s */
    run("rfe", 0.999);
    return bd_test_finish("loop_in_tension");
}
