/* boom model loader: YAML -> bd_boom_def (beltdyn/boom.h), validating every
 * key against boom-format.md with the field tables of model/fields.h and
 * reporting each problem as "FILE:LINE:COL: error: PATH: MESSAGE" at the
 * offending node, as the conveyor's loader (model/load.c) does.
 *
 * Choices of this loader where boom-format.md is silent:
 * - the top level holds name (default the file's base name), gravity
 *   (>= 0), boom and simulation {duration, time_step (or auto),
 *   output_interval}; a belt, pulleys or profile beside boom is refused;
 * - luffing angles lie in (-90, 90] degrees;
 * - pads.friction needs both static and dynamic, dynamic <= static;
 * - a cubic stroke profile needs every one of its keys; a table's strokes
 *   are >= 0 and its stroke at t = 0 is `initial` (to 1e-9 m);
 * - tip_load needs its mass; luffing_cylinder needs base and attach, with
 *   attach's s within section 1 (after the pivot's offset);
 * - added keys (boom-format.md allows more): pivot_offset,
 *   luffing_cylinder.stiffness,
 *   pads.damping_ratio and smoothing, telescopic_cylinder, ropes;
 * - the geometry the loader can judge: the stroke over the whole profile
 *   stays within [0, length_k - pads.width] for every outer section k
 *   (section k+1's bottom pads stay inside section k). */
#include "beltdyn/boom.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/constants.h"
#include "base/file.h"
#include "model/fields.h"

/* enums are stored through int pointers */
_Static_assert(sizeof(bd_stroke_kind) == sizeof(int), "enum size");

void bd_boom_def_init(bd_boom_def *d)
{
    memset(d, 0, sizeof *d);
    d->gravity = 9.81;
    d->gap = 0.005;
    d->synchronized = 1;
    d->elements_per_segment = 8;
    d->damping_ratio = 0.01;
    d->pads.damping_ratio = 0.2;
    d->pads.smoothing = 1e-4;
    d->luffing_cylinder.stiffness = 1e9;
    d->telescopic_cylinder.stiffness = 1e8;
    d->telescopic_cylinder.damping_ratio = 0.2;
    d->ropes.axial_stiffness = 2e8;
    d->simulation.output_interval = 0.01;   /* duration, time_step 0: auto */
    d->stroke.direction = 1;
}

void bd_boom_def_free(bd_boom_def *d)
{
    if (!d)
        return;
    free(d->sections);
    bd_table_free(&d->luffing_angle);
    bd_table_free(&d->stroke.table);
    bd_boom_def_init(d);
}

/* ---- sections ---- */

static void section_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                         bd_mark at, const char *path, void *base)
{
    (void)c, (void)fs, (void)found, (void)path;
    ((bd_boom_section_def *)base)->mark = at;
}

static const bd_field section_fields[] = {
    POS("length", bd_boom_section_def, length, REQ),
    POS("axial_stiffness", bd_boom_section_def, axial_stiffness, REQ),
    POS("bending_stiffness", bd_boom_section_def, bending_stiffness, REQ),
    POS("mass_per_length", bd_boom_section_def, mass_per_length, REQ),
    POS("height", bd_boom_section_def, height, REQ),
};
FIELDSET(section_fs, section_fields, section_post);

static void init_section(void *s)
{
    memset(s, 0, sizeof(bd_boom_section_def));
}

static const bd_listspec section_list = {&section_fs, sizeof(bd_boom_section_def),
                                         offsetof(bd_boom_def, section_count), init_section, 2};

/* ---- luffing ---- */

/* a number or a [time, deg] table of angles in (-90, 90] degrees, stored
 * in rad */
static void luffing_angle_fn(bd_fields_ctx *c, const bd_field *f, yaml_node_t *v, bd_mark key,
                             const char *path, void *base)
{
    bd_table *tab = &((bd_boom_def *)base)->luffing_angle;
    char sub[PATH_LEN];
    int before = c->errors;
    (void)f, (void)key;
    bd_fields_get_table(c, v, path, SCALAR, -INFINITY, tab);
    if (c->errors != before)
        return;
    for (int i = 0; i < tab->n; i++) {
        double deg = tab->v[i];
        tab->v[i] = deg * BD_DEG;
        if (deg > -90.0 && deg <= 90.0)
            continue;
        if (bd_fields_is_scalar(v)) {
            bd_fields_err(c, bd_fields_mark_of(v), path,
                          "expected an angle in (-90, 90] degrees, got %g", deg);
        } else {
            bd_fields_join_index(sub, path, i);
            bd_fields_err(c, bd_fields_mark_of(bd_fields_item(c, bd_fields_item(c, v, i), 1)),
                          sub, "expected an angle in (-90, 90] degrees, got %g", deg);
        }
    }
}

static void luffing_cylinder_post(bd_fields_ctx *c, const bd_fieldset *fs,
                                  yaml_node_t *const *found, bd_mark at, const char *path,
                                  void *base)
{
    bd_luffing_cylinder_def *lc = base;
    yaml_node_t *attach = bd_fields_got(fs, found, "attach");
    const bd_boom_def *d = c->boom;
    char sub[PATH_LEN];
    lc->present = 1;
    lc->mark = at;
    /* the sections come first in boom_fields: section 1's length is known
     * when it was given */
    if (c->map_errors || d->section_count < 1 || !(d->sections[0].length > 0.0))
        return;
    /* section 1 spans [-a, L - a] along its axis from the pivot, a the
     * pivot's offset along it from the bottom end */
    double lo = 0.0 - d->pivot_offset[0], hi = d->sections[0].length - d->pivot_offset[0];
    if (!(lc->attach[0] > lo && lc->attach[0] <= hi)) {
        bd_fields_join(sub, path, "attach");
        bd_fields_err(c, bd_fields_mark_of(attach), sub,
                      "expected s in (%g, %g] (along section 1's axis from the pivot: where "
                      "section 1 is), got %g", lo, hi, lc->attach[0]);
    }
}

static const bd_field luffing_cylinder_fields[] = {
    PAIR("base", bd_luffing_cylinder_def, base, REQ, "a point [x, y]"),
    PAIR("attach", bd_luffing_cylinder_def, attach, REQ, "a point [s, n] of section 1"),
    POS("stiffness", bd_luffing_cylinder_def, stiffness, 0),
};
FIELDSET(luffing_cylinder_fs, luffing_cylinder_fields, luffing_cylinder_post);

/* ---- pads ---- */

static void pads_friction_post(bd_fields_ctx *c, const bd_fieldset *fs,
                               yaml_node_t *const *found, bd_mark at, const char *path,
                               void *base)
{
    const bd_boom_pads_def *p = base;
    (void)at;
    bd_fields_check_friction(c, fs, found, path, p->mu_static, p->mu_dynamic);
}

static const bd_field pads_friction_fields[] = {
    NONNEG("static", bd_boom_pads_def, mu_static, REQ),
    NONNEG("dynamic", bd_boom_pads_def, mu_dynamic, REQ),
};
FIELDSET(pads_friction_fs, pads_friction_fields, pads_friction_post);

static const bd_field pads_fields[] = {
    POS("width", bd_boom_pads_def, width, REQ),
    POS("stiffness", bd_boom_pads_def, stiffness, REQ),
    SUBMAP("friction", REQ, &pads_friction_fs),
    POS("switch_speed", bd_boom_pads_def, switch_speed, REQ),
    NONNEG("damping_ratio", bd_boom_pads_def, damping_ratio, 0),
    POS("smoothing", bd_boom_pads_def, smoothing, 0),
};
FIELDSET(pads_fs, pads_fields, NULL);

/* ---- stroke ---- */

static const char *const cubic_names[] = {"cubic", NULL};
static const int cubic_vals[] = {BD_STROKE_CUBIC};
static const char *const direction_names[] = {"extend", "retract", NULL};
static const int direction_vals[] = {1, -1};
static const bd_field cubic_fields[] = {
    ENUM("kind", bd_boom_stroke_def, kind, REQ, cubic_names, cubic_vals),
    POS("v_max", bd_boom_stroke_def, v_max, REQ),
    NONNEG("accel_time", bd_boom_stroke_def, accel_time, REQ),
    NONNEG("hold_time", bd_boom_stroke_def, hold_time, REQ),
    NONNEG("decel_time", bd_boom_stroke_def, decel_time, REQ),
    ENUM("direction", bd_boom_stroke_def, direction, REQ, direction_names, direction_vals),
};
FIELDSET(cubic_fs, cubic_fields, NULL);

/* PROFILE: a [time_s, stroke_m] table or the cubic's mapping */
static void stroke_profile_fn(bd_fields_ctx *c, const bd_field *f, yaml_node_t *v, bd_mark key,
                              const char *path, void *base)
{
    bd_boom_stroke_def *s = base;
    (void)f;
    if (v && v->type == YAML_MAPPING_NODE) {
        bd_fields_parse_map(c, v, key, path, &cubic_fs, s);
    } else if (v && v->type == YAML_SEQUENCE_NODE) {
        s->kind = BD_STROKE_TABLE;
        bd_fields_get_table(c, v, path, 0, 0.0, &s->table);
    } else {
        bd_fields_type_error(c, v, path, "a list of [time, stroke] pairs or a mapping "
                                         "{kind: cubic, v_max, accel_time, hold_time, "
                                         "decel_time, direction}");
    }
}

static void stroke_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                        bd_mark at, const char *path, void *base)
{
    bd_boom_stroke_def *s = base;
    yaml_node_t *profile = bd_fields_got(fs, found, "profile");
    char sub[PATH_LEN];
    s->mark = at;
    if (c->map_errors || s->kind != BD_STROKE_TABLE)
        return;
    /* the run starts from `initial`: a table elsewhere at t = 0 would be a
     * jump of the cylinder */
    double x0 = bd_table_eval(&s->table, 0.0);
    if (fabs(x0 - s->initial) > 1e-9) {
        bd_fields_join(sub, path, "profile");
        bd_fields_err(c, bd_fields_mark_of(profile), sub,
                      "the table's stroke at t = 0 is %.10g m, not the initial stroke %.10g m",
                      x0, s->initial);
    }
}

static const bd_field stroke_fields[] = {
    NONNEG("initial", bd_boom_stroke_def, initial, REQ),
    FN_REQ("profile", stroke_profile_fn),
};
FIELDSET(stroke_fs, stroke_fields, stroke_post);

/* the stroke over the whole profile within [0, length_k - pads.width]
 * for every outer section k: section k+1's bottom stands `stroke` above
 * k's bottom and its pads, `width` long, must stay inside k. The
 * profiles are monotone between their samples: a table's points, the
 * cubic's start and end. */
static void check_stroke_range(bd_fields_ctx *c, const bd_boom_def *d, const char *path)
{
    const bd_boom_stroke_def *s = &d->stroke;
    double ends_t[2] = {0.0, bd_boom_stroke_end(s)}, ends_x[2];
    const double *t = ends_t, *x = ends_x;
    int n = 2, k = 0, hi = 0, lo = 0;
    char sub[PATH_LEN];
    if (s->kind == BD_STROKE_TABLE) {
        t = s->table.t;
        x = s->table.v;
        n = s->table.n;
    } else {
        bd_boom_stroke_eval(s, ends_t[0], &ends_x[0], NULL, NULL);
        bd_boom_stroke_eval(s, ends_t[1], &ends_x[1], NULL, NULL);
    }
    for (int i = 1; i < n; i++) {
        hi = x[i] > x[hi] ? i : hi;
        lo = x[i] < x[lo] ? i : lo;
    }
    /* the shortest outer section (the first of equals) allows the least */
    for (int j = 1; j + 1 < d->section_count; j++)
        if (d->sections[j].length < d->sections[k].length)
            k = j;
    double limit = d->sections[k].length - d->pads.width;
    bd_fields_join(sub, path, "stroke");
    if (n > 0 && x[hi] > limit)
        bd_fields_err(c, s->mark, sub, "the stroke reaches %g m at t = %g s, beyond the %g m "
                      "that section %d allows section %d (its length %g m less the pad width "
                      "%g m)", x[hi], t[hi], limit, k + 1, k + 2, d->sections[k].length,
                      d->pads.width);
    if (n > 0 && x[lo] < 0.0)
        bd_fields_err(c, s->mark, sub, "the stroke falls to %g m at t = %g s, below 0: "
                      "section 2 would leave section 1 at its bottom", x[lo], t[lo]);
}

/* ---- the boom ---- */

/* the section count's upper bound, then the stroke against the sections
 * when every key read well */
static void boom_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                      bd_mark at, const char *path, void *base)
{
    bd_boom_def *d = base;
    yaml_node_t *sections = bd_fields_got(fs, found, "sections");
    char sub[PATH_LEN];
    d->mark = at;
    if (sections && d->section_count > BD_BOOM_MAX_SECTIONS) {
        bd_fields_join(sub, path, "sections");
        bd_fields_err(c, bd_fields_mark_of(sections), sub,
                      "expected a list of at most %d entries, got %d", BD_BOOM_MAX_SECTIONS,
                      d->section_count);
    } else if (!c->map_errors) {
        check_stroke_range(c, d, path);
    }
}

static const bd_field tip_load_fields[] = {
    NONNEG("mass", bd_boom_def, tip_mass, REQ),
};
FIELDSET(tip_load_fs, tip_load_fields, NULL);

static const bd_field telescopic_cylinder_fields[] = {
    POS("stiffness", bd_telescopic_cylinder_def, stiffness, 0),
    NONNEG("damping_ratio", bd_telescopic_cylinder_def, damping_ratio, 0),
};
FIELDSET(telescopic_cylinder_fs, telescopic_cylinder_fields, NULL);

static const bd_field ropes_fields[] = {
    POS("axial_stiffness", bd_boom_ropes_def, axial_stiffness, 0),
};
FIELDSET(ropes_fs, ropes_fields, NULL);

/* table order is processing order: the sections and the pivot's offset
 * before the luffing cylinder that is attached to section 1 */
static const bd_field boom_fields[] = {
    PAIR("pivot", bd_boom_def, pivot, 0, "a point [x, y]"),
    PAIR("pivot_offset", bd_boom_def, pivot_offset, 0,
         "[along, across] m from section 1's bottom end"),
    FN_REQ("luffing_angle_deg", luffing_angle_fn),
    LIST("sections", bd_boom_def, sections, REQ, &section_list),
    MAP("luffing_cylinder", bd_boom_def, luffing_cylinder, 0, &luffing_cylinder_fs),
    MAP("pads", bd_boom_def, pads, REQ, &pads_fs),
    NONNEG("gap", bd_boom_def, gap, 0),
    MAP("stroke", bd_boom_def, stroke, REQ, &stroke_fs),
    BOOL("synchronized", bd_boom_def, synchronized),
    SUBMAP("tip_load", 0, &tip_load_fs),
    INT("elements_per_segment", bd_boom_def, elements_per_segment, 0, 1.0, 200.0),
    NUM("damping_ratio", bd_boom_def, damping_ratio, LT, 0.0, 1.0),
    MAP("telescopic_cylinder", bd_boom_def, telescopic_cylinder, 0, &telescopic_cylinder_fs),
    MAP("ropes", bd_boom_def, ropes, 0, &ropes_fs),
};
FIELDSET(boom_fs, boom_fields, boom_post);

/* ---- top level ---- */

/* a conveyor's keys beside `boom` */
static void conveyor_key_fn(bd_fields_ctx *c, const bd_field *f, yaml_node_t *v, bd_mark key,
                            const char *path, void *base)
{
    (void)f, (void)v, (void)base;
    bd_fields_err(c, key, path, "a boom model has no belt, pulleys or profile");
}

static void simulation_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                            bd_mark at, const char *path, void *base)
{
    bd_boom_simulation_def *s = base;
    yaml_node_t *ts = bd_fields_got(fs, found, "time_step");
    (void)c, (void)path;
    s->mark = at;
    if (ts)
        s->time_step_mark = bd_fields_mark_of(ts);
}

static const bd_field simulation_fields[] = {
    POS("duration", bd_boom_simulation_def, duration, 0),
    POS("time_step", bd_boom_simulation_def, time_step, AUTO),
    POS("output_interval", bd_boom_simulation_def, output_interval, 0),
};
FIELDSET(simulation_fs, simulation_fields, simulation_post);

static void top_post(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                     bd_mark at, const char *path, void *base)
{
    bd_boom_def *d = base;
    (void)c, (void)at, (void)path;
    if (!bd_fields_got(fs, found, "name"))
        bd_fields_default_name(d->source, d->name, sizeof d->name);
}

static const bd_field top_fields[] = {
    STR("name", bd_boom_def, name, 0),
    NONNEG("gravity", bd_boom_def, gravity, 0),
    SUBMAP("boom", REQ, &boom_fs),
    MAP("simulation", bd_boom_def, simulation, 0, &simulation_fs),
    FN("belt", conveyor_key_fn),
    FN("pulleys", conveyor_key_fn),
    FN("profile", conveyor_key_fn),
};
FIELDSET(top_fs, top_fields, top_post);

/* ---- entry points ---- */

int bd_model_is_boom(const char *path)
{
    char *text;
    size_t len;
    yaml_parser_t parser;
    yaml_document_t doc;
    int boom = 0;
    if (bd_read_file(path, &text, &len) != BD_READ_OK)
        return 0;
    if (!yaml_parser_initialize(&parser)) {
        free(text);
        return 0;
    }
    yaml_parser_set_input_string(&parser, (const unsigned char *)text, len);
    if (yaml_parser_load(&parser, &doc)) {
        yaml_node_t *root = yaml_document_get_root_node(&doc);
        if (root && root->type == YAML_MAPPING_NODE)
            for (yaml_node_pair_t *p = root->data.mapping.pairs.start;
                 !boom && p < root->data.mapping.pairs.top; p++)
                boom = bd_fields_scalar_is(yaml_document_get_node(&doc, p->key), "boom");
        yaml_document_delete(&doc);
    }
    yaml_parser_delete(&parser);
    free(text);
    return boom;
}

static void boom_init(void *d)
{
    bd_boom_def_init(d);
}

static void boom_free(void *d)
{
    bd_boom_def_free(d);
}

static const bd_fields_loader boom_loader = {
    &top_fs, "empty model: expected a mapping with boom", boom_init, boom_free,
    offsetof(bd_boom_def, source), sizeof(((bd_boom_def *)0)->source)};

int bd_boom_load_string(const char *text, size_t len, const char *path, bd_boom_def *out,
                        bd_diag *diag)
{
    bd_fields_ctx c = {.diag = diag, .boom = out};
    return bd_fields_load_text(&c, &boom_loader, text, len, path, out);
}

int bd_boom_load(const char *path, bd_boom_def *out, bd_diag *diag)
{
    bd_fields_ctx c = {.diag = diag, .boom = out};
    return bd_fields_load_file(&c, &boom_loader, path, out);
}
