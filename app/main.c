/* beltdyn: the command line (spec/cli.md). Only the public API is used. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "beltdyn/model.h"
#include "beltdyn/report.h"
#include "beltdyn/sim.h"
#include "beltdyn/standards.h"

static volatile sig_atomic_t interrupted = 0;

static void on_sigint(int sig)
{
    (void)sig;
    interrupted = 1;
}

static int usage(FILE *f)
{
    fprintf(f,
            "usage: beltdyn check MODEL.yaml\n"
            "       beltdyn static MODEL.yaml [--json]\n"
            "       beltdyn run MODEL.yaml [-o DIR] [--quiet] [--hdf5]\n"
            "       beltdyn report DIR\n"
            "\n"
            "  check   read and validate a model; print what was derived\n"
            "  static  design-standard tensions (DIN 22101, ISO 5048, CEMA)\n"
            "  run     transient simulation; writes summary.json, history.csv,\n"
            "          tension.csv and envelope.csv into DIR (default ./out);\n"
            "          --hdf5 also writes the tension field to DIR/tension.h5\n"
            "  report  plots and report.html from a finished run's DIR\n");
    return 2;
}

static void print_diag(const bd_diag *d)
{
    for (int i = 0; i < d->count + d->warning_count; i++)
        fprintf(stderr, "%s\n", d->lines[i]);
}

/* load and build; 0 ok, else exit code 2 with messages printed */
static int load_model(const char *path, bd_model_def *def, bd_sim **sim)
{
    bd_diag diag;
    bd_diag_init(&diag);
    int bad = bd_model_load(path, def, &diag);
    if (!bad && sim)
        bad = bd_sim_create(def, sim, &diag);
    print_diag(&diag);
    bd_diag_free(&diag);
    if (bad)
        bd_model_def_free(def);
    return bad ? 2 : 0;
}

static int cmd_check(int argc, char **argv)
{
    if (argc != 1)
        return usage(stderr);
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

static int cmd_run(int argc, char **argv)
{
    const char *path = NULL, *dir = "out";
    int quiet = 0, hdf5 = 0;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0 && i + 1 < argc)
            dir = argv[++i];
        else if (strcmp(argv[i], "--quiet") == 0 || strcmp(argv[i], "-q") == 0)
            quiet = 1;
        else if (strcmp(argv[i], "--hdf5") == 0)
            hdf5 = 1;
        else if (!path && argv[i][0] != '-')
            path = argv[i];
        else
            return usage(stderr);
    }
    if (!path)
        return usage(stderr);
    bd_model_def def;
    bd_sim *sim = NULL;
    int rc = load_model(path, &def, &sim);
    if (rc != 0)
        return rc;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigaction(SIGINT, &sa, NULL);
    bd_run_options opt = {0};
    opt.out_dir = dir;
    opt.progress = !quiet && isatty(STDERR_FILENO);
    opt.interrupted = &interrupted;
    opt.hdf5 = hdf5;
    char err[1024] = "";
    rc = bd_sim_run(sim, &opt, err, sizeof err);
    if (rc != BD_RUN_OK)
        fprintf(stderr, "beltdyn: %s%s\n", rc == BD_RUN_FAILED ? "error: " : "", err);
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
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
        usage(stdout);
        return 0;
    }
    fprintf(stderr, "beltdyn: unknown command '%s'\n", cmd);
    return usage(stderr);
}
