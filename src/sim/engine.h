/* The engine: building a simulation, the one step loop, the stable time
 * step, stabilization and the energy account (sim/). Everything below
 * (belt formulations, parts, sensors) it reaches through their headers. */
#ifndef BD_ENGINE_H
#define BD_ENGINE_H

#include "belt/belt.h"

/* step.c */
int bd_step_once(bd_sim *sim);
/* the forces phase alone (belt, part torques, wrap coupling, supports) at
 * the state now; 0, or 1 when it diverged (message in sim->fail_msg) */
int bd_step_forces(bd_sim *sim);
/* v(−Δt/2) for a start from rest */
int bd_sim_start_at_rest(bd_sim *sim);   /* 1: the forces failed (fail_msg) */
/* the run's records of belt tension and lift-off cleared: a run starts
 * (build) or starts again after stabilizing (step.c) */
void bd_run_records_clear(bd_sim *sim);
/* stabilize.c: a belt whose layout is not its own equilibrium
 * (bd_belt_ops settle_time) let go there before t = 0 (the build calls
 * it); 0, or 1 when it diverged (message in sim->fail_msg) */
int bd_sim_settle(bd_sim *sim);

/* pulley_resistance.c: each pulley's own resistance (design.secondary:
 * individual): its tension points placed (build, after the time step), and
 * its force from the tensions there (every step, after the belt's forces) */
void bd_pulley_resistance_init(bd_sim *sim);
void bd_pulley_resistance_update(bd_sim *sim);

/* bounds.c: the parts' physical bounds (build: bd_bounds_prepare sets
 * model->speed_bound and travel_bound; step: 0, or 1 with the message in
 * sim->fail_msg) */
void bd_bounds_prepare(bd_model *model);
int bd_bounds_check(bd_sim *sim);

/* estimate.c: what a run costs (model->cost). Before the build: 0, or 1
 * when refused (the error in diag; a long run gets a warning there); after
 * it, the nodes and the step actually made. Bytes and seconds as text. */
int bd_cost_estimate(bd_sim *sim, bd_diag *diag);
/* idler_turn.c: idler set k's turn φ of the discrete belt without bending
 * stiffness at rest and its speed over its wave speed (0: not that belt,
 * or no such span); the warning where φ and v/c are large */
int bd_idler_turn(const bd_sim *sim, int k, double *phi, double *v_over_c);
void bd_idler_turn_warn(bd_sim *sim);
/* how many of idler set k's idlers press on the discrete belt's quintic
 * running line (belt/lumped/idler_contact.c; on a vertical curve the
 * path's turn may put some of a set on it and not others) */
int bd_idler_set_quintic(const bd_sim *sim, int k);
/* sag_compliance.c: warned where the belt's elements leave out much of the
 * sag that its idler bays add to its axial compliance */
void bd_sag_compliance_warn(bd_sim *sim);
/* the same estimate of a definition over `duration` s, from its path and
 * its formulation's `estimate`, without a simulation: counts, step, bytes,
 * seconds (not the memory available; the study orders its cases by it).
 * 0, or -1 when the formulation or the path cannot be had (loop: the
 * path's length, m, or NULL) */
int bd_cost_from_def(const bd_model_def *def, double duration, bd_cost *c, double *loop);
void bd_cost_update(bd_sim *sim);
void bd_cost_bytes_text(double bytes, char *buf, size_t len);
void bd_cost_time_text(double s, char *buf, size_t len);

/* energy.c */
double bd_energy_potential(const bd_sim *sim);
/* the fall of the dissipated energy between two output times, over the
 * energy scale, that a run reports as negative dissipation */
#define BD_DISSIPATION_FALL_WARN 1e-3
void bd_energy_update_balance(bd_sim *sim);
/* the dissipated and input energy at t, where kinetic and potential are */
void bd_energy_at_t(const bd_energy *en, double *dissipated, double *input);

/* the tension field, for the writers: element e's midpoint path
 * coordinate and speed (the formulation's) */
double bd_element_s(const bd_sim *sim, int e);
double bd_element_speed(const bd_sim *sim, int e);

#endif
