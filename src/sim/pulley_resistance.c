/* A pulley's own resistance in a run (design.secondary: individual): the
 * same wrap, bearing and cleaner resistances as the static calculation
 * (model/secondary.c, ISO 5048 Table 3), from the belt tensions just
 * before and after its wrap at each step, acting on its surface against
 * its motion (parts/pulley.c adds it to the bearing torque, so its work is
 * booked as dissipated). O(pulleys) per step. */
#include "sim/engine.h"

#include <math.h>

#include "laws/rolling.h"
#include "model/secondary.h"
#include "sensors/sensors.h"

void bd_pulley_resistance_init(bd_sim *sim)
{
    const int n = sim->model->pulley_count;
    for (int i = 0; i < n; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        if (!p->m->resistance.active)
            continue;
        double s_in, s_out;
        bd_wrap_side_points(sim, i, &s_in, &s_out);
        sim->model->belt->point_init(sim, &p->res_in, s_in);
        sim->model->belt->point_init(sim, &p->res_out, s_out);
        p->res_force = 0.0;
        p->res_fade = BD_ROLLING_SPEED;
    }
}

void bd_pulley_resistance_update(bd_sim *sim)
{
    const bd_belt_ops *belt = sim->model->belt;
    const int n = sim->model->pulley_count;
    for (int i = 0; i < n; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        if (!p->m->resistance.active)
            continue;
        bd_belt_sample in, out;
        belt->point_update(sim, &p->res_in);
        belt->point_update(sim, &p->res_out);
        belt->sample(sim, &p->res_in, &in);
        belt->sample(sim, &p->res_out, &out);
        const double *u_in, *u_out;
        bd_path_wrap_dirs(&sim->model->path, i, &u_in, &u_out);
        bd_pulley_resistance r;
        bd_secondary_pulley_eval(&p->m->resistance, in.tension, out.tension, u_in, u_out, &r);
        p->res_force = r.wrap + r.bearing + r.cleaners;
        /* faded for the explicit step on the pulley's own inertia */
        double R = p->m->radius;
        p->res_fade = bd_coulomb_fade(p->res_force, R * R, sim->model->dt, p->m->inertia);
    }
}
