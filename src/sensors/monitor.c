/* Drive monitors: the quantities a start study compares (issue 4), kept
 * for every drive pulley while the run steps, O(1) per step and without
 * allocation.
 *
 * - tight side: belt tension at a fixed point of the span arriving at the
 *   drive pulley, MONITOR_OFFSET before the wrap begins (its largest value
 *   and when); slack side: the same just after the wrap (its lowest).
 * - swing: the range (max − min) of the tight-side tension once the start
 *   curve has reached full speed (t ≥ delay + T): the waves the start left
 *   in the belt. Seed 000 (§4, Fig. 12) judges start curves by it: a curve
 *   that ends its acceleration abruptly (linear) leaves the largest.
 * - belt acceleration: the belt speed at the tight-side point averaged over
 *   windows of ACCEL_WINDOW; the acceleration is the change between two
 *   consecutive window means divided by the window. Averaging keeps the
 *   step-scale ripple of the contacts (the idlers' node passage) out of it,
 *   which a per-step difference would blow up by 1/Δt.
 * - slip: the pulley's surface speed ω·R against the belt speed at the
 *   pulley (the mean of the tight- and slack-side speeds; elastic creep
 *   makes them differ by ΔT/EA of the speed, a fraction of a percent). The
 *   drive slips when they differ by more than SLIP_SPEED + SLIP_FRACTION·|ωR|
 *   for at least BD_SLIP_TIME without a break.
 * - friction used: ln(T_hi/T_lo)/(μ_s·φ) of the tight- and slack-side
 *   tensions, the larger over the smaller (a braking drive pulls the other
 *   way): the share of the wrap's friction the drive needs to pass its
 *   force (Euler–Eytelwein, seed 001 §2, seed 004's capstan law; the belt
 *   begins to slip at 1, and slides on at μ_d/μ_s). Its largest over the
 *   run is the dynamic slip margin (io/checks.c); samples with a slack
 *   side at or below zero tension are left out, as in the report's plot
 *   (the belt in compression has its own warning). */
#include "sensors/sensors.h"

#include <math.h>

#include "laws/belt_pulley_law.h"

#define MONITOR_OFFSET 0.5   /* m before / after the wrap, at most 1/4 span */
#define ACCEL_WINDOW 0.1     /* s */
#define SLIP_SPEED 0.05      /* m/s */
#define SLIP_FRACTION 0.02   /* of the surface speed */

static double offset_on(const bd_path_segment *span)
{
    double d = 0.25 * span->length;
    return d < MONITOR_OFFSET ? d : MONITOR_OFFSET;
}

void bd_wrap_side_points(const bd_sim *sim, int i, double *s_in, double *s_out)
{
    int before = (i + sim->model->pulley_count - 1) % sim->model->pulley_count;
    const bd_path_segment *arc = bd_path_arc(&sim->model->path, i);
    *s_in = arc->s0 - offset_on(bd_path_span(&sim->model->path, before));
    *s_out = arc->s0 + arc->length + offset_on(bd_path_span(&sim->model->path, i));
}

void bd_monitor_init(bd_sim *sim, bd_pulley_body *p)
{
    double s_in, s_out;
    bd_wrap_side_points(sim, (int)(p - sim->pulleys), &s_in, &s_out);
    sim->model->belt->point_init(sim, &p->mon.tight, s_in);
    sim->model->belt->point_init(sim, &p->mon.slack, s_out);
    p->mon.friction_cap = p->m->mu_s * bd_path_wrap_angle(&sim->model->path, (int)(p - sim->pulleys));
    bd_monitor_reset(sim, p);
}

void bd_monitor_reset(bd_sim *sim, bd_pulley_body *p)
{
    bd_drive_monitor *m = &p->mon;
    m->tight_max = -INFINITY;
    m->slack_min = INFINITY;
    m->swing_max = -INFINITY;
    m->swing_min = INFINITY;
    const bd_drive_def *d = &p->m->def->drive;
    m->ramp_end = d->control == BD_CONTROL_SPEED ? d->start_delay + d->start_time : 0.0;
    m->tight_max_t = m->slack_min_t = 0.0;
    m->win_sum = 0.0;
    m->win_count = 0;
    m->win_end = sim->t + ACCEL_WINDOW;
    m->win_have_prev = 0;
    m->accel_max = m->accel_max_t = 0.0;
    m->slip_dv_max = 0.0;
    m->slip_since = -1.0;
    m->slip_longest = 0.0;
    m->slip_first_t = -1.0;
    m->friction_used_max = m->friction_used_max_t = 0.0;
}

static void window_acceleration(bd_drive_monitor *m, double v, double t)
{
    m->win_sum += v;
    m->win_count++;
    if (t < m->win_end)
        return;
    double mean = m->win_sum / (double)m->win_count;
    if (m->win_have_prev) {
        double a = (mean - m->win_prev) / ACCEL_WINDOW;
        if (fabs(a) > fabs(m->accel_max)) {
            m->accel_max = a;
            /* the difference belongs between the two window centres */
            m->accel_max_t = m->win_end - ACCEL_WINDOW;
        }
    }
    m->win_prev = mean;
    m->win_have_prev = 1;
    m->win_sum = 0.0;
    m->win_count = 0;
    m->win_end += ACCEL_WINDOW;
}

static void slip(bd_drive_monitor *m, double v_surface, double v_belt, double t)
{
    double dv = fabs(v_surface - v_belt);
    if (dv > m->slip_dv_max)
        m->slip_dv_max = dv;
    if (dv <= SLIP_SPEED + SLIP_FRACTION * fabs(v_surface)) {
        m->slip_since = -1.0;
        return;
    }
    if (m->slip_since < 0.0)
        m->slip_since = t;
    double lasted = t - m->slip_since;
    if (lasted > m->slip_longest)
        m->slip_longest = lasted;
    if (lasted >= BD_SLIP_TIME && m->slip_first_t < 0.0)
        m->slip_first_t = m->slip_since;
}

void bd_monitor_sides(bd_sim *sim, bd_drive_monitor *m, bd_belt_sample *in,
                      bd_belt_sample *out)
{
    const bd_belt_ops *belt = sim->model->belt;
    belt->point_update(sim, &m->tight);
    belt->point_update(sim, &m->slack);
    belt->sample(sim, &m->tight, in);
    belt->sample(sim, &m->slack, out);
}

/* after a step: sim->t is the time the positions belong to */
void bd_monitor_update(bd_sim *sim, bd_pulley_body *p)
{
    bd_drive_monitor *m = &p->mon;
    double t = sim->t;
    bd_belt_sample in, out;
    bd_monitor_sides(sim, m, &in, &out);
    double T_in = in.tension;
    double T_out = out.tension;
    if (T_in > m->tight_max) {
        m->tight_max = T_in;
        m->tight_max_t = t;
    }
    if (T_out < m->slack_min) {
        m->slack_min = T_out;
        m->slack_min_t = t;
    }
    if (t >= m->ramp_end) {
        if (T_in > m->swing_max)
            m->swing_max = T_in;
        if (T_in < m->swing_min)
            m->swing_min = T_in;
    }
    double v_in = in.speed;
    double v_out = out.speed;
    window_acceleration(m, v_in, t);
    slip(m, p->omega * p->m->radius, 0.5 * (v_in + v_out), t);
    double used = bd_capstan_friction_used(T_in, T_out, m->friction_cap);
    if (used > m->friction_used_max) {   /* false for NaN: no tension on a side */
        m->friction_used_max = used;
        m->friction_used_max_t = t;
    }
}

/* tight-side tension range after the ramp; 0 while the ramp runs */
double bd_monitor_swing(const bd_drive_monitor *m)
{
    return m->swing_max >= m->swing_min ? m->swing_max - m->swing_min : 0.0;
}

void bd_sim_result(const bd_sim *sim, bd_run_result *r)
{
    r->drives = 0;
    r->tight_max_N = r->tight_max_t_s = 0.0;
    r->slack_min_N = r->slack_min_t_s = 0.0;
    r->accel_max_mps2 = r->accel_max_t_s = 0.0;
    r->torque_max_Nm = 0.0;
    r->slipped = 0;
    r->slip_t_s = -1.0;
    r->slip_longest_s = r->slip_speed_max_mps = 0.0;
    r->friction_used_max = 0.0;
    r->travel_range_m = 0.0;
    r->tight_swing_N = 0.0;
    r->tension_max_N = sim->tension_max;
    r->tension_min_N = sim->tension_min;
    r->tension_max_t_s = sim->tension_max_t;
    r->tension_max_s_m = sim->tension_max_s;
    r->static_warnings = sim->static_warnings;
    for (int i = 0; i < sim->model->pulley_count; i++) {
        const bd_pulley_body *p = &sim->pulleys[i];
        if (p->m->movable && p->travel_max - p->travel_min > r->travel_range_m)
            r->travel_range_m = p->travel_max - p->travel_min;
        if (!p->m->def->has_drive)
            continue;
        const bd_drive_monitor *m = &p->mon;
        int first = r->drives++ == 0;
        if (first || m->tight_max > r->tight_max_N) {
            r->tight_max_N = m->tight_max;
            r->tight_max_t_s = m->tight_max_t;
        }
        if (first || m->slack_min < r->slack_min_N) {
            r->slack_min_N = m->slack_min;
            r->slack_min_t_s = m->slack_min_t;
        }
        double swing = bd_monitor_swing(m);
        if (swing > r->tight_swing_N)
            r->tight_swing_N = swing;
        if (fabs(m->accel_max) > fabs(r->accel_max_mps2)) {
            r->accel_max_mps2 = m->accel_max;
            r->accel_max_t_s = m->accel_max_t;
        }
        if (p->torque_max_abs > r->torque_max_Nm)
            r->torque_max_Nm = p->torque_max_abs;
        if (m->slip_first_t >= 0.0) {
            if (!r->slipped || m->slip_first_t < r->slip_t_s)
                r->slip_t_s = m->slip_first_t;
            r->slipped = 1;
        }
        if (m->slip_longest > r->slip_longest_s)
            r->slip_longest_s = m->slip_longest;
        if (m->slip_dv_max > r->slip_speed_max_mps)
            r->slip_speed_max_mps = m->slip_dv_max;
        if (m->friction_used_max > r->friction_used_max)
            r->friction_used_max = m->friction_used_max;
    }
}
