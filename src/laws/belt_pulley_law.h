/* The belt–pulley law of seed 004 (Simscape Belt Pulley block) as pure
 * functions: a belt wrapping angle θ of a pulley of radius R, its arriving
 * end under tension T_in and its leaving end under T_out, slipping at
 * V_rel = V_belt − ω·R over the pulley surface. Used by the axial belt
 * (src/axial/) for every conveyor pulley and by the belt transmission
 * (src/parts/transmission.c) for both sheaves. */
#ifndef BD_BELT_PULLEY_LAW_H
#define BD_BELT_PULLEY_LAW_H

typedef struct bd_bpl {
    double f;        /* steady friction coefficient (f' for a V-belt), - */
    double theta;    /* rad, wrap angle */
    double rho;      /* kg/m, belt linear density (centrifugal tension) */
    double v_thr;    /* m/s, friction velocity threshold (tanh = 0.999 there) */
    double f_thr;    /* N, force threshold of the tension factor */
} bd_bpl;

/* V-belt effective friction f' = f / sin(φ/2), φ the groove angle (seed 004) */
double bd_bpl_vbelt_friction(double f, double groove_angle);
/* instantaneous friction coefficient μ = −f·tanh(4·V_rel/V_thr) (seed 004) */
double bd_bpl_mu(const bd_bpl *law, double v_rel);
/* centrifugal belt tension F_C = ρ·V² (seed 004) */
double bd_bpl_centrifugal(const bd_bpl *law, double v_belt);
/* tension factor tanh(T/F_thr): the pulley transmits nothing through a
 * belt end that has lost its tension (seed 004 torque equation); 0 for T ≤ 0 */
double bd_bpl_tension_factor(const bd_bpl *law, double T);
/* friction force of the pulley on the belt, N, positive along the travel:
 * the capstan relation (T_tight − F_C) = (T_slack − F_C)·e^(|μ|·θ) with the
 * slack end the one the friction pulls away from (T_out when μ > 0, the
 * pulley dragging the belt forward; T_in when μ < 0), times the tension
 * factor of the slack end */
double bd_bpl_force(const bd_bpl *law, double T_in, double T_out, double v_belt, double v_rel);
/* the largest force the wrap can carry forward (μ = f) and backward
 * (μ = −f), both ≥ 0 */
void bd_bpl_capacity(const bd_bpl *law, double T_in, double T_out, double v_belt,
                     double *fwd, double *back);
/* the friction force F for an explicit step, taken implicitly: F acts at the
 * slip speed it produces at the end of the step,
 *     F = bd_bpl_force(…, v_rel_free + κ·F),
 * v_rel_free the slip the step would give without friction and
 * κ = Δt·(1/m_belt + R²/I) the slip speed one newton adds. The right side
 * falls as F grows, so the root is unique; found by safeguarded Newton. */
double bd_bpl_solve(const bd_bpl *law, double T_in, double T_out, double v_belt,
                    double v_rel_free, double kappa);

/* the share of a wrap's friction that passing the force between its two
 * ends takes, ln(T_hi/T_lo)/(μ·φ), the larger end over the smaller either
 * way round (Euler–Eytelwein, the capstan law above without centrifugal
 * tension; the belt begins to slip at 1); NaN when the smaller end has no
 * tension, or mu_phi ≤ 0 */
double bd_capstan_friction_used(double T_a, double T_b, double mu_phi);

#endif
