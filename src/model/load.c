/* model loader: YAML (libyaml document API) -> bd_model_def, validating every
 * key against model-format.md and reporting each problem as
 * "FILE:LINE:COL: error: PATH: MESSAGE" at the offending node.
 *
 * Every mapping is described by a table of fields (key, kind, where it is
 * stored, range); parse_map() walks a YAML mapping against such a table,
 * reporting unknown, duplicate and missing keys, and calls one handler per
 * kind. What a table cannot say (derived values, keys required only in some
 * modes, uniqueness) is done by the table's post function.
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

#include <yaml.h>

#include <assert.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/constants.h"
#include "base/file.h"
#include "model/profile.h"

#define PATH_LEN 256
#define MAX_FIELDS 16
#define DEG_TO_RAD BD_DEG

/* enums are stored through int pointers */
_Static_assert(sizeof(bd_drive_control) == sizeof(int), "enum size");

typedef struct ctx {
    yaml_document_t *doc;
    const char *file;
    bd_diag *diag;
    bd_model_def *m;
    int errors;
    int index;   /* index of the list entry being parsed */
} ctx;

struct field;
struct fieldset;
typedef void (*field_fn)(ctx *c, const struct field *f, yaml_node_t *v,
                         bd_mark key, const char *path, void *base);
typedef void (*post_fn)(ctx *c, const struct fieldset *fs, yaml_node_t *const *found,
                        bd_mark at, const char *path, void *base);

typedef struct fieldset {
    const struct field *fields;
    int n;
    post_fn post;   /* after all fields, or NULL */
} fieldset;

typedef struct listspec {
    const fieldset *elem;
    size_t size;             /* bytes of one element */
    size_t count_off;        /* offset of the int count beside the pointer */
    void (*init)(void *elem);
    int min;                 /* least number of entries */
} listspec;

enum kind {
    K_NUM,    /* double with range */
    K_BOOL,   /* int 0/1 */
    K_STR,    /* char[size] */
    K_ENUM,   /* int from names[] (value vals[i], or i) */
    K_MAP,    /* nested mapping, fields relative to base + off */
    K_LIST,   /* list of mappings: T *at off, int count at list->count_off */
    K_TABLE,  /* bd_table of [t, value] pairs */
    K_SPAN,   /* int index of a pulley named by the value */
    K_FN      /* custom handler, given base + off */
};

enum {
    REQ = 1,       /* required */
    GT = 2,        /* lower bound is strict */
    AUTO = 4,      /* `auto` is accepted and stored as 0 */
    DEG = 8,       /* value in degrees, stored in rad */
    SCALAR = 16,   /* table: a single number is a one-point table */
    NONEMPTY = 32  /* string must not be empty */
};

typedef struct field {
    const char *key;
    int kind;
    unsigned flags;
    size_t off;
    double lo, hi;              /* K_NUM / K_TABLE values */
    const char *const *names;   /* K_ENUM, NULL-terminated */
    const int *vals;            /* K_ENUM values, NULL = index */
    const fieldset *sub;        /* K_MAP */
    const listspec *list;       /* K_LIST */
    field_fn fn;                /* K_FN */
    size_t size;                /* K_STR buffer size */
} field;

#define NUM(k, T, m, fl, l, h) {.key = k, .kind = K_NUM, .flags = fl, \
    .off = offsetof(T, m), .lo = l, .hi = h}
#define ANY(k, T, m, fl) NUM(k, T, m, fl, -INFINITY, INFINITY)
#define POS(k, T, m, fl) NUM(k, T, m, (fl) | GT, 0.0, INFINITY)
#define NONNEG(k, T, m, fl) NUM(k, T, m, fl, 0.0, INFINITY)
#define BOOL(k, T, m) {.key = k, .kind = K_BOOL, .off = offsetof(T, m)}
#define STR(k, T, m, fl) {.key = k, .kind = K_STR, .flags = fl, .off = offsetof(T, m), \
    .size = sizeof(((T *)0)->m)}
#define ENUM(k, T, m, fl, nm, v) {.key = k, .kind = K_ENUM, .flags = fl, \
    .off = offsetof(T, m), .names = nm, .vals = v}
#define MAP(k, T, m, fl, s) {.key = k, .kind = K_MAP, .flags = fl, .off = offsetof(T, m), .sub = s}
#define SUBMAP(k, fl, s) {.key = k, .kind = K_MAP, .flags = fl, .off = 0, .sub = s}
#define LIST(k, T, m, fl, l) {.key = k, .kind = K_LIST, .flags = fl, .off = offsetof(T, m), .list = l}
#define TABLE(k, T, m, fl, l) {.key = k, .kind = K_TABLE, .flags = fl, .off = offsetof(T, m), \
    .lo = l, .hi = INFINITY}
#define SPAN(k, T, m, fl) {.key = k, .kind = K_SPAN, .flags = fl, .off = offsetof(T, m)}
#define FN(k, f) {.key = k, .kind = K_FN, .off = 0, .fn = f}
#define FN_REQ(k, f) {.key = k, .kind = K_FN, .flags = REQ, .off = 0, .fn = f}
#define FIELDSET(name, arr, post) \
    static const fieldset name = {arr, (int)(sizeof arr / sizeof arr[0]), post}

/* ---- nodes, marks, messages ---- */

static yaml_node_t *node_at(ctx *c, int id)
{
    return yaml_document_get_node(c->doc, id);
}

static bd_mark mark_of(const yaml_node_t *n)
{
    bd_mark at = {1, 1};
    if (n) {
        at.line = (int)n->start_mark.line + 1;
        at.column = (int)n->start_mark.column + 1;
    }
    return at;
}

static void err(ctx *c, bd_mark at, const char *path, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static void err(ctx *c, bd_mark at, const char *path, const char *fmt, ...)
{
    char msg[768];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (path[0])
        bd_diag_error(c->diag, c->file, at, "%s: %s", path, msg);
    else
        bd_diag_error(c->diag, c->file, at, "%s", msg);
    c->errors++;
}

static void join(char *out, const char *path, const char *key)
{
    if (snprintf(out, PATH_LEN, "%s%s%s", path, path[0] ? "." : "", key) >= PATH_LEN)
        out[PATH_LEN - 1] = '\0';
}

static void join_index(char *out, const char *path, int i)
{
    if (snprintf(out, PATH_LEN, "%s[%d]", path, i) >= PATH_LEN)
        out[PATH_LEN - 1] = '\0';
}

static int is_scalar(const yaml_node_t *n)
{
    return n && n->type == YAML_SCALAR_NODE;
}

static const char *text_of(const yaml_node_t *n)
{
    return (const char *)n->data.scalar.value;
}

static int scalar_is(const yaml_node_t *n, const char *s)
{
    return is_scalar(n) && n->data.scalar.length == strlen(s) && strcmp(text_of(n), s) == 0;
}

/* a plain scalar that reads entirely as a finite decimal number */
static int scalar_number(const yaml_node_t *n, double *x)
{
    const char *s;
    char *end;
    size_t len;
    if (!is_scalar(n) || n->data.scalar.style != YAML_PLAIN_SCALAR_STYLE)
        return 0;
    s = text_of(n);
    len = n->data.scalar.length;
    if (len == 0 || strspn(s, "0123456789+-.eE") != len || strpbrk(s, "0123456789") == NULL)
        return 0;
    errno = 0;
    *x = strtod(s, &end);
    return end == s + len && isfinite(*x);
}

/* what a node is, for "got ..." */
static const char *describe(const yaml_node_t *n, char *buf, size_t size)
{
    double x;
    if (!n)
        return "nothing";
    if (n->type == YAML_MAPPING_NODE)
        return "a mapping";
    if (n->type == YAML_SEQUENCE_NODE)
        return "a list";
    if (n->data.scalar.length == 0 && n->data.scalar.style == YAML_PLAIN_SCALAR_STYLE)
        return "nothing";
    snprintf(buf, size, scalar_number(n, &x) ? "%.60s" : "'%.60s'", text_of(n));
    return buf;
}

static void type_error(ctx *c, const yaml_node_t *v, const char *path, const char *want)
{
    char buf[80];
    err(c, mark_of(v), path, "expected %s, got %s", want, describe(v, buf, sizeof buf));
}

static int seq_len(const yaml_node_t *n)
{
    return (int)(n->data.sequence.items.top - n->data.sequence.items.start);
}

/* ---- scalar helpers ---- */

/* a number in [lo, hi] ((lo, hi] with GT), `auto` -> 0 with AUTO; 0 = ok */
static int get_num(ctx *c, yaml_node_t *v, const char *path, double lo, double hi,
                   unsigned flags, double *out)
{
    char want[96];
    int k = 0;
    double x;
    if ((flags & AUTO) && scalar_is(v, "auto")) {
        *out = 0.0;
        return 0;
    }
    k = snprintf(want, sizeof want, "%sa number", (flags & AUTO) ? "auto or " : "");
    if (isfinite(lo) && isfinite(hi))
        snprintf(want + k, sizeof want - (size_t)k, " in %s%g, %g]", (flags & GT) ? "(" : "[", lo, hi);
    else if (isfinite(lo))
        snprintf(want + k, sizeof want - (size_t)k, " %s %g", (flags & GT) ? ">" : ">=", lo);
    if (!scalar_number(v, &x) || x < lo || x > hi || ((flags & GT) && x == lo)) {
        type_error(c, v, path, want);
        return 1;
    }
    *out = (flags & DEG) ? x * DEG_TO_RAD : x;
    return 0;
}

/* a list of exactly k numbers; 0 = ok */
static int get_numbers(ctx *c, yaml_node_t *v, const char *path, int k, const char *want,
                       double *out)
{
    char sub[PATH_LEN];
    int bad = 0;
    if (!v || v->type != YAML_SEQUENCE_NODE || seq_len(v) != k) {
        type_error(c, v, path, want);
        return 1;
    }
    for (int i = 0; i < k; i++) {
        join_index(sub, path, i);
        bad |= get_num(c, node_at(c, v->data.sequence.items.start[i]), sub,
                       -INFINITY, INFINITY, 0, &out[i]);
    }
    return bad;
}

static int get_bool(ctx *c, yaml_node_t *v, const char *path, int *out)
{
    static const char *const yes[] = {"true", "True", "TRUE", "yes", "Yes", "YES"};
    static const char *const no[] = {"false", "False", "FALSE", "no", "No", "NO"};
    for (int i = 0; is_scalar(v) && v->data.scalar.style == YAML_PLAIN_SCALAR_STYLE && i < 6; i++) {
        if (scalar_is(v, yes[i]) || scalar_is(v, no[i])) {
            *out = scalar_is(v, yes[i]);
            return 0;
        }
    }
    type_error(c, v, path, "true or false");
    return 1;
}

static int get_string(ctx *c, yaml_node_t *v, const char *path, unsigned flags,
                      char *out, size_t size)
{
    char want[64];
    size_t len;
    snprintf(want, sizeof want, "a %sname of at most %d characters",
             (flags & NONEMPTY) ? "non-empty " : "", (int)size - 1);
    if (!is_scalar(v) || (len = v->data.scalar.length) >= size || strlen(text_of(v)) != len
        || ((flags & NONEMPTY) && len == 0)) {
        type_error(c, v, path, want);
        return 1;
    }
    memcpy(out, text_of(v), len + 1);
    return 0;
}

static int get_enum(ctx *c, yaml_node_t *v, const char *path, const char *const *names,
                    const int *vals, int *out)
{
    char want[160] = "";
    int n = 0;
    for (; names[n]; n++) {
        if (scalar_is(v, names[n])) {
            *out = vals ? vals[n] : n;
            return 0;
        }
    }
    for (int i = 0; i < n; i++) {
        size_t used = strlen(want);
        snprintf(want + used, sizeof want - used, "%s%s",
                 i == 0 ? "" : (i == n - 1 ? " or " : ", "), names[i]);
    }
    type_error(c, v, path, want);
    return 1;
}

static int table_alloc(bd_table *tab, int n)
{
    tab->t = calloc((size_t)n, sizeof *tab->t);
    tab->v = calloc((size_t)n, sizeof *tab->v);
    if (!tab->t || !tab->v) {
        free(tab->t);
        free(tab->v);
        tab->t = tab->v = NULL;
        return 1;
    }
    tab->n = n;
    return 0;
}

/* [[t, v], ...] with strictly increasing t and v >= lo, or (SCALAR) one
 * number v meaning [[0, v]] */
static void get_table(ctx *c, yaml_node_t *v, const char *path, unsigned flags, double lo,
                      bd_table *tab)
{
    char sub[PATH_LEN];
    double one;
    int n;
    if ((flags & SCALAR) && is_scalar(v)) {
        if (get_num(c, v, path, lo, INFINITY, 0, &one) == 0 && table_alloc(tab, 1) == 0)
            tab->v[0] = one;
        return;
    }
    if (!v || v->type != YAML_SEQUENCE_NODE || (n = seq_len(v)) == 0) {
        type_error(c, v, path, (flags & SCALAR) ? "a number or a list of [time, value] pairs"
                                                : "a list of [time, value] pairs");
        return;
    }
    if (table_alloc(tab, n)) {
        err(c, mark_of(v), path, "out of memory");
        return;
    }
    for (int i = 0; i < n; i++) {
        yaml_node_t *item = node_at(c, v->data.sequence.items.start[i]);
        double pt[2];
        join_index(sub, path, i);
        if (get_numbers(c, item, sub, 2, "a [time, value] pair", pt))
            continue;
        if (i > 0 && !(pt[0] > tab->t[i - 1]))
            err(c, mark_of(node_at(c, item->data.sequence.items.start[0])), sub,
                "expected a time > %g (times must increase), got %g", tab->t[i - 1], pt[0]);
        if (pt[1] < lo)
            err(c, mark_of(node_at(c, item->data.sequence.items.start[1])), sub,
                "expected a value >= %g, got %g", lo, pt[1]);
        tab->t[i] = pt[0];
        tab->v[i] = pt[1];
    }
}

/* ---- mappings and lists ---- */

static void parse_map(ctx *c, yaml_node_t *node, bd_mark at, const char *path,
                      const fieldset *fs, void *base);

static void parse_list(ctx *c, const listspec *ls, yaml_node_t *v, const char *path, void *base,
                       size_t off)
{
    char sub[PATH_LEN];
    char buf[80];
    char *arr;
    int n, saved = c->index;
    if (!v || v->type != YAML_SEQUENCE_NODE) {
        type_error(c, v, path, "a list");
        return;
    }
    n = seq_len(v);
    if (n < ls->min) {
        snprintf(buf, sizeof buf, "%d", n);
        err(c, mark_of(v), path, "expected a list of at least %d entries, got %s", ls->min, buf);
    }
    if (n == 0)
        return;
    arr = calloc((size_t)n, ls->size);
    if (!arr) {
        err(c, mark_of(v), path, "out of memory");
        return;
    }
    *(void **)((char *)base + off) = arr;
    *(int *)((char *)base + ls->count_off) = n;
    for (int i = 0; i < n; i++)
        ls->init(arr + (size_t)i * ls->size);
    for (int i = 0; i < n; i++) {
        yaml_node_t *item = node_at(c, v->data.sequence.items.start[i]);
        join_index(sub, path, i);
        c->index = i;
        parse_map(c, item, mark_of(item), sub, ls->elem, arr + (size_t)i * ls->size);
    }
    c->index = saved;
}

static void span_index(ctx *c, yaml_node_t *v, const char *path, int *out)
{
    char name[BD_NAME_MAX];
    int i;
    if (get_string(c, v, path, NONEMPTY, name, sizeof name))
        return;
    i = bd_model_find_pulley(c->m, name);
    if (i >= 0)
        *out = i;
    else if (c->m->pulley_count > 0)   /* no pulleys at all was reported already */
        err(c, mark_of(v), path, "unknown pulley '%s'", name);
}

/* one field's value */
static void parse_field(ctx *c, const field *f, yaml_node_t *v, bd_mark key, const char *path,
                        void *base)
{
    void *dst = (char *)base + f->off;
    switch (f->kind) {
    case K_NUM: get_num(c, v, path, f->lo, f->hi, f->flags, dst); break;
    case K_BOOL: get_bool(c, v, path, dst); break;
    case K_STR: get_string(c, v, path, f->flags, dst, f->size); break;
    case K_ENUM: get_enum(c, v, path, f->names, f->vals, dst); break;
    case K_MAP: parse_map(c, v, key, path, f->sub, dst); break;
    case K_LIST: parse_list(c, f->list, v, path, base, f->off); break;
    case K_TABLE: get_table(c, v, path, f->flags, f->lo, dst); break;
    case K_SPAN: span_index(c, v, path, dst); break;
    case K_FN: f->fn(c, f, v, key, path, dst); break;
    default: assert(0);
    }
}

/* walk a mapping against fs: unknown, duplicate and missing keys, then every
 * present field in table order (so pulleys come before what names them),
 * then fs->post. at = where a missing key is reported. */
static void parse_map(ctx *c, yaml_node_t *node, bd_mark at, const char *path,
                      const fieldset *fs, void *base)
{
    yaml_node_t *found[MAX_FIELDS] = {0};
    bd_mark keys[MAX_FIELDS];
    char sub[PATH_LEN];
    assert(fs->n <= MAX_FIELDS);
    if (!node || node->type != YAML_MAPPING_NODE) {
        type_error(c, node, path, "a mapping");
        return;
    }
    for (yaml_node_pair_t *p = node->data.mapping.pairs.start; p < node->data.mapping.pairs.top; p++) {
        yaml_node_t *k = node_at(c, p->key);
        int i = 0;
        if (!is_scalar(k)) {
            type_error(c, k, path, "a key name");
            continue;
        }
        while (i < fs->n && !scalar_is(k, fs->fields[i].key))
            i++;
        if (i == fs->n)
            err(c, mark_of(k), path, "unknown key '%.60s'", text_of(k));
        else if (found[i])
            err(c, mark_of(k), path, "duplicate key '%s'", fs->fields[i].key);
        else {
            found[i] = node_at(c, p->value);
            keys[i] = mark_of(k);
        }
    }
    for (int i = 0; i < fs->n; i++) {
        const field *f = &fs->fields[i];
        if (!found[i]) {
            if (f->flags & REQ)
                err(c, at, path, "missing required key '%s'", f->key);
            continue;
        }
        join(sub, path, f->key);
        parse_field(c, f, found[i], keys[i], sub, base);
    }
    if (fs->post)
        fs->post(c, fs, found, at, path, base);
}

/* the node given for key in a finished parse_map, or NULL */
static yaml_node_t *got(const fieldset *fs, yaml_node_t *const *found, const char *key)
{
    for (int i = 0; i < fs->n; i++)
        if (strcmp(fs->fields[i].key, key) == 0)
            return found[i];
    return NULL;
}

/* "missing required key" for a key needed only in some modes */
static void need(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                 const char *path, const char *key, const char *why)
{
    if (!got(fs, found, key))
        err(c, at, path, "missing required key '%s' (%s)", key, why);
}

/* ---- friction ---- */

static void friction_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                          const char *path, void *base)
{
    bd_friction *fr = base;
    yaml_node_t *dyn = got(fs, found, "dynamic");
    char sub[PATH_LEN];
    (void)at;
    if (dyn && got(fs, found, "static") && fr->mu_dynamic > fr->mu_static) {
        join(sub, path, "dynamic");
        err(c, mark_of(dyn), sub, "expected a number <= static (%g), got %g",
            fr->mu_static, fr->mu_dynamic);
    }
}

static const field friction_fields[] = {
    NONNEG("static", bd_friction, mu_static, REQ),
    NONNEG("dynamic", bd_friction, mu_dynamic, REQ),
};
FIELDSET(friction_fs, friction_fields, friction_post);

/* ---- belt ---- */

static void belt_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                      const char *path, void *base)
{
    static const char *const ewt[] = {"modulus", "thickness", "width"};
    bd_belt_def *b = base;
    yaml_node_t *ea = got(fs, found, "axial_stiffness");
    int have = 0;
    for (int i = 0; i < 3; i++)
        have += got(fs, found, ewt[i]) != NULL;
    b->mark = at;
    if (ea && (got(fs, found, "modulus") || got(fs, found, "thickness"))) {
        err(c, mark_of(ea), path, "give either axial_stiffness or modulus, thickness and width, not both");
    } else if (!ea && (have == 0 || (have == 1 && got(fs, found, "width")))) {
        err(c, at, path, "missing required key 'axial_stiffness' (or modulus, thickness and width)");
    } else if (!ea) {
        for (int i = 0; i < 3; i++)
            need(c, fs, found, at, path, ewt[i], "EA = modulus*thickness*width");
        b->axial_stiffness = b->modulus * b->thickness * b->width;
    }
    if (have == 3 && !got(fs, found, "bending_stiffness"))
        b->bending_stiffness = b->modulus * b->width * b->thickness * b->thickness * b->thickness / 12.0;
}

static const field topology_fields[] = {
    BOOL("enabled", bd_belt_def, group_sections),
    POS("group_length", bd_belt_def, group_length, 0),
};
FIELDSET(topology_fs, topology_fields, NULL);

static const char *const formulation_names[] = {"discrete", "axial", "moving_node", "rfe", NULL};
static const field belt_fields[] = {
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
static const field start_fields[] = {
    ENUM("curve", bd_drive_def, curve, 0, curve_names, NULL),
    POS("time", bd_drive_def, start_time, 0),
    NONNEG("delay", bd_drive_def, start_delay, 0),
    NONNEG("creep_speed", bd_drive_def, creep_speed, 0),
};
FIELDSET(start_fs, start_fields, NULL);

static void stop_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                      const char *path, void *base)
{
    const bd_drive_def *d = base;
    if (d->stop_mode == BD_STOP_RAMP)
        need(c, fs, found, at, path, "time", "mode: ramp");
    if (d->stop_mode == BD_STOP_BRAKE)
        need(c, fs, found, at, path, "brake_torque", "mode: brake");
}

static const char *const stop_names[] = {"coast", "ramp", "brake", NULL};
static const int stop_vals[] = {BD_STOP_COAST, BD_STOP_RAMP, BD_STOP_BRAKE};
static const field stop_fields[] = {
    NONNEG("at", bd_drive_def, stop_at, REQ),
    ENUM("mode", bd_drive_def, stop_mode, REQ, stop_names, stop_vals),
    POS("time", bd_drive_def, stop_time, 0),
    POS("brake_torque", bd_drive_def, brake_torque, 0),
};
FIELDSET(stop_fs, stop_fields, stop_post);

/* the Kloss curve needs a breakdown torque above the rated one and a rated
 * speed below synchronous (a positive rated slip) */
static void motor_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                       const char *path, void *base)
{
    (void)fs;
    (void)found;
    const bd_motor_def *m = base;
    if (m->rated_speed_rpm > 0.0 && m->synchronous_speed_rpm > 0.0
        && m->rated_speed_rpm >= m->synchronous_speed_rpm)
        err(c, at, path, "rated_speed_rpm (%g) must be below synchronous_speed_rpm (%g): "
            "an induction motor runs with slip", m->rated_speed_rpm, m->synchronous_speed_rpm);
}

static const field motor_fields[] = {
    POS("rated_power", bd_motor_def, rated_power, REQ),
    POS("rated_speed_rpm", bd_motor_def, rated_speed_rpm, REQ),
    POS("synchronous_speed_rpm", bd_motor_def, synchronous_speed_rpm, REQ),
    NUM("breakdown_torque_ratio", bd_motor_def, breakdown_torque_ratio, REQ | GT, 1.0, INFINITY),
    POS("gear_ratio", bd_motor_def, gear_ratio, REQ),
    NONNEG("start_time", bd_motor_def, start_time, REQ),
};
FIELDSET(motor_fs, motor_fields, motor_post);

static const char *const vbelt_names[] = {"flat", "v", NULL};
static const field transmission_fields[] = {
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

static void drive_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                       const char *path, void *base)
{
    static const char *const need_key[] = {"speed", "torque", "motor"};
    static const char *const why[] = {"control: speed", "control: torque", "control: motor"};
    bd_drive_def *d = base;
    d->mark = at;
    d->has_transmission = got(fs, found, "transmission") != NULL;
    if (got(fs, found, "control"))
        need(c, fs, found, at, path, need_key[d->control], why[d->control]);
}

static const char *const control_names[] = {"speed", "torque", "motor", NULL};
static const field drive_fields[] = {
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

static void takeup_axis(ctx *c, const field *f, yaml_node_t *v, bd_mark key, const char *path,
                        void *base)
{
    bd_takeup_def *t = base;
    double a[2], len;
    (void)f;
    (void)key;
    if (get_numbers(c, v, path, 2, "a vector [x, y]", a))
        return;
    len = hypot(a[0], a[1]);
    if (len == 0.0) {
        err(c, mark_of(v), path, "expected a non-zero vector, got [0, 0]");
        return;
    }
    t->axis[0] = a[0] / len;
    t->axis[1] = a[1] / len;
}

static void takeup_travel(ctx *c, const field *f, yaml_node_t *v, bd_mark key, const char *path,
                          void *base)
{
    bd_takeup_def *t = base;
    double r[2];
    (void)f;
    (void)key;
    if (get_numbers(c, v, path, 2, "[min, max]", r))
        return;
    if (!(r[0] <= 0.0 && r[1] >= 0.0 && r[0] < r[1])) {
        err(c, mark_of(v), path, "expected [min, max] with min <= 0 <= max, got [%g, %g]", r[0], r[1]);
        return;
    }
    t->has_travel = 1;
    t->travel_min = r[0];
    t->travel_max = r[1];
}

static void takeup_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                        const char *path, void *base)
{
    bd_takeup_def *t = base;
    t->mark = at;
    if (!got(fs, found, "type") || got(fs, found, "force"))
        return;
    if (t->type == BD_TAKEUP_CONSTANT_FORCE)
        need(c, fs, found, at, path, "force", "type: constant_force");
    else if (t->type == BD_TAKEUP_GRAVITY && table_alloc(&t->force, 1) == 0)
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

static const field takeup_fields[] = {
    TAKEUP_BODY_FIELDS,
    FN("axis", takeup_axis),
};
FIELDSET(takeup_fs, takeup_fields, takeup_post);

/* ---- pulleys ---- */

/* name unique among the entries before this one */
static void unique_name(ctx *c, yaml_node_t *v, const char *path, const char *name,
                        const char *list, size_t stride, size_t name_off)
{
    char sub[PATH_LEN];
    for (int j = 0; v && j < c->index; j++) {
        if (strcmp(list + (size_t)j * stride + name_off, name) == 0) {
            join(sub, path, "name");
            err(c, mark_of(v), sub, "duplicate name '%s' (already used by entry %d)", name, j);
            return;
        }
    }
}

/* what a pulley and a profile's head or tail share: where it was given,
 * its drive, the inertia of a solid disc unless given */
static void pulley_body_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                             const char *path, void *base)
{
    bd_pulley_def *p = base;
    (void)c, (void)path;
    p->mark = at;
    p->has_drive = got(fs, found, "drive") != NULL;
    if (!got(fs, found, "inertia"))
        p->inertia = 0.5 * p->mass * p->radius * p->radius;
}

static void pulley_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                        const char *path, void *base)
{
    bd_pulley_def *p = base;
    pulley_body_post(c, fs, found, at, path, base);
    p->has_takeup = got(fs, found, "takeup") != NULL;
    unique_name(c, got(fs, found, "name"), path, p->name, (const char *)c->m->pulleys,
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
static const field pulley_fields[] = {
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

static const listspec pulley_list = {&pulley_fs, sizeof(bd_pulley_def),
                                     offsetof(bd_model_def, pulley_count), init_pulley, 2};

/* ---- idlers ---- */

static void curve_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                       const char *path, void *base)
{
    bd_idler_set_def *st = base;
    (void)fs, (void)found;
    st->has_curve = 1;
    st->curve_mark = at;
    /* a curve starts and ends on the straight span: the belt leaves and
     * reaches the pulleys along the span's tangent */
    if (!(st->curve_from > 0.0 && st->curve_from < st->curve_to && st->curve_to < 1.0))
        err(c, at, path, "expected 0 < from < to < 1, got from %g, to %g", st->curve_from,
            st->curve_to);
}

static const char *const sense_names[] = {"concave", "convex", NULL};
static const field curve_fields[] = {
    POS("radius", bd_idler_set_def, curve_radius, REQ),
    NUM("from", bd_idler_set_def, curve_from, REQ, 0.0, 1.0),
    NUM("to", bd_idler_set_def, curve_to, REQ, 0.0, 1.0),
    ENUM("sense", bd_idler_set_def, curve_convex, 0, sense_names, NULL),
};
FIELDSET(curve_fs, curve_fields, curve_post);

static void idler_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                       const char *path, void *base)
{
    bd_idler_set_def *st = base;
    (void)fs, (void)found, (void)path;
    st->mark = at;
    /* curves on one span may not overlap (model-format.md) */
    for (int j = 0; st->has_curve && j < c->index; j++) {
        const bd_idler_set_def *o = &c->m->idler_sets[j];
        if (o->has_curve && o->span == st->span && o->curve_from < st->curve_to
            && st->curve_from < o->curve_to)
            err(c, st->curve_mark, path, "curve: overlaps the curve of idlers[%d] on the same span", j);
    }
}

#define IDLER_FIELDS \
    POS("spacing", bd_idler_set_def, spacing, REQ), \
    POS("radius", bd_idler_set_def, radius, 0), \
    NONNEG("inertia", bd_idler_set_def, inertia, 0), \
    NONNEG("rotating_mass", bd_idler_set_def, rotating_mass, 0), \
    NONNEG("rolling_resistance", bd_idler_set_def, rolling_resistance, 0), \
    MAP("friction", bd_idler_set_def, friction, 0, &friction_fs)

static const field idler_fields[] = {
    SPAN("span", bd_idler_set_def, span, REQ),
    IDLER_FIELDS,
    SUBMAP("curve", 0, &curve_fs),
};
FIELDSET(idler_fs, idler_fields, idler_post);

static void init_idler(void *s)
{
    *(bd_idler_set_def *)s = bd_idler_set_default();
}

static const listspec idler_list = {&idler_fs, sizeof(bd_idler_set_def),
                                    offsetof(bd_model_def, idler_set_count), init_idler, 0};

/* ---- profile (model-format.md: a conveyor given by its route) ---- */

/* an idler set of the profile: its span is the layout's */
static const field profile_idler_fields[] = {IDLER_FIELDS};
FIELDSET(profile_idler_fs, profile_idler_fields, NULL);

static void profile_points(ctx *c, const field *f, yaml_node_t *v, bd_mark key, const char *path,
                           void *base)
{
    bd_profile_def *p = base;
    char sub[PATH_LEN];
    (void)f, (void)key;
    if (!v || v->type != YAML_SEQUENCE_NODE || seq_len(v) < 2) {
        type_error(c, v, path, "a list of at least two [chainage, elevation] points");
        return;
    }
    int n = seq_len(v);
    p->points = calloc((size_t)n, sizeof *p->points);
    p->point_marks = calloc((size_t)n, sizeof *p->point_marks);
    if (!p->points || !p->point_marks) {
        err(c, mark_of(v), path, "out of memory");
        return;
    }
    p->point_count = n;
    for (int i = 0; i < n; i++) {
        yaml_node_t *item = node_at(c, v->data.sequence.items.start[i]);
        join_index(sub, path, i);
        p->point_marks[i] = mark_of(item);
        if (get_numbers(c, item, sub, 2, "a [chainage, elevation] point", p->points[i]))
            continue;
        if (i > 0 && !(p->points[i][0] > p->points[i - 1][0]))
            err(c, mark_of(item), sub, "expected a chainage > %g (chainage must increase from "
                "the tail to the head), got %g", p->points[i - 1][0], p->points[i][0]);
    }
}

static void profile_curve_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                               const char *path, void *base)
{
    (void)c, (void)fs, (void)found, (void)path;
    ((bd_profile_curve *)base)->mark = at;
}

static const field profile_curve_fields[] = {
    NUM("at", bd_profile_curve, at, REQ, 1.0, INFINITY),
    POS("radius", bd_profile_curve, radius, REQ),
};
FIELDSET(profile_curve_fs, profile_curve_fields, profile_curve_post);

static void init_profile_curve(void *p)
{
    memset(p, 0, sizeof(bd_profile_curve));
}

static const listspec profile_curve_list = {&profile_curve_fs, sizeof(bd_profile_curve),
                                            offsetof(bd_profile_def, curve_count),
                                            init_profile_curve, 0};

static const field profile_end_fields[] = {PULLEY_BODY_FIELDS};
FIELDSET(profile_end_fs, profile_end_fields, pulley_body_post);

static const char *const end_names[] = {"tail", "head", NULL};
_Static_assert(offsetof(bd_profile_takeup, t) == 0, "a profile's takeup parses as a takeup");
static const field profile_takeup_fields[] = {
    ENUM("at", bd_profile_takeup, at_head, REQ, end_names, NULL),
    TAKEUP_BODY_FIELDS,
    POS("depth", bd_profile_takeup, depth, 0),
};
FIELDSET(profile_takeup_fs, profile_takeup_fields, takeup_post);

static void profile_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                         const char *path, void *base)
{
    bd_profile_def *p = base;
    p->mark = at;
    (void)fs, (void)found;
    for (int i = 0; i < p->curve_count; i++) {
        const bd_profile_curve *cv = &p->curves[i];
        char sub[PATH_LEN];
        join(sub, path, "curves");
        if (cv->at != floor(cv->at) || cv->at > p->point_count - 2)
            err(c, cv->mark, sub, "[%d].at: expected the index of an inner point, 1 to %d, got %g",
                i, p->point_count - 2, cv->at);
        for (int j = 0; j < i; j++)
            if (p->curves[j].at == cv->at)
                err(c, cv->mark, sub, "[%d].at: point %g already has a curve (curves[%d])", i,
                    cv->at, j);
    }
}

static const field profile_fields[] = {
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

static void profile_fn(ctx *c, const field *f, yaml_node_t *v, bd_mark key, const char *path,
                       void *base)
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
        err(c, key, path, "give either pulleys or profile, not both");
        return;
    }
    int before = c->errors;
    parse_map(c, v, key, path, &profile_fs, &p);
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
static void idlers_fn(ctx *c, const field *f, yaml_node_t *v, bd_mark key, const char *path,
                      void *base)
{
    bd_model_def *m = base;
    (void)f;
    if (m->from_profile) {
        err(c, key, path, "give either idlers or a profile's carry_idlers and return_idlers, "
            "not both");
        return;
    }
    parse_list(c, &idler_list, v, path, base, offsetof(bd_model_def, idler_sets));
}

/* ---- material ---- */

static const field feed_fields[] = {
    SPAN("span", bd_material_def, feed_span, REQ),
    NUM("at", bd_material_def, feed_at, 0, 0.0, 1.0),
};
FIELDSET(feed_fs, feed_fields, NULL);

static void material_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                          const char *path, void *base)
{
    bd_material_def *mat = base;
    const bd_model_def *m = c->m;
    (void)path;
    mat->present = 1;
    mat->mark = at;
    if (!got(fs, found, "feed")) {
        /* the start of the first span (in travel order) that has idlers */
        mat->feed_span = m->idler_set_count > 0 ? m->idler_sets[0].span : 0;
        mat->feed_at = 0.0;
        for (int i = 1; i < m->idler_set_count; i++)
            if (m->idler_sets[i].span < mat->feed_span)
                mat->feed_span = m->idler_sets[i].span;
    }
    if (!got(fs, found, "discharge") && m->pulley_count > 0)
        mat->discharge = (mat->feed_span + 1) % m->pulley_count;
}

static const field material_fields[] = {
    NONNEG("mass_per_length", bd_material_def, mass_per_length, REQ),
    SUBMAP("feed", 0, &feed_fs),
    SPAN("discharge", bd_material_def, discharge, 0),
    BOOL("initially_loaded", bd_material_def, initially_loaded),
    BOOL("feeding", bd_material_def, feeding),
};
FIELDSET(material_fs, material_fields, material_post);

/* ---- design ---- */

static const field cema_fields[] = {
    POS("Kt", bd_cema_def, Kt, 0),
    NONNEG("Ai", bd_cema_def, Ai, 0),
};
FIELDSET(cema_fs, cema_fields, NULL);

static void skirts_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                        const char *path, void *base)
{
    (void)c, (void)fs, (void)found, (void)at, (void)path;
    ((bd_skirts_def *)base)->present = 1;
}

static const field skirts_fields[] = {
    POS("width", bd_skirts_def, width, REQ),
    POS("length", bd_skirts_def, length, REQ),
    NONNEG("mu_material", bd_skirts_def, mu_material, REQ),
    POS("mu_belt_material", bd_skirts_def, mu_belt_material, REQ),
};
FIELDSET(skirts_fs, skirts_fields, skirts_post);

static void cleaners_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                          const char *path, void *base)
{
    bd_cleaners_def *cl = base;
    yaml_node_t *n = got(fs, found, "count");
    char sub[PATH_LEN];
    (void)at;
    cl->present = 1;
    if (n && cl->count != floor(cl->count)) {
        join(sub, path, "count");
        err(c, mark_of(n), sub, "expected a whole number of cleaners, got %g", cl->count);
    }
}

static const field cleaners_fields[] = {
    NUM("count", bd_cleaners_def, count, REQ, 1.0, 1000.0),
    POS("width", bd_cleaners_def, width, REQ),
    POS("thickness", bd_cleaners_def, thickness, REQ),
    POS("pressure", bd_cleaners_def, pressure, REQ),
    NONNEG("mu", bd_cleaners_def, mu, REQ),
    SPAN("pulley", bd_cleaners_def, pulley, 0),
};
FIELDSET(cleaners_fs, cleaners_fields, cleaners_post);

static const field bearing_fields[] = {
    POS("bore", bd_bearing_def, bore, REQ),
    NONNEG("mass", bd_bearing_def, mass, 0),
};
FIELDSET(bearing_fs, bearing_fields, NULL);

/* design.bearings: a mapping from pulley names to {bore, mass}; mass
 * defaults to the pulley's own */
static void bearings_fn(ctx *c, const field *f, yaml_node_t *v, bd_mark key, const char *path,
                        void *base)
{
    bd_design_def *d = base;
    char sub[PATH_LEN];
    (void)f, (void)key;
    if (!v || v->type != YAML_MAPPING_NODE) {
        type_error(c, v, path, "a mapping from pulley names to {bore, mass}");
        return;
    }
    int n = (int)(v->data.mapping.pairs.top - v->data.mapping.pairs.start);
    if (n == 0)
        return;
    d->bearings = calloc((size_t)n, sizeof *d->bearings);
    if (!d->bearings) {
        err(c, mark_of(v), path, "out of memory");
        return;
    }
    for (yaml_node_pair_t *p = v->data.mapping.pairs.start; p < v->data.mapping.pairs.top; p++) {
        yaml_node_t *k = node_at(c, p->key);
        int i = -1;
        span_index(c, k, path, &i);   /* the key names a pulley, as a span does */
        if (i < 0)
            continue;
        join(sub, path, text_of(k));
        for (int j = 0; j < d->bearing_count; j++)
            if (d->bearings[j].pulley == i)
                err(c, mark_of(k), path, "duplicate pulley '%.60s'", text_of(k));
        bd_bearing_def *b = &d->bearings[d->bearing_count++];
        b->pulley = i;
        b->mass = c->m->pulleys[i].mass;
        b->mark = mark_of(k);
        parse_map(c, node_at(c, p->value), mark_of(k), sub, &bearing_fs, b);
    }
}

static void design_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                        const char *path, void *base)
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
            yaml_node_t *v = got(fs, found, one_by_one[k]);
            if (v)
                bd_diag_warning(c->diag, c->file, mark_of(v),
                                "%s.%s: used only with secondary: individual; the C factor "
                                "stands for it here", path, one_by_one[k]);
        }
        return;
    }
    /* what the resistances one by one need (model-format.md `design`) */
    char sub[PATH_LEN];
    join(sub, path, "secondary");
    if (d->standard == BD_STANDARD_CEMA)
        err(c, mark_of(got(fs, found, "secondary")), sub,
            "`individual` is DIN 22101 / ISO 5048's; with standard: cema use "
            "secondary: C (CEMA's accessories are its own)");
    if (!(m->belt.width > 0.0))
        err(c, mark_of(got(fs, found, "secondary")), sub,
            "`individual` needs belt.width (m) for the wrap resistance");
    if (!got(fs, found, "belt_thickness") && !(m->belt.thickness > 0.0))
        need(c, fs, found, at, path, "belt_thickness",
             "secondary: individual needs it for the wrap resistance, or belt.thickness");
    if (d->skirts.present && m->material.present && m->material.mass_per_length > 0.0)
        need(c, fs, found, at, path, "bulk_density",
             "the skirt resistances of a loaded belt need it");
}

static const field safety_fields[] = {
    POS("running", bd_safety_factor_def, running, 0),
    POS("starting", bd_safety_factor_def, starting, 0),
};
FIELDSET(safety_fs, safety_fields, NULL);

static const char *const standard_names[] = {"din22101", "iso5048", "cema", NULL};
static const char *const secondary_names[] = {"C", "individual", NULL};
static const char *const carcass_names[] = {"fabric", "steel_cord", NULL};
static const field design_fields[] = {
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

static void probe_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                       const char *path, void *base)
{
    bd_probe_def *p = base;
    p->mark = at;
    unique_name(c, got(fs, found, "name"), path, p->name, (const char *)c->m->simulation.probes,
                sizeof *p, offsetof(bd_probe_def, name));
}

static const field probe_fields[] = {
    STR("name", bd_probe_def, name, REQ | NONEMPTY),
    SPAN("span", bd_probe_def, span, REQ),
    NUM("at", bd_probe_def, at, REQ, 0.0, 1.0),
};
FIELDSET(probe_fs, probe_fields, probe_post);

static void init_probe(void *p)
{
    memset(p, 0, sizeof(bd_probe_def));
}

static const listspec probe_list = {&probe_fs, sizeof(bd_probe_def),
                                    offsetof(bd_simulation_def, probe_count), init_probe, 0};

static void simulation_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                            const char *path, void *base)
{
    bd_simulation_def *s = base;
    yaml_node_t *ts = got(fs, found, "time_step");
    yaml_node_t *ti = got(fs, found, "tension_interval");
    s->mark = at;
    if (ts)
        s->time_step_mark = mark_of(ts);
    /* tension.csv rows are a subset of the history rows */
    if (ti && s->tension_interval > 0.0 && s->tension_interval < s->output_interval * (1.0 - 1e-9)) {
        char sub[PATH_LEN];
        join(sub, path, "tension_interval");
        err(c, mark_of(ti), sub, "expected at least output_interval (%g s), got %g s",
            s->output_interval, s->tension_interval);
    }
}

static const char *const initial_names[] = {"static", "rest", NULL};
static const field simulation_fields[] = {
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

static void model_post(ctx *c, const fieldset *fs, yaml_node_t *const *found, bd_mark at,
                       const char *path, void *base)
{
    bd_model_def *m = base;
    const char *slash, *dot;
    size_t len;
    (void)path;
    if (!got(fs, found, "pulleys") && !got(fs, found, "profile"))
        err(c, at, "", "missing required key 'pulleys' (or 'profile')");
    if (got(fs, found, "name"))
        return;
    /* default name: the file's base name without extension */
    slash = strrchr(m->source, '/');
    slash = slash ? slash + 1 : m->source;
    dot = strrchr(slash, '.');
    len = dot && dot != slash ? (size_t)(dot - slash) : strlen(slash);
    if (len >= sizeof m->name)
        len = sizeof m->name - 1;
    memcpy(m->name, slash, len);
    m->name[len] = '\0';
}

/* table order is processing order: gravity before takeups, pulleys before
 * the idlers, material and probes that name them, idlers before material */
static const field model_fields[] = {
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

static void yaml_error(ctx *c, const yaml_parser_t *parser)
{
    bd_mark at;
    at.line = (int)parser->problem_mark.line + 1;
    at.column = (int)parser->problem_mark.column + 1;
    if (parser->context)
        err(c, at, "", "invalid YAML: %s (%s)", parser->problem ? parser->problem : "error",
            parser->context);
    else
        err(c, at, "", "invalid YAML: %s", parser->problem ? parser->problem : "out of memory");
}

int bd_model_load_string(const char *text, size_t len, const char *path, bd_model_def *out,
                         bd_diag *diag)
{
    yaml_parser_t parser;
    yaml_document_t doc;
    ctx c;
    memset(&c, 0, sizeof c);
    bd_model_def_init(out);
    snprintf(out->source, sizeof out->source, "%s", path ? path : "<string>");
    c.file = path ? path : "<string>";
    c.diag = diag;
    c.m = out;
    c.doc = &doc;
    if (!yaml_parser_initialize(&parser)) {
        err(&c, (bd_mark){0, 0}, "", "out of memory");
        return 1;
    }
    yaml_parser_set_input_string(&parser, (const unsigned char *)text, len);
    if (!yaml_parser_load(&parser, &doc)) {
        yaml_error(&c, &parser);
    } else {
        yaml_node_t *root = yaml_document_get_root_node(&doc);
        if (!root)
            err(&c, (bd_mark){1, 1}, "", "empty model: expected a mapping with belt and pulleys");
        else
            parse_map(&c, root, mark_of(root), "", &model_fs, out);
        yaml_document_delete(&doc);
        /* a model is one document: look for a second one or trailing junk */
        if (root && !yaml_parser_load(&parser, &doc)) {
            yaml_error(&c, &parser);
        } else if (root) {
            yaml_node_t *extra = yaml_document_get_root_node(&doc);
            if (extra)
                err(&c, mark_of(extra), "", "expected one YAML document, found another");
            yaml_document_delete(&doc);
        }
    }
    yaml_parser_delete(&parser);
    if (c.errors) {
        bd_model_def_free(out);
        snprintf(out->source, sizeof out->source, "%s", c.file);
        return 1;
    }
    return 0;
}

int bd_model_load(const char *path, bd_model_def *out, bd_diag *diag)
{
    char *text;
    size_t len;
    int rc;
    bd_model_def_init(out);
    snprintf(out->source, sizeof out->source, "%s", path);
    rc = bd_read_file(path, &text, &len);
    if (rc != BD_READ_OK) {
        const char *why = strerror(errno);
        if (rc == BD_READ_OPEN)
            bd_diag_error(diag, path, (bd_mark){0, 0}, "cannot open model file: %s", why);
        else if (rc == BD_READ_NOMEM)
            bd_diag_error(diag, path, (bd_mark){0, 0}, "out of memory reading the model file");
        else
            bd_diag_error(diag, path, (bd_mark){0, 0}, "cannot read model file: %s", why);
        return 1;
    }
    rc = bd_model_load_string(text, len, path, out, diag);
    free(text);
    return rc;
}
