#include "testlib.h"

int bd_test_failures = 0;
int bd_test_checks = 0;

int bd_test_finish(const char *name)
{
    printf("%s: %d checks, %d failed\n", name, bd_test_checks, bd_test_failures);
    return bd_test_failures == 0 ? 0 : 1;
}

#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "beltdyn/model.h"
#include "beltdyn/sim.h"

static void print_diag(const bd_diag *d)
{
    for (int i = 0; i < d->count + d->warning_count; i++)
        fprintf(stderr, "%s\n", d->lines[i]);
}

char *bd_test_read_data(const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", BD_TEST_DATA_DIR, name);
    char *text = NULL;
    size_t len;
    CHECK(bd_read_file(path, &text, &len) == BD_READ_OK);
    return text;
}

char *bd_test_replaced(const char *text, const char *from, const char *to)
{
    const char *at = strstr(text, from);
    if (!at)
        return NULL;
    size_t n = strlen(text) + strlen(to) + 1;
    char *s = malloc(n);
    if (!s)
        return NULL;
    size_t head = (size_t)(at - text);
    memcpy(s, text, head);
    snprintf(s + head, n - head, "%s%s", to, at + strlen(from));
    return s;
}

int bd_test_make_sim(const char *yaml, bd_model_def *def, bd_sim **sim)
{
    bd_diag d;
    bd_diag_init(&d);
    int bad = bd_model_load_string(yaml, strlen(yaml), "test.yaml", def, &d);
    print_diag(&d);
    bd_diag_free(&d);
    if (!bad)
        bad = bd_test_create(def, sim);
    if (bad) {
        fprintf(stderr, "test model did not load\n");
        exit(2);
    }
    return 0;
}

int bd_test_compile(const bd_model_def *def, bd_model **model)
{
    bd_diag d;
    bd_diag_init(&d);
    int rc = bd_model_compile(def, model, &d);
    print_diag(&d);
    bd_diag_free(&d);
    return rc;
}

int bd_test_create(const bd_model_def *def, bd_sim **sim)
{
    bd_diag d;
    bd_diag_init(&d);
    int rc = bd_sim_create(def, sim, &d);
    print_diag(&d);
    bd_diag_free(&d);
    return rc;
}

int bd_test_run_to(bd_sim *sim, double t)
{
    char err[512];
    while (bd_sim_time(sim) < t - 0.5 * bd_sim_time_step(sim))
        if (bd_sim_step(sim, 1, err, sizeof err)) {
            fprintf(stderr, "run failed: %s\n", err);
            return 1;
        }
    return 0;
}

static double energy_sum(const bd_sim *sim)
{
    bd_energy_state en;
    bd_sim_energy(sim, &en);
    return en.kinetic_J + en.potential_J + en.dissipated_J - en.input_J;
}

int bd_test_run_balanced(bd_sim *sim, double t, double *err)
{
    char msg[512];
    bd_sim_book_energy_every_step(sim, 1);
    if (bd_sim_step(sim, 1, msg, sizeof msg)) {
        fprintf(stderr, "run failed: %s\n", msg);
        return 1;
    }
    double e0 = energy_sum(sim);
    int failed = bd_test_run_to(sim, t);
    *err = energy_sum(sim) - e0;
    return failed;
}

unsigned long long bd_test_hash_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    unsigned long long h = 1469598103934665603ULL;
    char line[65536];
    while (fgets(line, sizeof line, f)) {
        if (strstr(line, "\"wall_time_s\""))
            continue;
        for (const unsigned char *p = (const unsigned char *)line; *p; p++) {
            h ^= *p;
            h *= 1099511628211ULL;
        }
    }
    fclose(f);
    return h;
}

const char *const bd_test_run_files[BD_TEST_RUN_FILE_COUNT] = {"summary.json", "history.csv",
                                                               "tension.csv", "envelope.csv"};

void bd_test_remove_run(const char *dir)
{
    for (int i = 0; i < BD_TEST_RUN_FILE_COUNT; i++) {
        char p[1024];
        snprintf(p, sizeof p, "%s/%s", dir, bd_test_run_files[i]);
        remove(p);
    }
    remove(dir);
}

double bd_test_rigid_mass(const bd_sim *sim)
{
    double M = bd_sim_belt_mass(sim);
    for (int i = 0; i < bd_sim_pulley_count(sim); i++) {
        bd_pulley_state p;
        bd_sim_pulley(sim, i, &p);
        M += p.inertia_kgm2 / (p.radius_m * p.radius_m);
    }
    for (int i = 0; i < bd_sim_idler_count(sim); i++) {
        bd_idler_state id;
        bd_sim_idler(sim, i, &id);
        M += id.inertia_kgm2 / (id.radius_m * id.radius_m);
    }
    return M;
}
