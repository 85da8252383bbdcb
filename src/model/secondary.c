/* Which resistance acts where (model/secondary.h); the formulas and their
 * clauses are in laws/secondary_resistance.c. */
#include "model/secondary.h"

#include <math.h>
#include <string.h>

#include "laws/secondary_resistance.h"

int bd_secondary_individual(const bd_model_def *m)
{
    return m->design.present && m->design.secondary == BD_SECONDARY_INDIVIDUAL;
}

int bd_secondary_cleaner_pulley(const bd_model_def *m)
{
    if (!bd_secondary_individual(m) || !m->design.cleaners.present)
        return -1;
    if (m->design.cleaners.pulley >= 0)
        return m->design.cleaners.pulley;
    if (m->material.present)
        return m->material.discharge;
    for (int p = 0; p < m->pulley_count; p++)
        if (m->pulleys[p].has_drive)
            return p;
    return 0;
}

static const bd_bearing_def *bearing_of(const bd_model_def *m, int p)
{
    for (int k = 0; k < m->design.bearing_count; k++)
        if (m->design.bearings[k].pulley == p)
            return &m->design.bearings[k];
    return NULL;
}

void bd_secondary_pulley_law(const bd_model_def *m, int p, bd_pulley_resistance_law *law)
{
    memset(law, 0, sizeof *law);
    if (!bd_secondary_individual(m))
        return;
    const bd_design_def *d = &m->design;
    const bd_pulley_def *pd = &m->pulleys[p];
    double D = 2.0 * pd->radius;
    /* the wrap (ISO 5048:1989 Table 3, F_l; DIN 22101's bending resistance
     * of the belt around the pulleys): the belt flexes over every pulley it
     * wraps, the drive pulley too (there the drive supplies it at the
     * pulley's surface: T1 − T2 = Te − F_l). The bearing resistance below
     * is the standard's for non-driving pulleys only, a drive pulley's
     * bearings belonging to the drive's efficiency: it is counted where
     * design.bearings lists it (the static calculation notes a drive
     * pulley listed there). */
    double thick = d->belt_thickness > 0.0 ? d->belt_thickness : m->belt.thickness;
    bd_res_wrap_coeffs(d->carcass == BD_CARCASS_STEEL_CORD, m->belt.width, thick, D,
                       &law->wrap0, &law->wrap_per_N);
    law->active = 1;
    const bd_bearing_def *b = bearing_of(m, p);
    if (b) {
        law->bearing_per_N = bd_res_bearing(b->bore, D, 1.0);
        law->weight = b->mass * m->gravity;
        law->active = 1;
    }
    if (bd_secondary_cleaner_pulley(m) == p) {
        const bd_cleaners_def *c = &d->cleaners;
        law->cleaners = bd_res_cleaners(c->count, c->width, c->thickness, c->pressure, c->mu);
        law->active = 1;
    }
}

void bd_secondary_pulley_eval(const bd_pulley_resistance_law *law, double T_in, double T_out,
                              const double u_in[2], const double u_out[2],
                              bd_pulley_resistance *out)
{
    double ti = T_in > 0.0 ? T_in : 0.0, to = T_out > 0.0 ? T_out : 0.0;
    out->wrap = law->wrap0 + law->wrap_per_N * 0.5 * (ti + to);
    out->bearing = 0.0;
    if (law->bearing_per_N > 0.0) {
        /* F_T: the belt pulls the pulley back along its arriving end and
         * forward along its leaving end; its rotating parts weigh m·g */
        double fx = to * u_out[0] - ti * u_in[0];
        double fy = to * u_out[1] - ti * u_in[1] - law->weight;
        out->bearing = law->bearing_per_N * hypot(fx, fy);
    }
    out->cleaners = law->cleaners;
}

void bd_secondary_feed(const bd_model_def *m, double v, bd_feed_resistance *out)
{
    memset(out, 0, sizeof *out);
    if (!bd_secondary_individual(m) || !m->material.present || v <= 0.0)
        return;
    const bd_design_def *d = &m->design;
    double mL = m->material.mass_per_length, v0 = bd_landing_speed(m, 1, v), g = m->gravity;
    out->loading_inertia = bd_res_loading_inertia(mL, v, v0);
    if (!d->skirts.present)
        return;
    const bd_skirts_def *s = &d->skirts;
    out->acceleration_length = bd_res_acceleration_length(v, v0, g, s->mu_belt_material);
    out->loading_skirts = bd_res_skirt_friction(s->mu_material, mL, v, 0.5 * (v + v0),
                                                d->bulk_density, g, out->acceleration_length,
                                                s->width);
    out->skirts = bd_res_skirt_friction(s->mu_material, mL, v, v, d->bulk_density, g, s->length,
                                        s->width);
}
