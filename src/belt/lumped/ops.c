/* The lumped belt's entry in the formulation table (belt/belt.h). */
#include "belt/lumped/lumped.h"

/* the lumped belt has no step that follows the parts' motion: its nodes
 * touch the moving shells through the contact */
const bd_belt_ops bd_lumped_ops = {
    .name = "discrete",
    .description = "discrete (2D lumped-mass belt)",
    .node_dof = 2,
    .dof_text = "2 per node, 1 per pulley and idler, 1 per moving takeup",
    .build = bd_lumped_build,
    .free = bd_lumped_free,
    .free_model = bd_lumped_free_model,
    .clone = bd_lumped_clone,
    .stable_step = bd_lumped_stable_step,
    .estimate = bd_lumped_estimate,
    .forces = bd_lumped_forces,
    .wrap = bd_lumped_wrap,
    .supports = bd_lumped_idlers,
    .integrate = bd_lumped_integrate,
    .after_parts = NULL,
    .material = bd_lumped_material,
    .potential = bd_lumped_potential,
    .elastic_energy = bd_lumped_elastic_energy,
    /* the shell contacts' springs: bd_energy `springs` (pulley_contact.c) */
    .wrap_energy = NULL,
    .support_inertia = bd_lumped_support_inertia,
    .point_init = bd_tracker_init,
    .point_update = bd_tracker_update,
    .sample = bd_lumped_sample,
    .element_s = bd_lumped_element_s,
    .records_lift_off = 1,
    .element_speed = bd_lumped_element_speed,
    .element_strain = bd_lumped_element_strain,
    .node_speed = bd_lumped_node_speed,
    .report_events = NULL,
};
