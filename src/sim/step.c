/* The one step loop, for every belt formulation: explicit central
 * differences (seed 001 eqs 4.58–4.60, 4.62, 4.64–4.65, 4.67, 4.69).
 * Forces at t from positions at t and velocities at t − Δt/2, then
 * velocities to t + Δt/2 and positions to t + Δt. Energy is booked with
 * mid-step velocities v(t) = (v⁻ + v⁺)/2, for which the scheme's
 * kinetic-energy change is exactly Σ F·v(t)·Δt.
 *
 * The formulation (sim->model->belt, belt/belt.h) does what depends on how the
 * belt is discretized; the parts (parts/) and sensors (sensors/) never see
 * which one it is. */
#include "sim/engine.h"

#include <math.h>
#include <stdio.h>

#include "parts/parts.h"
#include "sensors/sensors.h"

/* strain beyond which an element is taken as diverged, and the shortening
 * at which it counts as reversed */
#define DIVERGED_STRAIN 1.0
#define REVERSED_STRAIN (-0.9)

/* after the forces: stop a diverged run with when, where and why; keep
 * the run's tension extremes */
static int check_elements(bd_sim *sim)
{
    double hi = sim->step_tension_max, lo = sim->step_tension_min;
    int nan_at = -1;
    if (sim->step_tension_nan) {
        /* a NaN: find the first element that has it (failure path only) */
        for (int e = 0; e < sim->model->n && nan_at < 0; e++)
            if (!(sim->tension[e] == sim->tension[e]))
                nan_at = e;
        hi = NAN;
    }
    const bd_belt_ops *belt = sim->model->belt;
    if (!(hi == hi) || !(lo == lo) || hi > DIVERGED_STRAIN * sim->model->EA
        || lo < REVERSED_STRAIN * sim->model->EA) {
        int e = nan_at >= 0 ? nan_at
              : hi > DIVERGED_STRAIN * sim->model->EA ? bd_tension_element(sim, hi)
                                                      : bd_tension_element(sim, lo);
        double strain = belt->element_strain(sim, e);
        char what[96];
        if (nan_at >= 0)
            /* the strain may be finite: a node's velocity is not (the
             * tension's dashpot term c·dl/dt carries it) */
            snprintf(what, sizeof what, "tension NaN (strain %.3g)", strain);
        else
            snprintf(what, sizeof what, "strain %.3g%s", strain,
                     strain < 0.0 ? " (element reversed)" : "");
        snprintf(sim->fail_msg, sizeof sim->fail_msg,
                 "the simulation diverged at t = %.6f s (step %ld): %s belt element %d at "
                 "s = %.3f m (x = %.3f, y = %.3f) has %s; the time step %.3g s "
                 "is too large for the forces acting, or the model is unstable",
                 sim->t, sim->steps, belt->name, e, belt->element_s(sim, e), sim->x[e],
                 sim->y[e], what, sim->model->dt);
        return 1;
    }
    if (hi > sim->tension_max) {
        sim->tension_max = hi;
        sim->tension_max_t = sim->t;
        sim->tension_max_s = belt->element_s(sim, bd_tension_element(sim, hi));
    }
    if (lo < sim->tension_min) {
        sim->tension_min = lo;
        sim->tension_min_t = sim->t;
        sim->tension_min_s = belt->element_s(sim, bd_tension_element(sim, lo));
    }
    return 0;
}

/* every force at t: the belt's own, the parts' torques, the belt–pulley
 * coupling at each pulley (what the pulley feels), the supports */
int bd_step_forces(bd_sim *sim)
{
    const bd_belt_ops *belt = sim->model->belt;
    sim->energy.springs = 0.0;   /* summed by the contacts below */
    belt->forces(sim);
    if (check_elements(sim))
        return 1;
    bd_pulley_resistance_update(sim);
    for (int i = 0; i < sim->model->pulley_count; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        belt->wrap(sim, p, bd_pulley_external_torque(sim, p));
    }
    if (belt->supports)
        belt->supports(sim);
    return 0;
}

void bd_run_records_clear(bd_sim *sim)
{
    sim->tension_max = -INFINITY;
    sim->tension_min = INFINITY;
    bd_lift_off_reset(sim);
}

void bd_sim_records_restart(bd_sim *sim)
{
    for (int i = 0; i < sim->model->pulley_count; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        p->travel_min = p->travel_max = p->q;
        p->torque_max_abs = 0.0;
        if (p->m->def->has_drive)
            bd_monitor_reset(sim, p);
    }
    for (int k = 0; k < sim->part_count; k++)
        bd_part_records_clear(&sim->parts[k]);
    for (int i = 0; i < sim->model->probe_count; i++) {
        sim->probes[i].tension_max = -INFINITY;
        sim->probes[i].tension_min = INFINITY;
    }
    bd_run_records_clear(sim);
}

/* A run starts at rest: v(0) = 0. The scheme carries velocities at half
 * steps, so the first one it needs is v(−Δt/2) = −a(0)·Δt/2 (nodes, pulley
 * rotation, takeup carriages, idlers); starting from
 * v(−Δt/2) = 0 instead would give the system a spurious kinetic energy
 * ½m(a·Δt/2)² wherever the initial state is not exactly in equilibrium. */
int bd_sim_start_at_rest(bd_sim *sim)
{
    double h = 0.5 * sim->model->dt;
    if (bd_step_forces(sim))
        return 1;
    for (int i = 0; i < sim->model->n; i++) {
        sim->vx[i] = -sim->fx[i] / sim->mass[i] * h;
        sim->vy[i] = -sim->fy[i] / sim->mass[i] * h;
    }
    if (sim->model->belt->rest_velocities)
        sim->model->belt->rest_velocities(sim, h);
    for (int i = 0; i < sim->model->pulley_count; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        p->omega = -p->alpha * h;
        /* a free carriage: its pull and the belt's (the wrap coupling solved
         * its acceleration with the pulley's) */
        double Mc;
        double pull = bd_pulley_carriage(sim, p, &Mc);
        p->qdot = Mc > 0.0 ? -(pull + p->f_axis) / Mc * h : 0.0;
    }
    for (int i = 0; i < sim->model->idler_count; i++)
        sim->idlers[i].omega = -sim->idlers[i].alpha * h;
    return 0;
}

/* one step; returns 0 or 1 (failed, message in sim->fail_msg) */
static int step(bd_sim *sim)
{
    const bd_belt_ops *belt = sim->model->belt;
    bd_energy *en = &sim->energy;

    const double dissipated0 = en->dissipated, input0 = en->input;
    en->step_input_at_t = 0.0;
    en->step_dissipated_after = en->step_input_after = 0.0;
    /* potential energy at t (positions before the update) when asked */
    const int reading = sim->want_energy || sim->energy_every_step;
    if (reading && belt->sync)
        belt->sync(sim);
    if (reading)
        en->potential = bd_energy_potential(sim);
    /* forces → part torques → wrap coupling → supports */
    if (bd_step_forces(sim))
        return 1;
    /* the contacts' springs at t (the forces phase just summed them):
     * potential energy, from the first step on (bd_energy) */
    if (!en->springs_started) {
        en->springs_started = 1;
        en->springs0 = en->springs;
        en->initial += en->springs;
    }
    if (sim->want_energy || sim->energy_every_step)
        en->potential += en->springs;

    /* integrate: belt nodes, then the parts (pulleys, transmissions,
     * carriages, idlers), then what follows the parts' motion */
    double ke = 0.0, w_nc = 0.0;
    belt->integrate(sim, &ke, &w_nc);
    bd_pulleys_advance(sim, &ke, &w_nc);
    bd_idlers_advance(sim, &ke, &w_nc);
    if (belt->after_parts)
        belt->after_parts(sim);
    /* the parts' physical bounds: a runaway pulley or carriage (bounds.c) */
    if (bd_bounds_check(sim))
        return 1;
    en->dissipated -= w_nc;
    en->kinetic = ke;
    if (ke > en->max_kinetic)
        en->max_kinetic = ke;

    /* material lands, rides and leaves */
    if (sim->model->material_mpl > 0.0)
        belt->material(sim);
    en->step_dissipated = en->dissipated - dissipated0 - en->step_dissipated_after;
    en->step_input = en->input - input0 - en->step_input_at_t - en->step_input_after;

    /* time, then the sensors at the new time; held at 0 while stabilizing
     * (seed 001 §6.2: time is there an iteration parameter, stabilize.c) */
    if (!sim->stabilizing)
        sim->t += sim->model->dt;
    bd_sensors_update(sim);
    sim->steps++;
    /* what is read after it (outputs, the energy account) */
    if (reading && belt->sync)
        belt->sync(sim);
    return 0;
}

int bd_step_once(bd_sim *sim)
{
    if (!step(sim))
        return 0;
    /* a failed run's state, as it was, for what is written of it */
    if (sim->model->belt->sync)
        sim->model->belt->sync(sim);
    return 1;
}

int bd_sim_step(bd_sim *sim, long count, char *err, size_t errlen)
{
    int failed = 0;
    for (long k = 0; k < count && !failed; k++)
        if (bd_step_once(sim)) {
            snprintf(err, errlen, "%s", sim->fail_msg);
            failed = 1;
        }
    if (sim->model->belt->sync)
        sim->model->belt->sync(sim);
    return failed;
}
