/* A conveyor given by its route (model-format.md `profile`, issue 15).
 *
 * 1. Layout against hand geometry: tail and head pulleys touch the carry
 *    line at the profile's end points, the concave curve at the inner
 *    point is the fillet of radius R tangent to both legs (tangent length
 *    t = R·tan(δ/2), δ the change of slope), and the carry span's length
 *    is (200 − t) + R·δ + (|leg 2| − t). Tolerance 1e-9 m: the layout is
 *    exact geometry, only rounding differs.
 * 2. Lift-off in a concave curve at rest: the idlers carry the belt while
 *    m'·g·cos δ > T/R per metre (a string under tension T bent to radius
 *    R presses T/R per metre on its supports; CEMA's concave-curve radius
 *    R = T/(m'g), see D. Pitcher, IMHC B17-16), so it lifts off when
 *    T > m'·g·R·cos δ. A
 *    level-ended valley (the tension nearly uniform) with the takeup set
 *    3 % below and 3 % above that tension: no lift-off, then lift-off
 *    reported inside the curve, by the moving-node and the axial belt
 *    (the margin allows for the tension at the
 *    curve differing from half the takeup's pull: the belt's weight on the
 *    valley's slopes, 0.9 %, and on the takeup loop's legs, 0.5 %).
 * 3. The return strand's corner is the carry strand's moved return_drop
 *    down (exactly), and the strand itself runs that far below the carry
 *    at the curve less 2.7 cm, within 2 mm: its legs meet the pulleys on tangents, so
 *    they turn by δ' a little more than the carry's δ, and the fillet's
 *    external distance R·(sec(δ/2) − 1) ≈ Rδ²/8 grows by Rδ·Δδ/4 (here
 *    2.7 cm, from the slopes 28/397 and 0.2/200 of its legs); a tail
 *    takeup is the tail pulley pulled horizontally away from the head.
 * 4. An idler curve on an explicit span: the arc through the span's points
 *    at from and to sags R − √(R² − c²/4) below the chord at its middle
 *    (1e-9 m); `check` calls it concave, and convex with sense: convex. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
static int lifts(const char *formulation, double T, double R, double *first_s)
{
    char text[1400];
    snprintf(text, sizeof text,
             "belt: {mass_per_length: 20, axial_stiffness: 3.0e7, damping_ratio: 0.2,\n"
             "       formulation: %s}\n"
             "profile:\n"
             "  points: [[0, 0], [100, -2.618], [200, 0]]\n"
             "  curves: [{at: 1, radius: %g}]\n"
             "  tail: {radius: 0.4}\n"
             "  head: {radius: 0.5, drive: {control: speed, speed: 3, start: {delay: 100}}}\n"
             "  takeup: {at: head, type: gravity, mass: %g}\n"
             "  carry_idlers: {spacing: 1.5}\n"
             "simulation: {duration: 1}\n", formulation, R, 2.0 * T / 9.81);
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

/* a profile with a tail takeup: its points line (or none) and what
 * follows the profile, written into buf */
static const char *tail_profile(char *buf, size_t len, const char *points, const char *after)
{
    snprintf(buf, len,
             "belt: {mass_per_length: 20, axial_stiffness: 3.0e7}\n"
             "profile:\n"
             "%s"
             "  tail: {radius: 0.4}\n"
             "  head: {radius: 0.5, drive: {control: speed, speed: 3}}\n"
             "  takeup: {at: tail, type: gravity, mass: 2000}\n"
             "  carry_idlers: {spacing: 1.5}\n"
             "%s", points, after);
    return buf;
}

/* the return strand's height below the carry strand at chainage x */
static double drop_at(const bd_sim *sim, double x)
{
    const bd_path *path = &sim->model->path;
    double yc = NAN, yr = NAN, p[2], t[2];
    for (double s = 0.0; s < path->length; s += 0.01) {
        bd_path_point(path, s, p, t);
        if (fabs(p[0] - x) < 0.005)
            *(t[0] > 0.0 ? &yc : &yr) = p[1];
    }
    return yc - yr;
}

static void return_and_tail_takeup(void)
{
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(layout_text, &def, &sim);
    const bd_pulley_def *bend2 = &def.pulleys[def.pulley_count - 1];
    CHECK(bend2->route_count == 1);
    CHECK(bend2->route[0].x == 200.0 && bend2->route[0].y == -1.0 && bend2->route[0].radius == 1000.0);
    double drop = drop_at(sim, 200.0);
    printf("return strand %.4f m below the carry strand at the curve (return_drop 1)\n", drop);
    /* 1 − R·[sec(δ'/2) − sec(δ/2)]: the carry turns by δ = atan(28/400),
     * the return by δ' = atan(28/397) + atan(0.2/200); 2 mm for the legs'
     * slopes, which the figures give to 3 digits, and the 1 cm sampling */
    double dc = atan(28.0 / 400.0), dr = atan(28.0 / 397.0) + atan(0.2 / 200.0);
    CHECK_ABS(drop, 1.0 - 1000.0 * (1.0 / cos(0.5 * dr) - 1.0 / cos(0.5 * dc)), 0.002);
    bd_sim_free(sim);
    bd_model_def_free(&def);
    char tail[600];
    bd_test_make_sim(tail_profile(tail, sizeof tail, "  points: [[0, 0], [300, 20]]\n", ""), &def,
                     &sim);
    CHECK(def.pulley_count == 2 && def.pulleys[0].has_takeup && !def.pulleys[1].has_takeup);
    CHECK(def.pulleys[0].takeup.axis[0] == -1.0 && def.pulleys[0].takeup.axis[1] == 0.0);
    CHECK(def.idler_sets[1].span == 1);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

/* a level 100 m two-pulley conveyor, its idler sets to follow */
static const char *two_pulleys =
        "belt: {mass_per_length: 20, axial_stiffness: 3.0e7, initial_tension: 20000}\n"
        "pulleys:\n"
        "  - {name: tail, x: 0, y: 0, radius: 0.4, wrap: cw}\n"
        "  - {name: head, x: 100, y: 0, radius: 0.4, wrap: cw}\n"
        "idlers:\n";

/* does `check` call the span's curve concave (1), convex (0), or neither (−1) */
static int curve_sense(const bd_sim *sim)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    bd_sim_describe(sim, f);
    fclose(f);
    int sense = strstr(text, "concave vertical curve") ? 1
              : strstr(text, "convex vertical curve") ? 0 : -1;
    free(text);
    return sense;
}

static void idler_curve(void)
{
    const char *fmt = "%s  - {span: tail, spacing: 1.5, curve: {radius: 500, from: 0.3, to: 0.7%s}}\n";
    for (int convex = 0; convex < 2; convex++) {
        char text[600];
        snprintf(text, sizeof text, fmt, two_pulleys, convex ? ", sense: convex" : "");
        bd_model_def def;
        bd_sim *sim;
        bd_test_make_sim(text, &def, &sim);
        double p[2], t[2], R = 500.0, c = 40.0;
        /* the arc's middle: 30 m of straight, then half its R·2·asin(c/2R) */
        bd_path_point(&sim->model->path, 30.0 + R * asin(0.5 * c / R), p, t);
        double sag = R - sqrt(R * R - 0.25 * c * c);
        printf("idler curve (%s): %.9f m off the chord, formula %.9f m\n",
               convex ? "convex" : "concave", convex ? p[1] - 0.4 : 0.4 - p[1], sag);
        CHECK_ABS(p[1], 0.4 + (convex ? sag : -sag), 1e-9);
        CHECK(curve_sense(sim) == !convex);
        bd_sim_free(sim);
        bd_model_def_free(&def);
    }
}

/* the first error of loading and building text, or "" */
static void first_error(const char *text, char *out, size_t size)
{
    bd_model_def def;
    bd_diag d;
    bd_sim *sim = NULL;
    bd_diag_init(&d);
    out[0] = '\0';
    if (bd_model_load_string(text, strlen(text), "t.yaml", &def, &d) == 0
        && bd_sim_create(&def, &sim, &d) == 0)
        bd_sim_free(sim);
    if (d.count > 0)
        snprintf(out, size, "%s", d.lines[0]);
    bd_model_def_free(&def);
    bd_diag_free(&d);
}

/* bad routes are errors at their line; two curves that touch share the
 * corner between them */
static void bad_routes(void)
{
    char e[512], t[600];
    first_error(tail_profile(t, sizeof t, "", ""), e, sizeof e);
    printf("%s\n", e);
    CHECK(strstr(e, "t.yaml:2:") && strstr(e, "missing required key 'points'"));
    first_error(tail_profile(t, sizeof t, "  points: [[0, 0], [100, 0]]\n",
                             "idlers:\n  - {span: tail, spacing: 1.5}\n"),
                e, sizeof e);
    printf("%s\n", e);
    CHECK(strstr(e, "t.yaml:8:") && strstr(e, "idlers: give either idlers or a profile's"));
    const char *fmt =
        "%s  - {span: tail, spacing: 1.5, curve: {radius: %g, from: 0.3, to: 0.4}}\n"
        "  - {span: tail, spacing: 1.5, curve: {radius: 500, from: 0.4, to: 0.5}}\n";
    char text[800];
    snprintf(text, sizeof text, fmt, two_pulleys, 4.0);
    first_error(text, e, sizeof e);
    printf("%s\n", e);
    CHECK(strstr(e, "t.yaml:6:") && strstr(e, "cannot bend"));
    snprintf(text, sizeof text, fmt, two_pulleys, 500.0);
    first_error(text, e, sizeof e);
    CHECK(e[0] == '\0');
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(text, &def, &sim);
    /* 5 corners (the touching curves share one): 6 legs and 2 arcs */
    CHECK(sim->model->path.piece_count == 8);
    printf("two touching curves: %d pieces\n", sim->model->path.piece_count);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

int main(void)
{
    bad_routes();
    layout();
    return_and_tail_takeup();
    idler_curve();
    double R = 300.0, delta = atan2(2.618, 100.0);
    double T_lift = 20.0 * 9.81 * R * cos(delta), s;
    /* the moving-node belt (its idler nodes feel the turn) and the axial
     * belt (its idlers' resistance in the curve follows T/R) */
    const char *forms[] = {"moving_node", "axial"};
    for (int f = 0; f < 2; f++) {
        CHECK(!lifts(forms[f], 0.97 * T_lift, R, &s));
        CHECK(lifts(forms[f], 1.03 * T_lift, R, &s));
        /* inside the curve: within its tangent length of the valley's bottom */
        double t = R * tan(delta);
        printf("%s: lift-off at s = %.2f m; the curve spans %.2f to %.2f m\n", forms[f], s,
               100.0 / cos(delta) - t, 100.0 / cos(delta) + t);
        CHECK(fabs(s - 100.0 / cos(delta)) < t + 1.5);
    }
    return bd_test_finish("profile");
}
