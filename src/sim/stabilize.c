/* Stabilization by kinetic-energy damping (seed 001 §6.2): run the model
 * without contact friction and without drives; each time the kinetic energy
 * passes a maximum, set every velocity to zero. The energy left after each
 * reset shrinks until the system rests in static equilibrium. Time here is
 * an iteration parameter: the clock is set back to 0 afterwards. */
#include "sim/engine.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "parts/parts.h"
#include "sensors/sensors.h"

#define STABILIZE_MAX_STEPS 2000000L
/* converged when the kinetic energy at a peak is below this fraction of the
 * belt's elastic energy (or of 1 J) for three peaks in a row; 1e-9 took 35×
 * the steps on head_drive and moved its tensions by 0.03% (physics.md §7) */
#define STABILIZE_TOL 1e-7

static void zero_velocities(bd_sim *sim)
{
    memset(sim->vx, 0, (size_t)sim->model->n * sizeof *sim->vx);
    memset(sim->vy, 0, (size_t)sim->model->n * sizeof *sim->vy);
    for (int i = 0; i < sim->model->pulley_count; i++) {
        sim->pulleys[i].omega = 0.0;
        sim->pulleys[i].qdot = 0.0;
    }
    for (int i = 0; i < sim->model->idler_count; i++)
        sim->idlers[i].omega = 0.0;
}

int bd_sim_stabilize(bd_sim *sim, FILE *log)
{
    sim->friction_off = 1;
    int feeding = sim->has_feed;
    sim->has_feed = 0;
    double prev = 0.0, scale = sim->model->belt->elastic_energy(sim);
    if (scale < 1.0)
        scale = 1.0;
    int quiet_peaks = 0, resets = 0;
    long k;
    for (k = 0; k < STABILIZE_MAX_STEPS; k++) {
        if (bd_step_once(sim)) {
            sim->friction_off = 0;
            sim->has_feed = feeding;
            return 1;
        }
        double ke = sim->energy.kinetic;
        if (ke < prev) {
            /* a peak: take the energy out */
            zero_velocities(sim);
            resets++;
            quiet_peaks = prev < STABILIZE_TOL * scale ? quiet_peaks + 1 : 0;
            if (quiet_peaks >= 3)
                break;
            prev = 0.0;
        } else {
            prev = ke;
        }
    }
    sim->stabilize_iterations = (int)(k < STABILIZE_MAX_STEPS ? k + 1 : k);
    sim->stabilize_final_kinetic = prev;
    if (k >= STABILIZE_MAX_STEPS)
        bd_sim_warn(sim, "stabilization stopped after %ld steps without reaching rest "
                    "(kinetic energy %.3g J)", k, prev);
    if (log)
        fprintf(log, "stabilized in %d steps (%d resets), final kinetic energy %.3g J\n",
                sim->stabilize_iterations, resets, prev);
    /* the run starts from here: clock, travel and bookkeeping back to zero */
    sim->friction_off = 0;
    sim->has_feed = feeding;
    sim->t = 0.0;
    sim->steps = 0;
    for (int i = 0; i < sim->model->pulley_count; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        p->q = 0.0;
        p->travel_min = p->travel_max = 0.0;
        p->torque_max_abs = 0.0;
        for (int m = p->m->first_part; m < p->m->first_part + p->m->part_count; m++)
            bd_part_reset(&sim->parts[m]);
        if (p->m->def->has_drive)
            bd_monitor_reset(sim, p);
    }
    sim->tension_max = -INFINITY;
    sim->tension_min = INFINITY;
    memset(&sim->energy, 0, sizeof sim->energy);
    bd_sim_start_at_rest(sim);
    return 0;
}
