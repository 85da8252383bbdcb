/* Stable time step. For central differences a mode of circular frequency ω
 * and damping ratio ζ is stable for
 *     Δt ≤ (2/ω)·(√(1+ζ²) − ζ)                         (DESIGN.md; seed 001 eq 6.1 for ζ = 0)
 * The highest frequency of the belt is that of a node between two elements
 * moving against its neighbours: for the axial springs ω² = 4k/m (k = EA/l0,
 * m = node mass), for the bending springs (k_θ = EI/l0, lever l0, a node and
 * its two neighbours) ω² = 16·k_θ/(m·l0²). Their sum bounds the largest
 * eigenvalue (Gershgorin); contacts are linearly implicit and add no limit
 * (pulley_contact.c, idler_contact.c). The
 * Kelvin–Voigt dashpot of ratio ζ_e (eq 4.3, per element) damps that mode
 * with ζ = 2ζ_e. */
#include "sim/timestep.h"

#include <math.h>

const char *bd_time_step_limit_name(bd_time_step_limit kind)
{
    switch (kind) {
    case BD_LIMIT_AXIAL: return "axial stiffness of the belt elements";
    case BD_LIMIT_BENDING: return "bending stiffness of the belt";
    case BD_LIMIT_USER: return "the time step given in the model";
    }
    return "?";
}

static int check_user_step(bd_sim *sim, bd_diag *diag);

int bd_time_step_choose(bd_sim *sim, bd_diag *diag)
{
    if (sim->axial) {
        sim->dt_limit = bd_axial_stable_step(sim);
        sim->limit_kind = BD_LIMIT_AXIAL;
        return check_user_step(sim, diag);
    }
    double m = sim->belt_mpl * sim->l0;   /* lightest node: no material */
    double w_axial = 4.0 * sim->k_axial;
    double w_bend = 16.0 * sim->k_bend / (sim->l0 * sim->l0);
    double omega = sqrt((w_axial + w_bend) / m);
    double zeta = 4.0 * sim->c_axial / (2.0 * m * omega);
    sim->dt_limit = 2.0 / omega * (sqrt(1.0 + zeta * zeta) - zeta);
    /* what limits it: the largest contribution to ω² */
    sim->limit_kind = BD_LIMIT_AXIAL;
    if (w_bend > w_axial)
        sim->limit_kind = BD_LIMIT_BENDING;
    return check_user_step(sim, diag);
}

/* a given step must be stable; else 0.8 × the limit */
static int check_user_step(bd_sim *sim, bd_diag *diag)
{
    double user = sim->def->simulation.time_step;
    if (user > 0.0) {
        if (user > sim->dt_limit) {
            bd_diag_error(diag, sim->def->source, sim->def->simulation.time_step_mark,
                          "simulation.time_step: %g s is above the stability limit %.6g s "
                          "(set by the %s); use a smaller step or 'auto'",
                          user, sim->dt_limit, bd_time_step_limit_name(sim->limit_kind));
            return 1;
        }
        sim->dt = user;
    } else {
        sim->dt = BD_TIME_STEP_SAFETY * sim->dt_limit;
    }
    return 0;
}
