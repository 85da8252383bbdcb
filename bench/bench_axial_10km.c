/* Benchmark (issue 5). Not a test: timing is not a test.
 *
 * 1. A 10 km overland conveyor (belt loop 20 km) with the axial belt and
 *    2 m elements (about 10000 nodes), carry idlers every 1.5 m and return
 *    idlers every 4.5 m spread along the spans, loaded 120 kg/m, gravity
 *    takeup behind the head drive: a 60 s S-curve start to 5 m/s on one
 *    core. Prints the real-time factor (simulated s per wall s); issue 5
 *    asks for more than 1.
 * 2. The start of tests/unit/test_axial_vs_discrete.c (100 m, 6 s) with the
 *    discrete belt at its default element length and with the axial belt
 *    at 2 m: prints the speed-up (issue 5 asks for at least 10).
 *
 *   bench_axial_10km [SIMULATED_SECONDS]   (default 60) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"

static const char *overland =
    "name: 10 km bench\n"
    "belt: {formulation: axial, element_length: 2.0, mass_per_length: 40,\n"
    "       axial_stiffness: 1.0e8, damping_ratio: 0.05}\n"
    "pulleys:\n"
    "  - {name: head, x: 10000, y: 50, radius: 0.8, wrap: cw, mass: 6000,\n"
    "     friction: {static: 0.4, dynamic: 0.35},\n"
    "     drive: {control: speed, speed: 5.0, start: {curve: s-curve, time: 50}, inertia: 8000}}\n"
    "  - {name: snub, x: 9995, y: 48.5, radius: 0.6, wrap: ccw, mass: 2000}\n"
    "  - {name: takeup, x: 9990, y: 35, radius: 0.7, wrap: cw, mass: 3000,\n"
    "     takeup: {type: gravity, mass: 20000}}\n"
    "  - {name: bend, x: 9985, y: 48.5, radius: 0.6, wrap: ccw, mass: 2000}\n"
    "  - {name: tail, x: 0, y: 0, radius: 0.7, wrap: cw, mass: 4000}\n"
    "idlers:\n"
    "  - {span: tail, spacing: 1.5, radius: 0.0795, inertia: 0.05, rolling_resistance: 0.02}\n"
    "  - {span: bend, spacing: 4.5, radius: 0.0795, inertia: 0.03, rolling_resistance: 0.02}\n"
    "material: {mass_per_length: 120, feed: {span: tail, at: 0.001}, discharge: head}\n";

static const char *start_fmt =
    "name: start %s\n"
    "belt: {mass_per_length: 20, axial_stiffness: 5.0e6, damping_ratio: 0.05,\n"
    "       formulation: %s%s}\n"
    "pulleys:\n"
    "  - {name: tail, x: 0, y: 0, radius: 0.5, wrap: cw, mass: 300,\n"
    "     takeup: {type: constant_force, mass: 500, force: 30000, axis: [-1, 0]}}\n"
    "  - {name: head, x: 100, y: 0, radius: 0.5, wrap: cw, mass: 500,\n"
    "     friction: {static: 0.4, dynamic: 0.35},\n"
    "     drive: {control: speed, speed: 2.0, start: {curve: s-curve, time: 4}, inertia: 200}}\n"
    "idlers:\n"
    "  - {span: tail, spacing: 1.5, rolling_resistance: 0.03}\n"
    "  - {span: head, spacing: 3.0, rolling_resistance: 0.03}\n";

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* build, run `seconds`, return the wall time (negative on failure) */
static double timed_run(const char *yaml, double seconds, int verbose)
{
    bd_model_def def;
    bd_diag d;
    bd_diag_init(&d);
    bd_sim *sim = NULL;
    if (bd_model_load_string(yaml, strlen(yaml), "bench", &def, &d)
        || bd_sim_create(&def, &sim, &d)) {
        for (int i = 0; i < d.count; i++)
            fprintf(stderr, "%s\n", d.lines[i]);
        return -1.0;
    }
    double dt = bd_sim_time_step(sim);
    long steps = (long)(seconds / dt);
    char err[512];
    double t0 = now();
    if (bd_sim_step(sim, steps, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return -1.0;
    }
    double wall = now() - t0;
    if (verbose) {
        int n = bd_sim_node_count(sim);
        bd_pulley_state head;
        bd_sim_pulley(sim, 0, &head);
        bd_run_result r;
        bd_sim_result(sim, &r);
        printf("nodes %d, dt %.3g s, %ld steps in %.2f s wall; head speed %.3f m/s, peak "
               "tension %.0f N\n", n, dt, steps, wall, head.omega_rad_s * head.radius_m,
               r.tension_max_N);
        printf("node-steps per second: %.3g\n", (double)n * (double)steps / wall);
    }
    bd_sim_free(sim);
    bd_model_def_free(&def);
    bd_diag_free(&d);
    return wall;
}

int main(int argc, char **argv)
{
    double seconds = argc > 1 ? atof(argv[1]) : 60.0;
    printf("1. 10 km conveyor, axial belt, 2 m elements, %.0f s start\n", seconds);
    double wall = timed_run(overland, seconds, 1);
    if (wall < 0.0)
        return 1;
    printf("real-time factor: %.2f (simulated s per wall s)\n\n", seconds / wall);

    char yaml[4096];
    printf("2. 100 m conveyor start (6 s), discrete default elements vs axial 2 m\n");
    snprintf(yaml, sizeof yaml, start_fmt, "discrete", "discrete", "");
    double wd = timed_run(yaml, 6.0, 1);
    snprintf(yaml, sizeof yaml, start_fmt, "axial", "axial", ", element_length: 2.0");
    double wa = timed_run(yaml, 6.0, 1);
    if (wd < 0.0 || wa < 0.0)
        return 1;
    printf("speed-up axial over discrete: %.1fx\n", wd / wa);
    return 0;
}
