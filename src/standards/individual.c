/* design.secondary: individual: the secondary resistances one by one in
 * place of DIN 22101's (C − 1)·F_H (ISO 5048:1989 §5.2 and Table 3,
 * DIN 22101 §5.2). Where each acts (model/secondary.c):
 *   - each pulley's wrap and bearing resistance at the pulley: the belt
 *     leaves it with T_out = T_in + F (in the next section's T0; at a
 *     drive T1 − T2 = Te − F, the drive supplying F at its surface);
 *   - F_bA, F_f and F_gl from the feed point on;
 *   - cleaners on their pulley, a constant T_out = T_in + F_r (in the
 *     section's pulley_special; at a drive T1 − T2 = Te − F_r).
 * Wrap and bearings depend on the tensions, which depend on them: a fixed
 * point, reached to 1e-9 of Te in a few passes (their tension terms are
 * ~0.1–0.2 % of T). */
#include "standards/standards_internal.h"

#include <math.h>
#include <stdlib.h>

#include "model/secondary.h"

#define MAX_PASSES 50

/* the section where the material lands: the first loaded one from the
 * feed span on */
static int feed_section(const bd_std_ctx *c)
{
    for (int k = 0; k < c->nsec; k++)
        if (c->sec[k].span == c->feed_span && c->sec[k].mL > 0.0)
            return k;
    return bd_std_first_sec(c, (c->feed_span + 1) % c->n);
}

int bd_individual_resistances(bd_std_ctx *c)
{
    const bd_model_def *m = c->m;
    bd_static_result *r = c->out;
    r->individual = 1;
    r->pulleys = calloc((size_t)c->n, sizeof *r->pulleys);
    if (!r->pulleys)
        return 1;

    /* the feed point (at the design speed) */
    if (c->feed_span >= 0) {
        bd_feed_resistance fr;
        bd_secondary_feed(m, c->speed, &fr);
        bd_std_section *s = &c->sec[feed_section(c)];
        s->local_secondary += fr.loading_inertia + fr.loading_skirts;
        s->local_special += fr.skirts;
        r->loading_inertia_N = fr.loading_inertia;
        r->loading_skirts_N = fr.loading_skirts;
        r->skirts_N = fr.skirts;
        r->acceleration_length_m = fr.acceleration_length;
        if (m->design.loading_speed > c->speed && c->speed > 0.0)
            bd_std_warn(r, "design.loading_speed %.3g m/s is above the belt speed %.3g m/s: the "
                           "material lands faster than the belt; its push is left out (F_bA "
                           "and the acceleration zone taken as 0, as the run does)",
                        m->design.loading_speed, c->speed);
    } else if (m->design.skirts.present) {
        bd_std_note(r, "design.skirts: the model has no material, so the skirts take nothing "
                       "(ISO 5048's skirt friction is that of the material)");
    }

    /* each pulley's law, once; the cleaners scrape the belt on their
     * pulley, a constant force: at a drive they come out of the belt's
     * T1 − T2 there, as in the run (our reading: ISO 5048:1989 Table 3
     * gives F_r = A·p·μ3, not where it acts; docs/standards.md) */
    bd_pulley_resistance_law *law = calloc((size_t)c->n, sizeof *law);
    if (!law)
        return 1;
    for (int p = 0; p < c->n; p++) {
        bd_secondary_pulley_law(m, p, &law[p]);
        if (m->pulleys[p].has_drive && law[p].bearing_per_N > 0.0)
            bd_std_note(r, "design.bearings.%s: %s drives; ISO 5048 leaves a drive pulley's "
                           "bearing resistance to the drive's efficiency, and it is counted "
                           "here as given (design.efficiency should then not include it)",
                        m->pulleys[p].name, m->pulleys[p].name);
        c->sec[bd_std_first_sec(c, p)].pulley_special += law[p].cleaners;
        r->pulleys[p].cleaners_N = law[p].cleaners;
    }

    /* the pulleys' wrap and bearings, to a fixed point with the tensions */
    double change = INFINITY;
    int pass = 0;
    bd_std_propagate(c);
    while (change > 1e-9 * (fabs(bd_std_total(c)) + 1.0) && pass < MAX_PASSES) {
        change = 0.0;
        for (int p = 0; p < c->n; p++) {
            if (!law[p].active)
                continue;
            const double *u_in, *u_out;
            bd_path_wrap_dirs(&c->path, p, &u_in, &u_out);
            bd_pulley_resistance pr;
            bd_secondary_pulley_eval(&law[p], bd_std_T_arrive(c, p), bd_std_T_leave(c, p), u_in,
                                     u_out, &pr);
            bd_std_section *s = &c->sec[bd_std_first_sec(c, p)];
            change = fmax(change, fabs(pr.wrap + pr.bearing - s->pulley_res));
            s->pulley_res = pr.wrap + pr.bearing;
            r->pulleys[p].wrap_N = pr.wrap;
            r->pulleys[p].bearing_N = pr.bearing;
        }
        bd_std_propagate(c);
        pass++;
    }
    free(law);
    if (change > 1e-9 * (fabs(bd_std_total(c)) + 1.0))
        bd_std_warn(r, "secondary: individual: the pulleys' resistances and the tensions did "
                       "not settle in %d passes (last change %.3g N)", MAX_PASSES, change);

    r->wrap_N = r->bearings_N = r->cleaners_N = 0.0;
    for (int p = 0; p < c->n; p++) {
        r->pulleys[p].T_in_N = bd_std_T_arrive(c, p);
        r->pulleys[p].T_out_N = bd_std_T_leave(c, p);
        r->wrap_N += r->pulleys[p].wrap_N;
        r->bearings_N += r->pulleys[p].bearing_N;
        r->cleaners_N += r->pulleys[p].cleaners_N;
    }
    return 0;
}
