/* Start curves of a speed drive (model-format.md `drive.start`, `stop`):
 * seed 000 eqs 52–55 for the shapes, a pre-start at creep speed, and the
 * linear ramp stop. Pure functions of the drive definition and time. */
#include "laws/start_curve.h"

#include <math.h>

#include "base/constants.h"

/* start curves, seed 000 eqs 52–55, τ = t/T in [0, 1]. Nordell's two-part
 * quadratic as printed in seed 000 (53) ends at 2·v0; we use the curve it
 * describes: v = 2v0τ² for τ ≤ ½, v0·(1 − 2(1−τ)²) after (continuous speed
 * and acceleration, reaching v0 at T). */
static double curve_shape(bd_start_curve c, double tau)
{
    if (tau <= 0.0)
        return 0.0;
    if (tau >= 1.0)
        return 1.0;
    switch (c) {
    case BD_CURVE_LINEAR: return tau;
    case BD_CURVE_HARRISON: return 0.5 * (1.0 - cos(BD_PI * tau));
    case BD_CURVE_NORDELL:
        return tau <= 0.5 ? 2.0 * tau * tau : 1.0 - 2.0 * (1.0 - tau) * (1.0 - tau);
    case BD_CURVE_SCURVE: return tau * tau * (3.0 - 2.0 * tau);
    }
    return tau;
}

/* pre-start (t < delay): the speed rises to creep_speed along the same
 * curve, over the time the main ramp's mean acceleration would take to
 * reach it (T·v_creep/v, at most the delay), and is held there. A jump to
 * creep speed at t = 0 would put the whole torque limit on the belt. */
static double prestart_speed(const bd_drive_def *d, double t)
{
    double tc = d->speed != 0.0 ? d->start_time * fabs(d->creep_speed / d->speed) : 0.0;
    if (tc > d->start_delay)
        tc = d->start_delay;
    if (tc <= 0.0)
        return d->creep_speed;
    return d->creep_speed * curve_shape(d->curve, t / tc);
}

/* the main ramp starts from creep speed after a pre-start, else from rest */
static double start_speed(const bd_drive_def *d, double t)
{
    if (d->start_delay > 0.0 && t < d->start_delay)
        return prestart_speed(d, t);
    if (d->start_time <= 0.0)
        return d->speed;
    double v0 = d->start_delay > 0.0 ? d->creep_speed : 0.0;
    return v0 + (d->speed - v0) * curve_shape(d->curve, (t - d->start_delay) / d->start_time);
}

/* target belt speed of a speed drive at time t, stops included */
double bd_start_curve_speed(const bd_drive_def *d, double t)
{
    if (d->stop_mode == BD_STOP_RAMP && t >= d->stop_at) {
        double f = d->stop_time > 0.0 ? 1.0 - (t - d->stop_at) / d->stop_time : 0.0;
        return f > 0.0 ? start_speed(d, d->stop_at) * f : 0.0;
    }
    return start_speed(d, t);
}

