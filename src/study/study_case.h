/* A study and its cases, shared by the files of src/study: study.c makes
 * the cases and runs them, table.c writes the tables, record.c each
 * case's result file, best.c picks the best case, case_cost.c estimates
 * what a case costs. */
#ifndef BD_STUDY_CASE_H
#define BD_STUDY_CASE_H

#include <stdint.h>
#include <stdio.h>

#include "beltdyn/study.h"
#include "study/keypath.h"
#include "study/runner.h"

typedef enum bd_study_kind {
    BD_STUDY_START = 0,    /* start curves × start times × delays */
    BD_STUDY_GRID,         /* --vary */
    BD_STUDY_SAMPLE,       /* --sample, --range */
    BD_STUDY_CASES         /* the standard load cases (load_cases.c) */
} bd_study_kind;

#define BD_LOAD_CASES 5

typedef struct bd_study_case {
    char name[96];             /* its directory in out_dir */
    /* the start study's case (a sweep: the model's first speed drive's) */
    bd_start_curve curve;
    double time, delay, creep; /* s, s, m/s */
    double duration;           /* s simulated */
    const double *values;      /* [nkeys] a sweep's key values, or NULL */
    char setup[240];           /* a load case: what it sets, in words */
    double records_from;       /* s, a stop case's records start there; 0 */
    /* its result: status BD_RUN_*, or -1 while it has none */
    int status;
    double wall_s;
    bd_run_result res;
    char message[1024];        /* why it did not complete, or "" */
} bd_study_case;

typedef struct bd_study {
    const bd_study_options *opt;
    bd_study_kind kind;
    int nkeys;
    const bd_study_range *keys;     /* [nkeys] a sweep's */
    double *values;                 /* [n][nkeys] */
    bd_key_site sites[BD_STUDY_MAX_KEYS];
    char *text;                     /* the model file, text_len bytes */
    size_t text_len;
    uint64_t model_hash;            /* FNV-1a of text */
    bd_model_def def;               /* the model file's; the start study sets
                                       its drives' start per case */
    bd_model_def *case_defs;        /* [n] a sweep: each case's model */
    int n;
    bd_study_case *cases;           /* [n] */
    int best;                       /* index of the best case; -1 none; -2 not asked */
} bd_study;

/* table.c: the tables of the cases that have a result, in case order */
int bd_study_write_tables(const bd_study *s, char *err, size_t errlen);
void bd_study_table_header(const bd_study *s, FILE *f);
void bd_study_table_row(const bd_study *s, FILE *f, const bd_study_case *c);
/* column `col` of case c: 1 a number in *num, 2 text in *text, 0 no such
 * column. c may be NULL to ask only what the column is */
int bd_study_column(const bd_study *s, const bd_study_case *c, const char *col, double *num,
                    const char **text);
/* the table's columns, comma-separated, for a message */
void bd_study_column_names(const bd_study *s, char *buf, size_t len);
const char *bd_study_status_word(int status);

/* record.c: out_dir/<case>/case.json, a case's result, written (by the
 * worker that ran it) whole under a temporary name and renamed (0, or -1
 * with the reason in err); read back by --resume only when it is the same
 * case of the same model */
int bd_study_record_write(const bd_study *s, const bd_study_case *c, const bd_job_result *r,
                          char *err, size_t errlen);
int bd_study_record_read(const bd_study *s, bd_study_case *c);
void bd_study_record_remove(const bd_study *s, const bd_study_case *c);

/* best.c: checks --best and --where against the table's columns (0, or
 * -1 and a message), then the best case's index, -1 when none qualifies */
int bd_study_best_check(const bd_study *s, char *err, size_t errlen);
int bd_study_best_find(const bd_study *s);
/* "lowest tight_tension_max_N where slipped=false" */
void bd_study_best_describe(const bd_study *s, char *buf, size_t len);
/* the column --best names, without its "max:" */
const char *bd_study_best_column(const bd_study *s);

/* load_cases.c: the load cases' models in s->case_defs and s->cases, their
 * costs in *cost (malloc'd); a BD_RUN_* status, the reason in err */
int bd_load_cases_make(bd_study *s, double **cost, char *err, size_t errlen);
/* "cases" or "study": the tables' and the directory mark's base name */
const char *bd_study_table_name(const bd_study *s);

/* case_cost.c: the estimated wall time of a run of def over duration s,
 * in seconds of this machine (relative: it orders the cases) */
double bd_study_case_cost(const bd_model_def *def, double duration);

#endif
