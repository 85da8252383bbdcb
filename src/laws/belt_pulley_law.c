/* The belt–pulley law of seed 004 (Simscape Belt Pulley block), in the
 * sign convention of beltdyn: travel is positive, V_rel = V_belt − ω·R is
 * positive when the belt runs faster than the pulley surface, the force is
 * the pulley's on the belt, positive along the travel.
 *
 *   f' = f / sin(φ/2)                               V-belt (seed 004)
 *   μ  = −f·tanh(4·V_rel/V_thr)                     regularized friction
 *   F_C = ρ·V²                                      centrifugal tension
 *   T_tight − F_C = (T_slack − F_C)·e^(|μ|·θ)       Euler capstan relation
 *   F = ±(T_slack − F_C)·(e^(|μ|θ) − 1)·tanh(T_slack/F_thr)
 *
 * Seed 004 writes the two cases V_rel ≥ 0 and V_rel < 0 with its ports A
 * and B; here μ > 0 means the pulley surface outruns the belt and drags it
 * forward, so the belt leaving the pulley is the slack end, T_slack = T_out,
 * and the arriving end is the tight one; μ < 0 the other way round. Both
 * cases meet at F = 0 for V_rel = 0, so F is continuous in V_rel. The seed's
 * pulley torque (F_A + F_B)·R·tanh(4V_rel/V_thr)·tanh(F_B/F_thr) − ω·b is
 * the reaction −R·F of this force; the bearing term −ω·b is added by the
 * caller. */
#include "laws/belt_pulley_law.h"

#include <math.h>

double bd_bpl_vbelt_friction(double f, double groove_angle)
{
    return f / sin(0.5 * groove_angle);
}

double bd_bpl_mu(const bd_bpl *law, double v_rel)
{
    return -law->f * tanh(4.0 * v_rel / law->v_thr);
}

double bd_bpl_centrifugal(const bd_bpl *law, double v_belt)
{
    return law->rho * v_belt * v_belt;
}

double bd_bpl_tension_factor(const bd_bpl *law, double T)
{
    return T > 0.0 ? tanh(T / law->f_thr) : 0.0;
}

/* force and its slope dF/dV_rel (≤ 0) */
static double force_slope(const bd_bpl *law, double T_in, double T_out, double v_belt,
                          double v_rel, double *slope)
{
    double th = tanh(4.0 * v_rel / law->v_thr);
    double mu = -law->f * th;
    double slack = mu >= 0.0 ? T_out : T_in;
    double base = slack - bd_bpl_centrifugal(law, v_belt);
    if (base < 0.0)
        base = 0.0;
    base *= bd_bpl_tension_factor(law, slack);
    double e = exp(fabs(mu) * law->theta);
    if (slope)
        *slope = base * law->theta * e * (-law->f * 4.0 / law->v_thr * (1.0 - th * th));
    return (mu >= 0.0 ? 1.0 : -1.0) * base * (e - 1.0);
}

double bd_bpl_force(const bd_bpl *law, double T_in, double T_out, double v_belt, double v_rel)
{
    return force_slope(law, T_in, T_out, v_belt, v_rel, 0);
}

void bd_bpl_capacity(const bd_bpl *law, double T_in, double T_out, double v_belt,
                     double *fwd, double *back)
{
    double Fc = bd_bpl_centrifugal(law, v_belt);
    double g = exp(law->f * law->theta) - 1.0;
    double bo = T_out - Fc, bi = T_in - Fc;
    *fwd = (bo > 0.0 ? bo : 0.0) * g * bd_bpl_tension_factor(law, T_out);
    *back = (bi > 0.0 ? bi : 0.0) * g * bd_bpl_tension_factor(law, T_in);
}

double bd_bpl_solve(const bd_bpl *law, double T_in, double T_out, double v_belt,
                    double v_rel_free, double kappa)
{
    double hi, lo;
    bd_bpl_capacity(law, T_in, T_out, v_belt, &hi, &lo);
    lo = -lo;
    if (hi - lo <= 0.0)
        return 0.0;
    /* h(F) = F − force(v_rel_free + κF) rises with F (h' ≥ 1); h(lo) ≤ 0 ≤ h(hi) */
    double tol = 1e-10 * (hi - lo);
    double F = bd_bpl_force(law, T_in, T_out, v_belt, v_rel_free);
    for (int it = 0; it < 100; it++) {
        double slope;
        double h = F - force_slope(law, T_in, T_out, v_belt, v_rel_free + kappa * F, &slope);
        if (h > 0.0)
            hi = F;
        else
            lo = F;
        if (fabs(h) <= tol || hi - lo <= tol)
            break;
        double next = F - h / (1.0 - kappa * slope);
        /* Newton inside the bracket, else bisect */
        F = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
    }
    return F;
}

double bd_capstan_friction_used(double T_a, double T_b, double mu_phi)
{
    double hi = fmax(T_a, T_b), lo = fmin(T_a, T_b);
    return lo > 0.0 && mu_phi > 0.0 ? log(hi / lo) / mu_phi : NAN;
}
