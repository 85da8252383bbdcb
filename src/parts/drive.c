/* Drives (model-format.md `drive`): the torque a drive puts on its pulley.
 * Torque and speed are positive in the sense that moves the belt forward.
 *
 * speed: a PI speed loop with acceleration feed-forward, like a VFD's,
 *   T = J·[α_ref + 2ζω_c·(ω_ref − ω) + ω_c²·∫(ω_ref − ω)dt],  ζ = 1,
 * tuned for J, the inertia of everything the drives move (belt, material,
 * pulleys, idlers reflected to this pulley, shared among the speed drives);
 * the integral stops winding up while the torque is at max_torque.
 * torque: the table, linear between points.
 * motor: an induction motor direct on line by the Kloss formula (the
 * classical approximation of the induction machine's torque–speed curve
 * from its breakdown point; not in the seeds — model-format.md `motor` and
 * issue 4 ask for it; seed 001 fig. 1.10 shows such curves)
 *   T_m = 2·T_b·s·s_b/(s² + s_b²),  s = 1 − ω_m/ω_sync,
 * T_b = breakdown_torque_ratio·T_rated, T_rated = P/ω_rated, and s_b from
 * the rated point: s_b = s_r·(k + √(k² − 1)), k = T_b/T_rated; at the pulley
 * T = gear_ratio·T_m with ω_m = gear_ratio·ω.
 * Stops at stop.at: coast (no torque), ramp (the speed reference falls
 * linearly to zero over stop.time), brake (brake_torque against the motion,
 * holding at standstill). Every torque is clipped to ±max_torque. */
#include "parts/parts.h"
#include "base/constants.h"
#include "laws/start_curve.h"

#include <math.h>

static double clip(double v, double limit)
{
    return v > limit ? limit : (v < -limit ? -limit : v);
}

/* Kloss curve at the motor shaft, N·m */
static double motor_torque(const bd_drive *p, double omega_pulley)
{
    const bd_motor_def *m = &p->def->motor;
    double w_sync = m->synchronous_speed_rpm * 2.0 * BD_PI / 60.0;
    double s = 1.0 - omega_pulley * m->gear_ratio / w_sync;
    double sb = p->motor_slip_b;
    return 2.0 * p->motor_breakdown * s * sb / (s * s + sb * sb);
}

void bd_drive_prepare(bd_sim *sim, bd_drive *dr, const bd_pulley_body *p,
                      double reflected_inertia)
{
    const bd_drive_def *d = dr->def;
    dr->ctrl_inertia = reflected_inertia;
    /* 2 Hz speed loop, slowed if the explicit step could not carry it: the
     * proportional gain acts like a damper 2ω_c·J on the pulley and the belt
     * sticking to it, stable for Δt·2ω_c·J/I_local < 2; keep it below 0.5 */
    double I_local = p->m->inertia + sim->model->belt_mpl * BD_PI * p->m->radius * p->m->radius * p->m->radius;
    double w = 2.0 * BD_PI * 2.0;
    double w_max = 0.25 * I_local / (sim->model->dt * reflected_inertia);
    dr->ctrl_bandwidth = w < w_max ? w : w_max;
    if (d->control == BD_CONTROL_MOTOR) {
        const bd_motor_def *m = &d->motor;
        double w_rated = m->rated_speed_rpm * 2.0 * BD_PI / 60.0;
        double T_rated = m->rated_power / w_rated;
        double k = m->breakdown_torque_ratio;
        double s_r = 1.0 - m->rated_speed_rpm / m->synchronous_speed_rpm;
        dr->motor_breakdown = k * T_rated;
        dr->motor_slip_b = s_r * (k + sqrt(k * k - 1.0));
    }
}

double bd_drive_torque(const bd_sim *sim, bd_drive *dr, const bd_pulley_body *p, double omega)
{
    const bd_drive_def *d = dr->def;
    double t = sim->t, T = 0.0;
    int stopped = d->stop_mode != BD_STOP_NONE && t >= d->stop_at;
    if (stopped && d->stop_mode == BD_STOP_COAST)
        return 0.0;
    if (stopped && d->stop_mode == BD_STOP_BRAKE) {
        /* brake: the torque that would stop the pulley this step, at most
         * brake_torque; it holds the pulley once stopped */
        return -clip(omega * p->m->inertia / sim->model->dt, d->brake_torque);
    }
    switch (d->control) {
    case BD_CONTROL_SPEED: {
        double R = p->m->radius;
        double w_ref = bd_start_curve_speed(d, t) / R;
        double w_ref_next = bd_start_curve_speed(d, t + sim->model->dt) / R;
        double a_ref = (w_ref_next - w_ref) / sim->model->dt;
        double err = w_ref - omega;
        double wc = dr->ctrl_bandwidth;
        double J = dr->ctrl_inertia;
        double T_unclipped = J * (a_ref + 2.0 * wc * err + wc * wc * dr->integral);
        T = clip(T_unclipped, d->max_torque);
        /* integrate only while not saturated (anti-windup) */
        if (T == T_unclipped)
            dr->integral += err * sim->model->dt;
        return T;
    }
    case BD_CONTROL_TORQUE:
        T = bd_table_eval(&d->torque, t);
        break;
    case BD_CONTROL_MOTOR:
        T = t >= d->motor.start_time ? motor_torque(dr, omega) * d->motor.gear_ratio : 0.0;
        break;
    }
    return clip(T, d->max_torque);
}

/* Stabilization held the pulley still (a holdback); the speed loop takes
 * the holding torque over without a jolt, as a drive proves its torque
 * before its brake lets go: the integral that gives that torque at zero
 * speed error (ω_ref(0) = 0). Torque and motor drives give at t = 0 what
 * their table or motor gives. */
void bd_drive_take_over(bd_drive *dr, double torque)
{
    double k = dr->ctrl_inertia * dr->ctrl_bandwidth * dr->ctrl_bandwidth;
    if (dr->def->control == BD_CONTROL_SPEED && k > 0.0)
        dr->integral = clip(torque, dr->def->max_torque) / k;
}
