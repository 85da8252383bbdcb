/* Belt transmissions between a drive's motor and its pulley (seed 004). */
#include "sim/system.h"

int bd_transmissions_create(bd_sim *sim, bd_diag *diag)
{
    const bd_model_def *def = sim->def;
    int bad = 0;
    for (int i = 0; i < def->pulley_count; i++)
        if (def->pulleys[i].has_drive && def->pulleys[i].drive.has_transmission) {
            bd_diag_error(diag, def->source, def->pulleys[i].drive.mark,
                          "pulleys[%d].drive.transmission: not yet available", i);
            bad = 1;
        }
    return bad;
}

void bd_transmissions_free(bd_sim *sim)
{
    (void)sim;
}

double bd_transmission_torque(bd_sim *sim, bd_pulley_body *p)
{
    (void)sim;
    (void)p;
    return 0.0;
}

void bd_transmission_advance(bd_sim *sim, bd_pulley_body *p, double omega_old, double *ke,
                             double *w_nc)
{
    (void)sim;
    (void)p;
    (void)omega_old;
    (void)ke;
    (void)w_nc;
}
