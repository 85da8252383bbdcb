/* The spring–damping elements' shear and bending, and the rigid elements'
 * rotation (seed 000 §2.3–2.4).
 *
 * SDE e joins element i = e to j = e + 1. With u the unit vector from i's
 * mass centre to j's, t_i = (cos φ_i, sin φ_i), and all angles measured
 * the counter-clockwise way:
 *   shear  γ = angle from the bisector of t_i and t_j to u
 *            = θ_u − ½(φ_i + φ_j)      (the SDE's transverse gap over l0)
 *   bend   β = angle from t_i to t_j = φ_j − φ_i
 * its potential (§2.3, Voigt, a rectangular section: GA and EI of the
 * belt over an element's length l0)
 *   V = ½·k_γ·γ² + ½·k_β·β²,   k_γ = GA·l0,  k_β = EI/l0,
 * and its dissipation function ½c_γ·γ̇² + ½c_β·β̇², with
 *   γ̇ = perp(u)·(v_j − v_i)/|x_j − x_i| − ½(ω_i + ω_j),  β̇ = ω_j − ω_i.
 * Lagrange's equations (§2.4) give, with Q = k_γ·γ + c_γ·γ̇ and
 * M = k_β·β + c_β·β̇ (∂θ_u/∂x_j = perp(u)/|x_j − x_i| = −∂θ_u/∂x_i,
 * perp(u) = (−u_y, u_x)):
 *   on i:  +Q·perp(u)/|x_j − x_i|,  torque  ½Q + M
 *   on j:  −Q·perp(u)/|x_j − x_i|,  torque  ½Q − M.
 * The SDE's axial part, EA/l0 on the belt's stretch between the centres,
 * is the lumped chain's (belt/lumped/forces.c). It pulls at the centres,
 * where the belt's tension pulls at an element's joints, ½l0 before and
 * after it: there it turns an element that stands askew to the line of
 * the belt back into it, by l0·T·ψ for a small angle ψ from the bisector
 * of the lines to its neighbours' centres,
 *   ψ_i = φ_i − ½(θ_{i−1} + θ_i).
 * Without it nothing holds the elements turning against each other with
 * their centres in line (γ = 0 for φ alternating ±Φ): with EI = 0 that
 * mode has no stiffness at all, and on a running belt it filled with
 * energy until tensions swung by ±2 kN (head_drive.yaml; with EI = 20 N·m²
 * the run matched the lumped belt's). It is taken as a spring of its own,
 *   V = ½·k_ψ,i·ψ_i²,  k_ψ,i = l0·T_i  (T_i the tension at rest there, build.c),
 * so that the forces stay conservative; its forces on the centres follow
 * from ∂θ_e/∂x as the shear's do: SDE e's Q less ½(H_e + H_e+1), with
 * H = k_ψ·ψ + c_ψ·ψ̇ and the torque −H on the element. For small angles γ·l0 is
 * the SDE's transverse gap of §2.3: this is its energy, not linearized
 * further, so the forces are conservative (the dashpots apart) and the
 * energy account holds to the scheme's accuracy. Derived here;
 * docs/physics.md §15. */
#include "belt/rfe/rfe.h"

#include <math.h>

/* atan2(y, x): for a small angle (x > 0, |y| ≤ 0.1·x) by the series of
 * atan(y/x) to the 9th power, off by less than t¹¹/11 = 1e-12 rad; else
 * atan2 itself. The SDEs' and the alignment's angles are small except a
 * bend on a pulley */
static inline double angle_of(double y, double x)
{
    if (x > 0.0 && fabs(y) <= 0.1 * x) {
        double t = y / x, t2 = t * t;
        return t * (1.0 + t2 * (-1.0 / 3.0 + t2 * (1.0 / 5.0 + t2 * (-1.0 / 7.0 + t2 / 9.0))));
    }
    return atan2(y, x);
}

/* SDE e's shear and bend, their forces (the element pass: nothing of an
 * element is written) */
static void sde(bd_sim *sim, int e, int j)
{
    bd_rfe *R = bd_rfe_of(sim);
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const bd_lumped *L = &R->lumped;
    const int i = e;
    double ux = L->ux[e], uy = L->uy[e];
    /* the bisector of t_i and t_j (not normalized: atan2 needs none) */
    double bx = R->ct[i] + R->ct[j], by = R->st[i] + R->st[j];
    double gam = angle_of(bx * uy - by * ux, bx * ux + by * uy);
    double bend = angle_of(R->ct[i] * R->st[j] - R->st[i] * R->ct[j],
                           R->ct[i] * R->ct[j] + R->st[i] * R->st[j]);
    /* perp(u)/|x_j − x_i| = ∂θ_u/∂x_j, for the turn rate here and the
     * forces on both elements (body) */
    double inv = 1.0 / L->len[e], px = -uy * inv, py = ux * inv;
    double thdot = px * (sim->vx[j] - sim->vx[i]) + py * (sim->vy[j] - sim->vy[i]);
    R->px[e] = px;
    R->py[e] = py;
    double gdot = thdot - 0.5 * (R->omega[i] + R->omega[j]);
    double qd = RM->c_shear * gdot, mbd = RM->c_bend * (R->omega[j] - R->omega[i]);
    R->thdot[e] = thdot;
    /* between two tied elements (inside a section or joining two) the
     * sections' lines hold both across and in their turn: no shear or
     * bending (sections.c) */
    double on = bd_rfe_sde_held(R, i, j) ? 0.0 : 1.0;
    R->qd[e] = on * qd;
    R->q[e] = on * (RM->k_shear * gam + qd);
    R->mbd[e] = on * mbd;
    R->mb[e] = on * (RM->k_bend * bend + mbd);
}

/* element i's angle to the line of the belt, the bisector of the lines
 * from centre i − 1 to i (SDE b) and from i to i + 1 (SDE a), and its
 * aligning moment (after every SDE's turn rate) */
static void align(bd_sim *sim, int i, int b)
{
    bd_rfe *R = bd_rfe_of(sim);
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const bd_lumped *L = &R->lumped;
    double wx = L->ux[i] + L->ux[b], wy = L->uy[i] + L->uy[b];
    double psi = angle_of(wx * R->st[i] - wy * R->ct[i], wx * R->ct[i] + wy * R->st[i]);
    double hd = RM->c_align[i] * (R->omega[i] - 0.5 * (R->thdot[i] + R->thdot[b]));
    /* a tied element's turn is its section's line's (sections.c) */
    if (R->sec[i] >= 0)
        hd = psi = 0.0;
    R->hd[i] = hd;
    R->h[i] = RM->k_align[i] * psi + hd;
}

/* element i: SDE i (it is its start) and SDE i − 1 (its end), and its
 * alignment; SDE e's force across the line is Q_e − ½(H_e + H_e+1) */
static void body(bd_sim *sim, int i, int b, int a)
{
    bd_rfe *R = bd_rfe_of(sim);
    double pax = R->px[i], pay = R->py[i], pbx = R->px[b], pby = R->py[b];
    double qa = R->q[i] - 0.5 * (R->h[i] + R->h[a]), qb = R->q[b] - 0.5 * (R->h[b] + R->h[i]);
    double qda = R->qd[i] - 0.5 * (R->hd[i] + R->hd[a]);
    double qdb = R->qd[b] - 0.5 * (R->hd[b] + R->hd[i]);
    sim->fx[i] += qa * pax - qb * pbx;
    sim->fy[i] += qa * pay - qb * pby;
    sim->fnx[i] += qda * pax - qdb * pbx;
    sim->fny[i] += qda * pay - qdb * pby;
    R->tq[i] = 0.5 * (R->q[i] + R->q[b]) + R->mb[i] - R->mb[b] - R->h[i];
    R->tqn[i] = 0.5 * (R->qd[i] + R->qd[b]) + R->mbd[i] - R->mbd[b] - R->hd[i];
}

/* the forces phase: the lumped chain's (axial SDE round the wraps,
 * gravity, the skirts), then the SDEs' shear and bending */
void bd_rfe_forces(bd_sim *sim)
{
    const int n = sim->model->n;
    const bd_rfe *R = bd_rfe_of(sim);
    if (!bd_rfe_some_tied(sim)) {
        bd_lumped_forces(sim);
        for (int e = 0; e + 1 < n; e++)
            sde(sim, e, e + 1);
        sde(sim, n - 1, 0);
        align(sim, 0, n - 1);
        for (int i = 1; i < n; i++)
            align(sim, i, i - 1);
        body(sim, 0, n - 1, 1 % n);
        for (int i = 1; i < n; i++)
            body(sim, i, i - 1, bd_node_next(i, n));
        return;
    }
    /* with sections (sections.c): the lumped chain's forces on the free
     * elements and the sections' ends (and a full section's every one),
     * the SDEs with a free element, the free
     * elements' alignment, and the free elements and the sections' ends
     * they pull; inside a section all of it is 0 (kept so from when its
     * elements were tied) */
    bd_rfe_sections_forces(sim);
    for (int r = 0; r < R->run_n; r++) {
        const int f = R->run_first[r], c = R->run_count[r];
        for (int q = -1, e = bd_node_prev(f, n); q < c; q++, e = bd_node_next(e, n))
            sde(sim, e, bd_node_next(e, n));
        for (int q = 0, i = f; q < c; q++, i = bd_node_next(i, n))
            align(sim, i, bd_node_prev(i, n));
        for (int q = -1, i = bd_node_prev(f, n); q <= c; q++, i = bd_node_next(i, n))
            body(sim, i, bd_node_prev(i, n), bd_node_next(i, n));
    }
}

/* (c, s) = (cos φ, sin φ) turned by d rad: cos d and sin d by their
 * series (to d⁴ and d⁵, off by d⁶/720: 1e-15 at d = 0.01, more than an
 * element turns in a step), then scaled back to unit length by one Newton
 * step for 1/√(c² + s²) (the series' rounding would otherwise add up over
 * millions of steps); atan-free and division-free */
static inline void turn(double *c, double *s, double d)
{
    double C, S;
    if (fabs(d) < 0.01) {
        double d2 = d * d;
        C = 1.0 - d2 * (0.5 - d2 / 24.0);
        S = d * (1.0 - d2 * (1.0 / 6.0 - d2 / 120.0));
    } else {
        C = cos(d);
        S = sin(d);
    }
    double c1 = *c * C - *s * S, s1 = *s * C + *c * S;
    double f = 1.5 - 0.5 * (c1 * c1 + s1 * s1);
    *c = c1 * f;
    *s = s1 * f;
}

/* rotations to t + Δt (φ) and t + Δt/2 (ω), as the centres move
 * (belt/lumped/forces.c advance), by the implicit step's Δω
 * (rotation_solve.c); the kinetic energy and the dashpots' work are
 * booked at the mid-step rate ω + ½Δω, as the centres' are */
void bd_rfe_integrate(bd_sim *sim, double *ke_out, double *w_nc_out)
{
    bd_rfe *R = bd_rfe_of(sim);
    const int n = sim->model->n;
    const double dt = sim->model->dt, J = bd_rfe_model_of(sim)->inertia;
    bd_rfe_rotation_implicit(sim);
    if (!R->tied) {
        bd_lumped_integrate(sim, ke_out, w_nc_out);
    } else {
        /* the free elements as the lumped belt's nodes, the sections
         * each as one body (sections.c) */
        const double *restrict lpw = R->lumped.pw, *restrict lek = R->lumped.ek;
        double w = 0.0, k = 0.0;
        for (int r = 0; r < R->run_n; r++) {
            /* a run round the loop's end in two pieces */
            int f = R->run_first[r], c = R->run_count[r];
            int c0 = f + c <= n ? c : n - f;
            bd_lumped_advance_range(sim, f, c0);
            if (c0 < c)
                bd_lumped_advance_range(sim, 0, c - c0);
            for (int q = 0, i = f; q < c; q++, i = bd_node_next(i, n)) {
                w += lpw[i];
                k += lek[i];
            }
        }
        *w_nc_out = w * dt;
        *ke_out = 0.5 * k;
        bd_rfe_sections_move(sim, ke_out, w_nc_out);
    }
    const double *restrict dw = R->rb, *restrict tqn = R->tqn;
    double *restrict om = R->omega, *restrict ct = R->ct, *restrict st = R->st,
           *restrict pw = R->pw, *restrict ek = R->ek;
    double w_nc = 0.0, ke = 0.0;
    if (!bd_rfe_some_tied(sim)) {
        for (int i = 0; i < n; i++) {
            double mid = om[i] + 0.5 * dw[i];
            pw[i] = tqn[i] * mid;
            ek[i] = mid * mid;
            om[i] += dw[i];
            turn(&ct[i], &st[i], om[i] * dt);
        }
        for (int i = 0; i < n; i++) {
            w_nc += pw[i];
            ke += ek[i];
        }
    } else {
        /* a tied element does not turn */
        for (int r = 0; r < R->run_n; r++)
            for (int q = 0, i = R->run_first[r]; q < R->run_count[r]; q++, i = bd_node_next(i, n)) {
                double mid = om[i] + 0.5 * dw[i];
                w_nc += tqn[i] * mid;
                ke += mid * mid;
                om[i] += dw[i];
                turn(&ct[i], &st[i], om[i] * dt);
            }
    }
    *w_nc_out += w_nc * dt;
    *ke_out += 0.5 * J * ke;
}

/* at rest at t (sim/step.c bd_sim_start_at_rest): the half-step angular
 * velocities −½Δω of the implicit step from the forces at t (h = Δt/2),
 * or 0 (h = 0) */
void bd_rfe_rest_velocities(bd_sim *sim, double h)
{
    bd_rfe *R = bd_rfe_of(sim);
    const int n = sim->model->n;
    if (h > 0.0)
        bd_rfe_rotation_implicit(sim);
    for (int i = 0; i < n; i++)
        R->omega[i] = h > 0.0 ? -h / sim->model->dt * R->rb[i] : 0.0;
}

/* SDE e's shear γ and bend β (into *bend) from the present positions,
 * as the forces phase measures them (there from the lumped pass's unit
 * vectors); for the energy and the build */
double bd_rfe_sde_angles(const bd_sim *sim, int e, double *bend)
{
    const bd_rfe *R = bd_rfe_of(sim);
    int i = e, j = bd_node_next(e, sim->model->n);
    double ci = R->ct[i], si = R->st[i], cj = R->ct[j], sj = R->st[j];
    double ux = sim->x[j] - sim->x[i], uy = sim->y[j] - sim->y[i];
    double bx = ci + cj, by = si + sj;
    *bend = atan2(ci * sj - si * cj, ci * cj + si * sj);
    return atan2(bx * uy - by * ux, bx * ux + by * uy);
}

/* element i's angle ψ to the line of the belt from the present positions
 * (the bisector of the lines to its neighbours' centres) */
double bd_rfe_align_angle(const bd_sim *sim, int i)
{
    const bd_rfe *R = bd_rfe_of(sim);
    const int n = sim->model->n;
    int b = bd_node_prev(i, n), a = bd_node_next(i, n);
    double ax = sim->x[a] - sim->x[i], ay = sim->y[a] - sim->y[i];
    double bx = sim->x[i] - sim->x[b], by = sim->y[i] - sim->y[b];
    double la = hypot(ax, ay), lb = hypot(bx, by);
    double wx = ax / la + bx / lb, wy = ay / la + by / lb;
    return atan2(wx * R->st[i] - wy * R->ct[i], wx * R->ct[i] + wy * R->st[i]);
}

double bd_rfe_sde_energy(const bd_sim *sim, int e)
{
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const bd_rfe *R = bd_rfe_of(sim);
    const int j = bd_node_next(e, sim->model->n);
    double x = hypot(sim->x[j] - sim->x[e], sim->y[j] - sim->y[e]) - sim->model->l0;
    double v = 0.5 * RM->lumped.k_axial * x * x;
    /* between two tied elements a section's line holds them: no shear or
     * bending (sde above) */
    if (!bd_rfe_sde_held(R, e, j)) {
        double bend, gam = bd_rfe_sde_angles(sim, e, &bend);
        v += 0.5 * RM->k_shear * gam * gam + 0.5 * RM->k_bend * bend * bend;
    }
    return v;
}

double bd_rfe_align_energy(const bd_sim *sim, int i)
{
    if (bd_rfe_of(sim)->sec[i] >= 0)
        return 0.0;
    double psi = bd_rfe_align_angle(sim, i);
    return 0.5 * bd_rfe_model_of(sim)->k_align[i] * psi * psi;
}

/* the SDEs' shear and bending energy and the alignment's */
static double sde_energy(const bd_sim *sim)
{
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const bd_rfe *R = bd_rfe_of(sim);
    double e = 0.0;
    for (int i = 0; i < sim->model->n; i++) {
        double bend, gam = bd_rfe_sde_angles(sim, i, &bend);
        double psi = bd_rfe_align_angle(sim, i);
        if (!bd_rfe_sde_held(R, i, bd_node_next(i, sim->model->n)))
            e += 0.5 * RM->k_shear * gam * gam + 0.5 * RM->k_bend * bend * bend;
        if (R->sec[i] < 0)
            e += 0.5 * RM->k_align[i] * psi * psi;
    }
    return e;
}

double bd_rfe_elastic_energy(const bd_sim *sim)
{
    return bd_lumped_elastic_energy(sim) + sde_energy(sim);
}

double bd_rfe_potential(const bd_sim *sim)
{
    return bd_lumped_potential(sim) + sde_energy(sim);
}
