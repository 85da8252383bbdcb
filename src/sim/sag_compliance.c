/* The warning where a belt model leaves out the sag between idlers that
 * a start pulls out (docs/physics.md §14, "The default span mesh holds no
 * sag").
 *
 * A bay of spacing a under tension T, carrying w = m'·g·cos δ per metre,
 * hangs in the parabola h = w·a²/(8T) and is longer than its chord by
 * 8h²/(3a) = w²a³/(24T²). As the tension rises the sag is pulled out:
 * d/dT of it is −w²a³/(12T³), against the elastic a/EA. Their ratio
 *     ρ = EA·(w·a/T)²/(12·T)
 * is what the sag adds to the bay's axial compliance: Irvine's λ²/12
 * (Irvine & Caughey 1974, the suspended cable's parameter
 * λ² = (w·a/T)²·a/(T·a/EA)). Derived here.
 *
 * A belt model holds the part of it its elements resolve: n straight
 * chords across the bay hold 1 − 1/n² of the parabola's excess length
 * (two chords 2h²/a of its 8h²/(3a); derived here), so it misses ρ/n².
 * The axial belt has no transverse motion (it misses all of it); the
 * moving-node belt has n = ⌈a/span_element_length⌉ (by default 1: one
 * chord per bay); the discrete and rfe belts a/l0.
 *
 * Measured on the minimal loop of §10 (3 m return bays at 5000 N, ρ 0.52):
 * the moving-node belt's peak tension of a 3 s start to 6 m/s is 7477 N at
 * n = 1 (missing 0.52), 9890 N at n = 2 (0.13), 10127 N at n = 3 (0.058),
 * 10400 N at n = 12, the discrete belt's 10453 N at its finer mesh; the
 * axial belt 7473 N. Missing 0.1 of the compliance costs about 5 % of
 * that peak: warned from there. */
#include "sim/engine.h"

#include <math.h>
#include <stdlib.h>

#include "base/alloc.h"
#include "belt/lumped/lumped.h"

#define SAG_MISSING_WARN 0.10

/* chords per bay the formulation puts across a spacing a (0: none, the
 * belt has no transverse motion) */
static double chords_per_bay(const bd_sim *sim, double a)
{
    const bd_model_def *def = sim->model->def;
    switch (def->belt.formulation) {
    case BD_FORMULATION_AXIAL:
        return 0.0;
    case BD_FORMULATION_MOVING_NODE: {
        double el = def->belt.span_element_length;
        return el > 0.0 ? ceil(a / el - 1e-9) : 1.0;
    }
    default:
        return fmax(1.0, a / sim->model->l0);
    }
}

void bd_sag_compliance_warn(bd_sim *sim)
{
    const bd_model_def *def = sim->model->def;
    const int sets = def->idler_set_count;
    if (sets == 0)
        return;
    bd_span_rest *rest = bd_xcalloc((size_t)sets, sizeof *rest);
    bd_lumped_span_rest(def, &sim->model->path, rest);
    const char *belt = sim->model->belt->name;
    for (int k = 0; k < sets; k++) {
        const bd_span_rest *r = &rest[k];
        if (!(r->tension > 0.0) || !(r->mass_per_length > 0.0))
            continue;
        double wa = r->mass_per_length * def->gravity * r->cos_slope * r->spacing;
        double rho = sim->model->EA * (wa / r->tension) * (wa / r->tension) / (12.0 * r->tension);
        double n = chords_per_bay(sim, r->spacing);
        double missing = n > 0.0 ? rho / (n * n) : rho;
        if (missing < SAG_MISSING_WARN)
            continue;
        /* chords enough to miss less than the threshold */
        double need = ceil(sqrt(rho / SAG_MISSING_WARN));
        const char *span = def->pulleys[def->idler_sets[k].span].name;
        char held[160];
        if (n > 0.0)
            snprintf(held, sizeof held, "its %.0f element%s per bay hold%s %.0f %% of that",
                     n, n > 1.0 ? "s" : "", n > 1.0 ? "" : "s", 100.0 * (1.0 - 1.0 / (n * n)));
        else
            snprintf(held, sizeof held, "it has no transverse motion and holds none of that");
        bd_sim_warn(sim, "span '%s': the belt's sag between its idlers (%.3g m apart, %.4g N "
                    "at rest) adds %.0f %% to its axial compliance (Irvine's lambda^2/12), and "
                    "the %s belt misses %.0f %% of it: %s. Peak tensions of starts and stops "
                    "can then be off by several percent (docs/physics.md section 14: 7477 N "
                    "against 10400 N on a loop missing 52 %%). For the peaks use elements of "
                    "at most %.3g m there (%s)", span, r->spacing, r->tension, 100.0 * rho, belt,
                    100.0 * missing, held, r->spacing / need,
                    def->belt.formulation == BD_FORMULATION_AXIAL
                        ? "the discrete belt, or the moving-node belt's span_element_length"
                    : def->belt.formulation == BD_FORMULATION_MOVING_NODE
                        ? "span_element_length"
                        : "belt.element_length");
    }
    free(rest);
}
