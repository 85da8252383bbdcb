/* The axial (1D) belt: building it from the model (model-format.md
 * `formulation: axial`; docs/physics.md §11).
 *
 * Nodes are stations fixed on the initial path; each carries the belt's
 * displacement u along the path. One node sits at the middle of every
 * pulley's wrap and stands for the belt on that wrap (seed 004: the wrap has
 * no compliance, its two ends move together); between two pulley nodes the
 * path is cut into equal elements of about `element_length`, independent of
 * the pulley radii. Node masses are the belt (and material) on half of each
 * adjacent element plus the idlers' rotating mass I/r² spread along their
 * span; gravity acts along the path; idler rolling resistance is spread
 * along the span in proportion to the belt's weight on it.
 *
 * The belt starts at its at-rest tension T(s) = T_c + W(s), W the weight of
 * belt and material integrated along the path from the drive pulley, T_c
 * from the takeup's force balance or the installed tension (as layout.c
 * does for the discrete belt). Each element's unstretched length is set so
 * that it carries exactly that tension, which makes the start an exact
 * equilibrium of the discrete equations. */
#include "belt/axial/axial.h"

#include "base/alloc.h"
#include "laws/stable_step.h"
#include "model/rest_weight.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* samples per element of the weight integral */
#define WEIGHT_SAMPLES 8

static double loaded_length(const bd_sim *sim, int full, double a, double b)
{
    return bd_fronts_loaded_length(sim, &bd_axial_of(sim)->fronts, full, a, b);
}

/* node path coordinates: pulley nodes at mid-wrap; between two of them
 * (half a wrap, a span, half a wrap) equal elements of about the target
 * length, unless that would put a node inside a wrap: then nodes at the
 * two tangent points and equal elements along the span. Either way the
 * belt on a wrap belongs to the two elements of its pulley node. */
static int piece_stations(const bd_path *path, int j, double target, double *s)
{
    const int np = path->pulley_count;
    const bd_path_segment *arc = bd_path_arc(path, j);
    const bd_path_segment *next = bd_path_arc(path, (j + 1) % np);
    double a1 = 0.5 * arc->length, a2 = 0.5 * next->length;
    double span = bd_path_span(path, j)->length, len = a1 + span + a2;
    /* the arc of pulley 0 ends the loop: its middle is at −arc/2 */
    double start = j == 0 ? -a1 : arc->s0 + a1;
    int n = (int)lround(len / target);
    if (n < 1)
        n = 1;
    if (len / n >= (a1 > a2 ? a1 : a2) * (1.0 - 1e-12)) {
        for (int k = 0; k < n; k++)
            if (s)
                s[k] = start + k * len / n;
        return n;
    }
    int m = (int)lround(span / target);
    if (m < 1)
        m = 1;
    if (s) {
        s[0] = start;
        for (int k = 0; k <= m; k++)
            s[k + 1] = start + a1 + k * span / m;
    }
    return m + 2;
}

static int place_stations(bd_sim *sim, double target, int **pulley_node_out)
{
    const bd_path *path = &sim->model->path;
    const int np = path->pulley_count;
    double L = path->length;
    int n = 0;
    for (int j = 0; j < np; j++)
        n += piece_stations(path, j, target, NULL);
    double *s = bd_xcalloc((size_t)n, sizeof *s);
    int *pnode = bd_xcalloc((size_t)np, sizeof *pnode);
    int at = 0;
    for (int j = 0; j < np; j++) {
        pnode[j] = at;
        at += piece_stations(path, j, target, s + at);
    }
    /* rotate so that node 0 is the first at s ≥ 0: s rises along the nodes */
    int r = 0;
    while (r < n && s[r] < 0.0)
        r++;
    r %= n;
    sim->own->n = n;
    sim->own->s_node0 = bd_xcalloc((size_t)n, sizeof *sim->own->s_node0);
    for (int i = 0; i < n; i++) {
        double si = s[(i + r) % n];
        sim->own->s_node0[i] = si < 0.0 ? si + L : si;
    }
    for (int j = 0; j < np; j++)
        pnode[j] = (pnode[j] - r + n) % n;
    free(s);
    *pulley_node_out = pnode;
    return n;
}

/* the axial state's and compiled model's arrays of doubles [n] */
static const size_t STATE_DOUBLES[] = {offsetof(bd_axial, u),       offsetof(bd_axial, gap),
                                       offsetof(bd_axial, gap_rate), offsetof(bd_axial, td),
                                       offsetof(bd_axial, f_const), offsetof(bd_axial, resist),
                                       offsetof(bd_axial, normal)};
static const size_t MODEL_DOUBLES[] = {offsetof(bd_axial_model, k), offsetof(bd_axial_model, c),
                                       offsetof(bd_axial_model, l0),
                                       offsetof(bd_axial_model, s_len)};
#define COUNT(a) ((int)(sizeof a / sizeof a[0]))

static void alloc_arrays(bd_sim *sim)
{
    size_t n = (size_t)sim->model->n;
    bd_node_arrays_alloc(sim);
    bd_axial *ax = bd_axial_of(sim);
    bd_axial_model *am = bd_axial_model_build(sim);
    ax->pulleys = bd_xcalloc((size_t)sim->model->pulley_count, sizeof *ax->pulleys);
    am->pulleys = bd_xcalloc((size_t)sim->model->pulley_count, sizeof *am->pulleys);
    bd_doubles_alloc(ax, STATE_DOUBLES, COUNT(STATE_DOUBLES), n);
    bd_doubles_alloc(am, MODEL_DOUBLES, COUNT(MODEL_DOUBLES), n);
}

/* weight of belt and material along the path from a to b, ∫ m'·g dy
 * (negative when b < a) */
static double weight_between(const bd_sim *sim, double a, double b)
{
    return bd_fronts_weight(sim, &bd_axial_of(sim)->fronts, a, b, WEIGHT_SAMPLES);
}

/* the weight over the two halves of every element */
static void element_weights(bd_sim *sim, double *h1, double *h2)
{
    const bd_axial_model *am = bd_axial_model_of(sim);
    for (int e = 0; e < sim->model->n; e++) {
        double s0 = sim->model->s_node0[e], half = 0.5 * am->s_len[e];
        h1[e] = weight_between(sim, s0, s0 + half);
        h2[e] = weight_between(sim, s0 + half, s0 + 2.0 * half);
    }
}

/* the tension level T_c: the takeup pulley's force balance along its axis,
 *   F + (m_p·g + wrap weight)·(−a_y) + T_out·(u_out·a) − T_in·(u_in·a) = 0,
 * with T_in, T_out the tensions of its two elements; or the installed
 * tension without a takeup (model-format.md `initial_tension`) */
static int tension_level(bd_sim *sim, const double *W_mid, double *Tc, bd_diag *diag)
{
    const bd_axial_model *am = bd_axial_model_of(sim);
    const bd_model_def *def = sim->model->def;
    *Tc = def->belt.initial_tension;
    for (int i = 0; i < sim->model->pulley_count; i++) {
        const bd_pulley_body *p = &sim->pulleys[i];
        const bd_axial_pulley *ap = &am->pulleys[i];
        if (!p->m->movable)
            continue;
        int e_out = ap->node, e_in = (ap->node + sim->model->n - 1) % sim->model->n;
        double F = bd_table_eval(&p->m->def->takeup.force, 0.0);
        double pull = F - p->m->def->mass * sim->model->gravity * p->m->axis[1] + p->m->wrap_pull;
        double denom = ap->c_out - ap->c_in;
        if (fabs(denom) < 1e-6) {
            bd_diag_error(diag, def->source, p->m->def->takeup.mark,
                          "pulleys[%d] '%s': takeup axis is perpendicular to the belt's pull "
                          "on the pulley; it cannot set the tension", i, p->m->def->name);
            return 1;
        }
        *Tc = -(pull + W_mid[e_out] * ap->c_out - W_mid[e_in] * ap->c_in) / denom;
        return 0;
    }
    return 0;
}

static void setup_pulleys(bd_sim *sim, const int *pnode)
{
    bd_axial_model *am = bd_axial_model_build(sim);
    const bd_model_def *def = sim->model->def;
    const int np = def->pulley_count;
    for (int i = 0; i < np; i++) {
        const bd_pulley_def *pd = &def->pulleys[i];
        bd_pulley_body *p = &sim->pulleys[i];
        bd_axial_pulley *ap = &am->pulleys[i];
        ap->node = pnode[i];
        const bd_path_segment *arc = bd_path_arc(&sim->model->path, i);
        ap->law.f = pd->friction.mu_dynamic;
        ap->law.theta = bd_path_wrap_angle(&sim->model->path, i);
        ap->law.rho = sim->model->belt_mpl;
        ap->law.v_thr = pd->velocity_threshold;
        ap->law.f_thr = pd->force_threshold;
        if (pd->has_takeup) {
            const double *a = p->m->axis;
            const double *u_in, *u_out;
            bd_path_wrap_dirs(&sim->model->path, i, &u_in, &u_out);
            ap->c_in = u_in[0] * a[0] + u_in[1] * a[1];
            ap->c_out = u_out[0] * a[0] + u_out[1] * a[1];
            /* the wrapped belt hangs on the pulley: its weight along the
             * axis; and the belt pulls at the tangent points, where the
             * tension differs from its elements' (at their middles) by the
             * weight in between: both are constant forces on the carriage */
            double m_wrap = sim->model->belt_mpl * arc->length
                          + sim->model->def->material.mass_per_length
                                * loaded_length(sim, 0, arc->s0, arc->s0 + arc->length);
            int n = sim->model->n, e_in = (ap->node + n - 1) % n;
            double L = sim->model->path.length;
            double mid_in = sim->model->s_node0[e_in] + 0.5 * am->s_len[e_in];
            double mid_out = sim->model->s_node0[ap->node] + 0.5 * am->s_len[ap->node];
            double a0 = arc->s0, a1 = arc->s0 + arc->length;
            /* unwrap the arc next to the node */
            while (a0 - sim->model->s_node0[ap->node] > 0.5 * L) {
                a0 -= L;
                a1 -= L;
            }
            while (sim->model->s_node0[ap->node] - a0 > 0.5 * L) {
                a0 += L;
                a1 += L;
            }
            if (mid_in - a0 > 0.5 * L)
                mid_in -= L;
            if (mid_out - a1 < -0.5 * L)
                mid_out += L;
            double w_in = weight_between(sim, mid_in, a0);    /* T(a0) = T_in + w_in */
            double w_out = weight_between(sim, a1, mid_out);  /* T(a1) = T_out − w_out */
            sim->own->pulleys[i].wrap_pull =
                -m_wrap * sim->model->gravity * a[1] - w_out * ap->c_out - w_in * ap->c_in;
        }
    }
}

/* the path interval [a, z] of node i's half elements */
static void node_range(const bd_sim *sim, int i, double *a, double *z)
{
    const bd_axial_model *am = bd_axial_model_of(sim);
    int b = i == 0 ? sim->model->n - 1 : i - 1;
    *a = sim->model->s_node0[i] - 0.5 * am->s_len[b];
    *z = sim->model->s_node0[i] + 0.5 * am->s_len[i];
}

/* idlers: rotating mass I/r² spread along their span */
static void spread_idlers(bd_sim *sim)
{
    const bd_model_def *def = sim->model->def;
    double L = sim->model->path.length;
    sim->own->idlers_per_set =
        bd_xcalloc((size_t)def->idler_set_count, sizeof *sim->own->idlers_per_set);
    sim->own->idler_spacing =
        bd_xcalloc((size_t)def->idler_set_count, sizeof *sim->own->idler_spacing);
    for (int k = 0; k < def->idler_set_count; k++) {
        const bd_idler_set_def *set = &def->idler_sets[k];
        int count = bd_idler_set_layout(sim, k, &sim->own->idler_spacing[k]);
        if (count == 0)
            continue;
        const bd_path_segment *sp = bd_path_span(&sim->model->path, set->span);
        double inertia = set->inertia > 0.0 ? set->inertia : 1e-6;
        double mass_per_m = count * inertia / (set->radius * set->radius) / sp->length;
        for (int i = 0; i < sim->model->n; i++) {
            double a, z;
            node_range(sim, i, &a, &z);
            sim->mass[i] += mass_per_m * bd_loop_overlap(a, z, sp->s0, sp->s0 + sp->length, L, NULL, NULL);
        }
    }
}

/* the share of idler set k's span its idlers carry the belt on,
 * count·spacing over the span's length (0: none stand on it) */
static double idler_cover(const bd_sim *sim, int k)
{
    const bd_path_segment *sp = bd_path_span(&sim->model->path, sim->model->def->idler_sets[k].span);
    return sim->model->idlers_per_set[k] * sim->model->idler_spacing[k] / sp->length;
}

/* the idlers' rolling resistance on node i, spread along their span in
 * proportion to the weight on it: the loaded region now, or (`full`) all
 * that can be loaded; the weight's part normal to the path, N, the idlers
 * carry there in *normal (may be NULL) */
static double node_resist(const bd_sim *sim, int i, int full, double *normal)
{
    const bd_model_def *def = sim->model->def;
    double L = sim->model->path.length, mL = def->material.mass_per_length, a, z, R = 0.0;
    double N = 0.0;
    node_range(sim, i, &a, &z);
    for (int k = 0; k < def->idler_set_count; k++) {
        int count = sim->model->idlers_per_set[k];
        if (count == 0)
            continue;
        const bd_idler_set_def *set = &def->idler_sets[k];
        const bd_path_segment *sp = bd_path_span(&sim->model->path, set->span);
        /* the idlers carry the weight on count·spacing of the span, its
         * component normal to the path: cos δ of the span, or on a routed
         * one at the middle of the node's share */
        double cover = idler_cover(sim, k);
        double lo = 0.0, hi = 0.0;
        double on = bd_loop_overlap(a, z, sp->s0, sp->s0 + sp->length, L, &lo, &hi);
        double cosd = fabs(sp->dir[0]);
        if (sp->piece_count > 0 && on > 0.0) {
            double p[2], t[2];
            bd_path_point(&sim->model->path, 0.5 * (lo + hi), p, t);
            cosd = fabs(t[0]);
        }
        if (on > 0.0) {
            double w = sim->model->gravity * cosd * cover
                     * (sim->model->belt_mpl * on + mL * loaded_length(sim, full, lo, hi));
            R += set->rolling_resistance * w;
            N += w;
        }
    }
    if (normal)
        *normal = N;
    return R;
}

/* the unit tangent of a routed span's piece at its start or its end */
static void piece_tangent(const bd_path_piece *pc, int end, double t[2])
{
    double p[2];
    bd_path_piece_point(pc, end ? pc->length : 0.0, p, t);
}

/* +1 when up (bd_path_up_normal) is left of travel direction t, else −1 */
static double up_side(const double t[2])
{
    double up[2];
    bd_path_up_normal(t, up);
    return t[0] * up[1] - t[1] * up[0] >= 0.0 ? 1.0 : -1.0;
}

/* The part of the idlers' load on node i that follows the belt tension
 * where a routed span turns: a string under tension T whose direction
 * turns by Δ presses T·Δ on its supports (T/R per metre on an arc of
 * radius R; seed 004's normal force of a wrap, as the moving-node belt,
 * moving_node/forces.c), onto the idlers where it turns away from them
 * (convex), off them where it turns towards them (concave), and there the
 * belt lifts once T/R exceeds m'·g·cos δ (CEMA's concave-curve radius
 * R = T/(m'g); D. Pitcher, IMHC B17-16). The turns are the arcs' (over the
 * node's share of each) and the corners between pieces: an idler `curve`
 * on an explicit span is an arc through two of its points, so it meets the
 * span at two corners that turn back by half its sweep each. Its turns
 * sum to zero, and so does what they add to the idlers' load (a belt
 * bent by a curve and straight on both sides: the tension's ends pull
 * along one line); a profile's fillet has no corners. A corner's turn is
 * shared by the idler spacing a on either side (the two idlers nearest
 * it carry it between them, as the 2D belts' would), so T·Δ over 2a.
 * Spread as the weight is (cover): kn·T on the node, kn = Σ −side·Δ·cover
 * (side +1 when up is left of the travel, Δ + ccw), and the resistance
 * kr·T, kr = Σ rr·(its part of kn). */
static double curve_turn(const bd_sim *sim, int i, double *kn)
{
    const bd_model_def *def = sim->model->def;
    const bd_path *path = &sim->model->path;
    double a, z, kr = 0.0;
    *kn = 0.0;
    node_range(sim, i, &a, &z);
    for (int k = 0; k < def->idler_set_count; k++) {
        int count = sim->model->idlers_per_set[k];
        const bd_path_segment *sp = bd_path_span(path, def->idler_sets[k].span);
        if (count == 0 || sp->piece_count == 0)
            continue;
        double cover = idler_cover(sim, k), spacing = sim->model->idler_spacing[k];
        double press = 0.0;
        for (int q = sp->piece_first; q < sp->piece_first + sp->piece_count; q++) {
            const bd_path_piece *pc = &path->pieces[q];
            double t[2], turn = 0.0, share = 0.0;
            if (pc->is_arc) {
                share = bd_loop_overlap(a, z, pc->s0, pc->s0 + pc->length, path->length, NULL,
                                        NULL) / pc->length;
                turn = pc->sweep;
                piece_tangent(pc, 0, t);
                if (share > 0.0)
                    press -= up_side(t) * turn * share;
            }
            /* the corner where the next piece begins */
            if (q + 1 == sp->piece_first + sp->piece_count)
                continue;
            double t1[2];
            piece_tangent(pc, 1, t);
            piece_tangent(&path->pieces[q + 1], 0, t1);
            turn = atan2(t[0] * t1[1] - t[1] * t1[0], t[0] * t1[0] + t[1] * t1[1]);
            if (fabs(turn) < 1e-9)
                continue;   /* a fillet's tangent joint */
            double s_c = path->pieces[q + 1].s0;
            share = bd_loop_overlap(a, z, s_c - spacing, s_c + spacing, path->length, NULL, NULL)
                  / (2.0 * spacing);
            if (share > 0.0)
                press -= up_side(t) * turn * share;
        }
        *kn += cover * press;
        kr += def->idler_sets[k].rolling_resistance * cover * press;
    }
    return kr;
}

/* the nodes in a vertical curve, and their kn and kr (curve_turn) */
static void find_curve_nodes(bd_sim *sim)
{
    bd_axial_model *am = bd_axial_model_build(sim);
    const int n = sim->model->n;
    am->curve_count = 0;
    if (sim->model->path.piece_count == 0)
        return;
    for (int pass = 0; pass < 2; pass++) {
        int c = 0;
        for (int i = 0; i < n; i++) {
            double kn, kr = curve_turn(sim, i, &kn);
            if (kn == 0.0)
                continue;
            if (pass == 1) {
                am->curve_node[c] = i;
                am->curve_kn[c] = kn;
                am->curve_kr[c] = kr;
            }
            c++;
        }
        if (pass == 0) {
            am->curve_count = c;
            am->curve_node = bd_xcalloc((size_t)(c ? c : 1), sizeof *am->curve_node);
            am->curve_kr = bd_xcalloc((size_t)(c ? c : 1), sizeof *am->curve_kr);
            am->curve_kn = bd_xcalloc((size_t)(c ? c : 1), sizeof *am->curve_kn);
        }
    }
}

/* node i's share of the loaded region: its material (the node's mass
 * changes with it), the weight along the path over its half elements and
 * the rolling resistance. The build and a moving load front (axial_step.c)
 * both set a node's load here. */
void bd_axial_node_load(bd_sim *sim, int i)
{
    const bd_axial_model *am = bd_axial_model_of(sim);
    int b = i == 0 ? sim->model->n - 1 : i - 1;
    double a, z;
    node_range(sim, i, &a, &z);
    double m = sim->model->def->material.mass_per_length * loaded_length(sim, 0, a, z);
    sim->mass[i] += m - sim->material[i];
    if (sim->model->dt > 0.0)   /* a load front moved (the build sets all at once) */
        bd_node_mass_changed(sim, i);
    sim->material[i] = m;
    /* the same halves as element_weights */
    double sb = sim->model->s_node0[b], hb = 0.5 * am->s_len[b];
    double si = sim->model->s_node0[i], hi = 0.5 * am->s_len[i];
    bd_axial_of(sim)->f_const[i] = -(weight_between(sim, sb + hb, sb + 2.0 * hb)
                           + weight_between(sim, si, si + hi));
    bd_axial_of(sim)->resist[i] = node_resist(sim, i, 0, &bd_axial_of(sim)->normal[i]);
}

int bd_axial_build(bd_sim *sim, bd_diag *diag)
{
    const bd_model_def *def = sim->model->def;
    if (bd_path_build(def, &sim->own->path, diag))
        return 1;
    sim->belt_data = bd_xcalloc(1, sizeof(bd_axial));
    sim->own->belt_model = bd_xcalloc(1, sizeof(bd_axial_model));
    bd_axial_model *am = bd_axial_model_build(sim);
    double target = def->belt.element_length > 0.0 ? def->belt.element_length : 1.0;
    int *pnode;
    place_stations(sim, target, &pnode);
    const int n = sim->model->n;
    alloc_arrays(sim);
    double L = sim->model->path.length;
    for (int e = 0; e < n; e++) {
        int j = e + 1 == n ? 0 : e + 1;
        double ds = sim->model->s_node0[j] - sim->model->s_node0[e];
        am->s_len[e] = ds > 0.0 ? ds : ds + L;
    }
    bd_fronts_init(sim, &bd_axial_of(sim)->fronts, 0);
    setup_pulleys(sim, pnode);
    free(pnode);

    /* at-rest tension: weights integrated from the (first) drive pulley's
     * node, so that the net weight of an inclined load sits on a pulley */
    double *h1 = bd_xcalloc((size_t)n, sizeof *h1), *h2 = bd_xcalloc((size_t)n, sizeof *h2);
    double *W_mid = bd_xcalloc((size_t)n, sizeof *W_mid);
    element_weights(sim, h1, h2);
    const bd_axial_pulley *ap = am->pulleys;
    int origin = ap[0].node;
    for (int i = 0; i < sim->model->pulley_count; i++)
        if (def->pulleys[i].has_drive) {
            origin = ap[i].node;
            break;
        }
    double W = 0.0;
    for (int k = 0; k < n; k++) {
        int e = (origin + k) % n;
        W_mid[e] = W + h1[e];
        W += h1[e] + h2[e];
    }
    double Tc;
    if (tension_level(sim, W_mid, &Tc, diag)) {
        free(h1);
        free(h2);
        free(W_mid);
        return 1;
    }
    int rest = def->simulation.initial_state == BD_INITIAL_REST;
    double EA = sim->model->EA, zeta = def->belt.damping_ratio, l0_sum = 0.0;
    for (int e = 0; e < n; e++) {
        double T = rest ? 0.0 : Tc + W_mid[e];
        double l0 = am->s_len[e] / (1.0 + T / EA);
        am->l0[e] = l0;
        bd_axial_of(sim)->gap[e] = am->s_len[e] - l0;
        am->k[e] = EA / l0;
        /* seed 001 eq 4.3 per element: c = 2ζ·√(k·m_e) */
        am->c[e] = 2.0 * zeta * sqrt(am->k[e] * sim->model->belt_mpl * l0);
        sim->tension[e] = T;
        l0_sum += l0;
    }
    sim->own->l0 = l0_sum / n;

    free(h1);
    free(h2);
    free(W_mid);
    /* nodes: mass of the belt and the idlers, then the load; position */
    for (int i = 0; i < n; i++) {
        double a, z;
        node_range(sim, i, &a, &z);
        sim->mass[i] = sim->model->belt_mpl * (z - a);
        double p[2], t[2];
        bd_path_point(&sim->model->path, sim->model->s_node0[i], p, t);
        sim->x[i] = p[0];
        sim->y[i] = p[1];
    }
    spread_idlers(sim);
    find_curve_nodes(sim);
    /* the lightest node carries no material: load leaving a node never
     * takes it below this, and the stable step is taken with it */
    am->min_mass = INFINITY;
    for (int i = 0; i < n; i++) {
        if (sim->mass[i] < am->min_mass)
            am->min_mass = sim->mass[i];
        bd_axial_node_load(sim, i);
    }

    bd_setup_probes_and_feed(sim);
    am->feed_node = -1;
    if (def->material.present) {
        if (sim->has_feed)
            am->feed_node = sim->feed.gamma < 0.5 ? sim->feed.element
                                                      : (sim->feed.element + 1) % n;
        bd_axial_of(sim)->fronts.e_tail = sim->feed.element;
        bd_axial_of(sim)->fronts.e_head = sim->feed.element;
    }
    return 0;
}

/* Gershgorin bound of the highest frequency, node by node: a node between
 * elements a and b has ω² ≤ 2·(k_a + k_b)/m (plus k·|u·a| where an element
 * pulls a takeup carriage) and damping 2·(c_a + c_b) + the slope of the
 * rolling resistance; a carriage ω² ≤ Σ (k·c² + 2·k·|c|)/M. The step for
 * each is (2/ω)·(√(1+ζ²) − ζ) (laws/stable_step.h). */
static double mode_step(double K, double C, double m)
{
    if (K <= 0.0 || m <= 0.0)
        return INFINITY;
    double w = sqrt(K / m), z = C / (2.0 * m * w);
    return bd_central_difference_limit(w, z);
}

double bd_axial_stable_step(const bd_sim *sim, bd_time_step_limit *limit)
{
    const bd_axial_model *am = bd_axial_model_of(sim);
    *limit = BD_LIMIT_AXIAL;
    const int n = sim->model->n;
    double dt = INFINITY;
    for (int i = 0; i < n; i++) {
        int b = i == 0 ? n - 1 : i - 1;
        double K = 2.0 * (am->k[b] + am->k[i]);
        /* the rolling resistance's slope with the most load the node can carry */
        double C = 2.0 * (am->c[b] + am->c[i]) + node_resist(sim, i, 1, NULL) / BD_ROLLING_SPEED;
        for (int p = 0; p < sim->model->pulley_count; p++) {
            const bd_axial_pulley *ap = &am->pulleys[p];
            if (!sim->pulleys[p].m->movable)
                continue;
            int e_in = (ap->node + n - 1) % n;
            if (i == e_in || i == (e_in + 1) % n)
                K += am->k[e_in] * fabs(ap->c_in);
            if (i == ap->node || i == (ap->node + 1) % n)
                K += am->k[ap->node] * fabs(ap->c_out);
        }
        double d = mode_step(K, C, sim->mass[i] - sim->material[i]);
        if (d < dt)
            dt = d;
    }
    for (int p = 0; p < sim->model->pulley_count; p++) {
        const bd_pulley_body *pb = &sim->pulleys[p];
        const bd_axial_pulley *ap = &am->pulleys[p];
        if (!pb->m->movable)
            continue;
        double ki = am->k[(ap->node + n - 1) % n], ko = am->k[ap->node];
        double K = ki * (ap->c_in * ap->c_in + 2.0 * fabs(ap->c_in))
                 + ko * (ap->c_out * ap->c_out + 2.0 * fabs(ap->c_out));
        double d = mode_step(K, 0.0, pb->m->carriage_mass);
        if (d < dt)
            dt = d;
    }
    return dt;
}

void bd_axial_free(bd_sim *sim)
{
    bd_axial *ax = bd_axial_of(sim);
    if (!ax)
        return;
    bd_doubles_free(ax, STATE_DOUBLES, COUNT(STATE_DOUBLES));
    free(ax->pulleys);
    free(ax);
    sim->belt_data = NULL;
}

void bd_axial_free_model(bd_model *model)
{
    bd_axial_model *am = model->belt_model;
    if (!am)
        return;
    bd_doubles_free(am, MODEL_DOUBLES, COUNT(MODEL_DOUBLES));
    free(am->pulleys);
    free(am->curve_node);
    free(am->curve_kr);
    free(am->curve_kn);
    free(am);
    model->belt_model = NULL;
}


/* dst's state as a copy of src's, for a new run on the same model (as
 * bd_lumped_clone: dst owns every pointer from the moment it is set) */
void bd_axial_clone(bd_sim *dst, const bd_sim *src)
{
    const bd_axial *S = bd_axial_of(src);
    size_t n = (size_t)src->model->n, np = (size_t)src->model->pulley_count;
    bd_axial *ax = bd_xcalloc(1, sizeof *ax);
    dst->belt_data = ax;
    /* the scalars by copy, the arrays not the source's until each is copied */
    *ax = *S;
    ax->pulleys = NULL;
    bd_doubles_dup(ax, S, STATE_DOUBLES, COUNT(STATE_DOUBLES), n);
    ax->pulleys = bd_xdup(S->pulleys, np, sizeof *ax->pulleys);
}

/* a point fixed on the path, between the two stations around it */
void bd_axial_point_init(const bd_sim *sim, bd_tracker *tr, double s)
{
    bd_station_point_init(sim, tr, s, bd_axial_model_of(sim)->s_len);
}

/* node-steps per second: bench/bench_axial_10km (10 013 nodes) runs 2.6e8
 * on the two-core machine this was written on; short belts run slower per
 * node (5.5e7 at 102 nodes) but cost little anyway */
#define AXIAL_RATE 2.5e8

/* what bd_axial_build would make, from the definition and the path: about
 * one node per element_length of the loop (its pulley nodes neglected),
 * idlers spread (no bodies), and the step of a node between two elements
 * of the empty belt (mode_step's law without the rolling resistance) */
void bd_axial_estimate(const bd_model_def *def, const bd_path *path, bd_belt_estimate *out)
{
    double l = def->belt.element_length > 0.0 ? def->belt.element_length : 1.0;
    out->element_length = l;
    out->nodes = fmax((double)path->pulley_count, floor(path->length / l + 0.5));
    out->idlers = 0.0;
    /* the node arrays, the state's and the model's arrays, s_node0, and the
     * build's three weight arrays */
    out->node_bytes = (double)(bd_node_arrays_bytes()
                               + (size_t)(COUNT(STATE_DOUBLES) + COUNT(MODEL_DOUBLES) + 4)
                                     * sizeof(double));
    out->idler_bytes = 0.0;
    double k = def->belt.axial_stiffness / l, m = def->belt.mass_per_length * l;
    double c = 2.0 * def->belt.damping_ratio * sqrt(k * m);
    out->stable_step = mode_step(4.0 * k, 4.0 * c, m);
    out->rate = AXIAL_RATE;
}
