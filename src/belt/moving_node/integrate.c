/* The moving-node belt: the step's update, the material flowing through
 * the nodes, the load fronts, and the energies (docs/physics.md §14). */
#include "belt/moving_node/moving_node.h"

#include <math.h>

/* Nodes to t + Δt. Along the path the solve gave v⁺; the belt passes
 * node i at v⁺_i/λ_i of unstretched length per second (seed 003 eq 2, the
 * stretch λ = 1 + ε of the element it comes from: upwind), which moves
 * ΔX from element to element (ΣΔX is kept exactly). Across a span:
 * explicit central differences. The kinetic energy is booked at mid step
 * as the other belts do, the gravity work on the flowing belt with v⁺
 * (the displacement of the step), so that −(its sum) is the potential of
 * the weights at t. */
void bd_mn_integrate(bd_sim *sim, double *ke_out, double *w_nc_out)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n;
    const double dt = sim->model->dt;
    double *v = sim->vx, *wd = sim->vy, *w = mn->w, *dX = mn->dX;
    const double *vn = mn->vnew;
    double ke = 0.0, w_nc = 0.0, grav = 0.0;
    for (int i = 0; i < n; i++) {
        double mid = 0.5 * (v[i] + vn[i]);
        ke += sim->mass[i] * mid * mid;
        w_nc += sim->fnx[i] * mid;
        grav += mn->f_grav[i] * vn[i];
    }
    /* the flux through each node, with the strains at t. Upwind is the
     * energy-conserving flux, v/λ̄ with λ̄ the mean stretch of the two
     * elements (for T = EA·ε it makes the nodes' power Σ v·ΔT equal the
     * elastic energy's rate exactly), plus a numerical diffusion; its
     * dissipation |v|·ΔT·Δε/(2λ_up) per node is booked (without it a
     * start from an untensioned belt lost 1.1 kJ in 25 s unbooked) */
    double *flux = mn->cp;   /* scratch after the solve */
    const double EA = sim->model->EA;
    double d_up = 0.0;
    for (int i = 0; i < n; i++) {
        int b = bd_node_prev(i, n), up = vn[i] >= 0.0 ? b : i;
        double lam = mn->len[up] / dX[up];
        flux[i] = dt * vn[i] / lam;
        double de = mn->len[i] / dX[i] - mn->len[b] / dX[b];
        d_up += fabs(vn[i]) * EA * de * de / (2.0 * lam);
    }
    sim->energy.dissipated += d_up * dt;
    for (int e = 0; e < n; e++)
        dX[e] += flux[e] - flux[bd_node_next(e, n)];
    for (int i = 0; i < n; i++) {
        mn->vold[i] = v[i];   /* the four-level rule's (solve.c) */
        v[i] = vn[i];
    }
    /* across the spans */
    for (int i = 0; i < n; i++) {
        if (mm->kind[i] == BD_MN_ARC)
            continue;
        double m = sim->mass[i] - mm->idler_mass[i];
        double a = sim->fy[i] * dt / m, mid = wd[i] + 0.5 * a;
        ke += m * mid * mid;
        w_nc += sim->fny[i] * mid;
        grav += mn->f_norm[i] * (wd[i] + a);
        wd[i] += a;
        w[i] += wd[i] * dt;
        if (mm->kind[i] != BD_MN_IDLER)
            continue;
        if (w[i] < 0.0)
            w[i] = 0.0;   /* the support put it there: rounding only */
        else if (w[i] > BD_LIFT_OFF_CLEARANCE && !sim->stabilizing) {
            /* lifted off its idler (recorded, said after the run) */
            bd_lift_off_note(sim, sim->model->s_node0[i]);
        }
    }
    mn->grav_work += grav * dt;
    *ke_out = 0.5 * ke;
    *w_nc_out = w_nc * dt;
}

/* the speeds set from outside (at rest, sim/step.c; zeroed, stabilize.c):
 * the wraps' four-level rule (solve.c) restarts its history from them, as
 * at the first step (Δv⁻⁻ = Δv⁻), instead of taking a jump from the speeds
 * before the reset for a motion */
void bd_mn_rest_velocities(bd_sim *sim, double h)
{
    (void)h;
    bd_mn *mn = bd_mn_of(sim);
    for (int i = 0; i < sim->model->n; i++)
        mn->vold[i] = sim->vx[i];
}

/* where the nodes are after the carriages moved: on a carriage or a
 * stretch that follows it, and across the span by w */
void bd_mn_takeup_geometry(bd_sim *sim)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    bd_mn *mn = bd_mn_of(sim);
    for (int p = 0; p < sim->model->pulley_count; p++)
        if (sim->pulleys[p].m->movable)
            mn->q_seen[p] += sim->pulleys[p].q - sim->pulleys[p].q_step_start;
    for (int i = 0; i < sim->model->n; i++) {
        double x = mm->x0[i], y = mm->y0[i];
        if (mm->mover[i] >= 0) {
            double q = mn->q_seen[mm->mover[i]];
            x += mm->mx[i] * q;
            y += mm->my[i] * q;
        }
        if (mm->kind[i] != BD_MN_ARC) {
            x += mn->w[i] * mm->nx[i];
            y += mn->w[i] * mm->ny[i];
        }
        sim->x[i] = x;
        sim->y[i] = y;
    }
}

/* ½·EA·ε²·ΔX of every element, and ½·EI·κ²·h of every span node */
double bd_mn_elastic_energy(const bd_sim *sim)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    const bd_mn *mn = bd_mn_of(sim);
    const int n = sim->model->n;
    const double EA = sim->model->EA, EI = sim->model->EI;
    double e = 0.0;
    for (int k = 0; k < n; k++) {
        double cs, sn;
        double eps = bd_mn_element_length(mm, mn, k, n, &cs, &sn) / mn->dX[k] - 1.0;
        e += 0.5 * EA * eps * eps * mn->dX[k];
    }
    if (EI > 0.0)
        for (int i = 0; i < n; i++) {
            if (mm->kind[i] == BD_MN_ARC)
                continue;
            int b = bd_node_prev(i, n), j = bd_node_next(i, n);
            double la = mm->ds0[b], lb = mm->ds0[i], h = 0.5 * (la + lb);
            double kap = ((mn->w[j] - mn->w[i]) / lb - (mn->w[i] - mn->w[b]) / la) / h;
            e += 0.5 * EI * kap * kap * h;   /* κ as forces.c's bending() */
        }
    return e;
}

/* elastic energy, and the weights' potential as the work they did on the
 * flowing belt so far (its change is −W·v per step; the pulleys' weight
 * and the takeup pulls, the moving nodes' weight with them through
 * wrap_pull, are the parts': sim/energy.c) */
double bd_mn_potential(const bd_sim *sim)
{
    return bd_mn_elastic_energy(sim) - bd_mn_of(sim)->grav_work;
}

/* a node's load after a front moved through its cell: material arriving
 * at belt speed brings ½Δm·v² (input), leaving takes it (dissipated) */
static void reload(bd_sim *sim, int i)
{
    double m0 = sim->material[i];
    bd_mn_node_load(sim, i);
    double de = 0.5 * (sim->material[i] - m0) * sim->vx[i] * sim->vx[i];
    if (de >= 0.0)
        sim->energy.input += de;
    else
        sim->energy.dissipated -= de;
}

/* the load fronts ride with the belt (belt/load_fronts.c) */
void bd_mn_material(bd_sim *sim)
{
    bd_fronts_move(sim, &bd_mn_of(sim)->fronts, bd_mn_model_of(sim)->ds0, reload);
}
