/* Design-standard calculation against hand calculations (issue 3).
 *
 * Three conveyors, each under DIN 22101 and CEMA, worked by hand below step
 * by step (g = 9.81 m/s², belt m'G = Wb = 20 kg/m, carry idlers every
 * 1.2 m with 18 kg rotating → m'R = 15 kg/m, return idlers every 3.0 m with
 * 12 kg → m'R = 4 kg/m, drive friction mu = 0.30, wrap 180°:
 * e^(0.3π) − 1 = 1.566332). Each result is asserted within 0.5 %.
 * The same models are in tests/data/static_{horizontal,incline,decline}.yaml
 * (checked through the loader in test_standards_files.c). */
#include "beltdyn/standards.h"
#include "standards/standards_internal.h"
#include "testlib.h"

#include <stdlib.h>
#include <string.h>

#define TOL 0.005 /* acceptance: within 0.5 % */

/* ---- building models by hand ------------------------------------------ */

static bd_pulley_def *add_pulley(bd_model_def *m, const char *name, double x, double y,
                                 int wrap)
{
    bd_pulley_def *p = &m->pulleys[m->pulley_count++];
    *p = bd_pulley_default();
    snprintf(p->name, sizeof p->name, "%s", name);
    p->x = x;
    p->y = y;
    p->radius = 0.5;
    p->wrap = wrap;
    return p;
}

static void add_idlers(bd_model_def *m, int span, double spacing, double rot_mass,
                       double radius)
{
    bd_idler_set_def *s = &m->idler_sets[m->idler_set_count++];
    *s = bd_idler_set_default();
    s->span = span;
    s->spacing = spacing;
    s->rotating_mass = rot_mass;
    s->radius = radius;
}

static void set_drive(bd_pulley_def *p, double speed)
{
    p->has_drive = 1;
    p->drive = bd_drive_default();
    p->drive.control = BD_CONTROL_SPEED;
    p->drive.speed = speed;
}

static void set_gravity_takeup(bd_pulley_def *p, double mass, double ax, double ay, double g)
{
    static double t0[8], v0[8];
    static int used = 0;
    p->has_takeup = 1;
    p->takeup = bd_takeup_default();
    p->takeup.type = BD_TAKEUP_GRAVITY;
    p->takeup.mass = mass;
    p->takeup.axis[0] = ax;
    p->takeup.axis[1] = ay;
    /* the loader's table: one point, mass·gravity */
    int k = used++ % 8;
    t0[k] = 0.0;
    v0[k] = mass * g;
    p->takeup.force.n = 1;
    p->takeup.force.t = &t0[k];
    p->takeup.force.v = &v0[k];
}

static void model_begin(bd_model_def *m, bd_standard std)
{
    bd_model_def_init(m);
    snprintf(m->name, sizeof m->name, "test");
    m->gravity = 9.81;
    m->belt.mass_per_length = 20.0;
    m->belt.axial_stiffness = 1e7;
    m->pulleys = calloc(8, sizeof *m->pulleys);
    m->idler_sets = calloc(8, sizeof *m->idler_sets);
    m->design = bd_design_default();
    m->design.present = 1;
    m->design.standard = std;
}

static void model_end(bd_model_def *m)
{
    /* tables point at static storage: detach before freeing */
    for (int i = 0; i < m->pulley_count; i++) {
        m->pulleys[i].takeup.force.n = 0;
        m->pulleys[i].takeup.force.t = m->pulleys[i].takeup.force.v = NULL;
    }
    bd_model_def_free(m);
}

static void set_material(bd_model_def *m, double mL, int feed, int discharge)
{
    m->material = bd_material_default();
    m->material.present = 1;
    m->material.mass_per_length = mL;
    m->material.feed_span = feed;
    m->material.feed_at = 0.0;
    m->material.discharge = discharge;
}

/* A: horizontal, 100 m between tail and head, vertical gravity takeup loop
 * in the return run:
 *   0 tail (0,0) cw → 1 head (100,0) cw, drive 2 m/s → 2 b1 (60,-1) ccw
 *   → 3 tu (59,-6) cw, gravity takeup, axis (0,-1) → 4 b2 (58,-1) ccw → tail
 * spans: tail 100 m carry (+x, loaded 60 kg/m), head 40 m return (-x),
 * b1 5 m down, tu 5 m up, b2 58 m return (-x). Idlers on tail (carry) and
 * on head and b2 (return). */
static void model_horizontal(bd_model_def *m, bd_standard std, double takeup_mass, double mu)
{
    model_begin(m, std);
    add_pulley(m, "tail", 0, 0, -1);
    bd_pulley_def *head = add_pulley(m, "head", 100, 0, -1);
    add_pulley(m, "b1", 60, -1, +1);
    bd_pulley_def *tu = add_pulley(m, "tu", 59, -6, -1);
    add_pulley(m, "b2", 58, -1, +1);
    set_drive(head, 2.0);
    head->friction.mu_dynamic = mu;
    set_gravity_takeup(tu, takeup_mass, 0.0, -1.0, m->gravity);
    add_idlers(m, 0, 1.2, 18.0, 0.0635);
    add_idlers(m, 1, 3.0, 12.0, 0.0635);
    add_idlers(m, 4, 3.0, 12.0, 0.0635);
    set_material(m, 60.0, 0, 1);
    m->design.cema.Ai = 8.01;
}

/* B: inclined, tail (0,0) → head (200,20), both cw, r 0.5: spans parallel to
 * the line of centres, L = √(200² + 20²) = 200.99751 m, L·cos δ = 200 m,
 * lift +20 m on the carry run, −20 m on the return. Drive head 3 m/s.
 * Gravity takeup on the tail, 3000 kg, pulling horizontally back, axis
 * (-1,0). Idler rolls 6 in (radius 0.0762 m). */
static void model_incline(bd_model_def *m, bd_standard std)
{
    model_begin(m, std);
    bd_pulley_def *tail = add_pulley(m, "tail", 0, 0, -1);
    bd_pulley_def *head = add_pulley(m, "head", 200, 20, -1);
    set_drive(head, 3.0);
    set_gravity_takeup(tail, 3000.0, -1.0, 0.0, m->gravity);
    add_idlers(m, 0, 1.2, 18.0, 0.0762);
    add_idlers(m, 1, 3.0, 12.0, 0.0762);
    set_material(m, 60.0, 0, 1);
}

/* C: declined, tail (0,30) → head (300,0), both cw: L = √(300² + 30²) =
 * 301.49627 m, L·cos δ = 300 m, lift −30 m on the carry run. 100 kg/m of
 * material, drive head 3 m/s, no takeup: belt.initial_tension = 20000 N at
 * the drive's slack side. DIN f = 0.012 (Table 2.2, drives as generators). */
static void model_decline(bd_model_def *m, bd_standard std)
{
    model_begin(m, std);
    add_pulley(m, "tail", 0, 30, -1);
    bd_pulley_def *head = add_pulley(m, "head", 300, 0, -1);
    set_drive(head, 3.0);
    m->belt.initial_tension = 20000.0;
    add_idlers(m, 0, 1.2, 18.0, 0.0635);
    add_idlers(m, 1, 3.0, 12.0, 0.0635);
    set_material(m, 100.0, 0, 1);
    m->design.f = 0.012;
}

static int has_warning(const bd_static_result *r, const char *text)
{
    for (int i = 0; i < r->warning_count; i++)
        if (strstr(r->warnings[i], text))
            return 1;
    return 0;
}

static void print_warnings(const bd_static_result *r)
{
    for (int i = 0; i < r->warning_count; i++)
        fprintf(stderr, "    warning: %s\n", r->warnings[i]);
}

static int compute(const bd_model_def *m, bd_static_result *r)
{
    bd_diag d;
    bd_diag_init(&d);
    int rc = bd_static_compute(m, r, &d);
    for (int i = 0; i < d.count + d.warning_count; i++)
        fprintf(stderr, "%s\n", d.lines[i]);
    bd_diag_free(&d);
    return rc;
}

/* ---- A: horizontal, DIN 22101 ------------------------------------------ */
/* f = 0.020; carrying run 100 m → Table 2.3: C = 1.78.
 * eq 2.10, F_H,i = f·g·[m'R,i + (m'G + m'L,i)·cos δ]·L_i, f·g = 0.1962:
 *   tail (carry)  0.1962·(15 + 20 + 60)·100 = 1863.9 N
 *   head (return) 0.1962·(4 + 20)·40        =  188.352 N
 *   b2 (return)   0.1962·(4 + 20)·58        =  273.1104 N
 *   b1, tu (vertical, no idlers, cos δ = 0)  =    0
 *   F_H = 2325.3624 N; F_N = 0.78·F_H = 1813.7827 N
 * eq 2.11, F_St: b1 −20·9.81·5 = −981 N, tu +981 N, sum 0.
 * Te = 1.78·2325.3624 = 4139.1451 N; P = Te·2 m/s = 8.27829 kW.
 * Takeup tu: u_in = (0,-1), u_out = (0,1), a = (0,-1):
 *   (u_in − u_out)·a = 2 → T = 2400·9.81/2 = 11772 N.
 * Along the travel from tu: b2 start 11772 + 981 = 12753;
 *   tail start (+1.78·273.1104) = 13239.1365; head arrival T1 =
 *   13239.1365 + 1.78·1863.9 = 16556.8785 N; T2 = T1 − Te = 12417.7334 N;
 *   b1 start = T2 + 1.78·188.352 = 12753.0 N; tu arrival 12753 − 981 = 11772 ✓.
 * Slip: T2_min = 4139.1451/1.566332 = 2642.571 N (T2 is above: no slip).
 * Sag: T_min = (20 + 60)·9.81·1.2/(8·0.01) = 11772 N; the carry span's
 *   lowest tension 13239.1 N is above: no warning. → a sound design. */
static void test_horizontal_din(void)
{
    bd_model_def m;
    bd_static_result r;
    model_horizontal(&m, BD_STANDARD_DIN22101, 2400.0, 0.30);
    CHECK(compute(&m, &r) == 0);
    CHECK_REL(r.C, 1.78, 1e-12);
    CHECK_REL(r.main_N, 2325.3624, TOL);
    CHECK_REL(r.secondary_N, 1813.7827, TOL);
    CHECK_ABS(r.slope_N, 0.0, 1e-6);
    CHECK_REL(r.effective_tension_N, 4139.1451, TOL);
    CHECK_REL(r.total_N, 4139.1451, TOL);
    CHECK_REL(r.power_kW, 8.27829, TOL);
    CHECK_REL(r.T1_N, 16556.8785, TOL);
    CHECK_REL(r.T2_N, 12417.7334, TOL);
    CHECK_REL(r.T2_min_slip_N, 2642.571, TOL);
    CHECK_REL(r.T_min_sag_N, 11772.0, TOL);
    CHECK_REL(r.takeup_force_N, 23544.0, TOL);
    CHECK(r.span_count == 5);
    CHECK_REL(r.spans[0].length_m, 100.0, 1e-9);
    CHECK_REL(r.spans[0].T_start_N, 13239.1365, TOL);
    CHECK_REL(r.spans[0].T_end_N, 16556.8785, TOL);
    CHECK_REL(r.spans[1].T_start_N, 12417.7334, TOL);
    CHECK_REL(r.spans[1].T_end_N, 12753.0, TOL);
    CHECK_REL(r.spans[2].T_end_N, 11772.0, TOL);
    CHECK_REL(r.spans[3].T_start_N, 11772.0, TOL);
    CHECK_REL(r.spans[3].T_end_N, 12753.0, TOL);
    CHECK_REL(r.spans[4].T_end_N, 13239.1365, TOL);
    CHECK_REL(r.spans[0].main_N, 1863.9, TOL);
    CHECK_REL(r.spans[0].secondary_N, 0.78 * 1863.9, TOL);
    CHECK(r.spans[0].loaded && r.spans[0].carry);
    CHECK(!r.spans[1].carry && !r.spans[4].carry);
    CHECK_REL(r.wrap_angle_rad * 180.0 / 3.14159265358979, 180.0, 1e-9);
    CHECK(!r.regenerative);
    /* the sound design: no warning */
    CHECK(r.warning_count == 0);
    print_warnings(&r);
    bd_static_free(&r);
    model_end(&m);
}

/* ---- A: horizontal, CEMA ------------------------------------------------ */
/* Kt = 1, C1 = 1 (not regenerative), Ai = 8.01 N (5 in rolls), Si = 1.2 m.
 * eq 2.2: Kx = 0.00068·(20 + 60)·9.81 + 8.01/1.2 = 0.533664 + 6.675
 *   = 7.208664 N/m.
 * Return runs (Kx = 0, Ky = 0.015), L·0.015·Wb·g:
 *   head 40·0.015·20·9.81 = 117.72 N, b2 58·… = 170.694 N; vertical spans
 *   have no idlers: no running resistance, only the lift ±981 N.
 * T_am = Wm·v² = 60·2² = 240 N at the feed point (start of the carry run).
 * Tension: tu 11772 (as DIN) → b2 start 12753 → tail start 12923.694 N.
 * Carry, eq 2.4: ΔT = L·(Kx + Ky·Wb·g) + Wm·g·L·Ky (+ T_am)
 *   = 720.8664 + 78480·Ky (+ 240); average tension
 *   T_avg = 12923.694 + (960.8664 + 78480·Ky)/2.
 * Table 2.1 at the solution: T_avg = 14288.859 N = 3212.263 lbf (row 3000,
 *   u = 0.212263), S = 1.2 m = 3.937008 ft (column 3.5, w = 0.874016),
 *   W = 80 kg/m = 53.757518 lb/ft: A = 0.9505978, B = 1.7436513,
 *   eq 2.3 Ky = 53.757518·0.9505978e-4 + 1.7436513e-2 = 0.02254669.
 * Carry ΔT w/o T_am = 720.8664 + 78480·0.02254669 = 2490.3307 N.
 * Te = 2490.3307 + 240 + 117.72 + 170.694 = 3018.7447 N; P = 6.03749 kW.
 * T1 = 12923.694 + 2490.3307 + 240 = 15654.0247 N; T2 = T1 − Te = 12635.28 N.
 * Slip: 3018.7447/1.566332 = 1927.270 N. */
static void test_horizontal_cema(void)
{
    bd_model_def m;
    bd_static_result r;
    model_horizontal(&m, BD_STANDARD_CEMA, 2400.0, 0.30);
    CHECK(compute(&m, &r) == 0);
    CHECK_REL(r.spans[0].cema_Kx, 7.208664, TOL);
    CHECK_REL(r.spans[0].cema_Ky, 0.02254669, TOL);
    CHECK_REL(r.spans[1].cema_Ky, 0.015, 1e-12);
    CHECK_REL(r.spans[0].main_N, 2490.3307, TOL);
    CHECK_REL(r.secondary_N, 240.0, TOL);
    CHECK_REL(r.effective_tension_N, 3018.7447, TOL);
    CHECK_REL(r.power_kW, 6.03749, TOL);
    CHECK_REL(r.T1_N, 15654.0247, TOL);
    CHECK_REL(r.T2_N, 12635.28, TOL);
    CHECK_REL(r.spans[0].T_start_N, 12923.694, TOL);
    CHECK_REL(r.spans[2].T_end_N, 11772.0, TOL);
    CHECK_REL(r.T2_min_slip_N, 1927.270, TOL);
    CHECK_REL(r.cema_C1, 1.0, 1e-12);
    CHECK(r.warning_count == 0);
    print_warnings(&r);
    bd_static_free(&r);
    model_end(&m);
}

/* ---- B: inclined with a 20 m lift, DIN 22101 ---------------------------- */
/* L = 200.99751 m; carrying run 200.99751 m → C = 1.45 + 0.0099751·(1.31 −
 *   1.45) = 1.4486035.
 * eq 2.10 (f·g = 0.1962): carry 0.1962·(15·200.99751 + 80·200) = 3730.7357 N
 *   return 0.1962·(4·200.99751 + 20·200) = 942.5428 N; F_H = 4673.2785 N,
 *   F_N = 0.4486035·F_H = 2096.4490 N.
 * eq 2.11: carry 9.81·80·20 = 15696 N, return 9.81·20·(−20) = −3924 N;
 *   F_St = 11772 N (= eq 2.8 H·g·m'L = 20·9.81·60).
 * Te = 1.4486035·4673.2785 + 11772 = 18541.7275 N; P = 55.62518 kW.
 * Takeup tail: u_in = (−cos δ, −sin δ), u_out = (cos δ, sin δ), a = (−1,0):
 *   (u_in − u_out)·a = 2 cos δ = 1.9900744 → T = 29430/1.9900744 = 14788.392 N.
 * T1 = 14788.392 + 1.4486035·3730.7357 + 15696 = 35888.749 N;
 * T2 = T1 − Te = 17347.021 N; back at the tail: T2 + 1.4486035·942.5428 −
 *   3924 = 14788.392 ✓. Slip minimum 18541.7275/1.566332 = 11837.671 N. */
static void test_incline_din(void)
{
    bd_model_def m;
    bd_static_result r;
    model_incline(&m, BD_STANDARD_DIN22101);
    CHECK(compute(&m, &r) == 0);
    CHECK_REL(r.spans[0].length_m, 200.99751, 1e-6);
    CHECK_REL(r.spans[0].lift_m, 20.0, 1e-6);
    CHECK_REL(r.C, 1.4486035, 1e-6);
    CHECK_REL(r.main_N, 4673.2785, TOL);
    CHECK_REL(r.secondary_N, 2096.4490, TOL);
    CHECK_REL(r.slope_N, 11772.0, TOL);
    CHECK_REL(r.effective_tension_N, 18541.7275, TOL);
    CHECK_REL(r.power_kW, 55.62518, TOL);
    CHECK_REL(r.T1_N, 35888.749, TOL);
    CHECK_REL(r.T2_N, 17347.021, TOL);
    CHECK_REL(r.spans[0].T_start_N, 14788.392, TOL);
    CHECK_REL(r.spans[1].T_end_N, 14788.392, TOL);
    CHECK_REL(r.T2_min_slip_N, 11837.671, TOL);
    CHECK_REL(r.takeup_force_N, 29430.0, TOL);
    CHECK(r.warning_count == 0);
    print_warnings(&r);
    bd_static_free(&r);
    model_end(&m);
}

/* ---- B: inclined, CEMA --------------------------------------------------- */
/* Ai not given → by roll diameter 2·0.0762 m = 6 in: Ai = 6.67 N.
 * eq 2.2: Kx = 0.533664 + 6.67/1.2 = 6.0919973 N/m.
 * Return: L·0.015·Wb·g = 200.99751·2.943 = 591.5357 N; lift −3924 N.
 * Carry lift (Wb + Wm)·g·ΔY = 80·9.81·20 = 15696 N; T_am = 60·3² = 540 N.
 * Tail 14788.392 N (as DIN). Carry friction by eq 2.4:
 *   L·(Kx + Ky·Wb·g) + Wm·g·L·Ky = 1224.4766 + 157774.05·Ky.
 * Table 2.1 at the solution: T_avg = 25005.262 N = 5621.406 lbf (row 5000,
 *   u = 0.621406), 3.937008 ft (column 3.5, w = 0.874016), 53.757518 lb/ft:
 *   A = 0.7449904, B = 1.4843913 → Ky = 0.01884880.
 * Carry friction = 1224.4766 + 157774.05·0.0188488 = 4197.7392 N.
 * Te = 4197.7392 + 540 + 15696 + 591.5357 − 3924 = 17101.2749 N,
 *   P = 51.30382 kW; T1 = 14788.392 + 4197.7392 + 540 + 15696 = 35222.131 N;
 *   T2 = 18120.856 N. */
static void test_incline_cema(void)
{
    bd_model_def m;
    bd_static_result r;
    model_incline(&m, BD_STANDARD_CEMA);
    CHECK(compute(&m, &r) == 0);
    CHECK_REL(r.cema_Ai_N, 6.67, 1e-12);
    CHECK_REL(r.spans[0].cema_Kx, 6.0919973, TOL);
    CHECK_REL(r.spans[0].cema_Ky, 0.01884880, TOL);
    CHECK_REL(r.spans[0].main_N, 4197.7392, TOL);
    CHECK_REL(r.spans[1].main_N, 591.5357, TOL);
    CHECK_REL(r.slope_N, 11772.0, TOL);
    CHECK_REL(r.effective_tension_N, 17101.2749, TOL);
    CHECK_REL(r.power_kW, 51.30382, TOL);
    CHECK_REL(r.T1_N, 35222.131, TOL);
    CHECK_REL(r.T2_N, 18120.856, TOL);
    CHECK(r.warning_count == 0);
    print_warnings(&r);
    bd_static_free(&r);
    model_end(&m);
}

/* ---- C: declined, regenerative, DIN 22101 -------------------------------- */
/* f = 0.012 → f·g = 0.11772; carrying run 301.49627 m → C = 1.31 +
 *   0.0149627·(1.25 − 1.31) = 1.3091022.
 * eq 2.10: carry 0.11772·(15·301.49627 + 120·300) = 4770.3021 N,
 *   return 0.11772·(4·301.49627 + 20·300) = 848.2886 N; F_H = 5618.5907 N,
 *   F_N = 0.3091022·F_H = 1736.7190 N.
 * eq 2.11: carry 9.81·120·(−30) = −35316 N, return 9.81·20·30 = 5886 N;
 *   F_St = −29430 N.
 * Te = 1.3091022·5618.5907 − 29430 = −22074.690 N < 0: regenerative, the
 *   drive brakes 22074.690·3 = 66.224 kW (power_kW = −66.224).
 * No takeup: slack side = the belt arriving at the braking head = 20000 N.
 *   T2 = 20000 N; T1 (tight, leaving the head) = 20000 + 22074.690 =
 *   42074.690 N; tail: T1 + 1.3091022·848.2886 + 5886 = 49071.187 N;
 *   carry back to the head: 49071.187 + 1.3091022·4770.3021 − 35316 = 20000 ✓.
 * Slip: 22074.690/1.566332 = 14093.235 N (< T2: no slip);
 * sag: 120·9.81·1.2/0.08 = 17658 N (< 20000: no sag). */
static void test_decline_din(void)
{
    bd_model_def m;
    bd_static_result r;
    model_decline(&m, BD_STANDARD_DIN22101);
    CHECK(compute(&m, &r) == 0);
    CHECK_REL(r.C, 1.3091022, 1e-6);
    CHECK_REL(r.main_N, 5618.5907, TOL);
    CHECK_REL(r.secondary_N, 1736.7190, TOL);
    CHECK_REL(r.slope_N, -29430.0, TOL);
    CHECK_REL(r.effective_tension_N, -22074.690, TOL);
    CHECK_REL(r.power_kW, -66.22407, TOL);
    CHECK(r.regenerative);
    CHECK_REL(r.T2_N, 20000.0, TOL);
    CHECK_REL(r.T1_N, 42074.690, TOL);
    CHECK_REL(r.spans[1].T_start_N, 42074.690, TOL);
    CHECK_REL(r.spans[1].T_end_N, 49071.187, TOL);
    CHECK_REL(r.spans[0].T_start_N, 49071.187, TOL);
    CHECK_REL(r.spans[0].T_end_N, 20000.0, TOL);
    CHECK_REL(r.T2_min_slip_N, 14093.235, TOL);
    CHECK_REL(r.T_min_sag_N, 17658.0, TOL);
    /* regenerative operation is said; no failed check besides */
    CHECK(r.warning_count == 1);
    CHECK(has_warning(&r, "regenerative"));
    CHECK(!has_warning(&r, "slips") && !has_warning(&r, "sag"));
    bd_static_free(&r);
    model_end(&m);
}

/* ---- C: declined, regenerative, CEMA ------------------------------------- */
/* Regenerative → seed 001 §2.2.1: Ai = 0, C1 = 0.5 (Kt = 1).
 * eq 2.2: Kx = 0.00068·120·9.81 + 0 = 0.800496 N/m.
 * Return: 301.49627·0.015·20·9.81 = 887.3035 N, lift +5886 N.
 * Carry lift 120·9.81·(−30) = −35316 N; T_am = 100·3² = 900 N.
 * Carry friction, eq 2.4: L·(Kx + C1·Ky·Wb·g) + Wm·g·C1·L·Ky
 *   = 241.3462 + 177437.01·Ky (L = 301.49627, C1 = 0.5).
 * The carry run ends at the slack side, 20000 N; it starts at
 *   20000 − (friction + 900 − 35316); T_avg = its mean.
 * Table 2.1 at the solution: T_avg = 35500.003 N = 7980.718 lbf (row 7000,
 *   u = 0.980718), 3.937008 ft (w = 0.874016), W = 120 kg/m = 80.636277
 *   lb/ft: A = 0.5812091, B = 1.3202640 → Ky = 0.01788929.
 * Carry friction = 241.3462 + 177437.01·0.01788929 = 3415.9932 N.
 * Te = 3415.9932 + 900 − 35316 + 887.3035 + 5886 = −24226.703 N;
 *   T2 = 20000, T1 = 44226.703 N; P = −72.6801 kW;
 *   slip minimum 24226.703/1.566332 = 15467.153 N. */
static void test_decline_cema(void)
{
    bd_model_def m;
    bd_static_result r;
    model_decline(&m, BD_STANDARD_CEMA);
    CHECK(compute(&m, &r) == 0);
    CHECK(r.regenerative);
    CHECK_REL(r.cema_C1, 0.5, 1e-12);
    CHECK_ABS(r.cema_Ai_N, 0.0, 1e-12);
    CHECK_REL(r.spans[0].cema_Kx, 0.800496, TOL);
    CHECK_REL(r.spans[0].cema_Ky, 0.01788929, TOL);
    CHECK_REL(r.spans[0].main_N, 3415.9932, TOL);
    CHECK_REL(r.effective_tension_N, -24226.703, TOL);
    CHECK_REL(r.power_kW, -72.6801, TOL);
    CHECK_REL(r.T2_N, 20000.0, TOL);
    CHECK_REL(r.T1_N, 44226.703, TOL);
    CHECK_REL(r.spans[0].T_start_N, 51000.007, TOL);
    CHECK_REL(r.T2_min_slip_N, 15467.153, TOL);
    CHECK(has_warning(&r, "regenerative"));
    CHECK(!has_warning(&r, "slips") && !has_warning(&r, "sag"));
    bd_static_free(&r);
    model_end(&m);
}

/* ---- checks: slip and sag ------------------------------------------------ */
/* Slipping: conveyor A with a wet drive, mu = 0.05: e^(0.05π) − 1 =
 * 0.1700888, T2_min = 4139.1451/0.1700888 = 24335.3 N > T2 = 12417.7 N.
 * Sagging: conveyor A with a 1500 kg counterweight: T = 7357.5 N at tu,
 * tail 7357.5 + 981 + 486.1365 = 8824.64 N < 11772 N. */
static void test_checks(void)
{
    bd_model_def m;
    bd_static_result r;

    model_horizontal(&m, BD_STANDARD_DIN22101, 2400.0, 0.05);
    CHECK(compute(&m, &r) == 0);
    CHECK_REL(r.T2_min_slip_N, 24335.3, TOL);
    CHECK(has_warning(&r, "drive slips"));
    CHECK(!has_warning(&r, "sag"));
    bd_static_free(&r);
    model_end(&m);

    model_horizontal(&m, BD_STANDARD_DIN22101, 1500.0, 0.30);
    CHECK(compute(&m, &r) == 0);
    CHECK_REL(r.spans[0].T_start_N, 8824.6365, TOL);
    CHECK(has_warning(&r, "sag:"));
    CHECK(!has_warning(&r, "slips"));
    bd_static_free(&r);
    model_end(&m);

    /* the same checks under CEMA */
    model_horizontal(&m, BD_STANDARD_CEMA, 2400.0, 0.05);
    CHECK(compute(&m, &r) == 0);
    CHECK(has_warning(&r, "drive slips"));
    bd_static_free(&r);
    model_end(&m);
    model_horizontal(&m, BD_STANDARD_CEMA, 1500.0, 0.30);
    CHECK(compute(&m, &r) == 0);
    CHECK(has_warning(&r, "sag:"));
    bd_static_free(&r);
    model_end(&m);
}

/* ---- level rules and drive sharing --------------------------------------- */
static void test_level_rules(void)
{
    bd_model_def m;
    bd_static_result r;

    /* a fixed takeup holds belt.initial_tension at its pulley; its reaction
     * along the axis is 2·11772 = 23544 N; tensions as with 2400 kg */
    model_horizontal(&m, BD_STANDARD_DIN22101, 2400.0, 0.30);
    m.pulleys[3].takeup.type = BD_TAKEUP_FIXED;
    m.belt.initial_tension = 11772.0;
    CHECK(compute(&m, &r) == 0);
    CHECK_REL(r.T1_N, 16556.8785, TOL);
    CHECK_REL(r.takeup_force_N, 23544.0, TOL);
    bd_static_free(&r);
    model_end(&m);

    /* two drives (head and tail) share Te equally: each takes 2069.5726 N;
     * T1/T2 are the head's, and the tension still closes around the loop */
    model_horizontal(&m, BD_STANDARD_DIN22101, 2400.0, 0.30);
    set_drive(&m.pulleys[0], 2.0);
    CHECK(compute(&m, &r) == 0);
    CHECK(r.drive_count == 2);
    CHECK(r.drive_pulley == 0);
    CHECK_REL(r.effective_tension_N, 4139.1451, TOL);
    /* tail is the first drive: the belt arrives at 13239.1365 N (takeup
     * level as before) and leaves 13239.1365 − 2069.5726 = 11169.5639 N */
    CHECK_REL(r.T1_N, 13239.1365, TOL);
    CHECK_REL(r.T2_N, 11169.5639, TOL);
    CHECK_REL(r.spans[0].T_end_N - r.spans[1].T_start_N, 2069.5726, TOL);
    CHECK_REL(r.T2_min_slip_N, 2069.5726 / 1.5663324, TOL);
    bd_static_free(&r);
    model_end(&m);

    /* feed half-way along the carry span: only its last 50 m carry
     * material; F_H,carry = 0.1962·(15·100 + 20·100 + 60·50) = 1275.3 N,
     * C stays 1.78 (the carrying run is the whole span, cli.md):
     * Te = 1.78·(1275.3 + 188.352 + 273.1104) = 3091.4371 N */
    model_horizontal(&m, BD_STANDARD_DIN22101, 2400.0, 0.30);
    m.material.feed_at = 0.5;
    CHECK(compute(&m, &r) == 0);
    CHECK_REL(r.spans[0].loaded_length_m, 50.0, 1e-9);
    CHECK_REL(r.spans[0].main_N, 1275.3, TOL);
    CHECK_REL(r.C, 1.78, 1e-12);
    CHECK_REL(r.effective_tension_N, 3091.4371, TOL);
    bd_static_free(&r);
    model_end(&m);

    /* a 50 m conveyor: C auto = 1.92 and the warning */
    model_begin(&m, BD_STANDARD_ISO5048);
    add_pulley(&m, "tail", 0, 0, -1);
    bd_pulley_def *head = add_pulley(&m, "head", 50, 0, -1);
    set_drive(head, 1.0);
    m.belt.initial_tension = 20000.0;
    add_idlers(&m, 0, 1.2, 18.0, 0.0635);
    set_material(&m, 60.0, 0, 1);
    CHECK(compute(&m, &r) == 0);
    CHECK_REL(r.C, 1.92, 1e-12);
    CHECK(has_warning(&r, "below the 80 m"));
    /* the ISO 5048 name in the JSON */
    char *json = bd_static_to_json(&r, &m);
    CHECK(json && strstr(json, "\"standard\":\t\"iso5048\""));
    free(json);
    bd_static_free(&r);
    model_end(&m);
}

/* ---- tables and unit conversions ----------------------------------------- */
static void test_tables(void)
{
    int cl = 0;
    /* Table 2.1 at a grid point: 8000 lbf = 35585.77 N, 4 ft = 1.2192 m,
     * 100 lb/ft = 148.81639 kg/m: Ky = 100·0.5808e-4 + 1.337e-2 = 0.019178 */
    CHECK_REL(bd_cema_ky(8000 * 4.4482216152605, 4 * 0.3048, 148.81639435695537, &cl),
              0.019178, 1e-9);
    CHECK(cl == 0);
    /* midway between 3.0 and 3.5 ft and between 1000 and 2000 lbf, W = 0:
     * B = (1.565 + 1.925 + 1.345 + 1.744)/4 = 1.64475 → Ky = 0.0164475 */
    CHECK_REL(bd_cema_ky(1500 * 4.4482216152605, 3.25 * 0.3048, 0.0, &cl), 0.0164475, 1e-9);
    /* above 16000 lbf (71.17 kN): 0.016 */
    CHECK_REL(bd_cema_ky(71200.0, 1.2, 100.0, &cl), 0.016, 1e-12);
    CHECK(cl == 0);
    /* below the table: the 1000 lbf row, flagged */
    double low = bd_cema_ky(1000.0, 0.9144, 0.0, &cl);
    CHECK_REL(low, 0.01565, 1e-9);
    CHECK(cl == 1);
    /* Table 2.3 */
    CHECK_REL(bd_din22101_C(50.0), 1.92, 1e-12);
    CHECK_REL(bd_din22101_C(80.0), 1.92, 1e-12);
    CHECK_REL(bd_din22101_C(100.0), 1.78, 1e-12);
    CHECK_REL(bd_din22101_C(125.0), 1.68, 1e-12);
    CHECK_REL(bd_din22101_C(1250.0), 1.075, 1e-12);
    CHECK_REL(bd_din22101_C(5000.0), 1.05, 1e-12);
}

/* ---- outputs -------------------------------------------------------------- */
static void test_outputs(void)
{
    bd_model_def m;
    bd_static_result r;
    model_horizontal(&m, BD_STANDARD_DIN22101, 1500.0, 0.30);
    CHECK(compute(&m, &r) == 0);
    char *json = bd_static_to_json(&r, &m);
    CHECK(json != NULL);
    if (json) {
        const char *keys[] = {"\"standard\"", "\"resistances_N\"", "\"main\"",
                              "\"secondary\"", "\"slope\"", "\"total\"",
                              "\"effective_tension_N\"", "\"power_kW\"", "\"T1_N\"",
                              "\"T2_N\"", "\"T2_min_slip_N\"", "\"T_min_sag_N\"",
                              "\"takeup_force_N\"", "\"spans\"", "\"from\"", "\"length_m\"",
                              "\"T_start_N\"", "\"T_end_N\"", "\"warnings\"", "sag:"};
        for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
            CHECK(strstr(json, keys[i]) != NULL);
        free(json);
    }
    FILE *f = tmpfile();
    CHECK(f != NULL);
    if (f) {
        bd_static_print_table(&r, &m, f);
        long size = ftell(f);
        CHECK(size > 500);
        rewind(f);
        char buf[8192];
        size_t got = fread(buf, 1, sizeof buf - 1, f);
        buf[got] = 0;
        CHECK(strstr(buf, "effective tension Te (N)") != NULL);
        CHECK(strstr(buf, "T start (N)") != NULL);
        CHECK(strstr(buf, "sag:") != NULL);
        fclose(f);
    }
    bd_static_free(&r);
    model_end(&m);

    /* no drive: an error, not a result */
    model_begin(&m, BD_STANDARD_DIN22101);
    add_pulley(&m, "a", 0, 0, -1);
    add_pulley(&m, "b", 10, 0, -1);
    bd_diag d;
    bd_diag_init(&d);
    CHECK(bd_static_compute(&m, &r, &d) != 0);
    CHECK(d.count == 1 && strstr(d.lines[0], "drive"));
    bd_diag_free(&d);
    model_end(&m);
}

int main(void)
{
    test_tables();
    test_horizontal_din();
    test_horizontal_cema();
    test_incline_din();
    test_incline_cema();
    test_decline_din();
    test_decline_cema();
    test_checks();
    test_level_rules();
    test_outputs();
    return bd_test_finish("test_standards");
}
