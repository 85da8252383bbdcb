/* Idlers as bodies (seed 001 eq 4.69): each turns under the belt's friction
 * torque that the belt formulation's support contact found this step. */
#include "parts/parts.h"

void bd_idlers_advance(bd_sim *sim, double *ke, double *w_nc)
{
    const double dt = sim->model->dt;
    /* the sums kept in registers (through the pointers they would be
     * stored and reloaded every idler: they may alias the idlers), added
     * in the same order */
    double k = *ke, w = *w_nc;
    for (int i = 0; i < sim->model->idler_count; i++) {
        bd_idler *id = &sim->idlers[i];
        if (id->lazy)
            continue;
        double w_mid = id->omega + 0.5 * id->alpha * dt;
        k += 0.5 * id->m->inertia * w_mid * w_mid;
        w += id->torque * w_mid * dt;
        id->omega += id->alpha * dt;
    }
    *ke = k;
    *w_nc = w;
}
