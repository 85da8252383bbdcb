/* The axial (1D) belt: forces and one explicit step (docs/physics.md §11).
 *
 * Element e (node e → e+1), Kelvin–Voigt (seed 001 eqs 4.1, 4.3 along the
 * path):
 *   T_e = k_e·(g_e + u_{e+1} − u_e) + c_e·(ġ_e + v_{e+1} − v_e),
 * g_e = l − l0 at u = 0, which a takeup's travel q changes by q·(u_in·a) on
 * the element arriving at its pulley and by −q·(u_out·a) on the one leaving.
 * Node i: m_i·v̇_i = T_i − T_{i−1} + W_i − R_i·sat(v_i/v_0) [+ feed] [+ F_p],
 * W_i the weight along the path, R_i the idlers' rolling resistance, the
 * feed force −m'_L·v² at the feed point (material accelerated to belt
 * speed), and at a pulley node the pulley's friction F_p from the seed-004
 * law (contact/belt_pulley_law.c) with T_in = T_{i−1}, T_out = T_i, taken
 * implicitly together with the pulley's rotation:
 *   I·ω̇ = Q − R·F_p,    Q = drive (or transmission) + bearing −b·ω.
 * Central differences as for the discrete belt (step.c). */
#include "belt/axial/axial.h"

#include <math.h>

#include "parts/parts.h"

/* elements 0 .. count−1 of the node arrays u, v (element e from node e
 * to e + 1): tension and its dashpot part; no node written */
static void elements(int count, const double *restrict u, const double *restrict v,
                     const double *restrict k, const double *restrict c,
                     const double *restrict gap, const double *restrict rate,
                     double *restrict td, double *restrict tension)
{
    for (int e = 0; e < count; e++) {
        double Td = c[e] * (rate[e] + v[e + 1] - v[e]);
        td[e] = Td;
        tension[e] = k[e] * (gap[e] + u[e + 1] - u[e]) + Td;
    }
}

/* the element pass: elements 0 .. n−2, then the one that closes the loop
 * from a copy of its two nodes */
static void element_pass(bd_sim *sim)
{
    const bd_axial *ax = bd_axial_of(sim);
    const int n = sim->model->n, z = n - 1;
    const double *u = ax->u, *v = sim->vx;
    const bd_axial_model *am = bd_axial_model_of(sim);
    elements(z, u, v, am->k, am->c, ax->gap, ax->gap_rate, ax->td, sim->tension);
    double cu[2] = {u[z], u[0]}, cv[2] = {v[z], v[0]};
    elements(1, cu, cv, am->k + z, am->c + z, ax->gap + z, ax->gap_rate + z, ax->td + z,
             sim->tension + z);
}

/* rolling resistance on node i at speed v, smoothed through zero */
static inline double rolling(double resist, double v)
{
    double sat = bd_coulomb_share(v, BD_ROLLING_SPEED);
    return -resist * sat;
}

/* the node pass: weight along the path and rolling resistance, element i
 * pulling forward and element i − 1 back; the sums in the order the
 * element-by-element scatter added them (element i − 1 first, except at
 * node 0), so the result is the same to the bit */
static void nodes(int n, const double *restrict fc, const double *restrict res,
                  const double *restrict v, const double *restrict T,
                  const double *restrict td, double *restrict f, double *restrict fn)
{
    double r = rolling(res[0], v[0]);
    f[0] = ((fc[0] + r) + T[0]) - T[n - 1];
    fn[0] = (r + td[0]) - td[n - 1];
    for (int i = 1; i < n; i++) {
        r = rolling(res[i], v[i]);
        f[i] = ((fc[i] + r) - T[i - 1]) + T[i];
        fn[i] = (r - td[i - 1]) + td[i];
    }
}

/* where the path turns the idlers' load follows the tension too (build.c
 * curve_turn): N_i + kn·T at the node's mean tension, R_i + kr·T its
 * rolling resistance. A node whose load would be negative is lifted (none,
 * noted as lift-off); the 2D belt then spans it straight and the turn it
 * would have taken is taken at the idlers next to it, so the idlers of
 * the turns carry what the tension adds over them in all, Σ kn·T, no
 * more: the loads left are scaled down by the lifted nodes' deficit
 * (derived here: the belt's vertical balance over the curve, whose
 * corners and arc turn it back to its line). */
static void curve_pass(bd_sim *sim)
{
    const bd_axial *ax = bd_axial_of(sim);
    const bd_axial_model *am = bd_axial_model_of(sim);
    const int n = sim->model->n;
    double carried = 0.0, deficit = 0.0;
    for (int c = 0; c < am->curve_count; c++) {
        int i = am->curve_node[c], b = bd_node_prev(i, n);
        double N = ax->normal[i] + am->curve_kn[c] * 0.5 * (sim->tension[b] + sim->tension[i]);
        if (N >= 0.0)
            carried += N;
        else
            deficit -= N;
    }
    double scale = carried > deficit ? (carried - deficit) / carried : 0.0;
    for (int c = 0; c < am->curve_count; c++) {
        int i = am->curve_node[c], b = bd_node_prev(i, n);
        double T = 0.5 * (sim->tension[b] + sim->tension[i]);
        double R = (ax->resist[i] + am->curve_kr[c] * T) * scale;
        if (ax->normal[i] + am->curve_kn[c] * T < 0.0) {
            R = 0.0;
            if (!sim->stabilizing)
                bd_lift_off_note(sim, sim->model->s_node0[i]);
        }
        double d = rolling(R, sim->vx[i]) - rolling(ax->resist[i], sim->vx[i]);
        sim->fx[i] += d;
        sim->fnx[i] += d;
    }
}

static void node_pass(bd_sim *sim)
{
    const bd_axial *ax = bd_axial_of(sim);
    nodes(sim->model->n, ax->f_const, ax->resist, sim->vx, sim->tension, ax->td, sim->fx, sim->fnx);
    curve_pass(sim);
}

/* the wrap coupling: the seed-004 law at pulley p, implicit in the
 * pulley's and the belt node's velocities at the end of the step */
void bd_axial_wrap(bd_sim *sim, bd_pulley_body *p, double Q)
{
    const bd_axial *ax = bd_axial_of(sim);
    const int ip = (int)(p - sim->pulleys);
    const bd_axial_model *am = bd_axial_model_of(sim);
    const bd_axial_pulley *ap = &am->pulleys[ip];
    bd_axial_pulley_state *as = &bd_axial_of(sim)->pulleys[ip];
    const int n = sim->model->n, i = ap->node;
    const double dt = sim->model->dt, R = p->m->radius;
    int e_in = i == 0 ? n - 1 : i - 1;
    double T_in = sim->tension[e_in], T_out = sim->tension[i];
    /* a held pulley (p->held: stabilization's holdback) does not turn: an
     * infinite inertia; a drive's implicit gain adds to a turning one's */
    double m = sim->mass[i], I, F;
    /* solved again, once, when a drive would pass its max_torque */
    do {
        I = bd_pulley_solve_inertia(sim, p);
        double w_free = p->held ? p->omega : p->omega + dt * Q / I;
        double v_free = sim->vx[i] + dt * sim->fx[i] / m - R * w_free;
        double kappa = dt * (1.0 / m + (p->held ? 0.0 : R * R / I));
        F = bd_bpl_solve(&ap->law, T_in, T_out, sim->vx[i], v_free, kappa);
    } while (!p->held && bd_pulley_drive_clip(sim, p, (Q - R * F) / I, &Q));
    sim->fx[i] += F;
    sim->fnx[i] += F;
    p->torque_friction = -R * F;
    p->alpha = p->held ? 0.0 : (Q - R * F) / I;
    /* recorded here, said after the run (bd_axial_report_events) */
    if ((T_in <= 0.0 || T_out <= 0.0) && !as->slack_warned && !sim->stabilizing) {
        as->slack_warned = 1;
        as->slack_t = sim->t;
        as->slack_arriving = T_in <= 0.0;
        as->slack_tension = T_in <= 0.0 ? T_in : T_out;
    }
    if (p->m->movable) {
        /* the belt's pull on the carriage along its axis, and its dashpot part */
        int j = i + 1 == n ? 0 : i + 1;
        double Td_in = am->c[e_in] * (ax->gap_rate[e_in] + sim->vx[i] - sim->vx[e_in]);
        double Td_out = am->c[i] * (ax->gap_rate[i] + sim->vx[j] - sim->vx[i]);
        p->f_axis = T_out * ap->c_out - T_in * ap->c_in + p->m->wrap_pull;
        p->fnc_axis = Td_out * ap->c_out - Td_in * ap->c_in;
    }
}

void bd_axial_forces(bd_sim *sim)
{
    element_pass(sim);
    node_pass(sim);
    bd_tension_extremes(sim);
    /* the feed point accelerates the material landing on it to belt speed
     * (and its skirts rub, belt.h bd_feed_force) */
    int fd = bd_axial_model_of(sim)->feed_node;
    if (fd >= 0) {
        double F = bd_feed_force(sim, sim->vx[fd], sim->mass[fd], 1, sim->material[fd] > 0.0);
        if (F != 0.0) {
            sim->fx[fd] += F;
            sim->fnx[fd] += F;
        }
    }
}

/* a takeup moved by dq: its two elements change length (and rate) */
void bd_axial_takeup_geometry(bd_sim *sim)
{
    const int n = sim->model->n;
    bd_axial *ax = bd_axial_of(sim);
    for (int p = 0; p < sim->model->pulley_count; p++) {
        if (sim->pulleys[p].m->movable) {
            int i = bd_axial_model_of(sim)->pulleys[p].node, e_in = i == 0 ? n - 1 : i - 1;
            ax->gap_rate[e_in] = 0.0;
            ax->gap_rate[i] = 0.0;
        }
    }
    for (int p = 0; p < sim->model->pulley_count; p++) {
        const bd_pulley_body *pb = &sim->pulleys[p];
        const bd_axial_pulley *ap = &bd_axial_model_of(sim)->pulleys[p];
        if (!pb->m->movable)
            continue;
        int i = ap->node, e_in = i == 0 ? n - 1 : i - 1;
        double dq = pb->q - pb->q_step_start;
        ax->gap[e_in] += ap->c_in * dq;
        ax->gap[i] -= ap->c_out * dq;
        ax->gap_rate[e_in] += ap->c_in * pb->qdot;
        ax->gap_rate[i] -= ap->c_out * pb->qdot;
        sim->x[i] += dq * pb->m->axis[0];
        sim->y[i] += dq * pb->m->axis[1];
    }
}

/* a node's load after a front moved in it; the material that arrives rides
 * in at belt speed (the node's velocity stays) and brings its kinetic
 * energy ½Δm·v² and the change −ΔW·u of the gravity potential, booked as
 * input; material that leaves takes them away, booked as dissipated */
static void reload_node(bd_sim *sim, int i)
{
    double m0 = sim->material[i], w0 = bd_axial_of(sim)->f_const[i];
    bd_axial_node_load(sim, i);
    double dm = sim->material[i] - m0, dw = bd_axial_of(sim)->f_const[i] - w0;
    double de = 0.5 * dm * sim->vx[i] * sim->vx[i] - dw * bd_axial_of(sim)->u[i];
    if (dm >= 0.0)
        sim->energy.input += de;
    else
        sim->energy.dissipated -= de;
}

/* the load fronts ride with the belt (belt/load_fronts.c) */
void bd_axial_material(bd_sim *sim)
{
    bd_fronts_move(sim, &bd_axial_of(sim)->fronts, bd_axial_model_of(sim)->s_len, reload_node);
}

/* nodes: velocities to t + Δt/2, displacements to t + Δt, with the
 * mid-step bookkeeping of the lumped belt (belt/lumped/forces.c) */
void bd_axial_integrate(bd_sim *sim, double *ke_out, double *w_nc_out)
{
    const double dt = sim->model->dt;
    const int n = sim->model->n;
    double *u = bd_axial_of(sim)->u, *v = sim->vx;
    const double *f = sim->fx, *fn = sim->fnx, *mass = sim->mass;
    double w_nc = 0.0, ke = 0.0;
    for (int i = 0; i < n; i++) {
        double a = f[i] * dt / mass[i];
        double mid = v[i] + 0.5 * a;
        w_nc += fn[i] * mid;
        ke += mass[i] * mid * mid;
        v[i] += a;
        u[i] += v[i] * dt;
    }
    *w_nc_out = w_nc * dt;
    *ke_out = ke * 0.5;
}

/* ½·k·(stretch)² of every element */
double bd_axial_elastic_energy(const bd_sim *sim)
{
    const int n = sim->model->n;
    const double *u = bd_axial_of(sim)->u, *gap = bd_axial_of(sim)->gap,
                 *k = bd_axial_model_of(sim)->k;
    double e = 0.0;
    for (int i = 0; i < n; i++) {
        int j = i + 1 == n ? 0 : i + 1;
        double d = gap[i] + u[j] - u[i];
        e += 0.5 * k[i] * d * d;
    }
    return e;
}

/* elastic energy and the potential −W_i·u_i of the weights along the
 * path; the pulleys' weight and the takeup pulls (−F·q, the wrapped belt's
 * weight included through wrap_pull) are the parts' (sim/energy.c) */
double bd_axial_potential(const bd_sim *sim)
{
    const bd_axial *ax = bd_axial_of(sim);
    double e = bd_axial_elastic_energy(sim);
    for (int i = 0; i < sim->model->n; i++)
        e -= ax->f_const[i] * ax->u[i];
    return e;
}

/* recorded in the step (bd_axial_wrap), said after the run */
void bd_axial_report_events(bd_sim *sim)
{
    for (int i = 0; i < sim->model->pulley_count; i++) {
        const bd_axial_pulley_state *ap = &bd_axial_of(sim)->pulleys[i];
        if (ap->slack_warned)
            bd_sim_warn(sim, "pulley '%s': a belt end lost its tension at t = %.3f s (%s side, "
                        "%.0f N); the belt-pulley law (seed 004) holds only while both ends "
                        "are in tension", sim->pulleys[i].m->def->name, ap->slack_t,
                        ap->slack_arriving ? "arriving" : "leaving", ap->slack_tension);
    }
}

static double element_s(const bd_sim *sim, int e)
{
    return bd_station_element_s(sim, e, bd_axial_model_of(sim)->s_len);
}

/* the elements differ in l0; the tension says the strain */
static double element_strain(const bd_sim *sim, int e)
{
    return sim->tension[e] / sim->model->EA;
}

const bd_belt_ops bd_axial_ops = {
    .name = "axial",
    .description = "axial (1D belt, seed-004 pulleys)",
    .node_dof = 1,
    .dof_text = "1 per node, 1 per pulley, 1 per moving takeup; idlers are distributed",
    .build = bd_axial_build,
    .free = bd_axial_free,
    .free_model = bd_axial_free_model,
    .clone = bd_axial_clone,
    .stable_step = bd_axial_stable_step,
    .estimate = bd_axial_estimate,
    .forces = bd_axial_forces,
    .wrap = bd_axial_wrap,
    .supports = NULL,
    .integrate = bd_axial_integrate,
    .after_parts = bd_axial_takeup_geometry,
    .material = bd_axial_material,
    .potential = bd_axial_potential,
    .elastic_energy = bd_axial_elastic_energy,
    .wrap_energy = bd_station_wrap_energy,
    .support_inertia = bd_station_support_inertia,
    .point_init = bd_axial_point_init,
    .point_update = bd_station_point_update,
    .sample = bd_station_sample,
    .element_s = element_s,
    .element_speed = bd_station_element_speed,
    .element_strain = element_strain,
    .node_speed = bd_station_node_speed,
    .report_events = bd_axial_report_events,
    /* it notes a curve's nodes lifted by T/R (curve_pass) */
    .records_lift_off = 1,
};
