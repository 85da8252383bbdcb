/* Drives (model-format.md `drive`): the torque a drive puts on its pulley.
 * Torque and speed are positive in the sense that moves the belt forward.
 *
 * speed: a PI speed loop with acceleration feed-forward, like a VFD's,
 *   T = J·[α_ref + 2ζω_c·(ω_ref − ω) + ω_c²·∫(ω_ref − ω)dt],  ζ = 1,
 * tuned for J, the inertia of everything the drives move (belt, material,
 * pulleys, idlers reflected to this pulley, shared among the speed drives);
 * the integral stops winding up while the torque is at max_torque.
 * Its bandwidth ω_c is the drive's `bandwidth`, 2 Hz unless given: the
 * drive follows its start curve, as the spec's `speed` control says and
 * as seed 000 §4 starts its conveyor (the drum on the starting speed
 * curves, eqs 52–55; seed 001 eq 4.66 applies a torque instead).
 * A loop that stiff reflects the belt's waves at the drum: the belt's low
 * modes then ring with the damping the belt declares (docs/physics.md §10,
 * "Low modes ring"). A drive tuned to the belt's wave impedance,
 * K_p = R²·(Z_in + Z_out), Z = √(EA·m′) (the characteristic impedance of
 * the belt's longitudinal wave equation m′·ü = EA·u″, force per unit of
 * speed at the end of a long rod: K. F. Graff, Wave Motion in Elastic
 * Solids, ch. 2; seed 001 §6.4 checks the wave speed √(EA/m′) on the
 * discrete belt), would absorb them, but its
 * bandwidth on a long conveyor is about the inverse of the wave's round
 * trip (0.13 rad/s on the cement plant, which then reached 1.35 of 2.0 m/s
 * at the end of a 10 s ramp and understated the start's peak tension by
 * 19 %, docs/starting.md); a user who wants that drive gives the lower
 * `bandwidth`. (Issue 10 item 3 capped K_p at that impedance when the
 * belt ran over the drum as chords whose speed ripple the loop turned into
 * 11 kN swings; the wrap elements now follow the shell and the ripple is
 * gone: on a loaded 500 m 30 s s-curve start the raw peak drive force is
 * 4.5 % above its 0.2 s mean.)
 * The proportional term is implicit: the torque applied is
 *   T = T(ω) − K_p·Δt·α,
 * the speed at the end of the step in place of the speed at its start (the
 * wrap coupling solves the pulley with I + K_p·Δt, see bd_pulley_body
 * torque_damping). Explicit, a loop tuned for a whole conveyor acting on the
 * bare pulley when the belt slips had a gain Δt·K_p/I of ~50 (stable below
 * 2) and ran to NaN; implicit it is stable for any gain.
 * torque: the table, linear between points.
 * motor: an induction motor direct on line by the Kloss formula (the
 * classical approximation of the induction machine's torque–speed curve
 * from its breakdown point; not in the seeds — model-format.md `motor` and
 * issue 4 ask for it; seed 001 fig. 1.10 shows such curves)
 *   T_m = 2·T_b·s·s_b/(s² + s_b²),  s = 1 − ω_m/ω_sync,
 * T_b = breakdown_torque_ratio·T_rated, T_rated = P/ω_rated, and s_b from
 * the rated point: s_b = s_r·(k + √(k² − 1)), k = T_b/T_rated; at the pulley
 * T = gear_ratio·T_m with ω_m = gear_ratio·ω. Where the curve falls with
 * speed (the stable side, |s| < s_b) its slope −dT/dω is taken implicitly
 * like the speed loop's gain: near synchronous speed it is steep.
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

double bd_motor_rated_torque(const bd_motor_def *m)
{
    return m->rated_power / (m->rated_speed_rpm * 2.0 * BD_PI / 60.0);
}

/* dT_m/dω_m of the Kloss curve at the motor shaft, N·m·s: the derivative
 * of T_m(s) above, dT_m/ds = 2·T_b·s_b·(s_b² − s²)/(s² + s_b²)², times
 * ds/dω_m = −1/ω_sync (derived here) */
static double motor_slope(const bd_drive *p, double omega_pulley)
{
    const bd_motor_def *m = &p->def->motor;
    double w_sync = m->synchronous_speed_rpm * 2.0 * BD_PI / 60.0;
    double s = 1.0 - omega_pulley * m->gear_ratio / w_sync;
    double sb = p->motor_slip_b, q = s * s + sb * sb;
    /* dT/ds = 2·T_b·s_b·(s_b² − s²)/(s² + s_b²)², ds/dω_m = −1/ω_sync */
    return -2.0 * p->motor_breakdown * sb * (sb * sb - s * s) / (q * q) / w_sync;
}

void bd_drive_prepare(bd_sim *sim, bd_drive *dr, const bd_pulley_body *p,
                      double reflected_inertia)
{
    const bd_drive_def *d = dr->def;
    dr->ctrl_inertia = reflected_inertia;
    double R = p->m->radius;
    double w = 2.0 * BD_PI * d->bandwidth;
    /* the integral term stays explicit: a spring ω_c²·J on the pulley and
     * the belt wrapped on it, stable for Δt·ω_c·√(J/I_local) < 2 (the
     * central-difference limit ω·Δt < 2 for that spring on I_local,
     * docs/physics.md §3 and §6); keep a tenth of that */
    double I_local = p->m->inertia + sim->model->belt_mpl * BD_PI * R * R * R;
    double w_max = 0.2 * sqrt(I_local / reflected_inertia) / sim->model->dt;
    dr->ctrl_bandwidth = w < w_max ? w : w_max;
    if (d->control == BD_CONTROL_MOTOR) {
        const bd_motor_def *m = &d->motor;
        double T_rated = bd_motor_rated_torque(m);
        double k = m->breakdown_torque_ratio;
        double s_r = 1.0 - m->rated_speed_rpm / m->synchronous_speed_rpm;
        dr->motor_breakdown = k * T_rated;
        dr->motor_slip_b = s_r * (k + sqrt(k * k - 1.0));
    }
}

int bd_drive_stopped(const bd_drive *dr, double t)
{
    return dr->def->stop_mode != BD_STOP_NONE && t >= dr->def->stop_at;
}

void bd_drive_note_torque(bd_drive *dr, double t, double torque)
{
    if (!bd_drive_stopped(dr, t) && fabs(torque) > dr->driving_peak)
        dr->driving_peak = fabs(torque);
}

double bd_drive_torque(const bd_sim *sim, bd_drive *dr, const bd_pulley_body *p, double omega,
                       double *slope)
{
    const bd_drive_def *d = dr->def;
    double t = sim->t, T = 0.0;
    double K = 0.0;   /* −dT/dω where the torque is not clipped */
    if (slope)
        *slope = 0.0;
    int stopped = bd_drive_stopped(dr, t);
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
        if (T == T_unclipped) {
            dr->integral += err * sim->model->dt;
            if (slope)
                *slope = 2.0 * wc * J;
        }
        return T;
    }
    case BD_CONTROL_TORQUE:
        T = bd_table_eval(&d->torque, t);
        break;
    case BD_CONTROL_MOTOR:
        if (t >= d->motor.start_time) {
            double G = d->motor.gear_ratio;
            T = motor_torque(dr, omega) * G;
            K = -motor_slope(dr, omega) * G * G;
        }
        break;
    }
    double Tc = clip(T, d->max_torque);
    if (slope && Tc == T && K > 0.0)
        *slope = K;
    return Tc;
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

/* the fastest belt speed a drive asks for, m/s (0: no drive with a speed) */
double bd_drives_reference_speed(const bd_model_def *def)
{
    double v = 0.0;
    for (int i = 0; i < def->pulley_count; i++) {
        const bd_pulley_def *pd = &def->pulleys[i];
        if (!pd->has_drive)
            continue;
        const bd_drive_def *d = &pd->drive;
        double vi = 0.0;
        switch (d->control) {
        case BD_CONTROL_SPEED:
            vi = fmax(fabs(d->speed), fabs(d->creep_speed));
            break;
        case BD_CONTROL_MOTOR:
            vi = d->motor.synchronous_speed_rpm * 2.0 * BD_PI / 60.0 / d->motor.gear_ratio
               * pd->radius;
            break;
        case BD_CONTROL_TORQUE: break;
        }
        v = fmax(v, vi);
    }
    return v;
}
