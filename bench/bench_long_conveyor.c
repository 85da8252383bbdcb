/* Benchmark (issue 2): a 1 km horizontal conveyor with 0.25 m elements
 * (about 8000 nodes), carry idlers every 1.2 m and return idlers every 3 m,
 * a tail takeup and a speed-controlled head drive. Prints node-steps per
 * second and the real-time factor of a run on one core. Not a test. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"

static const char *model =
    "name: 1 km bench\n"
    "belt: {mass_per_length: 30, axial_stiffness: 5.0e7, damping_ratio: 0.05,\n"
    "       element_length: 0.25}\n"
    "pulleys:\n"
    "  - name: tail\n"
    "    x: 0\n"
    "    y: 0\n"
    "    radius: 0.5\n"
    "    wrap: cw\n"
    "    mass: 1000\n"
    "    takeup: {type: constant_force, mass: 2000, force: 80000, axis: [-1, 0]}\n"
    "  - name: head\n"
    "    x: 1000\n"
    "    y: 0\n"
    "    radius: 0.5\n"
    "    wrap: cw\n"
    "    mass: 1500\n"
    "    drive: {control: speed, speed: 4.0, start: {curve: s-curve, time: 20}}\n"
    "idlers:\n"
    "  - {span: tail, spacing: 1.2, rolling_resistance: 0.02}\n"
    "  - {span: head, spacing: 3.0, rolling_resistance: 0.02}\n";

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv)
{
    double sim_seconds = argc > 1 ? atof(argv[1]) : 2.0;
    bd_model_def def;
    bd_diag d;
    bd_diag_init(&d);
    if (bd_model_load_string(model, strlen(model), "bench", &def, &d)) {
        for (int i = 0; i < d.count; i++)
            fprintf(stderr, "%s\n", d.lines[i]);
        return 1;
    }
    bd_sim *sim;
    if (bd_sim_create(&def, &sim, &d))
        return 1;
    double dt = bd_sim_time_step(sim);
    long steps = (long)(sim_seconds / dt);
    char err[512];
    double t0 = now();
    if (bd_sim_step(sim, steps, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    double wall = now() - t0;
    int n = bd_sim_node_count(sim);
    printf("nodes %d, idlers %d, dt %.3g s, %ld steps in %.2f s wall\n", n,
           bd_sim_idler_count(sim), dt, steps, wall);
    printf("node-steps per second: %.3g\n", (double)n * (double)steps / wall);
    printf("real-time factor: %.3f (simulated s per wall s)\n", sim_seconds / wall);
    bd_sim_free(sim);
    bd_model_def_free(&def);
    bd_diag_free(&d);
    return 0;
}
