/* The pass/fail table (io/checks.h). Each check is one a conveyor
 * engineer signs a design off with:
 *   - belt strength in starts and stops: the run's peak tension against
 *     belt.rated_tension / safety_factor.starting (DIN 22101's non-steady
 *     states);
 *   - belt strength in steady running: the static maximum against
 *     rated / safety_factor.running;
 *   - slip margin: the static slack-side tension T2 against the least
 *     that keeps the drive from slipping, Te/(e^(μφ) − 1) (Euler–Eytelwein);
 *   - sag: the static lowest tension of the carrying run against
 *     (m'G + m'L)·g·a/(8·sag_ratio);
 *   - drive slip in the run (the drive monitor's confirmed slip);
 *   - the dynamic slip margin: the most of its wrap's friction a drive
 *     used in the run, ln(T_hi/T_lo)/(μ_s·φ) (Euler–Eytelwein; the belt
 *     begins to slip at 100 %);
 *   - the drive's peak torque while driving against its max_torque:
 *     reaching it, the speed loop was saturated and could not follow its
 *     start (a brake's torque after a stop is not the drive's);
 *   - takeup travel against the takeup's travel limits, when given;
 *   - lift-off from the idlers (the 2D belts);
 *   - the run's energy balance (a trust check: 1 %);
 *   - the steady running force against the model's own resistance law,
 *     when the run ends in steady running (a trust check: 3 % for the
 *     discrete and rfe belts, 1 % for the axial and moving-node belts;
 *     sensors/running.c). */
#include "io/checks.h"

#include "parts/parts.h"
#include "sensors/sensors.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

const char *bd_check_rule_name(bd_check_rule rule)
{
    return rule == BD_CHECK_AT_LEAST ? "at least" : rule == BD_CHECK_BELOW ? "below"
         : rule == BD_CHECK_ABOVE ? "above" : "at most";
}

/* four for the belt and the static design, one for lift-off, one for the
 * energy balance, one for the running force; per pulley three for a drive
 * and two for a takeup */
int bd_run_checks_max(const bd_sim *sim)
{
    return 7 + 5 * sim->model->pulley_count;
}

static void add(bd_check *out, int *n, int max, const char *name, const char *unit, double value,
                double limit, bd_check_rule rule)
{
    if (*n >= max)
        return;
    bd_check *c = &out[(*n)++];
    snprintf(c->name, sizeof c->name, "%s", name);
    snprintf(c->unit, sizeof c->unit, "%s", unit);
    c->value = value;
    c->limit = limit;
    c->rule = rule;
    c->pass = rule == BD_CHECK_AT_MOST ? value <= limit
            : rule == BD_CHECK_AT_LEAST ? value >= limit
            : rule == BD_CHECK_BELOW ? value < limit : value > limit;
}

int bd_run_checks(const bd_sim *sim, const bd_static_result *st, bd_check *out, int max)
{
    const bd_model_def *def = sim->model->def;
    const double rated = def->belt.rated_tension;
    int n = 0;
    if (rated > 0.0 && sim->tension_max > -INFINITY)
        add(out, &n, max, "belt strength, starts and stops", "N", sim->tension_max,
            rated / def->design.safety_factor.starting, BD_CHECK_AT_MOST);
    if (st) {
        if (rated > 0.0)
            add(out, &n, max, "belt strength, steady running (static)", "N", st->T_max_N,
                rated / def->design.safety_factor.running, BD_CHECK_AT_MOST);
        add(out, &n, max, "slip margin, T2 (static)", "N", st->T2_N, st->T2_min_slip_N,
            BD_CHECK_AT_LEAST);
        double low = INFINITY;
        for (int i = 0; i < st->span_count; i++)
            if (st->spans[i].loaded || st->spans[i].carry)
                low = fmin(low, fmin(st->spans[i].T_start_N, st->spans[i].T_end_N));
        if (isfinite(low) && st->T_min_sag_N > 0.0)
            add(out, &n, max, "sag, carrying run (static)", "N", low, st->T_min_sag_N,
                BD_CHECK_AT_LEAST);
    }
    for (int i = 0; i < sim->model->pulley_count; i++) {
        const bd_pulley_body *p = &sim->pulleys[i];
        const bd_pulley_def *pd = &def->pulleys[i];
        char name[112];
        if (pd->has_drive) {
            /* slip counts once it lasts BD_SLIP_TIME (the monitor's rule) */
            snprintf(name, sizeof name, "drive slip, %s", pd->name);
            add(out, &n, max, name, "s", p->mon.slip_longest, BD_SLIP_TIME, BD_CHECK_BELOW);
            snprintf(name, sizeof name, "drive friction used, %s", pd->name);
            add(out, &n, max, name, "%", 100.0 * p->mon.friction_used_max, 100.0,
                BD_CHECK_BELOW);
        }
        const bd_part *dp = bd_pulley_drive_part(sim, p);
        const bd_drive *dr = dp ? bd_part_drive(dp) : NULL;
        if (dr && isfinite(pd->drive.max_torque)) {
            /* the drive's torque is clipped to max_torque: at it, saturated
             * (behind a transmission, its equivalent at the pulley) */
            snprintf(name, sizeof name, "drive torque, %s", pd->name);
            add(out, &n, max, name, "N·m", dr->driving_peak, pd->drive.max_torque,
                BD_CHECK_BELOW);
        }
        if (pd->has_takeup && p->m->movable) {
            /* an end at 0 is where the carriage starts: at it without
             * ever being held there, it would fail; held there, the run's
             * warning says so */
            if (isfinite(pd->takeup.travel_max) && pd->takeup.travel_max > 0.0) {
                snprintf(name, sizeof name, "takeup travel out, %s", pd->name);
                /* the carriage is held at the end it reaches: there it fails */
                add(out, &n, max, name, "m", p->travel_max, pd->takeup.travel_max,
                    BD_CHECK_BELOW);
            }
            if (isfinite(pd->takeup.travel_min) && pd->takeup.travel_min < 0.0) {
                snprintf(name, sizeof name, "takeup travel in, %s", pd->name);
                add(out, &n, max, name, "m", p->travel_min, pd->takeup.travel_min,
                    BD_CHECK_ABOVE);
            }
        }
    }
    if (sim->model->belt->records_lift_off)
        add(out, &n, max, "lift-off from the idlers", "s", sim->lift.total, 0.0,
            BD_CHECK_AT_MOST);
    add(out, &n, max, "energy balance of the run", "-", sim->energy.balance_error_rel, 0.01,
        BD_CHECK_AT_MOST);
    /* steady running against the model's own law, when the run ends steady
     * (sensors/running.c) */
    bd_running_check rc;
    bd_sim_running_check(sim, &rc);
    if (rc.checked)
        add(out, &n, max, "running force against the model's own law", "%",
            100.0 * fabs(rc.error_rel), 100.0 * rc.tolerance_rel, BD_CHECK_AT_MOST);
    return n;
}
