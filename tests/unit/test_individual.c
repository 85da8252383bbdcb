/* The secondary and special resistances one by one (design.secondary:
 * individual, ISO 5048:1989 §5.2 Table 3; issue 15), on conveyor A of
 * test_standards.c with a loading point, skirts, cleaners and bearings
 * (tests/data/static_individual.yaml): g = 9.81 m/s², belt width B = 1.0 m,
 * thickness d = 0.012 m, pulleys D = 1.0 m, fabric carcass; material
 * m'_L = 60 kg/m at v = 2 m/s landing at v0 = 0.5 m/s, bulk density
 * ρ = 1600 kg/m³ (volume flow I_V = m'_L·v/ρ = 0.075 m³/s); skirts b1 =
 * 0.6 m apart, l = 5 m long, μ1 = μ2 = 0.6; two cleaners 1.0 m × 0.01 m at
 * 5·10⁴ Pa, μ3 = 0.6; bearings d0 = 0.12 m on the tail (600 kg), 0.10 m on
 * the takeup pulley (400 kg).
 *
 * 1. Static, by hand (each within 0.5 %, the acceptance of issue 15):
 *    F_bA = I_V·ρ·(v − v0) = 120·1.5 = 180 N;
 *    l_b = (v² − v0²)/(2·g·μ1) = 3.75/11.772 = 0.318552 m;
 *    F_f = μ2·I_V²·ρ·g·l_b/(((v + v0)/2)²·b1²) = 52.974·0.318552/0.5625 = 30.0 N;
 *    F_gl = μ2·I_V²·ρ·g·l/(v²·b1²) = 52.974·5/1.44 = 183.94 N;
 *    F_r = 2·1.0·0.01·5·10⁴·0.6 = 600 N;
 *    at each pulley (the drive's too), from the tensions the calculation
 *    reports:
 *    wrap 9·B·(140 + 0.01·F/B)·d/D with F = (T_in + T_out)/2, bearing
 *    0.005·(d0/D)·|F_T| with F_T = T_out·u_out − T_in·u_in − m·g·ŷ, and
 *    the belt leaving T_out = T_in + wrap + bearing (+ F_r at the head
 *    drum, where the cleaners scrape it) (to 1e-3 N: the fixed
 *    point is iterated to 1e-9 of Te); the sums as cli.md defines them.
 *    The main resistance is that of the C calculation (unchanged).
 * 2. Dynamic (axial and moving-node belts; the lumped belt agrees to 0.2 %
 *    but takes 20 times longer and its issue-10 idler losses are not this
 *    test's): at steady running (t = 10..14 s after an S-curve start of 4 s)
 *    the drive's force with the resistances one by one less that with
 *    secondary: C — whose run has only the feed point's m'_L·v² = 240 N
 *    (the idlers have no rolling resistance) — is the static
 *    F_bA + F_f + F_gl + F_r + wrap + bearings − m'_L·v² (the loading speed
 *    takes m'_L·v·v0 = 60 N off the feed's momentum flux). Within 1.5 %:
 *    the run's tensions differ from the static ones (its idlers take no
 *    f·L resistance) by up to ~2.5 kN at the pulleys, which moves their
 *    tension-dependent parts (0.00108·F for the wrap, 0.0006·|F_T| for a
 *    bearing) by up to ~12 N of the ~895 N. The energy balance of each run
 *    at its end (cli.md's measure, the energy at t = 0 the potential after
 *    stabilizing) within 1e-4: the resistances are booked as dissipated.
 *    The drive's speed loop is given `bandwidth: 0.21` Hz, where its
 *    proportional gain 2ω_c·J equals the belt's wave impedance at the
 *    drum, R²·2·√(EA·m′) (J = 2661 kg·m²): such a drive absorbs the start's
 *    waves and the takeup's swing, so the running is steady by 10 s. The
 *    default 2 Hz loop reflects them, and the takeup's 3 s swing (±1 kN
 *    on a 240 N running force at 5 s, ±300 N at 14 s, damped mostly by the
 *    feed) would be in the window: what is tested is the steady force,
 *    not how soon the drive settles it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "beltdyn/standards.h"
#include "testlib.h"

#define TOL 0.005

static double wrap_by_hand(double T_in, double T_out)
{
    double B = 1.0, d = 0.012, D = 1.0, F = 0.5 * (T_in + T_out);
    return 9.0 * B * (140.0 + 0.01 * F / B) * d / D;
}

static void static_part(const char *text, double *extra)
{
    bd_model_def m;
    bd_diag dg;
    bd_diag_init(&dg);
    if (bd_model_load_string(text, strlen(text), "static_individual.yaml", &m, &dg) != 0) {
        for (int i = 0; i < dg.count + dg.warning_count; i++)
            fprintf(stderr, "%s\n", dg.lines[i]);
        CHECK(0);
        bd_diag_free(&dg);
        return;
    }
    bd_static_result r;
    CHECK(bd_static_compute(&m, &r, &dg) == 0);
    CHECK(r.individual == 1);

    /* the loading point and the special resistances, by hand */
    const double g = 9.81, Iv = 60.0 * 2.0 / 1600.0;
    const double lb = (2.0 * 2.0 - 0.5 * 0.5) / (2.0 * g * 0.6);
    CHECK_REL(r.loading_inertia_N, 1600.0 * Iv * (2.0 - 0.5), TOL);
    CHECK_REL(r.loading_inertia_N, 180.0, TOL);
    CHECK_REL(r.acceleration_length_m, 0.318552, TOL);
    CHECK_REL(r.loading_skirts_N, 0.6 * Iv * Iv * 1600.0 * g * lb / (1.25 * 1.25 * 0.36), TOL);
    CHECK_REL(r.loading_skirts_N, 30.0, TOL);
    CHECK_REL(r.skirts_N, 0.6 * Iv * Iv * 1600.0 * g * 5.0 / (2.0 * 2.0 * 0.36), TOL);
    CHECK_REL(r.skirts_N, 183.94, TOL);
    CHECK_REL(r.cleaners_N, 600.0, TOL);

    /* the pulleys: tail 0, head 1 (drive), b1 2, tu 3, b2 4 */
    const double bore[5] = {0.12, 0, 0, 0.10, 0}, mass[5] = {600, 0, 0, 400, 0};
    double wrap = 0.0, bearings = 0.0;
    for (int p = 0; p < 5; p++) {
        const bd_static_pulley *sp = &r.pulleys[p];
        /* the belt flexes over the drive pulley too (ISO 5048 Table 3's
         * F_l on every pulley; its bearings are not in `bearings`) */
        CHECK_REL(sp->wrap_N, wrap_by_hand(sp->T_in_N, sp->T_out_N), TOL);
        wrap += sp->wrap_N;
        if (p == 1) {
            CHECK(sp->bearing_N == 0.0);
            CHECK_REL(sp->cleaners_N, 600.0, TOL);
            continue;
        }
        double want_bearing = 0.0;
        if (bore[p] > 0.0) {
            /* tail: arrives travelling −x, leaves +x; tu: arrives going
             * down, leaves going up (the vertical loop) */
            double fx = p == 0 ? sp->T_out_N + sp->T_in_N : 0.0;
            double fy = p == 0 ? 0.0 : sp->T_out_N + sp->T_in_N;
            fy -= mass[p] * g;
            want_bearing = 0.005 * bore[p] / 1.0 * hypot(fx, fy);
        }
        CHECK_REL(sp->bearing_N, want_bearing, TOL);
        CHECK_ABS(sp->T_out_N - sp->T_in_N, sp->wrap_N + sp->bearing_N + sp->cleaners_N, 1e-3);
        bearings += sp->bearing_N;
    }
    CHECK_REL(r.wrap_N, wrap, 1e-12);
    CHECK_REL(r.bearings_N, bearings, 1e-12);
    CHECK(r.wrap_N > 100.0 && r.bearings_N > 20.0); /* the pulleys did take something */

    /* the sums (cli.md `static --json`) */
    CHECK_REL(r.secondary_N, r.loading_inertia_N + r.loading_skirts_N + r.wrap_N + r.bearings_N,
              1e-12);
    CHECK_REL(r.special_N, r.skirts_N + r.cleaners_N, 1e-12);
    CHECK_REL(r.total_N, r.main_N + r.secondary_N + r.special_N + r.slope_N, 1e-12);
    CHECK_REL(r.effective_tension_N, r.total_N, 1e-12);
    CHECK_REL(r.motor_power_kW, r.total_N * 2.0 / 1000.0, 1e-12);
    /* Te = T1 − T2 at the drive, less its cleaners and the belt's wrap
     * over it: they act on the head drum, as in the run (the belt's
     * tension leaving the drum carries them; the drive supplies them at
     * the drum's surface) */
    CHECK_REL(r.T1_N - r.T2_N,
              r.effective_tension_N - r.pulleys[1].cleaners_N - r.pulleys[1].wrap_N, 1e-9);
    /* the main resistance is the C calculation's, unchanged */
    char *with_c = bd_test_replaced(text, "secondary: individual", "secondary: C");
    bd_model_def mc;
    bd_static_result rc;
    if (with_c && bd_model_load_string(with_c, strlen(with_c), "c.yaml", &mc, &dg) == 0) {
        CHECK(bd_static_compute(&mc, &rc, &dg) == 0);
        CHECK_REL(r.main_N, rc.main_N, 1e-12);
        bd_static_free(&rc);
        bd_model_def_free(&mc);
    } else {
        CHECK(0);   /* the model with secondary: C did not load */
    }
    free(with_c);

    /* the JSON has the keys cli.md lists */
    char *js = bd_static_to_json(&r, &m);
    const char *keys[] = {"\"loading_inertia\"", "\"loading_skirts\"", "\"wrap\"",
                          "\"bearings\"", "\"skirts\"", "\"cleaners\"", "\"special\"",
                          "\"motor_power_kW\""};
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++)
        CHECK(js && strstr(js, keys[k]));
    free(js);

    *extra = r.loading_inertia_N + r.loading_skirts_N + r.skirts_N + r.cleaners_N + r.wrap_N
           + r.bearings_N - 60.0 * 2.0 * 2.0;
    bd_static_free(&r);
    bd_model_def_free(&m);
    bd_diag_free(&dg);
}

/* mean drive force at the head over t = 10..14 s, N; the run's energy
 * balance error at its end */
static double drive_force(const char *text, double *balance)
{
    bd_model_def def;
    bd_sim *sim = NULL;
    char err[512];
    bd_test_make_sim(text, &def, &sim);
    bd_sim_book_energy_every_step(sim, 1);
    CHECK(bd_sim_stabilize(sim, NULL, err, sizeof err) == BD_RUN_OK);
    /* at rest after stabilizing: the energy at t = 0 is the potential */
    double E0 = bd_sim_potential_energy(sim);
    double sum = 0.0;
    long samples = 0;
    while (bd_sim_time(sim) < 14.0) {
        if (bd_sim_step(sim, 1, err, sizeof err) != 0) {
            fprintf(stderr, "run failed: %s\n", err);
            CHECK(0);
            break;
        }
        if (bd_sim_time(sim) >= 10.0) {
            bd_pulley_state ps;
            bd_sim_pulley(sim, 1, &ps);
            sum += ps.drive_torque_Nm / 0.5;
            samples++;
        }
    }
    bd_energy_state e;
    bd_sim_energy(sim, &e);
    double scale = fmax(fmax(fabs(E0), e.input_J), 1.0);
    *balance = fabs(e.kinetic_J + e.potential_J + e.dissipated_J - e.input_J - E0) / scale;
    bd_sim_free(sim);
    bd_model_def_free(&def);
    return samples ? sum / (double)samples : 0.0;
}

static void dynamic_part(const char *text, const char *formulation, double extra)
{
    char belt[128];
    snprintf(belt, sizeof belt, "axial_stiffness: 1.0e7\n  formulation: %s", formulation);
    char *quiet = bd_test_replaced(text, "inertia: 20}", "inertia: 20, bandwidth: 0.21}");
    char *a = quiet ? bd_test_replaced(quiet, "axial_stiffness: 1.0e7", belt) : NULL;
    free(quiet);
    /* the model as written has no simulation block: one at its end */
    char *ind2 = a ? malloc(strlen(a) + 64) : NULL;
    if (ind2)
        sprintf(ind2, "%s\nsimulation: {duration: 14, stabilize: true}\n", a);
    free(a);
    char *c = ind2 ? bd_test_replaced(ind2, "  secondary: individual\n", "  secondary: C\n") : NULL;
    CHECK(ind2 && c);
    if (!ind2 || !c) {
        free(ind2);
        free(c);
        return;
    }
    double bal_i, bal_c;
    double F_ind = drive_force(ind2, &bal_i);
    double F_c = drive_force(c, &bal_c);
    fprintf(stderr, "%s: drive force %.1f N one by one, %.1f N with C; static extra %.1f N; "
                    "balance %.2e, %.2e\n", formulation, F_ind, F_c, extra, bal_i, bal_c);
    CHECK_REL(F_c, 240.0, 0.01);
    CHECK_REL(F_ind - F_c, extra, 0.015);
    CHECK(bal_i < 1e-4 && bal_c < 1e-4);
    free(ind2);
    free(c);
}

/* the model's text with `from` replaced by `to` must be refused with a
 * message holding `want` */
static void refused(const char *text, const char *from, const char *to, const char *want)
{
    char *bad = bd_test_replaced(text, from, to);
    CHECK(bad != NULL);
    if (!bad)
        return;
    bd_model_def m;
    bd_diag dg;
    bd_diag_init(&dg);
    int rc = bd_model_load_string(bad, strlen(bad), "bad.yaml", &m, &dg);
    CHECK(rc != 0);
    int found = 0;
    for (int i = 0; i < dg.count; i++)
        if (strstr(dg.lines[i], want) && strstr(dg.lines[i], "bad.yaml:"))
            found = 1;
    if (!found)
        for (int i = 0; i < dg.count; i++)
            fprintf(stderr, "  got: %s\n", dg.lines[i]);
    CHECK(found);
    if (rc == 0)
        bd_model_def_free(&m);
    bd_diag_free(&dg);
    free(bad);
}

int main(void)
{
    char *text = bd_test_read_data("static_individual.yaml");
    if (!text)
        return bd_test_finish("test_individual");
    double extra = 0.0;
    static_part(text, &extra);
    /* what the resistances one by one need, said with the key */
    refused(text, "  width: 1.0\n", "", "belt.width");
    refused(text, "  belt_thickness: 0.012\n", "", "belt_thickness");
    refused(text, "  bulk_density: 1.6\n", "", "bulk_density");
    refused(text, "standard: din22101", "standard: cema", "design.secondary: `individual`");
    refused(text, "    tu: {bore: 0.10, mass: 400}", "    tx: {bore: 0.10, mass: 400}",
            "unknown pulley 'tx'");
    refused(text, "    tu: {bore: 0.10, mass: 400}", "    tu: {mass: 400}", "'bore'");
    refused(text, "count: 2,", "count: 1.5,", "whole number");
    dynamic_part(text, "axial", extra);
    dynamic_part(text, "moving_node", extra);
    free(text);
    return bd_test_finish("test_individual");
}
