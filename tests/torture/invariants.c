/* The invariant checks of one run (invariants.h). */
#include "invariants.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* the belt speed at which the motors' Kloss curves deliver the law's force
 * (every drive a motor with the same data, sharing the force equally) */
static double motor_speed(const bd_running_law *law, const bd_model_def *def)
{
    int drives = 0;
    const bd_pulley_def *d = NULL;
    for (int i = 0; i < def->pulley_count; i++)
        if (def->pulleys[i].has_drive) {
            drives++;
            d = &def->pulleys[i];
        }
    if (!d)
        return 0.0;
    const bd_motor_def *m = &d->drive.motor;
    double w_sync = m->synchronous_speed_rpm * 2.0 * 3.14159265358979323846 / 60.0;
    double w_rated = m->rated_speed_rpm * 2.0 * 3.14159265358979323846 / 60.0;
    double k = m->breakdown_torque_ratio;
    double Tb = k * m->rated_power / w_rated;
    double s_r = 1.0 - m->rated_speed_rpm / m->synchronous_speed_rpm;
    double sb = s_r * (k + sqrt(k * k - 1.0));
    double lo = 0.0, hi = sb, v = 0.0;
    for (int it = 0; it < 100; it++) {
        double s = 0.5 * (lo + hi);
        v = (1.0 - s) * w_sync / m->gear_ratio * d->radius;
        double T = m->gear_ratio * 2.0 * Tb * s * sb / (s * s + sb * sb);
        double need = (bd_running_law_force(law, v, NULL) / drives) * d->radius
                    + d->bearing_damping * v / d->radius;
        if (T < need)
            lo = s;
        else
            hi = s;
    }
    return v;
}

/* the speed the model's drives aim at: a speed drive's set speed, the
 * motors' speed at the law's force, or (torque drives: none) the speed
 * measured */
static double model_speed(const bd_running_law *law, const bd_model_def *def, double measured)
{
    for (int i = 0; i < def->pulley_count; i++) {
        const bd_pulley_def *d = &def->pulleys[i];
        if (d->has_drive && d->drive.control == BD_CONTROL_SPEED)
            return d->drive.speed;
        if (d->has_drive && d->drive.control == BD_CONTROL_MOTOR)
            return motor_speed(law, def);
    }
    return measured;
}

void bd_torture_run(const char *yaml, const char *label, const bd_torture_options *opt,
                    bd_torture_result *res)
{
    memset(res, 0, sizeof *res);
    double wall0 = now();
    double *fs = NULL, *vs = NULL;
    bd_model_def def;
    bd_diag diag;
    bd_diag_init(&diag);
    bd_sim *sim = NULL;
    if (bd_model_load_string(yaml, strlen(yaml), label, &def, &diag)
        || bd_sim_create(&def, &sim, &diag)) {
        snprintf(res->message, sizeof res->message, "does not load: %s",
                 diag.count + diag.warning_count > 0 ? diag.lines[0] : "?");
        bd_diag_free(&diag);
        bd_model_def_free(&def);
        return;
    }
    bd_diag_free(&diag);
    res->loaded = 1;
    res->nodes = bd_sim_node_count(sim);
    /* the model's own resistance law (sim/running_law.c), which the
     * steady drive force is held to */
    bd_running_law law;
    bd_running_law_build(sim, &law);
    char err[600];
    if (def.simulation.stabilize) {
        bd_run_options ro = {0};
        char serr[600] = "";
        /* a stabilization that stops short of rest is said (not_at_rest)
         * and the run goes on from there, as the command does */
        if (bd_sim_stabilize(sim, &ro, serr, sizeof serr) != BD_RUN_OK) {
            snprintf(res->message, sizeof res->message, "stabilization: %s", serr);
            goto done;
        }
        res->not_at_rest = serr[0] != '\0';
    }
    bd_sim_book_energy_every_step(sim, 1);
    int drives[16], nd = 0;
    for (int i = 0; i < def.pulley_count && nd < 16; i++)
        if (def.pulleys[i].has_drive)
            drives[nd++] = i;
    double dt = bd_sim_time_step(sim), duration = def.simulation.duration;
    double window_start = duration - opt->window;
    double chunk = 0.01;
    bd_energy_state e0, e;
    /* the reference: one step in, when the scheme's energy is defined */
    if (bd_sim_step(sim, 1, err, sizeof err))
        goto failed;
    bd_sim_energy(sim, &e0);
    double ref = e0.kinetic_J + e0.potential_J + e0.dissipated_J - e0.input_J;
    /* the energy scale is the run's largest energy flow: input, dissipated,
     * kinetic, and the change of potential energy (not its level, whose
     * zero is arbitrary: m·g·y from the tail, a counterweight metres
     * below); the worst imbalance and the worst fall of the dissipated
     * energy are kept in joules and taken against it at the end */
    double k_max = 0.0, dp_max = 0.0, flow = 0.0, bal_worst = 0.0, drop_worst = 0.0;
    /* the dissipated energy may fall within a step (an explicit dashpot,
     * the implicit contacts on a motion at the step's own frequency,
     * docs/physics.md §9), not over 10 ms */
    double d_checked = e0.dissipated_J, t_checked = bd_sim_time(sim);
    /* the drive force and belt speed of every step from the window's start
     * on; a check every window: the means over the later half of what was
     * sampled (at least one window, Hann-weighted), so that a decaying transient leaves
     * the mean while a lasting, undamped swing is averaged over ever more
     * periods. Running is steady when three successive checks agree. */
    long cap = (long)ceil((opt->window + opt->max_extension) / dt) + 16, ns = 0;
    fs = malloc((size_t)cap * sizeof *fs);
    vs = malloc((size_t)cap * sizeof *vs);
    double f_prev[2] = {NAN, NAN}, v_prev[2] = {NAN, NAN}, v_probe = 0.0;
    double window_end = duration, end_limit = duration + opt->max_extension;
    if (!fs || !vs) {
        snprintf(err, sizeof err, "out of memory for the samples");
        goto failed;
    }
    for (;;) {
        double t = bd_sim_time(sim);
        if (t >= window_end - 0.5 * dt) {
            long from = ns / 2;
            long min_len = (long)(opt->window / dt);
            if (ns - from < min_len)
                from = ns > min_len ? ns - min_len : 0;
            /* Hann-weighted means: a swing that outlasts the run (a takeup
             * mode damped by ζ ≈ 0.002, ±2.8 kN at 1 Hz) leaves a plain mean
             * over N periods off by up to amplitude/(π·N), 25 N in 30 s; the
             * window's taper makes the part periods that is left over at its
             * ends negligible */
            if (ns - from < 1) {
                snprintf(err, sizeof err, "no steady window to average (window %.3g s, "
                         "duration %.3g s)", opt->window, duration);
                goto failed;
            }
            double f = 0.0, v = 0.0, wsum = 0.0, len = (double)(ns - from);
            for (long i = from; i < ns; i++) {
                double s = sin(3.14159265358979323846 * ((double)(i - from) + 0.5) / len);
                f += s * s * fs[i];
                v += s * s * vs[i];
                wsum += s * s;
            }
            f /= wsum;
            v /= wsum;
            res->force = f;
            res->speed = v;
            res->averaged_s = (double)(ns - from) * dt;
            double law_scale = 0.0;
            bd_running_law_force(&law, v, &law_scale);
            /* three checks in a row within the bounds (their spread, largest
             * less smallest): two could meet by chance on a slow swing */
            double ftol = opt->steady_force * fmax(law_scale, 1.0);
            double vtol = opt->steady_speed * fmax(fabs(v), 0.01);
            double f_lo = fmin(f, fmin(f_prev[0], f_prev[1]));
            double f_hi = fmax(f, fmax(f_prev[0], f_prev[1]));
            double v_lo = fmin(v, fmin(v_prev[0], v_prev[1]));
            double v_hi = fmax(v, fmax(v_prev[0], v_prev[1]));
            /* (NAN before the third check: fmin/fmax skip it, so test it) */
            int steady = !isnan(f_prev[1]) && f_hi - f_lo <= ftol && v_hi - v_lo <= vtol;
            if (steady || window_end + opt->window > end_limit + 0.5 * dt
                || ns + (long)(opt->window / dt) + 2 > cap) {
                res->steady = steady;
                break;
            }
            f_prev[1] = f_prev[0];
            f_prev[0] = f;
            v_prev[1] = v_prev[0];
            v_prev[0] = v;
            window_end += opt->window;
        }
        if (t >= window_start - 0.5 * dt) {
            /* every step: the drive torque carries the ripple of the mesh */
            if (bd_sim_step(sim, 1, err, sizeof err))
                goto failed;
            double F = 0.0;
            for (int k = 0; k < nd; k++) {
                bd_pulley_state ps;
                bd_sim_pulley(sim, drives[k], &ps);
                double b = def.pulleys[drives[k]].bearing_damping;
                F += (ps.drive_torque_Nm - b * ps.omega_rad_s) / ps.radius_m;
            }
            /* the belt's speed through a fixed point (the first probe) */
            bd_probe_state pr;
            if (bd_sim_probe(sim, 0, &pr) == 0)
                v_probe = pr.speed_mps;
            if (ns >= cap) {
                snprintf(err, sizeof err, "sample buffer full (%ld samples)", cap);
                goto failed;
            }
            fs[ns] = F;
            vs[ns] = v_probe;
            ns++;
        } else {
            long steps = (long)ceil(fmin(chunk, window_start - t) / dt);
            if (steps < 1)
                steps = 1;
            if (bd_sim_step(sim, steps, err, sizeof err))
                goto failed;
        }
        bd_sim_energy(sim, &e);
        k_max = fmax(k_max, e.kinetic_J);
        dp_max = fmax(dp_max, fabs(e.potential_J - e0.potential_J));
        flow = fmax(flow, fmax(fmax(e.input_J, fabs(e.dissipated_J)), fmax(k_max, dp_max)));
        bal_worst = fmax(bal_worst,
                         fabs(e.kinetic_J + e.potential_J + e.dissipated_J - e.input_J - ref));
        if (bd_sim_time(sim) - t_checked >= chunk - 0.5 * dt) {
            if (d_checked - e.dissipated_J > drop_worst) {
                drop_worst = d_checked - e.dissipated_J;
                res->drop_from_s = t_checked;
                res->drop_to_s = bd_sim_time(sim);
            }
            d_checked = e.dissipated_J;
            t_checked = bd_sim_time(sim);
        }
    }
    flow = fmax(flow, 1.0);
    res->balance = bal_worst / flow;
    res->dissipation_drop = drop_worst / flow;
    res->completed = 1;
    res->ran_s = bd_sim_time(sim);
    res->speed_target = opt->target_speed > 0.0 ? opt->target_speed
                                                : model_speed(&law, &def, res->speed);
    res->force_law = bd_running_law_force(&law, res->speed, &res->force_scale);
    goto done;
failed:
    snprintf(res->message, sizeof res->message, "%s", err);
done:
    free(fs);
    free(vs);
    res->wall_s = now() - wall0;
    bd_sim_free(sim);
    bd_model_def_free(&def);
}
