/* The boom model loader (model/boom_load.c, boom-format.md).
 *
 * 1. tests/data/boom_ok.yaml (seed 003 §9.2's boom) reads as written, in SI
 *    and rad, with every key it leaves out at boom.h's default.
 * 2. bd_model_is_boom: the boom file yes; a conveyor, a file that is not
 *    there, invalid YAML and a list at the top no.
 * 3. Variations of boom_ok.yaml are refused with their exact line
 *    "FILE:LINE:COL: error: PATH: MESSAGE", that one only (a value that
 *    did not read is not judged again across keys), and nothing left
 *    allocated:
 *    ranges, types, required keys of a cubic profile, friction, the
 *    section count, the luffing cylinder on section 1, the stroke against
 *    the sections and a table against `initial`.
 * 4. What else reads: a stroke table, time_step auto, a luffing table, the
 *    default name from the file's path. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "beltdyn/boom.h"
#include "testlib.h"

#define DEG (3.14159265358979323846 / 180.0)

static char *ok_text;

static void print_lines(const bd_diag *d)
{
    for (int i = 0; i < d->count + d->warning_count; i++)
        fprintf(stderr, "    %s\n", d->lines[i]);
}

static void ok_file(void)
{
    bd_boom_def b;
    bd_diag d;
    bd_diag_init(&d);
    int rc = bd_boom_load(BD_TEST_DATA_DIR "/boom_ok.yaml", &b, &d);
    CHECK(rc == 0 && d.count == 0 && d.warning_count == 0);
    print_lines(&d);
    if (rc != 0) {
        bd_diag_free(&d);
        return;
    }
    CHECK(strcmp(b.name, "boom_ok") == 0);
    CHECK(strcmp(b.source, BD_TEST_DATA_DIR "/boom_ok.yaml") == 0);
    CHECK(b.gravity == 9.81);
    CHECK(b.pivot[0] == 0.0 && b.pivot[1] == 0.0);
    CHECK(b.luffing_angle.n == 1);
    CHECK_ABS(bd_table_eval(&b.luffing_angle, 3.0), 60.0 * DEG, 1e-15);
    CHECK(b.luffing_cylinder.present);
    CHECK(b.luffing_cylinder.base[0] == 0.1 && b.luffing_cylinder.base[1] == 0.05);
    CHECK(b.luffing_cylinder.attach[0] == 7.25 && b.luffing_cylinder.attach[1] == -0.556);
    CHECK(b.luffing_cylinder.stiffness == 1e9);
    CHECK(b.luffing_cylinder.mark.line == 9 && b.luffing_cylinder.mark.column == 3);
    CHECK(b.section_count == 3);
    const double mass[] = {318.86, 304.07, 289.27}, height[] = {0.80, 0.76, 0.72};
    for (int k = 0; k < 3 && b.section_count == 3; k++) {
        const bd_boom_section_def *s = &b.sections[k];
        CHECK(s->length == 10.0 && s->axial_stiffness == 8.53e9);
        CHECK(s->bending_stiffness == 7.22e8);
        CHECK(s->mass_per_length == mass[k] && s->height == height[k]);
        CHECK(s->mark.line == 13 + k && s->mark.column == 7);
    }
    CHECK(b.pads.width == 0.3 && b.pads.stiffness == 1e9 && b.pads.switch_speed == 0.01);
    CHECK(b.pads.mu_static == 0.15 && b.pads.mu_dynamic == 0.10);
    CHECK(b.pads.damping_ratio == 0.2 && b.pads.smoothing == 1e-4);
    CHECK(b.gap == 0.005);
    CHECK(b.stroke.kind == BD_STROKE_CUBIC && b.stroke.initial == 2.0);
    CHECK(b.stroke.v_max == 0.5 && b.stroke.accel_time == 4.0 && b.stroke.hold_time == 8.0);
    CHECK(b.stroke.decel_time == 4.0 && b.stroke.direction == 1 && b.stroke.table.n == 0);
    CHECK(b.stroke.mark.line == 21 && b.stroke.mark.column == 3);
    CHECK(b.synchronized == 1 && b.tip_mass == 25000.0);
    CHECK(b.elements_per_segment == 8 && b.damping_ratio == 0.01);
    CHECK(b.telescopic_cylinder.stiffness == 1e8 && b.telescopic_cylinder.damping_ratio == 0.2);
    CHECK(b.ropes.axial_stiffness == 2e8);
    CHECK(b.simulation.duration == 0.0 && b.simulation.time_step == 0.0);
    CHECK(b.simulation.output_interval == 0.01 && b.simulation.mark.line == 0);
    CHECK(b.mark.line == 6 && b.mark.column == 1);
    bd_boom_def_free(&b);
    CHECK(b.sections == NULL && b.section_count == 0 && b.gravity == 9.81);
    bd_boom_def_free(&b);   /* twice is safe */
    bd_diag_free(&d);
}

static void is_boom(void)
{
    CHECK(bd_model_is_boom(BD_TEST_DATA_DIR "/boom_ok.yaml") == 1);
    CHECK(bd_model_is_boom(BD_TEST_DATA_DIR "/bad_boom_belt.yaml") == 1);
    CHECK(bd_model_is_boom(BD_TEST_DATA_DIR "/load_full.yaml") == 0);
    CHECK(bd_model_is_boom(BD_TEST_DATA_DIR "/load_malformed.yaml") == 0);
    CHECK(bd_model_is_boom(BD_TEST_DATA_DIR "/no_such_boom.yaml") == 0);
    const char *path = "test_boom_load_list.yaml";
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) {
        fputs("- boom\n- {boom: 1}\n", f);
        fclose(f);
        CHECK(bd_model_is_boom(path) == 0);
        remove(path);
    }
}

/* load text as m.yaml; its diagnostics in d (caller frees) */
static int load(const char *text, bd_boom_def *b, bd_diag *d)
{
    bd_diag_init(d);
    return bd_boom_load_string(text, strlen(text), "m.yaml", b, d);
}

/* boom_ok.yaml with `from` replaced by `to`: refused with the one line
 * `want` (no error drawn after it from what did not read) */
static void refused(const char *from, const char *to, const char *want)
{
    char *text = bd_test_replaced(ok_text, from, to);
    CHECK(text != NULL);
    if (!text)
        return;
    bd_boom_def b;
    bd_diag d;
    int rc = load(text, &b, &d);
    int first = d.count == 1 && strcmp(d.lines[0], want) == 0;
    CHECK(rc != 0);
    CHECK(first);
    if (!first) {
        fprintf(stderr, "  want %s\n  got:\n", want);
        print_lines(&d);
    }
    /* refused: nothing left to free */
    CHECK(b.sections == NULL && b.luffing_angle.t == NULL && b.stroke.table.t == NULL);
    CHECK(strcmp(b.source, "m.yaml") == 0);
    bd_boom_def_free(&b);
    bd_diag_free(&d);
    free(text);
}

static const char *const section1 =
    "    - {length: 10, axial_stiffness: 8.53e9, bending_stiffness: 7.22e8, "
    "mass_per_length: 318.86, height: 0.80}\n";
static const char *const cubic_line =
    "    profile: {kind: cubic, v_max: 0.5, accel_time: 4, hold_time: 8, decel_time: 4, "
    "direction: extend}\n";

static void refusals(void)
{
    refused("luffing_angle_deg: 60", "luffing_angle_deg: 95",
            "m.yaml:8:22: error: boom.luffing_angle_deg: expected an angle in (-90, 90] "
            "degrees, got 95");
    refused("luffing_angle_deg: 60", "luffing_angle_deg: [[0, 60], [10, -90]]",
            "m.yaml:8:37: error: boom.luffing_angle_deg[1]: expected an angle in (-90, 90] "
            "degrees, got -90");
    refused("luffing_angle_deg: 60", "luffing_angle_deg: steep",
            "m.yaml:8:22: error: boom.luffing_angle_deg: expected a number, got 'steep'");
    refused("attach: [7.25, -0.556]", "attach: [12, -0.556]",
            "m.yaml:11:13: error: boom.luffing_cylinder.attach: expected s in (0, 10] (along "
            "section 1's axis from the pivot: where section 1 is), got 12");
    refused("attach: [7.25, -0.556]", "attach: 7.25",
            "m.yaml:11:13: error: boom.luffing_cylinder.attach: expected a point [s, n] of "
            "section 1, got 7.25");
    refused("    base: [0.1, 0.05]\n", "",
            "m.yaml:9:3: error: boom.luffing_cylinder: missing required key 'base'");
    refused("  tip_load: {mass: 25000}", "  tip_load: {mass: 25000}\n  elements_per_segment: 2.5",
            "m.yaml:25:25: error: boom.elements_per_segment: expected a whole number in "
            "[1, 200], got 2.5");
    refused("  tip_load: {mass: 25000}", "  tip_load: {mass: 25000}\n  damping_ratio: 1",
            "m.yaml:25:18: error: boom.damping_ratio: expected a number in [0, 1), got 1");
    refused("  tip_load: {mass: 25000}", "  tip_load: {}",
            "m.yaml:24:3: error: boom.tip_load: missing required key 'mass'");
    refused("  tip_load: {mass: 25000}", "  tip_load: {mass: 25000}\n  synchronized: maybe",
            "m.yaml:25:17: error: boom.synchronized: expected true or false, got 'maybe'");
    refused("  tip_load: {mass: 25000}", "  tip_load: {mass: 25000}\n  gap: 0.01\n  gap: 0.02",
            "m.yaml:26:3: error: boom: duplicate key 'gap'");
    refused("dynamic: 0.10", "dynamic: 0.2",
            "m.yaml:19:39: error: boom.pads.friction.dynamic: expected a number <= static "
            "(0.15), got 0.2");
    refused("    switch_speed: 0.01\n", "",
            "m.yaml:16:3: error: boom.pads: missing required key 'switch_speed'");
    refused(", direction: extend}", "}",
            "m.yaml:23:5: error: boom.stroke.profile: missing required key 'direction'");
    refused("direction: extend", "direction: sideways",
            "m.yaml:23:95: error: boom.stroke.profile.direction: expected extend or retract, "
            "got 'sideways'");
    refused("kind: cubic", "kind: quintic",
            "m.yaml:23:21: error: boom.stroke.profile.kind: expected cubic, got 'quintic'");
    refused(cubic_line, "    profile: 8\n",
            "m.yaml:23:14: error: boom.stroke.profile: expected a list of [time, stroke] pairs "
            "or a mapping {kind: cubic, v_max, accel_time, hold_time, decel_time, direction}, "
            "got 8");
    refused(cubic_line, "    profile: [[0, 2], [4, -1]]\n",
            "m.yaml:23:27: error: boom.stroke.profile[1]: expected a value >= 0, got -1");
    refused(cubic_line, "    profile: [[0, 2.000001], [4, 3]]\n",
            "m.yaml:23:14: error: boom.stroke.profile: the table's stroke at t = 0 is 2.000001 "
            "m, not the initial stroke 2 m");
    /* what did not read is not compared with `initial` */
    refused(cubic_line, "    profile: [[0, x], [4, 3]]\n",
            "m.yaml:23:19: error: boom.stroke.profile[0][1]: expected a number, got 'x'");
    refused("    initial: 2.0\n    profile: {kind: cubic, v_max: 0.5, accel_time: 4, hold_time: 8, "
            "decel_time: 4, direction: extend}\n",
            "    initial: -2\n    profile: [[0, 2], [4, 3]]\n",
            "m.yaml:22:14: error: boom.stroke.initial: expected a number >= 0, got -2");
    /* retracting 6 m from 2 m */
    refused("direction: extend", "direction: retract",
            "m.yaml:21:3: error: boom.stroke: the stroke falls to -4 m at t = 16 s, below 0: "
            "section 2 would leave section 1 at its bottom");
    refused("mass_per_length: 304.07", "mass_per_length: 304.07, length: 8",
            "m.yaml:14:97: error: boom.sections[1]: duplicate key 'length'");
    /* the shortest outer section allows the least: section 2 of 8 m */
    refused("{length: 10, axial_stiffness: 8.53e9, bending_stiffness: 7.22e8, "
            "mass_per_length: 304.07",
            "{length: 8, axial_stiffness: 8.53e9, bending_stiffness: 7.22e8, "
            "mass_per_length: 304.07",
            "m.yaml:21:3: error: boom.stroke: the stroke reaches 8 m at t = 16 s, beyond the "
            "7.7 m that section 2 allows section 3 (its length 8 m less the pad width 0.3 m)");
    refused("{length: 10, axial_stiffness: 8.53e9, bending_stiffness: 7.22e8, "
            "mass_per_length: 318.86",
            "{length: 10, axial_stiffness: 8.53e9, mass_per_length: 318.86",
            "m.yaml:13:7: error: boom.sections[0]: missing required key 'bending_stiffness'");
    refused("name: boom_ok", "name: boom_ok\ngravity: -1",
            "m.yaml:6:10: error: gravity: expected a number >= 0, got -1");
    refused("name: boom_ok", "name: boom_ok\nsimulation: {time_step: 0}",
            "m.yaml:6:25: error: simulation.time_step: expected auto or a number > 0, got 0");
    refused("name: boom_ok", "name: boom_ok\npulleys: []",
            "m.yaml:6:1: error: pulleys: a boom model has no belt, pulleys or profile");
    refused("  tip_load: {mass: 25000}", "  tip_load: {mass: 25000}\n---\nname: two",
            "m.yaml:26:1: error: expected one YAML document, found another");

    /* 17 sections */
    size_t n = strlen(section1) * 17 + 1;
    char *many = malloc(n);
    CHECK(many != NULL);
    if (many) {
        many[0] = '\0';
        for (int k = 0; k < 17; k++)
            strcat(many, section1);
        char *from = malloc(strlen(section1) * 3 + 1);
        const char *at = strstr(ok_text, section1);
        CHECK(from != NULL && at != NULL);
        if (from && at) {
            memcpy(from, at, strlen(section1) * 3);
            from[strlen(section1) * 3] = '\0';
            refused(from, many,
                    "m.yaml:13:5: error: boom.sections: expected a list of at most 16 entries, "
                    "got 17");
        }
        free(from);
        free(many);
    }
}

/* boom_ok.yaml with `from` replaced by `to`, loaded: 0 when it reads */
static int accepted(const char *from, const char *to, bd_boom_def *b, const char *path)
{
    char *text = bd_test_replaced(ok_text, from, to);
    bd_diag d;
    CHECK(text != NULL);
    if (!text) {
        bd_boom_def_init(b);
        return 1;
    }
    bd_diag_init(&d);
    int rc = bd_boom_load_string(text, strlen(text), path, b, &d);
    CHECK(rc == 0);
    print_lines(&d);
    bd_diag_free(&d);
    free(text);
    return rc;
}

static void variations(void)
{
    bd_boom_def b;
    if (accepted(cubic_line, "    profile: [[0, 2], [4, 3], [12, 9.7]]\n", &b, "a/b/tele.yaml")
        == 0) {
        CHECK(b.stroke.kind == BD_STROKE_TABLE && b.stroke.table.n == 3);
        CHECK(b.stroke.table.t[2] == 12.0 && b.stroke.table.v[2] == 9.7);
    }
    bd_boom_def_free(&b);
    if (accepted("name: boom_ok\n", "", &b, "a/b/tele.yaml") == 0)
        CHECK(strcmp(b.name, "tele") == 0);
    bd_boom_def_free(&b);
    if (accepted("name: boom_ok", "gravity: 0\nsimulation: {duration: 30, time_step: auto, "
                 "output_interval: 0.05}", &b, "x.yaml") == 0) {
        CHECK(b.gravity == 0.0 && b.simulation.duration == 30.0);
        CHECK(b.simulation.time_step == 0.0 && b.simulation.output_interval == 0.05);
        CHECK(b.simulation.mark.line == 6 && b.simulation.time_step_mark.line == 6);
        CHECK(strcmp(b.name, "x") == 0);
    }
    bd_boom_def_free(&b);
    if (accepted("luffing_angle_deg: 60", "luffing_angle_deg: [[0, 30], [20, 90]]", &b,
                 "x.yaml") == 0) {
        CHECK(b.luffing_angle.n == 2);
        CHECK_ABS(bd_table_eval(&b.luffing_angle, 10.0), 60.0 * DEG, 1e-15);
    }
    bd_boom_def_free(&b);
    if (accepted("  tip_load: {mass: 25000}",
                 "  synchronized: false\n  elements_per_segment: 200\n  damping_ratio: 0\n"
                 "  gap: 0\n  telescopic_cylinder: {stiffness: 5e7, damping_ratio: 0.5}\n"
                 "  ropes: {axial_stiffness: 1e8}",
                 &b, "x.yaml") == 0) {
        CHECK(b.synchronized == 0 && b.elements_per_segment == 200 && b.damping_ratio == 0.0);
        CHECK(b.gap == 0.0 && b.tip_mass == 0.0);
        CHECK(b.telescopic_cylinder.stiffness == 5e7 && b.telescopic_cylinder.damping_ratio == 0.5);
        CHECK(b.ropes.axial_stiffness == 1e8);
    }
    bd_boom_def_free(&b);
    if (accepted("pivot: [0, 0]", "pivot: [1.5, -2]", &b, "x.yaml") == 0)
        CHECK(b.pivot[0] == 1.5 && b.pivot[1] == -2.0);
    bd_boom_def_free(&b);
    /* no luffing cylinder: the pivot holds the angle */
    if (accepted("  luffing_cylinder:\n    base: [0.1, 0.05]\n    attach: [7.25, -0.556]\n", "",
                 &b, "x.yaml") == 0)
        CHECK(!b.luffing_cylinder.present && b.luffing_cylinder.stiffness == 1e9);
    bd_boom_def_free(&b);
}

static void defaults(void)
{
    bd_boom_def b;
    bd_boom_def_init(&b);
    CHECK(b.gravity == 9.81 && b.pivot[0] == 0.0 && b.pivot[1] == 0.0 && b.gap == 0.005);
    CHECK(b.synchronized == 1 && b.elements_per_segment == 8 && b.damping_ratio == 0.01);
    CHECK(b.pads.damping_ratio == 0.2 && b.pads.smoothing == 1e-4);
    CHECK(b.luffing_cylinder.stiffness == 1e9 && !b.luffing_cylinder.present);
    CHECK(b.telescopic_cylinder.stiffness == 1e8 && b.telescopic_cylinder.damping_ratio == 0.2);
    CHECK(b.ropes.axial_stiffness == 2e8 && b.stroke.direction == 1);
    CHECK(b.simulation.duration == 0.0 && b.simulation.time_step == 0.0);
    CHECK(b.simulation.output_interval == 0.01 && b.tip_mass == 0.0);
    bd_boom_def_free(&b);
}

int main(void)
{
    ok_text = bd_test_read_data("boom_ok.yaml");
    if (!ok_text)
        return bd_test_finish("boom_load");
    defaults();
    ok_file();
    is_boom();
    refusals();
    variations();
    free(ok_text);
    return bd_test_finish("boom_load");
}
