/* A conveyor given by its route (model-format.md `profile`, issue 15).
 *
 * 1. Layout against hand geometry: tail and head pulleys touch the carry
 *    line at the profile's end points, the concave curve at the inner
 *    point is the fillet of radius R tangent to both legs (tangent length
 *    t = R·tan(δ/2), δ the change of slope), and the carry span's length
 *    is (200 − t) + R·δ + (|leg 2| − t). Tolerance 1e-9 m: the layout is
 *    exact geometry, only rounding differs.
 * 2. Lift-off in a concave curve at rest: the idlers carry the belt while
 *    m'·g·cos δ > T/R per metre, so it lifts off when T > m'·g·R·cos δ. A
 *    level-ended valley (the tension nearly uniform) with the takeup set
 *    15 % below and 15 % above that tension: no lift-off, then lift-off
 *    reported inside the curve (the margin allows for the tension's change
 *    along the loop by the belt's weight on the slopes, under 1 %). */
#include <math.h>
#include <stdio.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "model/system.h"
#include "testlib.h"

static const char *layout_text =
    "belt: {mass_per_length: 20, axial_stiffness: 3.0e7, formulation: moving_node}\n"
    "profile:\n"
    "  points: [[0, 0], [200, 0], [600, 28]]\n"
    "  curves: [{at: 1, radius: 1000}]\n"
    "  tail: {radius: 0.4}\n"
    "  head: {radius: 0.5, drive: {control: speed, speed: 3}}\n"
    "  takeup: {at: head, type: gravity, mass: 4000}\n"
    "  carry_idlers: {spacing: 1.5}\n";

static void layout(void)
{
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(layout_text, &def, &sim);
    CHECK(def.from_profile && def.pulley_count == 5);
    double d = atan2(28.0, 400.0), R = 1000.0, t = R * tan(0.5 * d);
    CHECK_ABS(def.pulleys[0].x, 0.0, 1e-9);
    CHECK_ABS(def.pulleys[0].y, -0.4, 1e-9);
    CHECK_ABS(def.pulleys[1].x, 600.0 + 0.5 * sin(d), 1e-9);
    CHECK_ABS(def.pulleys[1].y, 28.0 - 0.5 * cos(d), 1e-9);
    double carry = (200.0 - t) + R * d + (hypot(400.0, 28.0) - t);
    printf("carry span %.6f m, hand %.6f m\n", bd_sim_span_length(sim, 0), carry);
    CHECK_ABS(bd_sim_span_length(sim, 0), carry, 1e-9);
    /* the middle of the curve: R from the centre (200 − t, R), on the bisector */
    const bd_path *path = &sim->model->path;
    double p[2], tg[2];
    bd_path_point(path, 200.0 - t + 0.5 * R * d, p, tg);
    CHECK_ABS(hypot(p[0] - (200.0 - t), p[1] - R), R, 1e-9);
    CHECK_ABS(atan2(tg[1], tg[0]), 0.5 * d, 1e-12);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

/* a 200 m valley: down 1.5° and up again, curve of radius R at the bottom;
 * the takeup's counterweight pulls 2·T */
static int lifts(double T, double R, double *first_s)
{
    char text[1400];
    snprintf(text, sizeof text,
             "belt: {mass_per_length: 20, axial_stiffness: 3.0e7, damping_ratio: 0.2,\n"
             "       formulation: moving_node}\n"
             "profile:\n"
             "  points: [[0, 0], [100, -2.618], [200, 0]]\n"
             "  curves: [{at: 1, radius: %g}]\n"
             "  tail: {radius: 0.4}\n"
             "  head: {radius: 0.5, drive: {control: speed, speed: 3, start: {delay: 100}}}\n"
             "  takeup: {at: head, type: gravity, mass: %g}\n"
             "  carry_idlers: {spacing: 1.5}\n"
             "simulation: {duration: 1}\n", R, 2.0 * T / 9.81);
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(text, &def, &sim);
    CHECK(bd_test_run_to(sim, 1.0) == 0);
    int lifted = sim->lift.first_t >= 0.0;
    *first_s = sim->lift.first_s;
    bd_sim_free(sim);
    bd_model_def_free(&def);
    return lifted;
}

int main(void)
{
    layout();
    double R = 300.0, delta = atan2(2.618, 100.0);
    double T_lift = 20.0 * 9.81 * R * cos(delta), s;
    CHECK(!lifts(0.85 * T_lift, R, &s));
    CHECK(lifts(1.15 * T_lift, R, &s));
    /* inside the curve: within its tangent length of the valley's bottom */
    double t = R * tan(delta);
    printf("lift-off at s = %.2f m; the curve spans %.2f to %.2f m\n", s,
           100.0 / cos(delta) - t, 100.0 / cos(delta) + t);
    CHECK(fabs(s - 100.0 / cos(delta)) < t + 1.5);
    return bd_test_finish("profile");
}
