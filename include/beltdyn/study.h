/* beltdyn studies: one model run once per case, each case a normal run in
 * its own directory, and a table of what the cases are compared by. The
 * cases are the start study's start curves × start times × pre-start
 * delays (issue 4), or a sweep over model keys: a grid (--vary) or a Latin
 * hypercube sample (--sample, --range). They run in parallel: worker
 * processes on this machine, or the ranks of an MPI job under mpirun
 * (issue 16, docs/studies.md). */
#ifndef BELTDYN_STUDY_H
#define BELTDYN_STUDY_H

#include <signal.h>
#include <stdio.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

#define BD_STUDY_MAX 16   /* values per list */
#define BD_STUDY_MAX_KEYS 16  /* varied keys */
#define BD_STUDY_MAX_WHERE 16 /* --where constraints */
#define BD_STUDY_KEY_LEN 256

/* a varied model key: a dotted path into the model file
 * (pulleys.takeup.takeup.mass; a list entry by its name or index) */
typedef struct bd_study_range {
    char key[BD_STUDY_KEY_LEN];
    double lo, hi;       /* the key's values run from lo to hi */
    int n;               /* --vary: grid points (lo and hi included); --range: 0 */
} bd_study_range;

/* a constraint of --best: a table column compared with a value */
typedef enum bd_study_op {
    BD_OP_EQ = 0, BD_OP_NE, BD_OP_LT, BD_OP_LE, BD_OP_GT, BD_OP_GE
} bd_study_op;

typedef struct bd_study_where {
    char column[BD_STUDY_KEY_LEN];
    bd_study_op op;
    char value[128];     /* a number, true/false, or text (case, curve, status) */
} bd_study_where;

/* where the whole study stands, for a progress line */
typedef struct bd_study_progress {
    int cases;           /* in the study */
    int to_run;          /* of them run this time (--resume skips the complete ones) */
    int done, failed, running;
    int workers;         /* processes running cases */
    double fraction;     /* of the estimated work of this time's cases, 0..1 */
    double wall_s, remaining_s;  /* remaining: estimated, < 0 unknown */
    int clear;           /* 1: only erase the line (a table row or a message follows) */
    int finished;        /* 1: the last call */
} bd_study_progress;

typedef void (*bd_study_progress_fn)(const bd_study_progress *p, void *ctx);

typedef struct bd_study_options {
    const char *model_path;
    const char *out_dir;
    int ncurves;
    bd_start_curve curves[BD_STUDY_MAX];
    int ntimes;
    double times[BD_STUDY_MAX];    /* s, start time T (> 0) */
    int ndelays;
    double delays[BD_STUDY_MAX];   /* s, pre-start delay (>= 0) */
    double after;                  /* s run after delay + T; <= 0: the
                                      model's simulation.duration */
    /* a sweep instead of the start study: a grid over nvary keys (their
     * cartesian product, the first key slowest), or `samples` cases of a
     * Latin hypercube over nrange keys drawn with `seed` */
    int nvary;
    bd_study_range vary[BD_STUDY_MAX_KEYS];
    int samples;
    int nrange;
    bd_study_range range[BD_STUDY_MAX_KEYS];
    unsigned long long seed;
    /* 1: the five standard load cases instead (`beltdyn cases`, cli.md):
     * empty_start, loaded_start, loaded_coast_stop, loaded_brake_stop,
     * partial_load_start; tables DIR/cases.csv and DIR/cases.json */
    int load_cases;
    int jobs;                      /* worker processes on this machine; 0: one per
                                      core. Under mpirun: one per rank instead */
    int resume;                    /* 1: keep the cases whose results are complete */
    int force;                     /* 1: write into a non-empty directory that is
                                      not a study's */
    /* the best case: the lowest `best` (a table column; "max:COLUMN" the
     * highest) among the completed cases that meet every `where` */
    const char *best;
    int nwhere;
    bd_study_where where[BD_STUDY_MAX_WHERE];
    bd_study_progress_fn progress; /* the study's progress, or NULL */
    void *progress_ctx;
    /* the model's diagnostics and each failed case's message, one line at
     * a time, or NULL (the library prints nothing) */
    void (*message)(const char *line, void *ctx);
    void *message_ctx;
    volatile sig_atomic_t *interrupted;
} bd_study_options;

/* the defaults: all four curves, T = 10 and 30 s, delays 0 and 3 s, the
 * model's duration */
void bd_study_options_default(bd_study_options *o);

/* "linear", "harrison", "nordell", "s-curve" → curve; 0 ok, -1 unknown */
int bd_start_curve_from_name(const char *name, bd_start_curve *out);
const char *bd_start_curve_name(bd_start_curve c);

/* "KEY=LO:HI:N" (with_n) or "KEY=LO:HI" into out; 0, or -1 and a message */
int bd_study_parse_range(const char *text, int with_n, bd_study_range *out, char *err,
                         size_t errlen);
/* "COLUMN=VALUE" (also !=, <, <=, >, >=) into out; 0, or -1 and a message */
int bd_study_parse_where(const char *text, bd_study_where *out, char *err, size_t errlen);

/* run every case into out_dir/<case>/ (the outputs of `run`) and its
 * result into out_dir/<case>/case.json; the table out_dir/study.csv and
 * out_dir/study.json, in case order, rewritten as cases finish; a row per
 * case on `table` (may be NULL) as each finishes. Returns a BD_RUN_*
 * status: BD_RUN_BAD_INPUT for a bad model or options (messages through
 * `message` as FILE:LINE:COL lines, or in err), BD_RUN_FAILED when a case
 * failed (the others still ran), BD_RUN_INTERRUPTED. Under mpirun every
 * rank calls it; rank 0 writes the tables and says everything. */
int bd_study_run(const bd_study_options *opt, FILE *table, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
