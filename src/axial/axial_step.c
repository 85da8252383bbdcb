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
#include "sim/system.h"

#include <math.h>


static void element_pass(bd_sim *sim)
{
    const int n = sim->n;
    const double *u = sim->ax.u, *v = sim->vx, *gap = sim->ax.gap, *rate = sim->ax.gap_rate;
    const double *k = sim->ax.k, *c = sim->ax.c;
    double *f = sim->fx, *fn = sim->fnx, *tension = sim->tension;
    bd_extremes ext = {-INFINITY, INFINITY, 0.0, 0, 0};
    for (int e = 0; e < n; e++) {
        int j = e + 1 == n ? 0 : e + 1;
        double Td = c[e] * (rate[e] + v[j] - v[e]);
        double T = k[e] * (gap[e] + u[j] - u[e]) + Td;
        tension[e] = T;
        bd_extremes_add(&ext, T, e);
        f[e] += T;
        f[j] -= T;
        fn[e] += Td;
        fn[j] -= Td;
    }
    bd_extremes_store(sim, &ext);
}

/* the seed-004 law at pulley p, implicit in the pulley's and the belt
 * node's velocities at the end of the step */
static void pulley_law(bd_sim *sim, bd_pulley_body *p)
{
    const int n = sim->n, i = p->node;
    const double dt = sim->dt, R = p->radius;
    int e_in = i == 0 ? n - 1 : i - 1;
    double T_in = sim->tension[e_in], T_out = sim->tension[i];
    double Q = bd_pulley_external_torque(sim, p);
    double F = 0.0;
    if (!sim->friction_off) {
        double m = sim->mass[i];
        double v_free = sim->vx[i] + dt * sim->fx[i] / m - R * (p->omega + dt * Q / p->inertia);
        double kappa = dt * (1.0 / m + R * R / p->inertia);
        F = bd_bpl_solve(&p->law, T_in, T_out, sim->vx[i], v_free, kappa);
    }
    sim->fx[i] += F;
    sim->fnx[i] += F;
    p->belt_force = F;
    p->torque_friction = -R * F;
    p->torque_external = Q;
    p->alpha = (Q - R * F) / p->inertia;
    /* recorded here, said after the run (bd_sim_report_events) */
    if ((T_in <= 0.0 || T_out <= 0.0) && !p->slack_warned && !sim->friction_off) {
        p->slack_warned = 1;
        p->slack_t = sim->t;
        p->slack_arriving = T_in <= 0.0;
        p->slack_tension = T_in <= 0.0 ? T_in : T_out;
    }
    if (p->movable) {
        /* the belt's pull on the carriage along its axis, and its dashpot part */
        int j = i + 1 == n ? 0 : i + 1;
        double Td_in = sim->ax.c[e_in] * (sim->ax.gap_rate[e_in] + sim->vx[i] - sim->vx[e_in]);
        double Td_out = sim->ax.c[i] * (sim->ax.gap_rate[i] + sim->vx[j] - sim->vx[i]);
        p->f_axis = T_out * p->c_out - T_in * p->c_in + p->wrap_pull;
        p->fnc_axis = Td_out * p->c_out - Td_in * p->c_in;
    }
}

int bd_axial_forces(bd_sim *sim)
{
    const int n = sim->n;
    const double *fc = sim->ax.f_const, *res = sim->ax.resist, *v = sim->vx;
    double *f = sim->fx, *fn = sim->fnx;
    for (int i = 0; i < n; i++) {
        double sat = v[i] / BD_AXIAL_ROLLING_SPEED;
        sat = sat > 1.0 ? 1.0 : (sat < -1.0 ? -1.0 : sat);
        double r = -res[i] * sat;
        f[i] = fc[i] + r;
        fn[i] = r;
    }
    element_pass(sim);
    if (bd_check_elements(sim))
        return 1;
    int fd = sim->ax.feed_node;
    if (fd >= 0 && sim->has_feed && v[fd] > 0.0) {
        double F = -sim->material_mpl * v[fd] * v[fd];
        f[fd] += F;
        fn[fd] += F;
    }
    for (int p = 0; p < sim->pulley_count; p++)
        pulley_law(sim, &sim->pulleys[p]);
    return 0;
}

/* a takeup moved by dq: its two elements change length (and rate) */
static void takeup_geometry(bd_sim *sim)
{
    const int n = sim->n;
    bd_axial *ax = &sim->ax;
    for (int p = 0; p < sim->pulley_count; p++) {
        const bd_pulley_body *pb = &sim->pulleys[p];
        if (pb->movable) {
            int i = pb->node, e_in = i == 0 ? n - 1 : i - 1;
            ax->gap_rate[e_in] = 0.0;
            ax->gap_rate[i] = 0.0;
        }
    }
    for (int p = 0; p < sim->pulley_count; p++) {
        const bd_pulley_body *pb = &sim->pulleys[p];
        if (!pb->movable)
            continue;
        int i = pb->node, e_in = i == 0 ? n - 1 : i - 1;
        double dq = pb->q - pb->q_step_start;
        ax->gap[e_in] += pb->c_in * dq;
        ax->gap[i] -= pb->c_out * dq;
        ax->gap_rate[e_in] += pb->c_in * pb->qdot;
        ax->gap_rate[i] -= pb->c_out * pb->qdot;
        sim->x[i] += dq * pb->axis[0];
        sim->y[i] += dq * pb->axis[1];
    }
}

/* the element holding path point s, searched from *e; and the node whose
 * half elements hold it */
static int front_node(const bd_sim *sim, double s, int *e)
{
    const int n = sim->n;
    const double L = sim->path.length, *s0 = sim->s_node0, *len = sim->ax.s_len;
    for (int it = 0; it < n; it++) {
        double rel = s - s0[*e];
        rel -= L * floor(rel / L + 0.5);   /* into [−L/2, L/2) */
        if (rel < 0.0)
            *e = *e == 0 ? n - 1 : *e - 1;
        else if (rel >= len[*e])
            *e = *e + 1 == n ? 0 : *e + 1;
        else
            return rel < 0.5 * len[*e] ? *e : (*e + 1 == n ? 0 : *e + 1);
    }
    return *e;
}

/* a node's load after a front moved in it; the material that arrives rides
 * in at belt speed (the node's velocity stays) and brings its kinetic
 * energy ½Δm·v² and the change −ΔW·u of the gravity potential, booked as
 * input; material that leaves takes them away, booked as dissipated */
static void reload_node(bd_sim *sim, int i)
{
    double m0 = sim->material[i], w0 = sim->ax.f_const[i];
    bd_axial_node_load(sim, i);
    double dm = sim->material[i] - m0, dw = sim->ax.f_const[i] - w0;
    double de = 0.5 * dm * sim->vx[i] * sim->vx[i] - dw * sim->ax.u[i];
    if (dm >= 0.0)
        sim->energy.input += de;
    else
        sim->energy.dissipated -= de;
}

/* a free front moves with the belt, ds/dt = v interpolated between the
 * nodes of its element, within [lo, hi] from the feed point; the nodes it
 * passed through get their new load (at most two: a step crosses at most
 * one station). Returns 1 when it reached hi. */
static int move_front(bd_sim *sim, double *d, int *e, double lo, double hi)
{
    const int n = sim->n;
    const double L = sim->path.length, s_feed = sim->ax.s_feed;
    int k0 = front_node(sim, s_feed + *d, e);
    int j = *e + 1 == n ? 0 : *e + 1;
    double rel = s_feed + *d - sim->s_node0[*e];
    rel -= L * floor(rel / L);
    double g = rel / sim->ax.s_len[*e];
    double v = (1.0 - g) * sim->vx[*e] + g * sim->vx[j];
    double d_new = *d + v * sim->dt;
    d_new = d_new < lo ? lo : (d_new > hi ? hi : d_new);
    if (d_new == *d)
        return d_new >= hi;
    *d = d_new;
    int k1 = front_node(sim, s_feed + *d, e);
    /* walk from the node behind to the one ahead */
    int from = v >= 0.0 ? k0 : k1, to = v >= 0.0 ? k1 : k0;
    for (int i = from;; i = i + 1 == n ? 0 : i + 1) {
        reload_node(sim, i);
        if (i == to)
            break;
    }
    return d_new >= hi;
}

/* the load fronts (docs/physics.md §11): the head rides with the belt until
 * it reaches the discharge pulley, the tail once feeding has stopped */
static void move_load_fronts(bd_sim *sim)
{
    bd_axial *ax = &sim->ax;
    if (ax->head_free && move_front(sim, &ax->d_head, &ax->e_head, ax->d_tail, ax->load_len))
        ax->head_free = 0;
    if (ax->tail_free)
        move_front(sim, &ax->d_tail, &ax->e_tail, 0.0, ax->d_head);
}

int bd_axial_step(bd_sim *sim)
{
    const double dt = sim->dt;
    bd_energy *en = &sim->energy;
    if (sim->want_energy)
        en->potential = bd_axial_potential(sim);
    if (bd_axial_forces(sim))
        return 1;
    /* nodes: velocities to t + Δt/2, displacements to t + Δt */
    const int n = sim->n;
    double *u = sim->ax.u, *v = sim->vx;
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
    w_nc *= dt;
    ke *= 0.5;
    bd_pulleys_advance(sim, &ke, &w_nc);
    takeup_geometry(sim);
    en->dissipated -= w_nc;
    en->kinetic = ke;
    if (ke > en->max_kinetic)
        en->max_kinetic = ke;
    if (sim->material_mpl > 0.0)
        move_load_fronts(sim);
    sim->t += dt;
    sim->steps++;
    return 0;
}

/* ½·k·(stretch)² of every element */
double bd_axial_elastic_energy(const bd_sim *sim)
{
    const int n = sim->n;
    const double *u = sim->ax.u, *gap = sim->ax.gap, *k = sim->ax.k;
    double e = 0.0;
    for (int i = 0; i < n; i++) {
        int j = i + 1 == n ? 0 : i + 1;
        double d = gap[i] + u[j] - u[i];
        e += 0.5 * k[i] * d * d;
    }
    return e;
}

/* elastic energy, the potential −W_i·u_i of the weights along the path,
 * the pulleys' weight and the takeup pulls (−F·q, the wrapped belt's
 * weight included) */
double bd_axial_potential(const bd_sim *sim)
{
    double e = bd_axial_elastic_energy(sim);
    for (int i = 0; i < sim->n; i++)
        e -= sim->ax.f_const[i] * sim->ax.u[i];
    for (int i = 0; i < sim->pulley_count; i++) {
        const bd_pulley_body *p = &sim->pulleys[i];
        e += p->def->mass * sim->gravity * p->cy;
        if (p->movable)
            e -= (bd_takeup_force(sim, p, sim->t) + p->wrap_pull) * p->q;
    }
    return e + bd_transmissions_potential(sim);
}
