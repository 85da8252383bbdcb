/* The discrete belt converges with the mesh (issue 10): running force and
 * the peak tight-side tension change by less than 2 % when the element
 * length halves.
 *
 * The conveyor is tests/data/mesh_loaded_76m.yaml, generated conveyor
 * 1101: loaded, 76 m, a tail drive's s-curve start to 3.95 m/s. It is run
 * for 20 s at the default element (the chord of a 30° arc of its smallest
 * pulley, 0.159 m, 1060 nodes) and at half of it (2109 nodes: half the
 * loop's length over its nodes, which the stretch makes a little longer).
 * - Running force: the drive's torque over its radius, averaged over
 *   16–20 s of steady running.
 * - Peak tight-side tension: the drive monitor's, over the start.
 * Measured on 2026-11-24: 3349.5 against 3320.2 N (−0.87 %), and 30705.7
 * against 30594.0 N (−0.36 %).
 * The 2 % tolerance is the issue's. It leaves room for the belt's ringing
 * in the averaging window and for the moment the peak falls on; a mesh
 * error of the start's wave front would exceed it.
 * Its idlers turn the belt by 0.03 rad. On fast sagging returns
 * (φ ≥ 0.10 rad at v ≥ 0.2·c) the discrete belt's running force does not
 * converge (docs/physics.md §10, and `check` and `run` warn there). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "testlib.h"

#define DRIVE 4   /* the tail pulley, the drive */

static void run(const char *yaml, double *force, double *tight, int *nodes)
{
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(yaml, &def, &sim);
    *nodes = bd_sim_node_count(sim);
    char err[256];
    double sum = 0.0;
    long count = 0;
    int failed = 0;
    while (!failed && bd_sim_time(sim) < 20.0) {
        failed = bd_sim_step(sim, 1, err, sizeof err);
        if (bd_sim_time(sim) < 16.0)
            continue;
        bd_pulley_state p;
        bd_sim_pulley(sim, DRIVE, &p);
        sum += p.drive_torque_Nm / p.radius_m;
        count++;
    }
    CHECK(!failed);
    if (failed)
        fprintf(stderr, "%s\n", err);
    bd_run_result r;
    bd_sim_result(sim, &r);
    *force = count > 0 ? sum / (double)count : 0.0;
    *tight = r.tight_max_N;
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

int main(void)
{
    char *yaml = bd_test_read_data("mesh_loaded_76m.yaml");
    if (!yaml)
        return bd_test_finish("test_mesh_halving");
    double f1, t1, f2, t2;
    int n1, n2;
    run(yaml, &f1, &t1, &n1);
    /* half the default element: the loop over its node count, halved */
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(yaml, &def, &sim);
    double l0 = bd_sim_belt_length(sim) / bd_sim_node_count(sim);
    bd_sim_free(sim);
    bd_model_def_free(&def);
    char line[64];
    snprintf(line, sizeof line, "belt:\n  element_length: %.6g\n", 0.5 * l0);
    char *half = bd_test_replaced(yaml, "belt:\n", line);
    CHECK(half != NULL);
    if (half) {
        run(half, &f2, &t2, &n2);
        printf("elements %d -> %d: running force %.1f -> %.1f N (%+.2f %%), peak tight side "
               "%.1f -> %.1f N (%+.2f %%)\n",
               n1, n2, f1, f2, 100.0 * (f2 / f1 - 1.0), t1, t2, 100.0 * (t2 / t1 - 1.0));
        CHECK(n2 > 19 * n1 / 10);   /* about twice the nodes */
        CHECK(f1 > 1000.0);
        CHECK_REL(f2, f1, 0.02);
        CHECK_REL(t2, t1, 0.02);
    }
    free(half);
    free(yaml);
    return bd_test_finish("test_mesh_halving");
}
