/* One time step of the explicit central-difference scheme (seed 001 eqs
 * 4.58–4.60, 4.62, 4.64–4.65, 4.67, 4.69): forces at t from positions at t
 * and velocities at t − Δt/2, then velocities to t + Δt/2 and positions to
 * t + Δt. Energy is booked with mid-step velocities v(t) = (v⁻ + v⁺)/2, for
 * which the scheme's kinetic-energy change is exactly Σ F·v(t)·Δt. */
#include "sim/system.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* strain beyond which an element is taken as diverged, and the shortening
 * at which it counts as reversed */
#define DIVERGED_STRAIN 1.0
#define REVERSED_STRAIN (-0.9)

/* material: lands at the feed point with no velocity along the belt (the
 * belt's momentum is shared: v' = m·v/(m + Δm)), leaves at the discharge
 * pulley with the belt's velocity (model-format.md `material`) */
static void material_transport(bd_sim *sim)
{
    bd_tracker *fd = &sim->feed;
    bd_tracker_update(sim, fd);
    if (sim->has_feed) {
        int e = fd->element, j = e + 1 == sim->n ? 0 : e + 1;
        double g = fd->gamma;
        double v = bd_tracker_speed(sim, fd);
        if (v > 0.0) {
            double dm = sim->material_mpl * v * sim->dt;
            int nodes[2] = {e, j};
            double share[2] = {1.0 - g, g};
            for (int k = 0; k < 2; k++) {
                int i = nodes[k];
                double add = dm * share[k];
                double m = sim->mass[i];
                double ke = 0.5 * m * (sim->vx[i] * sim->vx[i] + sim->vy[i] * sim->vy[i]);
                sim->vx[i] *= m / (m + add);
                sim->vy[i] *= m / (m + add);
                sim->mass[i] += add;
                sim->material[i] += add;
                double ke2 = 0.5 * sim->mass[i]
                           * (sim->vx[i] * sim->vx[i] + sim->vy[i] * sim->vy[i]);
                sim->energy.dissipated += ke - ke2;
                sim->energy.input += add * sim->gravity * sim->y[i];
            }
        }
    }
}

static void material_discharge(bd_sim *sim)
{
    /* nodes that entered the discharge pulley's wrap lose their load */
    const bd_pulley_body *p = &sim->pulleys[sim->discharge_pulley];
    for (int c = 0; c < p->contact_count; c++) {
        int i = p->c_node[c];
        double dm = sim->material[i];
        if (dm <= 0.0)
            continue;
        double v2 = sim->vx[i] * sim->vx[i] + sim->vy[i] * sim->vy[i];
        sim->energy.dissipated += 0.5 * dm * v2 + dm * sim->gravity * sim->y[i];
        sim->mass[i] -= dm;
        sim->material[i] = 0.0;
    }
}

/* after the element pass of either belt formulation: stop a diverged run
 * with when, where and why; keep the run's tension extremes */
int bd_check_elements(bd_sim *sim)
{
    double hi = sim->step_tension_max, lo = sim->step_tension_min;
    int ihi = sim->step_element_max, ilo = sim->step_element_min;
    if (!(sim->step_tension_sum == sim->step_tension_sum)) {
        /* a NaN: find the first element that has it (failure path only) */
        for (int e = 0; e < sim->n; e++)
            if (!(sim->tension[e] == sim->tension[e])) {
                hi = sim->tension[e];
                ihi = e;
                break;
            }
    }
    if (!(hi == hi) || !(lo == lo) || hi > DIVERGED_STRAIN * sim->EA
        || lo < REVERSED_STRAIN * sim->EA) {
        int e = (!(hi == hi) || hi > DIVERGED_STRAIN * sim->EA) ? ihi : ilo;
        /* the axial belt's elements differ in l0; its tension says the strain */
        double strain = sim->axial ? sim->tension[e] / sim->EA
                                   : (sim->len[e] - sim->l0) / sim->l0;
        snprintf(sim->fail_msg, sizeof sim->fail_msg,
                 "the simulation diverged at t = %.6f s (step %ld): %sbelt element %d at "
                 "s = %.3f m (x = %.3f, y = %.3f) has strain %.3g%s; the time step %.3g s "
                 "is too large for the forces acting, or the model is unstable",
                 sim->t, sim->steps, sim->axial ? "axial " : "", e, bd_element_s(sim, e),
                 sim->x[e], sim->y[e], strain,
                 strain < 0.0 ? " (element reversed)" : "", sim->dt);
        return 1;
    }
    if (hi > sim->tension_max) {
        sim->tension_max = hi;
        sim->tension_max_t = sim->t;
        sim->tension_max_s = bd_element_s(sim, ihi);
    }
    if (lo < sim->tension_min) {
        sim->tension_min = lo;
        sim->tension_min_t = sim->t;
        sim->tension_min_s = bd_element_s(sim, ilo);
    }
    return 0;
}

/* the drive's torque (through its transmission, if any) and the bearing's */
double bd_pulley_external_torque(bd_sim *sim, bd_pulley_body *p)
{
    double T_drive = 0.0;
    if (p->trans)
        T_drive = bd_transmission_torque(sim, p);
    else if (p->def->has_drive && !sim->friction_off)
        T_drive = bd_drive_torque(sim, p);
    p->drive_torque = T_drive;
    if (fabs(T_drive) > p->torque_max_abs)
        p->torque_max_abs = fabs(T_drive);
    p->bearing_torque = -p->bearing_damping * p->omega;
    return T_drive + p->bearing_torque;
}

/* forces at t: belt, then pulleys (normal + stick–slip), then idlers */
static int compute_forces(bd_sim *sim)
{
    if (sim->axial)
        return bd_axial_forces(sim);
    bd_belt_forces(sim);
    if (bd_check_elements(sim))
        return 1;
    for (int i = 0; i < sim->pulley_count; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        bd_pulley_contact(sim, p, bd_pulley_external_torque(sim, p));
    }
    for (int i = 0; i < sim->idler_count; i++)
        bd_idler_contact(sim, &sim->idlers[i]);
    return 0;
}

/* A run starts at rest: v(0) = 0. The scheme carries velocities at half
 * steps, so the first one it needs is v(−Δt/2) = −a(0)·Δt/2; starting from
 * v(−Δt/2) = 0 instead would give the system a spurious kinetic energy
 * ½m(a·Δt/2)² wherever the initial state is not exactly in equilibrium. */
void bd_sim_start_at_rest(bd_sim *sim)
{
    double h = 0.5 * sim->dt;
    if (compute_forces(sim))
        return;
    for (int i = 0; i < sim->n; i++) {
        sim->vx[i] = -sim->fx[i] / sim->mass[i] * h;
        sim->vy[i] = -sim->fy[i] / sim->mass[i] * h;
    }
    for (int i = 0; i < sim->pulley_count; i++)
        sim->pulleys[i].omega = -sim->pulleys[i].alpha * h;
    for (int i = 0; i < sim->idler_count; i++)
        sim->idlers[i].omega = -sim->idlers[i].alpha * h;
}

/* pulleys: rotation (eqs 4.62, 4.67), their transmissions, and takeup
 * carriages (4.64–4.65) */
void bd_pulleys_advance(bd_sim *sim, double *ke, double *w_nc)
{
    const double dt = sim->dt;
    bd_energy *en = &sim->energy;
    for (int i = 0; i < sim->pulley_count; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        double w_mid = p->omega + 0.5 * p->alpha * dt;
        *ke += 0.5 * p->inertia * w_mid * w_mid;
        *w_nc += (p->torque_friction + p->bearing_torque) * w_mid * dt;
        double w_old = p->omega;
        p->omega += p->alpha * dt;
        if (p->trans)
            bd_transmission_advance(sim, p, w_old, ke, w_nc);
        else
            en->input += p->drive_torque * w_mid * dt;
        if (p->movable) {
            double qdot_old = p->qdot;
            p->q_step_start = p->q;
            *w_nc += bd_takeup_advance(sim, p, &en->input);
            double qm = 0.5 * (qdot_old + p->qdot);
            *ke += 0.5 * p->carriage_mass * qm * qm;
        }
    }
}

/* one step; returns 0 or 1 (failed, message in sim->fail_msg) */
int bd_step_once(bd_sim *sim)
{
    if (sim->axial)
        return bd_axial_step(sim);
    const double dt = sim->dt;
    bd_energy *en = &sim->energy;

    /* potential energy at t (positions before the update) when asked */
    if (sim->want_energy)
        en->potential = bd_energy_potential(sim);
    if (compute_forces(sim))
        return 1;

    /* nodes: velocities to t + Δt/2, positions to t + Δt */
    double w_nc = 0.0, ke = 0.0;
    const int n = sim->n;
    double *x = sim->x, *y = sim->y, *vx = sim->vx, *vy = sim->vy;
    const double *fx = sim->fx, *fy = sim->fy, *fnx = sim->fnx, *fny = sim->fny;
    const double *mass = sim->mass;
    for (int i = 0; i < n; i++) {
        double inv = dt / mass[i];
        double ax = fx[i] * inv, ay = fy[i] * inv;
        double mx = vx[i] + 0.5 * ax, my = vy[i] + 0.5 * ay;
        w_nc += fnx[i] * mx + fny[i] * my;
        ke += mass[i] * (mx * mx + my * my);
        vx[i] += ax;
        vy[i] += ay;
        x[i] += vx[i] * dt;
        y[i] += vy[i] * dt;
    }
    w_nc *= dt;
    ke *= 0.5;

    bd_pulleys_advance(sim, &ke, &w_nc);
    /* idlers (eq 4.69) */
    for (int i = 0; i < sim->idler_count; i++) {
        bd_idler *id = &sim->idlers[i];
        double w_mid = id->omega + 0.5 * id->alpha * dt;
        ke += 0.5 * id->inertia * w_mid * w_mid;
        w_nc += id->torque * w_mid * dt;
        id->omega += id->alpha * dt;
    }
    en->dissipated -= w_nc;
    en->kinetic = ke;
    if (ke > en->max_kinetic)
        en->max_kinetic = ke;

    if (sim->material_mpl > 0.0) {
        material_transport(sim);
        material_discharge(sim);
    }
    for (int i = 0; i < sim->probe_count; i++)
        bd_tracker_update(sim, &sim->probes[i].tr);
    sim->t += dt;
    for (int i = 0; i < sim->pulley_count; i++)
        if (sim->pulleys[i].def->has_drive)
            bd_monitor_update(sim, &sim->pulleys[i]);
    sim->steps++;
    return 0;
}

int bd_sim_step(bd_sim *sim, long count, char *err, size_t errlen)
{
    for (long k = 0; k < count; k++)
        if (bd_step_once(sim)) {
            snprintf(err, errlen, "%s", sim->fail_msg);
            return 1;
        }
    return 0;
}
