/* a tiny assertion library for the unit tests: each CHECK counts, a failing
 * one prints where and why, and the test's exit code is the failure count */
#ifndef BD_TESTLIB_H
#define BD_TESTLIB_H
#include <stdio.h>
#include <math.h>

extern int bd_test_failures;
extern int bd_test_checks;

#define CHECK(cond) do { bd_test_checks++; if (!(cond)) { bd_test_failures++; \
    fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); } } while (0)

/* |got - want| <= tol_rel * |want| */
#define CHECK_REL(got, want, tol_rel) do { double g_ = (got), w_ = (want); \
    bd_test_checks++; if (!(fabs(g_ - w_) <= (tol_rel) * fabs(w_))) { bd_test_failures++; \
    fprintf(stderr, "%s:%d: %s = %.9g, want %.9g within %.3g%%\n", __FILE__, __LINE__, \
            #got, g_, w_, 100.0 * (tol_rel)); } } while (0)

#define CHECK_ABS(got, want, tol) do { double g_ = (got), w_ = (want); \
    bd_test_checks++; if (!(fabs(g_ - w_) <= (tol))) { bd_test_failures++; \
    fprintf(stderr, "%s:%d: %s = %.9g, want %.9g within %.3g\n", __FILE__, __LINE__, \
            #got, g_, w_, (double)(tol)); } } while (0)

int bd_test_finish(const char *name);
/* 64-bit FNV-1a of a file's bytes, leaving out any line that holds
 * "wall_time_s" (the one value two runs may differ in); 0 when unreadable */
unsigned long long bd_test_hash_file(const char *path);
/* the files a run writes (cli.md `run` outputs) */
#define BD_TEST_RUN_FILE_COUNT 4
extern const char *const bd_test_run_files[BD_TEST_RUN_FILE_COUNT];
/* remove a run's directory with its files */
void bd_test_remove_run(const char *dir);
#endif

/* the text of tests/data/NAME (malloc'd), or NULL after a failed CHECK */
char *bd_test_read_data(const char *name);
/* `text` with its first `from` replaced by `to` (malloc'd), or NULL when
 * `from` is not in it */
char *bd_test_replaced(const char *text, const char *from, const char *to);
/* build a simulation from model text; aborts the test on failure */
struct bd_model_def;
struct bd_sim;
int bd_test_make_sim(const char *yaml, struct bd_model_def *def, struct bd_sim **sim);
/* compile a model, or create a simulation, from a definition; the
 * diagnostics printed; returns the library's code (0: built) */
struct bd_model;
int bd_test_compile(const struct bd_model_def *def, struct bd_model **model);
int bd_test_create(const struct bd_model_def *def, struct bd_sim **sim);
/* the mass of the rigid-body equation M·dv/dt = F_drive − F_resist(v), kg:
 * belt and material, and Σ I/r² of every pulley (drive inertia included)
 * and idler, from the built model */
double bd_test_rigid_mass(const struct bd_sim *sim);
/* advance to time t (s); returns 0, or 1 if the run failed */
int bd_test_run_to(struct bd_sim *sim, double t);
/* run to t (s) booking the energy every step; *err: how far
 * E_k + E_p + E_d − E_in moved from its value at t = 0 (as the first step
 * books it: the run command's initial_J is not set here), J. Returns 0,
 * or 1 if the run failed */
int bd_test_run_balanced(struct bd_sim *sim, double t, double *err);
