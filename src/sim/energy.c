/* Energy bookkeeping (cli.md `energy`): the potential energy is the belt's
 * (its formulation's: gravity of belt and material, each from its own
 * datum (the lumped belt's material from the discharge pulley's height),
 * elastic energy of elements and bending springs), the pulleys' weight, the
 * contact springs of the wraps, the potential −F·q of the takeup pulls (a
 * gravity takeup's counterweight included) and the transmissions' spans.
 * Kinetic energy and the work of dissipative forces and drives are booked
 * in the step (sim/step.c). */
#include "sim/engine.h"

#include <math.h>

#include "parts/parts.h"

double bd_energy_potential(const bd_sim *sim)
{
    const bd_belt_ops *belt = sim->model->belt;
    double g = sim->model->gravity;
    double e = belt->potential(sim);
    for (int i = 0; i < sim->model->pulley_count; i++) {
        const bd_pulley_body *p = &sim->pulleys[i];
        e += p->m->def->mass * g * p->cy;
        if (belt->wrap_energy)
            e += belt->wrap_energy(sim, p);
        for (int k = p->m->first_part; k < p->m->first_part + p->m->part_count; k++)
            e += bd_part_potential(sim, &sim->parts[k]);
    }
    return e + bd_parts_stored_energy(sim);
}

/* the largest |E_k + E_p + E_d − E_in − E_0| / max(|E_0|, E_in, max E_k, 1 J)
 * so far (cli.md `balance_error_rel`), and the largest fall of the
 * dissipated energy between two checks on the same scale: every force the
 * account books as dissipative (dashpots, friction, rolling resistance,
 * the implicit part of the contacts, bearings) must take energy out over
 * an output interval; one that puts energy in is reported (run.c) */
void bd_energy_update_balance(bd_sim *sim)
{
    bd_energy *en = &sim->energy;
    double dissipated, input;
    bd_energy_at_t(en, &dissipated, &input);
    double err = fabs(en->kinetic + en->potential + dissipated - input - en->initial);
    double scale = fabs(en->initial);
    if (input > scale)
        scale = input;
    if (en->max_kinetic > scale)
        scale = en->max_kinetic;
    if (scale < 1.0)
        scale = 1.0;
    if (err / scale > en->balance_error_rel)
        en->balance_error_rel = err / scale;
    double fall = (en->dissipated_checked - dissipated) / scale;
    if (fall > en->dissipation_fall_rel) {
        en->dissipation_fall_rel = fall;
        en->dissipation_fall_t = sim->t;
    }
    en->dissipated_checked = dissipated;
}

/* the dissipated and input energy at t, where the kinetic and potential
 * energy are (derived in docs/physics.md §9): the step books its works with the mid-step velocity v(t) over
 * [t − Δt/2, t + Δt/2], half a step past t. Without this the balance erred
 * by (input − dissipated power)·Δt/2, first order in Δt: 0.6–0.9 % of the
 * energy scale on motor starts, whose torque changes by 10 kN·m in 0.1 s,
 * and back to zero at steady running. The contacts' springs' energy
 * (bd_energy `springs`) counts as potential, not as dissipated. */
void bd_energy_at_t(const bd_energy *en, double *dissipated, double *input)
{
    /* net of what the contacts' springs took in since t = 0 (bd_energy) */
    *dissipated = en->dissipated - 0.5 * en->step_dissipated - en->step_dissipated_after
                - (en->springs - en->springs0);
    *input = en->input - 0.5 * en->step_input - en->step_input_after;
}

double bd_element_s(const bd_sim *sim, int e)
{
    return sim->model->belt->element_s(sim, e);
}

double bd_element_speed(const bd_sim *sim, int e)
{
    return sim->model->belt->element_speed(sim, e);
}
