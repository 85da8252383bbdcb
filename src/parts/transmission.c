/* Belt transmissions (model-format.md `drive.transmission`; seed 004): the
 * drive's motor turns a motor sheave (radius r_m) that drives the pulley's
 * sheave (radius r_p) through a flat or V belt. Nominal ratio i = r_p/r_m:
 * without slip the motor sheave turns i times as fast as the pulley.
 *
 * The belt is two spans, spring–dampers (stiffness k, dashpot c) installed
 * at the pretension T0, between the belt on the two wraps. The belt on each
 * wrap is one lumped mass m_w that slides on its sheave under the seed-004
 * law (contact/belt_pulley_law.c), with f' = f/sin(φ/2) for a V belt,
 * F_C = ρV², and the open-belt wrap angles θ = π ∓ 2·asin((r_p − r_m)/C)
 * on the smaller and larger sheave (C the centre distance).
 * Travel: motor wrap → span s → pulley wrap → span t → motor wrap, so a
 * motoring drive pulls span t tight and pushes span s slack:
 *   T_t = T0 + k·(x_m − x_p) + c·(v_m − v_p),   T_s = T0 − k·(x_m − x_p) − c·(v_m − v_p)
 *   m_w·v̇_m = T_s − T_t + F_m        (law: T_in = T_t, T_out = T_s, V_rel = v_m − ω_m·r_m)
 *   m_w·v̇_p = T_t − T_s + F_p        (law: T_in = T_s, T_out = T_t, V_rel = v_p − ω·r_p)
 *   J_m·ω̇_m = Q_m − b·ω_m − r_m·F_m,  and the pulley gets −r_p·F_p.
 * Q_m is the drive's torque (drive.c) evaluated at the pulley-equivalent
 * speed ω_m/i and divided by i, so every drive setting (speed loop, motor
 * curve with its gear_ratio, torque table, max_torque, stops) keeps its
 * meaning at the pulley shaft; the drive's `inertia` (given at the pulley
 * shaft) sits on the motor sheave as J_m = inertia/i².
 *
 * The wrap masses are tiny and the spans stiff: the belt's two velocities
 * and the span force are taken implicitly (backward Euler) together with
 * both sheaves' friction, which leaves the belt no fast chatter between
 * its wraps. The unknown is the span force difference D = T_t − T_s at the
 * end of the sub-step: given D, each wrap's friction is the implicit 1D
 * solve of bd_bpl_solve, and
 *   g(D) = D − 2k·(x_m − x_p + h·(v_m' − v_p')) − 2c·(v_m' − v_p')
 * rises with D (slope ≥ 1), so its root is bracketed and found by regula
 * falsi, the friction capacities following D too (T_t + T_s = 2·T0). Sub-steps resolve the motor sheave's torsional mode on the two
 * spans (ω_t = r_m·√(2k/J_m), 10 per radian).
 * Coupling to the conveyor: the conveyor's step turned the pulley with the
 * sheave torque of the previous step; the transmission then follows the
 * pulley's speed over the step and corrects it, sub-step by sub-step, for
 * the difference between the sheave's actual torque and the one applied
 * (the pulley sheave's friction is implicit in the pulley's inertia too,
 * so a gripping belt does not ring against the lagged torque). */
#include "parts/parts.h"
#include "base/alloc.h"
#include "base/constants.h"
#include "laws/belt_pulley_law.h"

#include <math.h>
#include <stdlib.h>


/* span damping: a ratio of the motor sheave's torsional mode on its two
 * spans, and the belt mass on a wrap floored at a fraction of the motor
 * sheave's (a massless belt would need an infinitely small sub-step) */
#define SPAN_DAMPING_RATIO 0.05
#define WRAP_MASS_FLOOR 1e-3
#define MAX_SUBSTEPS 100000

typedef struct bd_transmission {
    const bd_transmission_def *def;
    double i;             /* r_p / r_m */
    double r_m, r_p;      /* m */
    double J_m;           /* kg·m², motor sheave with motor and gearbox */
    double k, c, T0;      /* N/m, N·s/m, N per span */
    double m_w;           /* kg of belt on each wrap */
    bd_bpl law_m, law_p;  /* seed-004 law on the motor and pulley sheave */
    int sub;              /* sub-steps per conveyor step */
    /* state */
    double w_m;           /* rad/s motor sheave */
    double x_m, x_p;      /* m belt travel on the two wraps */
    double v_m, v_p;      /* m/s */
    double Q_m;           /* N·m drive torque on the motor sheave this step */
    double torque_p;      /* N·m mean torque of the sheave on the pulley, last step */
    double ke;            /* J, kinetic energy at the end of the last step */
    double slip_max;      /* m/s, largest |slip| on either sheave so far */
} bd_transmission;

/* the belt's end-of-sub-step velocities on both wraps and the frictions,
 * for a span force difference D; returns g(D) */
typedef struct span_solve {
    const bd_transmission *tr;
    double h, Q, w_p, dx, I_p;
    double v_m, v_p, F_m, F_p;    /* results */
} span_solve;

static double span_residual(span_solve *ss, double D, int friction)
{
    const bd_transmission *tr = ss->tr;
    double h = ss->h, m = tr->m_w, J = tr->J_m;
    ss->F_m = ss->F_p = 0.0;
    /* the spans are equal and linear: T_t + T_s = 2·T0 */
    double Tt = tr->T0 + 0.5 * D, Ts = tr->T0 - 0.5 * D;
    if (friction) {
        double vfree_m = tr->v_m - h * D / m - tr->r_m * (tr->w_m + h * ss->Q / J);
        ss->F_m = bd_bpl_solve(&tr->law_m, Tt, Ts, tr->v_m, vfree_m,
                               h * (1.0 / m + tr->r_m * tr->r_m / J));
        double vfree_p = tr->v_p + h * D / m - tr->r_p * ss->w_p;
        ss->F_p = bd_bpl_solve(&tr->law_p, Ts, Tt, tr->v_p, vfree_p,
                               h * (1.0 / m + tr->r_p * tr->r_p / ss->I_p));
    }
    ss->v_m = tr->v_m + h * (-D + ss->F_m) / m;
    ss->v_p = tr->v_p + h * (D + ss->F_p) / m;
    double dv = ss->v_m - ss->v_p;
    return D - 2.0 * tr->k * (ss->dx + h * dv) - 2.0 * tr->c * dv;
}

static void span_solve_run(span_solve *ss, int friction)
{
    const bd_transmission *tr = ss->tr;
    double D0 = 2.0 * tr->k * ss->dx + 2.0 * tr->c * (tr->v_m - tr->v_p);
    double g0 = span_residual(ss, D0, friction);
    if (g0 == 0.0)
        return;
    /* bracket: g rises with slope ≥ 1, so |g0| away is far enough */
    double step = fabs(g0) + 1.0;
    double a = D0, ga = g0, b = g0 > 0.0 ? D0 - step : D0 + step;
    double gb = span_residual(ss, b, friction);
    for (int it = 0; it < 60 && ga * gb > 0.0; it++) {
        step *= 2.0;
        b = g0 > 0.0 ? D0 - step : D0 + step;
        gb = span_residual(ss, b, friction);
    }
    double tol = 1e-10 * (fabs(D0) + tr->T0);
    double D = b;
    int side = 0;
    for (int it = 0; it < 100; it++) {
        D = (a * gb - b * ga) / (gb - ga);
        double g = span_residual(ss, D, friction);
        if (fabs(g) <= tol || fabs(b - a) <= tol)
            break;
        /* Illinois: halve the stale end's weight */
        if (g * gb > 0.0) {
            b = D;
            gb = g;
            if (side == -1)
                ga *= 0.5;
            side = -1;
        } else {
            a = D;
            ga = g;
            if (side == 1)
                gb *= 0.5;
            side = 1;
        }
    }
    span_residual(ss, D, friction);
}

/* the transmission of the drive on pulley p; it takes the drive's inertia
 * from the pulley to the motor side */
bd_transmission *bd_transmission_create(const bd_sim *sim, bd_pulley_model *pm)
{
    const bd_pulley_def *pd = pm->def;
    const bd_transmission_def *td = &pd->drive.transmission;
    bd_transmission *tr = bd_xcalloc(1, sizeof *tr);
    tr->def = td;
    tr->r_m = td->motor_sheave_radius;
    tr->r_p = td->pulley_sheave_radius;
    tr->i = tr->r_p / tr->r_m;
    /* the drive's inertia belongs to the motor side */
    tr->J_m = pd->drive.inertia / (tr->i * tr->i);
    if (tr->J_m < 1e-6)
        tr->J_m = 1e-6;
    if (pm->inertia - pd->drive.inertia > 0.0)
        pm->inertia -= pd->drive.inertia;
    tr->k = td->span_stiffness;
    tr->T0 = td->pretension;
    double f = td->v_belt ? bd_bpl_vbelt_friction(td->friction, td->sheave_angle)
                          : td->friction;
    bd_bpl law = {f, BD_PI, td->belt_mass_per_length, td->velocity_threshold,
                  td->force_threshold};
    /* open belt: the smaller sheave has the smaller wrap */
    double C = td->center_distance > 0.0 ? td->center_distance : 3.0 * (tr->r_m + tr->r_p);
    double d = (tr->r_p - tr->r_m) / C;
    d = d > 0.99 ? 0.99 : (d < -0.99 ? -0.99 : d);
    tr->law_m = tr->law_p = law;
    tr->law_m.theta = BD_PI - 2.0 * asin(d);
    tr->law_p.theta = BD_PI + 2.0 * asin(d);
    tr->m_w = td->belt_mass_per_length * tr->law_m.theta * tr->r_m;
    double floor_m = WRAP_MASS_FLOOR * tr->J_m / (tr->r_m * tr->r_m);
    if (tr->m_w < floor_m)
        tr->m_w = floor_m;
    /* ζ of the motor sheave turning against the two spans */
    double w_t = tr->r_m * sqrt(2.0 * tr->k / tr->J_m);
    tr->c = SPAN_DAMPING_RATIO * 2.0 * tr->J_m * w_t / (2.0 * tr->r_m * tr->r_m);
    double sub = ceil(sim->model->dt * w_t / 0.1);
    tr->sub = sub < 1.0 ? 1 : (sub > MAX_SUBSTEPS ? MAX_SUBSTEPS : (int)sub);
    return tr;
}

/* a speed loop acts on the motor sheave once per conveyor step: its
 * proportional gain is a damper 2·ω_c·J/i² on J_m, explicit, kept below a
 * quarter of its stability limit as drive.c does for a pulley; and the
 * inertia it is tuned for gains the motor side's J_m·i² */
void bd_transmission_tune(const bd_sim *sim, bd_part *part)
{
    bd_transmission *tr = part->u.transmission.belt;
    bd_drive *d = &part->u.transmission.drive;
    d->ctrl_inertia += tr->J_m * tr->i * tr->i;
    double w_max = 0.25 * tr->J_m * tr->i * tr->i / (sim->model->dt * d->ctrl_inertia);
    if (d->ctrl_bandwidth > w_max)
        d->ctrl_bandwidth = w_max;
}

/* the drive's torque on the motor sheave (at the pulley-equivalent speed)
 * for this step; returns the sheave's torque on the pulley */
double bd_transmission_torque(bd_sim *sim, bd_part *part)
{
    bd_transmission *tr = part->u.transmission.belt;
    tr->Q_m = 0.0;
    if (!sim->stabilizing) {
        bd_drive *d = &part->u.transmission.drive;
        double Q = bd_drive_torque(sim, d, &sim->pulleys[part->pulley], tr->w_m / tr->i, NULL);
        tr->Q_m = Q / tr->i;
        /* max_torque is meant at the pulley: the torque there is Q */
        bd_drive_note_torque(d, sim->t, Q);
    }
    return tr->torque_p;
}

void bd_transmission_advance(bd_sim *sim, bd_part *part, double omega_old, double *ke,
                             double *w_nc)
{
    bd_transmission *tr = part->u.transmission.belt;
    bd_pulley_body *p = &sim->pulleys[part->pulley];
    const int sub = tr->sub;
    const double h = sim->model->dt / sub, m = tr->m_w, J = tr->J_m;
    const double b = tr->def->bearing_damping;
    double torque_sum = 0.0, input = 0.0, wnc = 0.0, dw = 0.0;
    for (int k = 0; k < sub; k++) {
        /* the pulley's speed in this sub-step, with the correction so far */
        double w_p = omega_old + (p->omega - omega_old) * (k + 0.5) / sub + dw;
        double dx = tr->x_m - tr->x_p;
        double Qb = -b * tr->w_m;
        span_solve ss = {tr, h, tr->Q_m + Qb, w_p, dx, p->m->inertia, 0.0, 0.0, 0.0, 0.0};
        /* while stabilizing, its pulley is held: the transmission runs free */
        span_solve_run(&ss, !sim->stabilizing);
        double w_new = tr->w_m + h * (ss.Q - tr->r_m * ss.F_m) / J;
        double vm = 0.5 * (tr->v_m + ss.v_m), vp = 0.5 * (tr->v_p + ss.v_p);
        double wm = 0.5 * (tr->w_m + w_new);
        double dv_new = ss.v_m - ss.v_p;
        /* work: drive in; frictions, bearing and span dashpots out */
        input += tr->Q_m * wm * h;
        wnc += (ss.F_m * (vm - tr->r_m * wm) + ss.F_p * vp + Qb * wm
                - 2.0 * tr->c * dv_new * (vm - vp)) * h;
        torque_sum += -tr->r_p * ss.F_p;
        /* the pulley: the actual sheave torque instead of the applied one */
        double ddw = h * (-tr->r_p * ss.F_p - p->drive_torque) / p->m->inertia;
        wnc += (-tr->r_p * ss.F_p - p->drive_torque) * (w_p + 0.5 * ddw) * h;
        dw += ddw;
        tr->v_m = ss.v_m;
        tr->v_p = ss.v_p;
        tr->w_m = w_new;
        tr->x_m += h * tr->v_m;
        tr->x_p += h * tr->v_p;
        double s_m = fabs(tr->v_m - tr->r_m * tr->w_m), s_p = fabs(tr->v_p - tr->r_p * w_p);
        if (s_m > tr->slip_max)
            tr->slip_max = s_m;
        if (s_p > tr->slip_max)
            tr->slip_max = s_p;
        if (k == sub - 1)
            tr->ke = 0.5 * (m * (vm * vm + vp * vp) + J * wm * wm);
    }
    tr->torque_p = torque_sum / sub;
    /* the pulley's kinetic energy changes with the correction */
    *ke += 0.5 * p->m->inertia * (dw * dw + 2.0 * dw * 0.5 * (omega_old + p->omega));
    p->omega += dw;
    sim->energy.input += input;
    /* the pulley takes the sheave's torque as an outside, non-conservative
     * one (it was booked as drive input without a transmission) */
    double w_mid = 0.5 * (omega_old + p->omega);
    *w_nc += wnc + p->drive_torque * w_mid * sim->model->dt;
    *ke += tr->ke;
}

/* elastic energy of the spans beyond the pretension: k·(x_m − x_p)² */
double bd_transmission_potential(const bd_transmission *tr)
{
    return tr->k * (tr->x_m - tr->x_p) * (tr->x_m - tr->x_p);
}

/* motor sheave speed, rad/s, and the slip of the belt on it, m/s */
void bd_transmission_state(const bd_part *part, const bd_pulley_body *p, double *w_motor,
                           double *slip_motor, double *slip_pulley)
{
    const bd_transmission *tr = part->u.transmission.belt;
    *w_motor = tr->w_m;
    *slip_motor = tr->v_m - tr->r_m * tr->w_m;
    *slip_pulley = tr->v_p - tr->r_p * p->omega;
}

double bd_transmission_slip_max(const bd_part *part)
{
    return part->u.transmission.belt->slip_max;
}

/* a copy of the transmission's state, for a new run on the same model */
bd_transmission *bd_transmission_clone(const bd_transmission *tr)
{
    bd_transmission *c = bd_xcalloc(1, sizeof *c);
    *c = *tr;
    return c;
}
