/* Stable time step of the explicit central-difference scheme (timestep.c) */
#ifndef BD_TIMESTEP_H
#define BD_TIMESTEP_H

#include "sim/engine.h"

/* safety factor applied to the stability limit for `time_step: auto` */
#define BD_TIME_STEP_SAFETY 0.8

/* sets sim->model->dt, dt_limit and what limits it; a user step above the limit
 * is an error in diag. 0 = ok */
int bd_time_step_choose(bd_sim *sim, bd_diag *diag);
const char *bd_time_step_limit_name(bd_time_step_limit kind);

#endif
