/* A slow start's peak drive force is the rigid body's (issue 10): a 30 s
 * s-curve start of a loaded conveyor at the default element.
 *
 * The conveyor is tests/data/mesh_loaded_76m.yaml (loaded, 76 m, tail
 * drive), its start made a 30 s s-curve to v0 = 3.95 m/s. The belt's wave
 * takes 0.6 s round the loop, so over 30 s it moves as one body:
 *   F(t) = F_law(v) + M·dv/dt,   v = v0·(3τ² − 2τ³),  τ = t/30 s,
 * with F_law the model's own resistance law (sim/running_law.c: idlers,
 * lift, the feed's m'_L·v²) and M the belt, material, pulleys I/R² and
 * idlers I/r². Its peak is 4483 N at 18.9 s.
 *
 * The drive force is the drive's torque over its radius, and its peak is
 * taken over 0.2 s means. Measured on 2026-11-24: 4687 N, +4.6 % against a
 * tolerance of 10 % (the issue's). The tolerance allows for the takeup's
 * swing and the belt's slowest modes, which the element's dashpots barely
 * damp (ζ_mode = ζ·ω/ω_e, docs/physics.md §10).
 *
 * The raw peak carries ±0.8 kN of the belt's axial modes, 5–16 Hz at both
 * elements (not the node passage, 20 Hz there at the default element):
 * 5495 N (+22.6 %). It is no mesh artefact: at half the element it is
 * 5661 N, +3.0 % against the default's, and the test holds it within 5 %
 * of that (at a quarter, 5560 N). When the belt ran over the drum as
 * chords, the speed loop turned their ripple at the node passage into
 * raw peaks about twice the rigid body's (issue 10: 30–38 kN against
 * 16.8 kN on a 500 m conveyor). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "testlib.h"

#define DRIVE 4            /* the tail pulley, the drive */
#define V0 3.94763         /* m/s, the drive's speed */
#define T_START 30.0       /* s */

/* the rigid body's drive force, its largest over the curve (the s-curve
 * v = v0·(3τ² − 2τ³) of seed 000 eqs 52–55, as docs/physics.md §6 and
 * laws/start_curve.c take it) */
static double rigid_peak(const bd_sim *sim)
{
    double M = bd_test_rigid_mass(sim);
    bd_running_law law;
    bd_running_law_build(sim, &law);
    double peak = 0.0;
    for (int i = 1; i < 1000; i++) {
        double tau = i / 1000.0;
        double v = V0 * tau * tau * (3.0 - 2.0 * tau);
        double a = V0 * 6.0 * tau * (1.0 - tau) / T_START;
        double F = bd_running_law_force(&law, v, NULL) + M * a;
        if (F > peak)
            peak = F;
    }
    return peak;
}

/* the drive force's peak, raw and over 0.2 s means, to t_end */
static void drive_peaks(const char *yaml, double t_end, double *raw, double *mean, double *rigid)
{
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(yaml, &def, &sim);
    if (rigid)
        *rigid = rigid_peak(sim);
    char err[256];
    double sum = 0.0, window = 0.0;
    long count = 0;
    int failed = 0;
    *raw = 0.0;
    *mean = 0.0;
    while (!failed && bd_sim_time(sim) < t_end) {
        failed = bd_sim_step(sim, 1, err, sizeof err);
        bd_pulley_state p;
        bd_sim_pulley(sim, DRIVE, &p);
        double F = p.drive_torque_Nm / p.radius_m;
        if (F > *raw)
            *raw = F;
        sum += F;
        count++;
        window += bd_sim_time_step(sim);
        if (window >= 0.2 - 1e-9) {
            if (sum / (double)count > *mean)
                *mean = sum / (double)count;
            sum = 0.0;
            count = 0;
            window = 0.0;
        }
    }
    CHECK(!failed);
    if (failed)
        fprintf(stderr, "%s\n", err);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

int main(void)
{
    char *data = bd_test_read_data("mesh_loaded_76m.yaml");
    char *slow = data ? bd_test_replaced(data, "time: 4.86677", "time: 30") : NULL;
    char *yaml = slow ? bd_test_replaced(slow, "duration: 20", "duration: 32") : NULL;
    char *half = yaml ? bd_test_replaced(yaml, "belt:\n", "belt:\n  element_length: 0.0795\n")
                      : NULL;
    CHECK(yaml != NULL && half != NULL);
    if (yaml && half) {
        double raw, mean, rigid, raw_h, mean_h;
        drive_peaks(yaml, 32.0, &raw, &mean, &rigid);
        drive_peaks(half, 32.0, &raw_h, &mean_h, NULL);
        printf("30 s s-curve: rigid body's peak %.0f N; 0.2 s means %.0f N (%+.1f %%); raw "
               "%.0f N (%+.1f %%), at half the element %.0f N (%+.1f %% of it)\n",
               rigid, mean, 100.0 * (mean / rigid - 1.0), raw, 100.0 * (raw / rigid - 1.0),
               raw_h, 100.0 * (raw_h / raw - 1.0));
        CHECK(rigid > 4000.0);
        CHECK_REL(mean, rigid, 0.10);
        CHECK_REL(raw_h, raw, 0.05);
    }
    free(half);
    free(yaml);
    free(slow);
    free(data);
    return bd_test_finish("test_scurve_peak");
}
