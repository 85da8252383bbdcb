/* One compiled model, many runs (issue 11: the model is immutable after
 * building and shareable between runs and threads), through the public
 * API only.
 *
 * 1. Sequential: on head_drive (stabilization, a drive, a gravity takeup,
 *    idlers, material) and overland_axial, compile the model once, run a
 *    simulation made from it to the end, then make a second one from the
 *    same model and run it, and run a third through bd_sim_create. All
 *    three write the same bytes (summary.json less its wall time). Had the
 *    first run changed the model, the second would differ. Also on an axial
 *    belt whose load fronts move (started empty and fed; loaded and no
 *    longer fed): the material phase reads the model at step time.
 * 2. Threads: two simulations made from one model step side by side in two
 *    threads; every node of each ends bit-identical to a simulation stepped
 *    alone. Tolerance: none (the same operations on the same numbers). */
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "testlib.h"

/* all four outputs of a run in dir, hashed together */
static uint64_t hash_run(const char *dir)
{
    uint64_t h = 0;
    for (int i = 0; i < BD_TEST_RUN_FILE_COUNT; i++) {
        char p[1024];
        snprintf(p, sizeof p, "%s/%s", dir, bd_test_run_files[i]);
        uint64_t fh = bd_test_hash_file(p);
        CHECK(fh != 0);
        h = h * 31 + fh;
    }
    bd_test_remove_run(dir);
    return h;
}

static uint64_t run_into(bd_sim *sim, const char *dir)
{
    bd_run_options opt = {.out_dir = dir};
    char err[512];
    CHECK(bd_sim_run(sim, &opt, err, sizeof err) == BD_RUN_OK);
    return hash_run(dir);
}

/* an axial belt whose load fronts move while it runs: loaded from empty
 * (the head front rides to the discharge) or emptied (feeding stops, the
 * tail front rides) */
static const char *FRONTS =
    "name: moving load fronts\n"
    "belt: {mass_per_length: 15, axial_stiffness: 4.0e6, damping_ratio: 0.05,\n"
    "       element_length: 1.0, formulation: axial}\n"
    "pulleys:\n"
    "  - {name: head, x: 40, y: 2, radius: 0.4, wrap: cw, mass: 300,\n"
    "     drive: {control: speed, speed: 2.0, start: {curve: s-curve, time: 2}}}\n"
    "  - {name: tail, x: 0, y: 0, radius: 0.4, wrap: cw, mass: 300,\n"
    "     takeup: {type: gravity, mass: 1200, axis: [-1, 0]}}\n"
    "idlers:\n"
    "  - {span: tail, spacing: 1.2, rolling_resistance: 0.02}\n"
    "material: {mass_per_length: 30, feed: {span: tail, at: 0.05}, discharge: head,\n"
    "           initially_loaded: %s, feeding: %s}\n";

/* an example by name, or "fronts_empty" / "fronts_emptied" */
static int load(const char *name, double duration, bd_model_def *def)
{
    bd_diag diag;
    bd_diag_init(&diag);
    int bad;
    if (strncmp(name, "fronts_", 7) == 0) {
        char yaml[2048];
        int empty = strcmp(name, "fronts_empty") == 0;
        snprintf(yaml, sizeof yaml, FRONTS, empty ? "false" : "true", empty ? "true" : "false");
        bad = bd_model_load_string(yaml, strlen(yaml), name, def, &diag);
    } else {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s.yaml", BD_EXAMPLES_DIR, name);
        bad = bd_model_load(path, def, &diag);
    }
    for (int i = 0; i < diag.count; i++)
        fprintf(stderr, "%s\n", diag.lines[i]);
    bd_diag_free(&diag);
    CHECK(bad == 0);
    def->simulation.duration = duration;
    return bad;
}

static void sequential(const char *name, double duration, const char *root)
{
    bd_model_def def;
    if (load(name, duration, &def))
        return;
    bd_model *model = NULL;
    CHECK(bd_test_compile(&def, &model) == 0);
    bd_sim *c = NULL;
    CHECK(bd_test_create(&def, &c) == 0);
    if (!model || !c)
        return;
    char dir[600];
    bd_sim *a = NULL, *b = NULL;
    CHECK(bd_sim_create_from(model, &a) == 0);
    snprintf(dir, sizeof dir, "%s/%s_a", root, name);
    uint64_t ha = run_into(a, dir);
    bd_sim_free(a);
    CHECK(bd_sim_create_from(model, &b) == 0);
    snprintf(dir, sizeof dir, "%s/%s_b", root, name);
    uint64_t hb = run_into(b, dir);
    snprintf(dir, sizeof dir, "%s/%s_c", root, name);
    uint64_t hc = run_into(c, dir);
    printf("%-16s first run %016llx, second %016llx, bd_sim_create %016llx\n", name,
           (unsigned long long)ha, (unsigned long long)hb, (unsigned long long)hc);
    CHECK(ha == hb);
    CHECK(ha == hc);
    bd_sim_free(b);
    bd_sim_free(c);
    bd_model_free(model);
    bd_model_def_free(&def);
}

typedef struct stepper {
    bd_sim *sim;
    long steps;
    int failed;
} stepper;

static void *step_thread(void *arg)
{
    stepper *s = arg;
    char err[512];
    s->failed = bd_sim_step(s->sim, s->steps, err, sizeof err);
    return NULL;
}

static int same_state(const bd_sim *x, const bd_sim *y)
{
    int n = bd_sim_node_count(x);
    for (int i = 0; i < n; i++) {
        bd_node_state a, b;
        bd_sim_node(x, i, &a);
        bd_sim_node(y, i, &b);
        if (memcmp(&a, &b, sizeof a) != 0)
            return 0;
    }
    return 1;
}

static void threads(const char *name, long steps)
{
    bd_model_def def;
    if (load(name, 1.0, &def))
        return;
    bd_model *model = NULL;
    CHECK(bd_test_compile(&def, &model) == 0);
    if (!model)
        return;
    stepper s[3] = {{NULL, steps, 0}, {NULL, steps, 0}, {NULL, steps, 0}};
    for (int k = 0; k < 3; k++)
        CHECK(bd_sim_create_from(model, &s[k].sim) == 0);
    /* the reference alone, then two side by side */
    step_thread(&s[0]);
    pthread_t t[2];
    for (int k = 0; k < 2; k++)
        CHECK(pthread_create(&t[k], NULL, step_thread, &s[k + 1]) == 0);
    for (int k = 0; k < 2; k++)
        pthread_join(t[k], NULL);
    for (int k = 0; k < 3; k++)
        CHECK(!s[k].failed);
    int same1 = same_state(s[0].sim, s[1].sim), same2 = same_state(s[0].sim, s[2].sim);
    printf("%-16s %ld steps in two threads on one model: %s\n", name, steps,
           same1 && same2 ? "every node bit-identical to the run alone" : "DIFFERENT");
    CHECK(same1);
    CHECK(same2);
    for (int k = 0; k < 3; k++)
        bd_sim_free(s[k].sim);
    bd_model_free(model);
    bd_model_def_free(&def);
}

int main(void)
{
    char tmpl[] = "/tmp/bd_share_XXXXXX";
    const char *root = mkdtemp(tmpl);
    CHECK(root != NULL);
    if (!root)
        return bd_test_finish("test_model_share");
    sequential("head_drive", 0.5, root);
    sequential("overland_axial", 4.0, root);
    sequential("fronts_empty", 6.0, root);
    sequential("fronts_emptied", 6.0, root);
    remove(root);
    threads("head_drive", 3000);
    threads("overland_axial", 3000);
    threads("fronts_empty", 3000);
    return bd_test_finish("test_model_share");
}
