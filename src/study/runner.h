/* The case runner (runner.c): a list of jobs, each one run of the
 * simulator, run in this process, in N forked worker processes on this
 * machine, or across the ranks of an MPI job (ranks.h), and each job's
 * result gathered in one process as it finishes. Jobs are handed out one
 * at a time to whichever worker is free, the longest (by estimated cost)
 * first, so that a long job does not start last. `study` uses it, and so
 * will `cases`. */
#ifndef BD_STUDY_RUNNER_H
#define BD_STUDY_RUNNER_H

#include <signal.h>
#include <stddef.h>

#include "beltdyn/sim.h"

#define BD_JOB_MESSAGE 1024

/* what one job gives back: plain bytes, so that it crosses a pipe or an
 * MPI message unchanged, bit for bit */
typedef struct bd_job_result {
    int job;                       /* its index */
    int status;                    /* BD_RUN_* */
    double wall_s;                 /* its wall time */
    bd_run_result res;             /* what the run compares by */
    char message[BD_JOB_MESSAGE];  /* why it did not complete, or "" */
} bd_job_result;

/* what a job uses while it runs: give progress and interrupted to
 * bd_sim_run (the progress call is also where a worker hears that the
 * study was interrupted), message for its warnings */
typedef struct bd_job_env {
    bd_progress_fn progress;
    void *progress_ctx;
    void (*message)(const char *line, void *ctx);
    void *message_ctx;
    volatile sig_atomic_t *interrupted;
} bd_job_env;

/* run job `job` in this process; out is zeroed and out->job set before */
typedef void (*bd_job_fn)(void *ctx, int job, const bd_job_env *env, bd_job_result *out);

typedef struct bd_runner_progress {
    int total;          /* jobs to run */
    int done;           /* of them finished, whatever their status */
    int failed;         /* of those, not completed */
    int running;
    int workers;        /* processes running jobs */
    double fraction;    /* of the estimated work, done, 0..1 */
    double wall_s;      /* since the start */
    int finished;       /* 1: the last call */
} bd_runner_progress;

typedef struct bd_runner {
    int count;                   /* jobs 0 .. count-1 */
    const double *cost;          /* [count] estimated cost, any unit, or NULL */
    const unsigned char *todo;   /* [count] 1 to run it, or NULL: all */
    int workers;                 /* worker processes on this machine; 1: the jobs run
                                    in this process. Not used under an MPI launcher
                                    (one rank: the jobs run in this process) */
    int rank, ranks;             /* bd_ranks_begin's; ranks > 1: one worker per rank,
                                    rank 0 hands out, gathers and runs jobs too */
    bd_job_fn run;
    void *run_ctx;
    /* called in the gathering process (rank 0) only: */
    void (*done)(const bd_job_result *r, void *ctx);   /* as each job finishes */
    void *done_ctx;
    void (*progress)(const bd_runner_progress *p, void *ctx);  /* ~4 times a second, or NULL */
    void *progress_ctx;
    void (*message)(const char *line, void *ctx);      /* the jobs' warnings, or NULL */
    void *message_ctx;
    /* nonzero (SIGINT): the running jobs are told to stop, no more start */
    volatile sig_atomic_t *interrupted;
} bd_runner;

/* the processors this process may run on */
int bd_runner_cores(void);

/* run the jobs. Returns BD_RUN_OK when every job was run (whatever each
 * one's status: done() has it), BD_RUN_INTERRUPTED when interrupted
 * (jobs not started are not reported), BD_RUN_FAILED when workers could
 * not be started (message in err). On a rank > 0 it returns when rank 0
 * says there is no more work. */
int bd_runner_run(const bd_runner *r, char *err, size_t errlen);

#endif
