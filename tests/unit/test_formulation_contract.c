/* The formulation contract (issue 11): every belt formulation runs the same
 * conveyor through the public API (load, create, run, result) and passes
 * the same checks, so that drives, takeups, probes, monitors, outputs and
 * the energy account work on it with no code of its own.
 *
 * The conveyor: 40 m, horizontal, head drive (speed control, S-curve to
 * 2 m/s in 4 s), tail gravity takeup, carry and return idlers, 30 kg/m of
 * material from near the tail to the head, two probes; 7 s.
 *
 * Checks and what their tolerances allow for:
 * - every output file is there, and summary.json has every key of cli.md
 *   (exact);
 * - the probes read the moving belt, and where it is (within 5 cm of the
 *   probe's point on the path: the sag between idlers is millimetres);
 * - their speed: their final speed within 5% of the
 *   drive's 2 m/s (a sensor that is not wired reads 0). 5% allows for the
 *   lumped belt's speed ringing 3 s after the start: its carry probe reads
 *   1.94 m/s at 7 s and 1.973 m/s averaged over the last 2 s, while the
 *   axial belt's reads 2.0002 (issue 10 is about the lumped belt's ripple);
 * - the drive monitor sees the drive: tight-side maximum above the
 *   slack-side minimum, both positive, no slip (exact);
 * - the takeup moved and stayed within 0.5 m (the 40 m belt stretches by
 *   centimetres);
 * - energy balance_error_rel below 1% (measured: 0.16% discrete, 0.13%
 *   axial; issue 10 will tighten the engine to 0.5% of the largest flow on
 *   generated conveyors).
 * The formulations' numbers are printed side by side but not compared
 * here: on this conveyor the lumped belt drew 43% more running torque
 * than the axial one (319 against 223.5 N·m, the axial matching the
 * idlers' rolling resistance plus the feed) and peaked 45% higher after
 * the start, before issue 10's elements round the shell (then 13.6 kN
 * against 7.8 kN) and its smoothed idler contact (now 9.6 kN against
 * 7.8 kN, and a slack side of 2.9 kN against 5.1 kN). What remains is the
 * lumped engine's open defect at the default mesh (issue 10), where this
 * comparison becomes a check. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "testlib.h"

static const char *MODEL =
    "name: contract conveyor\n"
    "belt: {mass_per_length: 15, axial_stiffness: 4.0e6, damping_ratio: 0.05,\n"
    "       element_length: %s, formulation: %s}\n"
    "pulleys:\n"
    "  - name: head\n"
    "    x: 40\n"
    "    y: 0\n"
    "    radius: 0.4\n"
    "    wrap: cw\n"
    "    mass: 300\n"
    "    friction: {static: 0.4, dynamic: 0.35}\n"
    "    drive: {control: speed, speed: 2.0, start: {curve: s-curve, time: 4},\n"
    "            inertia: 10}\n"
    "  - name: tail\n"
    "    x: 0\n"
    "    y: 0\n"
    "    radius: 0.4\n"
    "    wrap: cw\n"
    "    mass: 300\n"
    "    takeup: {type: gravity, mass: 1200, axis: [-1, 0]}\n"
    "idlers:\n"
    "  - {span: tail, spacing: 1.2, rotating_mass: 12, rolling_resistance: 0.02}\n"
    "  - {span: head, spacing: 3.0, rotating_mass: 8, rolling_resistance: 0.02}\n"
    "material: {mass_per_length: 30, feed: {span: tail, at: 0.05}, discharge: head}\n"
    "simulation:\n"
    "  duration: 7\n"
    "  output_interval: 0.05\n"
    "  probes:\n"
    "    - {name: carry, span: tail, at: 0.5}\n"
    "    - {name: return, span: head, at: 0.5}\n";

static cJSON *read_json(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    static char buf[1 << 20];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    return cJSON_Parse(buf);
}

static double num(const cJSON *o, const char *a, const char *b, const char *c)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, a);
    if (b)
        v = cJSON_GetObjectItemCaseSensitive(v, b);
    if (c)
        v = cJSON_GetObjectItemCaseSensitive(v, c);
    return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

static int file_present(const char *dir, const char *name)
{
    char p[1024];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    return access(p, R_OK) == 0;
}

/* run one formulation into dir; its peak tension in *peak */
static void contract(const char *formulation, const char *element_length, const char *dir)
{
    char yaml[4096];
    snprintf(yaml, sizeof yaml, MODEL, element_length, formulation);
    bd_model_def def;
    bd_diag diag;
    bd_diag_init(&diag);
    int bad = bd_model_load_string(yaml, strlen(yaml), formulation, &def, &diag);
    bd_sim *sim = NULL;
    if (!bad)
        bad = bd_sim_create(&def, &sim, &diag);
    for (int i = 0; i < diag.count; i++)
        fprintf(stderr, "%s\n", diag.lines[i]);
    bd_diag_free(&diag);
    CHECK(bad == 0);
    if (bad)
        return;
    bd_run_options opt = {.out_dir = dir};
    char err[512] = "";
    int rc = bd_sim_run(sim, &opt, err, sizeof err);
    if (rc)
        fprintf(stderr, "%s: %s\n", formulation, err);
    CHECK(rc == BD_RUN_OK);
    bd_run_result r;
    bd_sim_result(sim, &r);

    /* every output */
    for (int i = 0; i < BD_TEST_RUN_FILE_COUNT; i++)
        CHECK(file_present(dir, bd_test_run_files[i]));
    char path[1024];
    snprintf(path, sizeof path, "%s/summary.json", dir);
    cJSON *s = read_json(path);
    CHECK(s != NULL);
    const char *top[] = {"model", "duration_s", "time_step_s", "steps", "nodes",
                         "belt_length_m", "wall_time_s", "tension", "probes", "pulleys",
                         "energy", "warnings"};
    for (int i = 0; i < 12; i++)
        CHECK(cJSON_GetObjectItemCaseSensitive(s, top[i]) != NULL);

    /* the belt runs at the drive's speed */
    double v_carry = num(s, "probes", "carry", "speed_final_mps");
    double v_return = num(s, "probes", "return", "speed_final_mps");
    CHECK_REL(v_carry, 2.0, 0.05);
    CHECK_REL(v_return, 2.0, 0.05);
    CHECK(num(s, "probes", "carry", "tension_max_N") > 0.0);
    /* sample(s) gives where the belt is at the probe: on its path point
     * within the sag between idlers (millimetres here; 5 cm allows for it) */
    bd_probe_state ps;
    CHECK(bd_sim_probe(sim, 0, &ps) == 0);
    CHECK(hypot(ps.belt_x_m - ps.x_m, ps.belt_y_m - ps.y_m) < 0.05);

    /* the drive monitor */
    CHECK(r.drives == 1);
    CHECK(r.tight_max_N > r.slack_min_N);
    CHECK(r.slack_min_N > 0.0);
    CHECK(!r.slipped);
    CHECK(r.torque_max_Nm > 0.0);
    /* the same number: cJSON writes 15 significant digits when they read
     * back within DBL_EPSILON of the value (12446.0409928878 for
     * 12446.040992887798), so equal to the last bit only by chance */
    CHECK_REL(num(s, "pulleys", "head", "tight_tension_max_N"), r.tight_max_N, 1e-14);

    /* the takeup */
    double travel_max = num(s, "pulleys", "tail", "travel_max_m");
    double travel_min = num(s, "pulleys", "tail", "travel_min_m");
    CHECK(travel_max - travel_min > 0.0);
    CHECK(travel_max - travel_min < 0.5);

    /* the energy account */
    double balance = num(s, "energy", "balance_error_rel", NULL);
    CHECK(balance < 0.01);
    printf("%-8s nodes %4.0f  peak %8.1f N  tight %8.1f N  slack %7.1f N  v %.4f/%.4f m/s  "
           "travel %.4f m  balance %.2e\n", formulation, num(s, "nodes", NULL, NULL), r.tension_max_N,
           r.tight_max_N, r.slack_min_N, v_carry, v_return, travel_max - travel_min, balance);
    cJSON_Delete(s);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

int main(void)
{
    char tmpl[] = "/tmp/bd_contract_XXXXXX";
    const char *root = mkdtemp(tmpl);
    CHECK(root != NULL);
    if (!root)
        return bd_test_finish("test_formulation_contract");
    /* each formulation at a mesh typical for it */
    const char *forms[][2] = {
        {"discrete", "0.1"}, {"axial", "1.0"}, {"moving_node", "1.0"}, {"rfe", "0.1"}};
    for (int k = 0; k < 4; k++) {
        char dir[512];
        snprintf(dir, sizeof dir, "%s/%s", root, forms[k][0]);
        contract(forms[k][0], forms[k][1], dir);
        bd_test_remove_run(dir);
    }
    remove(root);
    return bd_test_finish("test_formulation_contract");
}
