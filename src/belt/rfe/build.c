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
#include "laws/stable_step.h"

/* the state's arrays of doubles, [n] each */
static const size_t RFE_DOUBLES[] = {
    offsetof(bd_rfe, phi), offsetof(bd_rfe, omega), offsetof(bd_rfe, ct),  offsetof(bd_rfe, st),
    offsetof(bd_rfe, tq),  offsetof(bd_rfe, tqn),   offsetof(bd_rfe, gam), offsetof(bd_rfe, dphi),
    offsetof(bd_rfe, q),   offsetof(bd_rfe, qd),    offsetof(bd_rfe, mb),  offsetof(bd_rfe, mbd),
    offsetof(bd_rfe, pw),  offsetof(bd_rfe, ek),    offsetof(bd_rfe, thdot), offsetof(bd_rfe, psi),
    offsetof(bd_rfe, h),   offsetof(bd_rfe, hd)};
#define COUNT(a) ((int)(sizeof a / sizeof a[0]))

/* GA: model-format.md `shear_stiffness`, default 10·EA */
static double shear_stiffness(const bd_model_def *def)
{
    return def->belt.shear_stiffness > 0.0 ? def->belt.shear_stiffness
                                           : 10.0 * def->belt.axial_stiffness;
}

/* the SDEs' constants from the belt's (seed 000 §2.3, a rectangular
 * section of thickness h): k_γ = GA·l0, k_β = EI/l0, J = m·(l0² + h²)/12;
 * each dashpot the damping ratio ζ of the element's critical damping of
 * its own spring, c = 2ζ·√(k·J) for the rotations (the element's rotary
 * inertia is what they move) */
static void sde_constants(const bd_model_def *def, double l0, bd_rfe_model *RM)
{
    double m = def->belt.mass_per_length * l0, h = def->belt.thickness;
    double zeta = def->belt.damping_ratio;
    RM->gyration2 = (l0 * l0 + h * h) / 12.0;
    RM->k_shear = shear_stiffness(def) * l0;
    RM->k_bend = def->belt.bending_stiffness / l0;
    RM->c_shear = 2.0 * zeta * sqrt(RM->k_shear * m * RM->gyration2);
    RM->c_bend = 2.0 * zeta * sqrt(RM->k_bend * m * RM->gyration2);
}

/* each element along the path at its centre, φ continuous along the belt
 * (it turns by 2π round the loop) */
static void orient(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    double prev = 0.0;
    for (int i = 0; i < sim->model->n; i++) {
        double p[2], t[2];
        bd_path_point(&sim->model->path, sim->model->s_node0[i], p, t);
        double a = atan2(t[1], t[0]);
        if (i > 0)
            a = prev + remainder(a - prev, 2.0 * BD_PI);
        R->phi[i] = a;
        prev = a;
    }
}

/* the tension's aligning stiffness of each element (forces.c): l0 times
 * the belt's tension as laid at its centre, the mean of its two SDEs'
 * (none where the belt was laid slack) */
static void align_constants(bd_sim *sim, bd_rfe_model *RM)
{
    const int n = sim->model->n;
    const double l0 = sim->model->l0, zeta = sim->model->def->belt.damping_ratio;
    const double J = sim->model->belt_mpl * l0 * RM->gyration2;
    RM->k_align = bd_xcalloc((size_t)n, sizeof *RM->k_align);
    RM->c_align = bd_xcalloc((size_t)n, sizeof *RM->c_align);
    RM->k_align_max = 0.0;
    for (int i = 0; i < n; i++) {
        double T = 0.5 * (sim->tension[i] + sim->tension[bd_node_prev(i, n)]);
        double k = T > 0.0 ? l0 * T : 0.0;
        RM->k_align[i] = k;
        RM->c_align[i] = 2.0 * zeta * sqrt(k * J);
        if (k > RM->k_align_max)
            RM->k_align_max = k;
    }
}

int bd_rfe_build(bd_sim *sim, bd_diag *diag)
{
    if (bd_lumped_build_sized(sim, diag, sizeof(bd_rfe), sizeof(bd_rfe_model)))
        return 1;
    bd_rfe_model *RM = sim->own->belt_model;
    /* bending acts between the elements' orientations (forces.c), not
     * between the chords of the centres as on the lumped belt */
    RM->lumped.k_bend = 0.0;
    sde_constants(sim->model->def, sim->model->l0, RM);
    bd_doubles_alloc(bd_rfe_of(sim), RFE_DOUBLES, COUNT(RFE_DOUBLES), (size_t)sim->model->n);
    orient(sim);
    align_constants(sim, RM);
    return 0;
}

void bd_rfe_free_model(bd_model *model)
{
    bd_rfe_model *RM = model->belt_model;
    if (RM) {
        free(RM->k_align);
        free(RM->c_align);
    }
    bd_lumped_free_model(model);
}

void bd_rfe_free(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    if (!R)
        return;
    bd_doubles_free(R, RFE_DOUBLES, COUNT(RFE_DOUBLES));
    bd_lumped_free(sim);
}

void bd_rfe_clone(bd_sim *dst, const bd_sim *src)
{
    bd_lumped_clone_sized(dst, src, sizeof(bd_rfe));
    bd_doubles_dup(bd_rfe_of(dst), bd_rfe_of(src), RFE_DOUBLES, COUNT(RFE_DOUBLES),
                   (size_t)src->model->n);
}

/* Stable time step (laws/stable_step.h): the highest frequency of a
 * uniform straight chain of elements of mass m, rotary inertia J, SDE
 * constants k_a = EA/l0, k_γ, k_β and alignment k_ψ (the largest; the
 * estimate, before the layout, leaves it out: it is ~T/GA of k_γ). Along the belt ω² = 4k_a/m (the
 * lumped chain's). Across it, a wave of phase κ per element (s = sin κ/2,
 * c = cos κ/2) moves the centres by Y and turns the elements by Φ with
 *   K_YY = 4s²·(k_γ + k_ψ·c²)/l0²,  K_ΦΦ = k_γ·c² + 4k_β·s² + k_ψ,
 *   |K_YΦ| = 2s·c·(k_γ + k_ψ)/l0,
 * and det(K − λ·diag(m, J)) = 0 gives ω² = λ (derived here from forces.c's
 * energy). Its largest λ over κ (sampled) is that of the elements turning
 * together against the SDEs' shear, 12·GA/(m′·l0²) for J = m·l0²/12:
 * with the default GA = 10·EA, 30 times the axial ω², a step 5.5 times
 * the lumped belt's shorter. The dashpots damp these modes with
 * ζ ≈ 2ζ_e, as the lumped belt's axial one. m and J are the lightest
 * element's (no material). */
#define KAPPA_SAMPLES 64

static double stable_step_law(double m, double g2, double l0, double k_axial, double c_axial,
                              double k_shear, double k_bend, double k_align, double zeta_e,
                              bd_time_step_limit *limit)
{
    double J = m * g2;
    double w_axial = 4.0 * k_axial / m;
    double w_cross = 0.0;
    for (int k = 0; k <= KAPPA_SAMPLES; k++) {
        double kappa = BD_PI * k / KAPPA_SAMPLES;
        double s = sin(0.5 * kappa), c = cos(0.5 * kappa);
        double kyy = 4.0 * s * s * (k_shear + k_align * c * c) / (l0 * l0);
        double kpp = k_shear * c * c + 4.0 * k_bend * s * s + k_align;
        double kyp = 2.0 * s * c * (k_shear + k_align) / l0;
        /* m·J·λ² − (K_YY·J + K_ΦΦ·m)·λ + (K_YY·K_ΦΦ − K_YΦ²) = 0 */
        double b = kyy * J + kpp * m, d = kyy * kpp - kyp * kyp;
        double disc = b * b - 4.0 * m * J * d;
        double lam = (b + sqrt(disc > 0.0 ? disc : 0.0)) / (2.0 * m * J);
        if (lam > w_cross)
            w_cross = lam;
    }
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

/* (element + idler)-steps per second, measured as the lumped belt's
 * (belt/lumped/build.c): bench_long_conveyor with formulation rfe */
#define RFE_RATE 6.0e7

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
}
