/* The run: optional stabilization, then the step loop with outputs at every
 * output interval, progress reports to the caller, and a clean stop on
 * divergence or SIGINT with everything written so far flushed and valid. */
#include "io/outputs.h"
#include "sim/engine.h"
#include "parts/parts.h"
#include "sensors/sensors.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/clock.h"
#include "model/secondary.h"

static void progress(const bd_run_options *opt, const bd_sim *sim, double duration, double wall,
                     int done)
{
    bd_run_progress p = {sim->t, duration, wall, done, 0};
    opt->progress(&p, opt->progress_ctx);
}

/* energy at t = 0: the reference of the balance */
static void energy_start(bd_sim *sim)
{
    bd_energy *en = &sim->energy;
    memset(en, 0, sizeof *en);
    en->potential = bd_energy_potential(sim);
    en->initial = en->potential;
}

/* events the step loop only records (no text or allocation there) become
 * warnings: a takeup at the end of its travel, a slack belt end at an axial
 * pulley. Saying them twice is harmless (bd_sim_warn drops repeats). */
void bd_sim_report_events(bd_sim *sim)
{
    for (int k = 0; k < sim->part_count; k++)
        bd_part_report_events(sim, &sim->parts[k]);
    if (sim->model->belt->report_events)
        sim->model->belt->report_events(sim);
    bd_lift_off_report(sim);
}

/* m/s and s: a stop case's belt is at rest when every pulley's surface
 * has stayed below REST_SPEED for REST_TIME */
#define REST_SPEED 0.02
#define REST_TIME 0.5

static int pulleys_at_rest(const bd_sim *sim)
{
    for (int i = 0; i < sim->model->pulley_count; i++)
        if (fabs(sim->pulleys[i].omega * sim->pulleys[i].m->radius) >= REST_SPEED)
            return 0;
    return 1;
}

int bd_sim_run(bd_sim *sim, const bd_run_options *opt, char *err, size_t errlen)
{
    double rest_since = -1.0;
    double wall0 = bd_wall_seconds();
    bd_outputs out;
    if (bd_outputs_open(&out, sim, opt->out_dir, opt->hdf5, err, errlen))
        return BD_RUN_BAD_INPUT;
    const double duration = sim->model->def->simulation.duration;
    const double interval = sim->model->def->simulation.output_interval;
    const double dt = sim->model->dt;
    double next_out = interval;
    double last_progress = 0.0;
    int status = BD_RUN_OK, stabilize_ended = 0;
    /* relax first when asked. Not at rest: said now (opt->message) and in
     * the warnings, and the run goes on; a failure or an interruption
     * there ends the run with its outputs (no row: nothing simulated) and
     * its message in err */
    if (sim->model->def->simulation.stabilize) {
        status = bd_sim_stabilize(sim, opt, err, errlen);
        stabilize_ended = status != BD_RUN_OK;
        if (stabilize_ended) {
            bd_sim_warn(sim, "%s", err);
        } else {
            if (err[0] && opt->message)
                opt->message(err, opt->message_ctx);
            err[0] = '\0';
        }
    }
    if (status == BD_RUN_OK) {
        energy_start(sim);
        bd_sim_running_start(sim, duration);
        bd_outputs_row(&out, sim, sim->t);
    }
    /* the progress of the simulated time counts its own wall time (the
     * stabilization reported its own), so that the remaining time and the
     * real-time factor are the run's */
    const double wall_run0 = bd_wall_seconds();
    while (status == BD_RUN_OK && sim->t < duration - 0.5 * dt) {
        double t_step = sim->t;
        sim->want_energy = t_step >= next_out - 0.5 * dt;
        if (bd_step_once(sim)) {
            status = BD_RUN_FAILED;
            break;
        }
        if (opt->records_from_s > 0.0 && out.records_from == 0.0
            && sim->t >= opt->records_from_s - 0.5 * dt) {
            bd_sim_records_restart(sim);
            bd_outputs_records_restart(&out, sim->t);
        }
        if (sim->want_energy) {
            sim->want_energy = 0;
            bd_energy_update_balance(sim);
            bd_outputs_row(&out, sim, t_step);
            while (next_out <= t_step + 0.5 * dt)
                next_out += interval;
            if (opt->end_at_rest_after_s > 0.0 && sim->t > opt->end_at_rest_after_s) {
                if (!pulleys_at_rest(sim))
                    rest_since = -1.0;
                else if (rest_since < 0.0)
                    rest_since = sim->t;
                else if (sim->t - rest_since >= REST_TIME)
                    break;
            }
            if (opt->interrupted && *opt->interrupted) {
                status = BD_RUN_INTERRUPTED;
                break;
            }
            if (opt->progress) {
                double w = bd_wall_seconds() - wall_run0;
                if (w - last_progress > 0.25) {
                    progress(opt, sim, duration, w, 0);
                    last_progress = w;
                }
            }
        }
    }
    if (status == BD_RUN_OK) {
        /* the final state, at t as every row is: a step from t books the
         * potential energy at t and the kinetic energy of the speeds at t
         * (the mean of t − Δt/2 and t + Δt/2). Taking the potential energy
         * at t with the last step's kinetic energy (t − Δt) instead erred
         * by a step's change of the energy: 2.4e-3 of the energy scale on
         * an undamped takeup oscillation ending mid-swing, where every
         * other row balanced within 4e-5. */
        double t_step = sim->t;
        sim->want_energy = 1;
        if (bd_step_once(sim)) {
            status = BD_RUN_FAILED;
        } else {
            sim->want_energy = 0;
            bd_energy_update_balance(sim);
            bd_outputs_row(&out, sim, t_step);
        }
    }
    if (opt->progress)
        progress(opt, sim, duration, bd_wall_seconds() - wall_run0, 1);
    if (status == BD_RUN_FAILED && !stabilize_ended)
        snprintf(err, errlen, "%s", sim->fail_msg);
    else if (status == BD_RUN_INTERRUPTED && !stabilize_ended)
        snprintf(err, errlen, "interrupted at t = %.4f s; outputs written up to that time", sim->t);
    bd_sim_report_events(sim);
    if (sim->energy.dissipation_fall_rel > BD_DISSIPATION_FALL_WARN && !stabilize_ended)
        bd_sim_warn(sim, "the energy account booked negative dissipation: the dissipated "
                    "energy fell by %.2g %% of the energy in play in the output interval "
                    "ending at t = %.3f s (a force taken as dissipative put energy into "
                    "the belt; results near that time are suspect)",
                    100.0 * sim->energy.dissipation_fall_rel, sim->energy.dissipation_fall_t);
    if (sim->tension_min < 0.0 && !stabilize_ended)
        bd_sim_warn(sim, "the belt is in compression (lowest tension %.0f N at t = %.3f s, "
                    "s = %.2f m): raise the takeup force", sim->tension_min, sim->tension_min_t,
                    sim->tension_min_s);
    const bd_model_def *def = sim->model->def;
    /* steady running against the model's own law (sensors/running.c) */
    bd_running_check rc;
    bd_sim_running_check(sim, &rc);
    if (rc.checked && !rc.pass && status == BD_RUN_OK) {
        /* above the law: the belt model dissipates what the model does not
         * declare (physics.md §10); below it: a declared resistance does
         * not act in full (the belt off its idlers, a load not all there),
         * or energy enters that the model does not declare */
        const int above = rc.error_rel > 0.0;
        const bd_formulation fm = def->belt.formulation;
        const char *refine = fm == BD_FORMULATION_MOVING_NODE
                           ? "halve belt.span_element_length and wrap_element_angle_deg"
                           : "halve belt.element_length";
        bd_sim_warn(sim, "running force: in steady running (%.4g to %.4g s, %.3g m/s) the drives "
                    "deliver %.1f N, %+.1f %% against the model's own resistance law's %.1f N "
                    "(idler rolling resistance, lift, feed, bearings%s; tolerance %.0f %%): %s. "
                    "The running force, power and tensions carry that error: %s and compare "
                    "(beltdyn run --mesh-check)%s",
                    rc.from_s, rc.to_s, rc.speed_mps, rc.force_N, 100.0 * rc.error_rel,
                    rc.law_N, bd_secondary_individual(def) ? ", design.secondary" : "",
                    100.0 * rc.tolerance_rel,
                    above ? "the belt model dissipates energy the model does not declare "
                            "(docs/physics.md section 10)"
                          : "some declared resistance does not act in full (the belt lifted "
                            "off its idlers, material not all on the belt) or energy enters "
                            "that the model does not declare",
                    refine,
                    above && sim->model->EI <= 0.0
                        && (fm == BD_FORMULATION_DISCRETE || fm == BD_FORMULATION_RFE)
                        ? ", give the belt its bending stiffness (belt.bending_stiffness), "
                          "or run the axial or moving_node belt for the running force"
                        : "");
    }
    /* the peak against the allowable during starts and stops
     * (design.safety_factor.starting: DIN 22101's belt-strength check for
     * the non-steady states; model-format.md) */
    double allow = def->belt.rated_tension / def->design.safety_factor.starting;
    if (def->belt.rated_tension > 0.0 && sim->tension_max > allow && !stabilize_ended)
        bd_sim_warn(sim, "belt strength: peak tension %.0f N at t = %.3f s, s = %.2f m exceeds "
                    "the allowable during starts and stops, rated %.0f N / safety factor %.3g "
                    "= %.0f N", sim->tension_max, sim->tension_max_t, sim->tension_max_s,
                    def->belt.rated_tension, def->design.safety_factor.starting, allow);
    const char *word = status == BD_RUN_OK ? "completed"
                     : status == BD_RUN_FAILED ? "failed" : "interrupted";
    int closed = bd_outputs_close(&out, sim, bd_wall_seconds() - wall0, word);
    sim->static_warnings = out.static_warnings;
    if (closed && status == BD_RUN_OK) {
        snprintf(err, errlen, "could not write the outputs in '%s'", opt->out_dir);
        return BD_RUN_FAILED;
    }
    return status;
}
