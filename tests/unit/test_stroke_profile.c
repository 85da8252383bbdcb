/* The telescopic cylinder's stroke profile (laws/stroke_profile.c,
 * boom-format.md `stroke`).
 *
 * 1. Seed 003 §9's extension: from a 2 m stroke, 0.5 m/s reached over 4 s
 *    along the cubic ramp, held 8 s, back to rest over 4 s. Each ramp
 *    covers v_max·T/2 = 1 m, the hold 4 m: 2, 3, 7, 8 m at 0, 4, 12, 16 s
 *    and 8 m after (a 6 m stroke, 0.5·(2 + 8 + 2)); halfway up the ramp the
 *    speed is v_max·(3/4 − 2/8) = 0.25 m/s; the acceleration is zero at
 *    both ends of both ramps. Exact (1e-12): closed forms.
 * 2. The stroke is the integral of the speed and the speed of the
 *    acceleration: trapezoids over 1 ms steps match to 1e-6 m and 1e-6 m/s.
 * 3. Retraction from 8 m mirrors it: 8 − (s_ext − 2), speed and
 *    acceleration negated.
 * 4. accel_time 0 and decel_time 0 are steps of the speed; the stroke is
 *    continuous (v_max·hold).
 * 5. A table: linear between points, held outside, the speed of the
 *    segment (0 outside), no acceleration; its end is its last time. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "beltdyn/boom.h"
#include "testlib.h"

static bd_boom_stroke_def cubic(double initial, int direction, double Ta, double Th, double Td)
{
    bd_boom_stroke_def s;
    memset(&s, 0, sizeof s);
    s.initial = initial;
    s.kind = BD_STROKE_CUBIC;
    s.v_max = 0.5;
    s.accel_time = Ta;
    s.hold_time = Th;
    s.decel_time = Td;
    s.direction = direction;
    return s;
}

static double stroke_at(const bd_boom_stroke_def *s, double t)
{
    double x;
    bd_boom_stroke_eval(s, t, &x, NULL, NULL);
    return x;
}

static void seed_extension(void)
{
    bd_boom_stroke_def s = cubic(2.0, +1, 4.0, 8.0, 4.0);
    const double t[] = {0.0, 4.0, 12.0, 16.0, 20.0};
    const double want[] = {2.0, 3.0, 7.0, 8.0, 8.0};
    for (int i = 0; i < 5; i++)
        CHECK_ABS(stroke_at(&s, t[i]), want[i], 1e-12);
    CHECK_ABS(bd_boom_stroke_end(&s), 16.0, 0.0);
    CHECK_ABS(stroke_at(&s, bd_boom_stroke_end(&s)) - s.initial, 6.0, 1e-12);
    double x, v, a;
    bd_boom_stroke_eval(&s, 2.0, &x, &v, &a);
    CHECK_ABS(v, 0.25, 1e-12);
    CHECK_ABS(x, 2.0 + 0.5 * 4.0 * (0.125 - 0.0625 / 2.0), 1e-12);
    CHECK(a > 0.0);
    const double flat[] = {0.0, 4.0, 12.0, 16.0};
    for (int i = 0; i < 4; i++) {
        bd_boom_stroke_eval(&s, flat[i], &x, &v, &a);
        CHECK_ABS(a, 0.0, 1e-12);
    }
    bd_boom_stroke_eval(&s, 8.0, &x, &v, &a);
    CHECK_ABS(v, 0.5, 0.0);
    CHECK_ABS(a, 0.0, 0.0);
    bd_boom_stroke_eval(&s, 14.0, &x, &v, &a);
    CHECK_ABS(v, 0.25, 1e-12);
    CHECK(a < 0.0);
    bd_boom_stroke_eval(&s, -1.0, &x, &v, &a);
    CHECK(x == 2.0 && v == 0.0 && a == 0.0);
    bd_boom_stroke_eval(&s, 30.0, &x, &v, &a);
    CHECK(x == 8.0 && v == 0.0 && a == 0.0);
}

/* trapezoids of speed and acceleration over [0, 20] s in 1 ms steps */
static void integrals(const bd_boom_stroke_def *s)
{
    const double h = 1e-3;
    double x0, v0, a0, x = 0.0, v = 0.0, err_x = 0.0, err_v = 0.0;
    bd_boom_stroke_eval(s, 0.0, &x0, &v0, &a0);
    x = x0;
    v = v0;
    for (int k = 1; k <= 20000; k++) {
        double x1, v1, a1;
        bd_boom_stroke_eval(s, k * h, &x1, &v1, &a1);
        x += 0.5 * h * (v0 + v1);
        v += 0.5 * h * (a0 + a1);
        err_x = fmax(err_x, fabs(x - x1));
        err_v = fmax(err_v, fabs(v - v1));
        v0 = v1;
        a0 = a1;
    }
    printf("integrals: stroke %.3e m, speed %.3e m/s from their derivatives\n", err_x, err_v);
    CHECK(err_x < 1e-6);
    CHECK(err_v < 1e-6);
}

static void retraction(void)
{
    bd_boom_stroke_def ext = cubic(2.0, +1, 4.0, 8.0, 4.0);
    bd_boom_stroke_def ret = cubic(8.0, -1, 4.0, 8.0, 4.0);
    for (double t = -1.0; t <= 20.0; t += 0.25) {
        double xe, ve, ae, xr, vr, ar;
        bd_boom_stroke_eval(&ext, t, &xe, &ve, &ae);
        bd_boom_stroke_eval(&ret, t, &xr, &vr, &ar);
        CHECK_ABS(xr, 8.0 - (xe - 2.0), 1e-12);
        CHECK_ABS(vr, -ve, 1e-15);
        CHECK_ABS(ar, -ae, 1e-15);
    }
    CHECK_ABS(stroke_at(&ret, 16.0), 2.0, 1e-12);
}

static void steps(void)
{
    bd_boom_stroke_def s = cubic(1.0, +1, 0.0, 2.0, 0.0);
    double x, v, a;
    bd_boom_stroke_eval(&s, 1e-9, &x, &v, &a);
    CHECK_ABS(v, 0.5, 0.0);
    CHECK_ABS(x, 1.0, 1e-9);
    bd_boom_stroke_eval(&s, 1.0, &x, &v, &a);
    CHECK_ABS(x, 1.5, 1e-12);
    CHECK_ABS(a, 0.0, 0.0);
    bd_boom_stroke_eval(&s, 2.0, &x, &v, &a);
    CHECK_ABS(x, 2.0, 1e-12);
    CHECK_ABS(v, 0.0, 0.0);
    CHECK_ABS(bd_boom_stroke_end(&s), 2.0, 0.0);
}

static void table(void)
{
    double t[] = {1.0, 3.0, 5.0}, v[] = {3.0, 5.0, 4.0};
    bd_boom_stroke_def s;
    memset(&s, 0, sizeof s);
    s.initial = 3.0;
    s.kind = BD_STROKE_TABLE;
    s.table.n = 3;
    s.table.t = t;
    s.table.v = v;
    double x, sp, a;
    bd_boom_stroke_eval(&s, 0.0, &x, &sp, &a);
    CHECK(x == 3.0 && sp == 0.0 && a == 0.0);
    bd_boom_stroke_eval(&s, 2.0, &x, &sp, &a);
    CHECK_ABS(x, 4.0, 1e-12);
    CHECK_ABS(sp, 1.0, 1e-12);
    CHECK(a == 0.0);
    bd_boom_stroke_eval(&s, 3.0, &x, &sp, &a);   /* a point starts the next segment */
    CHECK_ABS(x, 5.0, 1e-12);
    CHECK_ABS(sp, -0.5, 1e-12);
    bd_boom_stroke_eval(&s, 4.5, &x, &sp, &a);
    CHECK_ABS(x, 4.25, 1e-12);
    CHECK_ABS(sp, -0.5, 1e-12);
    bd_boom_stroke_eval(&s, 5.0, &x, &sp, &a);
    CHECK(x == 4.0 && sp == 0.0 && a == 0.0);
    bd_boom_stroke_eval(&s, 9.0, &x, &sp, &a);
    CHECK(x == 4.0 && sp == 0.0);
    CHECK_ABS(bd_boom_stroke_end(&s), 5.0, 0.0);
    s.table.n = 1;   /* one point: held */
    bd_boom_stroke_eval(&s, 2.0, &x, &sp, &a);
    CHECK(x == 3.0 && sp == 0.0);
}

int main(void)
{
    seed_extension();
    bd_boom_stroke_def seed = cubic(2.0, +1, 4.0, 8.0, 4.0);
    integrals(&seed);
    bd_boom_stroke_def uneven = cubic(0.5, -1, 1.5, 0.7, 3.25);
    integrals(&uneven);
    retraction();
    steps();
    table();
    return bd_test_finish("stroke_profile");
}
