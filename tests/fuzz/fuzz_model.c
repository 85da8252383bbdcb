/* libFuzzer target (issue 10, "a fuzzed loader"): the input bytes are a
 * model file. They go through the public loader (bd_model_load_string) and,
 * when the model is valid, through what `beltdyn check` does (bd_sim_create,
 * bd_sim_describe) and what `beltdyn static` does (bd_static_compute, the
 * table and the JSON), without running the transient. The same bytes go
 * through the boom's loader (bd_boom_load_string, issue 13) and, when they
 * are a valid boom, through its `check` (bd_boom_create,
 * bd_boom_describe). Everything is freed: LeakSanitizer reports anything
 * left.
 *
 * Built by -DBD_FUZZ=ON with clang (tests/fuzz/CMakeLists.txt); run by
 * scripts/fuzz (README.md, Fuzzing). */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "beltdyn/boom.h"
#include "beltdyn/model.h"
#include "beltdyn/sim.h"
#include "beltdyn/standards.h"

/* the most belt nodes or idlers a model may ask for here: about 1 s under
 * the sanitizers (the lumped layout of a 5 km loop of 2e4 nodes; 1.6e5 took
 * 12 s, a timeout). Larger models are valid but too slow to fuzz (and a
 * machine-size limit is the library's to refuse, issue 10 #8) */
#define FUZZ_MAX_POINTS 2e4
#define FUZZ_PI 3.14159265358979323846

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* an upper bound of the belt's path: every centre-to-centre distance (a
 * tangent is never longer) plus every pulley's full circumference */
static double path_bound(const bd_model_def *m)
{
    double L = 0.0;
    for (int i = 0; i < m->pulley_count; i++) {
        const bd_pulley_def *a = &m->pulleys[i];
        const bd_pulley_def *b = &m->pulleys[(i + 1) % m->pulley_count];
        L += hypot(b->x - a->x, b->y - a->y) + 2.0 * FUZZ_PI * a->radius;
    }
    return L;
}

/* would the simulation ask for more than FUZZ_MAX_POINTS nodes or idlers?
 * The default element length is the formulations' (seed 001 §4.3.1: the
 * chord of 30° of the smallest pulley; axial: 1 m). */
static int too_big(const bd_model_def *m)
{
    double L = path_bound(m);
    if (!isfinite(L))
        return 1;
    double el = m->belt.element_length;
    if (el <= 0.0) {
        double r = INFINITY;
        for (int i = 0; i < m->pulley_count; i++)
            r = fmin(r, m->pulleys[i].radius);
        el = m->belt.formulation == BD_FORMULATION_AXIAL ? 1.0 : 2.0 * r * sin(FUZZ_PI / 12.0);
    }
    if (!(L / el <= FUZZ_MAX_POINTS))
        return 1;
    /* the moving-node belt's own elements: spans by span_element_length
     * (else the idler spacing, else 1 m) and the wraps by their angle */
    if (m->belt.formulation == BD_FORMULATION_MOVING_NODE) {
        double span = m->belt.span_element_length > 0.0 ? m->belt.span_element_length : 1.0;
        for (int k = 0; k < m->idler_set_count; k++)
            span = fmin(span, m->idler_sets[k].spacing);
        double arcs = m->pulley_count * (2.0 * FUZZ_PI / m->belt.wrap_element_angle + 1.0);
        if (!(L / span + arcs <= FUZZ_MAX_POINTS))
            return 1;
    }
    for (int k = 0; k < m->idler_set_count; k++)
        if (!(L / m->idler_sets[k].spacing <= FUZZ_MAX_POINTS))
            return 1;
    return 0;
}

static FILE *sink(void)
{
    static FILE *f;
    if (!f)
        f = fopen("/dev/null", "w");
    if (!f)
        abort();
    return f;
}

/* beltdyn check: build the simulation and describe it */
static void check(const bd_model_def *def)
{
    bd_diag diag;
    bd_diag_init(&diag);
    bd_sim *sim = NULL;
    if (bd_sim_create(def, &sim, &diag) == 0) {
        bd_sim_describe(sim, sink());
        bd_sim_free(sim);
    }
    bd_diag_free(&diag);
}

/* beltdyn static: the design standard's tensions, as a table and as JSON */
static void static_design(const bd_model_def *def)
{
    bd_diag diag;
    bd_diag_init(&diag);
    bd_static_result res;
    if (bd_static_compute(def, &res, &diag) == 0) {
        bd_static_print_table(&res, def, sink());
        free(bd_static_to_json(&res, def));
        bd_static_free(&res);
    }
    bd_diag_free(&diag);
}

/* a boom model: `beltdyn check` on it (its size is bounded by the loader:
 * at most BD_BOOM_MAX_SECTIONS sections of at most 2 x 200 elements) */
static void boom(const uint8_t *data, size_t size)
{
    bd_boom_def def;
    bd_diag diag;
    bd_diag_init(&diag);
    if (bd_boom_load_string((const char *)data, size, "fuzz.yaml", &def, &diag) == 0) {
        bd_boom *b = NULL;
        if (bd_boom_create(&def, &b, &diag) == 0) {
            bd_boom_describe(b, sink());
            bd_boom_free(b);
        }
        bd_boom_def_free(&def);
    }
    bd_diag_free(&diag);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    boom(data, size);
    bd_model_def def;
    bd_diag diag;
    bd_diag_init(&diag);
    int bad = bd_model_load_string((const char *)data, size, "fuzz.yaml", &def, &diag);
    bd_diag_free(&diag);
    if (!bad && !too_big(&def)) {
        check(&def);
        static_design(&def);
    }
    bd_model_def_free(&def);
    return 0;
}
