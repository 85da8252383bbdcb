/* Pulleys (seed 001 §4.2, eqs 4.62, 4.64–4.65, 4.67): a rotating body on a
 * fixed axle or on a takeup carriage. The belt formulation's wrap coupling
 * gives its angular acceleration and the belt's force along the carriage
 * axis; the drive (or transmission) and the bearing give its outside
 * torque. */
#include "parts/parts.h"

#include <math.h>

#include "base/constants.h"
#include "laws/rolling.h"

void bd_pulley_model_init(bd_model *model, bd_pulley_model *pm, const bd_pulley_def *pd)
{
    pm->def = pd;
    pm->radius = pd->radius;
    pm->wrap = pd->wrap;
    pm->mu_s = pd->friction.mu_static;
    pm->mu_d = pd->friction.mu_dynamic;
    pm->bearing_damping = pd->bearing_damping;
    /* its own resistance (design.secondary: individual, model/secondary.c) */
    bd_secondary_pulley_law(model->def, (int)(pd - model->def->pulleys), &pm->resistance);
    pm->inertia = pd->inertia + (pd->has_drive ? pd->drive.inertia : 0.0);
    /* a massless pulley would have an undefined speed when the belt
     * slips on it everywhere: floor its inertia at 1% of the inertia of
     * the belt wrapped on it (documented in docs/physics.md) */
    double floor_inertia = 0.01 * model->belt_mpl * BD_PI * pd->radius * pd->radius * pd->radius;
    if (pm->inertia < floor_inertia)
        pm->inertia = floor_inertia;
    pm->x0 = pd->x;
    pm->y0 = pd->y;
    if (pd->has_takeup) {
        pm->axis[0] = pd->takeup.axis[0];
        pm->axis[1] = pd->takeup.axis[1];
        pm->movable = pd->takeup.type != BD_TAKEUP_FIXED;
        pm->carriage_mass = pd->mass + pd->takeup.mass;
        if (pm->movable && pm->carriage_mass <= 0.0)
            pm->carriage_mass = 1e-3 * model->belt_mpl * pd->radius;
    }
}

/* the drive's torque (through its transmission, if any) and the bearing's
 * at the present speed; the drive's implicit part goes to torque_damping */
double bd_pulley_external_torque(bd_sim *sim, bd_pulley_body *p)
{
    bd_part *drive = bd_pulley_drive_part(sim, p);
    double K = 0.0;
    double T_drive = drive ? bd_part_torque(sim, drive, &K) : 0.0;
    p->drive_torque = T_drive;
    p->torque_damping = K;
    p->bearing_torque = -p->m->bearing_damping * p->omega;
    if (p->m->resistance.active) {
        /* its own resistance against the surface's motion (a Coulomb force
         * faded near rest, as the idlers' rolling resistance) */
        double R = p->m->radius, sat = bd_coulomb_share(p->omega * R, p->res_fade);
        p->bearing_torque -= p->res_force * R * sat;
    }
    return T_drive + p->bearing_torque;
}

/* the drive's implicit torque against its max_torque: when the torque it
 * applies at the end-of-step speed, drive_torque − torque_damping·Δt·α,
 * passes ±max_torque, the drive is saturated this step: its torque is the
 * limit, now explicit (torque_damping 0), and *external (drive + bearing)
 * follows. Returns 1: the wrap coupling solves the pulley again. */
int bd_pulley_drive_clip(const bd_sim *sim, bd_pulley_body *p, double alpha, double *external)
{
    if (p->torque_damping <= 0.0)
        return 0;
    double applied = p->drive_torque - p->torque_damping * sim->model->dt * alpha;
    double limit = p->m->def->drive.max_torque;
    if (fabs(applied) <= limit)
        return 0;
    p->drive_torque = applied > 0.0 ? limit : -limit;
    p->torque_damping = 0.0;
    *external = p->drive_torque + p->bearing_torque;
    return 1;
}

double bd_pulley_carriage(const bd_sim *sim, const bd_pulley_body *p, double *mass)
{
    *mass = 0.0;
    if (!p->m->movable)
        return 0.0;
    for (int k = p->m->first_part; k < p->m->first_part + p->m->part_count; k++) {
        const bd_part *part = &sim->parts[k];
        if (part->type != BD_PART_TAKEUP || part->u.takeup.at_limit)
            continue;
        *mass = p->m->carriage_mass;
        return bd_takeup_pull(sim, &part->u.takeup, p);
    }
    return 0.0;
}

/* rotation with the mid-step speed booked (central differences, as the
 * belt nodes), then its parts: the drive's work, the transmission, the
 * takeup carriage */
void bd_pulleys_advance(bd_sim *sim, double *ke, double *w_nc)
{
    const double dt = sim->model->dt;
    for (int i = 0; i < sim->model->pulley_count; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        /* the drive torque applied: its implicit part at the end-of-step speed */
        p->drive_torque -= p->torque_damping * dt * p->alpha;
        if (fabs(p->drive_torque) > p->torque_max_abs)
            p->torque_max_abs = fabs(p->drive_torque);
        double w_mid = p->omega + 0.5 * p->alpha * dt;
        *ke += 0.5 * p->m->inertia * w_mid * w_mid;
        *w_nc += (p->torque_friction + p->bearing_torque) * w_mid * dt;
        double w_old = p->omega;
        p->omega += p->alpha * dt;
        for (int k = p->m->first_part; k < p->m->first_part + p->m->part_count; k++)
            bd_part_advance(sim, &sim->parts[k], w_old, w_mid, ke, w_nc);
        /* held (a drive pulley while stabilizing, as its holdback holds it):
         * its wrap coupling took α = 0; what a transmission adds goes into
         * the hold */
        if (p->held)
            p->omega = 0.0;
    }
}
