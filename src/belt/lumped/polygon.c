/* The rfe belt's polygon on its pulleys: what its rigid elements' chordal
 * action there costs in running force, and the default element that keeps
 * it small (docs/physics.md §15, *The polygon on the pulleys*). The lumped
 * build sizes the rfe belt's chain (belt/rfe builds on belt/lumped), so
 * the rule lives here beside the discrete belt's (idler_turn.c).
 *
 * An rfe element rides a pulley as a link rides a sprocket (belt/rfe/
 * build.c): where it comes onto the shell and leaves it the belt's line is
 * a polygon of chords, not the arc, and each passage jolts the strands
 * beside it across. The energy that costs is a drag the drives pay, like
 * a chain drive's polygonal (chordal) loss: per pulley k a force
 *
 *     ΔF_k = C · m′ · v² · (l0 / R_k)³,
 *
 * m′ the belt's mass per metre, v the belt speed, R_k the radius. The cube
 * and C were measured on held-out generated seed 8504 (45 m, empty,
 * undamped, 4.68 m/s, two pulleys of 0.37 and 0.40 m): the running force
 * over its own law was +4.6 % at 15° elements, +1.4 to +3.4 % at 10.6°
 * (the takeup still moving) and +0.2 to +0.4 % at 7.5°; halving the return
 * idlers' spacing, ten times less shear stiffness and every element free
 * left it, half the speed took it away, twice the length halved it (a
 * force per pulley, not per metre). At 15°, C = 0.65 puts 4.6 % on 8504;
 * the same C predicts 0.0 to 2.5 % on 15 other generated conveyors, whose
 * measured excess (−0.6 to +2.7 %) it follows to within 1.8 % (seed 3),
 * mostly to well under a percent (the table in physics.md). */
#include "belt/lumped/lumped.h"

#include <math.h>

#include "model/path.h"
#include "parts/parts.h"

#define POLYGON_C 0.65
/* the most the default is shortened for it (a cost of (1/k)² at most:
 * nodes and the shear's step) */
#define POLYGON_SHRINK_MIN 0.5

/* the running resistance's scale at speed v, as sim/running_law.c sums it
 * in magnitude (idler rolling resistance with the load on the spans, the
 * load's lift and its acceleration at the feed), from the definition and
 * the path: each span's idlers carry its whole length */
double bd_lumped_resistance_scale(const bd_model_def *def, const bd_path *path, double v)
{
    const double g = def->gravity, mB = def->belt.mass_per_length;
    const double mL = def->material.present ? def->material.mass_per_length : 0.0;
    double s_feed = 0.0, loaded = 0.0;
    if (mL > 0.0)
        bd_path_loaded_region(path, &def->material, &s_feed, &loaded);
    double F = 0.0;
    for (int k = 0; k < def->idler_set_count; k++) {
        const bd_idler_set_def *set = &def->idler_sets[k];
        const bd_path_segment *sp = bd_path_span(path, set->span);
        double on =
            mL > 0.0 ? bd_path_region_overlap(path, sp->s0, sp->length, s_feed, loaded) : 0.0;
        F += set->rolling_resistance * g * fabs(sp->dir[0]) * (mB * sp->length + mL * on);
    }
    if (mL > 0.0) {
        double pf[2], pd[2], t[2];
        bd_path_point(path, s_feed, pf, t);
        bd_path_point(path, s_feed + loaded, pd, t);
        F += fabs(mL * g * (pd[1] - pf[1]));
        if (def->material.feeding)
            F += mL * v * v;
    }
    return F;
}

double bd_lumped_polygon_share(const bd_model_def *def, const bd_path *path, double l0)
{
    double v = bd_drives_reference_speed(def), sum = 0.0;
    for (int i = 0; i < def->pulley_count; i++)
        sum += pow(l0 / def->pulleys[i].radius, 3.0);
    double loss = POLYGON_C * def->belt.mass_per_length * v * v * sum;
    double F = bd_lumped_resistance_scale(def, path, v);
    return F > 0.0 ? loss / F : NAN;
}

double bd_lumped_polygon_element(const bd_model_def *def, const bd_path *path, double l0)
{
    double share = bd_lumped_polygon_share(def, path, l0);
    if (!(share > BD_POLYGON_SHARE_MAX))
        return l0;
    return l0 * fmax(POLYGON_SHRINK_MIN, cbrt(BD_POLYGON_SHARE_MAX / share));
}
