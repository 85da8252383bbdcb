/* The moving-node belt's axial motion over one step, implicit along the
 * whole loop together with every pulley's rotation (docs/physics.md §14).
 *
 * Element e's force over the step is the trapezoidal rule's (Newmark
 * β = 1/4, γ = 1/2: unconditionally stable, no numerical damping; T. J. R.
 * Hughes, The Finite Element Method, 2000, §9.1; here in the leapfrog form
 * m·(x⁺ − 2x + x⁻)/Δt² = −k·(x⁺ + 2x + x⁻)/4):
 *   T*_e = T_e(t)·cos_e + (Δt/4)·k_e·(Δv⁺_e − Δv⁻_e) + c_e·(Δv⁺_e + Δv⁻_e)/2,
 * Δv_e = v_{e+1} − v_e, v⁻ and v⁺ the speeds at t ∓ Δt/2, k_e = EA/ΔX_e.
 * Node i then gives one row of a cyclic tridiagonal system:
 *   (m_i/Δt + a_i + a_{i−1})·v⁺_i − a_{i−1}·v⁺_{i−1} − a_i·v⁺_{i+1}
 *       = m_i·v⁻_i/Δt + F_i + b_i·Δv⁻_i − b_{i−1}·Δv⁻_{i−1} + Fr_i,
 * a = Δt·k/4 + c/2, b = −Δt·k/4 + c/2, F_i the explicit forces (forces.c).
 * Fr_i is the friction of an arc node's pulley (Coulomb, static/dynamic,
 * the discrete belt's law): sticking, v⁺_i = R·ω⁺ and |Fr_i| ≤ μ_s·N_i;
 * slipping, Fr_i = ∓μ_d·N_i against the slip; none where N_i ≤ 0
 * (lift-off). Each pulley turns with
 *   I·(ω⁺ − ω⁻)/Δt = Q − R·Σ Fr_i      (its arc nodes),
 * I and Q with the drive's implicit damping (parts/pulley.c).
 *
 * For a guess of which nodes stick, the stuck nodes cut the loop into
 * runs; each run's speeds are affine in the pulley speeds at its ends
 * (one Thomas sweep, three right-hand sides), which leaves a small dense
 * system in the pulley speeds. The guess is corrected (a stuck node whose
 * friction passes μ_s·N slips; a slipping node whose slip reverses
 * sticks) until it holds: an active-set method, O(n) per pass. */
#include "belt/moving_node/moving_node.h"

#include <math.h>
#include <string.h>

#include "parts/parts.h"

/* passes of the contact-set correction; after HALF of them one node is
 * changed per pass (the worst), which cannot cycle */
#define PASSES 40
#define HALF 8

typedef struct affine {
    double c0;        /* constant part */
    int p;            /* the pulley whose speed it follows, −1 none */
    double g;         /* its factor */
} affine;

/* A wrap element the step does not resolve (a wave crosses it in less
 * than a step) has its own modes far above 1/Δt. The trapezoidal rule
 * leaves them undamped at the amplification −1, a double root: any
 * explicit coupling (the transport of strain through the nodes, the
 * friction) pushes one root outside the unit circle (measured: an odd-even
 * tension ripple on a driven pulley's slip arc grew ×3 every 0.08 s).
 * Such an element takes its tension at the end of the step instead,
 * T(t) + k·Δt·Δv⁺ (backward Euler: amplification 0 for its own modes,
 * which only carry the quasi-static strain the arc needs), i.e. the
 * trapezoidal force plus k·Δt·(3Δv⁺ + Δv⁻)/4, booked as numerical
 * dissipation. Between two stuck nodes it costs nothing (Δv = 0), and
 * where a node slips friction damps far more.
 * Backward Euler also damps the slow modes, by a ratio of about ωΔt/2
 * (0.02 at ωΔt = 0.04) in the strain the arc takes. Where no friction
 * acts (a frictionless pulley, a lifted node) nothing else damped them:
 * an undamped frictionless loop's takeup oscillation fell to half its
 * amplitude in 10 s (to 29 % with 0.8 m pulleys), and issue 10's loop from
 * rest booked 79 % of its energy as dissipated. An element whose two nodes
 * both take no friction therefore follows a four-level rule on its
 * elongation x, k·(8·x⁺ + 12·x + 6·x⁻ + x⁻⁻)/27 (derived here, docs/
 * physics.md §14): its weights are (λ + ½)³'s coefficients over their sum,
 * so they sum to 1 and are centred on t (8 − 6 − 2 = 0), and it stays
 * second-order. On m·ẍ = −k·x with z = ωΔt its characteristic polynomial
 * is λ(λ − 1)² + z²·(8λ³ + 12λ² + 6λ + 1)/27: for z → ∞ its roots are a
 * triple −½ (amplification ½ per step), at z = 0.04 the mode's damping
 * ratio is 1.2e-6, and its largest root stays within the unit circle for
 * every z (sampled 0.04 … 10⁴). With the implicit k = EA/ΔX (at build)
 * a fraction r of the element's tangent EA/ΔX(t) it stays so for
 * r ≥ 0.97 (sampled), i.e. up to 3 % more strain than at build.
 * In speeds (x⁺ − x = Δt·Δv⁺, x⁻ − x⁻⁻ = Δt·Δv⁻⁻): the trapezoidal force
 * plus k·Δt·[(8/27 − 1/4)·Δv⁺ − (7/27 − 1/4)·Δv⁻ − Δv⁻⁻/27], booked as
 * numerical dissipation. With friction it is not used: on a drive's slip
 * arc friction switching sides drove an odd-even pattern of slip
 * directions that an amplification of ½ did not hold (generated conveyor
 * 3 diverged at 3.5 s), and on stuck arcs its ringing tripled the passes
 * of the contact solve (cement plant) for no gain. Nor where the belt
 * runs through the element: its strain's transport through the nodes is
 * explicit, and against it an amplification of ½ did not hold either. The
 * cement plant with frictionless bends and tail pulley diverged at 9.3 s
 * of its start, at 1.9 m/s, 0.054 of a 5° element per step; with the rule
 * kept to passages below 0.07, 0.1 and 0.2 of an element per step its
 * energy balance erred by 52 %, 870 % and 38 000 %; below 0.04 it ran
 * as with backward Euler (peak tension within 10⁻⁷). So the rule is kept
 * to passages below 0.01 of an element per step, four times below the
 * last stable figure: takeup oscillations of a standing belt (the
 * loop's belt slides at up to 0.05 m/s, 0.002 of an element per step),
 * not the running belt, whose frictionless arcs keep backward Euler.
 * Span elements keep the trapezoidal rule even when a wave crosses them
 * in less than a step (the short spans of a takeup loop at 1 m elements):
 * backward Euler there damped the waves through the loop (cement plant,
 * Δt 1.9 ms: takeup travel −6 %, tension swing at the drive −16 %), the
 * trapezoidal rule does not (≤ 0.2 % from Δt/2). */
/* the belt's passage through a wrap element per step, as a fraction of
 * its length, up to which it may follow the four-level rule (above) */
#define FOUR_LEVEL_PASSAGE 0.01

static inline int unresolved(const bd_mn_model *mm, int e, double dt)
{
    return mm->on_arc[e] && mm->ds0[e] < mm->wave_speed * dt;
}

/* the coefficients of this step: every element's at the first step (and
 * when the step changes), then a wrap element's rule as its nodes took
 * friction in the last step. (The rule's older speeds, vold, start as the
 * speeds at rest: bd_mn_rest_velocities, run when the sim is built.) */
static void coefs(bd_sim *sim, double dt)
{
    bd_mn *mn = bd_mn_of(sim);
    const bd_mn_model *mm = bd_mn_model_of(sim);
    const int n = sim->model->n;
    const int all = mn->coef_dt != dt;
    mn->coef_dt = dt;
    int four_level = 0;
    for (int e = 0; e < n; e++) {
        int wrap = unresolved(mm, e, dt);
        if (!all && !wrap)
            continue;
        double na = 0.0, nb = 0.0, nc = 0.0;
        if (wrap) {
            int j = bd_node_next(e, n);
            double pass = fmax(fabs(sim->vx[e]), fabs(sim->vx[j])) * dt;
            if (mn->contact[e] != BD_MN_OFF || mn->contact[j] != BD_MN_OFF
                || pass > FOUR_LEVEL_PASSAGE * mm->ds0[e]) {
                na = 0.75 * dt * mm->k[e];
                nb = 0.25 * dt * mm->k[e];
            } else {
                double kdt = dt * mm->k[e];
                na = (8.0 / 27.0 - 0.25) * kdt;
                nb = -(7.0 / 27.0 - 0.25) * kdt;
                nc = -kdt / 27.0;
                four_level++;
            }
        }
        mn->ca[e] = 0.25 * dt * mm->k[e] + 0.5 * mm->c[e] + na;
        mn->cb[e] = -0.25 * dt * mm->k[e] + 0.5 * mm->c[e] + nb;
        mn->cna[e] = na;
        mn->cnb[e] = nb;
        mn->cnc[e] = nc;
    }
    mn->four_level = four_level;
}

/* the four-level rule's force from the speeds before, −k·Δt·Δv⁻⁻/27 on
 * each element that follows it, added to out (at the start node, and
 * taken from the end node) */
static void four_level_old(const bd_sim *sim, double *out)
{
    const bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n;
    const double *vo = mn->vold;
    for (int e = 0; e < n; e++) {
        if (mn->cnc[e] == 0.0)
            continue;
        int j = bd_node_next(e, n);
        double f = mn->cnc[e] * (vo[j] - vo[e]);
        out[e] += f;
        out[j] -= f;
    }
}

/* the speed of a stuck node's pulley surface: R·ω⁺, known when held */
static affine surface(const bd_sim *sim, int i)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    const bd_pulley_body *p = &sim->pulleys[mm->pulley[i]];
    double R = p->m->radius;
    if (p->held)
        return (affine){R * p->omega, -1, 0.0};
    return (affine){0.0, mm->pulley[i], R};
}

/* stuck on its pulley (contact_from_pressure makes every node that is
 * not on an arc BD_MN_OFF) */
static int is_stuck(const bd_mn *mn, int i)
{
    return mn->contact[i] == BD_MN_STICK;
}

/* the friction of a slipping or free arc node */
static double slip_force(const bd_sim *sim, int i)
{
    const bd_mn *mn = bd_mn_of(sim);
    const bd_mn_model *mm = bd_mn_model_of(sim);
    if (mm->kind[i] != BD_MN_ARC || mn->contact[i] == BD_MN_OFF || mn->contact[i] == BD_MN_STICK)
        return 0.0;
    double f = sim->pulleys[mm->pulley[i]].m->mu_d * mn->normal[i];
    return mn->contact[i] == BD_MN_SLIP_POS ? -f : f;
}

/* Thomas sweep over the run of `count` nodes from `first`, three
 * right-hand sides: the loads (into p0), a unit speed at the node before
 * the run (qa), and at the node after it (qb) */
static void run_solve(bd_sim *sim, int first, int count, double dt)
{
    bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n;
    double *cp = mn->cp, *x = mn->p0, *ya = mn->qa, *yb = mn->qb;
    double prev_c = 0.0, px = 0.0, pa = 0.0, pb = 0.0;
    int i = first;
    for (int k = 0; k < count; k++) {
        int b = bd_node_prev(i, n);
        double al = mn->ca[b], ar = mn->ca[i];
        double D = sim->mass[i] / dt + al + ar;
        double r = mn->rhs[i] + slip_force(sim, i);
        double ra = k == 0 ? al : 0.0, rb = k == count - 1 ? ar : 0.0;
        /* row: −al·x_{k−1} + D·x_k − ar·x_{k+1} */
        double inv = 1.0 / (k == 0 ? D : D + al * prev_c);
        double c = -ar * inv;
        if (k == 0) {
            px = r * inv;
            pa = ra * inv;
            pb = rb * inv;
        } else {
            px = (r + al * px) * inv;
            pa = (ra + al * pa) * inv;
            pb = (rb + al * pb) * inv;
        }
        cp[i] = c;
        x[i] = px;
        ya[i] = pa;
        yb[i] = pb;
        prev_c = c;
        i = bd_node_next(i, n);
    }
    /* back substitution */
    int last = (first + count - 1) % n;
    i = last;
    for (int k = count - 2; k >= 0; k--) {
        int j = i;
        i = bd_node_prev(i, n);
        x[i] -= cp[i] * x[j];
        ya[i] -= cp[i] * ya[j];
        yb[i] -= cp[i] * yb[j];
    }
}

/* no node sticks: the cyclic system of the whole loop (Sherman–Morrison
 * on the two corner entries −a_{n−1}; Numerical Recipes, 2nd ed., §2.7,
 * "cyclic tridiagonal systems") */
static void loop_solve(bd_sim *sim, double dt)
{
    bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n;
    double *cp = mn->cp, *x = mn->p0, *z = mn->qa;
    double corner = -mn->ca[n - 1];
    double D0 = sim->mass[0] / dt + mn->ca[n - 1] + mn->ca[0];
    double gam = -D0;
    /* T' = T − u·vᵀ with u = (γ, 0, …, corner), v = (1, 0, …, corner/γ) */
    double prev_c = 0.0, px = 0.0, pz = 0.0;
    for (int i = 0; i < n; i++) {
        int b = i == 0 ? n - 1 : i - 1;
        double al = i == 0 ? 0.0 : mn->ca[b], ar = i == n - 1 ? 0.0 : mn->ca[i];
        double D = sim->mass[i] / dt + mn->ca[b] + mn->ca[i];
        if (i == 0)
            D -= gam;
        if (i == n - 1)
            D -= corner * corner / gam;
        double r = mn->rhs[i] + slip_force(sim, i);
        double u = i == 0 ? gam : (i == n - 1 ? corner : 0.0);
        double inv = 1.0 / (i == 0 ? D : D + al * prev_c);
        double c = -ar * inv;
        px = i == 0 ? r * inv : (r + al * px) * inv;
        pz = i == 0 ? u * inv : (u + al * pz) * inv;
        cp[i] = c;
        x[i] = px;
        z[i] = pz;
        prev_c = c;
    }
    for (int i = n - 2; i >= 0; i--) {
        x[i] -= cp[i] * x[i + 1];
        z[i] -= cp[i] * z[i + 1];
    }
    double fact = (x[0] + corner / gam * x[n - 1]) / (1.0 + z[0] + corner / gam * z[n - 1]);
    for (int i = 0; i < n; i++)
        mn->vnew[i] = x[i] - fact * z[i];
}

/* Gaussian elimination with partial pivoting, m×m, in place; x in b */
static void dense_solve(double *A, double *b, int m)
{
    for (int k = 0; k < m; k++) {
        int piv = k;
        for (int r = k + 1; r < m; r++)
            if (fabs(A[r * m + k]) > fabs(A[piv * m + k]))
                piv = r;
        if (piv != k) {
            for (int c = 0; c < m; c++) {
                double t = A[k * m + c];
                A[k * m + c] = A[piv * m + c];
                A[piv * m + c] = t;
            }
            double t = b[k];
            b[k] = b[piv];
            b[piv] = t;
        }
        double d = A[k * m + k];
        if (d == 0.0)
            continue;
        for (int r = k + 1; r < m; r++) {
            double f = A[r * m + k] / d;
            if (f == 0.0)
                continue;
            for (int c = k; c < m; c++)
                A[r * m + c] -= f * A[k * m + c];
            b[r] -= f * b[k];
        }
    }
    for (int k = m - 1; k >= 0; k--) {
        double s = b[k];
        for (int c = k + 1; c < m; c++)
            s -= A[k * m + c] * b[c];
        b[k] = A[k * m + k] != 0.0 ? s / A[k * m + k] : 0.0;
    }
}

/* one pass with the present contact set: the pulley speeds into omega,
 * the node speeds into vnew, each stuck node's friction into fr */
static void solve_pass(bd_sim *sim, double dt, double *omega, double *fr)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n, np = sim->model->pulley_count;
    double *A = mn->A, *bv = mn->b;
    memset(A, 0, (size_t)(np * np) * sizeof *A);
    /* the pulleys' own rows */
    for (int p = 0; p < np; p++) {
        const bd_pulley_body *pb = &sim->pulleys[p];
        if (pb->held) {
            A[p * np + p] = 1.0;
            bv[p] = pb->omega;
            continue;
        }
        double I = bd_pulley_solve_inertia(sim, pb);
        A[p * np + p] = I / dt;
        bv[p] = I / dt * pb->omega + mn->Q[p];
    }
    for (int i = 0; i < n; i++) {
        double f = slip_force(sim, i);
        if (f != 0.0 && !sim->pulleys[mm->pulley[i]].held)
            bv[mm->pulley[i]] -= sim->pulleys[mm->pulley[i]].m->radius * f;
    }
    int s0 = -1;
    for (int i = 0; i < n && s0 < 0; i++)
        if (is_stuck(mn, i))
            s0 = i;
    if (s0 < 0) {
        loop_solve(sim, dt);
        dense_solve(A, bv, np);
        for (int p = 0; p < np; p++)
            omega[p] = bv[p];
        return;
    }
    /* the runs between stuck nodes: solve each, then book what its end
     * nodes' rows take from it into the pulley system */
    int s = s0;
    do {
        int first = bd_node_next(s, n), count = 0, e = first;
        while (!is_stuck(mn, e)) {
            count++;
            e = bd_node_next(e, n);
        }
        if (count > 0)
            run_solve(sim, first, count, dt);
        /* the stuck nodes at the run's two ends know each other */
        mn->run_next[s] = e;
        mn->run_prev[e] = s;
        s = e;
    } while (s != s0);

    /* each stuck node's friction, affine in the pulley speeds:
     * Fr = D·v_s − a_b·v_b − a_s·v_j − rhs, its neighbours' speeds from
     * their runs (p0 + qa·v_left end + qb·v_right end) or their pulleys */
    s = s0;
    do {
        int b = bd_node_prev(s, n), j = bd_node_next(s, n);
        double ab = mn->ca[b], as = mn->ca[s];
        double D = sim->mass[s] / dt + ab + as;
        affine vs = surface(sim, s);
        /* coefficients on up to three pulleys */
        int pk[3] = {vs.p, -1, -1};
        double gk[3] = {D * vs.g, 0.0, 0.0};
        double c0 = D * vs.c0 - mn->rhs[s];
        /* neighbour b: the end of the run before s (or stuck) */
        int nb[2] = {b, j};
        double an[2] = {ab, as};
        for (int side = 0; side < 2; side++) {
            int x = nb[side];
            affine add[2];
            int na = 0;
            double cx = 0.0;
            if (is_stuck(mn, x)) {
                add[na++] = surface(sim, x);
            } else {
                /* x is in a run: the one ending at s (side 0) or the one
                 * starting after it (side 1) */
                int l = side == 0 ? mn->run_prev[s] : s;
                int r = side == 0 ? s : mn->run_next[s];
                cx = mn->p0[x];
                affine L = surface(sim, l), R = surface(sim, r);
                L.c0 *= mn->qa[x];
                L.g *= mn->qa[x];
                R.c0 *= mn->qb[x];
                R.g *= mn->qb[x];
                add[na++] = L;
                add[na++] = R;
            }
            c0 -= an[side] * cx;
            for (int k = 0; k < na; k++) {
                c0 -= an[side] * add[k].c0;
                if (add[k].p < 0)
                    continue;
                int slot = 0;
                while (slot < 3 && pk[slot] != add[k].p && pk[slot] >= 0)
                    slot++;
                if (slot == 3)
                    continue;
                pk[slot] = add[k].p;
                gk[slot] -= an[side] * add[k].g;
            }
        }
        /* store Fr's constant part; its pulley's row takes R·Fr */
        fr[s] = c0;
        int ps = mm->pulley[s];
        if (!sim->pulleys[ps].held) {
            double R = sim->pulleys[ps].m->radius;
            bv[ps] -= R * c0;
            for (int k = 0; k < 3; k++)
                if (pk[k] >= 0)
                    A[ps * np + pk[k]] += R * gk[k];
        }
        /* keep the coefficients to evaluate Fr after the solve */
        for (int k = 0; k < 3; k++) {
            mn->frp[3 * s + k] = pk[k];
            mn->frg[3 * s + k] = gk[k];
        }
        do {
            s = bd_node_next(s, n);
        } while (!is_stuck(mn, s));
    } while (s != s0);

    dense_solve(A, bv, np);
    for (int p = 0; p < np; p++)
        omega[p] = bv[p];

    /* the speeds: stuck nodes on their pulleys, run nodes from their ends */
    s = s0;
    do {
        affine L = surface(sim, s);
        double vl = L.c0 + (L.p >= 0 ? L.g * omega[L.p] : 0.0);
        mn->vnew[s] = vl;
        /* Fr of s */
        double f = fr[s];
        for (int k = 0; k < 3; k++)
            if (mn->frp[3 * s + k] >= 0)
                f += mn->frg[3 * s + k] * omega[mn->frp[3 * s + k]];
        fr[s] = f;
        int e = bd_node_next(s, n);
        int first = e, count = 0;
        while (!is_stuck(mn, e)) {
            count++;
            e = bd_node_next(e, n);
        }
        if (count > 0) {
            affine R = surface(sim, e);
            double vr = R.c0 + (R.p >= 0 ? R.g * omega[R.p] : 0.0);
            for (int k = 0, i = first; k < count; k++, i = bd_node_next(i, n))
                mn->vnew[i] = mn->p0[i] + mn->qa[i] * vl + mn->qb[i] * vr;
        }
        s = e;
    } while (s != s0);
}

/* the wrap phase: the external torque of each pulley is kept for the
 * solve (supports phase), which takes all pulleys at once */
void bd_mn_wrap(bd_sim *sim, bd_pulley_body *p, double external_torque)
{
    bd_mn_of(sim)->Q[p - sim->pulleys] = external_torque;
}

/* the contact set from the pressures of this step: a node off its pulley
 * (N ≤ 0, or no friction) takes no friction; one coming back tries
 * sticking first */
static void contact_from_pressure(bd_sim *sim)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    bd_mn *mn = bd_mn_of(sim);
    for (int i = 0; i < sim->model->n; i++) {
        if (mm->kind[i] != BD_MN_ARC) {
            mn->contact[i] = BD_MN_OFF;
            continue;
        }
        const bd_pulley_model *pm = sim->pulleys[mm->pulley[i]].m;
        if (mn->normal[i] <= 0.0 || pm->mu_s <= 0.0) {
            if (mn->normal[i] < 0.0 && !sim->stabilizing) {
                if (mn->liftoff_steps == 0) {
                    mn->liftoff_first_t = sim->t;
                    mn->liftoff_first_node = i;
                }
                mn->liftoff_steps++;
            }
            mn->contact[i] = BD_MN_OFF;
        } else if (mn->contact[i] == BD_MN_OFF) {
            mn->contact[i] = BD_MN_STICK;
        }
    }
}

/* the contact set checked against the solution: returns how many nodes
 * change (all of them, or with `one` only the worst) */
static int correct_contacts(bd_sim *sim, double dt, int one)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    bd_mn *mn = bd_mn_of(sim);
    int changes = 0, worst = -1;
    unsigned char worst_to = BD_MN_STICK;
    double worst_by = 0.0;
    for (int i = 0; i < sim->model->n; i++) {
        unsigned char st = mn->contact[i], to = st;
        if (st == BD_MN_OFF)
            continue;
        const bd_pulley_body *p = &sim->pulleys[mm->pulley[i]];
        double by = 0.0;
        if (st == BD_MN_STICK) {
            double lim = p->m->mu_s * mn->normal[i];
            if (fabs(mn->fr[i]) > lim) {
                to = mn->fr[i] > 0.0 ? BD_MN_SLIP_NEG : BD_MN_SLIP_POS;
                by = fabs(mn->fr[i]) - lim;
            }
        } else {
            double vrel = mn->vnew[i] - p->m->radius * mn->omega[mm->pulley[i]];
            if ((st == BD_MN_SLIP_POS && vrel < 0.0) || (st == BD_MN_SLIP_NEG && vrel > 0.0)) {
                to = BD_MN_STICK;
                by = sim->mass[i] * fabs(vrel) / dt;
            }
        }
        if (to == st)
            continue;
        changes++;
        if (!one)
            mn->contact[i] = to;
        else if (by > worst_by) {
            worst_by = by;
            worst = i;
            worst_to = to;
        }
    }
    if (one && worst >= 0)
        mn->contact[worst] = worst_to;
    return changes;
}

/* the supports phase: the whole loop's axial speeds and the pulleys' */
void bd_mn_solve(bd_sim *sim)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n, np = sim->model->pulley_count;
    const double dt = sim->model->dt, *v = sim->vx;
    coefs(sim, dt);
    for (int i = 0; i < n; i++) {
        int b = bd_node_prev(i, n), j = bd_node_next(i, n);
        mn->rhs[i] = sim->mass[i] * v[i] / dt + sim->fx[i]
                   + mn->cb[i] * (v[j] - v[i]) - mn->cb[b] * (v[i] - v[b]);
    }
    if (mn->four_level)
        four_level_old(sim, mn->rhs);
    contact_from_pressure(sim);
    for (int clip = 0; clip < 3; clip++) {
        int pass = 0;
        for (; pass < PASSES; pass++) {
            solve_pass(sim, dt, mn->omega, mn->fr);
            if (correct_contacts(sim, dt, pass >= HALF) == 0)
                break;
        }
        if (pass == PASSES)
            mn->solve_fallbacks++;
        int again = 0;
        for (int p = 0; p < np; p++) {
            bd_pulley_body *pb = &sim->pulleys[p];
            if (!pb->held && bd_pulley_drive_clip(sim, pb, (mn->omega[p] - pb->omega) / dt, &mn->Q[p]))
                again = 1;
        }
        if (!again)
            break;
    }

    /* what the nodes feel over the step: the implicit elastic increment,
     * the dashpots at the mid-step speeds, the friction */
    for (int i = 0; i < n; i++) {
        if (mm->kind[i] != BD_MN_ARC || mn->contact[i] != BD_MN_STICK)
            mn->fr[i] = slip_force(sim, i);
    }
    const double *vn = mn->vnew;
    for (int i = 0; i < n; i++) {
        int b = bd_node_prev(i, n), j = bd_node_next(i, n);
        double dmi = 0.5 * (vn[j] - vn[i] + v[j] - v[i]), dmb = 0.5 * (vn[i] - vn[b] + v[i] - v[b]);
        double damp = mm->c[i] * dmi - mm->c[b] * dmb
                    + mn->cna[i] * (vn[j] - vn[i]) + mn->cnb[i] * (v[j] - v[i])
                    - mn->cna[b] * (vn[i] - vn[b]) - mn->cnb[b] * (v[i] - v[b]);
        sim->fnx[i] += damp + mn->fr[i];
        sim->fx[i] = sim->mass[i] * (vn[i] - v[i]) / dt;
    }
    if (mn->four_level)
        four_level_old(sim, sim->fnx);
    for (int p = 0; p < np; p++) {
        bd_pulley_body *pb = &sim->pulleys[p];
        const bd_mn_pulley *pp = &mm->pulleys[p];
        double R = pb->m->radius, F = 0.0;
        for (int k = 0; k < pp->count; k++)
            F += mn->fr[(pp->first + k) % n];
        pb->torque_friction = -R * F;
        pb->alpha = pb->held ? 0.0 : (mn->omega[p] - pb->omega) / dt;
        if (!pb->m->movable)
            continue;
        /* the belt's pull on the carriage: −∂U/∂q of the stretches'
         * elements, their dashpots, and the weight of what moves with it */
        double fa = 0.0, fnc = 0.0;
        const bd_mn_stretch *st[2] = {&pp->in, &pp->out};
        for (int h = 0; h < 2; h++)
            for (int k = 0; k < st[h]->count; k++) {
                int e = (st[h]->first + k) % n, j = bd_node_next(e, n);
                double d = mm->c[e] * (0.5 * (vn[j] - vn[e] + v[j] - v[e]) + mm->dsq[e] * pb->qdot);
                double Tel = sim->tension[e] - mn->td[e];
                fa -= (Tel + d) * mn->cos_e[e] * mm->dsq[e];
                fnc -= d * mn->cos_e[e] * mm->dsq[e];
            }
        pb->f_axis = fa + pb->m->wrap_pull;
        pb->fnc_axis = fnc;
    }
}
