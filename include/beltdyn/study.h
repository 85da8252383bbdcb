/* beltdyn start study: one model run over start curves × start times ×
 * pre-start delays (issue 4), each case a normal run in its own directory,
 * and a table of what the cases are compared by. */
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
    bd_progress_fn progress;       /* each case's progress, or NULL */
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

/* run every case into out_dir/<case>/ (the outputs of `run`), writing
 * out_dir/study.csv and out_dir/study.json after each case, and a table on
 * `table` (may be NULL). Returns a BD_RUN_* status: BD_RUN_BAD_INPUT for a
 * bad model or options (messages on stderr as FILE:LINE:COL lines, or in
 * err), BD_RUN_FAILED when a case failed (the others still ran),
 * BD_RUN_INTERRUPTED. */
int bd_study_run(const bd_study_options *opt, FILE *table, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
