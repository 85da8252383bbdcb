/* Building the RFE belt: the lumped chain of the elements' mass centres
 * (belt/lumped/build.c: the layout at rest on the path, contacts, idlers,
 * probes, feed), then each element's orientation along the path and the
 * SDEs' shear and bending (seed 000 §2.1–2.3). */
#include "belt/rfe/rfe.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "base/alloc.h"
#include "base/constants.h"
#include "belt/lumped/layout.h"
#include "laws/stable_step.h"
#include "parts/parts.h"

/* the state's arrays of doubles, [n] each */
static const size_t RFE_DOUBLES[] = {
    offsetof(bd_rfe, omega), offsetof(bd_rfe, ct),  offsetof(bd_rfe, st),
    offsetof(bd_rfe, tq),  offsetof(bd_rfe, tqn),   offsetof(bd_rfe, q),   offsetof(bd_rfe, qd),
    offsetof(bd_rfe, mb),  offsetof(bd_rfe, mbd),   offsetof(bd_rfe, thdot),
    offsetof(bd_rfe, px),  offsetof(bd_rfe, py),
    offsetof(bd_rfe, h),   offsetof(bd_rfe, hd),    offsetof(bd_rfe, pw),  offsetof(bd_rfe, ek),
    offsetof(bd_rfe, rinv), offsetof(bd_rfe, rcp),  offsetof(bd_rfe, rz),  offsetof(bd_rfe, rb)};
#define COUNT(a) ((int)(sizeof a / sizeof a[0]))

/* GA: model-format.md `shear_stiffness`, default 10·EA */
double bd_rfe_shear_stiffness(const bd_model_def *def)
{
    return def->belt.shear_stiffness > 0.0 ? def->belt.shear_stiffness
                                           : 10.0 * def->belt.axial_stiffness;
}

/* the SDEs' constants from the belt's (seed 000 §2.3, a rectangular
 * section of thickness h): k_γ = GA·l0, k_β = EI/l0, J = m·(l0² + h²)/12
 * of the belt's own mass m (seed 000 §2.1 assumption i: the element is the
 * belt; material on it adds to the mass its centre carries, not to J);
 * each dashpot the damping ratio ζ of the element's critical damping of
 * its own spring, c = 2ζ·√(k·J) for the rotations (the element's rotary
 * inertia is what they move) */
static void sde_constants(const bd_model_def *def, double l0, bd_rfe_model *RM)
{
    double m = def->belt.mass_per_length * l0, h = def->belt.thickness;
    double zeta = def->belt.damping_ratio;
    RM->gyration2 = (l0 * l0 + h * h) / 12.0;
    RM->inertia = m * RM->gyration2;
    RM->k_shear = bd_rfe_shear_stiffness(def) * l0;
    RM->k_bend = def->belt.bending_stiffness / l0;
    RM->c_shear = 2.0 * zeta * sqrt(RM->k_shear * m * RM->gyration2);
    RM->c_bend = 2.0 * zeta * sqrt(RM->k_bend * m * RM->gyration2);
}

/* each element along the path at its centre */
static void orient(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    for (int i = 0; i < sim->model->n; i++) {
        double p[2], t[2];
        bd_path_point(&sim->model->path, sim->model->s_node0[i], p, t);
        double inv = 1.0 / hypot(t[0], t[1]);
        R->ct[i] = t[0] * inv;
        R->st[i] = t[1] * inv;
    }
}

/* The orientations of least shear, alignment and bending energy with
 * the centres where they are, of the free elements first .. first +
 * count − 1 (all of them: the whole loop) with the others held, and with
 * turn_tied of the tied ones among them too (a section's end: an SDE
 * between two tied elements has no shear or bending energy, a tied
 * element no alignment, so only its SDE to the free belt turns it; one
 * inside its section has none and stays); the build's on the layout,
 * and where a section's end meets the free belt (sections.c). Along the
 * path's tangent the elements stand askew where the belt's curvature
 * jumps (a tangent point: the line between two centres there leans by
 * up to l0/(8R) from their tangents), and the stiff shear held up to
 * 2 kJ there on a 40 m conveyor that a start without stabilization let
 * go at once. The energy, the SDEs' shear and bending of seed 000 §2.3
 * and the alignment (forces.c), is quadratic in the turns δ_i from the
 * tangent (small angles):
 *   Σ ½k_γ(γ_e − ½(δ_i + δ_j))² + ½k_ψ,i(ψ_i + δ_i)² + ½k_β(β_e + δ_j − δ_i)²,
 * minimized by successive over-relaxation (Gauss–Seidel, factor
 * SOR_FACTOR) until no δ changes by RELAX_TOL rad; the alignment or the
 * bending makes it positive definite (forces.c) */
#define SOR_FACTOR 1.8
#define RELAX_STACK 64
#define RELAX_TOL 1e-13
#define RELAX_SWEEPS 20000

void bd_rfe_relax_turns(bd_sim *sim, int first, int count, int turn_tied)
{
    bd_rfe *R = bd_rfe_of(sim);
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const int n = sim->model->n, loop = count >= n;
    if (loop)
        count = n;
    /* local SDE k is the one before local element k, SDE first − 1 + k
     * (count + 1 of them; round the whole loop, n) */
    const int sdes = loop ? n : count + 1;
    /* a few elements (a section's end, in the step) on the stack, the
     * whole loop (the build) on the heap */
    double small[6 * (RELAX_STACK + 2)];
    double *heap = count > RELAX_STACK ? bd_xcalloc(6 * ((size_t)sdes + 2), sizeof *heap) : NULL;
    double *base = heap ? heap : small;
    const size_t stride = heap ? (size_t)sdes + 2 : RELAX_STACK + 2;
    double *g = base, *bt = base + stride, *S = base + 2 * stride;   /* γ at δ = 0, β, k_γ */
    double *p = base + 3 * stride, *d = base + 4 * stride;           /* ψ; δ with the fixed ends */
    double *B = base + 5 * stride;                                   /* k_β */
    for (size_t k = 0; k < 6 * stride; k++)
        base[k] = 0.0;
    /* an SDE between two tied elements has no shear or bending energy
     * (bd_rfe_sde_energy), a tied element no alignment */
    for (int k = 0; k < sdes; k++) {
        int e = (first + k + n - 1) % n;
        g[k] = bd_rfe_sde_angles(sim, e, &bt[k]);
        int held = bd_rfe_sde_held(R, e, bd_node_next(e, n));
        S[k] = held ? 0.0 : RM->k_shear;
        B[k] = held ? 0.0 : RM->k_bend;
    }
    for (int k = 0; k < count; k++)
        p[k] = bd_rfe_align_angle(sim, (first + k) % n);
    /* δ of local element k is d[k + 1]; d[0] and d[count + 1] the fixed
     * neighbours' (0), or, round the whole loop, the other end's */
    for (int sweep = 0; sweep < RELAX_SWEEPS; sweep++) {
        double most = 0.0;
        if (loop) {
            d[0] = d[count];
            d[count + 1] = d[1];
        }
        for (int k = 0; k < count; k++) {
            int i = (first + k) % n;
            if (R->sec[i] >= 0 && !turn_tied)
                continue;
            int sb = k, sa = loop ? (k + 1) % n : k + 1;
            double kh = R->sec[i] >= 0 ? 0.0 : RM->k_align[i];
            /* (B[sb] + B[sa]) is 2·k_β exactly for a free element, as
             * before turn_tied: the build's turns stay bit for bit */
            double coef = 0.25 * (S[sb] + S[sa]) + kh + (B[sb] + B[sa]);
            if (coef <= 0.0)
                continue;
            double db = d[k], da = d[k + 2];
            double c = -0.5 * S[sb] * (g[sb] - 0.5 * db) - 0.5 * S[sa] * (g[sa] - 0.5 * da)
                     + kh * p[k] - B[sa] * (bt[sa] + da) + B[sb] * (bt[sb] - db);
            double step = -c / coef - d[k + 1];
            d[k + 1] += SOR_FACTOR * step;
            if (fabs(step) > most)
                most = fabs(step);
        }
        if (most < RELAX_TOL)
            break;
    }
    for (int k = 0; k < count; k++) {
        int i = (first + k) % n;
        double c = cos(d[k + 1]), s = sin(d[k + 1]);
        double c1 = R->ct[i] * c - R->st[i] * s, s1 = R->st[i] * c + R->ct[i] * s;
        R->ct[i] = c1;
        R->st[i] = s1;
    }
    free(heap);
}

/* The tension the alignment is linearized about, per element (SDE e's):
 * the belt's tension at rest on its supports, Tc + W(s) of the layout
 * (belt/lumped/layout.c). A `static` start lays the belt with it; a `rest`
 * start lays it unstretched (no tension at all), so the static layout is
 * made here for the tension alone, and element e takes the tension at its
 * place along the loop. 0 where it cannot be laid (said in a warning). */
static void reference_tension(bd_sim *sim, double *T)
{
    const bd_model_def *def = sim->model->def;
    const int n = sim->model->n;
    if (def->simulation.initial_state != BD_INITIAL_REST) {
        for (int e = 0; e < n; e++)
            T[e] = sim->tension[e];
        return;
    }
    bd_model_def laid = *def;
    laid.simulation.initial_state = BD_INITIAL_STATIC;
    bd_path given;
    bd_diag quiet;
    bd_diag_init(&quiet);
    int bad = bd_path_build(def, &given, &quiet);
    bd_diag_free(&quiet);
    bd_layout lay;
    char err[512] = "";
    bd_layout_request req = {&given, sim->model->l0};
    if (!bad)
        bad = bd_layout_belt(&laid, &req, &lay, err, sizeof err);
    if (bad) {
        bd_sim_warn(sim, "rfe: the belt's tension at rest could not be found (%s); the "
                         "elements' alignment has no stiffness from the tension",
                    err[0] ? err : "no path");
        for (int e = 0; e < n; e++)
            T[e] = 0.0;
    } else {
        const double L = sim->model->path.length;
        for (int e = 0; e < n; e++) {
            double mid = sim->model->s_node0[e] + 0.5 * sim->model->l0;
            int k = (int)(mid / L * lay.n);
            T[e] = lay.tension[k < 0 ? 0 : k >= lay.n ? lay.n - 1 : k];
        }
        bd_layout_free(&lay);
    }
    bd_path_free(&given);
}

/* the tension's aligning stiffness of each element (forces.c): l0 times
 * the belt's tension at rest at its centre, the mean of its two SDEs'
 * (none where the belt hangs slack) */
static void align_constants(bd_sim *sim, bd_rfe_model *RM)
{
    const int n = sim->model->n;
    const double l0 = sim->model->l0, zeta = sim->model->def->belt.damping_ratio;
    const double J = sim->model->belt_mpl * l0 * RM->gyration2;
    double *T = bd_xcalloc((size_t)n, sizeof *T);
    reference_tension(sim, T);
    RM->k_align = bd_xcalloc((size_t)n, sizeof *RM->k_align);
    RM->c_align = bd_xcalloc((size_t)n, sizeof *RM->c_align);
    RM->k_align_max = 0.0;
    for (int i = 0; i < n; i++) {
        double Ti = 0.5 * (T[i] + T[bd_node_prev(i, n)]);
        double k = Ti > 0.0 ? l0 * Ti : 0.0;
        RM->k_align[i] = k;
        RM->c_align[i] = 2.0 * zeta * sqrt(k * J);
        if (k > RM->k_align_max)
            RM->k_align_max = k;
    }
    free(T);
}

/* Rigid elements ride a pulley as a chain rides a sprocket: each touches
 * the shell at its centre and turns with it, and where the belt comes onto
 * or leaves the shell the elements' stiff shear cannot follow the path's
 * turn within an element, so as each element passes a tangent point the
 * free belt beside it is pushed across by up to about l0²/(8R) (the
 * chordal rise, R·(1 − cos(l0/2R))) and the wrap's elements rock off the
 * shell (derived in docs/physics.md §15, *A chain on a sprocket*). The tension
 * there pulses with that passage, and the laid start (centres on the path)
 * may release it at once. Measured against the discrete belt (2026-12-01;
 * docs/physics.md §15), by the arc l0/R an element takes on the pulley:
 * - tests/data/vt_loop.yaml (R 0.3 m, 20 kN; 8-10 s at speed), the highest
 *   tension: +9.6 % at 29.7°, +4.3 % at 22.2°, +1.1 % at 19.9°, 0.0 % at
 *   14.8°; a spike of +1.6 to +10 % over the discrete belt's start peak in
 *   the first 10 ms at 6 of 9 elements from 19.9 to 30.6°, at none of 13
 *   from 13.8 to 19.1°;
 * - examples/head_drive.yaml (R 0.4 m, 8 s start), the highest and lowest
 *   tension: +9.7 % and −21 % at 29.7°, +2.0 % and −6.3 % at 14.8°.
 * So the rfe belt's default element is half the discrete belt's (belt/
 * lumped/idler_turn.c), and a longer one given is warned of. */
#define RFE_WRAP_WARN_DEG 19.5

static void warn_coarse(bd_sim *sim)
{
    const bd_model_def *def = sim->model->def;
    if (!(def->belt.element_length > 0.0))
        return;
    int worst = bd_lumped_smallest_pulley(def), refined;
    double R = def->pulleys[worst].radius, arc = sim->model->l0 / R;
    if (arc < RFE_WRAP_WARN_DEG * BD_DEG)
        return;
    double l_default = bd_lumped_default_element(def, &sim->model->path, sim->model->idler_turn,
                                                 &refined);
    bd_sim_warn(sim, "a belt element spans %.0f° of pulley '%s' (element length %.3g m, radius "
                "%.3g m): the rfe belt's rigid elements ride a pulley as a chain rides a sprocket, "
                "and near the wraps its tension pulses (against the discrete belt, +4 %% at "
                "22°, +10 %% at 30°; docs/physics.md §15); the default, %.3g m, spans %.0f°",
                arc / BD_DEG, def->pulleys[worst].name, sim->model->l0, R, l_default,
                l_default / R / BD_DEG);
}

/* a given element whose polygon on the pulleys costs more running force
 * than the torture test allows its law (3 %; belt/lumped/polygon.c) */
#define RFE_POLYGON_WARN 0.03

static void warn_polygon(bd_sim *sim)
{
    const bd_model_def *def = sim->model->def;
    if (!(def->belt.element_length > 0.0))
        return;
    const bd_path *path = &sim->model->path;
    double share = bd_lumped_polygon_share(def, path, sim->model->l0);
    if (!(share > RFE_POLYGON_WARN))
        return;
    bd_sim_warn(sim, "the rfe belt's elements (%.3g m) ride its pulleys as a polygon that costs "
                "about %.1f %% of the running resistance at %.3g m/s (an estimate, docs/physics.md "
                "§15): the drives' running force reads that much high; elements of %.3g m keep "
                "it to %.0f %%",
                sim->model->l0, 100.0 * share, bd_drives_reference_speed(def),
                sim->model->l0 * cbrt(BD_POLYGON_SHARE_MAX / share), 100.0 * BD_POLYGON_SHARE_MAX);
}

int bd_rfe_build(bd_sim *sim, bd_diag *diag)
{
    if (bd_lumped_build_sized(sim, diag, sizeof(bd_rfe), sizeof(bd_rfe_model)))
        return 1;
    warn_coarse(sim);
    warn_polygon(sim);
    bd_rfe_model *RM = sim->own->belt_model;
    /* bending acts between the elements' orientations (forces.c), not
     * between the chords of the centres as on the lumped belt */
    RM->lumped.k_bend = 0.0;
    sde_constants(sim->model->def, sim->model->l0, RM);
    bd_doubles_alloc(bd_rfe_of(sim), RFE_DOUBLES, COUNT(RFE_DOUBLES), (size_t)sim->model->n);
    orient(sim);
    align_constants(sim, RM);
    bd_rfe_sections_build(sim, RM);
    bd_rfe_sections_alloc(sim);
    bd_rfe_relax_turns(sim, 0, sim->model->n, 0);
    return 0;
}

void bd_rfe_free_model(bd_model *model)
{
    bd_rfe_model *RM = model->belt_model;
    if (RM) {
        free(RM->k_align);
        free(RM->c_align);
        bd_rfe_sections_free_model(RM);
    }
    bd_lumped_free_model(model);
}

void bd_rfe_free(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    if (!R)
        return;
    bd_doubles_free(R, RFE_DOUBLES, COUNT(RFE_DOUBLES));
    bd_rfe_sections_free(R);
    bd_lumped_free(sim);
}

void bd_rfe_clone(bd_sim *dst, const bd_sim *src)
{
    bd_lumped_clone_sized(dst, src, sizeof(bd_rfe));
    bd_doubles_dup(bd_rfe_of(dst), bd_rfe_of(src), RFE_DOUBLES, COUNT(RFE_DOUBLES),
                   (size_t)src->model->n);
    bd_rfe_sections_clone(dst, src);
}

/* Stable time step (laws/stable_step.h): the longest stable step of a
 * uniform straight chain of elements of mass m, rotary inertia J, SDE
 * constants k_a = EA/l0, k_γ, k_β and alignment k_ψ (the largest; the
 * estimate, before the layout, leaves it out: it is ~T/GA of k_γ). Along
 * the belt ω² = 4k_a/m (the lumped chain's). Across it, a wave of phase κ
 * per element (s = sin κ/2, c = cos κ/2) moves the centres by Y and turns
 * the elements by Φ with
 *   K_YY = 4s²·(k_γ + k_ψ·c²)/l0²,  K_ΦΦ = k_γ·c² + 4k_β·s² + k_ψ,
 *   |K_YΦ| = 2s·c·(k_γ + k_ψ)/l0
 * (derived here from forces.c's energy). The rotations are implicit
 * (rotation_solve.c: K_ΦΦ at Φ + ¼Δt·ΔΦ̇), the rest explicit; for the
 * wave, with w = (z − 1)²/z of the step's amplification z,
 *   det([m·w + Δt²K_YY, Δt²K_YΦ; Δt²K_YΦ, J·w + Δt²K_ΦΦ·(1 + w/4)]) = 0,
 * a quadratic in w with real negative roots; |z| ≤ 1 needs both ≥ −4, that
 * is Δt²·λ ≤ 4 for the largest λ of det(K − λ·diag(m, J + ¼Δt²K_ΦΦ)) = 0.
 * The largest such Δt is found by bisection below the zigzag's
 * 2/√(K_YY(π)/m), which no Δt passes. Explicitly, the elements turning
 * together against the shear set it, 12·GA/(m′·l0²) for J = m·l0²/12 (30
 * times the axial ω² at GA = 10·EA, a step 5.5 times the lumped belt's
 * shorter); now the centres' zigzag against the shear, 4·GA/(m′·l0²) with
 * the rotations coupled in (3.5 times shorter on issue 10's loop). The
 * dashpots damp these modes with ζ ≈ 2ζ_e, as the lumped belt's axial
 * one. m and J are the lightest element's (no material). */
#define KAPPA_SAMPLES 64
#define STEP_BISECTIONS 50

/* Δt²·λ_max over κ for the step dt (the stability measure above, ≤ 4) */
static double cross_measure(double dt, double m, double J, double l0, double k_shear,
                            double k_bend, double k_align)
{
    double worst = 0.0;
    for (int k = 0; k <= KAPPA_SAMPLES; k++) {
        double kappa = BD_PI * k / KAPPA_SAMPLES;
        double s = sin(0.5 * kappa), c = cos(0.5 * kappa);
        double kyy = 4.0 * s * s * (k_shear + k_align * c * c) / (l0 * l0);
        double kpp = k_shear * c * c + 4.0 * k_bend * s * s + k_align;
        double kyp = 2.0 * s * c * (k_shear + k_align) / l0;
        double Jw = J + 0.25 * dt * dt * kpp;
        /* m·J′·λ² − (K_YY·J′ + K_ΦΦ·m)·λ + (K_YY·K_ΦΦ − K_YΦ²) = 0 */
        double b = kyy * Jw + kpp * m, d = kyy * kpp - kyp * kyp;
        double disc = b * b - 4.0 * m * Jw * d;
        double lam = (b + sqrt(disc > 0.0 ? disc : 0.0)) / (2.0 * m * Jw);
        if (dt * dt * lam > worst)
            worst = dt * dt * lam;
    }
    return worst;
}

static double stable_step_law(double m, double g2, double l0, double k_axial, double c_axial,
                              double k_shear, double k_bend, double k_align, double zeta_e,
                              bd_time_step_limit *limit)
{
    double J = m * g2;
    double w_axial = 4.0 * k_axial / m;
    /* the zigzag (κ = π) alone: K_YY = 4k_γ/l0², uncoupled */
    double lo = 0.0, hi = 2.0 / sqrt(4.0 * k_shear / (l0 * l0 * m));
    for (int it = 0; it < STEP_BISECTIONS; it++) {
        double mid = 0.5 * (lo + hi);
        if (cross_measure(mid, m, J, l0, k_shear, k_bend, k_align) <= 4.0)
            lo = mid;
        else
            hi = mid;
    }
    double w_cross = 4.0 / (lo * lo);   /* the cross modes' ω² at that step */
    double omega;
    double zeta;
    if (w_cross > w_axial) {
        omega = sqrt(w_cross);
        zeta = 2.0 * zeta_e;
        *limit = BD_LIMIT_SHEAR;
    } else {
        omega = sqrt(w_axial);
        zeta = 4.0 * c_axial / (2.0 * m * omega);
        *limit = BD_LIMIT_AXIAL;
    }
    return bd_central_difference_limit(omega, zeta);
}

double bd_rfe_stable_step(const bd_sim *sim, bd_time_step_limit *limit)
{
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const double l0 = sim->model->l0;
    return stable_step_law(sim->model->belt_mpl * l0, RM->gyration2, l0, RM->lumped.k_axial,
                           RM->lumped.c_axial, RM->k_shear, RM->k_bend, RM->k_align_max,
                           sim->model->def->belt.damping_ratio, limit);
}

/* (element + idler)-steps per second: head_drive.yaml with rfe (1593
 * elements, 55 idlers, 413 113 steps with its stabilization) took 42.8 s
 * on the two-core machine this was written on (its other core busy) */
#define RFE_RATE 1.6e7

void bd_rfe_estimate(const bd_model_def *def, const bd_path *path, bd_belt_estimate *out)
{
    bd_lumped_estimate(def, path, out);
    double l = out->element_length;
    out->node_bytes += (double)COUNT(RFE_DOUBLES) * sizeof(double);
    bd_rfe_model RM;
    sde_constants(def, l, &RM);
    double k = def->belt.axial_stiffness / l, m = def->belt.mass_per_length * l;
    bd_time_step_limit limit;
    out->stable_step = stable_step_law(m, RM.gyration2, l, k,
                                       2.0 * def->belt.damping_ratio * sqrt(k * m), RM.k_shear,
                                       RM.k_bend, 0.0, def->belt.damping_ratio, &limit);
    out->rate = RFE_RATE;
    /* with long sections, what their windows will hold (sections.c) */
    double windows = 0.0, tied = fmin(bd_rfe_windows_estimate(def, path, l, &windows) / l,
                                      out->nodes);
    if (windows > 0.0 && out->nodes > 0.0)
        out->stepped = (out->nodes - tied) + BD_SECTION_STEP_ELEMENTS * windows
                     + out->idlers * (1.0 - tied / out->nodes);
}

/* How long the chain's own modes take to settle where the layout lays it
 * (sim/stabilize.c, bd_sim_settle): the centres' zigzag against the
 * shear, the fastest, lets the tangent points' misfit go within a few
 * steps and stirs the elements turning alternately against the alignment,
 * ω² = k_ψ/J (derived here: turning alternately, δ_i = ±δ, leaves every
 * SDE's shear ½(δ_i + δ_j) and the centres still, so only the alignment
 * k_ψ of physics.md §15 acts on the rotary inertia J of seed 000
 * assumption i; a bending stiffness adds 4k_β, not counted: with EI > 0 the
 * settle lasts somewhat more than the half period), which passes some of
 * it back at its first peak; half a period of that, π·√(J/k̄_ψ), k̄_ψ the mean of
 * the elements' alignment stiffness. Measured on examples/
 * flat_belt_drive.yaml at its rfe default (the period 175 steps): its
 * first kinetic-energy peaks came at steps 2, 5 and 8 (the zigzag), the
 * next at 54 (the alternating turn, larger than the first); settled 20,
 * 54, 88 or 175 steps its balance read 1.4·10⁻³, 2.8·10⁻⁴, 1.7·10⁻⁴ and
 * 1.5·10⁻⁴ (a full stabilization 1.5·10⁻⁴). Longer lets the belt begin to
 * fall into its sag between the idlers, which the sections' first tie
 * then lifts back (tests/data/vt_loop.yaml: 0.17 J booked as input
 * unsettled, 0.48 J at half a period, 2.3 J at a whole one). 0 with no
 * tension to align. */
double bd_rfe_settle_time(const bd_sim *sim)
{
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const int n = sim->model->n;
    double sum = 0.0;
    for (int i = 0; i < n; i++)
        sum += RM->k_align[i];
    if (!(sum > 0.0))
        return 0.0;
    return BD_PI * sqrt(RM->inertia * n / sum);
}
