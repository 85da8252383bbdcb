/* Writers of a run's output files (outputs.c) */
#ifndef BD_OUTPUTS_H
#define BD_OUTPUTS_H

#include <stdio.h>

#include "sim/engine.h"

enum {
    BD_OUT_HISTORY = 0, BD_OUT_TENSION, BD_OUT_ENVELOPE, BD_OUT_SUMMARY, BD_OUT_HDF5, BD_OUT_PARTS,
    BD_OUT_COUNT
};

struct bd_h5;

typedef struct bd_outputs {
    char dir[1024];
    char final_path[BD_OUT_COUNT][1100];
    char part_path[BD_OUT_COUNT][1100];
    FILE *history, *tension;
    FILE *parts;           /* parts.csv: drive sides and takeup pulls, or
                              NULL for a model with neither */
    char *history_buf, *tension_buf;   /* their stdio buffers (one per run:
                                          runs may write side by side) */
    struct bd_h5 *h5;      /* tension.h5 when asked for (run --hdf5), else NULL */
    int h5_failed;         /* writing tension.h5 failed (message in err) */
    int bins;              /* envelope bins along the path */
    double *env_max;       /* [bins] N */
    double *env_min;       /* [bins] N */
    long rows;
    int field_stride;      /* tension.csv: every field_stride-th element */
    double next_tension;   /* s, when the next tension.csv rows are due */
    double records_from;   /* s, when the records started again (0: t = 0) */
    int static_warnings;   /* summary.json's static-design warnings, and its
                              own failure as one (set by bd_outputs_close) */
    char err[2048];
} bd_outputs;

/* the run directory and its parents, made if missing; 0 ok */
int bd_outputs_make_dir(const char *dir, char *err, size_t errlen);
/* hdf5: also write DIR/tension.h5 (hdf5_out.c) */
int bd_outputs_open(bd_outputs *o, const bd_sim *sim, const char *dir, int hdf5, char *err,
                    size_t errlen);
/* one output time: a history row, the tension rows, the envelope update */
void bd_outputs_row(bd_outputs *o, bd_sim *sim, double t);
void bd_outputs_flush(bd_outputs *o);
/* the records start again at t (bd_run_options records_from_s): the
 * envelope is emptied */
void bd_outputs_records_restart(bd_outputs *o, double t);
/* finish every file (rename), write envelope.csv and summary.json; status
 * is "completed", "failed" or "interrupted" */
int bd_outputs_close(bd_outputs *o, const bd_sim *sim, double wall, const char *status);

#endif
