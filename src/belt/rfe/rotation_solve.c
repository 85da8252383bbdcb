/* The elements' rotations taken implicitly (derived here; docs/physics.md
 * §15, "Stable step").
 *
 * Explicitly, the elements turning together against the SDEs' shear set
 * the rfe belt's step: ω² = 12·GA/(m′·l0²) with J = m·l0²/12, 30 times the
 * axial ω² at the default GA = 10·EA. A rotation moves no mass centre, so
 * no contact acts on it (the contacts hold the centres), and the
 * rotations alone can be integrated implicitly without the contacts in
 * the solve. Each element's rotation is coupled to its neighbours' only,
 * through the SDEs' shear and bending (forces.c), and to itself through
 * the tension's alignment, so with the rotational stiffness
 *   K_φφ: SDE e (elements i, j = e + 1) adds k_γ/4 + k_β to (i, i) and
 *         (j, j) and k_γ/4 − k_β to (i, j); element i's alignment adds
 *         k_ψ,i to (i, i),
 * and the damping C_φφ formed alike from the dashpots, Newmark's average
 * acceleration on these terms (β = 1/4, γ = 1/2: unconditionally stable,
 * no numerical damping; T. J. R. Hughes, The Finite Element Method, 2000,
 * §9.1; in the leapfrog form the moving-node belt's axial step uses,
 * moving_node/solve.c: their moment at φ + ¼Δt·Δω and at the mid-step
 * rate ω + ½Δω, Δω = ω⁺ − ω⁻) gives
 *   (J + ¼Δt²·K_φφ + ½Δt·C_φφ)·Δω = Δt·τ,
 * with τ every moment on the elements at t (forces.c). The matrix is
 * cyclic tridiagonal, symmetric positive definite and constant while the
 * step is: factored once, then two sweeps a step, no division. The
 * coupling between the rotations and the centres (the shear's moment from
 * the centres' motion, and its force from the rotations) stays explicit,
 * and so does every force on the centres.
 *
 * What it buys: the highest mode left is the centres' zigzag across the
 * belt against the shear, ω² = 4·GA/(m′·l0²) (10 times the axial ω² at
 * GA = 10·EA), with the rotations coupled in; build.c's stable step finds
 * the longest stable step of the straight chain with the rotation's
 * inertia raised by ¼Δt²·K_φφ (from the scheme's characteristic
 * equation). The translations' shear cannot be taken implicitly the same
 * way: the contacts act on the centres, node by node, outside any solve,
 * and with an implicit coupling between centres the wraps went unstable
 * (physics.md §15). */
#include "belt/rfe/rfe.h"

/* The system's factors, for the step dt: its matrix is constant while the
 * step is (the elements' rotary inertia is the belt's own, build.c; the
 * material on an element adds to its mass, not to its J). The chain 1 … n−1
 * by Thomas' algorithm (inv = the pivots' reciprocals, cp the eliminated
 * couplings), its response z to the coupling with element 0, and the
 * reciprocal of row 0's Schur complement (positive: the matrix is positive
 * definite). n ≥ 8, the layout's least (belt/lumped/layout.c). */
/* the system's entries for the step dt: row i's diagonal, and the
 * coupling o of neighbouring rows (the SDEs' ¼k_γ ± k_β and dashpots, the
 * alignment's on the diagonal) */
typedef struct rows {
    double kq, cq, own, o;
} rows;

static rows rows_for(const bd_rfe_model *RM, double dt)
{
    rows w;
    w.kq = 0.25 * dt * dt;
    w.cq = 0.5 * dt;
    w.own = w.kq * (0.25 * RM->k_shear + RM->k_bend) + w.cq * (0.25 * RM->c_shear + RM->c_bend);
    w.o = w.kq * (0.25 * RM->k_shear - RM->k_bend) + w.cq * (0.25 * RM->c_shear - RM->c_bend);
    return w;
}

static inline double diag(const bd_rfe_model *RM, const rows *w, int i)
{
    return RM->inertia + 2.0 * w->own + w->kq * RM->k_align[i] + w->cq * RM->c_align[i];
}

static void factor(bd_rfe *R, const bd_rfe_model *RM, int n, double dt)
{
    const rows w = rows_for(RM, dt);
    const double o = w.o;
    double *inv = R->rinv, *cp = R->rcp, *z = R->rz;
    const int last = n - 1;
    inv[1] = 1.0 / diag(RM, &w, 1);
    cp[1] = o * inv[1];
    z[1] = -o * inv[1];
    for (int k = 2; k <= last; k++) {
        inv[k] = 1.0 / (diag(RM, &w, k) - o * cp[k - 1]);
        cp[k] = o * inv[k];
        z[k] = ((k == last ? -o : 0.0) - o * z[k - 1]) * inv[k];
    }
    for (int k = last - 1; k >= 1; k--)
        z[k] -= cp[k] * z[k + 1];
    R->rs0 = 1.0 / (diag(RM, &w, 0) + o * (z[1] + z[last]));
    R->rdt = dt;
    R->ro = o;
}

/* With sections (sections.c) a tied element does not turn: each run of
 * free elements between two tied ones is a chain of its own, held at both
 * ends, by Thomas' algorithm (factors into the same arrays, by element) */
static void factor_runs(bd_rfe *R, const bd_rfe_model *RM, int n, double dt)
{
    const rows w = rows_for(RM, dt);
    const double o = w.o;
    for (int r = 0; r < R->run_n; r++) {
        double cp = 0.0;
        for (int q = 0, k = R->run_first[r]; q < R->run_count[r]; q++, k = bd_node_next(k, n)) {
            R->rinv[k] = 1.0 / (diag(RM, &w, k) - o * cp);
            cp = R->rcp[k] = o * R->rinv[k];
        }
    }
    R->rdt = dt;
    R->ro = o;
}

static void solve_runs(bd_rfe *R, int n, double dt)
{
    const double o = R->ro;
    double *x = R->rb;
    for (int r = 0; r < R->run_n; r++) {
        const int f = R->run_first[r], c = R->run_count[r];
        double prev = 0.0;
        int k = f;
        for (int q = 0; q < c; q++, k = bd_node_next(k, n)) {
            x[k] = (dt * R->tq[k] - o * prev) * R->rinv[k];
            prev = x[k];
        }
        /* k is one past the run's last: back from the last */
        k = bd_node_prev(k, n);
        for (int q = c - 2; q >= 0; q--) {
            int j = bd_node_prev(k, n);
            x[j] -= R->rcp[j] * x[k];
            k = j;
        }
    }
}

/* −½C_φφ·Δω of element i (b before, a after it) into its non-conservative
 * moment: the dashpots' moment at the mid-step rate */
static inline void dashpot_share(bd_rfe *R, const bd_rfe_model *RM, int i, int b, int a)
{
    const double hc_own = 0.5 * (0.25 * RM->c_shear + RM->c_bend);
    const double hc_cross = 0.5 * (0.25 * RM->c_shear - RM->c_bend);
    const double *x = R->rb;
    R->tqn[i] -= (2.0 * hc_own + 0.5 * RM->c_align[i]) * x[i] + hc_cross * (x[b] + x[a]);
}

/* Δω into R->rb for the moments tq at t (forces.c), and the dashpots'
 * moment at the mid-step rate added to the non-conservative moment tqn:
 * −½C_φφ·Δω */
void bd_rfe_rotation_implicit(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const int n = sim->model->n, last = n - 1;
    const double dt = sim->model->dt;
    if (bd_rfe_some_tied(sim)) {
        if (R->rdt != dt)
            factor_runs(R, RM, n, dt);
        solve_runs(R, n, dt);
        for (int r = 0; r < R->run_n; r++)
            for (int q = 0, i = R->run_first[r]; q < R->run_count[r]; q++, i = bd_node_next(i, n))
                dashpot_share(R, RM, i, bd_node_prev(i, n), bd_node_next(i, n));
        return;
    }
    if (R->rdt != dt)
        factor(R, RM, n, dt);
    const double o = R->ro;
    const double *restrict inv = R->rinv, *restrict cp = R->rcp, *restrict z = R->rz;
    const double *restrict tq = R->tq;
    double *restrict x = R->rb;
    /* the chain 1 … n−1 for the right side Δt·τ */
    x[1] = dt * tq[1] * inv[1];
    for (int k = 2; k <= last; k++)
        x[k] = (dt * tq[k] - o * x[k - 1]) * inv[k];
    for (int k = last - 1; k >= 1; k--)
        x[k] -= cp[k] * x[k + 1];
    double s0 = (dt * tq[0] - o * (x[1] + x[last])) * R->rs0;
    x[0] = s0;
    for (int k = 1; k <= last; k++)
        x[k] += s0 * z[k];

    dashpot_share(R, RM, 0, last, 1);
    for (int i = 1; i < last; i++)
        dashpot_share(R, RM, i, i - 1, i + 1);
    dashpot_share(R, RM, last, last - 1, 0);
}
