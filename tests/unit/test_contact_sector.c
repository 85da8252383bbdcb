/* Every node of a wrap's sector is tested every step (issue 10 item 1).
 * The reproduction: a gravity-free, frictionless, undamped
 * two-pulley loop with a constant-force takeup, laid unstretched
 * (initial_state: rest) so that tension waves run round it and the wraps
 * load and unload. When only last step's contact set ± 3 nodes was tested,
 * nodes outside it sank 15–46 mm into the shell unseen and were then thrown
 * out; the run diverged at 1.06 s. Now it must complete 10 s, and no node
 * may ever be deeper in a shell than the contact spring allows: the stiff
 * contact (k_c = 100·EA/l0) holds a wrapped node at δ = T·l0/(R·k_c), about
 * 2 µm here at the 20 kN pull; 0.5 mm allows for a landing node's
 * overshoot within one step and is 30× below the depths the old search
 * let through. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "testlib.h"

int main(void)
{
    bd_model_def def;
    bd_sim *sim;
    char *model = bd_test_read_data("loop_from_rest.yaml");
    if (!model)
        return bd_test_finish("contact_sector");
    bd_test_make_sim(model, &def, &sim);
    free(model);
    int n = bd_sim_node_count(sim);
    double deepest = 0.0, deepest_t = 0.0;
    char err[512] = "";
    int ok = 1;
    while (ok && bd_sim_time(sim) < 10.0 - 1e-9) {
        /* every step: a node may sink and be thrown out within a few */
        ok = bd_sim_step(sim, 1, err, sizeof err) == 0;
        for (int p = 0; p < 2; p++) {
            bd_pulley_state ps;
            bd_sim_pulley(sim, p, &ps);
            for (int i = 0; i < n; i++) {
                bd_node_state nd;
                bd_sim_node(sim, i, &nd);
                double depth = ps.radius_m - hypot(nd.x_m - ps.x_m, nd.y_m - ps.y_m);
                if (depth > deepest) {
                    deepest = depth;
                    deepest_t = bd_sim_time(sim);
                }
            }
        }
    }
    printf("%s at t = %.3f s; deepest node in a shell %.3g mm (t = %.3f s)\n",
           ok ? "completed" : err, bd_sim_time(sim), 1e3 * deepest, deepest_t);
    CHECK(ok);
    CHECK(deepest < 0.5e-3);
    bd_sim_free(sim);
    bd_model_def_free(&def);
    return bd_test_finish("contact_sector");
}
