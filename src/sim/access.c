/* Read-outs of the state (include/beltdyn/sim.h): what a test, a tool or a
 * program stepping a simulation itself may look at, without the internals.
 * They change nothing. */
#include "sim/engine.h"

#include "parts/parts.h"

double bd_sim_time(const bd_sim *sim) { return sim->t; }
double bd_sim_time_step(const bd_sim *sim) { return sim->model->dt; }
int bd_sim_node_count(const bd_sim *sim) { return sim->model->n; }
const char *bd_sim_formulation(const bd_sim *sim) { return sim->model->belt->name; }
double bd_sim_belt_length(const bd_sim *sim) { return sim->model->path.length; }

double bd_sim_span_length(const bd_sim *sim, int pulley)
{
    if (pulley < 0 || pulley >= sim->model->pulley_count)
        return 0.0;
    return bd_path_span(&sim->model->path, pulley)->length;
}

int bd_sim_span_ends(const bd_sim *sim, int pulley, double start[2], double end[2])
{
    if (pulley < 0 || pulley >= sim->model->pulley_count)
        return -1;
    const bd_path_segment *span = bd_path_span(&sim->model->path, pulley);
    start[0] = span->p0[0];
    start[1] = span->p0[1];
    end[0] = span->p1[0];
    end[1] = span->p1[1];
    return 0;
}

int bd_sim_node(const bd_sim *sim, int i, bd_node_state *out)
{
    if (i < 0 || i >= sim->model->n)
        return -1;
    out->x_m = sim->x[i];
    out->y_m = sim->y[i];
    out->vx_mps = sim->vx[i];
    out->vy_mps = sim->vy[i];
    out->mass_kg = sim->mass[i];
    out->tension_N = sim->tension[i];
    return 0;
}

double bd_sim_belt_speed(const bd_sim *sim)
{
    double p = 0.0, m = 0.0;
    for (int i = 0; i < sim->model->n; i++) {
        p += sim->mass[i] * sim->model->belt->node_speed(sim, i);
        m += sim->mass[i];
    }
    return p / m;
}

double bd_sim_belt_mass(const bd_sim *sim)
{
    double m = 0.0;
    for (int i = 0; i < sim->model->n; i++)
        m += sim->mass[i];
    return m;
}

int bd_sim_pulley_count(const bd_sim *sim) { return sim->model->pulley_count; }

int bd_sim_pulley(const bd_sim *sim, int i, bd_pulley_state *out)
{
    if (i < 0 || i >= sim->model->pulley_count)
        return -1;
    const bd_pulley_body *p = &sim->pulleys[i];
    out->omega_rad_s = p->omega;
    out->drive_torque_Nm = p->drive_torque;
    out->travel_m = p->q;
    out->x_m = p->cx;
    out->y_m = p->cy;
    out->radius_m = p->m->radius;
    out->inertia_kgm2 = p->m->inertia;
    const bd_part *d = bd_pulley_drive_part(sim, p);
    out->has_transmission = d && d->type == BD_PART_TRANSMISSION;
    out->motor_omega_rad_s = out->slip_motor_mps = out->slip_pulley_mps = 0.0;
    if (out->has_transmission)
        bd_transmission_state(d, p, &out->motor_omega_rad_s, &out->slip_motor_mps,
                              &out->slip_pulley_mps);
    return 0;
}

int bd_sim_takeup(const bd_sim *sim, int pulley, bd_takeup_state *out)
{
    if (pulley < 0 || pulley >= sim->model->pulley_count)
        return -1;
    const bd_pulley_body *p = &sim->pulleys[pulley];
    for (int k = p->m->first_part; k < p->m->first_part + p->m->part_count; k++) {
        const bd_part *part = &sim->parts[k];
        if (part->type != BD_PART_TAKEUP)
            continue;
        out->travel_m = p->q;
        out->travel_min_m = p->travel_min;
        out->travel_max_m = p->travel_max;
        out->limit_hits = part->u.takeup.limit_hits;
        return 0;
    }
    return -1;
}

int bd_sim_idler_count(const bd_sim *sim) { return sim->model->idler_count; }

int bd_sim_idler(const bd_sim *sim, int i, bd_idler_state *out)
{
    if (i < 0 || i >= sim->model->idler_count)
        return -1;
    const bd_idler *id = &sim->idlers[i];
    out->x_m = id->m->centre[0];
    out->y_m = id->m->centre[1];
    out->radius_m = id->m->radius;
    out->inertia_kgm2 = id->m->inertia;
    out->omega_rad_s = id->omega;
    out->set = id->m->set;
    return 0;
}

int bd_sim_idler_set(const bd_sim *sim, int k, int *count, double *spacing_m)
{
    if (k < 0 || k >= sim->model->def->idler_set_count)
        return -1;
    *count = sim->model->idlers_per_set[k];
    *spacing_m = sim->model->idler_spacing[k];
    return 0;
}

int bd_sim_probe_count(const bd_sim *sim) { return sim->model->probe_count; }

int bd_sim_probe(const bd_sim *sim, int i, bd_probe_state *out)
{
    if (i < 0 || i >= sim->model->probe_count)
        return -1;
    const bd_tracker *tr = &sim->probes[i].tr;
    bd_belt_sample b;
    sim->model->belt->sample(sim, tr, &b);
    out->tension_N = b.tension;
    out->speed_mps = b.speed;
    out->belt_x_m = b.x;
    out->belt_y_m = b.y;
    out->x_m = tr->p[0];
    out->y_m = tr->p[1];
    out->s_m = tr->s;
    return 0;
}

void bd_sim_energy(const bd_sim *sim, bd_energy_state *out)
{
    const bd_energy *en = &sim->energy;
    out->kinetic_J = en->kinetic;
    out->potential_J = en->potential;
    bd_energy_at_t(en, &out->dissipated_J, &out->input_J);
    out->initial_J = en->initial;
    out->balance_error_rel = en->balance_error_rel;
    out->dissipation_fall_rel = en->dissipation_fall_rel;
}

void bd_sim_book_energy_every_step(bd_sim *sim, int on) { sim->energy_every_step = on != 0; }

/* with what the contacts' springs hold, as the account counts it (the last
 * step's forces phase summed them: 0 before the first step) */
double bd_sim_potential_energy(const bd_sim *sim)
{
    return bd_energy_potential(sim) + sim->energy.springs;
}

int bd_sim_warning_count(const bd_sim *sim) { return sim->warning_count; }

const char *bd_sim_warning(const bd_sim *sim, int i)
{
    return i >= 0 && i < sim->warning_count ? sim->warnings[i] : NULL;
}
