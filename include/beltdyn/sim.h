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
    double wall_s;       /* wall time so far */
    int done;            /* 1: the last call of the run */
} bd_run_progress;

typedef void (*bd_progress_fn)(const bd_run_progress *p, void *ctx);

typedef struct bd_run_options {
    const char *out_dir;                  /* directory for the outputs */
    bd_progress_fn progress;              /* called about 4 times a second, or NULL */
    volatile sig_atomic_t *interrupted;   /* set nonzero to stop (SIGINT) */
    int hdf5;                             /* 1: also DIR/tension.h5 */
    void *progress_ctx;                   /* passed to progress */
} bd_run_options;

/* derive the discrete model (path, elements, idlers, time step, initial
 * state). Problems found here (e.g. a time step above the stability limit)
 * go to diag with their file position. 0 = ok. The sim keeps a pointer to
 * def: def must outlive it. */
int bd_sim_create(const bd_model_def *def, bd_sim **out, bd_diag *diag);
void bd_sim_free(bd_sim *sim);

/* what `beltdyn check` prints: loop length, elements, dof, time step and
 * what limits it, idlers per span, masses */
void bd_sim_describe(const bd_sim *sim, FILE *f);

/* relax to static equilibrium if the model asks for it (called by run) */
int bd_sim_stabilize(bd_sim *sim, FILE *log);

/* advance n steps; returns 0, or 1 when the run failed (message in err) */
int bd_sim_step(bd_sim *sim, long n, char *err, size_t errlen);

/* the whole run with outputs; returns one of BD_RUN_*; message in err */
int bd_sim_run(bd_sim *sim, const bd_run_options *opt, char *err, size_t errlen);

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
    double travel_range_m;         /* largest (max − min) over the takeups */
    double tension_max_N, tension_min_N;  /* anywhere in the belt */
} bd_run_result;

void bd_sim_result(const bd_sim *sim, bd_run_result *r);

/* a few read-outs for tests and tools */
double bd_sim_time(const bd_sim *sim);
double bd_sim_time_step(const bd_sim *sim);
int bd_sim_node_count(const bd_sim *sim);

#ifdef __cplusplus
}
#endif
#endif
