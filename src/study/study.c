/* The start study (issue 4; seed 000 §4): one model, run once per start
 * curve × start time × pre-start delay with every speed drive's `start`
 * replaced, each case a normal run in DIR/<case>/. After each case the
 * table DIR/study.csv (and DIR/study.json) is rewritten whole under a
 * temporary name and renamed, so an interrupted study leaves a valid table
 * of the cases that finished. */
#include "beltdyn/study.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "beltdyn/sim.h"
#include "base/json_util.h"

#define PATH_LEN 2048
#define MAX_CASES (BD_STUDY_MAX * BD_STUDY_MAX * BD_STUDY_MAX)

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
}

typedef struct study_case {
    char name[96];
    bd_start_curve curve;
    double time, delay, creep;
    int status;            /* BD_RUN_*, or -1 not run yet */
    double wall_s;
    bd_run_result res;
} study_case;

static double wall_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static const char *status_word(int status)
{
    switch (status) {
    case BD_RUN_OK: return "completed";
    case BD_RUN_FAILED: return "failed";
    case BD_RUN_INTERRUPTED: return "interrupted";
    case -1: return "not run";
    default: return "bad input";
    }
}

/* write text to path through path.part and a rename */
static int write_whole(const char *path, const char *text, char *err, size_t errlen)
{
    char part[PATH_LEN + 8];
    snprintf(part, sizeof part, "%s.part", path);
    FILE *f = fopen(part, "w");
    int bad = !f || fputs(text, f) < 0;
    if (f && fclose(f) != 0)
        bad = 1;
    if (!bad && rename(part, path) != 0)
        bad = 1;
    if (bad) {
        snprintf(err, errlen, "cannot write '%s': %s", path, strerror(errno));
        remove(part);
    }
    return bad;
}

static const char csv_header[] =
    "case,curve,start_time_s,delay_s,creep_speed_mps,status,"
    "tight_tension_max_N,tight_tension_max_time_s,slack_tension_min_N,"
    "slack_tension_min_time_s,tight_tension_swing_N,belt_accel_max_mps2,belt_accel_max_time_s,"
    "takeup_travel_range_m,drive_torque_max_Nm,slipped,slip_longest_s,"
    "slip_speed_max_mps,belt_tension_max_N,belt_tension_min_N,wall_time_s\n";

static char *csv_text(const study_case *c, int n)
{
    size_t cap = sizeof csv_header + (size_t)n * 512;
    char *buf = malloc(cap);
    if (!buf)
        return NULL;
    size_t len = (size_t)snprintf(buf, cap, "%s", csv_header);
    for (int i = 0; i < n; i++) {
        const bd_run_result *r = &c[i].res;
        len += (size_t)snprintf(
            buf + len, cap - len,
            "%s,%s,%g,%g,%g,%s,%.6g,%.4f,%.6g,%.4f,%.6g,%.5g,%.4f,%.5g,%.6g,%d,%.4f,%.4g,%.6g,%.6g,"
            "%.2f\n",
            c[i].name, bd_start_curve_name(c[i].curve), c[i].time, c[i].delay, c[i].creep,
            status_word(c[i].status), r->tight_max_N, r->tight_max_t_s, r->slack_min_N,
            r->slack_min_t_s, r->tight_swing_N, r->accel_max_mps2, r->accel_max_t_s,
            r->travel_range_m,
            r->torque_max_Nm, r->slipped, r->slip_longest_s, r->slip_speed_max_mps,
            r->tension_max_N, r->tension_min_N, c[i].wall_s);
    }
    return buf;
}

static char *json_text(const bd_model_def *def, const study_case *c, int n)
{
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "model", def->name);
    cJSON_AddStringToObject(root, "model_file", def->source);
    cJSON_AddStringToObject(root, "slip_definition",
                            "drive pulley surface speed and belt speed at the pulley differ by "
                            "more than 0.05 m/s + 2% of the surface speed for at least 0.2 s");
    cJSON *cases = cJSON_AddArrayToObject(root, "cases");
    for (int i = 0; i < n; i++) {
        const bd_run_result *r = &c[i].res;
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "case", c[i].name);
        cJSON_AddStringToObject(o, "curve", bd_start_curve_name(c[i].curve));
        bd_json_add_number(o, "start_time_s", c[i].time);
        bd_json_add_number(o, "delay_s", c[i].delay);
        bd_json_add_number(o, "creep_speed_mps", c[i].creep);
        cJSON_AddStringToObject(o, "status", status_word(c[i].status));
        bd_json_add_number(o, "tight_tension_max_N", r->tight_max_N);
        bd_json_add_number(o, "tight_tension_max_time_s", r->tight_max_t_s);
        bd_json_add_number(o, "slack_tension_min_N", r->slack_min_N);
        bd_json_add_number(o, "slack_tension_min_time_s", r->slack_min_t_s);
        bd_json_add_number(o, "tight_tension_swing_N", r->tight_swing_N);
        bd_json_add_number(o, "belt_accel_max_mps2", r->accel_max_mps2);
        bd_json_add_number(o, "belt_accel_max_time_s", r->accel_max_t_s);
        bd_json_add_number(o, "takeup_travel_range_m", r->travel_range_m);
        bd_json_add_number(o, "drive_torque_max_Nm", r->torque_max_Nm);
        cJSON_AddBoolToObject(o, "slipped", r->slipped);
        bd_json_add_number(o, "slip_longest_s", r->slip_longest_s);
        bd_json_add_number(o, "slip_speed_max_mps", r->slip_speed_max_mps);
        bd_json_add_number(o, "belt_tension_max_N", r->tension_max_N);
        bd_json_add_number(o, "belt_tension_min_N", r->tension_min_N);
        bd_json_add_number(o, "wall_time_s", c[i].wall_s);
        cJSON_AddItemToArray(cases, o);
    }
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    return text;
}

static int write_tables(const char *dir, const bd_model_def *def, const study_case *c, int n,
                        char *err, size_t errlen)
{
    char path[PATH_LEN];
    char *csv = csv_text(c, n), *json = json_text(def, c, n);
    int bad = !csv || !json;
    if (bad)
        snprintf(err, errlen, "out of memory writing the study tables");
    if (!bad) {
        snprintf(path, sizeof path, "%s/study.csv", dir);
        bad = write_whole(path, csv, err, errlen);
    }
    if (!bad) {
        snprintf(path, sizeof path, "%s/study.json", dir);
        size_t len = strlen(json);
        char *withnl = realloc(json, len + 2);
        if (withnl) {
            json = withnl;
            json[len] = '\n';
            json[len + 1] = '\0';
        }
        bad = write_whole(path, json, err, errlen);
    }
    free(csv);
    free(json);
    return bad;
}

static void table_header(FILE *f)
{
    fprintf(f, "%-22s %9s %7s %9s %9s %9s %7s %8s %9s %5s %7s\n", "case", "T_tight", "at",
            "T_slack", "T_tight", "a_max", "travel", "M_max", "T_belt", "slip", "wall");
    fprintf(f, "%-22s %9s %7s %9s %9s %9s %7s %8s %9s %5s %7s\n", "", "max [kN]", "[s]",
            "min [kN]", "swing[kN]", "[m/s2]", "[m]", "[kN m]", "max [kN]", "", "[s]");
}

static void table_row(FILE *f, const study_case *c)
{
    const bd_run_result *r = &c->res;
    fprintf(f, "%-22s %9.2f %7.2f %9.2f %9.2f %9.3f %7.3f %8.2f %9.2f %5s %7.1f%s%s\n",
            c->name, r->tight_max_N / 1e3, r->tight_max_t_s, r->slack_min_N / 1e3,
            r->tight_swing_N / 1e3, r->accel_max_mps2,
            r->travel_range_m, r->torque_max_Nm / 1e3, r->tension_max_N / 1e3,
            r->slipped ? "yes" : "no", c->wall_s, c->status == BD_RUN_OK ? "" : "  ",
            c->status == BD_RUN_OK ? "" : status_word(c->status));
    fflush(f);
}

static int check_options(const bd_study_options *o, char *err, size_t errlen)
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

/* the model's creep speed (of its first speed drive); -1 when it has none */
static double model_creep(const bd_model_def *def)
{
    for (int i = 0; i < def->pulley_count; i++)
        if (def->pulleys[i].has_drive && def->pulleys[i].drive.control == BD_CONTROL_SPEED)
            return def->pulleys[i].drive.creep_speed;
    return -1.0;
}

/* every speed drive's start replaced by this case's; the run long enough */
static void apply_case(bd_model_def *def, const study_case *c, double after, double duration)
{
    for (int i = 0; i < def->pulley_count; i++) {
        bd_drive_def *d = &def->pulleys[i].drive;
        if (!def->pulleys[i].has_drive || d->control != BD_CONTROL_SPEED)
            continue;
        d->curve = c->curve;
        d->start_time = c->time;
        d->start_delay = c->delay;
    }
    def->simulation.duration = after > 0.0 ? c->delay + c->time + after : duration;
}

/* the model's diagnostics to the caller */
static void say_diag(const bd_study_options *opt, const bd_diag *diag)
{
    if (!opt->message)
        return;
    for (int i = 0; i < diag->count + diag->warning_count; i++)
        opt->message(diag->lines[i], opt->message_ctx);
}

/* a run's warning said as it arises (bd_run_options.message), with its case */
typedef struct case_message {
    const bd_study_options *opt;
    const char *name;
} case_message;

static void say_case_warning(const char *line, void *ctx)
{
    const case_message *cm = ctx;
    char buf[1400];
    snprintf(buf, sizeof buf, "case %s: warning: %s", cm->name, line);
    cm->opt->message(buf, cm->opt->message_ctx);
}

static int run_case(bd_model_def *def, study_case *c, const bd_study_options *opt, char *err,
                    size_t errlen)
{
    bd_diag diag;
    bd_diag_init(&diag);
    bd_sim *sim = NULL;
    int status;
    double w0 = wall_seconds();
    if (bd_sim_create(def, &sim, &diag) != 0) {
        say_diag(opt, &diag);
        snprintf(err, errlen, "case %s: the model could not be built", c->name);
        status = BD_RUN_BAD_INPUT;
    } else {
        char dir[PATH_LEN];
        snprintf(dir, sizeof dir, "%s/%s", opt->out_dir, c->name);
        bd_run_options ro = {0};
        ro.out_dir = dir;
        ro.progress = opt->progress;
        ro.progress_ctx = opt->progress_ctx;
        ro.interrupted = opt->interrupted;
        case_message cm = {opt, c->name};
        if (opt->message) {
            ro.message = say_case_warning;
            ro.message_ctx = &cm;
        }
        char msg[1024] = "";
        status = bd_sim_run(sim, &ro, msg, sizeof msg);
        if (status != BD_RUN_OK)
            snprintf(err, errlen, "case %s: %s", c->name, msg);
        bd_sim_result(sim, &c->res);
    }
    c->wall_s = wall_seconds() - w0;
    c->status = status;
    bd_sim_free(sim);
    bd_diag_free(&diag);
    return status;
}

int bd_study_run(const bd_study_options *opt, FILE *table, char *err, size_t errlen)
{
    err[0] = '\0';
    if (check_options(opt, err, errlen))
        return BD_RUN_BAD_INPUT;
    bd_model_def def;
    bd_diag diag;
    bd_diag_init(&diag);
    int bad = bd_model_load(opt->model_path, &def, &diag);
    say_diag(opt, &diag);
    bd_diag_free(&diag);
    if (bad) {
        snprintf(err, errlen, "%s: the model has errors", opt->model_path);
        return BD_RUN_BAD_INPUT;
    }
    double creep = model_creep(&def);
    if (creep < 0.0) {
        snprintf(err, errlen, "%s: no drive has `control: speed`: a start study varies the "
                 "start curve of speed-controlled drives", opt->model_path);
        bd_model_def_free(&def);
        return BD_RUN_BAD_INPUT;
    }
    if (mkdir(opt->out_dir, 0777) != 0 && errno != EEXIST) {
        snprintf(err, errlen, "cannot create '%s': %s", opt->out_dir, strerror(errno));
        bd_model_def_free(&def);
        return BD_RUN_BAD_INPUT;
    }
    int n = opt->ncurves * opt->ntimes * opt->ndelays;
    study_case *cases = calloc((size_t)n, sizeof *cases);
    if (!cases) {
        snprintf(err, errlen, "out of memory");
        bd_model_def_free(&def);
        return BD_RUN_FAILED;
    }
    int k = 0;
    for (int a = 0; a < opt->ncurves; a++)
        for (int b = 0; b < opt->ntimes; b++)
            for (int d = 0; d < opt->ndelays; d++, k++) {
                study_case *c = &cases[k];
                c->curve = opt->curves[a];
                c->time = opt->times[b];
                c->delay = opt->delays[d];
                c->creep = c->delay > 0.0 ? creep : 0.0;
                c->status = -1;
                snprintf(c->name, sizeof c->name, "%s_T%g_d%g", bd_start_curve_name(c->curve),
                         c->time, c->delay);
            }
    double duration = def.simulation.duration;
    if (table) {
        fprintf(table, "start study of %s: %d cases in %s/\n", def.name, n, opt->out_dir);
        table_header(table);
    }
    int status = BD_RUN_OK, done = 0;
    char case_err[1024];
    for (k = 0; k < n; k++) {
        apply_case(&def, &cases[k], opt->after, duration);
        case_err[0] = '\0';
        int st = run_case(&def, &cases[k], opt, case_err, sizeof case_err);
        done = k + 1;
        if (st != BD_RUN_OK) {
            if (opt->message)
                opt->message(case_err, opt->message_ctx);
            if (status == BD_RUN_OK || st != BD_RUN_FAILED)
                status = st;
            snprintf(err, errlen, "%s", case_err);
        }
        if (table)
            table_row(table, &cases[k]);
        char werr[512];
        if (write_tables(opt->out_dir, &def, cases, done, werr, sizeof werr)) {
            snprintf(err, errlen, "%s", werr);
            status = BD_RUN_FAILED;
            break;
        }
        if (st == BD_RUN_INTERRUPTED || st == BD_RUN_BAD_INPUT)
            break;
    }
    free(cases);
    bd_model_def_free(&def);
    return status;
}
