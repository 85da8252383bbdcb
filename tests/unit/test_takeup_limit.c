/* A takeup carriage stops at the end of its travel (model-format.md
 * `travel`), and the run says so once, however often it arrives there.
 *
 * The seed-001 vertical loop with a constant-force takeup whose pull steps
 * up by 20% over 0.2 s: unbounded, the carriage would settle
 * ΔF·L_h/(2·EA) = 29430·100/(2·7.62e6) = 0.193 m lower and swing about
 * twice that. With travel [-0.05, 0.05] m it must never pass a limit,
 * must reach +0.05 m (travel is measured along the carriage axis, which
 * points down by default, the way the pull moves it), and the run's warnings
 * must hold exactly one line about it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "testlib.h"

static const char *model =
    "name: takeup at its limit\n"
    "belt: {mass_per_length: 100, axial_stiffness: 7.62e6, damping_ratio: 0.02}\n"
    "pulleys:\n"
    "  - {name: top, x: 0, y: 100, radius: 5, wrap: cw, mass: 300}\n"
    "  - name: bottom\n"
    "    x: 0\n"
    "    y: 0\n"
    "    radius: 5\n"
    "    wrap: cw\n"
    "    mass: 300\n"
    "    takeup: {type: constant_force, mass: 15000, travel: [-0.05, 0.05],\n"
    "             force: [[0, 147150], [0.2, 176580]]}\n"
    "simulation: {duration: 3, output_interval: 0.1}\n";

int main(void)
{
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(model, &def, &sim);
    char dir[] = "/tmp/bd_takeup_limitXXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    bd_run_options opt = {0};
    opt.out_dir = dir;
    char err[512] = "";
    CHECK(bd_sim_run(sim, &opt, err, sizeof err) == BD_RUN_OK);
    bd_takeup_state tk = {0};
    CHECK(bd_sim_takeup(sim, 1, &tk) == 0);
    printf("travel %.4f .. %.4f m, arrivals at a limit %d\n", tk.travel_min_m, tk.travel_max_m,
           tk.limit_hits);
    CHECK(tk.travel_min_m >= -0.05 - 1e-12);
    CHECK(tk.travel_max_m <= 0.05 + 1e-12);
    CHECK_ABS(tk.travel_max_m, 0.05, 1e-12);
    CHECK(tk.limit_hits >= 1);
    int said = 0;
    for (int i = 0; i < bd_sim_warning_count(sim); i++) {
        const char *w = bd_sim_warning(sim, i);
        printf("warning: %s\n", w);
        if (strstr(w, "takeup 'bottom' reached the end of its travel (0.05 m)"))
            said++;
    }
    CHECK(said == 1);
    bd_sim_free(sim);
    bd_model_def_free(&def);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
    return bd_test_finish("takeup_limit");
}
