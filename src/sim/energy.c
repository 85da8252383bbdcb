/* Energy bookkeeping (cli.md `energy`): potential energy of gravity (belt,
 * material, pulleys; y = 0 is the datum), elastic energy of the belt
 * elements, bending springs and contact springs, and the potential −F·q of
 * the takeup pulls (a gravity takeup's counterweight included). Kinetic
 * energy and the work of dissipative forces and drives are booked in the
 * step (step.c). */
#include "sim/system.h"
#include "base/constants.h"

#include <math.h>

double bd_energy_potential(const bd_sim *sim)
{
    if (sim->axial)
        return bd_axial_potential(sim);
    double g = sim->gravity;
    double e = 0.0;
    for (int i = 0; i < sim->n; i++)
        e += sim->mass[i] * g * sim->y[i];
    e += bd_belt_elastic_energy(sim);
    for (int i = 0; i < sim->pulley_count; i++) {
        const bd_pulley_body *p = &sim->pulleys[i];
        e += p->def->mass * g * p->cy;
        e += bd_pulley_contact_energy(sim, p);
        if (p->movable)
            e -= bd_takeup_force(sim, p, sim->t) * p->q;
    }
    return e + bd_transmissions_potential(sim);
}

/* the largest |E_k + E_p + E_d − E_in − E_0| / max(|E_0|, E_in, max E_k, 1 J)
 * so far (cli.md `balance_error_rel`) */
void bd_energy_update_balance(bd_sim *sim)
{
    bd_energy *en = &sim->energy;
    double err = fabs(en->kinetic + en->potential + en->dissipated - en->input - en->initial);
    double scale = fabs(en->initial);
    if (en->input > scale)
        scale = en->input;
    if (en->max_kinetic > scale)
        scale = en->max_kinetic;
    if (scale < 1.0)
        scale = 1.0;
    if (err / scale > en->balance_error_rel)
        en->balance_error_rel = err / scale;
}

/* Eulerian path coordinate of element e's midpoint: its projection on the
 * path, searched from the segment it was on last time */
double bd_element_s(const bd_sim *sim, int e)
{
    if (sim->axial) {
        /* stations are fixed on the path */
        double s = sim->s_node0[e] + 0.5 * sim->ax.s_len[e];
        return s < sim->path.length ? s : s - sim->path.length;
    }
    int j = e + 1 == sim->n ? 0 : e + 1;
    double mx = 0.5 * (sim->x[e] + sim->x[j]), my = 0.5 * (sim->y[e] + sim->y[j]);
    int nseg = sim->path.segment_count;
    int seg = sim->seg_hint[e];
    double u = 0.0;
    for (int it = 0; it < 6; it++) {
        const bd_path_segment *g = &sim->path.segments[seg];
        if (g->kind == BD_SEGMENT_SPAN) {
            u = (mx - g->p0[0]) * g->dir[0] + (my - g->p0[1]) * g->dir[1];
        } else {
            double sense = g->sweep >= 0.0 ? 1.0 : -1.0;
            double rel = sense * (atan2(my - g->centre[1], mx - g->centre[0]) - g->angle0);
            /* put the gap outside the arc half before, half after it */
            double gap = 0.5 * (BD_TWO_PI - fabs(g->sweep));
            while (rel < -gap)
                rel += BD_TWO_PI;
            while (rel >= BD_TWO_PI - gap)
                rel -= BD_TWO_PI;
            u = rel * g->radius;
        }
        if (u < 0.0 && it < 5)
            seg = (seg + nseg - 1) % nseg;
        else if (u > g->length && it < 5)
            seg = (seg + 1) % nseg;
        else
            break;
    }
    ((bd_sim *)sim)->seg_hint[e] = seg;   /* a cache, not state */
    const bd_path_segment *g = &sim->path.segments[seg];
    if (u < 0.0)
        u = 0.0;
    if (u > g->length)
        u = g->length;
    return g->s0 + u;
}

/* belt speed along element e, m/s */
double bd_element_speed(const bd_sim *sim, int e)
{
    int j = e + 1 == sim->n ? 0 : e + 1;
    if (sim->axial)
        return 0.5 * (sim->vx[e] + sim->vx[j]);
    return 0.5 * (sim->ux[e] * (sim->vx[e] + sim->vx[j]) + sim->uy[e] * (sim->vy[e] + sim->vy[j]));
}
