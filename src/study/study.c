/* Studies (beltdyn/study.h): one model run once per case, each case a
 * normal run in DIR/<case>/, and the table DIR/study.csv and
 * DIR/study.json of what the cases are compared by.
 *
 * The cases: the start study (seed 000 §4) replaces every speed drive's
 * start with each start curve × start time × pre-start delay; a sweep sets
 * model keys to the values of a grid (--vary) or of a Latin hypercube
 * (--sample, sweep.c), in the model file's text (keypath.c), and loads
 * each case's model from it, so the loader checks every value.
 *
 * Every process makes the same list of cases from the same options (under
 * mpirun every rank does), then the runner (runner.c) hands them out and
 * gathers their results in one process, which writes the tables in case
 * order, so a parallel run writes the serial run's table. The model file
 * is read and loaded once per process (before the workers fork, so they
 * share it, a sweep's case models too); each case is built by the worker
 * that runs it, as `run` builds its model: the build reads the drives'
 * start, so one case's compiled model is not another's.
 *
 * Each case's result is written by its worker to DIR/<case>/case.json
 * (record.c) when the case has finished; --resume keeps those. */
#include "beltdyn/study.h"
#include "beltdyn/report.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/clock.h"
#include "base/file.h"
#include "study/ranks.h"
#include "study/study_case.h"
#include "study/sweep.h"

#define PATH_LEN 2048

static const char *const curve_names[] = {"linear", "harrison", "nordell", "s-curve"};

const char *bd_start_curve_name(bd_start_curve c)
{
    return (unsigned)c < 4 ? curve_names[c] : "?";
}

int bd_start_curve_from_name(const char *name, bd_start_curve *out)
{
    for (int i = 0; i < 4; i++)
        if (strcmp(name, curve_names[i]) == 0) {
            *out = (bd_start_curve)i;
            return 0;
        }
    return -1;
}

void bd_study_options_default(bd_study_options *o)
{
    memset(o, 0, sizeof *o);
    o->ncurves = 4;
    for (int i = 0; i < 4; i++)
        o->curves[i] = (bd_start_curve)i;
    o->ntimes = 2;
    o->times[0] = 10.0;
    o->times[1] = 30.0;
    o->ndelays = 2;
    o->delays[0] = 0.0;
    o->delays[1] = 3.0;
    o->seed = 1;
}

/* a study while it runs, in every process */
typedef struct study_run {
    bd_study s;
    int rank, ranks;
    int gathers;              /* 1: this process writes the tables and speaks */
    FILE *table;              /* the gatherer's rows, or NULL */
    unsigned char *todo;      /* [n] 1: run it this time */
    double *cost;             /* [n] estimated */
    int to_run, skipped;
    double last_write;
    int write_failed;
    char first_failure[1024]; /* the first case's failure, said at the end */
    int setup_failed;         /* a rank > 0 that could not set up: fails its jobs */
    char setup_err[512];
    int progress_shown;
} study_run;

/* ---- saying things (the gatherer only) ---- */

static void clear_progress(study_run *R)
{
    const bd_study_options *o = R->s.opt;
    if (!R->progress_shown || !o->progress)
        return;
    bd_study_progress p;
    memset(&p, 0, sizeof p);
    p.clear = 1;
    o->progress(&p, o->progress_ctx);
    R->progress_shown = 0;
}

static void say(study_run *R, const char *line)
{
    const bd_study_options *o = R->s.opt;
    if (!R->gathers || !o->message)
        return;
    clear_progress(R);
    o->message(line, o->message_ctx);
}

static void say_diag(study_run *R, const bd_diag *diag)
{
    for (int i = 0; i < diag->count + diag->warning_count; i++)
        say(R, diag->lines[i]);
}

static void say_message(const char *line, void *ctx)
{
    say(ctx, line);
}

/* ---- the cases ---- */

static uint64_t fnv1a(const char *p, size_t n)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (size_t i = 0; i < n; i++) {
        h ^= (unsigned char)p[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

/* the model's first speed drive, or NULL */
static const bd_drive_def *speed_drive(const bd_model_def *def)
{
    for (int i = 0; i < def->pulley_count; i++)
        if (def->pulleys[i].has_drive && def->pulleys[i].drive.control == BD_CONTROL_SPEED)
            return &def->pulleys[i].drive;
    return NULL;
}

/* every speed drive's start replaced by the case's; its duration */
static void apply_case(bd_model_def *def, const bd_study_case *c)
{
    for (int i = 0; i < def->pulley_count; i++) {
        bd_drive_def *d = &def->pulleys[i].drive;
        if (!def->pulleys[i].has_drive || d->control != BD_CONTROL_SPEED)
            continue;
        d->curve = c->curve;
        d->start_time = c->time;
        d->start_delay = c->delay;
    }
    def->simulation.duration = c->duration;
}

static int check_start_options(const bd_study_options *o, char *err, size_t errlen)
{
    if (o->ncurves < 1 || o->ntimes < 1 || o->ndelays < 1) {
        snprintf(err, errlen, "the study needs at least one curve, start time and delay");
        return 1;
    }
    for (int i = 0; i < o->ntimes; i++)
        if (!(o->times[i] > 0.0)) {
            snprintf(err, errlen, "--times: start time %g s must be > 0", o->times[i]);
            return 1;
        }
    for (int i = 0; i < o->ndelays; i++)
        if (!(o->delays[i] >= 0.0)) {
            snprintf(err, errlen, "--delays: delay %g s must be >= 0", o->delays[i]);
            return 1;
        }
    return 0;
}

static int make_start_cases(study_run *R, char *err, size_t errlen)
{
    bd_study *s = &R->s;
    const bd_study_options *o = s->opt;
    const bd_drive_def *drive = speed_drive(&s->def);
    if (!drive) {
        snprintf(err, errlen, "%s: no drive has `control: speed`: a start study varies the "
                 "start curve of speed-controlled drives (a sweep, --vary, varies any key)",
                 o->model_path);
        return BD_RUN_BAD_INPUT;
    }
    double creep = drive->creep_speed, duration = s->def.simulation.duration;
    s->n = o->ncurves * o->ntimes * o->ndelays;
    s->cases = calloc((size_t)s->n, sizeof *s->cases);
    R->cost = calloc((size_t)s->n, sizeof *R->cost);
    if (!s->cases || !R->cost) {
        snprintf(err, errlen, "out of memory");
        return BD_RUN_FAILED;
    }
    int k = 0;
    for (int a = 0; a < o->ncurves; a++)
        for (int b = 0; b < o->ntimes; b++)
            for (int d = 0; d < o->ndelays; d++, k++) {
                bd_study_case *c = &s->cases[k];
                c->curve = o->curves[a];
                c->time = o->times[b];
                c->delay = o->delays[d];
                c->creep = c->delay > 0.0 ? creep : 0.0;
                c->duration = o->after > 0.0 ? c->delay + c->time + o->after : duration;
                c->status = -1;
                snprintf(c->name, sizeof c->name, "%s_T%g_d%g", bd_start_curve_name(c->curve),
                         c->time, c->delay);
                /* one model: a case costs its simulated time */
                R->cost[k] = c->duration;
            }
    /* built once here (the gatherer) so that a model that cannot be built
     * is a bad model, said once, not a failure of every case */
    if (!R->gathers)
        return BD_RUN_OK;
    bd_diag diag;
    bd_diag_init(&diag);
    bd_sim *sim = NULL;
    apply_case(&s->def, &s->cases[0]);
    int bad = bd_sim_create(&s->def, &sim, &diag);
    if (bad)
        say_diag(R, &diag);
    bd_sim_free(sim);
    bd_diag_free(&diag);
    if (bad) {
        snprintf(err, errlen, "%s: the model could not be built", o->model_path);
        return BD_RUN_BAD_INPUT;
    }
    return BD_RUN_OK;
}

/* the model with the keys set to v, loaded; its problems said with what
 * was varied. 0 ok */
static int load_varied(study_run *R, const bd_key_site *sites, const double *v, int n,
                       const char *what, bd_model_def *out)
{
    bd_study *s = &R->s;
    size_t len;
    char *text = bd_key_apply(s->text, s->text_len, sites, v, n, &len);
    bd_diag diag;
    bd_diag_init(&diag);
    int bad = !text || bd_model_load_string(text, len, s->opt->model_path, out, &diag);
    if (bad) {
        char line[1400];
        snprintf(line, sizeof line, "beltdyn: %s: the model is not valid with it:", what);
        say(R, line);
        say_diag(R, &diag);
    }
    bd_diag_free(&diag);
    free(text);
    return bad;
}

/* the line (from 1) of byte `at` of the text */
static int line_at(const char *text, size_t at)
{
    int line = 1;
    for (size_t i = 0; i < at; i++)
        line += text[i] == '\n';
    return line;
}

static int make_sweep_cases(study_run *R, char *err, size_t errlen)
{
    bd_study *s = &R->s;
    const bd_study_options *o = s->opt;
    const char *opt_name = s->kind == BD_STUDY_GRID ? "--vary" : "--range";
    for (int k = 0; k < s->nkeys; k++) {
        char msg[900];
        for (int i = 0; i < k; i++)
            if (strcmp(s->keys[i].key, s->keys[k].key) == 0) {
                snprintf(err, errlen, "%s %s: the key is varied twice", opt_name,
                         s->keys[k].key);
                return BD_RUN_BAD_INPUT;
            }
        if (bd_key_find(s->text, s->text_len, s->keys[k].key, &s->sites[k], msg, sizeof msg)) {
            snprintf(err, errlen, "%s %s", opt_name, msg);
            return BD_RUN_BAD_INPUT;
        }
        /* one number under two spellings (pulleys.head.radius and
         * pulleys.0.radius, idlers[0].x and idlers.0.x) */
        for (int i = 0; i < k; i++)
            if (s->sites[i].len > 0 && s->sites[k].len > 0 && s->sites[i].at == s->sites[k].at) {
                snprintf(err, errlen, "%s %s: names the same number as %s %s (line %d of the "
                         "model file): vary it once", opt_name, s->keys[k].key, opt_name,
                         s->keys[i].key, line_at(s->text, s->sites[k].at));
                return BD_RUN_BAD_INPUT;
            }
        for (int i = 0; i < k; i++)
            if (s->sites[i].len == 0 && s->sites[k].len == 0 && s->sites[i].at == s->sites[k].at
                && strcmp(s->sites[i].adds, s->sites[k].adds) == 0) {
                snprintf(err, errlen, "%s %s: %s also adds '%s' to the model; give '%s' in the "
                         "model file to vary both", opt_name, s->keys[k].key, s->keys[i].key,
                         s->sites[k].adds, s->sites[k].adds);
                return BD_RUN_BAD_INPUT;
            }
        /* each key alone at both ends of its range */
        for (int end = 0; end < 2; end++) {
            double v = end ? s->keys[k].hi : s->keys[k].lo;
            char what[400];
            bd_model_def def;
            snprintf(what, sizeof what, "%s %s = %.10g", opt_name, s->keys[k].key, v);
            if (load_varied(R, &s->sites[k], &v, 1, what, &def)) {
                snprintf(err, errlen, "%s %s: the model does not take %.10g there (above)",
                         opt_name, s->keys[k].key, v);
                return BD_RUN_BAD_INPUT;
            }
            bd_model_def_free(&def);
        }
    }
    if (s->kind == BD_STUDY_GRID)
        s->values = bd_sweep_grid(s->keys, s->nkeys, &s->n);
    else {
        s->n = o->samples;
        s->values = bd_sweep_lhs(s->keys, s->nkeys, o->samples, o->seed);
    }
    if (!s->values) {
        snprintf(err, errlen, "%s: too many cases (at most %d) or out of memory", opt_name,
                 BD_SWEEP_MAX_CASES);
        return BD_RUN_BAD_INPUT;
    }
    s->cases = calloc((size_t)s->n, sizeof *s->cases);
    s->case_defs = calloc((size_t)s->n, sizeof *s->case_defs);
    R->cost = calloc((size_t)s->n, sizeof *R->cost);
    if (!s->cases || !s->case_defs || !R->cost) {
        snprintf(err, errlen, "out of memory");
        return BD_RUN_FAILED;
    }
    int width = s->n < 1000 ? 3 : s->n < 10000 ? 4 : s->n < 100000 ? 5 : 6;
    for (int j = 0; j < s->n; j++) {
        bd_study_case *c = &s->cases[j];
        snprintf(c->name, sizeof c->name, "case_%0*d", width, j + 1);
        c->values = &s->values[(size_t)j * (size_t)s->nkeys];
        c->status = -1;
        char what[1200];
        size_t w = (size_t)snprintf(what, sizeof what, "case %s (", c->name);
        for (int k = 0; k < s->nkeys && w < sizeof what; k++)
            w += (size_t)snprintf(what + w, sizeof what - w, "%s%s = %.10g", k ? ", " : "",
                                  s->keys[k].key, c->values[k]);
        if (w < sizeof what)
            snprintf(what + w, sizeof what - w, ")");
        if (load_varied(R, s->sites, c->values, s->nkeys, what, &s->case_defs[j])) {
            snprintf(err, errlen, "%s: the model is not valid with these values (above)", what);
            return BD_RUN_BAD_INPUT;
        }
        const bd_model_def *def = &s->case_defs[j];
        const bd_drive_def *d = speed_drive(def);
        if (d) {
            c->curve = d->curve;
            c->time = d->start_time;
            c->delay = d->start_delay;
            c->creep = d->creep_speed;
        }
        c->duration = def->simulation.duration;
        R->cost[j] = bd_study_case_cost(def, c->duration);
    }
    return BD_RUN_OK;
}

/* options, model and cases: the same in every process */
static int setup(study_run *R, char *err, size_t errlen)
{
    bd_study *s = &R->s;
    const bd_study_options *o = s->opt;
    int sweep = o->nvary > 0 || o->samples > 0 || o->nrange > 0;
    if (o->load_cases && (sweep || o->after > 0.0 || o->best || o->nwhere > 0)) {
        snprintf(err, errlen, "cases runs the five standard load cases: it takes -o, -j, "
                 "--resume and --force only");
        return BD_RUN_BAD_INPUT;
    }
    if (o->nvary > 0 && (o->samples > 0 || o->nrange > 0)) {
        snprintf(err, errlen, "--vary makes a grid, --sample and --range a Latin hypercube: "
                 "give one of them");
        return BD_RUN_BAD_INPUT;
    }
    if ((o->samples > 0) != (o->nrange > 0)) {
        snprintf(err, errlen, o->samples > 0 ? "--sample N needs the keys to sample: --range "
                 "KEY=LO:HI (repeatable)" : "--range needs --sample N, the number of cases");
        return BD_RUN_BAD_INPUT;
    }
    if (o->nvary > BD_STUDY_MAX_KEYS || o->nrange > BD_STUDY_MAX_KEYS || o->samples < 0) {
        snprintf(err, errlen, "at most %d keys are varied", BD_STUDY_MAX_KEYS);
        return BD_RUN_BAD_INPUT;
    }
    if (sweep && o->after > 0.0) {
        snprintf(err, errlen, "--after belongs to the start study; a sweep runs the model's "
                 "simulation.duration (vary it as a key)");
        return BD_RUN_BAD_INPUT;
    }
    if (!sweep && !o->load_cases && check_start_options(o, err, errlen))
        return BD_RUN_BAD_INPUT;
    s->kind = o->load_cases ? BD_STUDY_CASES
            : !sweep ? BD_STUDY_START : (o->nvary > 0 ? BD_STUDY_GRID : BD_STUDY_SAMPLE);
    s->nkeys = s->kind == BD_STUDY_GRID ? o->nvary : (s->kind == BD_STUDY_SAMPLE ? o->nrange : 0);
    s->keys = s->kind == BD_STUDY_GRID ? o->vary : o->range;
    if (bd_read_file(o->model_path, &s->text, &s->text_len) != BD_READ_OK) {
        snprintf(err, errlen, "%s: cannot read the model file: %s", o->model_path,
                 strerror(errno));
        return BD_RUN_BAD_INPUT;
    }
    s->model_hash = fnv1a(s->text, s->text_len);
    bd_diag diag;
    bd_diag_init(&diag);
    int bad = bd_model_load_string(s->text, s->text_len, o->model_path, &s->def, &diag);
    say_diag(R, &diag);
    bd_diag_free(&diag);
    if (bad) {
        snprintf(err, errlen, "%s: the model has errors", o->model_path);
        return BD_RUN_BAD_INPUT;
    }
    int rc = s->kind == BD_STUDY_START   ? make_start_cases(R, err, errlen)
           : s->kind == BD_STUDY_CASES ? bd_load_cases_make(s, &R->cost, err, errlen)
                                       : make_sweep_cases(R, err, errlen);
    if (rc != BD_RUN_OK)
        return rc;
    if (bd_study_best_check(s, err, errlen))
        return BD_RUN_BAD_INPUT;
    return BD_RUN_OK;
}

/* ---- the output directory (the gatherer) ---- */

static int prepare_dir(study_run *R, char *err, size_t errlen)
{
    bd_study *s = &R->s;
    const bd_study_options *o = s->opt;
    char mark_name[16];
    snprintf(mark_name, sizeof mark_name, "%s.json", bd_study_table_name(s));
    const char *const mark[1] = {mark_name};
    int state = bd_dir_state(o->out_dir, mark, 1);
    if (state == BD_DIR_BAD) {
        snprintf(err, errlen, "'%s' is not a directory", o->out_dir);
        return BD_RUN_BAD_INPUT;
    }
    if (state == BD_DIR_OTHER && !o->force) {
        snprintf(err, errlen, "'%s' is not empty and holds no %s (no %s): give "
                 "another -o DIR, or --force to write into it", o->out_dir,
                 s->kind == BD_STUDY_CASES ? "load cases" : "study", mark_name);
        return BD_RUN_BAD_INPUT;
    }
    if (mkdir(o->out_dir, 0777) != 0 && errno != EEXIST) {
        snprintf(err, errlen, "cannot create '%s': %s", o->out_dir, strerror(errno));
        return BD_RUN_BAD_INPUT;
    }
    R->todo = calloc((size_t)s->n, 1);
    if (!R->todo) {
        snprintf(err, errlen, "out of memory");
        return BD_RUN_FAILED;
    }
    for (int j = 0; j < s->n; j++) {
        if (o->resume && bd_study_record_read(s, &s->cases[j])) {
            R->skipped++;
            continue;
        }
        /* a result left by an earlier study is not this one's */
        bd_study_record_remove(s, &s->cases[j]);
        R->todo[j] = 1;
        R->to_run++;
    }
    if (bd_study_write_tables(s, err, errlen))
        return BD_RUN_FAILED;
    R->last_write = bd_wall_seconds();
    return BD_RUN_OK;
}

/* ---- a case, in whichever process runs it ---- */

typedef struct case_message {
    const bd_job_env *env;
    const char *name;
} case_message;

static void say_case_warning(const char *line, void *ctx)
{
    const case_message *cm = ctx;
    char buf[1400];
    snprintf(buf, sizeof buf, "case %s: warning: %s", cm->name, line);
    cm->env->message(buf, cm->env->message_ctx);
}

static void run_case(void *ctx, int job, const bd_job_env *env, bd_job_result *out)
{
    study_run *R = ctx;
    bd_study *s = &R->s;
    double w0 = bd_wall_seconds();
    if (R->setup_failed || job < 0 || job >= s->n) {
        out->status = BD_RUN_BAD_INPUT;
        snprintf(out->message, sizeof out->message, "rank %d could not set up the study: %s",
                 R->rank, R->setup_err);
        return;
    }
    const bd_study_case *c = &s->cases[job];
    char dir[PATH_LEN];
    if (bd_path_join(dir, sizeof dir, s->opt->out_dir, c->name)) {
        out->status = BD_RUN_BAD_INPUT;
        snprintf(out->message, sizeof out->message, "case %s: %.300s/%s: path too long",
                 c->name, s->opt->out_dir, c->name);
        return;
    }
    bd_sim *sim = NULL;
    bd_diag diag;
    bd_diag_init(&diag);
    int built;
    /* a case is a model of its own: the build reads the drives' start
     * (the monitors' ramp end, the start from rest), so a start study's
     * case cannot reuse another case's compiled model */
    bd_model_def *def = s->kind == BD_STUDY_START ? &s->def : &s->case_defs[job];
    if (s->kind == BD_STUDY_START)
        apply_case(def, c);
    built = bd_sim_create(def, &sim, &diag) == 0;
    if (!built)
        snprintf(out->message, sizeof out->message, "case %s: the model could not be "
                 "built: %.850s", c->name, diag.count > 0 ? diag.lines[0] : "");
    if (!built) {
        out->status = BD_RUN_BAD_INPUT;
    } else {
        char msg[1024] = "";
        bd_run_options ro = {0};
        ro.out_dir = dir;
        ro.progress = env->progress;
        ro.progress_ctx = env->progress_ctx;
        ro.interrupted = env->interrupted;
        ro.records_from_s = c->records_from;
        ro.end_at_rest_after_s = c->records_from;
        /* an earlier run's report, plots, tension.h5 and parts.csv in the
         * case's directory are not this run's (cli.md: as `run` does);
         * forced, it fails only on an unreadable directory, which the run
         * that follows reports */
        (void)bd_run_dir_prepare(dir, 1, msg, sizeof msg);
        msg[0] = '\0';
        case_message cm = {env, c->name};
        if (env->message) {
            ro.message = say_case_warning;
            ro.message_ctx = &cm;
        }
        out->status = bd_sim_run(sim, &ro, msg, sizeof msg);
        if (out->status != BD_RUN_OK)
            snprintf(out->message, sizeof out->message, "case %s: %.900s", c->name, msg);
        bd_sim_result(sim, &out->res);
    }
    out->wall_s = bd_wall_seconds() - w0;
    bd_sim_free(sim);
    bd_diag_free(&diag);
    /* a result that is not on disk is run again by --resume: say so */
    char werr[PATH_LEN + 64];
    if (bd_study_record_write(s, c, out, werr, sizeof werr) != 0 && env->message) {
        char line[PATH_LEN + 256];
        snprintf(line, sizeof line, "case %s: warning: cannot write case.json (--resume "
                 "runs it again): %s", c->name, werr);
        env->message(line, env->message_ctx);
    }
}

/* ---- gathering ---- */

static void on_done(const bd_job_result *r, void *ctx)
{
    study_run *R = ctx;
    bd_study *s = &R->s;
    bd_study_case *c = &s->cases[r->job];
    c->status = r->status;
    c->wall_s = r->wall_s;
    c->res = r->res;
    snprintf(c->message, sizeof c->message, "%s", r->status == BD_RUN_OK ? "" : r->message);
    if (r->status != BD_RUN_OK && r->status != BD_RUN_INTERRUPTED && r->message[0]) {
        say(R, r->message);
        if (!R->first_failure[0])
            snprintf(R->first_failure, sizeof R->first_failure, "%s", r->message);
    }
    if (R->table) {
        clear_progress(R);
        bd_study_table_row(s, R->table, c);
    }
    /* the table on disk follows at most once a second, and at the end */
    double now = bd_wall_seconds();
    if (now - R->last_write >= 1.0) {
        char err[512];
        if (bd_study_write_tables(s, err, sizeof err) && !R->write_failed) {
            R->write_failed = 1;
            say(R, err);
        }
        R->last_write = now;
    }
}

static void on_progress(const bd_runner_progress *p, void *ctx)
{
    study_run *R = ctx;
    const bd_study_options *o = R->s.opt;
    bd_study_progress q;
    memset(&q, 0, sizeof q);
    q.cases = R->s.n;
    q.to_run = p->total;
    q.done = p->done;
    q.failed = p->failed;
    q.running = p->running;
    q.workers = p->workers;
    q.fraction = p->fraction;
    q.wall_s = p->wall_s;
    q.remaining_s = p->fraction > 0.005 ? p->wall_s * (1.0 - p->fraction) / p->fraction : -1.0;
    q.finished = p->finished;
    o->progress(&q, o->progress_ctx);
    R->progress_shown = !p->finished;
}

/* `cases`: DIR/report.html comparing the load cases, with each case's own
 * report, written by the process that gathered them (rank 0: every rank
 * writing it raced on the same files under mpirun). A report that cannot
 * be written is said; the run's status stands */
static void cases_report(study_run *R)
{
    const bd_study_options *o = R->s.opt;
    char err[1024], line[1200];
    if (bd_report_write(o->out_dir, err, sizeof err) != BD_REPORT_OK) {
        snprintf(line, sizeof line, "report of %s: %s", o->out_dir, err);
        if (o->message)
            o->message(line, o->message_ctx);
    } else if (R->table) {
        /* where the table and the best case go (stdout in the app) */
        clear_progress(R);
        fprintf(R->table, "report: %s/report.html\n", o->out_dir);
        fflush(R->table);
    }
}

static int finish(study_run *R, int runner_status, char *err, size_t errlen)
{
    bd_study *s = &R->s;
    const bd_study_options *o = s->opt;
    if (o->best) {
        s->best = bd_study_best_find(s);
        char what[600], line[1600];
        bd_study_best_describe(s, what, sizeof what);
        if (s->best >= 0) {
            const bd_study_case *c = &s->cases[s->best];
            double v = 0.0;
            const char *t, *col = bd_study_best_column(s);
            bd_study_column(s, c, col, &v, &t);
            size_t n = (size_t)snprintf(line, sizeof line, "best (%s): %s, %s = %.6g", what,
                                        c->name, col, v);
            for (int k = 0; k < s->nkeys && n < sizeof line; k++)
                n += (size_t)snprintf(line + n, sizeof line - n, ", %s = %.6g", s->keys[k].key,
                                      c->values[k]);
        } else {
            snprintf(line, sizeof line, "best (%s): no completed case qualifies", what);
        }
        if (R->table) {
            clear_progress(R);
            fprintf(R->table, "%s\n", line);
            fflush(R->table);
        }
    }
    if (bd_study_write_tables(s, err, errlen))
        return BD_RUN_FAILED;
    if (runner_status == BD_RUN_INTERRUPTED) {
        int complete = 0;
        for (int j = 0; j < s->n; j++)
            complete += s->cases[j].status == BD_RUN_OK || s->cases[j].status == BD_RUN_FAILED;
        snprintf(err, errlen, "interrupted: %d of %d cases complete, in %s/%s.csv; "
                 "--resume runs the others", complete, s->n, o->out_dir, bd_study_table_name(s));
    }
    if (runner_status != BD_RUN_OK)
        return runner_status;
    if (R->write_failed) {
        snprintf(err, errlen, "the study table could not be written while the cases ran");
        return BD_RUN_FAILED;
    }
    for (int j = 0; j < s->n; j++)
        if (s->cases[j].status != BD_RUN_OK) {
            snprintf(err, errlen, "%s", R->first_failure[0] ? R->first_failure
                                                            : "a case did not complete");
            return BD_RUN_FAILED;
        }
    return BD_RUN_OK;
}

static void study_free(study_run *R)
{
    bd_study *s = &R->s;
    if (s->case_defs)
        for (int j = 0; j < s->n; j++)
            bd_model_def_free(&s->case_defs[j]);
    free(s->case_defs);
    free(s->cases);
    free(s->values);
    free(s->text);
    bd_model_def_free(&s->def);
    free(R->todo);
    free(R->cost);
}

int bd_study_run(const bd_study_options *opt, FILE *table, char *err, size_t errlen)
{
    err[0] = '\0';
    study_run *R = calloc(1, sizeof *R);
    if (!R) {
        snprintf(err, errlen, "out of memory");
        return BD_RUN_FAILED;
    }
    R->s.opt = opt;
    R->s.best = -2;
    bd_model_def_init(&R->s.def);
    if (bd_ranks_begin(&R->rank, &R->ranks, err, errlen)) {
        free(R);
        return BD_RUN_BAD_INPUT;
    }
    R->gathers = R->rank == 0;
    R->table = R->gathers ? table : NULL;
    int status = setup(R, err, errlen);
    if (status == BD_RUN_OK && R->gathers)
        status = prepare_dir(R, err, errlen);
    if (!R->gathers && status != BD_RUN_OK) {
        /* its jobs fail with the reason; rank 0 says it */
        R->setup_failed = 1;
        snprintf(R->setup_err, sizeof R->setup_err, "%s", err);
    }
    /* under an MPI launcher one worker per rank, -j not used: a world of
     * one rank runs the cases here, one after another (Open MPI does not
     * support fork after MPI_Init; the runner keeps to it too) */
    int launched = bd_ranks_launched();
    int workers = launched ? 1 : opt->jobs > 0 ? opt->jobs : bd_runner_cores();
    if (R->table && status == BD_RUN_OK) {
        int w = launched ? R->ranks : (workers < R->to_run ? workers : R->to_run);
        fprintf(R->table, "%s of %s: %d cases in %s/", R->s.kind == BD_STUDY_START
                ? "start study" : R->s.kind == BD_STUDY_CASES ? "load cases"
                : (R->s.kind == BD_STUDY_GRID ? "sweep (grid)" : "sweep (Latin hypercube)"),
                R->s.def.name, R->s.n, opt->out_dir);
        if (R->skipped > 0)
            fprintf(R->table, " (%d complete before, %d to run)", R->skipped, R->to_run);
        fprintf(R->table, ", %d %s\n", w > 0 ? w : 1,
                launched ? (w > 1 ? "MPI ranks" : "MPI rank")
                         : (w > 1 ? "worker processes" : "process"));
        bd_study_table_header(&R->s, R->table);
        fflush(R->table);
    }
    if (status == BD_RUN_OK || R->ranks > 1) {
        int ok = status == BD_RUN_OK;
        bd_runner r;
        memset(&r, 0, sizeof r);
        r.count = R->gathers && !ok ? 0 : R->s.n;   /* rank 0 failed: stop the others */
        r.cost = R->cost;
        r.todo = R->todo;
        r.workers = workers;
        r.rank = R->rank;
        r.ranks = R->ranks;
        r.run = run_case;
        r.run_ctx = R;
        r.done = on_done;
        r.done_ctx = R;
        r.progress = R->gathers && opt->progress ? on_progress : NULL;
        r.progress_ctx = R;
        r.message = R->gathers && opt->message ? say_message : NULL;
        r.message_ctx = R;
        r.interrupted = opt->interrupted;
        char rerr[512];
        int rs = bd_runner_run(&r, rerr, sizeof rerr);
        if (ok && R->gathers) {
            status = finish(R, rs, err, errlen);
            if (R->s.kind == BD_STUDY_CASES && (status == BD_RUN_OK || status == BD_RUN_FAILED))
                cases_report(R);
        }
        else if (ok && rs == BD_RUN_FAILED) {
            snprintf(err, errlen, "%s", rerr);
            status = rs;
        }
        if (rs == BD_RUN_FAILED && R->gathers && rerr[0]) {
            snprintf(err, errlen, "%s", rerr);
            status = BD_RUN_FAILED;
        }
    }
    if (!R->gathers)
        err[0] = '\0';   /* rank 0 says it */
    study_free(R);
    free(R);
    bd_ranks_end();
    return status;
}
