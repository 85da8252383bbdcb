/* Probes (model-format.md `simulation.probes`): a point fixed on the path
 * where the belt's tension and speed are recorded at every output time. */
#include "sensors/sensors.h"

void bd_sensors_update(bd_sim *sim)
{
    const bd_belt_ops *belt = sim->model->belt;
    for (int i = 0; i < sim->model->probe_count; i++)
        belt->point_update(sim, &sim->probes[i].tr);
    for (int i = 0; i < sim->model->pulley_count; i++)
        if (sim->pulleys[i].m->def->has_drive)
            bd_monitor_update(sim, &sim->pulleys[i]);
    bd_lift_off_update(sim);
    bd_running_update(sim);
}

void bd_probe_read(bd_sim *sim, bd_probe *pr)
{
    bd_belt_sample b;
    sim->model->belt->sample(sim, &pr->tr, &b);
    pr->tension = b.tension;
    pr->speed = b.speed;
    if (pr->tension > pr->tension_max)
        pr->tension_max = pr->tension;
    if (pr->tension < pr->tension_min)
        pr->tension_min = pr->tension;
}
