/* The conveyor generator (generate.h). Layout: the belt leaves the head
 * pulley along the return strand, passes a takeup loop (two bends and the
 * takeup pulley hanging below them) near the head or the tail, or none,
 * wraps the tail pulley and comes back on the carry strand, tail to head:
 *   head (cw) [snub (ccw)] [bend1 (ccw), takeup (cw), bend2 (ccw)] tail (cw)
 * The carry strand rises from the tail (0, 0) to the head (L, H). A snub
 * (3 in 10) stands just behind the head under the carry strand; the belt
 * leaving the head rises over it, so the head's wrap is more than 180°. */
#include "generate.h"

#include "belt/lumped/lumped.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define G 9.81
#define PI 3.14159265358979323846

/* splitmix64: small, good and the same everywhere */
typedef struct rng { unsigned long long s; } rng;

static double uniform(rng *r, double lo, double hi)
{
    unsigned long long z = (r->s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return lo + (hi - lo) * (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static int pick(rng *r, int n)
{
    int k = (int)uniform(r, 0.0, (double)n);
    return k < n ? k : n - 1;
}

static int chance(rng *r, double p)
{
    return uniform(r, 0.0, 1.0) < p;
}

typedef struct out { char *buf; size_t size, len; } out;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void put(out *o, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    size_t room = o->len < o->size ? o->size - o->len : 0;
    int k = vsnprintf(room ? o->buf + o->len : NULL, room, fmt, ap);
    va_end(ap);
    if (k > 0)
        o->len += (size_t)k;
}

static void put_pulley(out *o, const char *name, double x, double y, double R, const char *wrap,
                       double mass, double bearing)
{
    put(o, "  - name: %s\n    x: %.6g\n    y: %.6g\n    radius: %.6g\n    wrap: %s\n"
           "    mass: %.6g\n", name, x, y, R, wrap, mass);
    if (bearing > 0.0)
        put(o, "    bearing_damping: %.6g\n", bearing);
}

/* conveyor `seed`; an element drawn as a fraction of the default is that
 * fraction of `element_unit` (0: of the 30° chord of the smallest pulley);
 * `no_element` leaves belt.element_length out */
static size_t generate(unsigned long seed, const bd_gen_options *opt, double element_unit,
                       int no_element, char *buf, size_t size, bd_gen_info *info)
{
    rng r = {0x5EEDULL + 7919ULL * (unsigned long long)seed};
    out o = {buf, size, 0};
    if (size)
        buf[0] = '\0';
    int axial = strcmp(opt->formulation, "axial") == 0;

    /* a snub pulley behind the head, from a stream of its own so that the
     * conveyors of the other seeds stay what they were */
    rng r_snub = {0xB0BULL + 104729ULL * (unsigned long long)seed};
    int snub = chance(&r_snub, 0.3);
    double Rs_draw = uniform(&r_snub, 0.25, 0.45), snub_gap = uniform(&r_snub, 0.1, 0.5);
    double snub_clearance = uniform(&r_snub, 0.08, 0.25);
    /* a vertical curve on part of the carry span (issue 15: idlers
     * `curve`), from a stream of its own as the snub: concave or convex,
     * its radius a few times the one at which the start's tension would
     * lift the belt off (CEMA's R = T/(m'g)) */
    rng r_curve = {0xC0FFEEULL + 15485863ULL * (unsigned long long)seed};
    int vcurve = chance(&r_curve, 0.3) && opt->curves, vcurve_convex = chance(&r_curve, 0.5);
    double vcurve_from = uniform(&r_curve, 0.2, 0.4), vcurve_len = uniform(&r_curve, 0.2, 0.4);
    double vcurve_margin = uniform(&r_curve, 2.5, 5.0);

    /* route */
    double L = uniform(&r, 30.0, opt->max_length);
    double incline = uniform(&r, -8.0, 14.0) * PI / 180.0;
    double H = L * tan(incline);
    double Rh = uniform(&r, 0.3, 0.6), Rt = uniform(&r, 0.25, Rh);
    double Rb = uniform(&r, 0.25, 0.4), Rk = uniform(&r, 0.3, 0.5);
    enum { LOOP_HEAD, LOOP_TAIL, TAIL_TAKEUP } takeup = pick(&r, 3);
    enum { DRIVE_HEAD, DRIVE_TAIL, DRIVE_DUAL } drives = pick(&r, 5) < 3 ? DRIVE_HEAD
                                                       : chance(&r, 0.5) ? DRIVE_TAIL : DRIVE_DUAL;
    int motor = chance(&r, 0.2);
    /* belt and load */
    double mB = uniform(&r, 10.0, 40.0);
    double mL = chance(&r, 0.6) ? uniform(&r, 0.5, 3.0) * mB : 0.0;
    int preloaded = mL > 0.0 ? chance(&r, 0.75) : 1;
    double v = uniform(&r, 1.0, 5.0);
    double rr = uniform(&r, 0.01, 0.03);
    double a_carry = uniform(&r, 1.0, 1.5), a_return = 3.0;
    double mu_s = uniform(&r, 0.3, 0.45), mu_d = mu_s - uniform(&r, 0.03, 0.08);
    double zeta_choices[] = {0.0, 0.02, 0.05, 0.1, 0.2};
    double zeta = zeta_choices[pick(&r, 5)];
    double drive_inertia = chance(&r, 0.3) ? 0.0 : uniform(&r, 1.0, 40.0);
    double ramp = uniform(&r, 3.0, 8.0);
    const char *curves[] = {"s-curve", "harrison", "nordell", "linear"};
    const char *curve = curves[pick(&r, 4)];
    int rest = chance(&r, 0.3), stabilize = chance(&r, 0.5);
    double delay = rest && !stabilize ? uniform(&r, 2.0, 3.0) : 0.0;
    double bearing = chance(&r, 0.3) ? uniform(&r, 0.5, 5.0) : 0.0;

    /* rigid-body sizing (what a designer does by hand): running force,
     * start force, slack-side tension for the capstan with margin, sag */
    double cosd = cos(incline), Lc = L / cosd;
    double idler_I = 0.01, idler_r = 0.0635;
    double F_run = rr * G * cosd * (Lc * (mB + mL) + Lc * mB) + mL * G * H + mL * v * v;
    double M = 2.0 * Lc * mB + Lc * mL
             + (Lc / a_carry + Lc / a_return) * idler_I / (idler_r * idler_r)
             + drive_inertia / (Rh * Rh) + 600.0;
    double a_max = 2.0 * v / ramp;
    double F_start = fabs(F_run) + M * a_max;
    double rated_T = 0.0, t_acc = 0.0;
    if (motor) {
        /* Kloss with breakdown 2.2 and rated slip s_r starts with
         * T(1)/T_rated = 2·2.2·s_b/(1 + s_b²), s_b = s_r·(2.2 + √(2.2² − 1)):
         * about a quarter; size the motor to start the loaded belt */
        double s_b = 0.02 * (2.2 + sqrt(2.2 * 2.2 - 1.0));
        double start_ratio = 2.0 * 2.2 * s_b / (1.0 + s_b * s_b);
        rated_T = (fabs(F_run) + M * v / 6.0) * Rh * uniform(&r, 1.3, 1.8) / start_ratio;
        F_start = 2.2 * rated_T / Rh;
        t_acc = M * v / (1.2 * rated_T / Rh - F_run);
        if (t_acc < 1.0)
            t_acc = 1.0;
    }
    double wraps = drives == DRIVE_DUAL ? 2.0 : 1.0;
    /* the slack side a drive needs for its start force by the capstan
     * law T1/T2 = e^(μφ) (Euler–Eytelwein; seed 001, test_capstan) with
     * 30 % margin, plus the belt's lift between it and the takeup.
     * A tail drive's slack side is the carry leaving the tail: with the
     * takeup at the head it sits below the takeup's tension by the
     * carry's lift and resistance and the feed's acceleration of the
     * material (the belt's own lift is already counted). Seed 3341
     * (loaded, +12°) slipped at half speed once full without it. On a
     * dual drive the head drive's pull raises the carry above the tail
     * by its share, so there the term errs on the safe side. */
    double T_slip = F_start / wraps * 1.3 / (exp(mu_d * PI) - 1.0) + mB * G * fabs(H);
    if (drives != DRIVE_HEAD && takeup == LOOP_HEAD)
        T_slip += fmax(0.0, mL * G * H + rr * G * cosd * Lc * (mB + mL) + mL * v * v);
    double T_sag = (mB + mL) * G * a_carry / (8.0 * 0.015);
    double T0 = (T_slip > T_sag ? T_slip : T_sag) * uniform(&r, 1.1, 1.5);
    double T_max = T0 + F_start + mB * G * fabs(H);
    double EA = T_max / uniform(&r, 0.003, 0.012);
    /* the snub is no smaller than the others: the default element is the
     * 30° chord of the smallest pulley, drawn before the snub's turn */
    double R_min = fmin(fmin(Rh, Rt), takeup == TAIL_TAKEUP ? 1.0 : fmin(Rb, Rk));
    double Rs = fmax(Rs_draw, R_min);
    double elem_default = element_unit > 0.0 ? element_unit : 2.0 * R_min * sin(15.0 * PI / 180.0);
    double elem = axial ? (chance(&r, 0.5) ? 0.0 : uniform(&r, 0.5, 2.0))
                        : (chance(&r, 0.5) ? 0.0 : uniform(&r, 0.5, 1.0) * elem_default);
    /* the curve's radius against the carry's highest tension, and no less
     * than its chord */
    double vcurve_R = fmax(vcurve_margin * T_max / (mB * G), 2.0 * vcurve_len * Lc);

    double ramp_end = motor ? 0.5 + 1.5 * t_acc : delay + ramp;
    double fill = preloaded ? 0.0 : Lc / v;
    /* a motor started direct on line swings about its operating point
     * with the belt before it settles: more time */
    double duration = ramp_end + fill + opt->settle * (motor ? 3.0 : 1.0);

    static const char *tk_names[] = {"head loop", "tail loop", "tail takeup"};
    static const char *dr_names[] = {"head", "tail", "dual"};
    if (info) {
        snprintf(info->summary, sizeof info->summary,
                 "%s drive (%s), %s, L %.0f m at %+.1f deg, %s%s, v %.2f m/s, %s%s, zeta %.2f, "
                 "J_d %.0f", dr_names[drives], motor ? "motor" : curve, tk_names[takeup], L,
                 incline * 180.0 / PI, mL > 0.0 ? "loaded" : "empty",
                 mL > 0.0 && !preloaded ? " (filling)" : "", v, rest ? "rest" : "static",
                 stabilize ? "+stabilize" : "", zeta, drive_inertia);
        if (snub)
            snprintf(info->summary + strlen(info->summary),
                     sizeof info->summary - strlen(info->summary), ", snub");
        if (vcurve)
            snprintf(info->summary + strlen(info->summary),
                     sizeof info->summary - strlen(info->summary), ", %s curve R %.0f m",
                     vcurve_convex ? "convex" : "concave", vcurve_R);
        info->speed = v;
        info->ramp_end = ramp_end;
        info->duration = duration;
        info->motor = motor;
    }

    put(&o, "# generated conveyor, seed %lu: %s\n", seed, info ? info->summary : "");
    put(&o, "name: generated %lu\ngravity: %.6g\n", seed, G);
    put(&o, "belt:\n  formulation: %s\n  mass_per_length: %.6g\n  axial_stiffness: %.6g\n"
            "  damping_ratio: %.6g\n", opt->formulation, mB, EA, zeta);
    /* a mesh study scales the element the conveyor would have (the drawn
     * one or the default); the draws above are unchanged */
    if (opt->element_scale > 0.0 && !axial)
        elem = (elem > 0.0 ? elem : elem_default) * opt->element_scale;
    if (elem > 0.0 && !no_element)
        put(&o, "  element_length: %.6g\n", elem);
    if (opt->bending_stiffness > 0.0)
        put(&o, "  bending_stiffness: %.6g\n", opt->bending_stiffness);
    /* the moving-node belt: half of the conveyors with span nodes between
     * the idlers too (transverse waves on the spans; from a stream of its
     * own, the other belts' conveyors unchanged) */
    rng r_span = {0x5A4EULL + 32452843ULL * (unsigned long long)seed};
    if (strcmp(opt->formulation, "moving_node") == 0 && chance(&r_span, 0.5))
        put(&o, "  span_element_length: %.6g\n", uniform(&r_span, 0.2, 1.0));

    /* drives: a motor's gear ratio suits its own pulley, so that dual
     * drives on pulleys of different radii run the belt at one speed */
    char drive_head[1024], drive_tail[1024];
    out d_head = {drive_head, sizeof drive_head, 0}, d_tail = {drive_tail, sizeof drive_tail, 0};
    for (int which = 0; which < 2; which++) {
        out *d = which == 0 ? &d_head : &d_tail;
        double R = which == 0 ? Rh : Rt;
        if (motor) {
            double w_sync = 1500.0 * 2.0 * PI / 60.0;
            double gear = w_sync * R / (v * 1.01);
            double rpm_rated = 1500.0 * (1.0 - 0.02);
            put(d, "    drive:\n      control: motor\n      inertia: %.6g\n      motor: "
                   "{rated_power: %.6g, rated_speed_rpm: %.6g, synchronous_speed_rpm: 1500, "
                   "breakdown_torque_ratio: 2.2, gear_ratio: %.6g, start_time: 0.5}\n",
                drive_inertia, rated_T * (R / Rh) / gear * rpm_rated * 2.0 * PI / 60.0,
                rpm_rated, gear);
        } else {
            put(d, "    drive:\n      control: speed\n      speed: %.6g\n      inertia: %.6g\n"
                   "      start: {curve: %s, time: %.6g, delay: %.6g}\n",
                v, drive_inertia, curve, ramp, delay);
        }
        put(d, "    friction: {static: %.6g, dynamic: %.6g}\n", mu_s, mu_d);
    }

    double mh = uniform(&r, 200.0, 800.0) * (Rh / 0.5) * (Rh / 0.5);
    double mt = uniform(&r, 200.0, 800.0) * (Rt / 0.5) * (Rt / 0.5);
    double yret_slope = (H - Rh + Rt) / L;
    double drop = uniform(&r, 3.0, 8.0);
    /* both strands at T0 pull the takeup pulley (180° wrap) */
    double T_takeup = 2.0 * T0;
    int constant_force = chance(&r, 0.3);
    double carriage = uniform(&r, 50.0, 500.0);

    put(&o, "pulleys:\n");
    put_pulley(&o, "head", L, H, Rh, "cw", mh, 0.0);
    if (drives != DRIVE_TAIL)
        put(&o, "%s", drive_head);
    if (snub) {
        /* just behind the head, its top below the carry strand: the belt
         * wraps the head past its bottom, rises to the snub, passes over
         * it (ccw) and goes down its far side to the return strand */
        double xs = L - Rh - Rs - snub_gap;
        double ys = Rt + (H + Rh - Rt) * xs / L - snub_clearance - Rs;
        put_pulley(&o, "snub", xs, ys, Rs, "ccw", uniform(&r_snub, 80.0, 250.0), bearing);
    }
    if (takeup != TAIL_TAKEUP) {
        double xc = takeup == LOOP_HEAD ? L - Rh - 2.0 - Rb - Rk : Rt + 3.0 + Rb + Rk;
        double x1 = xc + Rk + Rb, x2 = xc - Rk - Rb;
        double y1 = -Rt + yret_slope * x1 - Rb, y2 = -Rt + yret_slope * x2 - Rb;
        double yk = fmin(y1, y2) - drop;
        double mk = uniform(&r, 100.0, 300.0);
        put_pulley(&o, "bend1", x1, y1, Rb, "ccw", uniform(&r, 100.0, 300.0), bearing);
        put_pulley(&o, "takeup", xc, yk, Rk, "cw", mk, bearing);
        /* the pulley's own weight pulls too: the counterweight makes up the rest */
        if (constant_force)
            put(&o, "    takeup: {type: constant_force, force: %.6g, mass: %.6g}\n",
                T_takeup - mk * G, carriage);
        else
            put(&o, "    takeup: {type: gravity, mass: %.6g}\n", T_takeup / G - mk);
        put_pulley(&o, "bend2", x2, y2, Rb, "ccw", uniform(&r, 100.0, 300.0), bearing);
    }
    put_pulley(&o, "tail", 0.0, 0.0, Rt, "cw", mt, drives == DRIVE_HEAD ? bearing : 0.0);
    if (drives != DRIVE_HEAD)
        put(&o, "%s", drive_tail);
    if (takeup == TAIL_TAKEUP) {
        /* horizontal along the conveyor: the pull leads away from the head */
        if (constant_force)
            put(&o, "    takeup: {type: constant_force, force: %.6g, mass: %.6g, "
                    "axis: [%.6g, %.6g]}\n",
                T_takeup, carriage, -cos(incline), -sin(incline));
        else
            put(&o, "    takeup: {type: gravity, mass: %.6g, axis: [%.6g, %.6g]}\n",
                T_takeup / G, -cos(incline), -sin(incline));
    }

    /* idlers: the carry strand leaves the tail; the long return span
     * leaves bend2 (head loop), or the snub, or the head */
    put(&o, "idlers:\n");
    if (vcurve)
        put(&o, "  - {span: tail, spacing: %.6g, rolling_resistance: %.6g, rotating_mass: 15,\n"
                "     curve: {radius: %.6g, from: %.6g, to: %.6g%s}}\n",
            a_carry, rr, vcurve_R, vcurve_from, vcurve_from + vcurve_len,
            vcurve_convex ? ", sense: convex" : "");
    else
        put(&o, "  - {span: tail, spacing: %.6g, rolling_resistance: %.6g, rotating_mass: 15}\n",
            a_carry, rr);
    const char *return_span = takeup == LOOP_HEAD ? "bend2" : snub ? "snub" : "head";
    put(&o, "  - {span: %s, spacing: %.6g, rolling_resistance: %.6g, rotating_mass: 10}\n",
        return_span, a_return, rr);
    if (mL > 0.0)
        put(&o, "material:\n  mass_per_length: %.6g\n  feed: {span: tail, at: %.6g}\n"
                "  discharge: head\n  initially_loaded: %s\n",
            mL, uniform(&r, 0.03, 0.15), preloaded ? "true" : "false");
    put(&o, "simulation:\n  duration: %.6g\n  output_interval: 0.05\n  initial_state: %s\n"
            "  stabilize: %s\n", duration, rest ? "rest" : "static", stabilize ? "true" : "false");
    /* the checks read the belt speed at the first probe */
    put(&o, "  probes:\n    - {name: carry, span: tail, at: 0.5}\n"
            "    - {name: return, span: %s, at: 0.5}\n", return_span);
    return o.len;
}

/* The discrete and rfe belts' element lengths are drawn up to the model's
 * own default: the discrete belt's halved where the idlers turn the belt
 * sharply, the rfe belt's half of it always (belt/lumped/idler_turn.c,
 * asked here with the conveyor written without one). Other belts, and
 * discrete conveyors the build does not refine, are drawn as before, byte
 * for byte. (The rfe belt's were drawn up to the
 * discrete belt's unhalved default until 2026-12-01, twice its own on
 * seeds 3 and 9: +4.1 and +10.2 % over their law there, docs/physics.md
 * §15.) */
size_t bd_gen_conveyor(unsigned long seed, const bd_gen_options *opt, char *buf, size_t size,
                       bd_gen_info *info)
{
    if (strcmp(opt->formulation, "discrete") && strcmp(opt->formulation, "rfe"))
        return generate(seed, opt, 0.0, 0, buf, size, info);
    size_t len = generate(seed, opt, 0.0, 1, buf, size, info);
    if (len >= size)
        return len;
    double unit = 0.0;
    bd_model_def def;
    bd_diag diag;
    bd_diag_init(&diag);
    if (bd_model_load_string(buf, len, "generated", &def, &diag) == 0) {
        bd_path path;
        if (bd_path_build(&def, &path, &diag) == 0) {
            int refined;
            double l = bd_lumped_default_element_on(&def, &path, &refined);
            unit = refined || strcmp(opt->formulation, "rfe") == 0 ? l : 0.0;
            bd_path_free(&path);
        }
        bd_model_def_free(&def);
    }
    bd_diag_free(&diag);
    return generate(seed, opt, unit, 0, buf, size, info);
}
