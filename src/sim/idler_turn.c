/* The warning where the discrete or rfe belt turns sharply over its idlers at
 * speed: φ and v/c of each idler set are the build's (belt/lumped/
 * idler_turn.c, which halves the default element for φ ≥ 0.05 rad). On
 * generated conveyors at the 30° element the running force ran above the
 * resistance law on 8 of 13 with φ ≥ 0.10 rad and v ≥ 0.2·c, on 1 of 88
 * with φ < 0.05 rad, the idlers pressing on the quadratic line round each
 * node. At the halved element 2 of 13 conveyors that had failed still did
 * (seeds 1138 and 1213, φ 0.20 and 0.25 on their return; docs/physics.md
 * §10). On the discrete belt's quintic running line (§5) they pass, so a
 * set whose idlers press on it is not warned of (the rfe belt's too, whose
 * idlers press on its centres' line by the same rule, §15). */
#include "sim/engine.h"

#include "parts/parts.h"

#define TURN_WARN_RAD 0.10
#define TURN_WARN_SPEED 0.2

int bd_idler_turn(const bd_sim *sim, int k, double *phi, double *v_over_c)
{
    const bd_model *m = sim->model;
    if (!m->idler_turn || !(m->idler_turn[k] > 0.0))
        return 0;
    *phi = m->idler_turn[k];
    *v_over_c = m->idler_turn_speed[k];
    return 1;
}

int bd_idler_set_quintic(const bd_sim *sim, int k)
{
    const bd_model *m = sim->model;
    int first = 0, count = 0;
    for (int j = 0; j < k; j++)
        first += m->idlers_per_set[j];
    for (int i = first; i < first + m->idlers_per_set[k]; i++)
        count += m->idlers[i].line_quintic;
    return count;
}

void bd_idler_turn_warn(bd_sim *sim)
{
    const bd_model_def *def = sim->model->def;
    for (int k = 0; k < def->idler_set_count; k++) {
        double phi, voc;
        if (!bd_idler_turn(sim, k, &phi, &voc) || phi < TURN_WARN_RAD || voc < TURN_WARN_SPEED
            || bd_idler_set_quintic(sim, k) == sim->model->idlers_per_set[k])
            continue;
        bd_sim_warn(sim, "the idlers of span '%s' turn the belt by %.2f rad at rest, at %.2f "
                    "of its wave speed: the %s belt without bending stiffness has drawn "
                    "running force above its resistance law on such spans (docs/physics.md "
                    "§10, §15)%s; give belt.bending_stiffness%s, or use the axial or "
                    "moving_node belt for the running force",
                    def->pulleys[def->idler_sets[k].span].name, phi, voc, sim->model->belt->name,
                    sim->model->element_refined == 1 ? ", also at the halved default element" : "",
                    def->belt.formulation == BD_FORMULATION_DISCRETE
                            || def->belt.formulation == BD_FORMULATION_RFE
                        ? ", or shorter elements: nine or more to a bay put its idlers on the "
                          "quintic running line (§5)"
                        : "");
    }
}
