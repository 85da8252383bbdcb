/* Benchmark (issue 12). Not a test: timing is not a test.
 *
 * The cement-plant conveyor (examples/cement_plant.yaml, 972 m, loaded,
 * 10 s S-curve start) run for SECONDS simulated with the belt formulation
 * FORMULATION set over the example's (moving_node: 5° wraps, idler spacing
 * on the spans). Prints the wall time, the node-steps per second and the
 * peak tight-side tension at the head drive, so the formulations can be
 * put side by side at their own meshes. Issue 12 asks for the 40 s start
 * with moving_node in under 3 s on one core.
 *
 *   bench_moving_node EXAMPLE.yaml [FORMULATION [SECONDS]]
 *   (defaults: moving_node, 40) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: bench_moving_node EXAMPLE.yaml [FORMULATION [SECONDS]]\n");
        return 2;
    }
    const char *form = argc > 2 ? argv[2] : "moving_node";
    double seconds = argc > 3 ? atof(argv[3]) : 40.0;
    bd_model_def def;
    bd_diag diag;
    bd_diag_init(&diag);
    if (bd_model_load(argv[1], &def, &diag)) {
        fprintf(stderr, "cannot load %s\n", argv[1]);
        return 2;
    }
    if (strcmp(form, "moving_node") == 0)
        def.belt.formulation = BD_FORMULATION_MOVING_NODE;
    else if (strcmp(form, "axial") == 0)
        def.belt.formulation = BD_FORMULATION_AXIAL;
    else
        def.belt.formulation = BD_FORMULATION_DISCRETE;
    bd_sim *sim;
    if (bd_sim_create(&def, &sim, &diag)) {
        fprintf(stderr, "cannot build the model\n");
        return 2;
    }
    char err[600];
    double t0 = now();
    long steps = (long)(seconds / bd_sim_time_step(sim) + 0.5);
    if (bd_sim_step(sim, steps, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    double wall = now() - t0;
    bd_run_result r;
    bd_sim_result(sim, &r);
    printf("%s: %d nodes, %ld steps of %.3g ms, %.2f s wall for %.1f s, %.3g node-steps/s, "
           "peak belt tension %.1f kN\n",
           form, bd_sim_node_count(sim), steps, 1e3 * bd_sim_time_step(sim), wall, seconds,
           (double)bd_sim_node_count(sim) * (double)steps / wall, r.tension_max_N / 1e3);
    bd_sim_free(sim);
    bd_model_def_free(&def);
    return 0;
}
