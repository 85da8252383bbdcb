/* Design-standard calculation, the parts DIN 22101 / ISO 5048 and CEMA
 * share (model-format.md `design`, cli.md `static`): the belt loop cut into
 * sections with their masses, the drive and the takeup, the tension level
 * and its propagation along the travel, the slip and sag checks, and the
 * text and JSON outputs. */
#include "standards/standards_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "base/constants.h"
#include "base/json_util.h"


const char *bd_standard_name(bd_standard s)
{
    switch (s) {
    case BD_STANDARD_DIN22101: return "din22101";
    case BD_STANDARD_ISO5048: return "iso5048";
    case BD_STANDARD_CEMA: return "cema";
    }
    return "unknown";
}

static const char *standard_title(bd_standard s)
{
    switch (s) {
    case BD_STANDARD_DIN22101: return "DIN 22101";
    case BD_STANDARD_ISO5048: return "ISO 5048";
    case BD_STANDARD_CEMA: return "CEMA";
    }
    return "unknown";
}

/* ---- messages ---------------------------------------------------------- */

static void vappend(char ***list, int *count, const char *fmt, va_list ap)
{
    char buf[1024];
    vsnprintf(buf, sizeof buf, fmt, ap);
    char **grown = realloc(*list, (size_t)(*count + 1) * sizeof **list);
    if (!grown)
        return;
    *list = grown;
    size_t len = strlen(buf) + 1;
    grown[*count] = malloc(len);
    if (!grown[*count])
        return;
    memcpy(grown[*count], buf, len);
    (*count)++;
}

void bd_std_warn(bd_static_result *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vappend(&r->warnings, &r->warning_count, fmt, ap);
    va_end(ap);
}

void bd_std_note(bd_static_result *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vappend(&r->notes, &r->note_count, fmt, ap);
    va_end(ap);
}

/* ---- tensions ---------------------------------------------------------- */

double bd_std_total(const bd_std_ctx *c)
{
    double sum = 0.0;
    for (int k = 0; k < c->nsec; k++)
        sum += c->sec[k].main + c->sec[k].secondary + c->sec[k].slope + c->sec[k].pulley_res
             + c->sec[k].pulley_special + c->sec[k].local_secondary + c->sec[k].local_special;
    return sum;
}

/* first and last section of span i */
int bd_std_first_sec(const bd_std_ctx *c, int span)
{
    for (int k = 0; k < c->nsec; k++)
        if (c->sec[k].span == span)
            return k;
    return 0;
}

static int last_sec(const bd_std_ctx *c, int span)
{
    for (int k = c->nsec - 1; k >= 0; k--)
        if (c->sec[k].span == span)
            return k;
    return 0;
}

/* tension arriving at and leaving pulley p */
double bd_std_T_arrive(const bd_std_ctx *c, int p)
{
    return c->sec[last_sec(c, (p + c->n - 1) % c->n)].T1;
}

double bd_std_T_leave(const bd_std_ctx *c, int p)
{
    return c->sec[bd_std_first_sec(c, p)].T0;
}

void bd_std_propagate(bd_std_ctx *c)
{
    const bd_model_def *m = c->m;
    double Te = bd_std_total(c);
    double Te_drive = Te / (double)c->drive_count; /* equal share per drive */

    /* tensions relative to the start of span 0: each section adds its
     * resistance (eq 2.9: ΔT = F_H,i + F_N,i + F_St,i; CEMA eq 2.4); wraps
     * add none; every drive takes out its share of Te */
    double T = 0.0;
    for (int k = 0; k < c->nsec; k++) {
        bd_std_section *s = &c->sec[k];
        if (k > 0 && c->sec[k - 1].span != s->span && c->is_drive[s->span])
            T -= Te_drive;
        T += s->pulley_res + s->pulley_special;
        s->T0 = T;
        T += s->main + s->secondary + s->slope + s->local_secondary + s->local_special;
        s->T1 = T;
    }

    /* the level: offset added to every relative tension */
    double offset = 0.0;
    int level_set = 0;
    if (c->takeup >= 0) {
        int p = c->takeup;
        const bd_takeup_def *tu = &m->pulleys[p].takeup;
        const double *uin, *uout;
        bd_path_wrap_dirs(&c->path, p, &uin, &uout);
        double ci = uin[0] * tu->axis[0] + uin[1] * tu->axis[1];
        double co = uout[0] * tu->axis[0] + uout[1] * tu->axis[1];
        double rin = bd_std_T_arrive(c, p), rout = bd_std_T_leave(c, p);
        if (tu->type == BD_TAKEUP_FIXED) {
            /* fixed takeup: the belt's installed tension at that pulley (on
             * its slack side if it is also a drive) */
            double rel = rout;
            if (c->is_drive[p] && Te < 0.0)
                rel = rin;
            offset = m->belt.initial_tension - rel;
            level_set = 1;
            c->takeup_force = (rin + offset) * ci - (rout + offset) * co;
        } else if (fabs(ci - co) > 1e-9) {
            /* model-format.md: F = T_in·(u_in·a) - T_out·(u_out·a) along the
             * axis (equilibrium of the carriage), T = F/((u_in - u_out)·a)
             * when T_in = T_out */
            offset = (c->takeup_force - rin * ci + rout * co) / (ci - co);
            level_set = 1;
        }
    }
    if (!level_set) {
        /* no takeup: belt.initial_tension at the drive's slack side */
        int d = c->drive;
        double rel = Te >= 0.0 ? bd_std_T_leave(c, d) : bd_std_T_arrive(c, d);
        offset = m->belt.initial_tension - rel;
    }
    for (int k = 0; k < c->nsec; k++) {
        c->sec[k].T0 += offset;
        c->sec[k].T1 += offset;
    }
}

/* ---- set-up ------------------------------------------------------------ */

/* largest spacing (and its roll radius) and Σ rotating_mass/spacing of the
 * idler sets on span i */
static void span_idlers(const bd_model_def *m, int span, double *spacing, double *mR,
                        double *radius)
{
    *spacing = 0.0;
    *mR = 0.0;
    *radius = 0.0;
    for (int k = 0; k < m->idler_set_count; k++) {
        const bd_idler_set_def *is = &m->idler_sets[k];
        if (is->span != span || is->spacing <= 0.0)
            continue;
        if (is->spacing > *spacing) {
            *spacing = is->spacing;
            *radius = is->radius;
        }
        /* m'_R,i: rotating mass per metre of belt (model-format.md idlers) */
        *mR += is->rotating_mass / is->spacing;
    }
}

static double design_speed(const bd_std_ctx *c)
{
    if (c->design.speed != 0.0)
        return c->design.speed;
    const bd_pulley_def *p = &c->m->pulleys[c->drive];
    const bd_drive_def *d = &p->drive;
    switch (d->control) {
    case BD_CONTROL_SPEED:
        return d->speed;
    case BD_CONTROL_MOTOR:
        /* belt speed at rated motor speed: ω = 2π·n/60/gear ratio, v = ω·r */
        if (d->motor.gear_ratio > 0.0)
            return d->motor.rated_speed_rpm * 2.0 * BD_PI / 60.0 / d->motor.gear_ratio * p->radius;
        return 0.0;
    case BD_CONTROL_TORQUE:
        return 0.0;
    }
    return 0.0;
}

/* a rise (or run) below 1e-9 of the length it is over is none: rounding */
static double level_cut(double rise, double length)
{
    return fabs(rise) < 1e-9 * length ? 0.0 : rise;
}

/* the points of span sp at fractions a and b of its length */
static void span_points_at(const bd_path *path, const bd_path_segment *sp, double a, double b,
                           double pa[2], double pb[2])
{
    double t[2];
    bd_path_point(path, sp->s0 + a * sp->length, pa, t);
    if (b >= 1.0) {
        pb[0] = sp->p1[0];
        pb[1] = sp->p1[1];
    } else {
        bd_path_point(path, sp->s0 + b * sp->length, pb, t);
    }
}

static int build_sections(bd_std_ctx *c)
{
    const bd_model_def *m = c->m;
    int n = c->n;
    bd_static_result *r = c->out;
    int *loaded = calloc((size_t)n, sizeof *loaded);
    c->sec = calloc((size_t)(2 * n), sizeof *c->sec);
    if (!loaded || !c->sec) {
        free(loaded);
        return 1;
    }

    /* loaded spans: from the feed span to the discharge pulley */
    int feed = -1;
    c->feed_span = -1;
    double feed_at = 0.0;
    if (m->material.present && m->material.mass_per_length > 0.0) {
        feed = m->material.feed_span;
        feed_at = m->material.feed_at;
        if (feed < 0 || feed >= n) {
            /* default: start of the first span with idlers */
            feed = 0;
            for (int i = 0; i < n; i++) {
                double sp, mr, rr;
                span_idlers(m, i, &sp, &mr, &rr);
                if (sp > 0.0) {
                    feed = i;
                    break;
                }
            }
            feed_at = 0.0;
        }
        if (feed_at < 0.0)
            feed_at = 0.0;
        if (feed_at > 1.0)
            feed_at = 1.0;
        c->feed_span = feed;
        int dis = m->material.discharge;
        if (dis < 0 || dis >= n)
            dis = (feed + 1) % n;
        int j = feed;
        for (int guard = 0; guard < n; guard++) {
            loaded[j] = 1;
            j = (j + 1) % n;
            if (j == dis)
                break;
        }
    }

    /* loop orientation: Σ signed wraps = ±2π; the inner face of the belt
     * (the one the pulleys touch) is its left face on a ccw loop */
    double sweep = 0.0;
    for (int i = 0; i < n; i++)
        sweep += bd_path_arc(&c->path, i)->sweep;
    int orient = sweep > BD_PI ? 1 : (sweep < -BD_PI ? -1 : 0);

    /* sections: every span, the feed span cut at the feed point */
    int ns = 0;
    for (int i = 0; i < n; i++) {
        const bd_path_segment *sp = bd_path_span(&c->path, i);
        double spacing, mR, roll;
        span_idlers(m, i, &spacing, &mR, &roll);
        /* carrying run: loaded, or its idlers touch the belt's inner face
         * (idlers stand below the belt: the lower face is the right face
         * when travelling in +x, the left face in -x) */
        int carry = loaded[i];
        if (!carry && spacing > 0.0) {
            if (orient == 0)
                carry = 1;
            else
                carry = (orient < 0 && sp->dir[0] > 0.0) || (orient > 0 && sp->dir[0] < 0.0);
        }
        double cut[3] = {0.0, 1.0, 1.0};
        int parts = 1;
        if (i == feed && feed_at > 0.0 && feed_at < 1.0) {
            cut[1] = feed_at;
            parts = 2;
        }
        /* each section's rise and mean cos δ (∫cos δ ds over its length)
         * from its ends on the path, straight or routed; a rise below
         * 1e-9 of the length (1 µm per km) is level: the trigonometry's
         * rounding (~1e-16 on a level span) summed into F_St had read as
         * 1.6e-12 N */
        for (int q = 0; q < parts; q++) {
            bd_std_section *s = &c->sec[ns++];
            double frac = cut[q + 1] - cut[q];
            s->span = i;
            s->length = sp->length * frac;
            double pa[2], pb[2];
            span_points_at(&c->path, sp, cut[q], cut[q + 1], pa, pb);
            s->lift = level_cut(pb[1] - pa[1], s->length);
            /* and a vertical one has no main resistance, not 1e-14 N */
            s->cos_delta = s->length > 0.0 ? fabs(level_cut(pb[0] - pa[0], s->length)) / s->length
                                           : fabs(sp->dir[0]);
            /* the feed span carries material only behind the feed point */
            int load_here = loaded[i] && !(i == feed && (feed_at >= 1.0 || (parts == 2 && q == 0)));
            s->mL = load_here ? m->material.mass_per_length : 0.0;
            s->mR = mR;
            s->spacing = spacing;
            s->roll_radius = roll;
            s->carry = carry;
        }
        bd_static_span *os = &r->spans[i];
        os->pulley = i;
        os->to = (i + 1) % n;
        os->length_m = sp->length;
        os->lift_m = level_cut(sp->p1[1] - sp->p0[1], sp->length);
        os->slope_rad = atan2(os->lift_m, fabs(level_cut(sp->p1[0] - sp->p0[0], sp->length)));
        os->idler_spacing_m = spacing;
        os->mR_kg_per_m = mR;
        os->loaded = loaded[i];
        os->carry = carry;
    }
    c->nsec = ns;
    if (!m->material.present && orient == 0)
        bd_std_note(r, "the loop's orientation is ambiguous; every span with idlers "
                       "is taken as carrying run");
    free(loaded);
    return 0;
}

/* ---- checks ------------------------------------------------------------ */

static void checks(bd_std_ctx *c)
{
    const bd_model_def *m = c->m;
    bd_static_result *r = c->out;
    double Te = r->effective_tension_N;
    double Te_drive = Te / (double)c->drive_count;

    /* slip: Euler–Eytelwein, T2 ≥ |Te|/(e^(μφ) - 1) for every drive */
    for (int p = 0; p < c->n; p++) {
        if (!c->is_drive[p])
            continue;
        double mu = m->pulleys[p].friction.mu_dynamic;
        double phi = bd_path_wrap_angle(&c->path, p);
        double arr = bd_std_T_arrive(c, p), lea = bd_std_T_leave(c, p);
        double T2 = Te >= 0.0 ? lea : arr;   /* slack side */
        double need = mu * phi > 0.0 ? fabs(Te_drive) / (exp(mu * phi) - 1.0)
                                     : (Te_drive != 0.0 ? INFINITY : 0.0);
        if (p == c->drive) {
            r->T2_min_slip_N = need;
            r->wrap_angle_rad = phi;
            r->mu = mu;
        }
        if (T2 < need * (1.0 - 1e-12))
            bd_std_warn(r, "drive slips: pulley '%s' slack-side tension T2 = %.0f N is below "
                           "the %.0f N needed to transmit %.0f N without slip "
                           "(Euler-Eytelwein, mu = %.3g, wrap %.1f deg): raise the takeup "
                           "force or the wrap",
                        m->pulleys[p].name, T2, need, fabs(Te_drive), mu, phi * 180.0 / BD_PI);
    }

    /* sag between carry idlers: T ≥ (m'G + m'L)·g·a/(8·h/a) on every carry
     * span (loaded spans when there is material) */
    int has_material = 0;
    for (int i = 0; i < c->n; i++)
        has_material |= r->spans[i].loaded;
    double a = 0.0;
    for (int i = 0; i < c->n; i++) {
        const bd_static_span *s = &r->spans[i];
        if (has_material ? s->loaded : s->carry)
            a = fmax(a, s->idler_spacing_m);
    }
    double mLoad = has_material ? m->material.mass_per_length : 0.0;
    double sag = c->design.sag_ratio;
    r->sag_spacing_m = a;
    r->T_min_sag_N = sag > 0.0 ? (c->mG + mLoad) * c->g * a / (8.0 * sag) : 0.0;
    for (int i = 0; i < c->n; i++) {
        const bd_static_span *s = &r->spans[i];
        if (!(has_material ? s->loaded : s->carry) || s->idler_spacing_m <= 0.0)
            continue;
        double low = fmin(s->T_start_N, s->T_end_N);
        if (low < r->T_min_sag_N * (1.0 - 1e-12))
            bd_std_warn(r, "sag: span '%s' (to '%s') falls to %.0f N, below the %.0f N "
                           "that keeps the sag between idlers %.2f m apart within %.3g "
                           "of the spacing",
                        m->pulleys[s->pulley].name, m->pulleys[s->to].name, low,
                        r->T_min_sag_N, a, sag);
    }
    if (!has_material)
        bd_std_note(r, "no material: the carrying run is the spans whose idlers touch the "
                       "belt's inner (pulley-side) face; the sag check uses the belt alone");

    /* slack belt anywhere */
    if (r->T_min_N < 0.0)
        bd_std_warn(r, "slack belt: the tension falls to %.0f N (compression) on the path; "
                       "raise the takeup force", r->T_min_N);

    /* belt strength (DIN 22101's belt-strength check, steady state): the
     * steady-running tension against the rated one over the running
     * safety factor (design.safety_factor, model-format.md) */
    if (m->belt.rated_tension > 0.0 && r->T_max_N > m->belt.rated_tension)
        bd_std_warn(r, "belt overloaded: maximum tension %.0f N exceeds the rated tension %.0f N",
                    r->T_max_N, m->belt.rated_tension);
    else if (m->belt.rated_tension > 0.0
             && r->T_max_N > m->belt.rated_tension / m->design.safety_factor.running)
        bd_std_warn(r, "belt strength: maximum tension %.0f N exceeds the allowable in steady "
                       "running, rated %.0f N / safety factor %.3g = %.0f N",
                    r->T_max_N, m->belt.rated_tension, m->design.safety_factor.running,
                    m->belt.rated_tension / m->design.safety_factor.running);

    /* regenerative */
    if (Te < 0.0) {
        if (c->design.standard == BD_STANDARD_CEMA)
            bd_std_warn(r, "regenerative: effective tension %.0f N < 0: the load drives the "
                           "belt and the drive must brake %.1f kW; the tight side T1 is the "
                           "belt leaving pulley '%s'",
                        Te, fabs(r->power_kW), m->pulleys[c->drive].name);
        else
            bd_std_warn(r, "regenerative: effective tension %.0f N < 0: the load drives the "
                           "belt and the drive must brake %.1f kW; the tight side T1 is the "
                           "belt leaving pulley '%s'; DIN 22101 suggests f = 0.012-0.016 for "
                           "drives working as generators (f = %.4g used)",
                        Te, fabs(r->power_kW), m->pulleys[c->drive].name, c->design.f);
    }
}

/* ---- the calculation --------------------------------------------------- */

/* everything the calculation holds freed once its path is built, and
 * the failure said */
static int out_of_memory(bd_std_ctx *c, bd_diag *diag, bd_mark at)
{
    free(c->is_drive);
    free(c->sec);
    bd_path_free(&c->path);
    bd_static_free(c->out);
    bd_diag_error(diag, c->m->source, at, "static: out of memory");
    return 2;
}

int bd_static_compute(const bd_model_def *m, bd_static_result *out, bd_diag *diag)
{
    memset(out, 0, sizeof *out);
    out->drive_pulley = -1;
    out->takeup_pulley = -1;
    bd_mark at = m->design.present ? m->design.mark : (bd_mark){0, 0};
    if (m->pulley_count < 2) {
        bd_diag_error(diag, m->source, at, "static: the model needs at least two pulleys");
        return 2;
    }

    bd_std_ctx c;
    memset(&c, 0, sizeof c);
    c.m = m;
    c.out = out;
    c.n = m->pulley_count;
    c.g = m->gravity;
    c.mG = m->belt.mass_per_length;
    c.design = m->design.present ? m->design : bd_design_default();
    c.takeup = -1;
    out->standard = c.design.standard;
    if (!m->design.present)
        bd_std_note(out, "the model has no `design`: the defaults of model-format.md are used");

    /* the drive: the first pulley with `drive` */
    c.is_drive = calloc((size_t)c.n, sizeof *c.is_drive);
    out->spans = calloc((size_t)c.n, sizeof *out->spans);
    if (!c.is_drive || !out->spans) {
        free(c.is_drive);
        bd_static_free(out);
        bd_diag_error(diag, m->source, at, "static: out of memory");
        return 2;
    }
    out->span_count = c.n;
    c.drive = -1;
    for (int p = 0; p < c.n; p++) {
        if (m->pulleys[p].has_drive) {
            c.is_drive[p] = 1;
            c.drive_count++;
            if (c.drive < 0)
                c.drive = p;
        }
        if (m->pulleys[p].has_takeup) {
            if (c.takeup < 0)
                c.takeup = p;
            else
                bd_std_note(out, "takeup '%s' ignored: the first takeup ('%s') sets the "
                                 "tension level", m->pulleys[p].name, m->pulleys[c.takeup].name);
        }
    }
    if (c.drive < 0) {
        free(c.is_drive);
        bd_static_free(out);
        bd_diag_error(diag, m->source, at,
                      "static: no pulley has a `drive`; the design calculation needs one");
        return 2;
    }
    if (c.drive_count > 1)
        bd_std_note(out, "%d drives share the effective tension equally; T1, T2 and the "
                         "slip minimum shown are those of '%s'",
                    c.drive_count, m->pulleys[c.drive].name);

    /* speed */
    c.speed = design_speed(&c);
    if (c.speed < 0.0) {
        free(c.is_drive);
        bd_static_free(out);
        bd_diag_error(diag, m->source, at,
                      "static: design speed %.4g m/s is negative (reverse travel); give "
                      "the pulleys in the direction of travel", c.speed);
        return 2;
    }
    if (c.speed == 0.0)
        bd_std_warn(out, "no design speed (set design.speed or a speed-controlled drive): "
                         "power not computed");

    /* geometry */
    if (bd_path_build(m, &c.path, diag) != 0) {
        free(c.is_drive);
        bd_static_free(out);
        return 2;
    }
    if (build_sections(&c) != 0)
        return out_of_memory(&c, diag, at);

    /* takeup force at t = 0 */
    if (c.takeup >= 0) {
        const bd_pulley_def *tp = &m->pulleys[c.takeup];
        const bd_takeup_def *tu = &tp->takeup;
        if (tu->type != BD_TAKEUP_FIXED) {
            if (tu->force.n > 0)
                c.takeup_force = bd_table_eval(&tu->force, 0.0);
            else if (tu->type == BD_TAKEUP_GRAVITY)
                c.takeup_force = tu->mass * c.g; /* counterweight's weight */
            const double *uin, *uout;
            bd_path_wrap_dirs(&c.path, c.takeup, &uin, &uout);
            double den = (uin[0] - uout[0]) * tu->axis[0] + (uin[1] - uout[1]) * tu->axis[1];
            if (fabs(den) <= 1e-9)
                bd_std_warn(out, "takeup '%s': its axis is perpendicular to the belt's pull, "
                                 "so it cannot set the tension; belt.initial_tension at the "
                                 "drive's slack side is used", tp->name);
            if (tp->mass > 0.0 && fabs(tu->axis[1]) > 1e-12)
                bd_std_note(out, "takeup '%s': the pulley's own weight (%.0f N) is not added to "
                                 "the takeup force (model-format.md: T = force/((u_in - u_out)*a))",
                            tp->name, tp->mass * c.g);
        }
        out->takeup_pulley = c.takeup;
    } else {
        bd_std_note(out, "no takeup: the belt's initial_tension (%.0f N) is the tension at "
                         "the drive's slack side", m->belt.initial_tension);
    }

    /* resistances and tensions by the standard */
    out->f = c.design.f;
    if (c.design.standard == BD_STANDARD_CEMA) {
        bd_cema_resistances(&c);
    } else {
        /* C: given, or by Table 2.3 at the carrying run's length (cli.md) */
        double Lc = 0.0, Lmax = 0.0;
        for (int i = 0; i < c.n; i++) {
            if (out->spans[i].loaded)
                Lc += out->spans[i].length_m;
            Lmax = fmax(Lmax, out->spans[i].length_m);
        }
        if (Lc <= 0.0)
            Lc = Lmax;
        out->carry_length_m = Lc;
        if (c.design.secondary == BD_SECONDARY_INDIVIDUAL) {
            out->C = 0.0; /* not used: the resistances one by one */
        } else if (c.design.C > 0.0) {
            out->C = c.design.C;
        } else {
            out->C = bd_din22101_C(Lc);
            if (Lc < 80.0)
                bd_std_warn(out, "C auto: the conveyor is %.1f m long, below the 80 m of "
                                 "DIN 22101 Table 2.3; C = 1.92 is used, but secondary "
                                 "resistances should be computed one by one", Lc);
        }
        bd_din22101_resistances(&c);
        if (c.design.secondary != BD_SECONDARY_INDIVIDUAL) {
            bd_std_propagate(&c);
        } else if (bd_individual_resistances(&c) != 0) {
            return out_of_memory(&c, diag, at);
        }
    }

    /* results per span and in total */
    out->T_max_N = -INFINITY;
    out->T_min_N = INFINITY;
    double slope_abs = 0.0;
    for (int k = 0; k < c.nsec; k++) {
        const bd_std_section *s = &c.sec[k];
        bd_static_span *os = &out->spans[s->span];
        if (k == bd_std_first_sec(&c, s->span))
            os->T_start_N = s->T0;
        os->T_end_N = s->T1;
        os->main_N += s->main;
        os->secondary_N += s->secondary + s->pulley_res + s->local_secondary;
        os->special_N += s->pulley_special + s->local_special;
        os->slope_N += s->slope;
        if (s->mL > 0.0)
            os->loaded_length_m += s->length;
        if (s->carry || k == last_sec(&c, s->span)) {
            os->cema_Kx = s->Kx;
            os->cema_Ky = s->Ky;
        }
        out->main_N += s->main;
        out->secondary_N += s->secondary + s->pulley_res + s->local_secondary;
        out->special_N += s->pulley_special + s->local_special;
        out->slope_N += s->slope;
        slope_abs += fabs(s->slope);
        out->T_max_N = fmax(out->T_max_N, fmax(s->T0, s->T1));
        out->T_min_N = fmin(out->T_min_N, fmin(s->T0, s->T1));
    }
    /* rises and falls that cancel (a takeup loop's two vertical spans)
     * leave the rounding of their sum: below 1e-12 of the terms it is 0 */
    if (fabs(out->slope_N) <= 1e-12 * slope_abs)
        out->slope_N = 0.0;
    out->total_N = out->main_N + out->secondary_N + out->special_N + out->slope_N;
    /* eq 2.1 / ISO 5048 eq (1): Te = F_U = F_H + F_N + F_S + F_St (F_S = 0
     * unless the resistances are taken one by one) */
    out->effective_tension_N = out->total_N;
    out->regenerative = out->total_N < 0.0;
    out->speed_mps = c.speed;
    /* power at the drive pulley(s): P = Te·v (cli.md) */
    out->power_kW = out->effective_tension_N * c.speed / 1000.0;
    /* motor power P_M = P_T/η (cli.md `static --json`; DIN 22101's drive
     * power over the transmission efficiency) */
    out->motor_power_kW = out->power_kW / m->design.efficiency;
    out->drive_pulley = c.drive;
    out->drive_count = c.drive_count;
    {
        double arr = bd_std_T_arrive(&c, c.drive), lea = bd_std_T_leave(&c, c.drive);
        /* T1 tight side, T2 slack side; regenerative: the belt leaving the
         * braking drive is the tight side */
        out->T1_N = out->regenerative ? lea : arr;
        out->T2_N = out->regenerative ? arr : lea;
    }
    if (c.takeup >= 0)
        out->takeup_force_N = c.takeup_force;
    out->safety_factor = m->belt.rated_tension > 0.0 && out->T_max_N > 0.0
        ? m->belt.rated_tension / out->T_max_N : 0.0;
    checks(&c);

    free(c.is_drive);
    free(c.sec);
    bd_path_free(&c.path);
    return 0;
}

void bd_static_free(bd_static_result *r)
{
    if (!r)
        return;
    for (int i = 0; i < r->warning_count; i++)
        free(r->warnings[i]);
    for (int i = 0; i < r->note_count; i++)
        free(r->notes[i]);
    free(r->warnings);
    free(r->notes);
    free(r->spans);
    free(r->pulleys);
    memset(r, 0, sizeof *r);
}

/* ---- outputs ----------------------------------------------------------- */

void bd_static_print_table(const bd_static_result *r, const bd_model_def *m, FILE *f)
{
    const char *dname = r->drive_pulley >= 0 ? m->pulleys[r->drive_pulley].name : "-";
    fprintf(f, "%s: static tensions by %s\n", m->name[0] ? m->name : "model",
            standard_title(r->standard));
    if (r->standard == BD_STANDARD_CEMA)
        fprintf(f, "Kt = %.3g, Ai = %.3g N, C1 = %.2f (%d iterations)\n", r->cema_Kt,
                r->cema_Ai_N, r->cema_C1, r->cema_iterations);
    else if (r->individual)
        fprintf(f, "f = %.4g, secondary resistances one by one (ISO 5048 5.2; conveyor "
                   "length %.1f m)\n", r->f, r->carry_length_m);
    else
        fprintf(f, "f = %.4g, C = %.4g (conveyor length %.1f m)\n", r->f, r->C,
                r->carry_length_m);
    fprintf(f, "design speed %.3f m/s; drive '%s' (%d drive%s): wrap %.1f deg, mu %.3g\n\n",
            r->speed_mps, dname, r->drive_count, r->drive_count > 1 ? "s" : "",
            r->wrap_angle_rad * 180.0 / BD_PI, r->mu);

    fprintf(f, "%-34s %14.1f\n", "main resistance (N)", r->main_N);
    fprintf(f, "%-34s %14.1f\n", "secondary resistance (N)", r->secondary_N);
    if (r->individual) {
        /* the parts of F_N, then F_S and its parts (indented) */
        const struct {
            const char *label;
            double value;
        } parts[] = {{"  loading point inertia F_bA (N)", r->loading_inertia_N},
                     {"  skirts, acceleration zone F_f (N)", r->loading_skirts_N},
                     {"  wrap over pulleys (N)", r->wrap_N},
                     {"  pulley bearings (N)", r->bearings_N},
                     {"special resistance (N)", r->special_N},
                     {"  skirts, whole length F_gl (N)", r->skirts_N},
                     {"  belt cleaners F_r (N)", r->cleaners_N}};
        for (size_t i = 0; i < sizeof parts / sizeof parts[0]; i++)
            fprintf(f, "%-34s %14.1f\n", parts[i].label, parts[i].value);
    }
    fprintf(f, "%-34s %14.1f\n", "slope resistance (N)", r->slope_N);
    fprintf(f, "%-34s %14.1f\n", "total resistance (N)", r->total_N);
    fprintf(f, "%-34s %14.1f%s\n", "effective tension Te (N)", r->effective_tension_N,
            r->regenerative ? "  regenerative" : "");
    fprintf(f, "%-34s %14.3f\n", "power at the drive (kW)", r->power_kW);
    fprintf(f, "%-34s %14.3f\n", "motor power, / efficiency (kW)", r->motor_power_kW);
    fprintf(f, "%-34s %14.1f\n", "T1 tight side (N)", r->T1_N);
    fprintf(f, "%-34s %14.1f\n", "T2 slack side (N)", r->T2_N);
    fprintf(f, "%-34s %14.1f\n", "T2 minimum for no slip (N)", r->T2_min_slip_N);
    fprintf(f, "%-34s %14.1f\n", "T minimum for sag (N)", r->T_min_sag_N);
    fprintf(f, "%-34s %14.1f\n", "takeup force (N)", r->takeup_force_N);
    fprintf(f, "%-34s %14.1f\n", "maximum tension (N)", r->T_max_N);
    if (r->safety_factor > 0.0)
        fprintf(f, "%-34s %14.2f\n", "safety factor (rated/max) (-)", r->safety_factor);

    fprintf(f, "\n%-12s %-12s %10s %9s %9s %6s %12s %12s %12s %12s %12s\n", "span", "to",
            "length (m)", "lift (m)", "slope(deg)", "loaded", "main (N)", "second. (N)",
            "slope (N)", "T start (N)", "T end (N)");
    for (int i = 0; i < r->span_count; i++) {
        const bd_static_span *s = &r->spans[i];
        fprintf(f, "%-12s %-12s %10.3f %9.3f %9.2f %6s %12.1f %12.1f %12.1f %12.1f %12.1f\n",
                m->pulleys[s->pulley].name, m->pulleys[s->to].name, s->length_m, s->lift_m,
                s->slope_rad * 180.0 / BD_PI, s->loaded ? "yes" : (s->carry ? "carry" : "no"),
                s->main_N, s->secondary_N, s->slope_N, s->T_start_N, s->T_end_N);
    }
    if (r->individual) {
        fprintf(f, "\n%-12s %12s %12s %12s %12s %12s\n", "pulley", "T in (N)", "T out (N)",
                "wrap (N)", "bearing (N)", "cleaners (N)");
        for (int i = 0; i < r->span_count; i++) {
            const bd_static_pulley *p = &r->pulleys[i];
            fprintf(f, "%-12s %12.1f %12.1f %12.1f %12.1f %12.1f\n", m->pulleys[i].name,
                    p->T_in_N, p->T_out_N, p->wrap_N, p->bearing_N, p->cleaners_N);
        }
        if (r->acceleration_length_m > 0.0)
            fprintf(f, "acceleration length at the feed point l_b = %.3f m\n",
                    r->acceleration_length_m);
    }
    fprintf(f, "\nwarnings: %s\n", r->warning_count ? "" : "none");
    for (int i = 0; i < r->warning_count; i++)
        fprintf(f, "  - %s\n", r->warnings[i]);
    if (r->note_count) {
        fprintf(f, "notes:\n");
        for (int i = 0; i < r->note_count; i++)
            fprintf(f, "  - %s\n", r->notes[i]);
    }
}

/* a number that JSON can hold (non-finite values become null) */
static cJSON *string_array(char **items, int count)
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; i < count; i++)
        cJSON_AddItemToArray(a, cJSON_CreateString(items[i]));
    return a;
}

char *bd_static_to_json(const bd_static_result *r, const bd_model_def *m)
{
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    /* cli.md `static --json` keys */
    cJSON_AddStringToObject(o, "standard", bd_standard_name(r->standard));
    cJSON *res = cJSON_AddObjectToObject(o, "resistances_N");
    bd_json_add_number(res, "main", r->main_N);
    bd_json_add_number(res, "secondary", r->secondary_N);
    bd_json_add_number(res, "slope", r->slope_N);
    bd_json_add_number(res, "total", r->total_N);
    if (r->individual) {
        /* cli.md: the resistances one by one; secondary = the first four */
        bd_json_add_number(res, "loading_inertia", r->loading_inertia_N);
        bd_json_add_number(res, "loading_skirts", r->loading_skirts_N);
        bd_json_add_number(res, "wrap", r->wrap_N);
        bd_json_add_number(res, "bearings", r->bearings_N);
        bd_json_add_number(res, "skirts", r->skirts_N);
        bd_json_add_number(res, "cleaners", r->cleaners_N);
        bd_json_add_number(res, "special", r->special_N);
    }
    bd_json_add_number(o, "effective_tension_N", r->effective_tension_N);
    bd_json_add_number(o, "power_kW", r->power_kW);
    bd_json_add_number(o, "motor_power_kW", r->motor_power_kW);
    bd_json_add_number(o, "T1_N", r->T1_N);
    bd_json_add_number(o, "T2_N", r->T2_N);
    bd_json_add_number(o, "T2_min_slip_N", r->T2_min_slip_N);
    bd_json_add_number(o, "T_min_sag_N", r->T_min_sag_N);
    bd_json_add_number(o, "takeup_force_N", r->takeup_force_N);
    cJSON *spans = cJSON_AddArrayToObject(o, "spans");
    for (int i = 0; i < r->span_count; i++) {
        const bd_static_span *s = &r->spans[i];
        cJSON *js = cJSON_CreateObject();
        cJSON_AddStringToObject(js, "from", m->pulleys[s->pulley].name);
        bd_json_add_number(js, "length_m", s->length_m);
        bd_json_add_number(js, "T_start_N", s->T_start_N);
        bd_json_add_number(js, "T_end_N", s->T_end_N);
        /* extra keys */
        cJSON_AddStringToObject(js, "to", m->pulleys[s->to].name);
        bd_json_add_number(js, "lift_m", s->lift_m);
        bd_json_add_number(js, "slope_deg", s->slope_rad * 180.0 / BD_PI);
        cJSON_AddBoolToObject(js, "loaded", s->loaded);
        cJSON_AddBoolToObject(js, "carry", s->carry);
        bd_json_add_number(js, "main_N", s->main_N);
        bd_json_add_number(js, "secondary_N", s->secondary_N);
        bd_json_add_number(js, "slope_N", s->slope_N);
        if (r->individual)
            bd_json_add_number(js, "special_N", s->special_N);
        if (r->standard == BD_STANDARD_CEMA) {
            bd_json_add_number(js, "Kx_N_per_m", s->cema_Kx);
            bd_json_add_number(js, "Ky", s->cema_Ky);
        }
        cJSON_AddItemToArray(spans, js);
    }
    cJSON_AddItemToObject(o, "warnings", string_array(r->warnings, r->warning_count));

    /* extra keys */
    cJSON_AddStringToObject(o, "model", m->name);
    bd_json_add_number(o, "speed_mps", r->speed_mps);
    cJSON_AddBoolToObject(o, "regenerative", r->regenerative);
    cJSON_AddStringToObject(o, "drive", r->drive_pulley >= 0 ? m->pulleys[r->drive_pulley].name : "");
    cJSON_AddNumberToObject(o, "drive_count", r->drive_count);
    bd_json_add_number(o, "wrap_angle_deg", r->wrap_angle_rad * 180.0 / BD_PI);
    bd_json_add_number(o, "mu", r->mu);
    bd_json_add_number(o, "sag_idler_spacing_m", r->sag_spacing_m);
    bd_json_add_number(o, "T_max_N", r->T_max_N);
    bd_json_add_number(o, "T_min_N", r->T_min_N);
    if (r->safety_factor > 0.0)
        bd_json_add_number(o, "safety_factor", r->safety_factor);
    if (r->takeup_pulley >= 0)
        cJSON_AddStringToObject(o, "takeup", m->pulleys[r->takeup_pulley].name);
    if (r->standard == BD_STANDARD_CEMA) {
        cJSON *ce = cJSON_AddObjectToObject(o, "cema");
        bd_json_add_number(ce, "Kt", r->cema_Kt);
        bd_json_add_number(ce, "Ai_N", r->cema_Ai_N);
        bd_json_add_number(ce, "C1", r->cema_C1);
        cJSON_AddNumberToObject(ce, "iterations", r->cema_iterations);
    } else {
        bd_json_add_number(o, "f", r->f);
        if (r->individual) {
            cJSON_AddStringToObject(o, "secondary", "individual");
            bd_json_add_number(o, "acceleration_length_m", r->acceleration_length_m);
            cJSON *ps = cJSON_AddArrayToObject(o, "pulleys");
            for (int i = 0; i < r->span_count; i++) {
                const bd_static_pulley *p = &r->pulleys[i];
                cJSON *jp = cJSON_CreateObject();
                cJSON_AddStringToObject(jp, "name", m->pulleys[i].name);
                bd_json_add_number(jp, "T_in_N", p->T_in_N);
                bd_json_add_number(jp, "T_out_N", p->T_out_N);
                bd_json_add_number(jp, "wrap_N", p->wrap_N);
                bd_json_add_number(jp, "bearing_N", p->bearing_N);
                bd_json_add_number(jp, "cleaners_N", p->cleaners_N);
                cJSON_AddItemToArray(ps, jp);
            }
        } else {
            cJSON_AddStringToObject(o, "secondary", "C");
        }
        bd_json_add_number(o, "C", r->C);
        bd_json_add_number(o, "conveyor_length_m", r->carry_length_m);
    }
    cJSON_AddItemToObject(o, "notes", string_array(r->notes, r->note_count));

    char *text = cJSON_Print(o);
    cJSON_Delete(o);
    return text;
}
