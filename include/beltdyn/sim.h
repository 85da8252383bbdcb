/* beltdyn transient simulation: build a simulation from a validated model,
 * step it, run it to completion writing the outputs of cli.md. */
#ifndef BELTDYN_SIM_H
#define BELTDYN_SIM_H

#include <signal.h>
#include <stdio.h>

#include "beltdyn/model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct bd_sim bd_sim;
/* a compiled model: everything derived from a definition that no step
 * changes, with the state at t = 0; shareable between runs and threads */
typedef struct bd_model bd_model;

/* exit statuses of bd_sim_run, as the command uses them (cli.md) */
enum {
    BD_RUN_OK = 0,
    BD_RUN_FAILED = 1,       /* diverged, element reversed, takeup limit */
    BD_RUN_BAD_INPUT = 2,
    BD_RUN_INTERRUPTED = 130
};

/* where a run stands, for a progress display (the library prints nothing) */
typedef struct bd_run_progress {
    double t_s;          /* simulated time reached */
    double duration_s;   /* simulated time asked for */
    double wall_s;       /* wall time so far (of the stabilization while it
                            runs, then of the simulated time) */
    int done;            /* 1: the last call of the run */
    long stabilize_steps; /* > 0: still relaxing before t = 0 (stabilize),
                             this many steps so far; t_s is then 0 */
} bd_run_progress;

typedef void (*bd_progress_fn)(const bd_run_progress *p, void *ctx);

typedef struct bd_run_options {
    const char *out_dir;                  /* directory for the outputs */
    bd_progress_fn progress;              /* called about 4 times a second, or NULL */
    volatile sig_atomic_t *interrupted;   /* set nonzero to stop (SIGINT) */
    int hdf5;                             /* 1: also DIR/tension.h5 */
    void *progress_ctx;                   /* passed to progress */
    /* a warning said when it arises, one line (a stabilization that did
     * not reach rest; the run goes on); it is in summary.json's warnings
     * too. NULL: only there */
    void (*message)(const char *line, void *ctx);
    void *message_ctx;                    /* passed to message */
    long stabilize_max_steps;             /* 0: 2 000 000 (bd_sim_stabilize) */
    /* > 0: the run's records (extremes of tension, torque, travel, the
     * drive monitors, probes, lift-off, the envelope) start again at this
     * time, s: a stop case's peaks without its start's (cases). The time
     * history keeps the whole run; summary.json says `records_from_s` */
    double records_from_s;
    /* > 0: from this time on the run ends early once every pulley's
     * surface has stayed below 0.02 m/s for 0.5 s (a stop case: the belt
     * has stopped); simulation.duration stays the limit */
    double end_at_rest_after_s;
} bd_run_options;

/* derive the discrete model (path, elements, idlers, time step, initial
 * state). Problems found here (e.g. a time step above the stability limit)
 * go to diag with their file position. 0 = ok. The sim keeps a pointer to
 * def: def must outlive it. */
int bd_sim_create(const bd_model_def *def, bd_sim **out, bd_diag *diag);
void bd_sim_free(bd_sim *sim);

/* the same in two steps: compile the model once (problems in diag, 0 ok),
 * then start any number of runs on it, each at t = 0 with a state of its
 * own (0 ok). bd_sim_create_from does not change the model, nor does
 * stepping or running a simulation made from it; free the simulations
 * first, the model last. def must outlive the model. */
int bd_model_compile(const bd_model_def *def, bd_model **out, bd_diag *diag);
int bd_sim_create_from(const bd_model *model, bd_sim **out);
void bd_model_free(bd_model *model);

/* what `beltdyn check` prints: loop length, elements, dof, time step and
 * what limits it, idlers per span, masses */
void bd_sim_describe(const bd_sim *sim, FILE *f);

/* relax to static equilibrium by kinetic-energy damping (seed 001 §6.2;
 * bd_sim_run calls it first when the model has simulation.stabilize): the
 * clock stays at t = 0 (every table is read there), drives are off and
 * their pulleys held as a holdback would hold them, friction is on, no
 * material is fed; all velocities are zeroed at each kinetic-energy peak
 * until the peaks fall below 1e-7 of the belt's elastic energy. Then the
 * drive pulleys are let go and the run's clock, travel and statistics
 * start from zero. opt may be NULL; its interrupted flag stops it, its
 * progress is called about 4 times a second (stabilize_steps > 0), its
 * stabilize_max_steps bounds the steps; its out_dir, hdf5 and message are
 * not used. Returns
 *   BD_RUN_OK: at rest (err empty), or not at rest after the step limit:
 *     err then holds the warning (also in the warnings), the state is
 *     the one reached and a run may go on from it;
 *   BD_RUN_FAILED: it diverged; err says when, where and why;
 *   BD_RUN_INTERRUPTED: *opt->interrupted became nonzero. */
int bd_sim_stabilize(bd_sim *sim, const bd_run_options *opt, char *err, size_t errlen);

/* advance n steps; returns 0, or 1 when the run failed (message in err) */
int bd_sim_step(bd_sim *sim, long n, char *err, size_t errlen);

/* turn the events the steps only recorded (a takeup at the end of its
 * travel, a slack belt end at an axial pulley) into warnings; bd_sim_run
 * does this at its end, a program stepping a simulation itself calls it
 * before reading the warnings. Saying them twice adds nothing. */
void bd_sim_report_events(bd_sim *sim);

/* the run's records start again from the state now (bd_run_options
 * records_from_s): tension, probe and torque extremes, takeup travel range
 * (from the travel now), drive monitors, lift-off */
void bd_sim_records_restart(bd_sim *sim);

/* the whole run with outputs; returns one of BD_RUN_*; message in err */
int bd_sim_run(bd_sim *sim, const bd_run_options *opt, char *err, size_t errlen);

/* make ready the directory a run is to write (cli.md): an empty or missing
 * one is used as it is; one holding an earlier run loses that run's
 * report, plots and tension.h5, which would no longer describe the
 * outputs; one holding anything else is refused (BD_RUN_BAD_INPUT and a
 * message in err) unless force, and then keeps its files. BD_RUN_OK. */
int bd_run_dir_prepare(const char *dir, int force, char *err, size_t errlen);

/* what a start study compares (monitor.c), over the run so far. The
 * tight side is a point of the belt just before a drive pulley's wrap, the
 * slack side one just after it; with several drives, the extreme over
 * them. Slip: the drive pulley's surface speed differed from the belt
 * speed at it by more than 0.05 m/s + 2% of the surface speed for at least
 * 0.2 s. Belt acceleration: of the belt at the tight-side point, from its
 * speed averaged over 0.1 s windows. */
typedef struct bd_run_result {
    int drives;                    /* number of drive pulleys (0: the drive
                                      values below are not meaningful) */
    double tight_max_N, tight_max_t_s;
    double slack_min_N, slack_min_t_s;
    double tight_swing_N;          /* max − min tight-side tension after the
                                      start curve reached full speed */
    double accel_max_mps2, accel_max_t_s;  /* signed, largest magnitude */
    double torque_max_Nm;          /* largest |drive torque| */
    int slipped;
    double slip_t_s;               /* when the first confirmed slip began, or -1 */
    double slip_longest_s;         /* longest time above the threshold */
    double slip_speed_max_mps;     /* largest |surface − belt| speed */
    /* the most of its wrap's friction any drive used, ln(T_hi/T_lo)/(μ_s·φ)
     * of its tight and slack sides (the belt begins to slip at 1) */
    double friction_used_max;
    double travel_range_m;         /* largest (max − min) over the takeups */
    double tension_max_N, tension_min_N;  /* anywhere in the belt */
    double tension_max_t_s, tension_max_s_m;  /* when and where the largest was */
    int static_warnings;           /* the static design's warnings that
                                      bd_sim_run wrote into summary.json
                                      (its failure counts as one) */
} bd_run_result;

void bd_sim_result(const bd_sim *sim, bd_run_result *r);

/* Steady running against the model's own resistance law (sensors/
 * running.c): the invariant issue 10 holds every generated conveyor to,
 * kept on every run. The drives' force on the belt, Σ(τ − b·ω)/R, and the
 * belt speed at the first drive's tight side are averaged (Hann-weighted)
 * over each of the run's last three windows of 3 s (6 s with a motor
 * drive), and held to the law (bd_running_law) at the mean speed, plus
 * the resistances design.secondary: individual adds (the pulleys' own
 * from the live tensions, the skirts and the loading at its own speed).
 * Judged when the speed is steady (the windows within 0.25 %) and every
 * window agrees with the verdict beyond the windows' spread and what a
 * takeup still moving could shift them by; force_N and error_rel are the
 * three windows' mean, so that pass ⇔ |error_rel| ≤ tolerance_rel. */
typedef struct bd_running_check {
    int checked;            /* 1: held to the law (the run ended steady) */
    int pass;               /* checked and |error_rel| ≤ tolerance_rel */
    char why[400];          /* not checked: why, in words */
    double from_s, to_s;    /* the three windows force and speed are the means of */
    double force_N;         /* the drives' mean force on the belt */
    double law_N;           /* the law at speed_mps */
    double scale_N;         /* the law's terms summed in magnitude */
    double error_rel;       /* (force − law) / max(scale, 1 N) */
    double tolerance_rel;   /* 0.03 (discrete, rfe: nodes pass the idlers)
                               or 0.01 (axial, moving_node) */
    double speed_mps;
    double spread_mps;      /* the three windows' speeds: largest less smallest */
} bd_running_check;
/* turn the averaging on for windows that end at end_s (bd_sim_run does,
 * at simulation.duration); before the first step of the run */
void bd_sim_running_start(bd_sim *sim, double end_s);
void bd_sim_running_check(const bd_sim *sim, bd_running_check *out);

/* The mesh check (`beltdyn run --mesh-check`, io/mesh_check.c): the same
 * model run again on elements half as long, and the figures an engineer
 * reads first compared. Each is judged within 2 % (issue 10: running
 * force and peak tight-side tension must change by less than that when
 * the element length halves). */
#define BD_MESH_QUANTITIES 8
typedef struct bd_mesh_quantity {
    char name[64];
    char unit[8];
    double coarse, fine;   /* the run's, the finer run's */
    double change_rel;     /* (fine − coarse)/|coarse| */
    int pass;              /* |change_rel| ≤ tolerance_rel */
} bd_mesh_quantity;
typedef struct bd_mesh_check {
    char mesh[160];        /* the two meshes in words */
    int count;
    bd_mesh_quantity q[BD_MESH_QUANTITIES];
    double tolerance_rel;
    int converged;         /* every quantity compared passed */
    double fine_wall_s;
    /* the steady running force not compared: why (a run did not judge
     * it, sensors/running.c); "" when compared */
    char running_force_why[440];
} bd_mesh_check;
/* set def's element keys to half of what `coarse` was built with (def
 * loaded from the same file: element_length, or the moving-node belt's
 * wrap_element_angle and span_element_length); the finer run writes only
 * the first and last rows of its tension field. Says the meshes in
 * mc->mesh. */
void bd_mesh_refine(const bd_sim *coarse, bd_model_def *def, bd_mesh_check *mc);
/* compare the two finished runs (mc->mesh and fine_wall_s kept) */
void bd_mesh_compare(const bd_sim *coarse, const bd_sim *fine, bd_mesh_check *mc);
/* add mc to DIR/summary.json as "mesh_check", and a warning when it did
 * not converge (rewritten whole, by a temporary name). 0 ok */
int bd_mesh_check_write(const char *dir, const bd_mesh_check *mc, char *err, size_t errlen);

/* Read-outs of the state now, for tests, tools and programs that step a
 * simulation themselves. They change nothing. */
double bd_sim_time(const bd_sim *sim);           /* s */
double bd_sim_time_step(const bd_sim *sim);      /* s */
int bd_sim_node_count(const bd_sim *sim);
const char *bd_sim_formulation(const bd_sim *sim);   /* "discrete", "axial" */
double bd_sim_belt_length(const bd_sim *sim);    /* m, the loop's path at t = 0 */
/* m, length of the span leaving pulley i */
double bd_sim_span_length(const bd_sim *sim, int pulley);
/* where the span leaving pulley `pulley` starts and ends on the path at
 * t = 0 (the tangent points), m; 0 ok, -1 out of range */
int bd_sim_span_ends(const bd_sim *sim, int pulley, double start[2], double end[2]);

typedef struct bd_node_state {
    double x_m, y_m;           /* position */
    double vx_mps, vy_mps;     /* velocity (at the last half step) */
    double mass_kg;            /* belt and material */
    double tension_N;          /* of the element from this node to the next */
} bd_node_state;
/* node i (0 ≤ i < node count); 0 ok, -1 out of range */
int bd_sim_node(const bd_sim *sim, int i, bd_node_state *out);
/* the belt's mean speed along itself, momentum / mass, m/s */
double bd_sim_belt_speed(const bd_sim *sim);
/* total mass of belt and material, kg */
double bd_sim_belt_mass(const bd_sim *sim);

typedef struct bd_pulley_state {
    double omega_rad_s;        /* + drives the belt forward */
    double drive_torque_Nm;    /* drive (or transmission) torque this step */
    double travel_m;           /* takeup carriage travel along its axis */
    double x_m, y_m;           /* centre */
    double radius_m, inertia_kgm2;
    int has_transmission;
    double motor_omega_rad_s;  /* transmission: motor sheave speed */
    double slip_motor_mps, slip_pulley_mps;  /* transmission: belt slip on each sheave */
} bd_pulley_state;
int bd_sim_pulley_count(const bd_sim *sim);
int bd_sim_pulley(const bd_sim *sim, int i, bd_pulley_state *out);

typedef struct bd_takeup_state {
    double travel_m;           /* m, carriage travel along its axis now */
    double travel_min_m, travel_max_m;  /* m, its extremes over the run so far */
    int limit_hits;            /* times it arrived at a travel limit so far */
} bd_takeup_state;
/* the takeup (gravity or constant force) on pulley i; -1 when it has none */
int bd_sim_takeup(const bd_sim *sim, int pulley, bd_takeup_state *out);

typedef struct bd_idler_state {
    double x_m, y_m;           /* centre */
    double radius_m, inertia_kgm2, omega_rad_s;
    int set;                   /* its entry in the model's idlers list */
} bd_idler_state;
/* idlers as bodies (the discrete belt; the axial belt spreads them and
 * has none) */
int bd_sim_idler_count(const bd_sim *sim);
int bd_sim_idler(const bd_sim *sim, int i, bd_idler_state *out);
/* idler set k as laid: how many idlers, at what actual spacing (m) */
int bd_sim_idler_set(const bd_sim *sim, int k, int *count, double *spacing_m);

/* the model's own resistance law in steady running (sim/running_law.c):
 * the drive force that keeps the belt at v, from what the model declares,
 * F(v) = idlers·sgn(v) + lift + feed_mass·v·|v| + bearings·v */
typedef struct bd_running_law {
    double idlers;     /* N, rr·N summed over every idler, belt and load */
    double lift;       /* N, the load raised from its feed to its discharge */
    double feed_mass;  /* kg/m, the load brought to belt speed at the feed */
    double bearings;   /* N·s/m, Σ b/R² of the pulleys the belt turns */
} bd_running_law;
void bd_running_law_build(const bd_sim *sim, bd_running_law *law);
/* N at v m/s; *scale (may be NULL): the terms summed in magnitude */
double bd_running_law_force(const bd_running_law *law, double v, double *scale);

typedef struct bd_probe_state {
    double tension_N, speed_mps;   /* the belt at the probe now */
    double belt_x_m, belt_y_m;     /* where the belt is there now */
    double x_m, y_m, s_m;          /* the probe's fixed point on the path */
} bd_probe_state;
int bd_sim_probe_count(const bd_sim *sim);
int bd_sim_probe(const bd_sim *sim, int i, bd_probe_state *out);

/* the energy account (cli.md `energy`): kinetic at the last mid step,
 * potential as last booked (each output time, or every step once asked
 * for), dissipated and input so far, E_0 at the start */
typedef struct bd_energy_state {
    double kinetic_J, potential_J, dissipated_J, input_J, initial_J;
    double balance_error_rel;      /* largest so far */
    double dissipation_fall_rel;   /* largest fall of dissipated between checks, same scale */
} bd_energy_state;
void bd_sim_energy(const bd_sim *sim, bd_energy_state *out);
/* book the potential energy in every step from now on (slower) */
void bd_sim_book_energy_every_step(bd_sim *sim, int on);
/* the potential energy of the state now, J: gravity, the belt's and the
 * parts' elastic energy and what the contact springs hold (as of the last
 * step; none before the first), as bd_sim_energy counts it */
double bd_sim_potential_energy(const bd_sim *sim);

int bd_sim_warning_count(const bd_sim *sim);
const char *bd_sim_warning(const bd_sim *sim, int i);

#ifdef __cplusplus
}
#endif
#endif
