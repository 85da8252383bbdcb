/* The moving-node belt's entry in the formulation table (belt/belt.h):
 * what the sensors read and the events said after the run. */
#include "belt/moving_node/moving_node.h"

static void point_init(const bd_sim *sim, bd_tracker *tr, double s)
{
    bd_station_point_init(sim, tr, s, bd_mn_model_of(sim)->ds0);
}

static double element_s(const bd_sim *sim, int e)
{
    return bd_station_element_s(sim, e, bd_mn_model_of(sim)->ds0);
}

static double element_strain(const bd_sim *sim, int e)
{
    const bd_mn *mn = bd_mn_of(sim);
    return mn->len[e] / mn->dX[e] - 1.0;
}

static void report_events(bd_sim *sim)
{
    const bd_mn *mn = bd_mn_of(sim);
    const bd_mn_model *mm = bd_mn_model_of(sim);
    if (mn->liftoff_steps > 0) {
        int i = mn->liftoff_first_node;
        bd_sim_warn(sim, "pulley '%s': the belt lifted off its wrap (pressure below zero) at "
                    "t = %.3f s, s = %.2f m, first; %ld node-steps in all",
                    sim->pulleys[mm->pulley[i]].m->def->name, mn->liftoff_first_t,
                    sim->model->s_node0[i], mn->liftoff_steps);
    }
    if (mn->solve_fallbacks > 0)
        bd_sim_warn(sim, "moving_node: in %ld steps the stick/slip set of the wraps did not "
                    "settle within its passes; the last pass was used", mn->solve_fallbacks);
}

const bd_belt_ops bd_moving_node_ops = {
    .name = "moving_node",
    .description = "moving_node (2D belt, nodes fixed in space, seed 003)",
    .node_dof = 2,
    .dof_text = "1 per node along the path, 1 more per span node, 1 per pulley, 1 per moving "
                "takeup; idlers are no bodies",
    .build = bd_mn_build,
    .free = bd_mn_free,
    .free_model = bd_mn_free_model,
    .clone = bd_mn_clone,
    .stable_step = bd_mn_stable_step,
    .estimate = bd_mn_estimate,
    .forces = bd_mn_forces,
    .wrap = bd_mn_wrap,
    .supports = bd_mn_solve,
    .integrate = bd_mn_integrate,
    .rest_velocities = bd_mn_rest_velocities,
    .after_parts = bd_mn_takeup_geometry,
    .material = bd_mn_material,
    .potential = bd_mn_potential,
    .elastic_energy = bd_mn_elastic_energy,
    .wrap_energy = bd_station_wrap_energy,
    .support_inertia = bd_station_support_inertia,
    .point_init = point_init,
    .point_update = bd_station_point_update,
    .sample = bd_station_sample,
    .element_s = element_s,
    .element_speed = bd_station_element_speed,
    .element_strain = element_strain,
    .node_speed = bd_station_node_speed,
    .report_events = report_events,
    .records_lift_off = 1,
};
