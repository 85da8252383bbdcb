/* The record of the belt lifting off its idlers (system.h bd_lift_off):
 * where (the stations' range), when (first), how long (the longest run of
 * consecutive steps with a station lifted, and the total). */
#include "sensors/sensors.h"

#include <math.h>

void bd_lift_off_reset(bd_sim *sim)
{
    bd_lift_off *l = &sim->lift;
    *l = (bd_lift_off){0};
    l->first_t = -1.0;
    l->since = -1.0;
    l->s_min = INFINITY;
    l->s_max = -INFINITY;
}

void bd_lift_off_update(bd_sim *sim)
{
    bd_lift_off *l = &sim->lift;
    double dt = sim->model->dt;
    if (l->step_count == 0) {
        l->since = -1.0;
        return;
    }
    if (l->first_t < 0.0) {
        l->first_t = sim->t;
        l->first_s = l->step_s_min;
    }
    if (l->since < 0.0)
        l->since = sim->t - dt;
    l->s_min = fmin(l->s_min, l->step_s_min);
    l->s_max = fmax(l->s_max, l->step_s_max);
    l->total += dt;
    l->longest = fmax(l->longest, sim->t - l->since);
    if (l->step_count > l->max_stations)
        l->max_stations = l->step_count;
    l->step_count = 0;
}

void bd_lift_off_report(bd_sim *sim)
{
    const bd_lift_off *l = &sim->lift;
    if (l->first_t < 0.0)
        return;
    bd_sim_warn(sim, "the belt lifted off its idlers between s = %.2f and %.2f m: first at "
                "t = %.3f s (s = %.2f m), for %.3f s in all, %.3f s at the longest, up to %d "
                "idler stations at once", l->s_min, l->s_max, l->first_t, l->first_s, l->total,
                l->longest, l->max_stations);
}
