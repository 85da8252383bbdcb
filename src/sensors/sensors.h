/* Sensors: probes and drive monitors. They read the belt only through its
 * formulation's point_update and sample (belt/belt.h), so every belt
 * formulation has them with no code of its own. */
#ifndef BD_SENSORS_H
#define BD_SENSORS_H

#include "belt/belt.h"

/* monitor.c: drive monitors (set up in build, reset when a run starts) */
/* s a drive's slip must last to count as slip (the drive monitor) */
#define BD_SLIP_TIME 0.2
void bd_monitor_init(bd_sim *sim, bd_pulley_body *p);
/* the belt points just before and after pulley i's wrap (0.5 m, at most a
 * quarter of the span), path coordinates: where the drive monitor and a
 * pulley's own resistance (sim/pulley_resistance.c) read the tensions */
void bd_wrap_side_points(const bd_sim *sim, int i, double *s_in, double *s_out);
void bd_monitor_reset(bd_sim *sim, bd_pulley_body *p);
double bd_monitor_swing(const bd_drive_monitor *m);
void bd_monitor_update(bd_sim *sim, bd_pulley_body *p);
/* the belt arriving at a drive's wrap and leaving it, read now (its
 * monitor's points moved to the present belt) */
void bd_monitor_sides(bd_sim *sim, bd_drive_monitor *m, bd_belt_sample *in,
                      bd_belt_sample *out);

/* probe.c */
/* the sensors phase of a step: probes follow the belt, drive monitors
 * record (sim->t is the time the positions belong to) */
void bd_sensors_update(bd_sim *sim);
/* the lift-off record (lift_off.c): cleared, the step folded in, said */
void bd_lift_off_reset(bd_sim *sim);
void bd_lift_off_update(bd_sim *sim);
void bd_lift_off_report(bd_sim *sim);
/* running.c: the steady running force's averages (bd_sim_running_start
 * turns them on), every step */
void bd_running_update(bd_sim *sim);
/* a probe's reading now, into its record (output times) */
void bd_probe_read(bd_sim *sim, bd_probe *pr);

#endif
