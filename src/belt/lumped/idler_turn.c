/* How sharply the discrete belt (and the rfe belt, whose element centres
 * are its nodes) turns over its idlers, and the default element that
 * resolves it (docs/physics.md §2, §10, §15).
 *
 * Idler set k turns the belt by φ = m'g·a·cos δ/(T − m'v²) at each idler:
 * twice the slope m'g·a/(2T) at the ends of the sag parabola
 * h = m'g·a²/(8T) whose limit standards.c takes for DIN 22101's minimum
 * tension (T_min_sag), with the moving string's T − m'v² (Wickert & Mote
 * 1990, as in moving_node/forces.c); T and m' the span's at rest on its
 * supports (the `static` layout, whatever the start), a the set's
 * spacing, v the drives' speed; and v against the transverse wave speed
 * c = √(T/m'). At every idler the belt's running line cuts the corner of
 * its free lines as the nodes pass; on the quadratic line that cut swings
 * with the nodes' phase and the passage pumps the spans (§10), on the
 * quintic hardly (§5, idler_contact.c, which build.c chooses by φ).
 *
 * The default element: the chord of 30° of the smallest pulley (its wrap,
 * §4), halved where a set turns the belt by φ ≥ 0.05 rad (a sag of 0.6 %
 * of the spacing) and the belt has no bending stiffness. Measured on
 * generated conveyors (tests/torture --force-check): seeds 1100–1139, 35
 * of 40 within 3 % of their law at 30°, 39 of 40 at half of it; of 13
 * that failed at 30° (φ 0.04–0.25), 11 pass at half (1138 and 1213 at
 * φ 0.20 and 0.25 do not). Without the speed condition of the warning
 * (v ≥ 0.2·c): seed 1174 at v 0.18·c, φ 0.19 drew +9.0 % at 30° and
 * +2.3 % at half. Half costs about 4× (twice the nodes, half the step).
 *
 * The rfe belt's default is that half whatever its idlers: the chord of
 * 15° (belt/rfe/build.c says why: its rigid elements ride a pulley as a
 * chain rides a sprocket), shortened on fast belts for the running force
 * that polygon costs (polygon.c). */
#include "belt/lumped/lumped.h"

#include <math.h>
#include <stdlib.h>

#include "base/alloc.h"
#include "base/constants.h"
#include "belt/lumped/layout.h"
#include "parts/parts.h"

#define REFINE_TURN_RAD 0.05
/* the turns need the spans' tensions, not the belt's nodes: a belt given a
 * long element on tiny pulleys is not laid at their chord to find them
 * (13 MB at most; a 0.5 m element on a 0.5 µm bend pulley ran out of
 * memory in `check`) */
#define TURN_LAYOUT_MAX_NODES 1e5

/* the rfe belt's elements meet the idlers through the same node chain
 * (belt/rfe/rfe.h) and turn at them as sharply: generated seeds 8, 12 and
 * 16 (φ ≥ 0.05, default elements) drew +6.9, +10.5 and +13.3 % above
 * their law at the 30° element, +2.6, +4.1 and +1.8 % at half of it
 * (docs/physics.md §15) */
int bd_lumped_turns_refine(const bd_model_def *def)
{
    return def->belt.formulation == BD_FORMULATION_DISCRETE
        || def->belt.formulation == BD_FORMULATION_RFE;
}

int bd_lumped_smallest_pulley(const bd_model_def *def)
{
    int worst = 0;
    for (int i = 1; i < def->pulley_count; i++)
        if (def->pulleys[i].radius < def->pulleys[worst].radius)
            worst = i;
    return worst;
}

double bd_lumped_pulley_element(const bd_model_def *def)
{
    if (def->pulley_count <= 0)
        return INFINITY;
    return 2.0 * def->pulleys[bd_lumped_smallest_pulley(def)].radius * sin(BD_PI / 12.0);
}

/* idler set k's span on the laid belt: its mean tension, its mass per
 * metre (belt and load at rest), the cosine of its slope and the
 * spacing; 0 when it has no idlers */
static int set_rest(const bd_model_def *def, const bd_layout *lay, int k, bd_span_rest *out)
{
    const bd_path *path = &lay->path;
    const bd_path_segment *sp = bd_path_span(path, def->idler_sets[k].span);
    double a;
    if (sp->length <= 0.0 || bd_idler_count(def, path, k, &a) <= 0)
        return 0;
    double T = 0.0;
    int count = 0;
    for (int i = 0; i < lay->n; i++)
        if (lay->s[i] >= sp->s0 && lay->s[i] <= sp->s0 + sp->length) {
            T += lay->tension[i];
            count++;
        }
    if (count == 0)
        return 0;
    bd_rest_load load = bd_layout_rest_load(def, path);
    out->tension = T / count;
    out->mass_per_length = bd_rest_mass(path, &load, sp->s0, sp->s0 + sp->length) / sp->length;
    out->cos_slope = fabs(sp->dir[0]);
    out->spacing = a;
    return out->mass_per_length > 0.0;
}

int bd_lumped_span_rest(const bd_model_def *def, const bd_path *path, bd_span_rest *out)
{
    for (int k = 0; k < def->idler_set_count; k++)
        out[k] = (bd_span_rest){0};
    if (def->idler_set_count == 0)
        return 0;
    /* the tension at rest on the supports, whatever the start */
    bd_model_def laid = *def;
    laid.simulation.initial_state = BD_INITIAL_STATIC;
    bd_layout lay;
    char err[256];
    double l = fmax(bd_lumped_pulley_element(def), path->length / TURN_LAYOUT_MAX_NODES);
    bd_layout_request req = {path, l};
    if (bd_layout_belt(&laid, &req, &lay, err, sizeof err))
        return 0;
    int found = 0;
    for (int k = 0; k < def->idler_set_count; k++)
        found |= set_rest(def, &lay, k, &out[k]);
    bd_layout_free(&lay);
    return found;
}

int bd_lumped_idler_turns(const bd_model_def *def, const bd_path *path, double *phi,
                          double *voc)
{
    for (int k = 0; k < def->idler_set_count; k++)
        phi[k] = voc[k] = 0.0;
    if (def->idler_set_count == 0 || def->belt.bending_stiffness > 0.0)
        return 0;
    bd_span_rest *rest = bd_xcalloc((size_t)def->idler_set_count, sizeof *rest);
    bd_lumped_span_rest(def, path, rest);
    double v = bd_drives_reference_speed(def);
    int found = 0;
    for (int k = 0; k < def->idler_set_count; k++) {
        const bd_span_rest *r = &rest[k];
        double tc = r->tension - r->mass_per_length * v * v;
        if (r->mass_per_length <= 0.0 || tc <= 0.0)
            continue;
        phi[k] = r->mass_per_length * def->gravity * r->spacing * r->cos_slope / tc;
        voc[k] = v / sqrt(r->tension / r->mass_per_length);
        found = 1;
    }
    free(rest);
    return found;
}

double bd_lumped_default_element(const bd_model_def *def, const bd_path *path, const double *phi,
                                 int *refined)
{
    double l = bd_lumped_pulley_element(def);
    *refined = 0;
    if (def->belt.formulation == BD_FORMULATION_RFE) {
        double p = bd_lumped_polygon_element(def, path, 0.5 * l);
        if (p < 0.5 * l)
            *refined = 2;
        return p;
    }
    if (!bd_lumped_turns_refine(def))
        return l;
    for (int k = 0; k < def->idler_set_count; k++)
        if (phi[k] >= REFINE_TURN_RAD)
            *refined = 1;
    return *refined ? 0.5 * l : l;
}

double bd_lumped_default_element_on(const bd_model_def *def, const bd_path *path,
                                    int *refined)
{
    size_t sets = (size_t)(def->idler_set_count > 0 ? def->idler_set_count : 1);
    double *phi = bd_xcalloc(sets, sizeof *phi), *voc = bd_xcalloc(sets, sizeof *voc);
    if (bd_lumped_turns_refine(def))
        bd_lumped_idler_turns(def, path, phi, voc);
    double l = bd_lumped_default_element(def, path, phi, refined);
    free(phi);
    free(voc);
    return l;
}
