/* Acceptance (issue 5): the same conveyor start run with the discrete belt
 * (seed 001, default element length) and with the axial belt (seed 004,
 * 2 m elements) agrees on the peak drive torque and the peak tight-side
 * tension within 5%. The conveyor: 100 m, horizontal, head drive with an
 * S-curve start to 2 m/s in 4 s, a constant-force takeup at the tail, carry
 * idlers every 1.5 m and return idlers every 3 m with rolling resistance.
 * The two models differ in what the axial one leaves out (sag between
 * idlers, bending over the pulleys, the wrap's friction lumped on nodes,
 * idler spin-up by friction), which the 5% of the issue covers.
 *
 * Both peaks are taken from the signals averaged over 0.2 s, about what a
 * drive's torque display shows; the raw peaks are printed. Until issue 10
 * the discrete belt ran over each pulley as a polygon of chords, whose
 * speed ripple at the node-passing frequency the speed controller answered
 * with torque spikes of ±40 %; its elements now follow the shell
 * (wrap_elements.c). The raw peak is 25 % above the averaged one (3633
 * against 2919 N·m; axial 1 %, moving-node 8 %): the speed loop follows
 * the start curve at 2 Hz, and the drum answers the discrete belt's 5 and
 * 11 Hz speed ripple (the nodes' passage, ±450 N·m at steady running on a
 * 600 N·m mean) with torque. Loop capped at the belt's impedance it was
 * 9 % (2978 against 2727 N·m), but lagged the curve (docs/physics.md §6).
 * The drive inertia (200 kg·m² at the pulley: motor and gearbox) is a
 * typical one. Speed is not a test: bench/bench_axial_10km.c times both. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "testlib.h"

static const char *model_fmt =
    "name: start %s\n"
    "belt: {mass_per_length: 20, axial_stiffness: 5.0e6, damping_ratio: 0.05,\n"
    "       formulation: %s%s}\n"
    "pulleys:\n"
    "  - name: tail\n"
    "    x: 0\n"
    "    y: 0\n"
    "    radius: 0.5\n"
    "    wrap: cw\n"
    "    mass: 300\n"
    "    takeup: {type: constant_force, mass: 500, force: 30000, axis: [-1, 0]}\n"
    "  - name: head\n"
    "    x: 100\n"
    "    y: 0\n"
    "    radius: 0.5\n"
    "    wrap: cw\n"
    "    mass: 500\n"
    "    friction: {static: 0.4, dynamic: 0.35}\n"
    "    drive: {control: speed, speed: 2.0, start: {curve: s-curve, time: 4}, inertia: 200}\n"
    "idlers:\n"
    "  - {span: tail, spacing: 1.5, rolling_resistance: 0.03}\n"
    "  - {span: head, spacing: 3.0, rolling_resistance: 0.03}\n"
    "simulation:\n"
    "  probes:\n"
    "    - {name: tight, span: tail, at: 0.9}\n";

#define T_END 6.0
#define WINDOW 0.2

typedef struct peaks {
    double torque, tight;          /* of the 0.2 s averages */
    double torque_raw, tight_raw;  /* of the step values */
} peaks;

/* largest mean of a[k..k+w) */
static double peak_of_mean(const double *a, long n, long w)
{
    double sum = 0.0, best = -INFINITY;
    for (long k = 0; k < n; k++) {
        sum += a[k];
        if (k >= w)
            sum -= a[k - w];
        if (k >= w - 1 && sum / (double)w > best)
            best = sum / (double)w;
    }
    return best;
}

static peaks run(const char *formulation, const char *extra)
{
    char yaml[4096];
    snprintf(yaml, sizeof yaml, model_fmt, formulation, formulation, extra);
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(yaml, &def, &sim);
    peaks pk = {0.0, 0.0, 0.0, 0.0};
    const double dt = bd_sim_time_step(sim);
    long steps = (long)ceil(T_END / dt), k = 0;
    double *torque = calloc((size_t)steps, sizeof *torque);
    double *tight = calloc((size_t)steps, sizeof *tight);
    char err[512];
    bd_pulley_state head;
    bd_probe_state pr;
    for (; k < steps; k++) {
        if (bd_sim_step(sim, 1, err, sizeof err)) {
            fprintf(stderr, "%s run failed: %s\n", formulation, err);
            CHECK(0);
            break;
        }
        bd_sim_pulley(sim, 1, &head);
        bd_sim_probe(sim, 0, &pr);
        torque[k] = head.drive_torque_Nm;
        tight[k] = pr.tension_N;
    }
    long w = lround(WINDOW / dt);
    pk.torque = peak_of_mean(torque, k, w);
    pk.tight = peak_of_mean(tight, k, w);
    pk.torque_raw = peak_of_mean(torque, k, 1);
    pk.tight_raw = peak_of_mean(tight, k, 1);
    printf("%-8s n = %5d, dt = %.3g s: peak torque %.1f N m (raw %.1f), peak tight-side "
           "tension %.1f N (raw %.1f)\n", formulation, bd_sim_node_count(sim), dt, pk.torque,
           pk.torque_raw, pk.tight, pk.tight_raw);
    free(torque);
    free(tight);
    bd_sim_free(sim);
    bd_model_def_free(&def);
    return pk;
}

int main(void)
{
    peaks d = run("discrete", "");
    peaks a = run("axial", ", element_length: 2.0");
    printf("axial - discrete: torque %+.2f%%, tension %+.2f%%\n",
           100.0 * (a.torque / d.torque - 1.0), 100.0 * (a.tight / d.tight - 1.0));
    CHECK_REL(a.torque, d.torque, 0.05);
    CHECK_REL(a.tight, d.tight, 0.05);
    /* the tension has no controller in the loop: even raw it agrees */
    CHECK_REL(a.tight_raw, d.tight_raw, 0.05);
    return bd_test_finish("axial_vs_discrete");
}
