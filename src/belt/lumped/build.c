/* Building the lumped belt from a validated model: discretize the belt,
 * lay it at rest on its path, place the idlers, set up the pulleys' shell
 * contacts, probes and feed point. Everything allocated here; the step
 * loop allocates nothing. */
#include "belt/lumped/lumped.h"
#include "belt/lumped/layout.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "base/constants.h"
#include "laws/stable_step.h"

/* default target element length: chord of a 30° arc of the smallest pulley
 * (seed 001 §4.3.1, §6.1) */
/* the lumped state's arrays of doubles: [n] of the belt, [node_max] of a
 * shell contact (ints apart) */
static const size_t BELT_DOUBLES[] = {offsetof(bd_lumped, ux), offsetof(bd_lumped, uy),
                                      offsetof(bd_lumped, len), offsetof(bd_lumped, td),
                                      offsetof(bd_lumped, pw), offsetof(bd_lumped, ek)};
static const size_t WRAP_DOUBLES[] = {offsetof(bd_wrap_contact, c_fn0),
                                      offsetof(bd_wrap_contact, c_g),
                                      offsetof(bd_wrap_contact, c_arc),
                                      offsetof(bd_wrap_contact, run_arc),
                                      offsetof(bd_wrap_contact, c_tx),
                                      offsetof(bd_wrap_contact, c_ty),
                                      offsetof(bd_wrap_contact, c_nx),
                                      offsetof(bd_wrap_contact, c_ny),
                                      offsetof(bd_wrap_contact, c_f)};
#define COUNT(a) ((int)(sizeof a / sizeof a[0]))

/* the most elements wrap_elements.c can list in a step: each sector's
 * run and the element that enters it */
static int wrapped_max(const bd_sim *sim)
{
    int total = 0;
    for (int i = 0; i < sim->model->pulley_count; i++)
        total += bd_lumped_model_of(sim)->sectors[i].node_max + 1;
    return total;
}

static void setup_pulleys(bd_sim *sim, const bd_layout *lay)
{
    const bd_model_def *def = sim->model->def;
    bd_lumped *L = bd_lumped_of(sim);
    bd_lumped_model *LM = sim->own->belt_model;
    LM->sectors = bd_xcalloc((size_t)def->pulley_count, sizeof *LM->sectors);
    L->wraps = bd_xcalloc((size_t)def->pulley_count, sizeof *L->wraps);
    for (int i = 0; i < def->pulley_count; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        bd_wrap_contact *W = &L->wraps[i];
        if (i == lay->takeup) {
            /* the takeup pulley as laid: where the belt's loop closes */
            bd_pulley_model *pm = &sim->own->pulleys[i];
            p->cx += lay->takeup_shift * pm->axis[0];
            p->cy += lay->takeup_shift * pm->axis[1];
            pm->x0 = p->cx;
            pm->y0 = p->cy;
        }
        /* contact: stiff and linearly implicit, every node of the wrap's
         * sector tested every step (pulley_contact.c) */
        bd_wrap_sector *S = &LM->sectors[i];
        bd_lumped_sector_init(sim, i, S);
        bd_doubles_alloc(W, WRAP_DOUBLES, COUNT(WRAP_DOUBLES), (size_t)S->node_max);
        W->c_node = bd_xcalloc((size_t)S->node_max, sizeof *W->c_node);
        W->c_state = bd_xcalloc((size_t)S->node_max, sizeof *W->c_state);
        W->c_press = bd_xcalloc((size_t)S->node_max, sizeof *W->c_press);
    }
    L->wrapped = bd_xcalloc((size_t)wrapped_max(sim), sizeof *L->wrapped);
    L->wrap_mark = bd_xcalloc((size_t)sim->model->n, sizeof *L->wrap_mark);
}

/* the discrete and rfe belts' idlers press on the quintic running line
 * where their bay holds this many elements and the belt turns over them by at
 * least BD_QUINTIC_TURN, on the quadratic line elsewhere
 * (idler_contact.c).
 * - The bay (the quintic's six nodes take five elements of it; measured,
 *   no theory yet): on 7 elements to a bay (tests/data/mesh_loaded_76m's
 *   carry idlers at the default element) the quintic left the belt
 *   between two idlers ringing at 18.5 Hz after its start, a mode of that
 *   mesh alone: test_scurve_peak's raw peak drive force rose from 5494 to
 *   5976 N, against 5570 N at half the element. On the minimal loop of
 *   docs/physics.md §10 at 8.6 to a return bay it drew +19.6 % against
 *   +13.9 % on the quadratic line. On 9.9, the carry of generated seed
 *   7001 (--curves; 0.104 rad at 0.22·c), +0.3 % against +4.5 %; on 19
 *   and more, the loops of §10, it is what holds their running force to
 *   the law.
 * - The turn: what a passing idler radiates grows as φ². With the
 *   pulleys' friction on the tangent lines (pulley_contact.c), 106 of
 *   generated conveyors 7700-8199 run with every idler on the quadratic
 *   line drew at most +0.14 % over their law where their sets turn the
 *   belt by 0.020-0.025 rad (21 conveyors), and the worst at 0.025-0.030 rad,
 *   7731 at 0.027, +3.94 %; scaled as φ² that reaches the 3 % at
 *   0.0236 rad, so the quintic starts at 0.0225 rad (7731 would draw
 *   +2.7 % there). Below it the quadratic line's three nodes cost less
 *   than the quintic's six: bench_long_conveyor, whose return turns the
 *   belt by 0.022 rad, stepped 10-12 % slower with its return on the
 *   quintic. (Before that pulley change, 4135 and 4170 at 0.027 and
 *   0.032 rad drew +3.55 and +3.12 % on the quadratic line, partly the
 *   pulleys' drag: +1.9 and +0.2 % now.) */
#define BD_QUINTIC_BAY_ELEMENTS 9.0
#define BD_QUINTIC_TURN 0.0225

/* how the discrete or rfe belt turns over the idler of set k at s on span sp,
 * rad: the set's sag at rest (idler_turn.c, none with bending stiffness,
 * whose belt rounds the corner itself) and the path's own turn over the
 * idler's bay (a vertical curve; convex, toward the roll, counts
 * positive); 0 for other belts */
static double idler_turn_at(const bd_sim *sim, int k, const bd_path_segment *sp, double s)
{
    if (!bd_lumped_model_of(sim)->quintic_allowed || sim->model->EI > 0.0)
        return 0.0;
    const bd_path *path = &sim->model->path;
    double half = 0.5 * sim->model->idler_spacing[k];
    double s1 = fmax(s - half, sp->s0), s2 = fmin(s + half, sp->s0 + sp->length);
    double p[2], t1[2], t2[2], t[2], up[2];
    bd_path_point(path, s1, p, t1);
    bd_path_point(path, s2, p, t2);
    bd_path_point(path, s, p, t);
    bd_path_up_normal(t, up);
    double turn = -((t2[0] - t1[0]) * up[0] + (t2[1] - t1[1]) * up[1]);
    if (sim->model->idler_turn)
        turn += sim->model->idler_turn[k];
    return turn > 0.0 ? turn : 0.0;
}

static void setup_idlers(bd_sim *sim)
{
    const bd_model_def *def = sim->model->def;
    int total = 0;
    sim->own->idlers_per_set =
        bd_xcalloc((size_t)def->idler_set_count, sizeof *sim->own->idlers_per_set);
    sim->own->idler_spacing =
        bd_xcalloc((size_t)def->idler_set_count, sizeof *sim->own->idler_spacing);
    for (int k = 0; k < def->idler_set_count; k++)
        total += bd_idler_set_layout(sim, k, &sim->own->idler_spacing[k]);
    sim->own->idler_count = total;
    sim->own->idlers = bd_xcalloc((size_t)total, sizeof *sim->own->idlers);
    sim->idlers = bd_xcalloc((size_t)total, sizeof *sim->idlers);
    bd_lumped_of(sim)->touch = bd_xcalloc((size_t)total, sizeof *bd_lumped_of(sim)->touch);
    int at = 0;
    for (int k = 0; k < def->idler_set_count; k++) {
        const bd_idler_set_def *set = &def->idler_sets[k];
        const bd_path_segment *sp = bd_path_span(&sim->model->path, set->span);
        for (int j = 0; j < sim->model->idlers_per_set[k]; j++) {
            bd_idler_model *im = &sim->own->idlers[at];
            bd_idler *id = &sim->idlers[at++];
            id->m = im;
            double s = sp->s0 + (j + 1) * sim->model->idler_spacing[k];
            /* the lower side of the belt there (a vertical curve turns it):
             * the normal pointing down */
            double pt[2], t[2];
            bd_path_point(&sim->model->path, s, pt, t);
            double up[2];
            bd_path_up_normal(t, up);
            double nx = -up[0], ny = -up[1];
            bd_tracker_init(sim, &id->tr, s);
            /* touch the belt as laid (not the ideal path): no initial kick */
            int e = id->tr.element, e1 = e + 1 == sim->model->n ? 0 : e + 1;
            double g = id->tr.gamma;
            id->tr.p[0] = sim->x[e] + g * (sim->x[e1] - sim->x[e]);
            id->tr.p[1] = sim->y[e] + g * (sim->y[e1] - sim->y[e]);
            im->s = s;
            im->radius = set->radius;
            /* the running line it presses on, and where: the corner that
             * line cuts over it taken off its radius (idler_contact.c) */
            double turn = idler_turn_at(sim, k, sp, s);
            im->line_quintic = turn >= BD_QUINTIC_TURN
                               && sim->model->idler_spacing[k]
                                      >= BD_QUINTIC_BAY_ELEMENTS * sim->model->l0;
            im->contact_radius =
                set->radius - bd_lumped_line_corner(turn, sim->model->l0, im->line_quintic);
            im->centre[0] = id->tr.p[0] + nx * set->radius;
            im->centre[1] = id->tr.p[1] + ny * set->radius;
            im->inertia = set->inertia > 0.0 ? set->inertia : 1e-6;
            im->inv_inertia = 1.0 / im->inertia;
            im->r2_per_inertia = set->radius * set->radius / im->inertia;
            im->mu_s = set->friction.mu_static;
            im->mu_d = set->friction.mu_dynamic;
            im->rolling = set->rolling_resistance;
            /* stiff, linearly implicit contact (idler_contact.c) */
            im->k_contact = bd_lumped_model_of(sim)->k_contact;
            im->half_per_k = 0.5 / im->k_contact;
            im->set = k;
        }
    }
}

/* place nodes on the laid path: the layout spaced them by the belt's
 * length along it, round the wraps too, which is the length the elements
 * have there (wrap_elements.c) */
static void place_nodes(bd_sim *sim, const bd_layout *lay)
{
    for (int i = 0; i < sim->model->n; i++) {
        double p[2], t[2];
        bd_path_point(&sim->model->path, lay->s[i], p, t);
        sim->x[i] = p[0];
        sim->y[i] = p[1];
        sim->own->s_node0[i] = lay->s[i];
        bd_lumped_of(sim)->seg_hint[i] = bd_path_segment_at(&sim->model->path, lay->s[i]);
        sim->mass[i] = sim->model->belt_mpl * sim->model->l0;
    }
}

/* initial material: nodes from the feed point to the discharge pulley */
static void load_material(bd_sim *sim)
{
    const bd_material_def *mat = &sim->model->def->material;
    if (!mat->present || !mat->initially_loaded)
        return;
    double s_feed, len;
    bd_path_loaded_region(&sim->model->path, mat, &s_feed, &len);
    for (int i = 0; i < sim->model->n; i++) {
        if (bd_path_in_region(&sim->model->path, sim->model->s_node0[i], s_feed, len)) {
            sim->material[i] = mat->mass_per_length * sim->model->l0;
            sim->mass[i] += sim->material[i];
        }
    }
}

int bd_lumped_build(bd_sim *sim, bd_diag *diag)
{
    return bd_lumped_build_sized(sim, diag, sizeof(bd_lumped), sizeof(bd_lumped_model));
}

int bd_lumped_build_sized(bd_sim *sim, bd_diag *diag, size_t state_size, size_t model_size)
{
    const bd_model_def *def = sim->model->def;
    bd_path given;
    if (bd_path_build(def, &given, diag))
        return 1;
    bd_lumped *L = bd_xcalloc(1, state_size);
    sim->belt_data = L;
    /* the idlers' turn of the discrete or rfe belt at rest: the default
     * element (idler_turn.c), `check` and the warning (sim/idler_turn.c) */
    if (bd_lumped_turns_refine(def) && def->idler_set_count > 0) {
        size_t sets = (size_t)def->idler_set_count;
        sim->own->idler_turn = bd_xcalloc(sets, sizeof *sim->own->idler_turn);
        sim->own->idler_turn_speed = bd_xcalloc(sets, sizeof *sim->own->idler_turn_speed);
        bd_lumped_idler_turns(def, &given, sim->own->idler_turn, sim->own->idler_turn_speed);
    }
    double target = def->belt.element_length > 0.0
                        ? def->belt.element_length
                        : bd_lumped_default_element(def, &given, sim->own->idler_turn,
                                                    &sim->own->element_refined);
    bd_layout lay;
    char err[512];
    bd_layout_request req = {&given, target};
    if (bd_layout_belt(def, &req, &lay, err, sizeof err)) {
        bd_diag_error(diag, def->source, def->belt.mark, "%s", err);
        bd_path_free(&given);
        return 1;
    }
    bd_path_free(&given);
    sim->own->path = lay.path;
    memset(&lay.path, 0, sizeof lay.path);   /* the simulation owns it now */
    sim->own->n = lay.n;
    sim->own->l0 = lay.l0;
    bd_lumped_model *LM = bd_xcalloc(1, model_size);
    sim->own->belt_model = LM;
    LM->k_axial = sim->model->EA / sim->model->l0;
    double m_el = sim->model->belt_mpl * sim->model->l0;
    /* seed 001 eq 4.3: c = 2·m·ζ·√(k/m) with m the element mass */
    LM->c_axial = 2.0 * def->belt.damping_ratio * sqrt(LM->k_axial * m_el);
    /* seed 001 eq 4.11: k_θ = EI/l */
    LM->k_bend = sim->model->EI / sim->model->l0;
    /* contacts: stiff and linearly implicit (pulley_contact.c, idler_contact.c) */
    LM->k_contact = 100.0 * LM->k_axial;
    /* the discrete and rfe belts' idlers press on the quintic running line
     * where it pays, and at their contact radius (setup_idlers,
     * idler_contact.c; the rfe belt's centres are its nodes) */
    LM->quintic_allowed = bd_lumped_turns_refine(def);
    /* the arc an element spans on the smallest pulley: the element takes
     * the belt's length round the shell (wrap_elements.c), so there is no
     * chordal action (docs/physics.md §4: 0.06 % of the tension at the
     * default 30°, against 2.1 % as chords), but the wrap's pressure and
     * friction sit on its nodes, and the geodesic follows a pulley for less
     * than half a turn per element */
    int worst = bd_lumped_smallest_pulley(def);
    double R = def->pulleys[worst].radius, span = sim->model->l0 / R;
    if (span >= BD_PI) {
        bd_diag_error(diag, def->source, def->belt.mark,
                      "belt.element_length: an element of %.3g m is longer than half the "
                      "circumference of pulley '%s' (radius %.3g m) and cannot follow it; "
                      "use less than %.3g m (the default is %.3g m, 30° of it)",
                      sim->model->l0, def->pulleys[worst].name, R, BD_PI * R,
                      bd_lumped_pulley_element(def));
        bd_layout_free(&lay);
        return 1;
    }
    if (span > BD_WRAP_WARN_DEG * BD_DEG)
        bd_sim_warn(sim, "a belt element spans %.0f° of pulley '%s' (element length %.3g m, "
                    "radius %.3g m): the wrap's pressure and friction are carried by few "
                    "nodes; belt.element_length %.3g m gives 30°",
                    span / BD_DEG, def->pulleys[worst].name, sim->model->l0, R,
                    bd_lumped_pulley_element(def));

    bd_node_arrays_alloc(sim);
    size_t n = (size_t)sim->model->n;
    bd_doubles_alloc(L, BELT_DOUBLES, COUNT(BELT_DOUBLES), n);
    L->seg_hint = bd_xcalloc(n, sizeof *L->seg_hint);
    sim->own->s_node0 = bd_xcalloc(n, sizeof *sim->own->s_node0);
    for (int i = 0; i < sim->model->n; i++)
        sim->own->s_node0[i] = lay.s[i];
    setup_pulleys(sim, &lay);
    place_nodes(sim, &lay);
    for (int i = 0; i < sim->model->pulley_count; i++)
        bd_lumped_sector_anchor(sim, i, &bd_lumped_of(sim)->wraps[i]);
    for (int i = 0; i < sim->model->n; i++)
        sim->tension[i] = lay.tension[i];
    bd_layout_free(&lay);
    load_material(sim);
    setup_idlers(sim);
    bd_setup_probes_and_feed(sim);
    return 0;
}

void bd_lumped_free(bd_sim *sim)
{
    bd_lumped *L = bd_lumped_of(sim);
    if (!L)
        return;
    bd_doubles_free(L, BELT_DOUBLES, COUNT(BELT_DOUBLES));
    free(L->seg_hint);
    for (int i = 0; L->wraps && i < sim->model->pulley_count; i++) {
        bd_wrap_contact *W = &L->wraps[i];
        bd_doubles_free(W, WRAP_DOUBLES, COUNT(WRAP_DOUBLES));
        free(W->c_node);
        free(W->c_state);
        free(W->c_press);
    }
    free(L->wraps);
    free(L->wrapped);
    free(L->wrap_mark);
    free(L->touch);
    free(L);
    sim->belt_data = NULL;
}

void bd_lumped_free_model(bd_model *model)
{
    bd_lumped_model *LM = model->belt_model;
    if (LM)
        free(LM->sectors);
    free(model->belt_model);
    model->belt_model = NULL;
}

/* dst's state as a copy of src's, for a new run on the same model; every
 * pointer is dst's own from the moment it is set, so that a jump out of
 * memory half way leaves nothing shared to free */
void bd_lumped_clone(bd_sim *dst, const bd_sim *src)
{
    bd_lumped_clone_sized(dst, src, sizeof(bd_lumped));
}

void bd_lumped_clone_sized(bd_sim *dst, const bd_sim *src, size_t state_size)
{
    const bd_lumped *S = bd_lumped_of(src);
    size_t n = (size_t)src->model->n;
    bd_lumped *L = bd_xcalloc(1, state_size);
    dst->belt_data = L;
    bd_doubles_dup(L, S, BELT_DOUBLES, COUNT(BELT_DOUBLES), n);
    L->seg_hint = bd_xdup(S->seg_hint, n, sizeof *L->seg_hint);
    size_t np = (size_t)src->model->pulley_count;
    L->wraps = bd_xcalloc(np, sizeof *L->wraps);
    for (size_t i = 0; i < np; i++) {
        const bd_wrap_contact *from = &S->wraps[i];
        bd_wrap_contact *W = &L->wraps[i];
        size_t w = (size_t)bd_lumped_model_of(src)->sectors[i].node_max;
        /* the scalars by copy, the arrays not the source's until each is
         * copied */
        *W = *from;
        W->c_node = NULL;
        W->c_state = NULL;
        W->c_press = NULL;
        bd_doubles_dup(W, from, WRAP_DOUBLES, COUNT(WRAP_DOUBLES), w);
        W->c_node = bd_xdup(from->c_node, w, sizeof *W->c_node);
        W->c_state = bd_xdup(from->c_state, w, sizeof *W->c_state);
        W->c_press = bd_xdup(from->c_press, w, sizeof *W->c_press);
    }
    L->wrapped = bd_xdup(S->wrapped, (size_t)wrapped_max(src), sizeof *L->wrapped);
    L->wrap_mark = bd_xdup(S->wrap_mark, n, sizeof *L->wrap_mark);
    L->touch = bd_xdup(S->touch, (size_t)src->model->idler_count, sizeof *L->touch);
}

/* Stable time step (laws/stable_step.h). The highest frequency of the belt is that of a node between two elements
 * moving against its neighbours: for the axial springs ω² = 4k/m (k = EA/l0,
 * m = node mass), for the bending springs (k_θ = EI/l0, lever l0, a node and
 * its two neighbours) ω² = 16·k_θ/(m·l0²). Their sum bounds the largest
 * eigenvalue (Gershgorin); contacts are linearly implicit and add no limit
 * (pulley_contact.c, idler_contact.c). The Kelvin–Voigt dashpot of ratio ζ_e
 * (eq 4.3, per element) damps that mode with ζ = 2ζ_e. m is the lightest
 * node's (no material): m′·l0. */
static double stable_step_law(double m, double l0, double k_axial, double k_bend,
                              double c_axial, bd_time_step_limit *limit)
{
    double w_axial = 4.0 * k_axial;
    double w_bend = 16.0 * k_bend / (l0 * l0);
    double omega = sqrt((w_axial + w_bend) / m);
    double zeta = 4.0 * c_axial / (2.0 * m * omega);
    /* what limits it: the largest contribution to ω² */
    *limit = w_bend > w_axial ? BD_LIMIT_BENDING : BD_LIMIT_AXIAL;
    return bd_central_difference_limit(omega, zeta);
}

double bd_lumped_stable_step(const bd_sim *sim, bd_time_step_limit *limit)
{
    const bd_lumped_model *L = bd_lumped_model_of(sim);
    return stable_step_law(sim->model->belt_mpl * sim->model->l0, sim->model->l0, L->k_axial,
                           L->k_bend, L->c_axial, limit);
}

/* bytes per node at the build's peak: the node arrays, the lumped arrays,
 * seg_hint and s_node0, with the layout's s and tension still held (the
 * layout's weight grid, 8 doubles a node, is freed before) */
static double node_bytes(void)
{
    return (double)(bd_node_arrays_bytes() + (size_t)COUNT(BELT_DOUBLES) * sizeof(double)
                    + sizeof(int) + 3 * sizeof(double));
}

/* (node + idler)-steps per second: bench/bench_long_conveyor (8006 nodes,
 * 1164 idlers) runs 9.1e7 node-steps per second on the two-core machine
 * this was written on; a faster machine is done sooner */
#define LUMPED_RATE 1.0e8

/* what bd_lumped_build would make, from the definition and the path: n
 * from the loop length (its stretch neglected), the idlers each set would
 * get, and the step of elements that long (the build's own law) */
void bd_lumped_estimate(const bd_model_def *def, const bd_path *path, bd_belt_estimate *out)
{
    double l = def->belt.element_length;
    int refined;
    if (!(l > 0.0))
        l = bd_lumped_default_element_on(def, path, &refined);
    out->element_length = l;
    out->nodes = fmax(8.0, floor(path->length / l + 0.5));
    out->idlers = 0.0;
    for (int k = 0; k < def->idler_set_count; k++) {
        double spacing;
        out->idlers += bd_idler_count(def, path, k, &spacing);
    }
    out->node_bytes = node_bytes();
    out->idler_bytes = (double)(sizeof(bd_idler_model) + sizeof(bd_idler));
    double k = def->belt.axial_stiffness / l, m = def->belt.mass_per_length * l;
    bd_time_step_limit limit;
    out->stable_step = stable_step_law(m, l, k, def->belt.bending_stiffness / l,
                                       2.0 * def->belt.damping_ratio * sqrt(k * m), &limit);
    out->rate = LUMPED_RATE;
}

/* the idlers' inertia reflected to a pulley of radius R */
double bd_lumped_support_inertia(const bd_sim *sim, double R, double J)
{
    for (int k = 0; k < sim->model->idler_count; k++) {
        double r = sim->idlers[k].m->radius;
        J += sim->idlers[k].m->inertia * (R / r) * (R / r);
    }
    return J;
}
