/* Golden outputs of every example (issue 11): each example runs through the
 * public API (load, create, run) for a fixed, shortened duration, and the
 * 64-bit FNV-1a hash of each output file is compared with the hash stored
 * in tests/golden/examples.txt. summary.json is hashed without its
 * wall_time_s line (the only value that may differ between two runs).
 *
 * Outputs change only on purpose: a change that moves any of them by one
 * printed digit fails here. Whoever changes results on purpose reruns
 *     build/tests/test_golden --update
 * and says in the commit why the numbers moved. Tolerance: none; the build
 * uses -ffp-contract=off and no -ffast-math, so the release and the
 * sanitizer builds must give the same bits. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "testlib.h"

#ifndef BD_GOLDEN_FILE
#error "BD_GOLDEN_FILE must name tests/golden/examples.txt"
#endif

/* each example, and how long it runs here (s): full length where that is
 * quick, else long enough to cover the start (the stabilization, the first
 * waves, the drive's speed loop) */
static const struct {
    const char *name;
    double duration;
} EXAMPLES[] = {
    {"vertical_loop", 5.0},  {"flat_belt_drive", 1.5}, {"head_drive", 1.0},
    {"cement_plant", 0.3},   {"overland_axial", 8.0},  {"vbelt_dol_axial", 6.0},
    {"belt_drive_moving_node", 3.0},
};
#define EXAMPLE_COUNT ((int)(sizeof EXAMPLES / sizeof EXAMPLES[0]))


/* run one example into dir; 0 ok */
static int run_example(const char *name, double duration, const char *dir)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s.yaml", BD_EXAMPLES_DIR, name);
    bd_model_def def;
    bd_diag diag;
    bd_diag_init(&diag);
    if (bd_model_load(path, &def, &diag)) {
        for (int i = 0; i < diag.count; i++)
            fprintf(stderr, "%s\n", diag.lines[i]);
        bd_diag_free(&diag);
        return 1;
    }
    def.simulation.duration = duration;
    bd_sim *sim = NULL;
    int rc = bd_sim_create(&def, &sim, &diag);
    bd_diag_free(&diag);
    if (rc == 0) {
        bd_run_options opt = {.out_dir = dir};
        char err[512];
        rc = bd_sim_run(sim, &opt, err, sizeof err);
        if (rc)
            fprintf(stderr, "%s: %s\n", name, err);
        bd_sim_free(sim);
    }
    bd_model_def_free(&def);
    return rc;
}

/* the stored hash of name/file, or 0 */
static uint64_t stored_hash(const char *name, const char *file)
{
    FILE *f = fopen(BD_GOLDEN_FILE, "r");
    if (!f)
        return 0;
    char line[512], a[128], b[128];
    unsigned long long h;
    uint64_t found = 0;
    while (fgets(line, sizeof line, f))
        if (line[0] != '#' && sscanf(line, "%127s %127s %llx", a, b, &h) == 3
            && strcmp(a, name) == 0 && strcmp(b, file) == 0)
            found = (uint64_t)h;
    fclose(f);
    return found;
}

int main(int argc, char **argv)
{
    int update = argc > 1 && strcmp(argv[1], "--update") == 0;
    char tmpl[] = "/tmp/bd_golden_XXXXXX";
    const char *root = mkdtemp(tmpl);
    CHECK(root != NULL);
    if (!root)
        return bd_test_finish("test_golden");
    FILE *out = update ? fopen(BD_GOLDEN_FILE, "w") : NULL;
    if (update && !out) {
        fprintf(stderr, "cannot write %s\n", BD_GOLDEN_FILE);
        return 1;
    }
    if (out)
        fprintf(out, "# example file fnv1a64 (tests/unit/test_golden.c; regenerate with "
                     "test_golden --update)\n");
    for (int k = 0; k < EXAMPLE_COUNT; k++) {
        char dir[512];
        snprintf(dir, sizeof dir, "%s/%s", root, EXAMPLES[k].name);
        int rc = run_example(EXAMPLES[k].name, EXAMPLES[k].duration, dir);
        CHECK(rc == 0);
        for (int j = 0; j < BD_TEST_RUN_FILE_COUNT; j++) {
            char path[1024];
            snprintf(path, sizeof path, "%s/%s", dir, bd_test_run_files[j]);
            uint64_t h = bd_test_hash_file(path);
            CHECK(h != 0);
            if (out) {
                fprintf(out, "%s %s %016llx\n", EXAMPLES[k].name, bd_test_run_files[j],
                        (unsigned long long)h);
                continue;
            }
            uint64_t want = stored_hash(EXAMPLES[k].name, bd_test_run_files[j]);
            bd_test_checks++;
            if (h != want) {
                bd_test_failures++;
                fprintf(stderr, "%s/%s: hash %016llx, stored %016llx (outputs in %s)\n",
                        EXAMPLES[k].name, bd_test_run_files[j], (unsigned long long)h,
                        (unsigned long long)want, dir);
            } else {
                remove(path);
            }
        }
        if (bd_test_failures == 0)
            remove(dir);
    }
    if (out)
        fclose(out);
    if (bd_test_failures == 0)
        remove(root);
    return bd_test_finish("test_golden");
}
