/* How sharply the discrete belt turns over its idlers, and the warning
 * where that belt has drawn running force above its own law.
 *
 * The discrete belt without bending stiffness over idler set k: the angle
 * by which the belt turns at each idler, φ = m'g·a·cos δ/(T − m'v²): twice
 * the slope m'g·a/(2T) at the ends of the sag parabola h = m'g·a²/(8T)
 * whose limit standards.c takes for DIN 22101's minimum tension
 * (T_min_sag), with the moving string's T − m'v² (Wickert & Mote 1990, as
 * in moving_node/forces.c); T and m' the span's at rest, v the drives'
 * speed; and v against the transverse wave speed c = √(T/m'). At every
 * idler the belt's smoothed line cuts the corner of its free lines by
 * between φl0/8 and φl0/4 as the nodes pass, a lift of φl0/8 at v/l0 that
 * pumps the spans (docs/physics.md §10). On generated conveyors the
 * running force ran above the resistance law on 8 of 13 with
 * φ ≥ 0.10 rad and v ≥ 0.2·c, on 1 of 88 with φ < 0.05 rad. */
#include "sim/engine.h"

#include <math.h>

#include "parts/parts.h"

#define TURN_WARN_RAD 0.10
#define TURN_WARN_SPEED 0.2

int bd_idler_turn(const bd_sim *sim, int k, double *phi, double *v_over_c)
{
    const bd_model_def *def = sim->model->def;
    if (def->belt.formulation != BD_FORMULATION_DISCRETE || sim->model->EI > 0.0)
        return 0;
    const bd_path_segment *sp = bd_path_span(&sim->model->path, def->idler_sets[k].span);
    double T = 0.0, mass = 0.0;
    int count = 0;
    for (int e = 0; e < sim->model->n; e++) {
        double s = sim->model->belt->element_s(sim, e);
        if (s < sp->s0 || s > sp->s0 + sp->length)
            continue;
        T += sim->tension[e];
        mass += sim->mass[e];
        count++;
    }
    if (count == 0 || sp->length <= 0.0)
        return 0;
    T /= count;
    double mpl = mass / (count * sim->model->l0), v = bd_drives_reference_speed(sim->model);
    double cos_d = fabs(sp->dir[0]), a = sim->model->idler_spacing[k];
    double tc = T - mpl * v * v, c = T > 0.0 ? sqrt(T / mpl) : 0.0;
    if (tc <= 0.0 || c <= 0.0)
        return 0;
    *phi = mpl * def->gravity * a * cos_d / tc;
    *v_over_c = v / c;
    return 1;
}

void bd_idler_turn_warn(bd_sim *sim)
{
    const bd_model_def *def = sim->model->def;
    for (int k = 0; k < def->idler_set_count; k++) {
        double phi, voc;
        if (!bd_idler_turn(sim, k, &phi, &voc) || phi < TURN_WARN_RAD || voc < TURN_WARN_SPEED)
            continue;
        bd_sim_warn(sim, "the idlers of span '%s' turn the belt by %.2f rad at rest, at %.2f "
                    "of its wave speed: the discrete belt without bending stiffness has drawn "
                    "running force above its resistance law on such spans (docs/physics.md "
                    "§10); give belt.bending_stiffness, or use the axial or moving_node belt "
                    "for the running force", def->pulleys[def->idler_sets[k].span].name, phi,
                    voc);
    }
}
