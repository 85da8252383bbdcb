/* Start curves of a speed-controlled drive (issue 4; seed 000 eqs 52–55).
 *
 * 1. Following: a 10 m loop without gravity, the tail pulley's bearing
 *    damping as the load, torque limit far above what the start needs.
 *    For each curve (and for the s-curve with a pre-start delay at creep
 *    speed) the drive pulley's surface speed ω·R stays within 2% of the
 *    target speed v₀ of the curve v(t) written out here from the formulas
 *    (not taken from drive.c), through the start and 1 s after, both
 *    averaged over 50 ms windows. 2% is issue 4's tolerance. The averaging
 *    takes out the pulley's torsional vibration on the belt's contact
 *    springs (about 100 Hz, ±1–2% of v₀ step by step, printed), which a
 *    2 Hz speed loop cannot and a drive's speed measurement does not see;
 *    what is left is the loop's tracking error.
 * 2. Saturation: the same start with max_torque below what the ramp needs
 *    (belt and pulleys, 245 kg reduced to the rim, take M·a·R = 25 N·m at
 *    a = 0.5 m/s²; the limit is 10 N·m): the
 *    drive torque sits exactly at max_torque through the ramp (never above)
 *    and the pulley falls behind the curve. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "testlib.h"

static const double PI = 3.14159265358979323846;
static const double V0 = 1.0;   /* m/s */
static const double T = 2.0;    /* s, start time */
static const double R = 0.2;    /* m, drive radius */
static const double WINDOW = 0.05;  /* s, speeds compared as window means */

static const char *model_fmt =
    "name: start curve\n"
    "gravity: 0\n"
    "belt: {mass_per_length: 10, axial_stiffness: 2.0e6, damping_ratio: 0.1,\n"
    "       initial_tension: 5000, element_length: 0.05}\n"
    "pulleys:\n"
    "  - {name: drive, x: 0, y: 0, radius: 0.2, wrap: ccw, mass: 40,\n"
    "     friction: {static: 0.5, dynamic: 0.45},\n"
    "     drive: {control: speed, speed: 1.0, max_torque: %g,\n"
    "             start: {curve: %s, time: 2, delay: %g, creep_speed: %g}}}\n"
    "  - {name: tail, x: 10, y: 0, radius: 0.2, wrap: ccw, mass: 40, bearing_damping: 2}\n";

/* seed 000 eqs 52–55 as fractions of v0 at τ = t/T (Nordell: the
 * continuous two-part quadratic of docs/physics.md) */
static double shape(const char *curve, double tau)
{
    if (tau <= 0.0) return 0.0;
    if (tau >= 1.0) return 1.0;
    if (strcmp(curve, "linear") == 0) return tau;
    if (strcmp(curve, "harrison") == 0) return 0.5 * (1.0 - cos(PI * tau));
    if (strcmp(curve, "nordell") == 0)
        return tau <= 0.5 ? 2.0 * tau * tau : 1.0 - 2.0 * (1.0 - tau) * (1.0 - tau);
    return 3.0 * tau * tau - 2.0 * tau * tau * tau;
}

/* the target speed: pre-start up to creep speed over T·creep/v0 (at most
 * the delay), then the ramp from creep speed (docs/model-format.md) */
static double target(const char *curve, double delay, double creep, double t)
{
    if (delay > 0.0 && t < delay) {
        double tc = fmin(T * creep / V0, delay);
        return creep * shape(curve, t / tc);
    }
    double v_from = delay > 0.0 ? creep : 0.0;
    return v_from + (V0 - v_from) * shape(curve, (t - delay) / T);
}

static void make(const char *curve, double max_torque, double delay, double creep,
                 bd_model_def *def, bd_sim **sim)
{
    char yaml[2048];
    snprintf(yaml, sizeof yaml, model_fmt, max_torque, curve, delay, creep);
    bd_test_make_sim(yaml, def, sim);
}

static void following(const char *curve, double delay, double creep)
{
    bd_model_def def;
    bd_sim *sim;
    make(curve, 1e5, delay, creep, &def, &sim);
    char err[256];
    double worst = 0.0, worst_t = 0.0, raw = 0.0;
    double sum_v = 0.0, sum_ref = 0.0, window_end = WINDOW;
    long count = 0;
    int failed = 0;
    bd_pulley_state drive;
    while (bd_sim_time(sim) < delay + T + 1.0) {
        failed |= bd_sim_step(sim, 1, err, sizeof err);
        bd_sim_pulley(sim, 0, &drive);
        double t = bd_sim_time(sim);
        double v = drive.omega_rad_s * R, ref = target(curve, delay, creep, t);
        raw = fmax(raw, fabs(v - ref));
        sum_v += v;
        sum_ref += ref;
        count++;
        if (t < window_end)
            continue;
        double d = fabs(sum_v - sum_ref) / (double)count;
        if (d > worst) {
            worst = d;
            worst_t = window_end - 0.5 * WINDOW;
        }
        sum_v = sum_ref = 0.0;
        count = 0;
        window_end += WINDOW;
    }
    CHECK(!failed);
    printf("%-8s delay %.1f s: largest |omega R - v(t)| over %.0f ms means = %.5f m/s "
           "(%.2f%% of v0) at t = %.3f s; step by step %.2f%%\n",
           curve, delay, 1e3 * WINDOW, worst, 100.0 * worst / V0, worst_t, 100.0 * raw / V0);
    CHECK(worst <= 0.02 * V0);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

static void saturation(void)
{
    const double limit = 10.0;  /* N·m, well below the 25 N·m the ramp needs */
    bd_model_def def;
    bd_sim *sim;
    make("linear", limit, 0.0, 0.0, &def, &sim);
    char err[256];
    int steps = 0, at_limit = 0;
    double above = 0.0;
    int failed = 0;
    bd_pulley_state drive;
    while (bd_sim_time(sim) < T) {
        failed |= bd_sim_step(sim, 1, err, sizeof err);
        bd_sim_pulley(sim, 0, &drive);
        double M = drive.drive_torque_Nm;
        above = fmax(above, fabs(M) - limit);
        if (bd_sim_time(sim) > 0.2) {
            steps++;
            at_limit += fabs(M - limit) < 1e-9;
        }
    }
    bd_sim_pulley(sim, 0, &drive);
    double lag = target("linear", 0.0, 0.0, bd_sim_time(sim)) - drive.omega_rad_s * R;
    printf("saturation: torque at max_torque = %g N m in %d of %d steps of the ramp "
           "(largest excess %.3g N m); pulley %.3f m/s behind the curve at t = %.1f s\n",
           limit, at_limit, steps, above, lag, bd_sim_time(sim));
    CHECK(!failed);
    CHECK(above <= 0.0);
    CHECK(at_limit == steps);
    CHECK(lag > 0.1 * V0);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

int main(void)
{
    static const char *const curves[4] = {"linear", "harrison", "nordell", "s-curve"};
    for (int i = 0; i < 4; i++)
        following(curves[i], 0.0, 0.0);
    following("s-curve", 1.0, 0.2);
    saturation();
    return bd_test_finish("start_curves");
}
