/* The takeup carriage is solved with the belt on its pulley (issue 10
 * item 4): a step in the takeup force sets the carriage oscillating about
 * the static stretch, and the oscillation decays as the belt's damping
 * says, with energy that balances and a dissipation that never falls.
 *
 * 1. Gravity-free two-pulley loop, frictionless shells, a constant-force
 *    takeup stepped from 20 to 24 kN. The belt's tension is uniform, so
 *    the carriage's static travel is q = ΔF·L/(4·EA) (both strands carry
 *    ΔF/2 over the loop's length L, and q lengthens the loop by 2q). The
 *    carriage and pulley (M) ride on the belt's stiffness k = 4·EA/L, with
 *    the belt's own mass in the mode by Rayleigh's estimate (the wrap on
 *    the takeup pulley moves with it, each span stretches linearly: a
 *    third of its mass): ω² = k/(M + m_wrap + (2/3)·m_span).
 *    Every element's dashpot is c = 2ζ·√(k_e·m_e) (seed 001 eq 4.3), a
 *    relaxation time τ = c/k_e; the loop's dashpots all stretch with it,
 *    so the mode is damped by c_q = k·τ: a logarithmic decrement of π·ω·τ
 *    per cycle. ζ = 1 (the element critically damped) makes it 0.023,
 *    measurable in nine cycles.
 *    Tolerances (what each allows for is said at the checks): the mean
 *    within 1 % (measured −0.20 %; when the wraps were chords they added
 *    compliance, +0.35 % here at 7.4° and +6.0 % at the default 30°, which
 *    is why this model sets element_length); ω within 1 % of the Rayleigh
 *    estimate (measured +0.36 %), the decrement within 2 % (measured
 *    0.02255 against 0.02254).
 * 2. The runaway: a 10 kg carriage under massless frictionless
 *    pulleys. With the carriage explicit and the belt's contact solved
 *    against last step's acceleration, the wrapped belt's mass fed back
 *    against the carriage's: "dissipated" energy grew by 90 kW while the
 *    run said it completed (640 kJ in 6 s, against 500 J in the system).
 *    Now it must stay within its static stretch's swing, balance its
 *    energy within 0.5 % of the energy in play, and never book a fall of
 *    dissipated energy over a millisecond beyond 1e-9 of it (round-off of
 *    the sums). */
#include <math.h>
#include <stdio.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "testlib.h"

#define EA 5.0e6
#define MPL 2.0
#define ZETA 1.0
#define L0 0.2071
#define DF 4000.0
#define PI 3.14159265358979323846

static const char *decay_model =
    "name: takeup force step, frictionless\n"
    "gravity: 0\n"
    "belt: {mass_per_length: 2, axial_stiffness: 5.0e6, damping_ratio: 1.0,\n"
    "       element_length: 0.2071}\n"
    "pulleys:\n"
    "  - {name: a, x: 20, y: 0, radius: 1.6, wrap: cw, mass: 200, inertia: 20,\n"
    "     friction: {static: 0, dynamic: 0}}\n"
    "  - name: b\n"
    "    x: 0\n"
    "    y: 0\n"
    "    radius: 1.6\n"
    "    wrap: cw\n"
    "    mass: 200\n"
    "    inertia: 20\n"
    "    friction: {static: 0, dynamic: 0}\n"
    "    takeup: {type: constant_force, mass: 300, axis: [-1, 0],\n"
    "             force: [[0, 20000], [0.05, 20000], [0.0501, 24000]]}\n"
    "simulation: {duration: 2.5, initial_state: static}\n";

static const char *light_model =
    "name: light carriage, massless frictionless pulleys\n"
    "gravity: 0\n"
    "belt: {mass_per_length: 20, axial_stiffness: 5.0e6, damping_ratio: 0.02}\n"
    "pulleys:\n"
    "  - {name: a, x: 20, y: 0, radius: 0.4, wrap: cw, mass: 0, inertia: 20,\n"
    "     friction: {static: 0, dynamic: 0}}\n"
    "  - name: b\n"
    "    x: 0\n"
    "    y: 0\n"
    "    radius: 0.4\n"
    "    wrap: cw\n"
    "    mass: 0\n"
    "    inertia: 20\n"
    "    friction: {static: 0, dynamic: 0}\n"
    "    takeup: {type: constant_force, mass: 10, axis: [-1, 0],\n"
    "             force: [[0, 20000], [0.2, 20000], [0.21, 24000]]}\n"
    "simulation: {duration: 6, initial_state: static}\n";

/* energy account: the largest |balance| and fall of dissipation so far,
 * the dissipation compared over each millisecond: within one step an
 * explicit dashpot (its force from the last half step's velocity) and the
 * implicit contact may do negative work on a motion at the step's own
 * frequency; over a millisecond (≥ 40 steps) what they book is theirs */
typedef struct account {
    double ref, scale, balance, d_prev, t_prev, drop;
} account;

static void account_start(bd_sim *sim, account *a)
{
    bd_energy_state e;
    bd_sim_energy(sim, &e);
    a->ref = e.kinetic_J + bd_sim_potential_energy(sim) + e.dissipated_J - e.input_J;
    a->scale = fabs(a->ref);
    a->d_prev = e.dissipated_J;
    a->t_prev = bd_sim_time(sim);
    a->balance = a->drop = 0.0;
}

static void account_check(bd_sim *sim, account *a)
{
    bd_energy_state e;
    bd_sim_energy(sim, &e);
    if (e.kinetic_J > a->scale)
        a->scale = e.kinetic_J;
    if (fabs(e.input_J) > a->scale)
        a->scale = fabs(e.input_J);
    double bal = fabs(e.kinetic_J + e.potential_J + e.dissipated_J - e.input_J - a->ref);
    if (bal > a->balance)
        a->balance = bal;
    if (bd_sim_time(sim) < a->t_prev + 1e-3)
        return;
    if (a->d_prev - e.dissipated_J > a->drop)
        a->drop = a->d_prev - e.dissipated_J;
    a->d_prev = e.dissipated_J;
    a->t_prev = bd_sim_time(sim);
}

static void decay(void)
{
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(decay_model, &def, &sim);
    bd_sim_book_energy_every_step(sim, 1);
    const double L = bd_sim_belt_length(sim), dt = bd_sim_time_step(sim);
    /* extremes of the carriage's travel after the step */
    double ext[64], ext_t[64];
    int n_ext = 0;
    double q1 = 0.0, q2 = 0.0;
    char err[512] = "";
    int ok = 1;
    account acc;
    account_start(sim, &acc);
    for (long k = 0; ok && bd_sim_time(sim) < 2.5 - 1e-9; k++) {
        ok = bd_sim_step(sim, 1, err, sizeof err) == 0;
        account_check(sim, &acc);
        bd_takeup_state ts;
        bd_sim_takeup(sim, 1, &ts);
        double q = ts.travel_m;
        if (k > 2 && bd_sim_time(sim) > 0.1 && n_ext < 64
            && ((q1 > q2 && q1 >= q) || (q1 < q2 && q1 <= q))) {
            ext[n_ext] = q1;
            ext_t[n_ext++] = bd_sim_time(sim) - dt;
        }
        q2 = q1;
        q1 = q;
    }
    CHECK(ok);
    CHECK(n_ext >= 20);
    if (n_ext < 20) {
        fprintf(stderr, "%s; %d extremes\n", err, n_ext);
        return;
    }
    /* mean: midpoints of successive extremes; period: 9 cycles */
    double mean = 0.0;
    for (int i = 0; i + 1 < 19; i++)
        mean += 0.5 * (ext[i] + ext[i + 1]);
    mean /= 18.0;
    double period = (ext_t[18] - ext_t[0]) / 9.0;
    double omega = 2.0 * PI / period;
    /* decrement: peak-to-peak swings 9 cycles apart */
    double swing0 = fabs(ext[1] - ext[0]), swing9 = fabs(ext[19] - ext[18]);
    double decrement = log(swing0 / swing9) / 9.0;
    double k_e = EA / L0, m_e = MPL * L0, tau = 2.0 * ZETA * sqrt(m_e / k_e);
    double k = 4.0 * EA / L;
    double span = 20.0, wrap = PI * 1.6;
    double m_eff = 500.0 + MPL * wrap + (2.0 / 3.0) * MPL * span;
    double q_static = DF * L / (4.0 * EA);
    printf("decay: mean travel %.6f m (static %.6f), omega %.3f rad/s (Rayleigh %.3f), "
           "decrement %.5f (pi*omega*tau %.5f); balance %.3g J, dissipation fell %.3g J "
           "of %.4g J\n",
           mean, q_static, omega, sqrt(k / m_eff), decrement, PI * omega * tau, acc.balance,
           acc.drop, acc.scale);
    /* mean within 1 %: each midpoint of two successive extremes of a
     * decaying swing is off by about decrement/4 of the swing (0.6 % here,
     * the swing about the mean's size); measured −0.20 %.
     * ω within 1 %: Rayleigh's estimate takes the strands' mode shapes as
     * linear (2/3 of a span's mass); measured +0.36 %.
     * decrement within 2 %: the carriage mode's alone; the spans' own
     * modes, damped faster, ride on the first swings; measured 0.02255 for
     * 0.02254 */
    CHECK_REL(mean, q_static, 0.01);
    CHECK_REL(omega, sqrt(k / m_eff), 0.01);
    CHECK_REL(decrement, PI * omega * tau, 0.02);
    CHECK(acc.balance <= 0.005 * acc.scale);
    CHECK(acc.drop <= 1e-9 * acc.scale);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

static void light_carriage(void)
{
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(light_model, &def, &sim);
    bd_sim_book_energy_every_step(sim, 1);
    char err[512] = "";
    int ok = 1;
    double q_lo = 0.0, q_hi = 0.0;
    account acc;
    account_start(sim, &acc);
    while (ok && bd_sim_time(sim) < 6.0 - 1e-9) {
        ok = bd_sim_step(sim, 1, err, sizeof err) == 0;
        account_check(sim, &acc);
        bd_takeup_state ts;
        bd_sim_takeup(sim, 1, &ts);
        if (ts.travel_m < q_lo)
            q_lo = ts.travel_m;
        if (ts.travel_m > q_hi)
            q_hi = ts.travel_m;
    }
    /* twice the static travel ΔF·L/(4·EA) is the undamped swing's top */
    double q_static = DF * bd_sim_belt_length(sim) / (4.0 * EA);
    printf("light carriage: %s; travel %.6f .. %.6f m (static %.6f); balance %.3g J, "
           "dissipation fell %.3g J of %.4g J\n",
           ok ? "completed" : err, q_lo, q_hi, q_static, acc.balance, acc.drop, acc.scale);
    CHECK(ok);
    CHECK(q_lo > -0.1 * q_static && q_hi < 2.2 * q_static);
    CHECK(acc.balance <= 0.005 * acc.scale);
    CHECK(acc.drop <= 1e-9 * acc.scale);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

int main(void)
{
    decay();
    light_carriage();
    return bd_test_finish("takeup_step");
}
