/* The pieces of a study that are not the simulator (issue 16):
 * - key paths: a number in the model text replaced in place (the rest of
 *   the text unchanged), a key the file lacks added to a block mapping
 *   and to a flow mapping, both read back by the loader; the errors;
 * - the grid (every combination, ends exact) and the Latin hypercube (one
 *   case per stratum of every key, the same for a seed);
 * - Spearman's rank correlation on known data;
 * - a whole file read, a path joined (base/file.c);
 * - the runner in worker processes: every job reported once with its
 *   result, a job whose process dies is reported failed and the others
 *   still finish, the longest job is handed out first. */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "base/file.h"
#include "beltdyn/model.h"
#include "io/sensitivity.h"
#include "study/keypath.h"
#include "study/runner.h"
#include "study/sweep.h"
#include "testlib.h"

static const char model[] =
    "name: key test\n"
    "belt:\n"
    "  mass_per_length: 10\n"
    "  axial_stiffness: 1.0e6   # N\n"
    "pulleys:\n"
    "  - name: head\n"
    "    x: 10\n"
    "    y: 0\n"
    "    radius: 0.2\n"
    "    wrap: cw\n"
    "    drive:\n"
    "      control: speed\n"
    "      speed: 1.0\n"
    "      start: {curve: s-curve, time: 1}\n"
    "  - name: tail\n"
    "    x: 0\n"
    "    y: 0\n"
    "    radius: 0.2\n"
    "    wrap: cw\n"
    "    takeup: {type: gravity, mass: 600, axis: [-1, 0]}\n"
    "simulation:\n"
    "  duration: 1.5\n";

/* load text with key set to v; 0 ok */
static int load_with(const char *key, double v, bd_model_def *def, char **text_out)
{
    bd_key_site site;
    char err[600];
    if (bd_key_find(model, strlen(model), key, &site, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    size_t len;
    char *text = bd_key_apply(model, strlen(model), &site, &v, 1, &len);
    bd_diag diag;
    bd_diag_init(&diag);
    int bad = bd_model_load_string(text, len, "key.yaml", def, &diag);
    for (int i = 0; i < diag.count && strcmp(key, "belt.colour") != 0; i++)
        fprintf(stderr, "%s\n%s\n", diag.lines[i], text);
    bd_diag_free(&diag);
    if (text_out)
        *text_out = text;
    else
        free(text);
    return bad;
}

static void test_keys(void)
{
    bd_model_def def;
    char *text;
    /* in place: the number changes, nothing else */
    CHECK(load_with("belt.axial_stiffness", 2.5e6, &def, &text) == 0);
    CHECK(def.belt.axial_stiffness == 2.5e6);
    const char *at = strstr(model, "1.0e6");
    CHECK(strncmp(text, model, (size_t)(at - model)) == 0);
    CHECK(strstr(text, "axial_stiffness: 2500000   # N\n") != NULL);
    free(text);
    bd_model_def_free(&def);
    /* a list entry by name, in a flow mapping; a gravity takeup's force
     * follows its mass (the loader derives it) */
    CHECK(load_with("pulleys.tail.takeup.mass", 900, &def, NULL) == 0);
    CHECK(def.pulleys[1].takeup.mass == 900.0);
    CHECK_REL(bd_table_eval(&def.pulleys[1].takeup.force, 0.0), 900.0 * def.gravity, 1e-12);
    bd_model_def_free(&def);
    /* by index; a value with 17 digits reads back the same double */
    double third = 1.0 / 3.0;
    CHECK(load_with("pulleys[0].radius", third, &def, NULL) == 0);
    CHECK(def.pulleys[0].radius == third);
    bd_model_def_free(&def);
    /* added to a flow mapping, and to a block mapping */
    CHECK(load_with("pulleys.head.drive.start.delay", 2.0, &def, NULL) == 0);
    CHECK(def.pulleys[0].drive.start_delay == 2.0 && def.pulleys[0].drive.start_time == 1.0);
    bd_model_def_free(&def);
    CHECK(load_with("pulleys.head.mass", 75.0, &def, NULL) == 0);
    CHECK(def.pulleys[0].mass == 75.0 && def.pulleys[0].drive.speed == 1.0);
    bd_model_def_free(&def);
    CHECK(load_with("simulation.output_interval", 0.02, &def, NULL) == 0);
    CHECK(def.simulation.output_interval == 0.02 && def.simulation.duration == 1.5);
    bd_model_def_free(&def);
    /* a whole section added: design is not in the file */
    CHECK(load_with("design.f", 0.025, &def, NULL) == 0);
    CHECK(def.design.present && def.design.f == 0.025);
    bd_model_def_free(&def);
    /* what is not a number's place */
    bd_key_site site;
    char err[600];
    CHECK(bd_key_find(model, strlen(model), "pulleys.head.wrap", &site, err, sizeof err) != 0);
    CHECK(strstr(err, "pulleys.head.wrap") && strstr(err, "'cw'") && strstr(err, "not a number"));
    CHECK(bd_key_find(model, strlen(model), "pulleys.middle.mass", &site, err, sizeof err) != 0);
    CHECK(strstr(err, "no entry named 'middle'") && strstr(err, "head, tail"));
    CHECK(bd_key_find(model, strlen(model), "belt", &site, err, sizeof err) != 0);
    CHECK(strstr(err, "a mapping"));
    CHECK(bd_key_find(model, strlen(model), "belt..x", &site, err, sizeof err) != 0);
    CHECK(strstr(err, "not a key path"));
    CHECK(bd_key_find(model, strlen(model), "belt.mass_per_length.x", &site, err,
                      sizeof err) != 0);
    /* a key the model does not take: added, and the loader refuses it */
    CHECK(load_with("belt.colour", 1.0, &def, NULL) != 0);
    /* one number under two spellings: the same site, which the text
     * cannot be set at twice (the study refuses the pair, naming both) */
    bd_key_site two[2];
    CHECK(bd_key_find(model, strlen(model), "pulleys.head.radius", &two[0], err, sizeof err)
          == 0);
    CHECK(bd_key_find(model, strlen(model), "pulleys[0].radius", &two[1], err, sizeof err)
          == 0);
    CHECK(two[0].len > 0 && two[0].at == two[1].at && two[0].len == two[1].len);
    double both[2] = {0.25, 0.3};
    size_t len;
    CHECK(bd_key_apply(model, strlen(model), two, both, 2, &len) == NULL);
}

static void test_grid_and_sample(void)
{
    bd_study_range k[2];
    char err[300];
    CHECK(bd_study_parse_range("a.b=0.1:0.3:3", 1, &k[0], err, sizeof err) == 0);
    CHECK(bd_study_parse_range("c=10:20:2", 1, &k[1], err, sizeof err) == 0);
    CHECK(strcmp(k[0].key, "a.b") == 0 && k[0].n == 3 && k[1].hi == 20.0);
    CHECK(bd_study_parse_range("a=1:2", 1, &k[0], err, sizeof err) != 0);
    CHECK(bd_study_parse_range("a=1:2:0", 1, &k[0], err, sizeof err) != 0);
    CHECK(bd_study_parse_range("a=2:1", 0, &k[0], err, sizeof err) != 0);
    CHECK(bd_study_parse_range("=1:2:3", 1, &k[0], err, sizeof err) != 0);
    bd_study_parse_range("a.b=0.1:0.3:3", 1, &k[0], err, sizeof err);
    int n = 0;
    double *g = bd_sweep_grid(k, 2, &n);
    CHECK(g && n == 6);
    /* the first key slowest; the ends exact */
    CHECK(g[0] == 0.1 && g[1] == 10.0 && g[3] == 20.0 && g[4] == 0.2 && g[10] == 0.3
          && g[11] == 20.0);
    free(g);
    bd_study_range r[3];
    bd_study_parse_range("x=0:1", 0, &r[0], err, sizeof err);
    bd_study_parse_range("y=-5:5", 0, &r[1], err, sizeof err);
    bd_study_parse_range("z=100:200", 0, &r[2], err, sizeof err);
    const int N = 17;
    double *s1 = bd_sweep_lhs(r, 3, N, 42), *s2 = bd_sweep_lhs(r, 3, N, 42),
           *s3 = bd_sweep_lhs(r, 3, N, 43);
    CHECK(s1 && s2 && s3 && memcmp(s1, s2, sizeof(double) * 3 * (size_t)N) == 0);
    CHECK(memcmp(s1, s3, sizeof(double) * 3 * (size_t)N) != 0);
    for (int key = 0; key < 3; key++) {
        int seen[17] = {0};
        for (int i = 0; i < N; i++) {
            double u = (s1[i * 3 + key] - r[key].lo) / (r[key].hi - r[key].lo);
            int stratum = (int)floor(u * N);
            CHECK(u >= 0.0 && u < 1.0 && stratum >= 0 && stratum < N);
            if (stratum >= 0 && stratum < N)
                seen[stratum]++;
        }
        for (int b = 0; b < N; b++)
            CHECK(seen[b] == 1);
    }
    free(s1);
    free(s2);
    free(s3);
}

static void test_spearman(void)
{
    double x[6] = {1, 2, 3, 4, 5, 6};
    double up[6] = {0.1, 0.5, 0.6, 3, 10, 11};       /* monotone, not linear */
    double down[6] = {9, 8, 7, 1, 0.5, -3};
    double flat[6] = {2, 2, 2, 2, 2, 2};
    double mixed[6] = {1, 3, 2, 5, 4, 6};
    CHECK_ABS(bd_spearman(x, up, 6), 1.0, 1e-12);
    CHECK_ABS(bd_spearman(x, down, 6), -1.0, 1e-12);
    CHECK(isnan(bd_spearman(x, flat, 6)));
    /* 1 - 6·Σd²/(n(n²-1)) with Σd² = 4: 1 - 24/210 */
    CHECK_ABS(bd_spearman(x, mixed, 6), 1.0 - 24.0 / 210.0, 1e-12);
    /* an output that does not depend on a two-level key of a grid: 0 */
    double key[6] = {0, 1, 0, 1, 0, 1}, out[6] = {5, 5, 7, 7, 6, 6};
    CHECK_ABS(bd_spearman(key, out, 6), 0.0, 1e-12);
    double withnan[6] = {1, NAN, 3, 4, 5, 6};
    CHECK_ABS(bd_spearman(x, withnan, 6), 1.0, 1e-12);
}

/* ---- the runner, with jobs that are not simulations ---- */

#define NJOBS 7
static int seen[NJOBS], order[NJOBS], order_n;

static void job(void *ctx, int j, const bd_job_env *env, bd_job_result *out)
{
    (void)env;
    if (j == 3 && ctx)
        abort();   /* its worker process dies */
    const struct timespec pause = {0, 10000000};
    nanosleep(&pause, NULL);
    out->status = BD_RUN_OK;
    out->wall_s = j;
    out->res.tight_max_N = 1000.0 + j / 7.0;
    snprintf(out->message, sizeof out->message, "job %d", j);
}

static void done(const bd_job_result *r, void *ctx)
{
    if (order_n < NJOBS)
        order[order_n] = r->job;
    order_n++;
    if (r->job < 0 || r->job >= NJOBS)
        return;
    seen[r->job]++;
    if (r->job == 3 && ctx)
        CHECK(r->status == BD_RUN_FAILED && strstr(r->message, "signal"));
    else
        CHECK(r->status == BD_RUN_OK && r->res.tight_max_N == 1000.0 + r->job / 7.0
              && r->wall_s == r->job);
}

/* the NJOBS jobs on `workers` workers, job 5 the costliest */
static const double job_cost[NJOBS] = {1, 1, 1, 1, 1, 9, 1};

static bd_runner jobs_runner(int workers)
{
    bd_runner r;
    memset(&r, 0, sizeof r);
    r.count = NJOBS;
    r.cost = job_cost;
    r.workers = workers;
    r.run = job;
    r.done = done;
    return r;
}

static void test_runner(void)
{
    /* the aborting job's core dump is not wanted */
    signal(SIGABRT, SIG_DFL);
    bd_runner r = jobs_runner(2);
    char err[256];
    int dies = 1;   /* ctx: job 3 aborts */
    r.run_ctx = r.done_ctx = &dies;
    CHECK(bd_runner_run(&r, err, sizeof err) == BD_RUN_OK);
    for (int j = 0; j < NJOBS; j++)
        CHECK(seen[j] == 1);
    CHECK(order_n == NJOBS);
    /* in this process, one at a time: the costliest first, then in order */
    memset(seen, 0, sizeof seen);
    order_n = 0;
    r.workers = 1;
    r.run_ctx = r.done_ctx = NULL;
    CHECK(bd_runner_run(&r, err, sizeof err) == BD_RUN_OK);
    const int want[NJOBS] = {5, 0, 1, 2, 3, 4, 6};
    CHECK(order_n == NJOBS && memcmp(order, want, sizeof want) == 0);
    /* skipped jobs are not run */
    r.workers = 2;
    r.run_ctx = r.done_ctx = &dies;
    memset(seen, 0, sizeof seen);
    order_n = 0;
    unsigned char todo[NJOBS] = {1, 0, 1, 0, 0, 0, 1};
    r.todo = todo;
    CHECK(bd_runner_run(&r, err, sizeof err) == BD_RUN_OK);
    CHECK(order_n == 3 && seen[0] == 1 && seen[2] == 1 && seen[6] == 1 && seen[1] == 0);
}

/* workers that cannot start (no file descriptors left for their pipes,
 * as under EMFILE or a fork's EAGAIN): the one that did start runs every
 * job; none at all is an error naming why. A slot whose worker never
 * started used to count as busy with job 0 forever, and the coordinator
 * spun at full speed without end (the alarm fails this test then) */
static int messages;

static void count_message(const char *line, void *ctx)
{
    (void)ctx;
    if (strstr(line, "could not be started"))
        messages++;
}

static void test_runner_spawn_fails(void)
{
    bd_runner r = jobs_runner(3);
    r.message = count_message;
    char err[256];
    struct rlimit old, low;
    CHECK(getrlimit(RLIMIT_NOFILE, &old) == 0);
    int first = dup(0);   /* the lowest free descriptor */
    close(first);
    alarm(60);
    for (int room = 4; room >= 0; room -= 4) {
        /* room 4: the first worker's two pipes, then none for the others */
        low = old;
        low.rlim_cur = (rlim_t)first + (rlim_t)room;
        CHECK(setrlimit(RLIMIT_NOFILE, &low) == 0);
        memset(seen, 0, sizeof seen);
        order_n = messages = 0;
        int rs = bd_runner_run(&r, err, sizeof err);
        CHECK(setrlimit(RLIMIT_NOFILE, &old) == 0);
        CHECK(messages == 1);
        if (room > 0) {
            CHECK(rs == BD_RUN_OK);
            CHECK(order_n == NJOBS);
            for (int j = 0; j < NJOBS; j++)
                CHECK(seen[j] == 1);
        } else {
            CHECK(rs == BD_RUN_FAILED && order_n == 0);
            CHECK(strstr(err, "no worker process could be started for 7 cases (pipe: "));
        }
    }
    alarm(0);
}

/* a whole file: across the first buffer's growth, empty, missing, a
 * directory (opens, cannot be read) */
static void test_read_file(void)
{
    char path[] = "/tmp/bd_read_fileXXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    FILE *f = fdopen(fd, "wb");
    for (int i = 0; i < 20000; i++)
        fprintf(f, "%07d\n", i);   /* 160 000 bytes */
    fclose(f);
    char *text;
    size_t len;
    CHECK(bd_read_file(path, &text, &len) == BD_READ_OK);
    CHECK(len == 160000 && text[len] == '\0' && strncmp(text + len - 8, "0019999\n", 8) == 0);
    free(text);
    f = fopen(path, "wb");
    fclose(f);
    CHECK(bd_read_file(path, &text, &len) == BD_READ_OK && len == 0 && text[0] == '\0');
    free(text);
    remove(path);
    CHECK(bd_read_file(path, &text, &len) == BD_READ_OPEN && text == NULL && errno == ENOENT);
    CHECK(bd_read_file("/tmp", &text, &len) == BD_READ_ERROR && text == NULL && len == 0);
    /* a path joined whole, or refused: never cut short */
    char p[8];
    CHECK(bd_path_join(p, sizeof p, "ab", "cdef") == 0 && strcmp(p, "ab/cdef") == 0);
    CHECK(bd_path_join(p, sizeof p, "ab", "cdefg") == -1 && p[0] == '\0');
}

int main(void)
{
    test_keys();
    test_grid_and_sample();
    test_spearman();
    test_runner();
    test_runner_spawn_fails();
    test_read_file();
    return bd_test_finish("test_study_parts");
}
