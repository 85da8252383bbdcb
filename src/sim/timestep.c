/* Stable time step: the belt formulation bounds the highest frequency of
 * its belt (bd_belt_ops.stable_step; for central differences a mode of
 * circular frequency ω and damping ratio ζ is stable for
 * Δt ≤ (2/ω)·(√(1+ζ²) − ζ), DESIGN.md, seed 001 eq 6.1 for ζ = 0), and the
 * step used is BD_TIME_STEP_SAFETY of it, or the model's own if stable. */
#include "sim/timestep.h"

#include <math.h>

const char *bd_time_step_limit_name(bd_time_step_limit kind)
{
    switch (kind) {
    case BD_LIMIT_AXIAL: return "axial stiffness of the belt elements";
    case BD_LIMIT_BENDING: return "bending stiffness of the belt";
    case BD_LIMIT_USER: return "the time step given in the model";
    case BD_LIMIT_TRANSVERSE: return "transverse (string) motion of the span nodes";
    case BD_LIMIT_TRANSPORT: return "belt's passage through the shortest elements";
    case BD_LIMIT_SHEAR: return "shear stiffness of the spring-damping elements";
    }
    return "?";
}

static int check_user_step(bd_sim *sim, bd_diag *diag);

int bd_time_step_choose(bd_sim *sim, bd_diag *diag)
{
    sim->own->dt_limit = sim->own->belt->stable_step(sim, &sim->own->limit_kind);
    /* a property far out of any physical range (a belt 1e308 m thick) can
     * overflow the highest frequency: there is no step to take */
    if (!(sim->own->dt_limit > 0.0 && isfinite(sim->own->dt_limit))) {
        const bd_model_def *def = sim->model->def;
        bd_diag_error(diag, def->source, def->belt.mark,
                      "belt: no stable time step: the %s gives no finite highest "
                      "frequency; a property of the belt is out of any physical range",
                      bd_time_step_limit_name(sim->own->limit_kind));
        return 1;
    }
    return check_user_step(sim, diag);
}

/* a given step must be stable; else 0.8 × the limit */
static int check_user_step(bd_sim *sim, bd_diag *diag)
{
    double user = sim->model->def->simulation.time_step;
    if (user > 0.0) {
        if (user > sim->model->dt_limit) {
            bd_diag_error(diag, sim->model->def->source, sim->model->def->simulation.time_step_mark,
                          "simulation.time_step: %g s is above the stability limit %.6g s "
                          "(set by the %s); use a smaller step or 'auto'",
                          user, sim->model->dt_limit, bd_time_step_limit_name(sim->model->limit_kind));
            return 1;
        }
        sim->own->dt = user;
    } else {
        sim->own->dt = BD_TIME_STEP_SAFETY * sim->own->dt_limit;
    }
    sim->own->inv_dt = 1.0 / sim->own->dt;
    return 0;
}
