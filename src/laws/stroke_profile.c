/* The telescopic cylinder's stroke against time (boom-format.md `stroke`,
 * beltdyn/boom.h): a [time, stroke] table, or the cubic speed profile of
 * seed 003 §9. Pure functions of the stroke definition and time. */
#include "beltdyn/boom.h"

/* the speed ramp of seed 003 §9 ("the curve of velocity with time in the
 * acceleration and deceleration stages can be fitted by cubic polynomial
 * interpolation", with zero acceleration at both ends of the ramp): over
 * u = τ/T in [0, 1]
 *     v(u) = v_max·(3u² − 2u³),   dv/dt = v_max·6u(1 − u)/T,
 *     ∫v dτ = v_max·T·(u³ − u⁴/2)   (v_max·T/2 over the whole ramp). */
static void ramp(double v_max, double T, double tau, double *dist, double *v, double *a)
{
    double u = tau / T;
    *dist = v_max * T * u * u * u * (1.0 - 0.5 * u);
    *v = v_max * u * u * (3.0 - 2.0 * u);
    *a = v_max * 6.0 * u * (1.0 - u) / T;
}

/* seed 003 §9: from rest up to v_max over accel_time, v_max for hold_time,
 * down to rest over decel_time the same way mirrored; before t = 0 and
 * after the end the stroke holds. accel_time 0 is a step to v_max (its
 * infinite acceleration is not reported); decel_time 0 a step to rest. */
static void cubic(const bd_boom_stroke_def *s, double t, double *x, double *v, double *a)
{
    double Ta = s->accel_time, Th = s->hold_time, Td = s->decel_time, vm = s->v_max;
    double d = 0.0;
    *v = *a = 0.0;
    if (t <= 0.0) {
        /* at rest at the initial stroke */
    } else if (t < Ta) {
        ramp(vm, Ta, t, &d, v, a);
    } else if (t < Ta + Th) {
        d = 0.5 * vm * Ta + vm * (t - Ta);
        *v = vm;
    } else if (t < Ta + Th + Td) {
        /* the ramp mirrored in time: v(τ) = v_ramp(Td − τ), distance the
         * whole ramp's less what the mirror still has to cover */
        double rest, vr, ar;
        ramp(vm, Td, Ta + Th + Td - t, &rest, &vr, &ar);
        d = 0.5 * vm * Ta + vm * Th + (0.5 * vm * Td - rest);
        *v = vr;
        *a = -ar;
    } else {
        d = vm * (0.5 * Ta + Th + 0.5 * Td);
    }
    *x = s->initial + s->direction * d;
    *v *= s->direction;
    *a *= s->direction;
}

/* linear between the points, held outside them: the slope of the segment
 * t falls in (t[i] <= t < t[i+1]), none outside; no acceleration (it is
 * a train of impulses at the points) */
static void table(const bd_boom_stroke_def *s, double t, double *x, double *v, double *a)
{
    const bd_table *tab = &s->table;
    *x = tab->n > 0 ? bd_table_eval(tab, t) : s->initial;
    *v = *a = 0.0;
    if (tab->n < 2 || t < tab->t[0] || t >= tab->t[tab->n - 1])
        return;
    int lo = 0, hi = tab->n - 1;
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (tab->t[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    *v = (tab->v[hi] - tab->v[lo]) / (tab->t[hi] - tab->t[lo]);
}

void bd_boom_stroke_eval(const bd_boom_stroke_def *s, double t, double *stroke, double *speed,
                         double *accel)
{
    double x, v, a;
    if (s->kind == BD_STROKE_CUBIC)
        cubic(s, t, &x, &v, &a);
    else
        table(s, t, &x, &v, &a);
    if (stroke)
        *stroke = x;
    if (speed)
        *speed = v;
    if (accel)
        *accel = a;
}

double bd_boom_stroke_end(const bd_boom_stroke_def *s)
{
    if (s->kind == BD_STROKE_CUBIC)
        return s->accel_time + s->hold_time + s->decel_time;
    return s->table.n > 0 ? s->table.t[s->table.n - 1] : 0.0;
}
