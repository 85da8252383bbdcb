/* The model's own resistance law in steady running: the force the drives
 * must deliver to keep the belt at speed v, from what the model declares
 * and nothing the run computes (the same split as DIN 22101's main, slope
 * and loading-point resistances, with the model's own idler law in place
 * of f). `beltdyn check` prints it (describe.c); the torture test holds
 * every run's steady drive force to it (issue 10). */
#include "sim/engine.h"

#include <math.h>

void bd_running_law_build(const bd_sim *sim, bd_running_law *law)
{
    const bd_model_def *def = sim->model->def;
    double g = def->gravity, mB = def->belt.mass_per_length;
    double mL = def->material.present ? def->material.mass_per_length : 0.0;
    *law = (bd_running_law){0};
    /* idler rolling resistance, rr·N: each idler carries the weight (normal
     * to its span) between the midpoints to its neighbours, a pulley's
     * tangent point being the neighbour of the first and the last; the
     * idlers stand where the layout rule puts them (model-format: evenly,
     * the spacing closest to the one given), whether or not the belt
     * resolves them */
    const bd_path *path = &sim->model->path;
    double s_feed = 0.0, loaded = 0.0;
    if (mL > 0.0)
        bd_path_loaded_region(path, &def->material, &s_feed, &loaded);
    for (int k = 0; k < def->idler_set_count; k++) {
        const bd_idler_set_def *set = &def->idler_sets[k];
        const bd_path_segment *sp = bd_path_span(path, set->span);
        double p0[2], p1[2];
        bd_sim_span_ends(sim, set->span, p0, p1);
        double Ls = hypot(p1[0] - p0[0], p1[1] - p0[1]);
        double cos_slope = fabs(p1[0] - p0[0]) / Ls, to_s = sp->length / Ls;
        int count = 0;
        double spacing = 0.0;
        bd_sim_idler_set(sim, k, &count, &spacing);
        /* idler i at i·spacing (i = 1 .. count), the span's ends at 0, Ls */
        for (int i = 1; i <= count; i++) {
            double next = i == count ? Ls : (i + 1) * spacing;
            double a = 0.5 * ((i - 1) * spacing + i * spacing), b = 0.5 * (i * spacing + next);
            double on = mL > 0.0 ? bd_path_region_overlap(path, sp->s0 + a * to_s,
                                                          (b - a) * to_s, s_feed, loaded) / to_s
                                 : 0.0;
            law->idlers += set->rolling_resistance * g * cos_slope * (mB * (b - a) + mL * on);
        }
        /* an idler `curve` adds nothing: it is an arc through two points of
         * the span, meeting the straight span at two corners that turn the
         * belt back by half its sweep each, so the tension pulls its ends
         * along one line and the idlers carry the weight alone,
         * Σ N = m'·g·cos δ·length, however the load is shared among them
         * (T/R on the arc, T·Δ at the corners, the belt lifting off some;
         * vertical balance of the belt over the curve). The linear law
         * rr·ΣN is then this span's as if straight. */
    }
    /* the load: lifted from the feed point to the end of the loaded
     * region, and brought to belt speed where it lands */
    if (mL > 0.0) {
        double pf[2], pd[2], t[2];
        bd_path_point(path, s_feed, pf, t);
        bd_path_point(path, s_feed + loaded, pd, t);
        law->lift = mL * g * (pd[1] - pf[1]);
        if (def->material.feeding)
            law->feed_mass = mL;
    }
    /* bearings of the pulleys the belt turns, b·ω = R·ΔT: b/R² per m/s */
    for (int i = 0; i < def->pulley_count; i++) {
        const bd_pulley_def *p = &def->pulleys[i];
        if (!p->has_drive)
            law->bearings += p->bearing_damping / (p->radius * p->radius);
    }
}

double bd_running_law_force(const bd_running_law *law, double v, double *scale)
{
    double idlers = v > 0.0 ? law->idlers : (v < 0.0 ? -law->idlers : 0.0);
    double feed = law->feed_mass * v * fabs(v), bearings = law->bearings * v;
    if (scale)
        *scale = fabs(idlers) + fabs(law->lift) + fabs(feed) + fabs(bearings);
    return idlers + law->lift + feed + bearings;
}
