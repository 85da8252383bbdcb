/* Runaway is seen (issue 10 item 7, sim/bounds.c): a state beyond physical
 * bounds stops the run with when, where and why, naming the part.
 *
 * 1. A torque drive on a frictionless pulley: the belt cannot take the
 *    torque, the pulley spins up alone (α = T/I) and passes the 50 m/s
 *    surface-speed bound (no drive asks for a speed).
 * 2. A constant-force takeup whose set force jumps to 10⁸ N on a 10 kg
 *    carriage, no travel limits: the carriage runs away (far faster than
 *    the belt can follow) and passes the 50 m/s carriage-speed bound.
 * 3. A carriage put beyond half the loop length (the travel bound) and a
 *    pulley speed made NaN: stopped at the next step; a NaN node velocity:
 *    stopped by the belt's divergence check (the tension's dashpot term).
 * 4. Both formulations: a sane run of the same conveyors never trips them
 *    (the bounds change no output: tests/golden holds every example). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "model/system.h"
#include "testlib.h"

static const char *torque_model =
    "name: runaway torque drive\n"
    "gravity: 0\n"
    "belt: {mass_per_length: 10, axial_stiffness: 1.0e6, initial_tension: 5000}\n"
    "pulleys:\n"
    "  - name: head\n"
    "    x: 10\n"
    "    y: 0\n"
    "    radius: 0.3\n"
    "    wrap: cw\n"
    "    mass: 100\n"
    "    friction: {static: 0, dynamic: 0}\n"
    "    drive: {control: torque, torque: [[0, 0], [0.05, 50000]]}\n"
    "  - {name: tail, x: 0, y: 0, radius: 0.3, wrap: cw, mass: 100}\n";

static const char *takeup_model =
    "name: runaway takeup\n"
    "belt: {mass_per_length: 10, axial_stiffness: 1.0e6, formulation: %s}\n"
    "pulleys:\n"
    "  - {name: head, x: 10, y: 0, radius: 0.3, wrap: cw, mass: 100,\n"
    "     drive: {control: speed, speed: 2, start: {time: 1}}}\n"
    "  - name: tail\n"
    "    x: 0\n"
    "    y: 0\n"
    "    radius: 0.3\n"
    "    wrap: cw\n"
    "    mass: 10\n"
    "    takeup: {type: constant_force, axis: [-1, 0],\n"
    "             force: [[0, 4000], [0.05, 4000], [0.06, %s]]}\n";

/* steps until the run fails or t_end; returns 1 when it failed (err set) */
static int run(bd_sim *sim, double t_end, char *err, size_t errlen)
{
    err[0] = '\0';
    while (bd_sim_time(sim) < t_end)
        if (bd_sim_step(sim, 1, err, errlen))
            return 1;
    return 0;
}

static void check_message(const char *err, const char *part, const char *what)
{
    printf("  %s\n", err);
    CHECK(strstr(err, part) != NULL);
    CHECK(strstr(err, what) != NULL);
    CHECK(strstr(err, "at t = ") != NULL);
}

static void torque_runaway(void)
{
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(torque_model, &def, &sim);
    char err[600];
    CHECK(run(sim, 1.0, err, sizeof err) == 1);
    check_message(err, "pulley 'head'", "surface speed");
    CHECK(strstr(err, "beyond the bound of 50 m/s") != NULL);
    /* it stopped at the bound, not long after: one step's spin-up past it,
     * α·R·Δt with α = T/I (50 kN·m on ½·100 kg·(0.3 m)² = 4.5 kg·m²),
     * twice that for the belt's share of the inertia left out */
    bd_pulley_state ps;
    bd_sim_pulley(sim, 0, &ps);
    double overshoot = 2.0 * (50000.0 / 4.5) * 0.3 * bd_sim_time_step(sim);
    CHECK(fabs(ps.omega_rad_s) * ps.radius_m < 50.0 + overshoot);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

static void takeup_runaway(const char *formulation)
{
    char text[2048];
    snprintf(text, sizeof text, takeup_model, formulation, "1.0e8");
    bd_model_def def;
    bd_sim *sim;
    bd_test_make_sim(text, &def, &sim);
    char err[600];
    CHECK(run(sim, 1.0, err, sizeof err) == 1);
    printf("%s:\n", formulation);
    check_message(err, "pulley 'tail' (takeup)", "carriage");
    /* the force ramps at F' = 10¹⁰ N/s from 0.05 s: the 10 kg carriage
     * passes 50 m/s after τ = √(2·m·50/F') = 0.3 ms (the belt's 4 kN is
     * nothing against it); 2 ms allows for the steps */
    CHECK(bd_sim_time(sim) < 0.052);
    bd_sim_free(sim);
    bd_model_def_free(&def);

    /* the same conveyor at a sane force runs to the end */
    snprintf(text, sizeof text, takeup_model, formulation, "5000");
    bd_test_make_sim(text, &def, &sim);
    CHECK(run(sim, 1.0, err, sizeof err) == 0);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

/* a state put out of bounds by hand (kind 0: carriage travel, 1: pulley
 * speed NaN, 2: a node velocity NaN) is stopped at the next step */
static void injected(int kind, const char *part, const char *what)
{
    char text[2048];
    snprintf(text, sizeof text, takeup_model, "discrete", "5000");
    bd_model_def def;
    bd_sim *sim;
    char err[600];
    bd_test_make_sim(text, &def, &sim);
    if (kind == 0)
        sim->pulleys[1].q = 0.6 * bd_sim_belt_length(sim);
    else if (kind == 1)
        sim->pulleys[0].omega = NAN;
    else
        sim->vx[bd_sim_node_count(sim) / 2] = NAN;
    CHECK(bd_sim_step(sim, 1, err, sizeof err) == 1);
    check_message(err, part, what);
    bd_sim_free(sim);
    bd_model_def_free(&def);
}

int main(void)
{
    torque_runaway();
    takeup_runaway("discrete");
    takeup_runaway("axial");
    injected(0, "pulley 'tail' (takeup)", "half the belt loop");
    injected(1, "pulley 'head'", "diverged");
    injected(2, "belt element", "diverged");
    return bd_test_finish("bounds");
}
