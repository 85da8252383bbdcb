/* Physical bounds of the parts' state, checked every step (issue 10 item
 * 7). The divergence check of the belt (step.c, check_elements) sees the
 * element strains, and through them any NaN or infinite node position or
 * velocity (the tension carries the dashpot term c·dl/dt, and 0·NaN is
 * NaN); it does not see a pulley spinning up or a takeup carriage running
 * away from a belt it has lost. These bounds do, at O(pulleys) cost:
 *
 * - every pulley's ω, every carriage's q and q̇ finite;
 * - pulley surface speed |ω|·R and carriage speed |q̇| at most
 *     v_max = max(50 m/s, 10·v_ref),
 *   v_ref the fastest speed a drive of the model asks for: a speed drive's
 *   `speed` (or creep speed), a motor's synchronous speed at the pulley
 *   surface, ω_sync·R/gear_ratio (above it an induction motor brakes).
 *   Belt conveyors run at up to about 10 m/s; 50 m/s is five times the
 *   fastest and ten times a typical one, and a drive cannot push its belt
 *   to ten times its own speed. A pulley's speed follows the belt's, whose
 *   wave speeds are strain × √(EA/m′): at the belt's divergence strain
 *   that too is far beyond any sane bound. A torque drive has no speed of
 *   its own: the 50 m/s floor then holds;
 * - carriage travel |q| at most half the belt loop length L: moving the
 *   carriage by q lengthens the path by at most 2|q| (two strands), so
 *   |q| > L/2 asks the belt to stretch by more than 100 % (the strain the
 *   divergence check stops at) or the loop to have a negative length. The
 *   carriage has left the belt (e.g. lost contact with it). A takeup with
 *   `travel` limits stops at them long before.
 * Out of bounds, the run stops with when, where (the pulley or takeup by
 * name, its centre) and why, as check_elements does for the belt. Nothing
 * is formatted or allocated except on that failure path. */
#include "sim/engine.h"

#include <math.h>
#include <stdio.h>

#include "parts/parts.h"

/* the floor of the speed bound, m/s, and its multiple of the drives' speed */
#define SPEED_BOUND_FLOOR 50.0
#define SPEED_BOUND_FACTOR 10.0

void bd_bounds_prepare(bd_model *m)
{
    m->speed_bound = fmax(SPEED_BOUND_FLOOR, SPEED_BOUND_FACTOR * bd_drives_reference_speed(m->def));
    m->travel_bound = 0.5 * m->path.length;
}

/* the failure path: say when, where and why */
static int out_of_bounds(bd_sim *sim, const bd_pulley_body *p, const char *what, double value,
                         const char *unit, double bound, const char *why)
{
    /* the state's time: the end of this step (held at 0 while stabilizing) */
    const double t = sim->stabilizing ? sim->t : sim->t + sim->model->dt;
    const char *name = p->m->def->name;
    if (!isfinite(value))
        snprintf(sim->fail_msg, sizeof sim->fail_msg,
                 "the simulation diverged at t = %.6f s (step %ld): pulley '%s'%s at "
                 "(x = %.3f, y = %.3f) has %s %g: the model's state is no longer a number; "
                 "the time step %.3g s is too large for the forces acting, or the model is "
                 "unstable", t, sim->steps + 1, name, p->m->movable ? " (takeup)" : "", p->cx,
                 p->cy, what, value, sim->model->dt);
    else
        snprintf(sim->fail_msg, sizeof sim->fail_msg,
                 "the simulation ran away at t = %.6f s (step %ld): pulley '%s'%s at "
                 "(x = %.3f, y = %.3f) has %s %.4g %s, beyond the bound of %.4g %s (%s)",
                 t, sim->steps + 1, name, p->m->movable ? " (takeup)" : "", p->cx, p->cy, what,
                 value, unit, bound, unit, why);
    return 1;
}

int bd_bounds_check(bd_sim *sim)
{
    const bd_model *m = sim->model;
    const double v_max = m->speed_bound, q_max = m->travel_bound;
    for (int i = 0; i < m->pulley_count; i++) {
        const bd_pulley_body *p = &sim->pulleys[i];
        double v = p->omega * p->m->radius;
        /* written so that a NaN fails the test too */
        if (!(fabs(v) <= v_max))
            return out_of_bounds(sim, p, "surface speed", v, "m/s", v_max,
                                 "10 x the fastest drive speed, at least 50 m/s: a runaway; "
                                 "is a drive's torque far above what its belt can carry?");
        if (!p->m->movable)
            continue;
        if (!(fabs(p->qdot) <= v_max))
            return out_of_bounds(sim, p, "carriage speed", p->qdot, "m/s", v_max,
                                 "10 x the fastest drive speed, at least 50 m/s: the carriage "
                                 "runs away");
        if (!(fabs(p->q) <= q_max))
            return out_of_bounds(sim, p, "carriage travel", p->q, "m", q_max,
                                 "half the belt loop: the belt would have to stretch by more "
                                 "than 100 %; the carriage has left the belt");
    }
    return 0;
}
