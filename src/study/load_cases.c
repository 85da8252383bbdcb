/* The standard load cases of a conveyor (`beltdyn cases`, cli.md): each a
 * model of its own, the model file's with its material and drives set so:
 *
 *   empty_start         no material; the drives' start as the model has it
 *   loaded_start        loaded from feed to discharge, feeding
 *   loaded_coast_stop   loaded_start, then every drive switched off at t_stop
 *                       (power failure): the belt coasts to rest
 *   loaded_brake_stop   the same with every drive braking at t_stop
 *   partial_load_start  the worst partial loading for the profile: loaded
 *                       only from the point of the carrying run beyond which
 *                       the material needs the most drive force (on an
 *                       incline ending on a decline, the incline's top part
 *                       and not the decline), not feeding during the start
 *
 * t_stop is when the conveyor runs steadily: the last speed drive's start
 * delay + start time + max(2 s, 20 % of the start time); without a speed
 * drive, the model's simulation.duration. The stop cases run until the
 * belt has stopped (every pulley's surface below 0.02 m/s for 0.5 s), at
 * most five times the stopping time the static calculation expects (the
 * coast-down time v·M/F_U, the braking time v·M/(F_U + F_B/R), M the
 * moving mass reduced to the belt) plus 10 s — a run's own resistance may
 * be well below the standard's F_U — and their records (peaks, monitors,
 * envelope) start at t_stop, so their rows are the stop's. The brake: the model's own `stop: {mode: brake}` torque
 * when a drive has one, else 1.5 × the drive's share of the steady-running
 * torque F_U·R (a common sizing; say it in the case's setup column). */
#include "study/study_case.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "beltdyn/standards.h"
#include "model/path.h"

#define SETTLE_MIN 2.0        /* s after the start curve */
#define SETTLE_FRACTION 0.2   /* of the start time */
#define STOP_MARGIN 5.0       /* × the estimated stopping time, at most */
#define STOP_EXTRA 10.0       /* s */
#define BRAKE_FACTOR 1.5      /* × steady-running torque, when the model has none */
#define PARTIAL_PIECES 400    /* samples of the loaded region */

static const char *const case_names[BD_LOAD_CASES] = {
    "empty_start", "loaded_start", "loaded_coast_stop", "loaded_brake_stop",
    "partial_load_start"};

/* s, the rigid belt's stopping time from speed v, mass M under a
 * retarding force F: v·M/F (Newton); 60 s when nothing retards it (a
 * resistance-free model: the case then still ends) */
static double stop_time(double v, double M, double F)
{
    return F > 0.0 ? v * M / F : 60.0;
}

/* when the conveyor runs steadily after its start (see above) */
static double steady_time(const bd_model_def *def)
{
    double t = -1.0;
    for (int i = 0; i < def->pulley_count; i++) {
        const bd_drive_def *d = &def->pulleys[i].drive;
        if (!def->pulleys[i].has_drive || d->control != BD_CONTROL_SPEED)
            continue;
        double ti = d->start_delay + d->start_time
                  + fmax(SETTLE_MIN, SETTLE_FRACTION * d->start_time);
        t = fmax(t, ti);
    }
    return t > 0.0 ? t : def->simulation.duration;
}

/* the moving mass reduced to the belt, kg: belt, material on it, idler
 * rolls (Σ m'_R·L), pulleys and drives (J/R²) */
static double moving_mass(const bd_model_def *def, const bd_static_result *r, double loop)
{
    double M = def->belt.mass_per_length * loop;
    for (int i = 0; i < r->span_count; i++)
        M += r->spans[i].mR_kg_per_m * r->spans[i].length_m
           + (def->material.present ? def->material.mass_per_length * r->spans[i].loaded_length_m
                                    : 0.0);
    for (int i = 0; i < def->pulley_count; i++) {
        const bd_pulley_def *p = &def->pulleys[i];
        double J = p->inertia + (p->has_drive ? p->drive.inertia : 0.0);
        if (p->radius > 0.0)
            M += J / (p->radius * p->radius);
    }
    return M;
}

/* the feed point of the worst partial loading: the point of the loaded
 * region beyond which the material's drive force, Σ m'_L·g·(f·cos δ·ds +
 * dy) to the discharge, is largest; as (span, at), and its distance from
 * the model's feed point along the path, m */
static double worst_feed(const bd_model_def *def, const bd_path *path, double f, int *span,
                         double *at)
{
    double s0, len;
    bd_path_loaded_region(path, &def->material, &s0, &len);
    double best = 0.0, suffix = 0.0, s_best = s0;
    double ds = len / PARTIAL_PIECES;
    /* suffix sums from the discharge back to the feed point */
    for (int k = PARTIAL_PIECES - 1; k >= 0; k--) {
        double pa[2], pb[2], t[2];
        bd_path_point(path, fmod(s0 + k * ds, path->length), pa, t);
        bd_path_point(path, fmod(s0 + (k + 1) * ds, path->length), pb, t);
        double dx = pb[0] - pa[0], dy = pb[1] - pa[1];
        suffix += f * fabs(dx) + dy;   /* f·cos δ·ds + dy, per m'_L·g */
        if (suffix > best) {
            best = suffix;
            s_best = s0 + k * ds;
        }
    }
    /* onto the span it lies on (the start of the span after it when on a
     * wrap: a wrap's segment and the next span share the pulley's index) */
    double s = fmod(s_best, path->length);
    const bd_path_segment *seg = &path->segments[bd_path_segment_at(path, s)];
    *span = seg->pulley;
    *at = seg->kind == BD_SEGMENT_SPAN && seg->length > 0.0 ? (s - seg->s0) / seg->length : 0.0;
    *at = fmin(fmax(*at, 0.0), 1.0);
    return fmod(bd_path_span_s(path, *span, *at) - s0 + path->length, path->length);
}

int bd_load_cases_make(bd_study *s, double **cost, char *err, size_t errlen)
{
    const bd_model_def *m = &s->def;
    s->n = BD_LOAD_CASES;
    s->cases = calloc((size_t)s->n, sizeof *s->cases);
    s->case_defs = calloc((size_t)s->n, sizeof *s->case_defs);
    *cost = calloc((size_t)s->n, sizeof **cost);
    if (!s->cases || !s->case_defs || !*cost) {
        snprintf(err, errlen, "out of memory");
        return BD_RUN_FAILED;
    }
    int drives = 0;
    for (int i = 0; i < m->pulley_count; i++)
        drives += m->pulleys[i].has_drive;
    if (drives == 0) {
        snprintf(err, errlen, "%s: no pulley has a drive: the load cases start and stop the "
                 "conveyor by its drives", s->opt->model_path);
        return BD_RUN_BAD_INPUT;
    }

    /* the steady running the stops start from: the static calculation */
    bd_static_result r;
    bd_diag diag;
    bd_diag_init(&diag);
    bd_path path;
    memset(&path, 0, sizeof path);
    int computed = bd_static_compute(m, &r, &diag) == 0;
    if (!computed || bd_path_build(m, &path, &diag) != 0) {
        snprintf(err, errlen, "%s: the load cases need the static calculation, which failed: "
                 "%.600s", s->opt->model_path, diag.count ? diag.lines[0] : "");
        if (computed)
            bd_static_free(&r);
        bd_diag_free(&diag);
        bd_path_free(&path);
        return BD_RUN_BAD_INPUT;
    }
    bd_diag_free(&diag);
    double t_stop = steady_time(m);
    double v = r.speed_mps > 0.0 ? r.speed_mps : 1.0;
    double M = moving_mass(m, &r, path.length);
    double Fu = fabs(r.effective_tension_N);
    double t_coast = stop_time(v, M, Fu);

    for (int j = 0; j < s->n; j++) {
        bd_study_case *c = &s->cases[j];
        bd_model_def *d = &s->case_defs[j];
        bd_diag dg;
        bd_diag_init(&dg);
        int bad = bd_model_load_string(s->text, s->text_len, s->opt->model_path, d, &dg);
        bd_diag_free(&dg);
        if (bad) {
            snprintf(err, errlen, "%s: the model has errors", s->opt->model_path);
            bd_static_free(&r);
            bd_path_free(&path);
            return BD_RUN_BAD_INPUT;
        }
        snprintf(c->name, sizeof c->name, "%s", case_names[j]);
        c->status = -1;
        c->duration = fmax(d->simulation.duration, t_stop);
        bd_material_def *mat = &d->material;
        int loaded = mat->present && mat->mass_per_length > 0.0;
        switch (j) {
        case 0:
            mat->present = 0;
            snprintf(c->setup, sizeof c->setup, "no material; the model's start");
            break;
        case 1:
            mat->initially_loaded = 1;
            mat->feeding = 1;
            snprintf(c->setup, sizeof c->setup, loaded ? "loaded from feed to discharge, "
                     "feeding; the model's start" : "the model has no material: as empty_start");
            break;
        case 2:
        case 3: {
            mat->initially_loaded = 1;
            mat->feeding = 1;
            double brake_total = 0.0;
            int own_brake = 0;
            for (int i = 0; i < d->pulley_count; i++)
                if (d->pulleys[i].has_drive && d->pulleys[i].drive.stop_mode == BD_STOP_BRAKE
                    && d->pulleys[i].drive.brake_torque > 0.0)
                    own_brake = 1;
            for (int i = 0; i < d->pulley_count; i++) {
                bd_pulley_def *p = &d->pulleys[i];
                if (!p->has_drive)
                    continue;
                bd_drive_def *dr = &p->drive;
                dr->stop_at = t_stop;
                if (j == 2) {
                    dr->stop_mode = BD_STOP_COAST;
                    continue;
                }
                if (!(own_brake && dr->stop_mode == BD_STOP_BRAKE && dr->brake_torque > 0.0))
                    dr->brake_torque = own_brake ? 0.0 : BRAKE_FACTOR * Fu / drives * p->radius;
                dr->stop_mode = dr->brake_torque > 0.0 ? BD_STOP_BRAKE : BD_STOP_COAST;
                if (p->radius > 0.0)
                    brake_total += dr->brake_torque / p->radius;
            }
            double t_window = j == 2 ? t_coast : stop_time(v, M, Fu + brake_total);
            c->duration = t_stop + STOP_MARGIN * t_window + STOP_EXTRA;
            c->records_from = t_stop;
            if (j == 2)
                snprintf(c->setup, sizeof c->setup, "loaded; drives off at %.3g s (power "
                         "failure), coast-down ~%.3g s", t_stop, t_coast);
            else if (own_brake)
                snprintf(c->setup, sizeof c->setup, "loaded; drives brake at %.3g s with %.4g N "
                         "at the belt (the model's brakes), braking ~%.3g s", t_stop,
                         brake_total, t_window);
            else
                snprintf(c->setup, sizeof c->setup, "loaded; drives brake at %.3g s with %.4g N "
                         "at the belt (%g x running torque), braking ~%.3g s", t_stop,
                         brake_total, BRAKE_FACTOR, t_window);
            break;
        }
        case 4: {
            if (!loaded) {
                snprintf(c->setup, sizeof c->setup, "the model has no material: as empty_start");
                break;
            }
            int span;
            double at;
            double from = worst_feed(d, &path, r.f > 0.0 ? r.f : 0.02, &span, &at);
            mat->feed_span = span;
            mat->feed_at = at;
            mat->initially_loaded = 1;
            mat->feeding = 0;
            snprintf(c->setup, sizeof c->setup, "loaded from %.4g m past the feed point (span "
                     "'%s' at %.3f) to the discharge, not feeding; the model's start", from,
                     d->pulleys[span].name, at);
            break;
        }
        }
        d->simulation.duration = c->duration;
        (*cost)[j] = bd_study_case_cost(d, c->duration);
    }
    bd_static_free(&r);
    bd_path_free(&path);
    return BD_RUN_OK;
}
