/* The parts mounted on pulleys as one table (parts.h): built in pulley
 * order, each pulley's parts in the order drive (or transmission), takeup;
 * one switch per phase. */
#include "parts/parts.h"

#include <math.h>
#include <stdlib.h>

#include "base/alloc.h"

/* a drive (or transmission), and a takeup whose carriage moves */
static int parts_of(const bd_pulley_model *pm)
{
    return (pm->def->has_drive ? 1 : 0) + pm->movable;
}

void bd_parts_create(bd_sim *sim)
{
    int total = 0;
    for (int i = 0; i < sim->model->pulley_count; i++)
        total += parts_of(&sim->model->pulleys[i]);
    /* the table first, its count after: a jump out of memory in between
     * leaves an empty table to free */
    sim->parts = bd_xcalloc((size_t)total, sizeof *sim->parts);
    sim->part_count = total;
    int at = 0;
    for (int i = 0; i < sim->model->pulley_count; i++) {
        bd_pulley_model *pm = &sim->own->pulleys[i];
        const bd_pulley_def *pd = pm->def;
        pm->first_part = at;
        pm->part_count = parts_of(pm);
        if (pd->has_drive) {
            bd_part *part = &sim->parts[at++];
            part->pulley = i;
            if (pd->drive.has_transmission) {
                part->type = BD_PART_TRANSMISSION;
                part->u.transmission.drive.def = &pd->drive;
                part->u.transmission.belt = bd_transmission_create(sim, pm);
            } else {
                part->type = BD_PART_DRIVE;
                part->u.drive.def = &pd->drive;
            }
        }
        if (pm->movable) {
            bd_part *part = &sim->parts[at++];
            part->type = BD_PART_TAKEUP;
            part->pulley = i;
            part->u.takeup.def = &pd->takeup;
            part->u.takeup.force_prev = bd_table_eval(&pd->takeup.force, 0.0);
        }
    }
}

void bd_parts_free(bd_sim *sim)
{
    if (!sim->parts)
        return;
    for (int k = 0; k < sim->part_count; k++)
        if (sim->parts[k].type == BD_PART_TRANSMISSION)
            free(sim->parts[k].u.transmission.belt);
    free(sim->parts);
    sim->parts = NULL;
    sim->part_count = 0;
}

void bd_parts_clone(bd_sim *dst, const bd_sim *src)
{
    dst->parts = bd_xcalloc((size_t)src->part_count, sizeof *dst->parts);
    dst->part_count = src->part_count;
    for (int k = 0; k < src->part_count; k++) {
        dst->parts[k] = src->parts[k];
        if (src->parts[k].type == BD_PART_TRANSMISSION) {
            /* not the source's, should the copy below run out of memory */
            dst->parts[k].u.transmission.belt = NULL;
            dst->parts[k].u.transmission.belt =
                bd_transmission_clone(src->parts[k].u.transmission.belt);
        }
    }
}

bd_part *bd_pulley_drive_part(const bd_sim *sim, const bd_pulley_body *p)
{
    for (int k = p->m->first_part; k < p->m->first_part + p->m->part_count; k++) {
        bd_part *part = &sim->parts[k];
        if (part->type == BD_PART_DRIVE || part->type == BD_PART_TRANSMISSION)
            return part;
    }
    return NULL;
}

bd_drive *bd_part_drive(const bd_part *part)
{
    bd_part *p = (bd_part *)part;
    switch (p->type) {
    case BD_PART_DRIVE: return &p->u.drive;
    case BD_PART_TRANSMISSION: return &p->u.transmission.drive;
    case BD_PART_TAKEUP: break;
    }
    return NULL;
}

/* part torques phase: what the part puts on its pulley's shaft at the
 * pulley's present speed, and (*slope) how fast that falls with the speed.
 * A drive is off while stabilizing (its pulley is held); a transmission
 * then still carries its belt. */
double bd_part_torque(bd_sim *sim, bd_part *part, double *slope)
{
    bd_pulley_body *p = &sim->pulleys[part->pulley];
    *slope = 0.0;
    switch (part->type) {
    case BD_PART_DRIVE:
        return sim->stabilizing ? 0.0 : bd_drive_torque(sim, &part->u.drive, p, p->omega, slope);
    case BD_PART_TRANSMISSION: return bd_transmission_torque(sim, part);
    case BD_PART_TAKEUP: break;
    }
    return 0.0;
}

/* parts advance phase, after the pulley turned from omega_old at the
 * mid-step speed w_mid */
void bd_part_advance(bd_sim *sim, bd_part *part, double omega_old, double w_mid, double *ke,
                     double *w_nc)
{
    bd_pulley_body *p = &sim->pulleys[part->pulley];
    bd_energy *en = &sim->energy;
    switch (part->type) {
    case BD_PART_DRIVE: {
        en->input += p->drive_torque * w_mid * sim->model->dt;
        bd_drive_note_torque(&part->u.drive, sim->t, p->drive_torque);
        break;
    }
    case BD_PART_TRANSMISSION:
        bd_transmission_advance(sim, part, omega_old, ke, w_nc);
        break;
    case BD_PART_TAKEUP: {
        double qdot_old = p->qdot;
        p->q_step_start = p->q;
        *w_nc += bd_takeup_advance(sim, &part->u.takeup, p, &en->input, &en->step_input_at_t);
        double qm = 0.5 * (qdot_old + p->qdot);
        *ke += 0.5 * p->m->carriage_mass * qm * qm;
        break;
    }
    }
}

double bd_part_potential(const bd_sim *sim, const bd_part *part)
{
    const bd_pulley_body *p = &sim->pulleys[part->pulley];
    switch (part->type) {
    case BD_PART_TAKEUP:
        return -(bd_takeup_force(&part->u.takeup, sim->t) + p->m->wrap_pull) * p->q;
    case BD_PART_DRIVE:
    case BD_PART_TRANSMISSION: break;
    }
    return 0.0;
}

double bd_parts_stored_energy(const bd_sim *sim)
{
    double e = 0.0;
    for (int k = 0; k < sim->part_count; k++)
        if (sim->parts[k].type == BD_PART_TRANSMISSION)
            e += bd_transmission_potential(sim->parts[k].u.transmission.belt);
    return e;
}

void bd_part_reset(bd_part *part)
{
    switch (part->type) {
    case BD_PART_DRIVE: part->u.drive.integral = 0.0; break;
    case BD_PART_TRANSMISSION: part->u.transmission.drive.integral = 0.0; break;
    case BD_PART_TAKEUP: break;
    }
}

void bd_part_records_clear(bd_part *part)
{
    switch (part->type) {
    case BD_PART_DRIVE: part->u.drive.driving_peak = 0.0; break;
    case BD_PART_TRANSMISSION: part->u.transmission.drive.driving_peak = 0.0; break;
    case BD_PART_TAKEUP: part->u.takeup.limit_hits = 0; break;
    }
}

void bd_part_release(bd_part *part, double holding_torque)
{
    switch (part->type) {
    case BD_PART_DRIVE: bd_drive_take_over(&part->u.drive, holding_torque); break;
    /* its motor side ran free while the pulley was held: it starts from
     * its own torque */
    case BD_PART_TRANSMISSION:
    case BD_PART_TAKEUP: break;
    }
}

void bd_part_report_events(bd_sim *sim, const bd_part *part)
{
    switch (part->type) {
    case BD_PART_TAKEUP: {
        const bd_takeup *tk = &part->u.takeup;
        if (tk->limit_hits > 0)
            bd_sim_warn(sim, "takeup '%s' reached the end of its travel (%g m) at t = %.3f s%s",
                        sim->pulleys[part->pulley].m->def->name, tk->limit_first_q,
                        tk->limit_first_t, tk->limit_hits > 1 ? " and again later" : "");
        break;
    }
    case BD_PART_DRIVE:
    case BD_PART_TRANSMISSION: {
        /* the speed loop's torque is clipped to max_torque: at it exactly,
         * the drive was saturated */
        const bd_drive *dr = bd_part_drive(part);
        if (dr->driving_peak >= dr->def->max_torque)
            bd_sim_warn(sim, "drive '%s' reached its torque limit, %.4g N·m (drive.max_torque): "
                        "the belt needed more than it can give",
                        sim->pulleys[part->pulley].m->def->name, dr->def->max_torque);
        break;
    }
    }
}
