/* Stabilization by kinetic-energy damping (seed 001 §6.2): "When the
 * kinetic energy of the system attains a maximum, the kinetic energy of the
 * system is set to zero ... by setting the velocities of all the objects to
 * zero", until the total energy is constant; "time is a non-physical
 * iteration (or relaxation) parameter during the stabilization process".
 *
 * So the clock is held at t = 0 (sim->stabilizing; step.c does not advance
 * it): every table — a takeup's force, a drive's torque — is read at t = 0,
 * and the state reached is the equilibrium the run starts from at t = 0.
 *
 * The conveyor is at rest as it stands before a start: drives off, each
 * drive pulley held still as its holdback or brake holds it (p->held: its
 * wrap coupling takes α = 0 and the belt sticks to it by friction, up to
 * the capstan limit), no material fed. Friction stays on everywhere: at
 * rest it holds what a real belt's friction holds, and on the held drive
 * pulley it is what keeps a loaded incline from running back. (With
 * friction and drives off, as before, nothing held the belt: on a loaded
 * incline the belt ran back downhill through the whole step limit.)
 *
 * Converged when the kinetic energy at a peak is below STABILIZE_TOL of the
 * belt's elastic energy (or of 1 J) for three peaks in a row. Then the
 * drive pulleys are let go and the clock, travel and bookkeeping restart
 * from zero; the run's first step finds its drive at t = 0. */
#include "sim/engine.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/clock.h"
#include "parts/parts.h"
#include "sensors/sensors.h"

/* steps at most, unless the caller's options say (bd_run_options) */
#define STABILIZE_MAX_STEPS 2000000L
/* 1e-9 took 35× the steps on head_drive and moved its tensions by 0.03%
 * (physics.md §7) */
#define STABILIZE_TOL 1e-7
/* belt nodes whose displacement the messages quote (sampled evenly) */
#define SAMPLED_NODES 64
/* progress: the wall clock is read every this many steps */
#define PROGRESS_EVERY 1024

static void zero_velocities(bd_sim *sim)
{
    memset(sim->vx, 0, (size_t)sim->model->n * sizeof *sim->vx);
    memset(sim->vy, 0, (size_t)sim->model->n * sizeof *sim->vy);
    if (sim->model->belt->rest_velocities)
        sim->model->belt->rest_velocities(sim, 0.0);
    for (int i = 0; i < sim->model->pulley_count; i++) {
        sim->pulleys[i].omega = 0.0;
        sim->pulleys[i].qdot = 0.0;
    }
    for (int i = 0; i < sim->model->idler_count; i++)
        sim->idlers[i].omega = 0.0;
}

/* at rest at the present positions, as the scheme defines rest (step.c,
 * bd_sim_start_at_rest): the mid-step velocity v(t) = 0, so the half-step
 * velocities are −a·Δt/2. Setting the half-step velocities to zero instead
 * leaves v(t) = a·Δt/2 and the leapfrog's conserved energy
 * ½v(t)² + ½ω²(1 − ω²Δt²/4)x² (the modified energy the Störmer–Verlet
 * scheme keeps exactly on a linear oscillator; Hairer, Lubich & Wanner,
 * Geometric Numerical Integration, Springer 2006) can grow at a reset: a mode near the
 * step's limit, reset every few steps in phase with it, was pumped ~15 %
 * per reset and diverged (an undamped takeup loop held by its drive
 * pulley, 2 of 500 generated conveyors). At v(t) = 0 every reset takes
 * ½v(t)² out and nothing else. */
static int rest_here(bd_sim *sim)
{
    zero_velocities(sim);
    return bd_sim_start_at_rest(sim);
}

/* one step of the kinetic-energy damping: the step, and at a peak of the
 * kinetic energy (below *prev, the last step's) rest where the belt now
 * is (rest_here), the peak into *peak. 1 at a peak, 0 while it rises, −1
 * when the step or the rest failed (sim->fail_msg) */
static int damped_step(bd_sim *sim, double *prev, double *peak)
{
    if (bd_step_once(sim))
        return -1;
    double ke = sim->energy.kinetic;
    if (!(ke < *prev)) {
        *prev = ke;
        return 0;
    }
    if (rest_here(sim))
        return -1;
    *peak = *prev;
    *prev = 0.0;
    return 1;
}

/* the drive pulleys held (1) or let go (0); the clock, drives and feed
 * with them */
static void hold(bd_sim *sim, int on, int feeding)
{
    sim->stabilizing = on;
    sim->has_feed = on ? 0 : feeding;
    for (int i = 0; i < sim->model->pulley_count; i++)
        sim->pulleys[i].held = on && sim->pulleys[i].m->def->has_drive;
}

/* where a sample of the belt's nodes is (before), and how far the farthest
 * of them has moved since (after): the messages' "the belt moved" */
typedef struct node_sample {
    int count, node[SAMPLED_NODES];
    double x[SAMPLED_NODES], y[SAMPLED_NODES];
} node_sample;

static void sample_nodes(const bd_sim *sim, node_sample *s)
{
    int n = sim->model->n;
    s->count = n < SAMPLED_NODES ? n : SAMPLED_NODES;
    for (int k = 0; k < s->count; k++) {
        s->node[k] = (int)((long)k * n / s->count);
        s->x[k] = sim->x[s->node[k]];
        s->y[k] = sim->y[s->node[k]];
    }
}

static double sample_moved(const bd_sim *sim, const node_sample *s)
{
    double d = 0.0;
    for (int k = 0; k < s->count; k++)
        d = fmax(d, hypot(sim->x[s->node[k]] - s->x[k], sim->y[s->node[k]] - s->y[k]));
    return d;
}

static void report_progress(const bd_run_options *opt, long steps, double wall)
{
    bd_run_progress p = {0};
    p.wall_s = wall;
    p.stabilize_steps = steps;
    opt->progress(&p, opt->progress_ctx);
}

/* the run starts from here: clock, travel and bookkeeping back to zero,
 * at rest; 1: the forces there failed (fail_msg) */
static int restart_clock(bd_sim *sim)
{
    sim->t = 0.0;
    sim->steps = 0;
    for (int i = 0; i < sim->model->pulley_count; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        p->q = 0.0;
        /* what the held pulley's holdback carried: the belt's friction
         * torque on it, reversed */
        for (int m = p->m->first_part; m < p->m->first_part + p->m->part_count; m++) {
            bd_part_reset(&sim->parts[m]);
            bd_part_release(&sim->parts[m], -p->torque_friction);
        }
    }
    /* travel from q = 0, extremes, monitors, probes, lift-off */
    bd_sim_records_restart(sim);
    memset(&sim->energy, 0, sizeof sim->energy);
    return bd_sim_start_at_rest(sim);
}

int bd_sim_stabilize(bd_sim *sim, const bd_run_options *opt, char *err, size_t errlen)
{
    const double wall0 = bd_wall_seconds();
    double last_progress = 0.0;
    int feeding = sim->has_feed;
    node_sample laid;
    sample_nodes(sim, &laid);
    hold(sim, 1, feeding);
    /* at rest with the drive pulleys held: the velocities the build left
     * were those of rest with the drives free */
    int status = rest_here(sim) ? BD_RUN_FAILED : BD_RUN_OK;
    double prev = 0.0, peak = 0.0, scale = sim->model->belt->elastic_energy(sim);
    if (scale < 1.0)
        scale = 1.0;
    int quiet_peaks = 0, resets = 0, converged = 0;
    long k, max_steps = opt && opt->stabilize_max_steps > 0 ? opt->stabilize_max_steps
                                                            : STABILIZE_MAX_STEPS;
    err[0] = '\0';
    for (k = 0; status == BD_RUN_OK && k < max_steps && !converged; k++) {
        if (opt && opt->interrupted && *opt->interrupted) {
            status = BD_RUN_INTERRUPTED;
            break;
        }
        int step = damped_step(sim, &prev, &peak);
        if (step < 0) {
            status = BD_RUN_FAILED;
            break;
        }
        if (step > 0) {
            resets++;
            quiet_peaks = peak < STABILIZE_TOL * scale ? quiet_peaks + 1 : 0;
            converged = quiet_peaks >= 3;
        }
        if (opt && opt->progress && k % PROGRESS_EVERY == 0) {
            double w = bd_wall_seconds() - wall0;
            if (w - last_progress > 0.25) {
                report_progress(opt, k + 1, w);
                last_progress = w;
            }
        }
    }
    /* at rest and still held: what each holdback carries now is the belt's
     * static friction torque on its pulley (the speed drives take it over) */
    if (status == BD_RUN_OK) {
        zero_velocities(sim);
        if (bd_step_forces(sim))
            status = BD_RUN_FAILED;
    }
    hold(sim, 0, feeding);
    sim->stabilize_iterations = k;
    sim->stabilize_resets = resets;
    sim->stabilize_converged = converged;
    sim->stabilize_final_kinetic = peak;
    double moved = sample_moved(sim, &laid);
    if (status == BD_RUN_FAILED) {
        snprintf(err, errlen, "stabilization failed in its step %ld (relaxing to rest before "
                 "t = 0; the belt had moved up to %.3g m from where it was laid): %s", k + 1,
                 moved, sim->fail_msg);
        return status;
    }
    if (status == BD_RUN_INTERRUPTED) {
        snprintf(err, errlen, "interrupted while stabilizing, after %ld steps (before t = 0; "
                 "nothing simulated)", k);
        return status;
    }
    if (!converged) {
        snprintf(err, errlen, "stabilization did not reach rest in %ld steps: the kinetic "
                 "energy still peaks at %.3g J (%.2g of the belt's elastic energy; rest is "
                 "below %.0e for three peaks); the belt moved up to %.3g m from where it was "
                 "laid%s. The run starts from that state, not in equilibrium",
                 k, peak, peak / scale, STABILIZE_TOL, moved,
                 moved > sim->model->l0 ? ", more than an element: it creeps (slips on a held "
                                          "drive pulley, or a pulley with no drive lets it run)"
                                        : "");
        bd_sim_warn(sim, "%s", err);
    }
    if (restart_clock(sim)) {
        snprintf(err, errlen, "the stabilized state could not be started from: %s",
                 sim->fail_msg);
        return BD_RUN_FAILED;
    }
    return BD_RUN_OK;
}

/* A belt whose layout is not its own equilibrium (the rfe belt's,
 * belt/rfe/build.c; `static` or `rest`): its centres are laid on the
 * string's path and its elements turned to the least shear and alignment
 * with the centres held there, but where the path's curvature jumps (a
 * tangent point) a chain of rigid elements cannot lie with every centre
 * on it; what the turns cannot take up stays in the shear, which lets it
 * go through the centres' zigzag, the fastest mode, in the first steps. A
 * mode that near the step's limit is booked with its potential energy
 * some times what the scheme keeps of it (the modified energy above), so
 * the energy account missed what it lost: 0.12 J of the 2.4 J laid on
 * examples/flat_belt_drive.yaml at its rfe default (balance 4.5 %; laid at
 * rest 11.4 %), 165 J on the cement plant at 0.2 m (5·10⁻⁴). So the build
 * lets the belt go where it is laid for the time its own modes take to
 * settle (bd_belt_ops settle_time), by the kinetic-energy damping of
 * bd_sim_stabilize (clock held, drives held, no feed), and the run starts
 * from there, at rest. Not a stabilization: the slow modes (the spans'
 * sag, a takeup) stay nearly as laid, and a stabilization, when asked
 * for, does all of it. SETTLE_MAX_STEPS bounds what it adds to the build
 * (83 steps on the cement plant). */
#define SETTLE_MAX_STEPS 2000L

int bd_sim_settle(bd_sim *sim)
{
    const double settle_s = sim->model->belt->settle_time(sim);
    long steps = (long)ceil(settle_s / sim->model->dt);
    if (steps > SETTLE_MAX_STEPS)
        steps = SETTLE_MAX_STEPS;
    if (steps <= 0)
        return 0;
    int feeding = sim->has_feed;
    hold(sim, 1, feeding);
    int failed = rest_here(sim);
    const double e0 = bd_energy_potential(sim);
    double prev = 0.0, peak = 0.0;
    int resets = 0;
    long k;
    for (k = 0; !failed && k < steps; k++) {
        int step = damped_step(sim, &prev, &peak);
        if (step < 0) {
            failed = 1;
            break;
        }
        resets += step;
    }
    if (!failed) {
        zero_velocities(sim);
        failed = bd_step_forces(sim);
    }
    hold(sim, 0, feeding);
    sim->settle_steps = k;
    sim->settle_resets = resets;
    sim->settle_released = e0 - bd_energy_potential(sim);
    return failed || restart_clock(sim);
}
