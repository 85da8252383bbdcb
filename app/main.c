/* beltdyn: the command line (spec/cli.md). Only the public API is used. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "beltdyn/boom.h"
#include "beltdyn/model.h"
#include "beltdyn/report.h"
#include "beltdyn/sim.h"
#include "beltdyn/standards.h"
#include "beltdyn/study.h"

static volatile sig_atomic_t interrupted = 0;

static void on_sigint(int sig)
{
    (void)sig;
    interrupted = 1;
}

/* 1 while a progress line is on the terminal without its newline */
static int progress_open = 0;

/* the progress line on a terminal (cli.md): simulated time, percent, wall
 * time, estimated remaining, real-time factor; while stabilizing, the
 * relaxation's steps and wall time */
static void show_progress(const bd_run_progress *p, void *ctx)
{
    (void)ctx;
    progress_open = !p->done;
    if (p->stabilize_steps > 0) {
        fprintf(stderr, "\r  stabilizing (t = 0): %9ld steps  wall %7.1f s ", p->stabilize_steps,
                p->wall_s);
        return;
    }
    double frac = p->duration_s > 0.0 ? p->t_s / p->duration_s : 1.0;
    double remaining = frac > 0.0 ? p->wall_s * (1.0 - frac) / frac : 0.0;
    fprintf(stderr, "\r  t = %8.3f s  %5.1f%%  wall %7.1f s  remaining %7.1f s  %6.2fx real time ",
            p->t_s, 100.0 * frac, p->wall_s, remaining,
            p->wall_s > 0.0 ? p->t_s / p->wall_s : 0.0);
    if (p->done)
        fputc('\n', stderr);
}

/* a line below the progress line, not on it */
static void say(const char *prefix, const char *line)
{
    fprintf(stderr, "%s%s%s\n", progress_open ? "\n" : "", prefix, line);
    progress_open = 0;
}

/* a study's model diagnostics, its cases' warnings and failures */
static void show_message(const char *line, void *ctx)
{
    (void)ctx;
    say("", line);
}

/* a run's warning as it arises (a stabilization that did not reach rest) */
static void show_warning(const char *line, void *ctx)
{
    (void)ctx;
    say("beltdyn: warning: ", line);
}

static int usage(FILE *f)
{
    fprintf(f,
            "usage: beltdyn check MODEL.yaml\n"
            "       beltdyn static MODEL.yaml [--json]\n"
            "       beltdyn run MODEL.yaml [-o DIR] [--quiet] [--hdf5] [--force]\n"
            "                   [--mesh-check]\n"
            "       beltdyn report DIR\n"
            "       beltdyn study MODEL.yaml [-o DIR] [--curves LIST] [--times LIST]\n"
            "                     [--delays LIST] [--after S] [-j N] [--resume] [--force]\n"
            "                     [--quiet]\n"
            "       beltdyn study MODEL.yaml --vary KEY=LO:HI:N [--vary ...] [options]\n"
            "       beltdyn study MODEL.yaml --sample N --range KEY=LO:HI [--range ...]\n"
            "                     [--seed S] [options]\n"
            "                     [--best [max:]COLUMN [--where COLUMN=VALUE ...]]\n"
            "       beltdyn cases MODEL.yaml [-o DIR] [-j N] [--resume] [--force] [--quiet]\n"
            "\n"
            "  check   read and validate a model; print what was derived\n"
            "  static  design-standard tensions (DIN 22101, ISO 5048, CEMA)\n"
            "  run     transient simulation; writes summary.json, history.csv,\n"
            "          tension.csv and envelope.csv into DIR (default ./out);\n"
            "          --hdf5 also writes the tension field to DIR/tension.h5;\n"
            "          a DIR that is not empty must hold an earlier run (whose\n"
            "          report and plots are then removed), else --force;\n"
            "          --mesh-check runs it again on elements half as long and\n"
            "          says in summary.json what moved by more than 2 %%\n"
            "  report  plots and report.html from a finished run's DIR, or the\n"
            "          comparison of a study's DIR (start curves, or a sweep's\n"
            "          outputs against its keys and their sensitivity ranking)\n"
            "  study   runs the model once per case, each case in DIR/<case>/ (default\n"
            "          ./study), the table in DIR/study.csv and study.json and on\n"
            "          stdout (docs/studies.md, docs/starting.md). Start study: every\n"
            "          speed drive's start over\n"
            "          --curves linear,harrison,nordell,s-curve (default all four)\n"
            "          --times 10,30 (s)  --delays 0,3 (s; creep speed from the model)\n"
            "          --after S: run each case to delay + time + S seconds\n"
            "          (default: the model's simulation.duration).\n"
            "          Sweep: --vary KEY=LO:HI:N, N values from LO to HI (repeatable: every\n"
            "          combination), or --sample N --range KEY=LO:HI (repeatable) --seed S,\n"
            "          N cases of a Latin hypercube; KEY a path into the model file, e.g.\n"
            "          pulleys.takeup.takeup.mass or belt.axial_stiffness.\n"
            "          -j N: N worker processes (default: one per core); under mpirun one\n"
            "          per rank. --resume: keep the cases already complete in DIR.\n"
            "          --force: write into a non-empty DIR that holds no study.\n"
            "          --best COLUMN: the case with the lowest COLUMN (max:COLUMN the\n"
            "          highest) among those that meet every --where COLUMN=VALUE\n"
            "          (also !=, <, <=, >, >=)\n"
            "  cases   the standard load cases, each a run in DIR/CASE/ (default ./cases):\n"
            "          empty_start, loaded_start, loaded_coast_stop (power failure),\n"
            "          loaded_brake_stop, partial_load_start (the worst partial loading);\n"
            "          the table in DIR/cases.csv and cases.json, each case's report and\n"
            "          DIR/report.html comparing them (docs/studies.md)\n"
            "\n"
            "A model whose top level has `boom` is a telescopic boom (boom-format.md):\n"
            "check and run take it (run writes summary.json, history.csv and beams.csv);\n"
            "static, study and cases take only a conveyor.\n");
    return 2;
}

static void print_diag(const bd_diag *d)
{
    for (int i = 0; i < d->count + d->warning_count; i++)
        fprintf(stderr, "%s\n", d->lines[i]);
}

/* a load's and a build's messages printed; 0, or exit code 2 when bad */
static int said(bd_diag *diag, int bad)
{
    print_diag(diag);
    bd_diag_free(diag);
    return bad ? 2 : 0;
}

/* load and build; 0 ok, else exit code 2 with messages printed */
static int load_model(const char *path, bd_model_def *def, bd_sim **sim)
{
    bd_diag diag;
    bd_diag_init(&diag);
    int bad = bd_model_load(path, def, &diag);
    if (!bad && sim)
        bad = bd_sim_create(def, sim, &diag);
    if (bad)
        bd_model_def_free(def);
    return said(&diag, bad);
}

/* a boom model (boom-format.md), loaded and built as load_model does */
static int load_boom(const char *path, bd_boom_def *def, bd_boom **boom)
{
    bd_diag diag;
    bd_diag_init(&diag);
    int bad = bd_boom_load(path, def, &diag);
    if (!bad)
        bad = bd_boom_create(def, boom, &diag);
    if (bad)
        bd_boom_def_free(def);
    return said(&diag, bad);
}

/* a boom model given where only a conveyor will do: said, exit code 2 */
static int conveyor_only(const char *cmd, const char *path)
{
    if (!bd_model_is_boom(path))
        return 0;
    fprintf(stderr, "beltdyn: %s: %s takes a conveyor model, not a boom\n", path, cmd);
    return 2;
}

static int check_boom(const char *path)
{
    bd_boom_def def;
    bd_boom *boom = NULL;
    int rc = load_boom(path, &def, &boom);
    if (rc == 0) {
        bd_boom_describe(boom, stdout);
        bd_boom_free(boom);
        bd_boom_def_free(&def);
    }
    return rc;
}

static int cmd_check(int argc, char **argv)
{
    if (argc != 1)
        return usage(stderr);
    if (bd_model_is_boom(argv[0]))
        return check_boom(argv[0]);
    bd_model_def def;
    bd_sim *sim = NULL;
    int rc = load_model(argv[0], &def, &sim);
    if (rc == 0) {
        bd_sim_describe(sim, stdout);
        bd_sim_free(sim);
    }
    bd_model_def_free(&def);
    return rc;
}

static int cmd_static(int argc, char **argv)
{
    const char *path = NULL;
    int json = 0;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0)
            json = 1;
        else if (!path && argv[i][0] != '-')
            path = argv[i];
        else
            return usage(stderr);
    }
    if (!path)
        return usage(stderr);
    if (conveyor_only("static", path))
        return 2;
    bd_model_def def;
    int rc = load_model(path, &def, NULL);
    if (rc != 0)
        return rc;
    bd_diag diag;
    bd_diag_init(&diag);
    bd_static_result res;
    if (bd_static_compute(&def, &res, &diag) != 0) {
        print_diag(&diag);
        bd_diag_free(&diag);
        bd_model_def_free(&def);
        return 2;
    }
    if (json) {
        char *text = bd_static_to_json(&res, &def);
        if (text)
            printf("%s\n", text);
        free(text);
    } else {
        bd_static_print_table(&res, &def, stdout);
    }
    bd_static_free(&res);
    bd_diag_free(&diag);
    bd_model_def_free(&def);
    return 0;
}

/* the end-of-run summary on a terminal (cli.md): the peak tension, where
 * and when, its safety factor, slip, takeup travel, warnings */
static void print_summary(const bd_sim *sim, const bd_model_def *def, FILE *f)
{
    bd_run_result r;
    bd_sim_result(sim, &r);
    fprintf(f, "peak belt tension %.2f kN at s = %.1f m, t = %.2f s", r.tension_max_N / 1e3,
            r.tension_max_s_m, r.tension_max_t_s);
    if (def->belt.rated_tension > 0.0 && r.tension_max_N > 0.0) {
        double sf = def->belt.rated_tension / r.tension_max_N;
        /* its verdict is the checks table's, printed after this */
        fprintf(f, ",\n  safety factor %.2f against the rated %.0f kN", sf,
                def->belt.rated_tension / 1e3);
    }
    fprintf(f, "\nlowest belt tension %.2f kN\n", r.tension_min_N / 1e3);
    if (r.drives > 0) {
        if (r.slipped)
            fprintf(f, "drive slip: yes, from t = %.2f s, longest %.2f s, up to %.3f m/s\n",
                    r.slip_t_s, r.slip_longest_s, r.slip_speed_max_mps);
        else
            fprintf(f, "drive slip: no\n");
        if (r.torque_max_Nm >= 1e4)
            fprintf(f, "peak drive torque %.1f kN·m\n", r.torque_max_Nm / 1e3);
        else
            fprintf(f, "peak drive torque %.4g N·m\n", r.torque_max_Nm);
    }
    for (int p = 0; p < bd_sim_pulley_count(sim); p++) {
        bd_takeup_state tk;
        if (bd_sim_takeup(sim, p, &tk) == 0)
            fprintf(f, "takeup '%s': travel %.3f to %.3f m\n", def->pulleys[p].name,
                    tk.travel_min_m, tk.travel_max_m);
    }
    /* counted as the report counts them: the run's and the static
     * design's that summary.json holds */
    fprintf(f, "warnings: %d", bd_sim_warning_count(sim) + r.static_warnings);
    if (r.static_warnings > 0)
        fprintf(f, " (%d of them the static design's: beltdyn static)", r.static_warnings);
    fprintf(f, "\n");
}

/* the end-of-run summary of a boom on a terminal: its extremes
 * (boom-format.md, summary.json `boom`) */
static void print_boom_summary(const bd_boom *boom, const bd_boom_def *def, FILE *f)
{
    bd_boom_result r;
    bd_boom_get_result(boom, &r);
    fprintf(f, "tip: x up to %.3f m, y up to %.3f m; its deflection from the rigid boom's "
            "tip up to %.1f mm\n", r.tip_x_max_m, r.tip_y_max_m, r.tip_deflection_max_m * 1e3);
    fprintf(f, "peak telescopic cylinder force %.2f kN\n",
            r.telescopic_cylinder_force_max_N / 1e3);
    if (def->luffing_cylinder.present)
        fprintf(f, "peak luffing cylinder force %.2f kN\n", r.luffing_force_max_N / 1e3);
    else
        fprintf(f, "peak pivot moment %.2f kN·m\n", r.luffing_force_max_N / 1e3);
    fprintf(f, "peak pad normal force %.2f kN\n", r.pad_normal_force_max_N / 1e3);
}

typedef struct run_args {
    const char *path, *dir;
    int quiet, hdf5, force, mesh_check;
} run_args;

/* what every run does before it starts (cli.md): the output directory,
 * never one that holds something else; Ctrl-C; the progress line and the
 * warnings. 0, or exit code 2 with the message printed */
static int run_start(const run_args *a, bd_run_options *opt)
{
    char err[1024] = "";
    if (bd_run_dir_prepare(a->dir, a->force, err, sizeof err) != BD_RUN_OK) {
        fprintf(stderr, "beltdyn: %s\n", err);
        return 2;
    }
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigaction(SIGINT, &sa, NULL);
    memset(opt, 0, sizeof *opt);
    opt->out_dir = a->dir;
    opt->progress = !a->quiet && isatty(STDERR_FILENO) ? show_progress : NULL;
    opt->interrupted = &interrupted;
    opt->hdf5 = a->hdf5;
    opt->message = show_warning;
    return 0;
}

/* a run's end: its error said; 1 when a terminal wants the summary */
static int run_end(int rc, const char *err, const run_args *a)
{
    if (rc != BD_RUN_OK)
        fprintf(stderr, "beltdyn: %s%s\n", rc == BD_RUN_FAILED ? "error: " : "", err);
    return (rc == BD_RUN_OK || rc == BD_RUN_FAILED || rc == BD_RUN_INTERRUPTED) && !a->quiet
           && isatty(STDOUT_FILENO);
}

static int run_boom(const run_args *a)
{
    if (a->hdf5) {
        fprintf(stderr, "beltdyn: %s: --hdf5 writes a conveyor's tension field; a boom has "
                "none\n", a->path);
        return 2;
    }
    bd_boom_def def;
    bd_boom *boom = NULL;
    int rc = load_boom(a->path, &def, &boom);
    if (rc != 0)
        return rc;
    bd_run_options opt;
    rc = run_start(a, &opt);
    if (rc == 0) {
        char err[1024] = "";
        rc = bd_boom_run(boom, &opt, err, sizeof err);
        if (run_end(rc, err, a))
            print_boom_summary(boom, &def, stdout);
    }
    bd_boom_free(boom);
    bd_boom_def_free(&def);
    return rc;
}

/* the mesh check (io/mesh_check.c): the model run again on elements half
 * as long into DIR/.mesh-check (its tension field thinned, removed after),
 * the figures compared into DIR/summary.json. The run's exit code: 0, 1
 * (the finer run failed or was interrupted), 2 (it cannot be built) */
static const char *const mesh_files[] = {"summary.json", "history.csv", "tension.csv",
                                         "envelope.csv", "parts.csv", "tension.h5"};

static int mesh_check(const run_args *a, const bd_sim *coarse, bd_run_options *opt)
{
    bd_model_def def;
    bd_diag diag;
    bd_diag_init(&diag);
    if (bd_model_load(a->path, &def, &diag))
        return said(&diag, 1);
    bd_mesh_check mc;
    bd_mesh_refine(coarse, &def, &mc);
    bd_sim *fine = NULL;
    if (bd_sim_create(&def, &fine, &diag)) {
        fprintf(stderr, "beltdyn: mesh check: the model on %s cannot be built:\n", mc.mesh);
        bd_model_def_free(&def);
        return said(&diag, 1);
    }
    bd_diag_free(&diag);
    char tmp[1024], err[1200] = "";
    int rc = BD_RUN_BAD_INPUT;
    if (snprintf(tmp, sizeof tmp, "%s/.mesh-check", a->dir) >= (int)sizeof tmp
        || (mkdir(tmp, 0777) != 0 && errno != EEXIST)) {
        snprintf(err, sizeof err, "cannot make '%s'", tmp);
    } else {
        if (!a->quiet)
            fprintf(stderr, "mesh check: the same run on %s\n", mc.mesh);
        bd_run_options o = *opt;
        o.out_dir = tmp;
        o.hdf5 = 0;
        struct timespec t0, t1;
        clock_gettime(CLOCK_MONOTONIC, &t0);
        rc = bd_sim_run(fine, &o, err, sizeof err);
        clock_gettime(CLOCK_MONOTONIC, &t1);
        mc.fine_wall_s = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
        if (rc == BD_RUN_OK) {
            bd_mesh_compare(coarse, fine, &mc);
            rc = bd_mesh_check_write(a->dir, &mc, err, sizeof err) ? BD_RUN_FAILED : BD_RUN_OK;
        }
        /* the finer run's files, and those it writes by a temporary name
         * (.NAME.part) should it have stopped before renaming them */
        for (size_t i = 0; i < sizeof mesh_files / sizeof mesh_files[0]; i++) {
            char f[1100];
            snprintf(f, sizeof f, "%s/%s", tmp, mesh_files[i]);
            remove(f);
            snprintf(f, sizeof f, "%s/.%s.part", tmp, mesh_files[i]);
            remove(f);
        }
        if (rmdir(tmp) != 0 && errno != ENOENT)
            fprintf(stderr, "beltdyn: mesh check: could not remove '%s'\n", tmp);
    }
    if (rc != BD_RUN_OK)
        fprintf(stderr, "beltdyn: %smesh check: %s\n", rc == BD_RUN_FAILED ? "error: " : "", err);
    else if (!a->quiet && isatty(STDOUT_FILENO)) {
        printf("mesh check, %s: %s\n", mc.mesh, mc.converged ? "converged" : "NOT converged");
        for (int i = 0; i < mc.count; i++)
            printf("  %-28s %12.6g -> %-12.6g %s  %+.2f %%%s\n", mc.q[i].name, mc.q[i].coarse,
                   mc.q[i].fine, mc.q[i].unit, 100.0 * mc.q[i].change_rel,
                   mc.q[i].pass ? "" : "  (over 2 %)");
        if (mc.running_force_why[0])
            printf("  steady running force not compared: %s\n", mc.running_force_why);
    }
    bd_sim_free(fine);
    bd_model_def_free(&def);
    return rc == BD_RUN_BAD_INPUT ? 2 : rc;
}

static int cmd_run(int argc, char **argv)
{
    run_args a = {.dir = "out"};
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0 && i + 1 < argc)
            a.dir = argv[++i];
        else if (strcmp(argv[i], "--quiet") == 0 || strcmp(argv[i], "-q") == 0)
            a.quiet = 1;
        else if (strcmp(argv[i], "--hdf5") == 0)
            a.hdf5 = 1;
        else if (strcmp(argv[i], "--force") == 0)
            a.force = 1;
        else if (strcmp(argv[i], "--mesh-check") == 0)
            a.mesh_check = 1;
        else if (!a.path && argv[i][0] != '-')
            a.path = argv[i];
        else
            return usage(stderr);
    }
    if (!a.path)
        return usage(stderr);
    if (bd_model_is_boom(a.path) && a.mesh_check) {
        fprintf(stderr, "beltdyn: %s: --mesh-check halves a conveyor belt's elements; a boom "
                "has none\n", a.path);
        return 2;
    }
    if (bd_model_is_boom(a.path))
        return run_boom(&a);
    bd_model_def def;
    bd_sim *sim = NULL;
    int rc = load_model(a.path, &def, &sim);
    if (rc != 0)
        return rc;
    bd_run_options opt;
    rc = run_start(&a, &opt);
    if (rc == 0) {
        char err[1024] = "";
        rc = bd_sim_run(sim, &opt, err, sizeof err);
        int show = run_end(rc, err, &a);
        if (show) {
            print_summary(sim, &def, stdout);
            bd_report_print_checks(a.dir, stdout);
        }
        if (rc == BD_RUN_OK && a.mesh_check)
            rc = mesh_check(&a, sim, &opt);
    }
    bd_sim_free(sim);
    bd_model_def_free(&def);
    return rc;
}

static int cmd_report(int argc, char **argv)
{
    if (argc != 1)
        return usage(stderr);
    char err[1024] = "";
    if (bd_report_write(argv[0], err, sizeof err) != 0) {
        fprintf(stderr, "beltdyn: error: %s\n", err);
        return 2;
    }
    return 0;
}

/* "a,b,c" → numbers; 0 ok, else a message */
static int parse_list(const char *opt, const char *text, double *out, int *n)
{
    char buf[512];
    snprintf(buf, sizeof buf, "%s", text);
    *n = 0;
    for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
        char *end;
        double v = strtod(tok, &end);
        if (end == tok || *end != '\0' || *n >= BD_STUDY_MAX) {
            fprintf(stderr, "beltdyn: %s: '%s' is not a list of at most %d numbers\n", opt, text,
                    BD_STUDY_MAX);
            return 1;
        }
        out[(*n)++] = v;
    }
    return *n == 0;
}

static int parse_curves(const char *text, bd_study_options *o)
{
    char buf[512];
    snprintf(buf, sizeof buf, "%s", text);
    o->ncurves = 0;
    for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
        if (o->ncurves >= BD_STUDY_MAX
            || bd_start_curve_from_name(tok, &o->curves[o->ncurves]) != 0) {
            fprintf(stderr, "beltdyn: --curves: '%s' is not one of linear, harrison, nordell, "
                    "s-curve\n", tok);
            return 1;
        }
        o->ncurves++;
    }
    return o->ncurves == 0;
}

/* the study's one progress line (cli.md: on a terminal only) */
static void show_study_progress(const bd_study_progress *p, void *ctx)
{
    (void)ctx;
    if (p->clear || p->finished) {
        if (progress_open)
            fputs("\r\033[K", stderr);
        progress_open = 0;
        return;
    }
    char rem[32] = "?";
    if (p->remaining_s >= 0.0)
        snprintf(rem, sizeof rem, "%.0f s", p->remaining_s);
    fprintf(stderr, "\r  study: %d/%d cases done", p->done, p->to_run);
    if (p->failed > 0)
        fprintf(stderr, " (%d not completed)", p->failed);
    fprintf(stderr, ", %d running on %d %s, %5.1f%%, wall %.0f s, remaining %s\033[K",
            p->running, p->workers, p->workers == 1 ? "process" : "processes",
            100.0 * p->fraction, p->wall_s, rem);
    fflush(stderr);
    progress_open = 1;
}

/* `study`, or `cases` (cases = 1): the five standard load cases, then
 * their reports and the one comparing them */
static int cmd_study(int argc, char **argv, int cases)
{
    bd_study_options o;
    bd_study_options_default(&o);
    o.out_dir = cases ? "cases" : "study";
    o.load_cases = cases;
    int quiet = 0, start_options = 0;
    char err[1024] = "";
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        int more = i + 1 < argc;
        if (strcmp(a, "-o") == 0 && more)
            o.out_dir = argv[++i];
        else if (strcmp(a, "--curves") == 0 && more) {
            start_options = 1;
            if (parse_curves(argv[++i], &o))
                return 2;
        } else if (strcmp(a, "--times") == 0 && more) {
            start_options = 1;
            if (parse_list(a, argv[++i], o.times, &o.ntimes))
                return 2;
        } else if (strcmp(a, "--delays") == 0 && more) {
            start_options = 1;
            if (parse_list(a, argv[++i], o.delays, &o.ndelays))
                return 2;
        } else if (strcmp(a, "--after") == 0 && more) {
            int one = 0;
            if (parse_list(a, argv[++i], &o.after, &one) || one != 1 || !(o.after > 0.0)) {
                fprintf(stderr, "beltdyn: --after: expected one number of seconds > 0\n");
                return 2;
            }
        } else if ((strcmp(a, "-j") == 0 || strcmp(a, "--jobs") == 0) && more) {
            char *end;
            long n = strtol(argv[++i], &end, 10);
            if (*end != '\0' || n < 1 || n > 4096) {
                fprintf(stderr, "beltdyn: %s: expected a number of worker processes >= 1, "
                        "got '%s'\n", a, argv[i]);
                return 2;
            }
            o.jobs = (int)n;
        } else if (strncmp(a, "-j", 2) == 0 && a[2] >= '0' && a[2] <= '9') {
            char *end;
            long n = strtol(a + 2, &end, 10);
            if (*end != '\0' || n < 1 || n > 4096) {
                fprintf(stderr, "beltdyn: -j: expected a number of worker processes >= 1\n");
                return 2;
            }
            o.jobs = (int)n;
        } else if (strcmp(a, "--resume") == 0)
            o.resume = 1;
        else if (strcmp(a, "--force") == 0)
            o.force = 1;
        else if ((strcmp(a, "--vary") == 0 || strcmp(a, "--range") == 0) && more) {
            int vary = a[2] == 'v';
            int *n = vary ? &o.nvary : &o.nrange;
            if (*n >= BD_STUDY_MAX_KEYS) {
                fprintf(stderr, "beltdyn: %s: at most %d keys\n", a, BD_STUDY_MAX_KEYS);
                return 2;
            }
            bd_study_range *r = vary ? &o.vary[*n] : &o.range[*n];
            if (bd_study_parse_range(argv[++i], vary, r, err, sizeof err)) {
                fprintf(stderr, "beltdyn: %s %s\n", a, err);
                return 2;
            }
            (*n)++;
        } else if (strcmp(a, "--sample") == 0 && more) {
            char *end;
            long n = strtol(argv[++i], &end, 10);
            if (*end != '\0' || n < 1 || n > 100000) {
                fprintf(stderr, "beltdyn: --sample: expected a number of cases from 1 to "
                        "100000, got '%s'\n", argv[i]);
                return 2;
            }
            o.samples = (int)n;
        } else if (strcmp(a, "--seed") == 0 && more) {
            if (cases) {
                fprintf(stderr, "beltdyn: cases runs the five standard load cases: --seed "
                        "belongs to study --sample\n");
                return 2;
            }
            char *end;
            o.seed = strtoull(argv[++i], &end, 10);
            if (*end != '\0' || argv[i][0] == '-' || !argv[i][0]) {
                fprintf(stderr, "beltdyn: --seed: expected a whole number >= 0, got '%s'\n",
                        argv[i]);
                return 2;
            }
        } else if (strcmp(a, "--best") == 0 && more)
            o.best = argv[++i];
        else if (strcmp(a, "--where") == 0 && more) {
            if (o.nwhere >= BD_STUDY_MAX_WHERE) {
                fprintf(stderr, "beltdyn: --where: at most %d\n", BD_STUDY_MAX_WHERE);
                return 2;
            }
            if (bd_study_parse_where(argv[++i], &o.where[o.nwhere], err, sizeof err)) {
                fprintf(stderr, "beltdyn: --where %s\n", err);
                return 2;
            }
            o.nwhere++;
        } else if (strcmp(a, "--quiet") == 0 || strcmp(a, "-q") == 0)
            quiet = 1;
        else if (!o.model_path && a[0] != '-')
            o.model_path = a;
        else
            return usage(stderr);
    }
    if (!o.model_path)
        return usage(stderr);
    if (conveyor_only(cases ? "cases" : "study", o.model_path))
        return 2;
    if (cases && start_options) {
        fprintf(stderr, "beltdyn: cases runs the five standard load cases with the model's "
                "own start: --curves, --times and --delays belong to study\n");
        return 2;
    }
    if (start_options && (o.nvary > 0 || o.samples > 0 || o.nrange > 0)) {
        fprintf(stderr, "beltdyn: --curves, --times and --delays make a start study; a sweep "
                "varies the start through its keys, e.g. --vary "
                "pulleys.NAME.drive.start.time=5:20:4\n");
        return 2;
    }
    /* Ctrl-C, or a batch scheduler's SIGTERM at its time limit: the
     * running cases stop, the table keeps what is complete */
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    o.progress = !quiet && isatty(STDERR_FILENO) ? show_study_progress : NULL;
    o.message = show_message;
    o.interrupted = &interrupted;
    int rc = bd_study_run(&o, stdout, err, sizeof err);
    if (rc != BD_RUN_OK && err[0])
        fprintf(stderr, "beltdyn: %s%s\n", rc == BD_RUN_FAILED ? "error: " : "", err);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return usage(stderr);
    const char *cmd = argv[1];
    if (strcmp(cmd, "check") == 0)
        return cmd_check(argc - 2, argv + 2);
    if (strcmp(cmd, "static") == 0)
        return cmd_static(argc - 2, argv + 2);
    if (strcmp(cmd, "run") == 0)
        return cmd_run(argc - 2, argv + 2);
    if (strcmp(cmd, "report") == 0)
        return cmd_report(argc - 2, argv + 2);
    if (strcmp(cmd, "study") == 0)
        return cmd_study(argc - 2, argv + 2, 0);
    if (strcmp(cmd, "cases") == 0)
        return cmd_study(argc - 2, argv + 2, 1);
    if (strcmp(cmd, "--version") == 0) {
        printf("beltdyn %s\n", bd_version());
        return 0;
    }
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
        usage(stdout);
        return 0;
    }
    fprintf(stderr, "beltdyn: unknown command '%s'\n", cmd);
    return usage(stderr);
}
