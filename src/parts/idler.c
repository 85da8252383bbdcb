/* Idlers as bodies (seed 001 eq 4.69): each turns under the belt's friction
 * torque that the belt formulation's support contact found this step. */
#include "parts/parts.h"

void bd_idlers_advance(bd_sim *sim, double *ke, double *w_nc)
{
    const double dt = sim->model->dt;
    for (int i = 0; i < sim->model->idler_count; i++) {
        bd_idler *id = &sim->idlers[i];
        double w_mid = id->omega + 0.5 * id->alpha * dt;
        *ke += 0.5 * id->m->inertia * w_mid * w_mid;
        *w_nc += id->torque * w_mid * dt;
        id->omega += id->alpha * dt;
    }
}
