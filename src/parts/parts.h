/* The parts a belt runs on and is driven by, one file each: pulley.c (the
 * rotating body and its carriage), drive.c, takeup.c, transmission.c,
 * idler.c. Parts never know which belt formulation carries them: they
 * read what the formulation's wrap coupling left in the pulley body
 * (alpha, torque_friction, f_axis, fnc_axis) and nothing else of the belt. */
#ifndef BD_PARTS_H
#define BD_PARTS_H

#include "model/system.h"

/* pulley.c */
/* what every pulley body takes from its definition (build) */
void bd_pulley_body_init(bd_sim *sim, bd_pulley_body *p, const bd_pulley_def *pd);
/* part torques phase: the drive's (or transmission's) and the bearing's
 * torque on pulley p this step */
double bd_pulley_external_torque(bd_sim *sim, bd_pulley_body *p);
/* parts advance phase: pulley rotations, transmissions and takeup
 * carriages to the next step; adds their kinetic energy to *ke and their
 * non-conservative work to *w_nc */
void bd_pulleys_advance(bd_sim *sim, double *ke, double *w_nc);

/* idler.c: idler rotations to the next step (parts advance phase) */
void bd_idlers_advance(bd_sim *sim, double *ke, double *w_nc);

/* drive.c */
/* tune the speed loop for the inertia it moves (build) */
void bd_drive_prepare(bd_sim *sim, bd_pulley_body *p, double reflected_inertia);
double bd_drive_torque(const bd_sim *sim, bd_pulley_body *p);

/* takeup.c */
double bd_takeup_force(const bd_sim *sim, const bd_pulley_body *p, double t);
/* advance the carriage one step; returns the non-conservative work done on
 * it this step (J) and adds the set-point work to *input */
double bd_takeup_advance(bd_sim *sim, bd_pulley_body *p, double *input);

/* transmission.c: belt transmissions of drives (seed 004) */
int bd_transmissions_create(bd_sim *sim, bd_diag *diag);
/* torque of the transmission on its pulley this step */
double bd_transmission_torque(bd_sim *sim, bd_pulley_body *p);
/* advance the transmission over the step in which its pulley went from
 * omega_old to p->omega; books its energy */
void bd_transmission_advance(bd_sim *sim, bd_pulley_body *p, double omega_old, double *ke,
                             double *w_nc);
void bd_transmissions_free(bd_sim *sim);
/* after the drives are prepared: the speed loops of transmission drives */
void bd_transmissions_tune(bd_sim *sim);
/* elastic energy of the transmissions' spans, J */
double bd_transmissions_potential(const bd_sim *sim);
/* motor sheave speed (rad/s) and the belt's slip on both sheaves (m/s) */
void bd_transmission_state(const bd_pulley_body *p, double *w_motor, double *slip_motor,
                           double *slip_pulley);
/* largest slip of the belt on either sheave so far, m/s */
double bd_transmission_slip_max(const bd_pulley_body *p);

#endif
