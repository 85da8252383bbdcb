/* The RFE belt's entry in the formulation table (belt/belt.h): the
 * lumped chain's contacts, sensors and tension field (the elements' mass
 * centres are its nodes), the rigid elements' own forces, rotation and
 * energy. */
#include "belt/rfe/rfe.h"

const bd_belt_ops bd_rfe_ops = {
    .name = "rfe",
    .description = "rfe (rigid finite elements joined by spring-damping elements)",
    .node_dof = 3,
    .dof_text = "3 per element (x, y, phi), 1 per pulley and idler, 1 per moving takeup",
    .build = bd_rfe_build,
    .free = bd_rfe_free,
    .free_model = bd_rfe_free_model,
    .clone = bd_rfe_clone,
    .stable_step = bd_rfe_stable_step,
    .settle_time = bd_rfe_settle_time,
    .estimate = bd_rfe_estimate,
    .forces = bd_rfe_forces,
    .wrap = bd_lumped_wrap,
    .supports = bd_rfe_supports,
    .integrate = bd_rfe_integrate,
    .rest_velocities = bd_rfe_rest_velocities,
    /* variable topology: sections released and tied for the next step,
     * after the idlers have turned (a section giving its rolls back
     * writes their speeds: sections.c unstick) */
    .after_parts = bd_rfe_sections_regroup,
    /* material adds to the centres' mass, not to J (build.c) */
    .material = bd_rfe_material,
    .potential = bd_rfe_potential,
    .elastic_energy = bd_rfe_elastic_energy,
    /* the shell contacts' springs: bd_energy `springs` (pulley_contact.c) */
    .wrap_energy = NULL,
    .support_inertia = bd_lumped_support_inertia,
    .point_init = bd_tracker_init,
    .point_update = bd_rfe_point_update,
    .sample = bd_lumped_sample,
    .element_s = bd_lumped_element_s,
    .records_lift_off = 1,
    .element_speed = bd_lumped_element_speed,
    .element_strain = bd_lumped_element_strain,
    .node_speed = bd_lumped_node_speed,
    .report_events = NULL,
    .topology = bd_rfe_topology,
    .sync = bd_rfe_sync,
};
