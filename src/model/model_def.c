/* model definitions: diagnostics, tables, the defaults of model-format.md,
 * and init/free of a whole model description */
#include "beltdyn/model.h"
#include "base/constants.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- diagnostics ---- */

void bd_diag_init(bd_diag *d)
{
    memset(d, 0, sizeof *d);
}

void bd_diag_free(bd_diag *d)
{
    for (int i = 0; i < d->count + d->warning_count; i++)
        free(d->lines[i]);
    free(d->lines);
    bd_diag_init(d);
}

/* format "FILE:LINE:COL: KIND: MSG" (or "FILE: KIND: MSG" for a mark that
 * is not from the file, line 0) and append it; out of memory aborts */
static void diag_add(bd_diag *d, const char *file, bd_mark at, const char *kind,
                     const char *fmt, va_list ap)
{
    char msg[1024];
    char *line;
    size_t size;
    int n = d->count + d->warning_count;
    if (!file)
        file = "<input>";
    vsnprintf(msg, sizeof msg, fmt, ap);
    if (n >= d->capacity) {
        int cap = d->capacity ? 2 * d->capacity : 16;
        char **grown = realloc(d->lines, (size_t)cap * sizeof *grown);
        if (!grown)
            abort();
        d->lines = grown;
        d->capacity = cap;
    }
    size = strlen(file) + strlen(msg) + strlen(kind) + 64;
    line = malloc(size);
    if (!line)
        abort();
    if (at.line > 0)
        snprintf(line, size, "%s:%d:%d: %s: %s", file, at.line, at.column, kind, msg);
    else
        snprintf(line, size, "%s: %s: %s", file, kind, msg);
    d->lines[n] = line;
    if (strcmp(kind, "error") == 0)
        d->count++;
    else
        d->warning_count++;
}

void bd_diag_error(bd_diag *d, const char *file, bd_mark at, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    diag_add(d, file, at, "error", fmt, ap);
    va_end(ap);
}

void bd_diag_warning(bd_diag *d, const char *file, bd_mark at, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    diag_add(d, file, at, "warning", fmt, ap);
    va_end(ap);
}

/* ---- tables ---- */

double bd_table_eval(const bd_table *tab, double t)
{
    int lo, hi;
    double w;
    if (!tab || tab->n <= 0)
        return 0.0;
    if (tab->n == 1 || t <= tab->t[0])
        return tab->v[0];
    if (t >= tab->t[tab->n - 1])
        return tab->v[tab->n - 1];
    /* bisect for t[lo] <= t < t[hi] */
    lo = 0;
    hi = tab->n - 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (tab->t[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    w = (t - tab->t[lo]) / (tab->t[hi] - tab->t[lo]);
    return tab->v[lo] + w * (tab->v[hi] - tab->v[lo]);
}

void bd_table_free(bd_table *tab)
{
    free(tab->t);
    free(tab->v);
    tab->t = tab->v = NULL;
    tab->n = 0;
}

/* ---- defaults (model-format.md) ---- */

bd_belt_def bd_belt_default(void)
{
    bd_belt_def b;
    memset(&b, 0, sizeof b);
    b.formulation = BD_FORMULATION_DISCRETE;
    b.wrap_element_angle = 5.0 * BD_DEG;
    b.group_sections = 1;
    b.group_length = 10.0;
    return b;
}

bd_drive_def bd_drive_default(void)
{
    bd_drive_def d;
    memset(&d, 0, sizeof d);
    d.control = BD_CONTROL_SPEED;
    d.curve = BD_CURVE_SCURVE;
    d.start_time = 10.0;
    d.start_delay = 0.0;
    d.creep_speed = 0.0;
    d.max_torque = INFINITY;
    d.bandwidth = 2.0;
    d.stop_mode = BD_STOP_NONE;
    /* transmission defaults for its optional keys (see load.c) */
    d.transmission.v_belt = 0;
    d.transmission.sheave_angle = 38.0 * BD_DEG;
    d.transmission.friction = 0.5;
    d.transmission.velocity_threshold = 1e-3;
    d.transmission.force_threshold = 1e-3;
    return d;
}

bd_takeup_def bd_takeup_default(void)
{
    bd_takeup_def t;
    memset(&t, 0, sizeof t);
    t.type = BD_TAKEUP_GRAVITY;
    t.axis[0] = 0.0;
    t.axis[1] = -1.0;
    t.travel_min = -INFINITY;
    t.travel_max = INFINITY;
    return t;
}

bd_pulley_def bd_pulley_default(void)
{
    bd_pulley_def p;
    memset(&p, 0, sizeof p);
    p.wrap = 1;
    p.friction.mu_static = 0.35;
    p.friction.mu_dynamic = 0.30;
    p.velocity_threshold = 1e-3;
    p.force_threshold = 1e-3;
    p.drive = bd_drive_default();
    p.takeup = bd_takeup_default();
    return p;
}

bd_idler_set_def bd_idler_set_default(void)
{
    bd_idler_set_def s;
    memset(&s, 0, sizeof s);
    s.radius = 0.0635;
    s.inertia = 0.01;
    s.friction.mu_static = 0.5;
    s.friction.mu_dynamic = 0.4;
    return s;
}

bd_material_def bd_material_default(void)
{
    bd_material_def m;
    memset(&m, 0, sizeof m);
    m.discharge = 1;
    m.initially_loaded = 1;
    m.feeding = 1;
    return m;
}

bd_design_def bd_design_default(void)
{
    bd_design_def d;
    memset(&d, 0, sizeof d);
    d.standard = BD_STANDARD_DIN22101;
    d.f = 0.020;
    d.C = 0.0;
    d.speed = 0.0;
    d.sag_ratio = 0.01;
    /* the belt-strength check of DIN 22101 (steady running, and the
     * non-steady states: starts and stops); these defaults are
     * spec/model-format.md's */
    d.safety_factor.running = 6.7;
    d.safety_factor.starting = 4.8;
    d.efficiency = 1.0;
    d.cema.Kt = 1.0;
    d.cema.Ai = 0.0;
    d.cema.Kx_extra = -1.0;
    d.secondary = BD_SECONDARY_C;
    d.carcass = BD_CARCASS_FABRIC;
    d.cleaners.pulley = -1;
    return d;
}

bd_simulation_def bd_simulation_default(void)
{
    bd_simulation_def s;
    memset(&s, 0, sizeof s);
    s.duration = 10.0;
    s.time_step = 0.0;
    s.output_interval = 0.01;
    s.initial_state = BD_INITIAL_STATIC;
    s.stabilize = 0;
    return s;
}

double bd_tension_interval(const bd_simulation_def *s)
{
    return s->tension_interval > 0.0 ? s->tension_interval : s->output_interval;
}

int bd_tension_stride(const bd_simulation_def *s, double loop, double elements)
{
    double mean = loop / elements;
    if (!(s->tension_spacing > mean))
        return 1;
    return (int)fmin(floor(s->tension_spacing / mean + 0.5), elements);
}

void bd_model_def_init(bd_model_def *m)
{
    memset(m, 0, sizeof *m);
    m->gravity = 9.81;
    m->belt = bd_belt_default();
    m->material = bd_material_default();
    m->design = bd_design_default();
    m->simulation = bd_simulation_default();
}

void bd_model_def_free(bd_model_def *m)
{
    if (!m)
        return;
    for (int i = 0; m->pulleys && i < m->pulley_count; i++) {
        bd_table_free(&m->pulleys[i].drive.torque);
        bd_table_free(&m->pulleys[i].takeup.force);
        free(m->pulleys[i].route);
    }
    free(m->pulleys);
    free(m->idler_sets);
    free(m->simulation.probes);
    free(m->design.bearings);
    bd_model_def_init(m);
}

int bd_model_find_pulley(const bd_model_def *m, const char *name)
{
    for (int i = 0; name && i < m->pulley_count; i++)
        if (strcmp(m->pulleys[i].name, name) == 0)
            return i;
    return -1;
}
