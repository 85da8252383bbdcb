/* The static_*.yaml models through the loader: the same numbers as the hand
 * calculations of test_standards.c (which builds the models by hand), so the
 * files and the worked examples cannot drift apart. */
#include "beltdyn/standards.h"
#include "testlib.h"

#include <stdlib.h>
#include <string.h>

#define TOL 0.005

typedef struct expect {
    const char *file;
    double Te, T1, T2, T2_min_slip, T_min_sag;
    const char *warning; /* NULL: no warning at all */
} expect;

static const expect CASES[] = {
    /* A, horizontal (worked in test_standards.c) */
    {"static_horizontal.yaml", 4139.1451, 16556.8785, 12417.7334, 2642.571, 11772.0, NULL},
    {"static_horizontal_cema.yaml", 3018.7447, 15654.0247, 12635.28, 1927.270, 11772.0, NULL},
    {"static_slip.yaml", 4139.1451, 16556.8785, 12417.7334, 24335.3, 11772.0, "drive slips"},
    {"static_sag.yaml", 4139.1451, 12142.3785, 8003.2334, 2642.571, 11772.0, "sag:"},
    /* B, inclined */
    {"static_incline.yaml", 18541.7275, 35888.749, 17347.021, 11837.671, 11772.0, NULL},
    {"static_incline_cema.yaml", 17101.2749, 35222.131, 18120.856, 10918.0, 11772.0, NULL},
    /* C, declined and regenerative */
    {"static_decline.yaml", -22074.690, 42074.690, 20000.0, 14093.235, 17658.0, "regenerative"},
    {"static_decline_cema.yaml", -24226.703, 44226.703, 20000.0, 15467.153, 17658.0,
     "regenerative"},
};

static void run(const expect *e)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", BD_TEST_DATA_DIR, e->file);
    bd_model_def m;
    bd_diag d;
    bd_diag_init(&d);
    int rc = bd_model_load(path, &m, &d);
    CHECK(rc == 0);
    if (rc != 0) {
        for (int i = 0; i < d.count; i++)
            fprintf(stderr, "%s\n", d.lines[i]);
        bd_diag_free(&d);
        return;
    }
    bd_static_result r;
    rc = bd_static_compute(&m, &r, &d);
    CHECK(rc == 0);
    if (rc == 0) {
        fprintf(stderr, "%s\n", e->file);
        CHECK_REL(r.effective_tension_N, e->Te, TOL);
        CHECK_REL(r.T1_N, e->T1, TOL);
        CHECK_REL(r.T2_N, e->T2, TOL);
        CHECK_REL(r.T2_min_slip_N, e->T2_min_slip, TOL);
        CHECK_REL(r.T_min_sag_N, e->T_min_sag, TOL);
        if (e->warning) {
            int found = 0;
            for (int i = 0; i < r.warning_count; i++)
                found |= strstr(r.warnings[i], e->warning) != NULL;
            CHECK(found);
        } else {
            CHECK(r.warning_count == 0);
        }
        bd_static_free(&r);
    }
    bd_model_def_free(&m);
    bd_diag_free(&d);
}

int main(void)
{
    for (size_t i = 0; i < sizeof CASES / sizeof CASES[0]; i++)
        run(&CASES[i]);
    return bd_test_finish("test_standards_files");
}
