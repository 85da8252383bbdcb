/* model loader: YAML (libyaml document API) -> bd_model_def, validating every
 * key against model-format.md and reporting each problem as
 * "FILE:LINE:COL: error: PATH: MESSAGE" at the offending node.
 *
 * Every mapping is described by a table of fields (model/fields.h, shared
 * with the boom's loader); what a table cannot say (derived values, keys
 * required only in some modes, uniqueness) is done by the table's post
 * function.
 *
 * Choices of this loader where model-format.md is silent:
 * - friction maps need both `static` and `dynamic`;
 * - drive.stop needs `at` and `mode`; `time` is required for mode ramp and
 *   `brake_torque` for mode brake;
 * - drive.transmission requires motor_sheave_radius, pulley_sheave_radius,
 *   pretension and span_stiffness; the optional keys default to belt: flat,
 *   sheave_angle_deg: 38 (a common V-belt groove), friction: 0.5,
 *   belt_mass_per_length: 0 (no centrifugal tension), velocity_threshold:
 *   1e-3 m/s, force_threshold: 1e-3 N, bearing_damping: 0,
 *   center_distance: 3·(motor_sheave_radius + pulley_sheave_radius)
 *   (see bd_drive_default and parts/transmission.c);
 * - pulleys accept velocity_threshold (1e-3 m/s) and force_threshold
 *   (1e-3 N) for the seed-004 law of the axial formulation;
 * - takeup.travel is [min, max] with min <= 0 <= max;
 * - an explicit takeup `force` is accepted for a gravity takeup and
 *   replaces mass*gravity;
 * - probes need all of name, span and at;
 * - gravity must be >= 0. */
#include "beltdyn/model.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "model/fields.h"
#include "model/profile.h"

/* enums are stored through int pointers */
_Static_assert(sizeof(bd_drive_control) == sizeof(int), "enum size");

/* ---- friction ---- */

static void friction_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                          bd_mark at, const char *path, void *base)
{
    const bd_friction *fr = base;
    (void)at;
    bd_fields_check_friction(c, fs, found, path, fr->mu_static, fr->mu_dynamic);
}

static const bd_field friction_fields[] = {
    NONNEG("static", bd_friction, mu_static, REQ),
    NONNEG("dynamic", bd_friction, mu_dynamic, REQ),
};
FIELDSET(friction_fs, friction_fields, friction_post);

/* ---- belt ---- */

static void belt_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                      bd_mark at, const char *path, void *base)
{
    static const char *const ewt[] = {"modulus", "thickness", "width"};
    bd_belt_def *b = base;
    yaml_node_t *ea = bd_fields_got(fs, found, "axial_stiffness");
    int have = 0;
    for (int i = 0; i < 3; i++)
        have += bd_fields_got(fs, found, ewt[i]) != NULL;
    b->mark = at;
    if (ea && (bd_fields_got(fs, found, "modulus") || bd_fields_got(fs, found, "thickness"))) {
        bd_fields_err(c, bd_fields_mark_of(ea), path,
                      "give either axial_stiffness or modulus, thickness and width, not both");
    } else if (!ea && (have == 0 || (have == 1 && bd_fields_got(fs, found, "width")))) {
        bd_fields_err(c, at, path,
                      "missing required key 'axial_stiffness' (or modulus, thickness and width)");
    } else if (!ea) {
        for (int i = 0; i < 3; i++)
            bd_fields_need(c, fs, found, at, path, ewt[i], "EA = modulus*thickness*width");
        b->axial_stiffness = b->modulus * b->thickness * b->width;
    }
    if (have == 3 && !bd_fields_got(fs, found, "bending_stiffness"))
        b->bending_stiffness = b->modulus * b->width * b->thickness * b->thickness * b->thickness / 12.0;
}

static const bd_field topology_fields[] = {
    BOOL("enabled", bd_belt_def, group_sections),
    POS("group_length", bd_belt_def, group_length, 0),
};
FIELDSET(topology_fs, topology_fields, NULL);

static const char *const formulation_names[] = {"discrete", "axial", "moving_node", "rfe", NULL};
static const bd_field belt_fields[] = {
    POS("mass_per_length", bd_belt_def, mass_per_length, REQ),
    POS("axial_stiffness", bd_belt_def, axial_stiffness, 0),
    POS("modulus", bd_belt_def, modulus, 0),
    POS("thickness", bd_belt_def, thickness, 0),
    POS("width", bd_belt_def, width, 0),
    NONNEG("bending_stiffness", bd_belt_def, bending_stiffness, 0),
    NONNEG("damping_ratio", bd_belt_def, damping_ratio, 0),
    POS("rated_tension", bd_belt_def, rated_tension, 0),
    NONNEG("initial_tension", bd_belt_def, initial_tension, 0),
    POS("element_length", bd_belt_def, element_length, 0),
    NUM("wrap_element_angle_deg", bd_belt_def, wrap_element_angle, GT | DEG, 0.0, 90.0),
    POS("span_element_length", bd_belt_def, span_element_length, 0),
    POS("shear_stiffness", bd_belt_def, shear_stiffness, 0),
    SUBMAP("variable_topology", 0, &topology_fs),
    ENUM("formulation", bd_belt_def, formulation, 0, formulation_names, NULL),
};
FIELDSET(belt_fs, belt_fields, belt_post);

/* ---- drive ---- */

static const char *const curve_names[] = {"linear", "harrison", "nordell", "s-curve", NULL};
static const bd_field start_fields[] = {
    ENUM("curve", bd_drive_def, curve, 0, curve_names, NULL),
    POS("time", bd_drive_def, start_time, 0),
    NONNEG("delay", bd_drive_def, start_delay, 0),
    NONNEG("creep_speed", bd_drive_def, creep_speed, 0),
};
FIELDSET(start_fs, start_fields, NULL);

static void stop_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                      bd_mark at, const char *path, void *base)
{
    const bd_drive_def *d = base;
    if (d->stop_mode == BD_STOP_RAMP)
        bd_fields_need(c, fs, found, at, path, "time", "mode: ramp");
    if (d->stop_mode == BD_STOP_BRAKE)
        bd_fields_need(c, fs, found, at, path, "brake_torque", "mode: brake");
}

static const char *const stop_names[] = {"coast", "ramp", "brake", NULL};
static const int stop_vals[] = {BD_STOP_COAST, BD_STOP_RAMP, BD_STOP_BRAKE};
static const bd_field stop_fields[] = {
    NONNEG("at", bd_drive_def, stop_at, REQ),
    ENUM("mode", bd_drive_def, stop_mode, REQ, stop_names, stop_vals),
    POS("time", bd_drive_def, stop_time, 0),
    POS("brake_torque", bd_drive_def, brake_torque, 0),
};
FIELDSET(stop_fs, stop_fields, stop_post);

/* the Kloss curve needs a breakdown torque above the rated one and a rated
 * speed below synchronous (a positive rated slip) */
static void motor_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                       bd_mark at, const char *path, void *base)
{
    (void)fs;
    (void)found;
    const bd_motor_def *m = base;
    if (m->rated_speed_rpm > 0.0 && m->synchronous_speed_rpm > 0.0
        && m->rated_speed_rpm >= m->synchronous_speed_rpm)
        bd_fields_err(c, at, path, "rated_speed_rpm (%g) must be below synchronous_speed_rpm (%g): "
            "an induction motor runs with slip", m->rated_speed_rpm, m->synchronous_speed_rpm);
}

static const bd_field motor_fields[] = {
    POS("rated_power", bd_motor_def, rated_power, REQ),
    POS("rated_speed_rpm", bd_motor_def, rated_speed_rpm, REQ),
    POS("synchronous_speed_rpm", bd_motor_def, synchronous_speed_rpm, REQ),
    NUM("breakdown_torque_ratio", bd_motor_def, breakdown_torque_ratio, REQ | GT, 1.0, INFINITY),
    POS("gear_ratio", bd_motor_def, gear_ratio, REQ),
    NONNEG("start_time", bd_motor_def, start_time, REQ),
};
FIELDSET(motor_fs, motor_fields, motor_post);

static const char *const vbelt_names[] = {"flat", "v", NULL};
static const bd_field transmission_fields[] = {
    ENUM("belt", bd_transmission_def, v_belt, 0, vbelt_names, NULL),
    NUM("sheave_angle_deg", bd_transmission_def, sheave_angle, GT | DEG, 0.0, 180.0),
    POS("motor_sheave_radius", bd_transmission_def, motor_sheave_radius, REQ),
    POS("pulley_sheave_radius", bd_transmission_def, pulley_sheave_radius, REQ),
    NONNEG("friction", bd_transmission_def, friction, 0),
    NONNEG("belt_mass_per_length", bd_transmission_def, belt_mass_per_length, 0),
    POS("pretension", bd_transmission_def, pretension, REQ),
    POS("span_stiffness", bd_transmission_def, span_stiffness, REQ),
    POS("velocity_threshold", bd_transmission_def, velocity_threshold, 0),
    POS("force_threshold", bd_transmission_def, force_threshold, 0),
    NONNEG("bearing_damping", bd_transmission_def, bearing_damping, 0),
    POS("center_distance", bd_transmission_def, center_distance, 0),
};
FIELDSET(transmission_fs, transmission_fields, NULL);

static void drive_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                       bd_mark at, const char *path, void *base)
{
    static const char *const need_key[] = {"speed", "torque", "motor"};
    static const char *const why[] = {"control: speed", "control: torque", "control: motor"};
    bd_drive_def *d = base;
    d->mark = at;
    d->has_transmission = bd_fields_got(fs, found, "transmission") != NULL;
    if (bd_fields_got(fs, found, "control"))
        bd_fields_need(c, fs, found, at, path, need_key[d->control], why[d->control]);
}

static const char *const control_names[] = {"speed", "torque", "motor", NULL};
static const bd_field drive_fields[] = {
    ENUM("control", bd_drive_def, control, REQ, control_names, NULL),
    ANY("speed", bd_drive_def, speed, 0),
    SUBMAP("start", 0, &start_fs),
    POS("max_torque", bd_drive_def, max_torque, 0),
    NONNEG("inertia", bd_drive_def, inertia, 0),
    POS("bandwidth", bd_drive_def, bandwidth, 0),
    TABLE("torque", bd_drive_def, torque, 0, -INFINITY),
    MAP("motor", bd_drive_def, motor, 0, &motor_fs),
    SUBMAP("stop", 0, &stop_fs),
    MAP("transmission", bd_drive_def, transmission, 0, &transmission_fs),
};
FIELDSET(drive_fs, drive_fields, drive_post);

/* ---- takeup ---- */

static void takeup_axis(bd_fields_ctx *c, const bd_field *f, yaml_node_t *v, bd_mark key,
                        const char *path, void *base)
{
    bd_takeup_def *t = base;
    double a[2], len;
    (void)f;
    (void)key;
    if (bd_fields_get_numbers(c, v, path, 2, "a vector [x, y]", a))
        return;
    len = hypot(a[0], a[1]);
    if (len == 0.0) {
        bd_fields_err(c, bd_fields_mark_of(v), path, "expected a non-zero vector, got [0, 0]");
        return;
    }
    t->axis[0] = a[0] / len;
    t->axis[1] = a[1] / len;
}

static void takeup_travel(bd_fields_ctx *c, const bd_field *f, yaml_node_t *v, bd_mark key,
                          const char *path, void *base)
{
    bd_takeup_def *t = base;
    double r[2];
    (void)f;
    (void)key;
    if (bd_fields_get_numbers(c, v, path, 2, "[min, max]", r))
        return;
    if (!(r[0] <= 0.0 && r[1] >= 0.0 && r[0] < r[1])) {
        bd_fields_err(c, bd_fields_mark_of(v), path,
                      "expected [min, max] with min <= 0 <= max, got [%g, %g]", r[0], r[1]);
        return;
    }
    t->has_travel = 1;
    t->travel_min = r[0];
    t->travel_max = r[1];
}

static void takeup_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                        bd_mark at, const char *path, void *base)
{
    bd_takeup_def *t = base;
    t->mark = at;
    if (!bd_fields_got(fs, found, "type") || bd_fields_got(fs, found, "force"))
        return;
    if (t->type == BD_TAKEUP_CONSTANT_FORCE)
        bd_fields_need(c, fs, found, at, path, "force", "type: constant_force");
    else if (t->type == BD_TAKEUP_GRAVITY && bd_fields_table_alloc(&t->force, 1) == 0)
        t->force.v[0] = t->mass * c->m->gravity;
}

static const char *const takeup_names[] = {"gravity", "constant_force", "fixed", NULL};
/* a takeup's own fields, for a pulley's takeup and a profile's (whose
 * bd_profile_takeup holds a bd_takeup_def first) */
#define TAKEUP_BODY_FIELDS                                          \
    ENUM("type", bd_takeup_def, type, REQ, takeup_names, NULL),     \
    NONNEG("mass", bd_takeup_def, mass, 0),                         \
    TABLE("force", bd_takeup_def, force, SCALAR, 0.0),              \
    FN("travel", takeup_travel)

static const bd_field takeup_fields[] = {
    TAKEUP_BODY_FIELDS,
    FN("axis", takeup_axis),
};
FIELDSET(takeup_fs, takeup_fields, takeup_post);

/* ---- pulleys ---- */

/* name unique among the entries before this one */
static void unique_name(bd_fields_ctx *c, yaml_node_t *v, const char *path, const char *name,
                        const char *list, size_t stride, size_t name_off)
{
    char sub[PATH_LEN];
    for (int j = 0; v && j < c->index; j++) {
        if (strcmp(list + (size_t)j * stride + name_off, name) == 0) {
            bd_fields_join(sub, path, "name");
            bd_fields_err(c, bd_fields_mark_of(v), sub,
                          "duplicate name '%s' (already used by entry %d)", name, j);
            return;
        }
    }
}

/* what a pulley and a profile's head or tail share: where it was given,
 * its drive, the inertia of a solid disc unless given */
static void pulley_body_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                             bd_mark at, const char *path, void *base)
{
    bd_pulley_def *p = base;
    (void)c, (void)path;
    p->mark = at;
    p->has_drive = bd_fields_got(fs, found, "drive") != NULL;
    if (!bd_fields_got(fs, found, "inertia"))
        p->inertia = 0.5 * p->mass * p->radius * p->radius;
}

static void pulley_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                        bd_mark at, const char *path, void *base)
{
    bd_pulley_def *p = base;
    pulley_body_post(c, fs, found, at, path, base);
    p->has_takeup = bd_fields_got(fs, found, "takeup") != NULL;
    unique_name(c, bd_fields_got(fs, found, "name"), path, p->name, (const char *)c->m->pulleys,
                sizeof *p, offsetof(bd_pulley_def, name));
}

/* a pulley's body and drive: a pulley entry's keys, and a profile's head
 * and tail (model-format.md) */
#define PULLEY_BODY_FIELDS \
    POS("radius", bd_pulley_def, radius, REQ), \
    NONNEG("mass", bd_pulley_def, mass, 0), \
    NONNEG("inertia", bd_pulley_def, inertia, 0), \
    MAP("friction", bd_pulley_def, friction, 0, &friction_fs), \
    NONNEG("bearing_damping", bd_pulley_def, bearing_damping, 0), \
    POS("velocity_threshold", bd_pulley_def, velocity_threshold, 0), \
    POS("force_threshold", bd_pulley_def, force_threshold, 0), \
    MAP("drive", bd_pulley_def, drive, 0, &drive_fs)

static const char *const wrap_names[] = {"cw", "ccw", NULL};
static const int wrap_vals[] = {-1, 1};
static const bd_field pulley_fields[] = {
    STR("name", bd_pulley_def, name, REQ | NONEMPTY),
    ANY("x", bd_pulley_def, x, REQ),
    ANY("y", bd_pulley_def, y, REQ),
    ENUM("wrap", bd_pulley_def, wrap, REQ, wrap_names, wrap_vals),
    PULLEY_BODY_FIELDS,
    MAP("takeup", bd_pulley_def, takeup, 0, &takeup_fs),
};
FIELDSET(pulley_fs, pulley_fields, pulley_post);

static void init_pulley(void *p)
{
    *(bd_pulley_def *)p = bd_pulley_default();
}

static const bd_listspec pulley_list = {&pulley_fs, sizeof(bd_pulley_def),
                                     offsetof(bd_model_def, pulley_count), init_pulley, 2};

/* ---- idlers ---- */

static void curve_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                       bd_mark at, const char *path, void *base)
{
    bd_idler_set_def *st = base;
    (void)fs, (void)found;
    st->has_curve = 1;
    st->curve_mark = at;
    /* a curve starts and ends on the straight span: the belt leaves and
     * reaches the pulleys along the span's tangent */
    if (!(st->curve_from > 0.0 && st->curve_from < st->curve_to && st->curve_to < 1.0))
        bd_fields_err(c, at, path, "expected 0 < from < to < 1, got from %g, to %g", st->curve_from,
            st->curve_to);
}

static const char *const sense_names[] = {"concave", "convex", NULL};
static const bd_field curve_fields[] = {
    POS("radius", bd_idler_set_def, curve_radius, REQ),
    NUM("from", bd_idler_set_def, curve_from, REQ, 0.0, 1.0),
    NUM("to", bd_idler_set_def, curve_to, REQ, 0.0, 1.0),
    ENUM("sense", bd_idler_set_def, curve_convex, 0, sense_names, NULL),
};
FIELDSET(curve_fs, curve_fields, curve_post);

static void idler_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                       bd_mark at, const char *path, void *base)
{
    bd_idler_set_def *st = base;
    (void)fs, (void)found, (void)path;
    st->mark = at;
    /* curves on one span may not overlap (model-format.md) */
    for (int j = 0; st->has_curve && j < c->index; j++) {
        const bd_idler_set_def *o = &c->m->idler_sets[j];
        if (o->has_curve && o->span == st->span && o->curve_from < st->curve_to
            && st->curve_from < o->curve_to)
            bd_fields_err(c, st->curve_mark, path,
                          "curve: overlaps the curve of idlers[%d] on the same span", j);
    }
}

#define IDLER_FIELDS \
    POS("spacing", bd_idler_set_def, spacing, REQ), \
    POS("radius", bd_idler_set_def, radius, 0), \
    NONNEG("inertia", bd_idler_set_def, inertia, 0), \
    NONNEG("rotating_mass", bd_idler_set_def, rotating_mass, 0), \
    NONNEG("rolling_resistance", bd_idler_set_def, rolling_resistance, 0), \
    MAP("friction", bd_idler_set_def, friction, 0, &friction_fs)

static const bd_field idler_fields[] = {
    SPAN("span", bd_idler_set_def, span, REQ),
    IDLER_FIELDS,
    SUBMAP("curve", 0, &curve_fs),
};
FIELDSET(idler_fs, idler_fields, idler_post);

static void init_idler(void *s)
{
    *(bd_idler_set_def *)s = bd_idler_set_default();
}

static const bd_listspec idler_list = {&idler_fs, sizeof(bd_idler_set_def),
                                    offsetof(bd_model_def, idler_set_count), init_idler, 0};

/* ---- profile (model-format.md: a conveyor given by its route) ---- */

/* an idler set of the profile: its span is the layout's */
static const bd_field profile_idler_fields[] = {IDLER_FIELDS};
FIELDSET(profile_idler_fs, profile_idler_fields, NULL);

static void profile_points(bd_fields_ctx *c, const bd_field *f, yaml_node_t *v, bd_mark key,
                           const char *path, void *base)
{
    bd_profile_def *p = base;
    char sub[PATH_LEN];
    (void)f, (void)key;
    if (!v || v->type != YAML_SEQUENCE_NODE || bd_fields_seq_len(v) < 2) {
        bd_fields_type_error(c, v, path, "a list of at least two [chainage, elevation] points");
        return;
    }
    int n = bd_fields_seq_len(v);
    p->points = calloc((size_t)n, sizeof *p->points);
    p->point_marks = calloc((size_t)n, sizeof *p->point_marks);
    if (!p->points || !p->point_marks) {
        bd_fields_err(c, bd_fields_mark_of(v), path, "out of memory");
        return;
    }
    p->point_count = n;
    for (int i = 0; i < n; i++) {
        yaml_node_t *item = bd_fields_node_at(c, v->data.sequence.items.start[i]);
        bd_fields_join_index(sub, path, i);
        p->point_marks[i] = bd_fields_mark_of(item);
        if (bd_fields_get_numbers(c, item, sub, 2, "a [chainage, elevation] point", p->points[i]))
            continue;
        if (i > 0 && !(p->points[i][0] > p->points[i - 1][0]))
            bd_fields_err(c, bd_fields_mark_of(item), sub, "expected a chainage > %g (chainage "
                "must increase from the tail to the head), got %g", p->points[i - 1][0],
                p->points[i][0]);
    }
}

static void profile_curve_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                               bd_mark at, const char *path, void *base)
{
    (void)c, (void)fs, (void)found, (void)path;
    ((bd_profile_curve *)base)->mark = at;
}

static const bd_field profile_curve_fields[] = {
    NUM("at", bd_profile_curve, at, REQ, 1.0, INFINITY),
    POS("radius", bd_profile_curve, radius, REQ),
};
FIELDSET(profile_curve_fs, profile_curve_fields, profile_curve_post);

static void init_profile_curve(void *p)
{
    memset(p, 0, sizeof(bd_profile_curve));
}

static const bd_listspec profile_curve_list = {&profile_curve_fs, sizeof(bd_profile_curve),
                                            offsetof(bd_profile_def, curve_count),
                                            init_profile_curve, 0};

static const bd_field profile_end_fields[] = {PULLEY_BODY_FIELDS};
FIELDSET(profile_end_fs, profile_end_fields, pulley_body_post);

static const char *const end_names[] = {"tail", "head", NULL};
_Static_assert(offsetof(bd_profile_takeup, t) == 0, "a profile's takeup parses as a takeup");
static const bd_field profile_takeup_fields[] = {
    ENUM("at", bd_profile_takeup, at_head, REQ, end_names, NULL),
    TAKEUP_BODY_FIELDS,
    POS("depth", bd_profile_takeup, depth, 0),
};
FIELDSET(profile_takeup_fs, profile_takeup_fields, takeup_post);

static void profile_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                         bd_mark at, const char *path, void *base)
{
    bd_profile_def *p = base;
    p->mark = at;
    (void)fs, (void)found;
    for (int i = 0; i < p->curve_count; i++) {
        const bd_profile_curve *cv = &p->curves[i];
        char sub[PATH_LEN];
        bd_fields_join(sub, path, "curves");
        if (cv->at != floor(cv->at) || cv->at > p->point_count - 2)
            bd_fields_err(c, cv->mark, sub,
                "[%d].at: expected the index of an inner point, 1 to %d, got %g",
                i, p->point_count - 2, cv->at);
        for (int j = 0; j < i; j++)
            if (p->curves[j].at == cv->at)
                bd_fields_err(c, cv->mark, sub,
                    "[%d].at: point %g already has a curve (curves[%d])", i, cv->at, j);
    }
}

static const bd_field profile_fields[] = {
    FN_REQ("points", profile_points),
    LIST("curves", bd_profile_def, curves, 0, &profile_curve_list),
    MAP("head", bd_profile_def, head, REQ, &profile_end_fs),
    MAP("tail", bd_profile_def, tail, REQ, &profile_end_fs),
    MAP("takeup", bd_profile_def, takeup, REQ, &profile_takeup_fs),
    POS("return_drop", bd_profile_def, return_drop, 0),
    POS("bend_radius", bd_profile_def, bend_radius, 0),
    MAP("carry_idlers", bd_profile_def, carry, REQ, &profile_idler_fs),
    MAP("return_idlers", bd_profile_def, ret, 0, &profile_idler_fs),
};
FIELDSET(profile_fs, profile_fields, profile_post);

static void profile_fn(bd_fields_ctx *c, const bd_field *f, yaml_node_t *v, bd_mark key,
                       const char *path, void *base)
{
    bd_model_def *m = base;
    bd_profile_def p;
    (void)f;
    memset(&p, 0, sizeof p);
    p.head = bd_pulley_default();
    p.tail = bd_pulley_default();
    p.takeup.t = bd_takeup_default();
    p.return_drop = 1.0;
    p.carry = bd_idler_set_default();
    p.ret = bd_idler_set_default();
    p.ret.spacing = 3.0;
    if (m->pulley_count > 0) {
        bd_fields_err(c, key, path, "give either pulleys or profile, not both");
        return;
    }
    int before = c->errors;
    bd_fields_parse_map(c, v, key, path, &profile_fs, &p);
    if (c->errors == before && p.point_count >= 2) {
        if (bd_profile_layout(&p, m, c->diag))
            c->errors++;
    } else {
        bd_profile_free_tables(&p);
    }
    bd_profile_free(&p);
}

/* the top-level idlers: a profile lays out its own (carry_idlers,
 * return_idlers), so both are refused */
static void idlers_fn(bd_fields_ctx *c, const bd_field *f, yaml_node_t *v, bd_mark key,
                      const char *path, void *base)
{
    bd_model_def *m = base;
    (void)f;
    if (m->from_profile) {
        bd_fields_err(c, key, path, "give either idlers or a profile's carry_idlers and "
            "return_idlers, not both");
        return;
    }
    bd_fields_parse_list(c, &idler_list, v, path, base, offsetof(bd_model_def, idler_sets));
}

/* ---- material ---- */

static const bd_field feed_fields[] = {
    SPAN("span", bd_material_def, feed_span, REQ),
    NUM("at", bd_material_def, feed_at, 0, 0.0, 1.0),
};
FIELDSET(feed_fs, feed_fields, NULL);

static void material_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                          bd_mark at, const char *path, void *base)
{
    bd_material_def *mat = base;
    const bd_model_def *m = c->m;
    (void)path;
    mat->present = 1;
    mat->mark = at;
    if (!bd_fields_got(fs, found, "feed")) {
        /* the start of the first span (in travel order) that has idlers */
        mat->feed_span = m->idler_set_count > 0 ? m->idler_sets[0].span : 0;
        mat->feed_at = 0.0;
        for (int i = 1; i < m->idler_set_count; i++)
            if (m->idler_sets[i].span < mat->feed_span)
                mat->feed_span = m->idler_sets[i].span;
    }
    if (!bd_fields_got(fs, found, "discharge") && m->pulley_count > 0)
        mat->discharge = (mat->feed_span + 1) % m->pulley_count;
}

static const bd_field material_fields[] = {
    NONNEG("mass_per_length", bd_material_def, mass_per_length, REQ),
    SUBMAP("feed", 0, &feed_fs),
    SPAN("discharge", bd_material_def, discharge, 0),
    BOOL("initially_loaded", bd_material_def, initially_loaded),
    BOOL("feeding", bd_material_def, feeding),
};
FIELDSET(material_fs, material_fields, material_post);

/* ---- design ---- */

static const bd_field cema_fields[] = {
    POS("Kt", bd_cema_def, Kt, 0),
    NONNEG("Ai", bd_cema_def, Ai, 0),
};
FIELDSET(cema_fs, cema_fields, NULL);

static void skirts_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                        bd_mark at, const char *path, void *base)
{
    (void)c, (void)fs, (void)found, (void)at, (void)path;
    ((bd_skirts_def *)base)->present = 1;
}

static const bd_field skirts_fields[] = {
    POS("width", bd_skirts_def, width, REQ),
    POS("length", bd_skirts_def, length, REQ),
    NONNEG("mu_material", bd_skirts_def, mu_material, REQ),
    POS("mu_belt_material", bd_skirts_def, mu_belt_material, REQ),
};
FIELDSET(skirts_fs, skirts_fields, skirts_post);

static void cleaners_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                          bd_mark at, const char *path, void *base)
{
    bd_cleaners_def *cl = base;
    yaml_node_t *n = bd_fields_got(fs, found, "count");
    char sub[PATH_LEN];
    (void)at;
    cl->present = 1;
    if (n && cl->count != floor(cl->count)) {
        bd_fields_join(sub, path, "count");
        bd_fields_err(c, bd_fields_mark_of(n), sub, "expected a whole number of cleaners, got %g",
                      cl->count);
    }
}

static const bd_field cleaners_fields[] = {
    NUM("count", bd_cleaners_def, count, REQ, 1.0, 1000.0),
    POS("width", bd_cleaners_def, width, REQ),
    POS("thickness", bd_cleaners_def, thickness, REQ),
    POS("pressure", bd_cleaners_def, pressure, REQ),
    NONNEG("mu", bd_cleaners_def, mu, REQ),
    SPAN("pulley", bd_cleaners_def, pulley, 0),
};
FIELDSET(cleaners_fs, cleaners_fields, cleaners_post);

static const bd_field bearing_fields[] = {
    POS("bore", bd_bearing_def, bore, REQ),
    NONNEG("mass", bd_bearing_def, mass, 0),
};
FIELDSET(bearing_fs, bearing_fields, NULL);

/* design.bearings: a mapping from pulley names to {bore, mass}; mass
 * defaults to the pulley's own */
static void bearings_fn(bd_fields_ctx *c, const bd_field *f, yaml_node_t *v, bd_mark key,
                        const char *path, void *base)
{
    bd_design_def *d = base;
    char sub[PATH_LEN];
    (void)f, (void)key;
    if (!v || v->type != YAML_MAPPING_NODE) {
        bd_fields_type_error(c, v, path, "a mapping from pulley names to {bore, mass}");
        return;
    }
    int n = (int)(v->data.mapping.pairs.top - v->data.mapping.pairs.start);
    if (n == 0)
        return;
    d->bearings = calloc((size_t)n, sizeof *d->bearings);
    if (!d->bearings) {
        bd_fields_err(c, bd_fields_mark_of(v), path, "out of memory");
        return;
    }
    for (yaml_node_pair_t *p = v->data.mapping.pairs.start; p < v->data.mapping.pairs.top; p++) {
        yaml_node_t *k = bd_fields_node_at(c, p->key);
        int i = -1;
        bd_fields_span_index(c, k, path, &i);   /* the key names a pulley, as a span does */
        if (i < 0)
            continue;
        bd_fields_join(sub, path, bd_fields_text_of(k));
        for (int j = 0; j < d->bearing_count; j++)
            if (d->bearings[j].pulley == i)
                bd_fields_err(c, bd_fields_mark_of(k), path, "duplicate pulley '%.60s'",
                              bd_fields_text_of(k));
        bd_bearing_def *b = &d->bearings[d->bearing_count++];
        b->pulley = i;
        b->mass = c->m->pulleys[i].mass;
        b->mark = bd_fields_mark_of(k);
        bd_fields_parse_map(c, bd_fields_node_at(c, p->value), bd_fields_mark_of(k), sub,
                            &bearing_fs, b);
    }
}

static void design_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                        bd_mark at, const char *path, void *base)
{
    bd_design_def *d = base;
    const bd_model_def *m = c->m;
    d->present = 1;
    d->mark = at;
    d->bulk_density *= 1000.0; /* t/m³ in the file */
    if (d->secondary != BD_SECONDARY_INDIVIDUAL) {
        /* the resistances one by one are not used with the C factor: say
         * so where they stand, not silently */
        const char *one_by_one[] = {"skirts", "cleaners", "bearings", "loading_speed"};
        for (int k = 0; k < 4; k++) {
            yaml_node_t *v = bd_fields_got(fs, found, one_by_one[k]);
            if (v)
                bd_diag_warning(c->diag, c->file, bd_fields_mark_of(v),
                                "%s.%s: used only with secondary: individual; the C factor "
                                "stands for it here", path, one_by_one[k]);
        }
        return;
    }
    /* what the resistances one by one need (model-format.md `design`) */
    char sub[PATH_LEN];
    bd_fields_join(sub, path, "secondary");
    if (d->standard == BD_STANDARD_CEMA)
        bd_fields_err(c, bd_fields_mark_of(bd_fields_got(fs, found, "secondary")), sub,
            "`individual` is DIN 22101 / ISO 5048's; with standard: cema use "
            "secondary: C (CEMA's accessories are its own)");
    if (!(m->belt.width > 0.0))
        bd_fields_err(c, bd_fields_mark_of(bd_fields_got(fs, found, "secondary")), sub,
            "`individual` needs belt.width (m) for the wrap resistance");
    if (!bd_fields_got(fs, found, "belt_thickness") && !(m->belt.thickness > 0.0))
        bd_fields_need(c, fs, found, at, path, "belt_thickness",
            "secondary: individual needs it for the wrap resistance, or belt.thickness");
    if (d->skirts.present && m->material.present && m->material.mass_per_length > 0.0)
        bd_fields_need(c, fs, found, at, path, "bulk_density",
            "the skirt resistances of a loaded belt need it");
}

static const bd_field safety_fields[] = {
    POS("running", bd_safety_factor_def, running, 0),
    POS("starting", bd_safety_factor_def, starting, 0),
};
FIELDSET(safety_fs, safety_fields, NULL);

static const char *const standard_names[] = {"din22101", "iso5048", "cema", NULL};
static const char *const secondary_names[] = {"C", "individual", NULL};
static const char *const carcass_names[] = {"fabric", "steel_cord", NULL};
static const bd_field design_fields[] = {
    ENUM("standard", bd_design_def, standard, 0, standard_names, NULL),
    NONNEG("f", bd_design_def, f, 0),
    NUM("C", bd_design_def, C, AUTO, 1.0, INFINITY),
    POS("speed", bd_design_def, speed, 0),
    POS("sag_ratio", bd_design_def, sag_ratio, 0),
    MAP("cema", bd_design_def, cema, 0, &cema_fs),
    MAP("safety_factor", bd_design_def, safety_factor, 0, &safety_fs),
    NUM("efficiency", bd_design_def, efficiency, GT, 0.0, 1.0),
    ENUM("secondary", bd_design_def, secondary, 0, secondary_names, NULL),
    POS("bulk_density", bd_design_def, bulk_density, 0),
    NONNEG("loading_speed", bd_design_def, loading_speed, 0),
    MAP("skirts", bd_design_def, skirts, 0, &skirts_fs),
    MAP("cleaners", bd_design_def, cleaners, 0, &cleaners_fs),
    POS("belt_thickness", bd_design_def, belt_thickness, 0),
    ENUM("carcass", bd_design_def, carcass, 0, carcass_names, NULL),
    FN("bearings", bearings_fn),
};
FIELDSET(design_fs, design_fields, design_post);

/* ---- simulation ---- */

static void probe_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                       bd_mark at, const char *path, void *base)
{
    bd_probe_def *p = base;
    p->mark = at;
    unique_name(c, bd_fields_got(fs, found, "name"), path, p->name,
                (const char *)c->m->simulation.probes, sizeof *p, offsetof(bd_probe_def, name));
}

static const bd_field probe_fields[] = {
    STR("name", bd_probe_def, name, REQ | NONEMPTY),
    SPAN("span", bd_probe_def, span, REQ),
    NUM("at", bd_probe_def, at, REQ, 0.0, 1.0),
};
FIELDSET(probe_fs, probe_fields, probe_post);

static void init_probe(void *p)
{
    memset(p, 0, sizeof(bd_probe_def));
}

static const bd_listspec probe_list = {&probe_fs, sizeof(bd_probe_def),
                                    offsetof(bd_simulation_def, probe_count), init_probe, 0};

static void simulation_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                            bd_mark at, const char *path, void *base)
{
    bd_simulation_def *s = base;
    yaml_node_t *ts = bd_fields_got(fs, found, "time_step");
    yaml_node_t *ti = bd_fields_got(fs, found, "tension_interval");
    s->mark = at;
    if (ts)
        s->time_step_mark = bd_fields_mark_of(ts);
    /* tension.csv rows are a subset of the history rows */
    if (ti && s->tension_interval > 0.0
        && s->tension_interval < s->output_interval * (1.0 - 1e-9)) {
        char sub[PATH_LEN];
        bd_fields_join(sub, path, "tension_interval");
        bd_fields_err(c, bd_fields_mark_of(ti), sub,
            "expected at least output_interval (%g s), got %g s",
            s->output_interval, s->tension_interval);
    }
}

static const char *const initial_names[] = {"static", "rest", NULL};
static const bd_field simulation_fields[] = {
    POS("duration", bd_simulation_def, duration, 0),
    POS("time_step", bd_simulation_def, time_step, AUTO),
    POS("output_interval", bd_simulation_def, output_interval, 0),
    POS("tension_interval", bd_simulation_def, tension_interval, 0),
    NONNEG("tension_spacing", bd_simulation_def, tension_spacing, 0),
    ENUM("initial_state", bd_simulation_def, initial_state, 0, initial_names, NULL),
    BOOL("stabilize", bd_simulation_def, stabilize),
    LIST("probes", bd_simulation_def, probes, 0, &probe_list),
};
FIELDSET(simulation_fs, simulation_fields, simulation_post);

/* ---- top level ---- */

static void model_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                       bd_mark at, const char *path, void *base)
{
    bd_model_def *m = base;
    (void)path;
    if (!bd_fields_got(fs, found, "pulleys") && !bd_fields_got(fs, found, "profile"))
        bd_fields_err(c, at, "", "missing required key 'pulleys' (or 'profile')");
    if (!bd_fields_got(fs, found, "name"))
        bd_fields_default_name(m->source, m->name, sizeof m->name);
}

/* table order is processing order: gravity before takeups, pulleys before
 * the idlers, material and probes that name them, idlers before material */
static const bd_field model_fields[] = {
    STR("name", bd_model_def, name, 0),
    NONNEG("gravity", bd_model_def, gravity, 0),
    MAP("belt", bd_model_def, belt, REQ, &belt_fs),
    LIST("pulleys", bd_model_def, pulleys, 0, &pulley_list),
    FN("profile", profile_fn),
    FN("idlers", idlers_fn),
    MAP("material", bd_model_def, material, 0, &material_fs),
    MAP("design", bd_model_def, design, 0, &design_fs),
    MAP("simulation", bd_model_def, simulation, 0, &simulation_fs),
};
FIELDSET(model_fs, model_fields, model_post);

/* ---- entry points ---- */

static void model_init(void *m)
{
    bd_model_def_init(m);
}

static void model_free(void *m)
{
    bd_model_def_free(m);
}

static const bd_fields_loader model_loader = {
    &model_fs, "empty model: expected a mapping with belt and pulleys", model_init, model_free,
    offsetof(bd_model_def, source), sizeof(((bd_model_def *)0)->source)};

int bd_model_load_string(const char *text, size_t len, const char *path, bd_model_def *out,
                         bd_diag *diag)
{
    bd_fields_ctx c = {.diag = diag, .m = out};
    return bd_fields_load_text(&c, &model_loader, text, len, path, out);
}

int bd_model_load(const char *path, bd_model_def *out, bd_diag *diag)
{
    bd_fields_ctx c = {.diag = diag, .m = out};
    return bd_fields_load_file(&c, &model_loader, path, out);
}
