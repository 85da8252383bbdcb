/* Bulk material on the lumped belt (model-format.md `material`). */
#include "belt/lumped/lumped.h"

#include "model/secondary.h"

/* material: lands at the feed point with no velocity along the belt, or
 * with design.loading_speed v0 along it (secondary: individual; no faster
 * than the belt) — the momentum is shared, v' = (m·v + Δm·v0)/(m + Δm) —
 * and leaves at the discharge pulley with the belt's velocity
 * (model-format.md `material`) */
static void material_transport(bd_sim *sim)
{
    bd_tracker *fd = &sim->feed;
    const double yd = bd_lumped_material_datum(sim);
    bd_tracker_update(sim, fd);
    if (sim->has_feed) {
        int e = fd->element, j = e + 1 == sim->model->n ? 0 : e + 1;
        double g = fd->gamma;
        double v = bd_tracker_speed(sim, fd);
        if (v > 0.0) {
            double dm = sim->model->material_mpl * v * sim->model->dt;
            double v0 = bd_landing_speed(sim->model->def, sim->model->feed_individual, v);
            int nodes[2] = {e, j};
            double share[2] = {1.0 - g, g};
            for (int k = 0; k < 2; k++) {
                int i = nodes[k];
                double add = dm * share[k];
                double m = sim->mass[i];
                double ke = 0.5 * m * (sim->vx[i] * sim->vx[i] + sim->vy[i] * sim->vy[i]);
                if (v0 > 0.0) {
                    /* what the landing material brings, its kinetic energy
                     * booked as input */
                    double ke_in = 0.5 * add * v0 * v0;
                    sim->vx[i] = (m * sim->vx[i] + add * v0 * fd->dir[0]) / (m + add);
                    sim->vy[i] = (m * sim->vy[i] + add * v0 * fd->dir[1]) / (m + add);
                    ke += ke_in;
                    sim->energy.input += ke_in;
                } else {
                    sim->vx[i] *= m / (m + add);
                    sim->vy[i] *= m / (m + add);
                }
                sim->mass[i] += add;
                bd_node_mass_changed(sim, i);
                sim->material[i] += add;
                double ke2 = 0.5 * sim->mass[i]
                           * (sim->vx[i] * sim->vx[i] + sim->vy[i] * sim->vy[i]);
                sim->energy.dissipated += ke - ke2;
                sim->energy.input += add * sim->model->gravity * (sim->y[i] - yd);
            }
        }
    }
}

static void material_discharge(bd_sim *sim)
{
    /* nodes in contact with the discharge pulley lose their load: on its
     * shell, or carrying a share of a wrapped arc (up to an element before
     * the tangent point, pulley_contact.c) */
    const bd_wrap_contact *W = &bd_lumped_of(sim)->wraps[sim->model->discharge_pulley];
    const double yd = bd_lumped_material_datum(sim);
    for (int c = 0; c < W->contact_count; c++) {
        int i = W->c_node[c];
        double dm = sim->material[i];
        if (dm <= 0.0)
            continue;
        /* its kinetic energy and what is left of its potential (the wrap's
         * height about the datum, ± R) leave with it. Measured from y = 0
         * the potential made the dissipated energy fall on loaded declines
         * whose discharge lies below 0: 37 of the soak's first 76 failures
         * (issue 10) */
        double v2 = sim->vx[i] * sim->vx[i] + sim->vy[i] * sim->vy[i];
        double h = sim->y[i] - yd;
        sim->energy.dissipated += 0.5 * dm * v2 + dm * sim->model->gravity * h;
        sim->mass[i] -= dm;
        bd_node_mass_changed(sim, i);
        sim->material[i] = 0.0;
    }
}

void bd_lumped_material(bd_sim *sim)
{
    material_transport(sim);
    material_discharge(sim);
}
