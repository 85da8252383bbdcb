/* model loader: defaults, derived values, tables, and one error line with
 * the right FILE:LINE:COL and key path for each class of bad input */
#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "testlib.h"

#include <math.h>
#include <string.h>

/* a minimal valid model; lines 1-4, so appended text starts at line 5 */
#define BASE \
    "belt: {mass_per_length: 10, axial_stiffness: 1e6}\n" \
    "pulleys:\n" \
    "  - {name: a, x: 0, y: 0, radius: 0.5, wrap: ccw}\n" \
    "  - {name: b, x: 10, y: 0, radius: 0.5, wrap: ccw}\n"

static int load(const char *text, bd_model_def *m, bd_diag *d)
{
    bd_diag_init(d);
    return bd_model_load_string(text, strlen(text), "dir/t.yaml", m, d);
}

static int has_line(const bd_diag *d, const char *want)
{
    for (int i = 0; i < d->count + d->warning_count; i++)
        if (strcmp(d->lines[i], want) == 0)
            return 1;
    fprintf(stderr, "missing diagnostic: %s\n  got:\n", want);
    for (int i = 0; i < d->count + d->warning_count; i++)
        fprintf(stderr, "    %s\n", d->lines[i]);
    return 0;
}

/* text must fail with exactly `errors` errors, one of them `want` */
static void expect_error(const char *text, int errors, const char *want)
{
    bd_model_def m;
    bd_diag d;
    int rc = load(text, &m, &d);
    CHECK(rc != 0);
    CHECK(d.count == errors);
    if (d.count != errors)
        fprintf(stderr, "  (%d errors, want %d) for: %s\n", d.count, errors, want);
    CHECK(has_line(&d, want));
    /* nothing left to free, and freeing is safe */
    CHECK(m.pulleys == NULL && m.pulley_count == 0 && m.simulation.probes == NULL);
    bd_model_def_free(&m);
    bd_model_def_free(&m);
    bd_diag_free(&d);
}

static void test_full_file(void)
{
    bd_model_def m;
    bd_diag d;
    const bd_pulley_def *head, *tu, *tail;
    bd_diag_init(&d);
    int rc = bd_model_load(BD_TEST_DATA_DIR "/load_full.yaml", &m, &d);
    CHECK(rc == 0);
    CHECK(d.count == 0);
    CHECK(strcmp(m.name, "full test conveyor") == 0);
    CHECK(strcmp(m.source, BD_TEST_DATA_DIR "/load_full.yaml") == 0);
    /* belt: EA and EI derived from modulus, thickness, width */
    CHECK_REL(m.belt.axial_stiffness, 2.0e8 * 0.015 * 1.2, 1e-12);
    CHECK_REL(m.belt.bending_stiffness, 2.0e8 * 1.2 * 0.015 * 0.015 * 0.015 / 12.0, 1e-12);
    CHECK_REL(m.belt.rated_tension, 1.5e6, 1e-12);
    CHECK(m.belt.formulation == BD_FORMULATION_AXIAL);
    CHECK(m.belt.mark.line == 4 && m.belt.mark.column == 1);
    /* pulleys */
    CHECK(m.pulley_count == 3);
    if (m.pulley_count != 3)
        return;
    head = &m.pulleys[0];
    tu = &m.pulleys[1];
    tail = &m.pulleys[2];
    CHECK(head->wrap == -1 && tu->wrap == 1 && tail->wrap == -1);
    CHECK_REL(head->inertia, 800 * 0.5 * 0.5 / 2, 1e-12);
    CHECK_REL(tu->inertia, 12, 1e-12);
    CHECK(tail->inertia == 0.0);
    CHECK_REL(head->friction.mu_static, 0.4, 1e-12);
    CHECK_REL(head->friction.mu_dynamic, 0.35, 1e-12);
    CHECK_REL(tail->friction.mu_static, 0.35, 1e-12);
    CHECK_REL(tail->friction.mu_dynamic, 0.30, 1e-12);
    CHECK(bd_model_find_pulley(&m, "tail") == 2 && bd_model_find_pulley(&m, "nope") == -1);
    /* drive */
    CHECK(head->has_drive && !head->has_takeup && !tail->has_drive);
    CHECK(head->drive.control == BD_CONTROL_SPEED);
    CHECK_REL(head->drive.speed, 4, 1e-12);
    CHECK(head->drive.curve == BD_CURVE_HARRISON);
    CHECK_REL(head->drive.start_time, 20, 1e-12);
    CHECK_REL(head->drive.start_delay, 2, 1e-12);
    CHECK_REL(head->drive.creep_speed, 0.2, 1e-12);
    CHECK_REL(head->drive.max_torque, 50000, 1e-12);
    CHECK(head->drive.stop_mode == BD_STOP_RAMP);
    CHECK_REL(head->drive.stop_at, 60, 1e-12);
    CHECK_REL(head->drive.stop_time, 10, 1e-12);
    CHECK(head->drive.has_transmission && head->drive.transmission.v_belt == 1);
    CHECK_REL(head->drive.transmission.sheave_angle, 34 * 3.14159265358979323846 / 180, 1e-12);
    CHECK_REL(head->drive.transmission.friction, 0.5, 1e-12);
    CHECK_REL(head->drive.transmission.span_stiffness, 1e6, 1e-12);
    CHECK(head->drive.mark.line == 20);
    /* takeups: gravity force = mass*g, axis normalised, force table */
    CHECK(tu->has_takeup && tu->takeup.type == BD_TAKEUP_GRAVITY);
    CHECK(tu->takeup.force.n == 1);
    CHECK_REL(bd_table_eval(&tu->takeup.force, 3.0), 1000 * 9.81, 1e-12);
    CHECK_REL(tu->takeup.axis[0], 0.6, 1e-12);
    CHECK_REL(tu->takeup.axis[1], -0.8, 1e-12);
    CHECK(tu->takeup.has_travel && tu->takeup.travel_min == -1 && tu->takeup.travel_max == 2);
    CHECK(tail->takeup.type == BD_TAKEUP_CONSTANT_FORCE && tail->takeup.force.n == 2);
    CHECK_REL(bd_table_eval(&tail->takeup.force, 2.5), 15000, 1e-12);
    CHECK_REL(bd_table_eval(&tail->takeup.force, 10), 20000, 1e-12);
    CHECK_REL(bd_table_eval(&tail->takeup.force, -1), 10000, 1e-12);
    CHECK(tail->takeup.axis[0] == -1.0 && !tail->takeup.has_travel);
    /* idlers */
    CHECK(m.idler_set_count == 2);
    CHECK(m.idler_sets[0].span == 2 && m.idler_sets[1].span == 0);
    CHECK_REL(m.idler_sets[0].radius, 0.0635, 1e-12);
    CHECK_REL(m.idler_sets[0].inertia, 0.01, 1e-12);
    CHECK_REL(m.idler_sets[0].rotating_mass, 25, 1e-12);
    CHECK_REL(m.idler_sets[0].friction.mu_dynamic, 0.4, 1e-12);
    CHECK_REL(m.idler_sets[1].friction.mu_static, 0.6, 1e-12);
    CHECK(m.idler_sets[1].mark.line == 57);
    /* material: feed defaults to the first span (in travel order) with
     * idlers, discharge to the next pulley */
    CHECK(m.material.present);
    CHECK(m.material.feed_span == 0 && m.material.feed_at == 0.0);
    CHECK(m.material.discharge == 1);
    CHECK(m.material.feeding == 0 && m.material.initially_loaded == 1);
    /* design */
    CHECK(m.design.present && m.design.standard == BD_STANDARD_CEMA);
    CHECK_REL(m.design.f, 0.025, 1e-12);
    CHECK_REL(m.design.C, 1.5, 1e-12);
    CHECK_REL(m.design.cema.Kt, 1.1, 1e-12);
    CHECK(m.design.cema.Ai == 0.0);
    CHECK_REL(m.design.sag_ratio, 0.01, 1e-12);
    /* simulation */
    CHECK_REL(m.simulation.duration, 30, 1e-12);
    CHECK_REL(m.simulation.time_step, 1e-4, 1e-12);
    CHECK(m.simulation.mark.line == 66 && m.simulation.time_step_mark.line == 68);
    CHECK(m.simulation.time_step_mark.column == 14);
    CHECK_REL(m.simulation.output_interval, 0.01, 1e-12);
    CHECK(m.simulation.initial_state == BD_INITIAL_REST && m.simulation.stabilize == 1);
    CHECK(m.simulation.probe_count == 2);
    if (m.simulation.probe_count == 2) {
        CHECK(strcmp(m.simulation.probes[1].name, "p2") == 0);
        CHECK(m.simulation.probes[0].span == 2 && m.simulation.probes[1].span == 0);
        CHECK(m.simulation.probes[0].at == 0.5);
    }
    bd_model_def_free(&m);
    CHECK(m.pulleys == NULL && m.pulley_count == 0);
    bd_diag_free(&d);
}

static void test_defaults(void)
{
    bd_model_def m;
    bd_diag d;
    const char *text = BASE
        "material: {mass_per_length: 50, feed: {span: b, at: 0.25}}\n"
        "design: {C: auto}\n"
        "simulation: {time_step: auto}\n";
    int rc = load(text, &m, &d);
    CHECK(rc == 0 && d.count == 0);
    CHECK(strcmp(m.name, "t") == 0);
    CHECK(m.gravity == 9.81);
    CHECK(m.belt.axial_stiffness == 1e6 && m.belt.bending_stiffness == 0.0);
    CHECK(m.belt.formulation == BD_FORMULATION_DISCRETE && m.belt.element_length == 0.0);
    CHECK(m.pulley_count == 2 && m.idler_set_count == 0 && m.idler_sets == NULL);
    if (m.pulley_count == 2) {
        CHECK(m.pulleys[1].wrap == 1 && m.pulleys[1].mass == 0.0 && m.pulleys[1].inertia == 0.0);
        CHECK(!m.pulleys[0].has_drive && !m.pulleys[0].has_takeup);
        CHECK(m.pulleys[0].mark.line == 3 && m.pulleys[0].mark.column == 5);
    }
    CHECK(m.material.feed_span == 1 && m.material.feed_at == 0.25);
    CHECK(m.material.discharge == 0);  /* the next pulley after b is a */
    CHECK(m.design.present && m.design.C == 0.0 && m.design.standard == BD_STANDARD_DIN22101);
    CHECK_REL(m.design.f, 0.020, 1e-12);
    CHECK(m.simulation.time_step == 0.0 && m.simulation.duration == 10.0);
    CHECK(m.simulation.initial_state == BD_INITIAL_STATIC && !m.simulation.stabilize);
    bd_model_def_free(&m);
    bd_diag_free(&d);

    /* the default functions themselves */
    bd_drive_def dr = bd_drive_default();
    CHECK(dr.curve == BD_CURVE_SCURVE && dr.start_time == 10.0 && isinf(dr.max_torque));
    bd_takeup_def tk = bd_takeup_default();
    CHECK(tk.axis[0] == 0.0 && tk.axis[1] == -1.0 && tk.force.n == 0);
    bd_idler_set_def id = bd_idler_set_default();
    CHECK(id.radius == 0.0635 && id.inertia == 0.01 && id.friction.mu_static == 0.5);
    bd_design_def de = bd_design_default();
    CHECK(de.f == 0.020 && de.C == 0.0 && de.sag_ratio == 0.01 && de.cema.Kt == 1.0);

    /* no idlers: material fed at the start of span 0, discharged at pulley 1;
     * a speed drive with minimal keys; a torque table */
    text = BASE
        "  - name: c\n"
        "    x: 5\n"
        "    y: -3\n"
        "    radius: 0.3\n"
        "    wrap: cw\n"
        "    mass: 40\n"
        "    drive: {control: torque, torque: [[0, 0], [2, 1000]]}\n"
        "material: {mass_per_length: 50}\n";
    rc = load(text, &m, &d);
    CHECK(rc == 0 && d.count == 0);
    CHECK(m.material.feed_span == 0 && m.material.discharge == 1);
    if (m.pulley_count == 3) {
        const bd_drive_def *dv = &m.pulleys[2].drive;
        CHECK(m.pulleys[2].wrap == -1);
        CHECK_REL(m.pulleys[2].inertia, 40 * 0.3 * 0.3 / 2, 1e-12);
        CHECK(dv->control == BD_CONTROL_TORQUE && dv->torque.n == 2);
        CHECK_REL(bd_table_eval(&dv->torque, 0.5), 250, 1e-12);
        CHECK(dv->curve == BD_CURVE_SCURVE && isinf(dv->max_torque));
    }
    bd_model_def_free(&m);
    bd_diag_free(&d);
}

static void test_table_eval(void)
{
    double t[3] = {0, 1, 3}, v[3] = {10, 20, 0};
    bd_table empty = {0, NULL, NULL}, one = {1, t, v}, three = {3, t, v};
    CHECK(bd_table_eval(&empty, 1.0) == 0.0);
    CHECK(bd_table_eval(&one, -5.0) == 10.0 && bd_table_eval(&one, 5.0) == 10.0);
    CHECK_REL(bd_table_eval(&three, 0.5), 15, 1e-12);
    CHECK_REL(bd_table_eval(&three, 2.0), 10, 1e-12);
    CHECK(bd_table_eval(&three, 3.0) == 0.0 && bd_table_eval(&three, 9.0) == 0.0);
    CHECK(bd_table_eval(&three, -1.0) == 10.0);
}

static void test_diag_format(void)
{
    bd_diag d;
    bd_diag_init(&d);
    for (int i = 0; i < 40; i++)
        bd_diag_error(&d, "m.yaml", (bd_mark){3, 7}, "x: %d", i);
    bd_diag_warning(&d, "m.yaml", (bd_mark){1, 2}, "careful");
    CHECK(d.count == 40 && d.warning_count == 1);
    CHECK(strcmp(d.lines[39], "m.yaml:3:7: error: x: 39") == 0);
    CHECK(strcmp(d.lines[40], "m.yaml:1:2: warning: careful") == 0);
    bd_diag_free(&d);
    CHECK(d.count == 0 && d.lines == NULL);
}

static void test_errors(void)
{
    bd_model_def m;
    bd_diag d;

    /* malformed YAML: one error at the parser's mark */
    bd_diag_init(&d);
    CHECK(bd_model_load(BD_TEST_DATA_DIR "/load_malformed.yaml", &m, &d) != 0);
    CHECK(d.count == 1);
    CHECK(has_line(&d, BD_TEST_DATA_DIR "/load_malformed.yaml:4:8: error: invalid YAML: "
                       "did not find expected ',' or ']' (while parsing a flow sequence)"));
    bd_model_def_free(&m);
    bd_diag_free(&d);

    /* a file that does not exist */
    bd_diag_init(&d);
    CHECK(bd_model_load(BD_TEST_DATA_DIR "/load_no_such_file.yaml", &m, &d) != 0 && d.count == 1);
    bd_diag_free(&d);

    /* unknown key, nested */
    expect_error(BASE "  - name: c\n    x: 1\n    y: 1\n    radius: 1\n    wrap: cw\n"
                      "    drive: {control: speed, sped: 3}\n",
                 2, "dir/t.yaml:10:29: error: pulleys[2].drive: unknown key 'sped'");
    /* (the second error: speed is then missing for control: speed) */
    expect_error(BASE "  - name: c\n    x: 1\n    y: 1\n    radius: 1\n    wrap: cw\n"
                      "    drive: {control: speed}\n",
                 1, "dir/t.yaml:10:5: error: pulleys[2].drive: missing required key 'speed' "
                    "(control: speed)");
    expect_error(BASE "simulaton: {duration: 3}\n", 1, "dir/t.yaml:5:1: error: unknown key 'simulaton'");

    /* wrong types */
    expect_error(BASE "gravity: true\n", 1, "dir/t.yaml:5:10: error: gravity: expected a number >= 0, got 'true'");
    expect_error(BASE "design: {f: \"0.02\"}\n", 1,
                 "dir/t.yaml:5:13: error: design.f: expected a number >= 0, got '0.02'");
    expect_error("belt: [1, 2]\n"
                 "pulleys:\n"
                 "  - {name: a, x: 0, y: 0, radius: 0.5, wrap: ccw}\n"
                 "  - {name: b, x: 10, y: 0, radius: 0.5, wrap: ccw}\n",
                 1, "dir/t.yaml:1:7: error: belt: expected a mapping, got a list");
    expect_error(BASE "idlers: {span: a, spacing: 1}\n", 1,
                 "dir/t.yaml:5:9: error: idlers: expected a list, got a mapping");
    expect_error(BASE "simulation: {stabilize: 3}\n", 1,
                 "dir/t.yaml:5:25: error: simulation.stabilize: expected true or false, got 3");

    /* missing required key, reported at the parent's key */
    expect_error("name: x\n"
                 "belt:\n"
                 "  axial_stiffness: 1e6\n"
                 "pulleys:\n"
                 "  - {name: a, x: 0, y: 0, radius: 0.5, wrap: ccw}\n"
                 "  - {name: b, x: 10, y: 0, radius: 0.5, wrap: ccw}\n",
                 1, "dir/t.yaml:2:1: error: belt: missing required key 'mass_per_length'");
    expect_error(BASE "  - {name: c, x: 0, radius: 0.5, wrap: ccw}\n", 1,
                 "dir/t.yaml:5:5: error: pulleys[2]: missing required key 'y'");
    expect_error("belt: {mass_per_length: 10, axial_stiffness: 1e6}\n", 1,
                 "dir/t.yaml:1:1: error: missing required key 'pulleys' (or 'profile')");

    /* out of range */
    expect_error("belt: {mass_per_length: 10, axial_stiffness: 1e6}\n"
                 "pulleys:\n"
                 "  - {name: a, x: 0, y: 0, radius: 0.5, wrap: ccw}\n"
                 "  - {name: b, x: 10, y: 0, radius: -0.5, wrap: ccw}\n",
                 1, "dir/t.yaml:4:36: error: pulleys[1].radius: expected a number > 0, got -0.5");
    expect_error("belt: {mass_per_length: 10, axial_stiffness: 1e6}\n"
                 "pulleys:\n"
                 "  - {name: a, x: 0, y: 0, radius: 0.5, wrap: ccw}\n",
                 1, "dir/t.yaml:3:3: error: pulleys: expected a list of at least 2 entries, got 1");
    expect_error(BASE "  - {name: c, x: 0, y: 5, radius: 0.5, wrap: clockwise}\n", 1,
                 "dir/t.yaml:5:46: error: pulleys[2].wrap: expected cw or ccw, got 'clockwise'");
    expect_error(BASE "  - {name: a, x: 0, y: 5, radius: 0.5, wrap: cw}\n", 1,
                 "dir/t.yaml:5:12: error: pulleys[2].name: duplicate name 'a' (already used by entry 0)");
    expect_error(BASE "idlers:\n  - {span: a, spacing: 1}\n  - {span: z, spacing: 1}\n", 1,
                 "dir/t.yaml:7:12: error: idlers[1].span: unknown pulley 'z'");
    expect_error(BASE "simulation:\n  probes:\n    - {name: p, span: q, at: 0.5}\n", 1,
                 "dir/t.yaml:7:23: error: simulation.probes[0].span: unknown pulley 'q'");
    expect_error(BASE "simulation:\n  probes:\n    - {name: p, span: a, at: 1.5}\n"
                      "    - {name: p, span: b, at: 0}\n", 2,
                 "dir/t.yaml:8:14: error: simulation.probes[1].name: duplicate name 'p' (already used by entry 0)");
    expect_error(BASE "design: {C: 0.9}\n", 1,
                 "dir/t.yaml:5:13: error: design.C: expected auto or a number >= 1, got 0.9");
    expect_error(BASE "design: {standard: din2210}\n", 1,
                 "dir/t.yaml:5:20: error: design.standard: expected din22101, iso5048 or cema, got 'din2210'");
    expect_error(BASE "design: {f: -0.01}\n", 1,
                 "dir/t.yaml:5:13: error: design.f: expected a number >= 0, got -0.01");
    expect_error(BASE "simulation: {time_step: 0}\n", 1,
                 "dir/t.yaml:5:25: error: simulation.time_step: expected auto or a number > 0, got 0");

    /* EA: both ways, or neither */
    expect_error("belt: {mass_per_length: 10, axial_stiffness: 1e6, modulus: 1e8, thickness: 0.01, width: 1}\n"
                 "pulleys:\n"
                 "  - {name: a, x: 0, y: 0, radius: 0.5, wrap: ccw}\n"
                 "  - {name: b, x: 10, y: 0, radius: 0.5, wrap: ccw}\n",
                 1, "dir/t.yaml:1:46: error: belt: give either axial_stiffness or modulus, "
                    "thickness and width, not both");
    expect_error("belt: {mass_per_length: 10, width: 1}\n"
                 "pulleys:\n"
                 "  - {name: a, x: 0, y: 0, radius: 0.5, wrap: ccw}\n"
                 "  - {name: b, x: 10, y: 0, radius: 0.5, wrap: ccw}\n",
                 1, "dir/t.yaml:1:1: error: belt: missing required key 'axial_stiffness' "
                    "(or modulus, thickness and width)");

    /* duplicate key, friction order, takeup force and axis, table order */
    expect_error(BASE "gravity: 9\ngravity: 10\n", 1, "dir/t.yaml:6:1: error: duplicate key 'gravity'");
    expect_error(BASE "  - {name: c, x: 0, y: 5, radius: 0.5, wrap: cw, friction: {static: 0.2, dynamic: 0.3}}\n",
                 1, "dir/t.yaml:5:83: error: pulleys[2].friction.dynamic: expected a number <= static (0.2), got 0.3");
    expect_error(BASE "  - {name: c, x: 0, y: 5, radius: 0.5, wrap: cw, takeup: {type: constant_force, axis: [0, 0]}}\n",
                 2, "dir/t.yaml:5:87: error: pulleys[2].takeup.axis: expected a non-zero vector, got [0, 0]");
    expect_error(BASE "  - {name: c, x: 0, y: 5, radius: 0.5, wrap: cw, takeup: {type: constant_force, axis: [0, 0]}}\n",
                 2, "dir/t.yaml:5:50: error: pulleys[2].takeup: missing required key 'force' (type: constant_force)");
    expect_error(BASE "  - {name: c, x: 0, y: 5, radius: 0.5, wrap: cw, takeup: {type: constant_force, force: [[0, 1], [0, 2]]}}\n",
                 1, "dir/t.yaml:5:98: error: pulleys[2].takeup.force[1]: expected a time > 0 (times must increase), got 0");

    /* every problem of a file is reported, not just the first */
    expect_error("belt: {mass_per_length: -1, axial_stiffness: 1e6}\n"
                 "pulleys:\n"
                 "  - {name: a, x: 0, y: 0, radius: 0, wrap: ccw}\n"
                 "  - {name: b, x: 10, y: zero, radius: 0.5, wrap: up}\n"
                 "design: {standard: x, f: -1, C: 0}\n",
                 7, "dir/t.yaml:4:25: error: pulleys[1].y: expected a number, got 'zero'");

    /* an empty file */
    expect_error("", 1, "dir/t.yaml:1:1: error: empty model: expected a mapping with belt and pulleys");
}

/* a pulley standing across a span it does not take part in: the belt
 * would run through it; refused when the belt is built, on either belt,
 * at the pulley's mark (a snub across the carry strand laid the discrete
 * belt through it, and its first step diverged) */
static void test_span_through_pulley(void)
{
    static const char *text =
        "belt: {mass_per_length: 10, axial_stiffness: 1e6, formulation: %s}\n"
        "pulleys:\n"
        "  - {name: a, x: 0, y: 0, radius: 0.5, wrap: ccw}\n"
        "  - {name: b, x: 10, y: 0, radius: 0.5, wrap: ccw}\n"
        "  - {name: c, x: 5, y: -6, radius: 0.5, wrap: ccw}\n"
        "  - {name: stray, x: 5, y: -0.8, radius: 0.4, wrap: ccw}\n";
    const char *forms[] = {"discrete", "axial"};
    for (int f = 0; f < 2; f++) {
        char buf[512];
        snprintf(buf, sizeof buf, text, forms[f]);
        bd_model_def m;
        bd_diag d;
        CHECK(load(buf, &m, &d) == 0);
        bd_diag_free(&d);
        bd_diag_init(&d);
        bd_sim *sim = NULL;
        CHECK(bd_sim_create(&m, &sim, &d) != 0);
        CHECK(has_line(&d, "dir/t.yaml:6:5: error: pulleys[3] 'stray': the belt span from 'a' "
                           "to 'b' runs through it (0.3 m from its centre, radius 0.4 m); move "
                           "the pulley or change a wrap direction"));
        bd_sim_free(sim);
        bd_diag_free(&d);
        bd_model_def_free(&m);
    }
}

int main(void)
{
    test_span_through_pulley();
    test_table_eval();
    test_diag_format();
    test_full_file();
    test_defaults();
    test_errors();
    return bd_test_finish("test_model_load");
}
