/* Every formula of seed 004 (contact/belt_pulley_law.c) against its closed
 * form. These are algebra, so the tolerances are rounding (1e-12) except
 * where a regularized quantity is compared with its limit: tanh(4·10) = 1 −
 * 4e-35, so at V_rel = 10·V_thr the capstan limit holds to 1e-12 too.
 * Includes laws/belt_pulley_law.h: it tests that internal law, which no public call shows. */
#include <math.h>
#include <stdio.h>

#include "laws/belt_pulley_law.h"
#include "testlib.h"

static const double PI = 3.14159265358979323846;

int main(void)
{
    /* V-belt: f' = f/sin(φ/2); a 38° groove and f = 0.3 give 0.9215 */
    CHECK_REL(bd_bpl_vbelt_friction(0.3, 38.0 * PI / 180.0), 0.3 / sin(19.0 * PI / 180.0), 1e-12);
    CHECK_REL(bd_bpl_vbelt_friction(0.3, 38.0 * PI / 180.0), 0.92147, 1e-4);
    /* a flat belt is the 180° groove limit */
    CHECK_REL(bd_bpl_vbelt_friction(0.3, PI), 0.3, 1e-12);

    bd_bpl law = {.f = 0.3, .theta = PI, .rho = 2.0, .v_thr = 0.01, .f_thr = 50.0};
    /* μ = −f·tanh(4V_rel/V_thr): 0 at no slip, odd, and 0.999·f at the
     * threshold (the seed's definition of V_thr: tanh(4) = 0.99933) */
    CHECK_ABS(bd_bpl_mu(&law, 0.0), 0.0, 1e-15);
    CHECK_REL(bd_bpl_mu(&law, 0.01), -0.3 * tanh(4.0), 1e-12);
    CHECK(fabs(bd_bpl_mu(&law, 0.01)) > 0.999 * 0.3);
    CHECK_REL(bd_bpl_mu(&law, -0.004), 0.3 * tanh(1.6), 1e-12);
    /* F_C = ρV² */
    CHECK_REL(bd_bpl_centrifugal(&law, 5.0), 50.0, 1e-12);
    CHECK_REL(bd_bpl_centrifugal(&law, -5.0), 50.0, 1e-12);
    /* tension factor tanh(T/F_thr); a slack end transmits nothing */
    CHECK_REL(bd_bpl_tension_factor(&law, 50.0), tanh(1.0), 1e-12);
    CHECK_ABS(bd_bpl_tension_factor(&law, 0.0), 0.0, 0.0);
    CHECK_ABS(bd_bpl_tension_factor(&law, -10.0), 0.0, 0.0);

    /* capstan, pulley dragging the belt forward (belt slower: V_rel < 0):
     * the arriving end is tight, (T_in − F_C) = (T_out − F_C)·e^(fθ) */
    double v = 5.0, Fc = 50.0, T_out = 1000.0;
    double tf = tanh(T_out / law.f_thr);
    double F = bd_bpl_force(&law, 0.0, T_out, v, -10.0 * law.v_thr);
    double T_in = T_out + F;   /* a massless wrap: the ends balance F */
    CHECK_REL(F, (T_out - Fc) * (exp(0.3 * PI) - 1.0) * tf, 1e-12);
    CHECK_REL((T_in - Fc) / (T_out - Fc), 1.0 + (exp(0.3 * PI) - 1.0) * tf, 1e-12);
    /* the other way: the belt outruns the pulley, friction holds it back,
     * the leaving end is tight: (T_out − F_C) = (T_in − F_C)·e^(fθ) */
    double Tin2 = 800.0;
    double F2 = bd_bpl_force(&law, Tin2, 0.0, v, 10.0 * law.v_thr);
    CHECK_REL(F2, -(Tin2 - Fc) * (exp(0.3 * PI) - 1.0) * tanh(Tin2 / law.f_thr), 1e-12);
    /* partial slip: the capstan exponent uses |μ| */
    double mu = bd_bpl_mu(&law, -0.002);
    CHECK_REL(bd_bpl_force(&law, 0.0, T_out, v, -0.002), (T_out - Fc) * (exp(mu * PI) - 1.0) * tf,
              1e-12);
    /* continuity at V_rel = 0 and no force below the centrifugal tension */
    CHECK_ABS(bd_bpl_force(&law, 900.0, 1000.0, v, 0.0), 0.0, 1e-12);
    CHECK_ABS(bd_bpl_force(&law, 900.0, 40.0, v, -1.0), 0.0, 1e-12);
    /* capacity: both directions at μ = ±f */
    double fwd, back;
    bd_bpl_capacity(&law, Tin2, T_out, v, &fwd, &back);
    CHECK_REL(fwd, (T_out - Fc) * (exp(0.3 * PI) - 1.0) * tf, 1e-12);
    CHECK_REL(back, (Tin2 - Fc) * (exp(0.3 * PI) - 1.0) * tanh(Tin2 / law.f_thr), 1e-12);

    /* implicit solve: the root satisfies F = force(v_free + κF) */
    double kappa = 1e-4, vfree = 0.5;
    double Fs = bd_bpl_solve(&law, Tin2, T_out, v, vfree, kappa);
    CHECK_ABS(Fs - bd_bpl_force(&law, Tin2, T_out, v, vfree + kappa * Fs), 0.0, 1e-6 * back);
    /* a large slip saturates at the backward capacity */
    CHECK_REL(Fs, -back, 1e-9);
    /* a small free slip within the capacity sticks: the force cancels it,
     * leaving a slip below V_thr (the regularization's creep) */
    double Fstick = bd_bpl_solve(&law, Tin2, T_out, v, 0.02, 1e-3);
    double v_end = 0.02 + 1e-3 * Fstick;
    printf("stick: F = %.4f N, slip left %.3g m/s\n", Fstick, v_end);
    CHECK(fabs(v_end) < 0.1 * law.v_thr);
    CHECK_REL(Fstick, -0.02 / 1e-3, 0.1 * law.v_thr / 0.02);
    /* nothing to hold: no tension on either end */
    CHECK_ABS(bd_bpl_solve(&law, 0.0, 0.0, v, 1.0, 1e-3), 0.0, 0.0);
    return bd_test_finish("belt_pulley_law");
}
