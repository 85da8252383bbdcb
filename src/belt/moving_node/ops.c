/* The moving-node belt's entry in the formulation table (belt/belt.h):
 * what the sensors read and the events said after the run. */
#include "belt/moving_node/moving_node.h"

#include <math.h>

/* a point fixed on the path: its place between the two nodes around it,
 * which stay where they are */
static void point_init(const bd_sim *sim, bd_tracker *tr, double s)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    bd_belt_point_place(sim, tr, s);
    int lo = tr->element;
    double rel = tr->s - sim->model->s_node0[lo];
    if (rel < 0.0) {
        tr->element = sim->model->n - 1;
        rel = tr->s + sim->model->path.length - sim->model->s_node0[sim->model->n - 1];
    }
    tr->gamma = rel / mm->ds0[tr->element];
}

static void point_update(const bd_sim *sim, bd_tracker *tr)
{
    (void)sim;
    (void)tr;
}

static void sample(const bd_sim *sim, const bd_tracker *tr, bd_belt_sample *out)
{
    int e = tr->element, j = bd_mn_next(e, sim->model->n);
    double g = tr->gamma;
    bd_belt_point_position(sim, tr, &out->x, &out->y);
    out->tension = bd_belt_point_tension(sim, tr);
    out->speed = (1.0 - g) * sim->vx[e] + g * sim->vx[j];
}

static double element_s(const bd_sim *sim, int e)
{
    double s = sim->model->s_node0[e] + 0.5 * bd_mn_model_of(sim)->ds0[e];
    return s < sim->model->path.length ? s : s - sim->model->path.length;
}

static double element_speed(const bd_sim *sim, int e)
{
    return 0.5 * (sim->vx[e] + sim->vx[bd_mn_next(e, sim->model->n)]);
}

static double element_strain(const bd_sim *sim, int e)
{
    const bd_mn *mn = bd_mn_of(sim);
    return mn->len[e] / mn->dX[e] - 1.0;
}

static double node_speed(const bd_sim *sim, int i)
{
    return sim->vx[i];
}

/* the wraps' elastic energy is the belt's own (its arc elements) */
static double wrap_energy(const bd_sim *sim, const bd_pulley_body *p)
{
    (void)sim;
    (void)p;
    return 0.0;
}

/* the idlers' rotating mass is in the node masses already */
static double support_inertia(const bd_sim *sim, double R, double J)
{
    (void)sim;
    (void)R;
    return J;
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
    if (mn->idler_lift_steps > 0)
        bd_sim_warn(sim, "the belt lifted off an idler at t = %.3f s, s = %.2f m, first; "
                    "%ld node-steps in all", mn->idler_lift_first_t,
                    sim->model->s_node0[mn->idler_lift_first_node], mn->idler_lift_steps);
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
    .after_parts = bd_mn_takeup_geometry,
    .material = bd_mn_material,
    .potential = bd_mn_potential,
    .elastic_energy = bd_mn_elastic_energy,
    .wrap_energy = wrap_energy,
    .support_inertia = support_inertia,
    .point_init = point_init,
    .point_update = point_update,
    .sample = sample,
    .element_s = element_s,
    .element_speed = element_speed,
    .element_strain = element_strain,
    .node_speed = node_speed,
    .report_events = report_events,
};
