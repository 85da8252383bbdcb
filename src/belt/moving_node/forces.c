/* The moving-node belt's forces at t (docs/physics.md §14).
 *
 * Element e (node e → e+1) in the material description (Kelvin–Voigt,
 * seed 001 eq 4.1 per unit unstretched length; seed 003 §5):
 *   ε_e = l_e/ΔX_e − 1,   T_e = EA·ε_e + c_e·(v_{e+1} − v_e + dsq_e·q̇),
 * l_e its length in space (span: from the chord and the transverse
 * displacements; arc: R·Δθ), the dashpot acting on the material rate of
 * stretch ∂v/∂X (the belt speed relative to the nodes plus the mesh's own
 * rate where a takeup carriage moves it). Across a span the dashpot pulls
 * with the rate at which the transverse motion stretches the element
 * instead (elements(), below).
 *
 * Node i, along the path (seed 003 §3 eqs 3–4: the material time
 * derivative at a spatial point, ∂/∂t = d/dt − ṡ·∂/∂s, makes the
 * acceleration of the belt passing a fixed node ∂v/∂t + v·∂v/∂s):
 *   m_i·∂v_i/∂t = T_i·cos_i − T_{i−1}·cos_{i−1} + W_i − m_i·v_i·∂v/∂s
 *                 − f_r·N_i·sat(v_i/v_0) [idler] − m'_L·v_i² [feed] + F_i [pulley]
 * with m·v·∂v/∂s in skew-symmetric form plus its upwind diffusion
 * (convective(), below). Only the elastic part at t goes into fx here; the
 * dashpots, the elastic increment over the step and the pulley friction
 * are the implicit solve's (solve.c).
 *
 * Node i of a span, across it (the axially moving string, w_tt + 2v·w_st
 * + v²·w_ss = (T/m')·w_ss + ..., in the spatial description: S. Wickert,
 * C. D. Mote, J. Appl. Mech. 57 (1990) 738, eq 1; seed 003 eq 4 gives
 * the same convective terms):
 *   m_i·ẅ_i = T_i·sin_i − T_{i−1}·sin_{i−1} − m_i·v_i²·w_ss − 2·m_i·v_i·ẇ_s
 *             + N_i + W⊥_i + bending,
 * explicit central differences; an idler node rests on its idler (N ≥ 0
 * keeps w ≥ 0) or lifts off.
 *
 * An arc node lies on its pulley: the pressure the pulley must give it,
 *   N_i = Σ T·Δθ/2 (its arc elements) − m_arc·v²/R + weight towards the
 *         centre (+ the pull of a sagging span at a tangent point),
 * the belt on a drum pressing with (T − ρv²)/R per unit length (the
 * Euler–Eytelwein wrap with seed 004's centrifugal force F_C = ρ·V²),
 * bounds its friction (solve.c); N < 0 is lift-off. */
#include "belt/moving_node/moving_node.h"

#include <math.h>

#include "laws/rolling.h"

/* every element's length, direction, strain and tension */
static void elements(bd_sim *sim)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n;
    const double EA = sim->model->EA, *v = sim->vx, *wd = sim->vy;
    for (int e = 0; e < n; e++) {
        int j = bd_node_next(e, n);
        double rate = v[j] - v[e];
        if (mm->eq[e] >= 0)
            rate += mm->dsq[e] * sim->pulleys[mm->eq[e]].qdot;
        /* its length in space, shortened in a vertical curve (the pull
         * T·Δθ across, below) */
        double cs, sn, l = bd_mn_element_length(mm, mn, e, n, &cs, &sn);
        mn->len[e] = l;
        mn->cos_e[e] = cs;
        mn->sin_e[e] = sn;
        double td = mm->c[e] * rate;
        mn->td[e] = td;
        sim->tension[e] = EA * (l / mn->dX[e] - 1.0) + td;
        /* the transverse part of the length's rate, ∂l/∂w·∂w/∂t of both
         * ends (the pull across below is −T·∂l/∂w), and its own dashpot */
        double ke = mm->kw[e] * cs;
        mn->tdw[e] = mm->c[e] * ((sn - ke) * wd[j] - (sn + ke) * wd[e]);
    }
}

/* bending (EI > 0): the discrete energy Σ ½·EI·κ_i²·h_i over the span
 * nodes, κ_i the second difference of w (Euler–Bernoulli, U = ∫½EI·w''²;
 * discretized here); its forces −∂U/∂w into out */
static void bending(const bd_sim *sim, double *out)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    const bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n;
    const double EI = sim->model->EI, *w = mn->w;
    for (int i = 0; i < n; i++)
        out[i] = 0.0;
    if (EI <= 0.0)
        return;
    for (int i = 0; i < n; i++) {
        if (mm->kind[i] == BD_MN_ARC)
            continue;
        int b = bd_node_prev(i, n), j = bd_node_next(i, n);
        double la = mm->ds0[b], lb = mm->ds0[i], h = 0.5 * (la + lb);
        double M = EI * ((w[j] - w[i]) / lb - (w[i] - w[b]) / la) / h;   /* EI·κ_i */
        out[j] -= M / lb;
        out[i] += M * (1.0 / la + 1.0 / lb);
        out[b] -= M / la;
    }
}

/* the pressure on arc node i */
static double arc_pressure(const bd_sim *sim, int i)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    const bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n;
    int b = bd_node_prev(i, n), j = bd_node_next(i, n);
    const double *T = sim->tension;
    double N = 0.0, R = 0.0;
    if (mm->on_arc[b]) {
        R = mm->radius[b];
        N += 0.5 * T[b] * mm->ds0[b] / R;
    } else if (mn->sin_e[b] != 0.0) {
        /* a sagging span pulls the tangent point along its normal */
        N -= T[b] * mn->sin_e[b] * (mm->nx[b] * mm->nx[i] + mm->ny[b] * mm->ny[i]);
    }
    if (mm->on_arc[i]) {
        R = mm->radius[i];
        N += 0.5 * T[i] * mm->ds0[i] / R;
    } else if (mn->sin_e[i] != 0.0) {
        N += T[i] * mn->sin_e[i] * (mm->nx[j] * mm->nx[i] + mm->ny[j] * mm->ny[i]);
    }
    if (R > 0.0) {
        double cell = 0.5 * (mm->ds0[b] + mm->ds0[i]), share = mm->arc_len[i] / cell;
        double m = sim->mass[i] - mm->idler_mass[i];
        N += share * (mn->f_norm[i] - m * sim->vx[i] * sim->vx[i] / R);
    }
    return N;
}

/* The convective force m·v·∂v/∂s in a form whose power vanishes over the
 * loop, as the continuum's does (it only carries kinetic energy along):
 * element e (nodes a → z, ρ_e its mass per metre) gives
 *     node a: −(ρ_e/6)·(v_a·v_z + v_z²),   node z: +(ρ_e/6)·(v_a² + v_a·v_z),
 * whose power v_a·F_a + v_z·F_z is zero; summed at a node between
 * elements of any lengths it is −m·v·∂v/∂s to first order (the
 * skew-symmetric form of Burgers' term). Upwinding, which the explicit
 * transport needs, adds the diffusion κ_e·(v_z − v_a) on a and its
 * opposite on z with κ_e = ρ_e·|v̄_e|/2: exactly what separates the
 * one-sided difference from this central one (the kinetic-energy-
 * conserving form of the convective term: Y. Morinishi, T. S. Lund, O. V.
 * Vasilyev, P. Moin, J. Comput. Phys. 143 (1998) 90). Its power −κ_e·(v_z − v_a)²
 * is booked as dissipated. (The one-sided difference alone lost energy
 * unbooked wherever the speed varies along the belt: a rest start with a
 * swinging takeup lost 470 J of 23 kJ in 25 s; now 33 J.)
 * Into to_a[e], to_z[e] the forces on a and z, into diff[e] the diffusion. */
static void convective(const bd_sim *sim, double *to_a, double *to_z, double *diff)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    const int n = sim->model->n;
    const double *v = sim->vx, *m = sim->mass, *mi = mm->idler_mass, *icell = mm->inv_cell;
    for (int e = 0; e < n; e++) {
        int z = bd_node_next(e, n);
        double rho = 0.5 * ((m[e] - mi[e]) * icell[e] + (m[z] - mi[z]) * icell[z]);
        double va = v[e], vz = v[z];
        double d = 0.25 * rho * fabs(va + vz) * (vz - va);
        to_a[e] = -rho / 6.0 * (va * vz + vz * vz) + d;
        to_z[e] = rho / 6.0 * (va * va + va * vz) - d;
        diff[e] = d;
    }
}

/* The Coriolis force across a span, −2·m'·v·∂ẇ/∂s (the moving string,
 * above), taken implicitly: explicit, with ẇ half a step old, it fed the
 * spans' transverse modes (a 6 m/s belt on 0.25 m span elements gained
 * 92 % of its energy scale in 40 s; at 2 m/s it held). Per edge e (nodes
 * e, e + 1) κ_e = ρ_e·v̄_e, and node i gets −(κ_i·ẇ_{i+1} − κ_{i−1}·ẇ_{i−1})
 * at mid step, ẇ = (ẇ⁻ + ẇ⁺)/2: the cell's integral of 2·m'·v·∂ẇ/∂s,
 * and skew, so its power Σ ẇ_i·F_i is zero to round-off, as the
 * continuum's is (the trapezoidal rule on a gyroscopic force; derived
 * here, physics.md §14). */
static double coriolis(const bd_sim *sim, int e)
{
    return bd_mn_of(sim)->kap[e];
}

/* κ_e of every element, from the speeds at t − Δt/2 */
static void coriolis_factors(bd_sim *sim)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    double *kap = bd_mn_of(sim)->kap;
    const int n = sim->model->n;
    const double *m = sim->mass, *mi = mm->idler_mass, *icell = mm->inv_cell, *v = sim->vx;
    for (int e = 0; e < n; e++) {
        int z = bd_node_next(e, n);
        double rho = 0.5 * ((m[e] - mi[e]) * icell[e] + (m[z] - mi[z]) * icell[z]);
        kap[e] = rho * 0.5 * (v[e] + v[z]);
    }
}

/* ẇ of node k at t − Δt/2 (an arc node has none) */
static double wd_at(const bd_sim *sim, int k)
{
    return bd_mn_model_of(sim)->kind[k] == BD_MN_ARC ? 0.0 : sim->vy[k];
}

/* the Coriolis force on node i at mid step, once ẇ⁺ is solved */
static double coriolis_force(const bd_sim *sim, int i)
{
    const bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n;
    int b = bd_node_prev(i, n), j = bd_node_next(i, n);
    double mid_j = 0.5 * (mn->wdn[j] + wd_at(sim, j)), mid_b = 0.5 * (mn->wdn[b] + wd_at(sim, b));
    return -(coriolis(sim, i) * mid_j - coriolis(sim, b) * mid_b);
}

/* one run of free nodes, first .. first + count − 1, between set ones:
 *   (m/Δt)·ẇ⁺_i + (κ_i/2)·ẇ⁺_{i+1} − (κ_{i−1}/2)·ẇ⁺_{i−1}
 *     = (m/Δt)·ẇ⁻_i + G_i − (κ_i/2)·ẇ⁻_{i+1} + (κ_{i−1}/2)·ẇ⁻_{i−1},
 * tridiagonal and diagonally dominant while the belt passes less than a
 * cell per step (the transport's limit); Thomas */
static void transverse_run(bd_sim *sim, int first, int count)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n;
    const double dt = sim->model->dt;
    double *c = mn->sweep_c, *d = mn->sweep_d;
    int i = first, prev_i = -1;
    for (int k = 0; k < count; k++, prev_i = i, i = bd_node_next(i, n)) {
        int b = bd_node_prev(i, n), j = bd_node_next(i, n);
        double m = sim->mass[i] - mm->idler_mass[i];
        double kb = 0.5 * coriolis(sim, b), ki = 0.5 * coriolis(sim, i);
        double diag = m / dt, lo = -kb, up = ki;
        double r = m / dt * sim->vy[i] + mn->gw[i] - ki * wd_at(sim, j) + kb * wd_at(sim, b);
        if (k == 0)
            r -= lo * mn->wdn[b];   /* set: its ẇ⁺ is known */
        if (k == count - 1)
            r -= up * mn->wdn[j];
        if (k > 0) {
            diag -= lo * c[prev_i];
            r -= lo * d[prev_i];
        }
        c[i] = k == count - 1 ? 0.0 : up / diag;
        d[i] = r / diag;
    }
    /* back substitution, from the run's last node */
    int last = prev_i;
    mn->wdn[last] = d[last];
    for (int k = count - 2, q = last; k >= 0; k--) {
        int p = bd_node_prev(q, n);
        mn->wdn[p] = d[p] - c[p] * mn->wdn[q];
        q = p;
    }
}

/* passes of the supports' set (an idler node held or lifting) */
#define SUPPORT_PASSES 8

/* ẇ⁺ of every span node, the Coriolis force implicit: the runs of free
 * nodes between set ones (arc nodes, ẇ = 0; idler nodes held on their
 * idler, w + Δt·ẇ⁺ = 0: N = m·(−w/Δt − ẇ)/Δt − G, derived here, the
 * unilateral constraint w ≥ 0 met at the step's end, physics.md §14).
 * A held node whose support would pull is let go, a free one that would
 * end below its idler is held, and the runs solved again. */
static void transverse(bd_sim *sim)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n;
    const double dt = sim->model->dt;
    const int start = mm->first_arc;
    for (int pass = 0; pass < SUPPORT_PASSES; pass++) {
        /* the runs, walking once round the loop from an arc node; a set
         * node's ẇ⁺ is known before the run it ends is solved */
        mn->wdn[start] = 0.0;
        int run_first = -1, run_count = 0;
        for (int k = 1, i = bd_node_next(start, n); k <= n; k++, i = bd_node_next(i, n)) {
            int arc = mm->kind[i] == BD_MN_ARC;
            if (!arc && mn->pin[i] == 0.0) {
                if (run_count++ == 0)
                    run_first = i;
                continue;
            }
            mn->wdn[i] = arc ? 0.0 : -mn->w[i] / dt;
            if (run_count > 0)
                transverse_run(sim, run_first, run_count);
            run_count = 0;
        }
        /* the last pass keeps the set it was solved with */
        if (pass == SUPPORT_PASSES - 1)
            break;
        int changed = 0;
        for (int q = 0; q < mm->idler_node_count; q++) {
            int i = mm->idler_nodes[q];
            double m = sim->mass[i] - mm->idler_mass[i];
            if (mn->pin[i] != 0.0) {
                double N = m * (mn->wdn[i] - sim->vy[i]) / dt - mn->gw[i]
                         - coriolis_force(sim, i);
                if (N < 0.0) {
                    mn->pin[i] = 0.0;
                    changed = 1;
                }
            } else if (mn->w[i] + dt * mn->wdn[i] < 0.0) {
                mn->pin[i] = 1.0;
                changed = 1;
            }
        }
        if (!changed)
            break;
    }
}

void bd_mn_forces(bd_sim *sim)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n;
    const double dt = sim->model->dt;
    elements(sim);
    coriolis_factors(sim);
    bd_tension_extremes(sim);
    double *fb = mn->cp;   /* scratch until the solve */
    bending(sim, fb);
    double *to_a = mn->qa, *to_z = mn->qb, *diff = mn->p0;   /* the same */
    convective(sim, to_a, to_z, diff);

    const double *v = sim->vx, *wd = sim->vy, *w = mn->w, *T = sim->tension, *td = mn->td;
    const double *tdw = mn->tdw;
    for (int i = 0; i < n; i++) {
        int b = bd_node_prev(i, n), j = bd_node_next(i, n);
        double vi = v[i];
        double m = sim->mass[i] - mm->idler_mass[i];
        /* the elastic pull along the path, and the mesh's dashpot part
         * (known: the carriage speed is at the half step) */
        double Ti = T[i] - td[i], Tb = T[b] - td[b];
        double F = Ti * mn->cos_e[i] - Tb * mn->cos_e[b] + mn->f_grav[i], Fn = 0.0;
        if (mm->eq[i] >= 0) {
            double d = mm->c[i] * mm->dsq[i] * sim->pulleys[mm->eq[i]].qdot * mn->cos_e[i];
            F += d;
            Fn += d;
        }
        if (mm->eq[b] >= 0) {
            double d = mm->c[b] * mm->dsq[b] * sim->pulleys[mm->eq[b]].qdot * mn->cos_e[b];
            F -= d;
            Fn -= d;
        }
        /* the convective acceleration v·∂v/∂s (convective(), above) */
        F += to_a[i] + to_z[b];
        Fn += diff[i] - diff[b];
        double G = 0.0, Gn = 0.0;
        if (mm->kind[i] == BD_MN_ARC) {
            mn->normal[i] = arc_pressure(sim, i);
        } else {
            double la = mn->len[b], lb = mn->len[i];
            double wss = ((w[j] - w[i]) / lb - (w[i] - w[b]) / la) / (0.5 * (la + lb));
            /* the pull across: the elements' slopes, and in a vertical
             * curve the turn of the path, T·Δθ: a string under tension T
             * bent to radius R presses T/R per metre on its supports, as
             * on a drum (seed 004's normal force of the wrap); in a
             * concave curve it lifts off once T/R exceeds the weight's
             * m'g·cos δ, CEMA's concave-curve radius R = T/(m'g) (as
             * compared in D. Pitcher, "Calculation of correct radii for
             * vertical curves in troughed belt conveyors", IMHC B17-16) */
            double ki = mm->kw[i] * mn->cos_e[i], kb = mm->kw[b] * mn->cos_e[b];
            /* across, the dashpot pulls with the transverse stretching's
             * rate alone, not the along-path one: its power is then
             * −c·(∂l/∂w·ẇ)² ≤ 0. With the whole dashpot tension the pull
             * did work c·Δv·(∂l/∂w·ẇ), of either sign (generated seed 1060:
             * the dissipated energy fell at a start) */
            Gn = tdw[i] * (mn->sin_e[i] + ki) - tdw[b] * (mn->sin_e[b] - kb);
            /* all but the Coriolis force, which the transverse solve
             * takes implicitly (transverse(), below) */
            G = Ti * (mn->sin_e[i] + ki) - Tb * (mn->sin_e[b] - kb) + Gn + mn->f_norm[i] + fb[i]
              - m * vi * vi * wss;
            mn->normal[i] = 0.0;
            mn->pin[i] = 0.0;
            if (mm->kind[i] == BD_MN_IDLER) {
                /* the guess of the support's set: on its idler when the
                 * explicit step would end below it */
                double kap_i = coriolis(sim, i), kap_b = coriolis(sim, b);
                double gc = kap_b * wd_at(sim, b) - kap_i * wd_at(sim, j);
                if (w[i] + dt * (wd[i] + dt * (G + gc) / m) < 0.0)
                    mn->pin[i] = 1.0;
            }
        }
        if (i == mm->feed_node) {
            /* the material landing is accelerated to belt speed, the
             * skirts rub (belt.h bd_feed_force; physics.md §11) */
            double f = bd_feed_force(sim, vi, sim->mass[i], 1, sim->material[i] > 0.0);
            F += f;
            Fn += f;
        }
        sim->fx[i] = F;
        sim->fnx[i] = Fn;
        mn->gw[i] = G;
        sim->fny[i] = Gn;
    }
    transverse(sim);
    /* the supports' forces, the rolling resistance they bring, and the
     * force across that gives the solved ẇ⁺ (integrate.c) */
    for (int i = 0; i < n; i++) {
        if (mm->kind[i] == BD_MN_ARC) {
            sim->fy[i] = 0.0;
            continue;
        }
        double m = sim->mass[i] - mm->idler_mass[i];
        double Ftot = m * (mn->wdn[i] - wd[i]) / dt;
        sim->fy[i] = Ftot;
        if (mm->kind[i] != BD_MN_IDLER)
            continue;
        double N = mn->pin[i] != 0.0 ? Ftot - mn->gw[i] - coriolis_force(sim, i) : 0.0;
        mn->normal[i] = N;
        sim->fny[i] += N;
        /* rolling resistance against the belt's motion (seed 004 §5;
         * faded below BD_ROLLING_SPEED) */
        double sat = bd_coulomb_share(v[i], BD_ROLLING_SPEED);
        double r = -mm->rolling[i] * N * sat;
        sim->fx[i] += r;
        sim->fnx[i] += r;
    }
}
