/* The moving-node belt: building it from the model (model-format.md
 * `formulation: moving_node`; docs/physics.md §14).
 *
 * Nodes come from layout.c. The belt starts at its at-rest tension
 * T(s) = T_c + W(s), W the weight of belt and material integrated along
 * the path from the drive pulley, T_c from the takeup's force balance or
 * the installed tension (as the axial belt, build.c there): each element's
 * unstretched content ΔX_e = l_e/(1 + T_e/EA) makes the start an exact
 * equilibrium of the discrete equations along the path. */
#include "belt/moving_node/moving_node.h"

#include "base/alloc.h"
#include "base/constants.h"
#include "laws/stable_step.h"
#include "parts/parts.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

/* the belt's passage per step through an element, at most (stable_step) */
#define TRANSPORT_CFL 0.5
/* samples per half element of the weight integral */
#define WEIGHT_SAMPLES 4

static const size_t STATE_DOUBLES[] = {
    offsetof(bd_mn, w),      offsetof(bd_mn, dX),     offsetof(bd_mn, len),
    offsetof(bd_mn, cos_e),  offsetof(bd_mn, sin_e),  offsetof(bd_mn, td),
    offsetof(bd_mn, tdw),    offsetof(bd_mn, f_grav), offsetof(bd_mn, f_norm),
    offsetof(bd_mn, normal), offsetof(bd_mn, vnew),   offsetof(bd_mn, rhs),
    offsetof(bd_mn, p0),     offsetof(bd_mn, qa),     offsetof(bd_mn, qb),
    offsetof(bd_mn, cp),     offsetof(bd_mn, fr),     offsetof(bd_mn, ca),
    offsetof(bd_mn, cb),     offsetof(bd_mn, cna),    offsetof(bd_mn, cnb),
    offsetof(bd_mn, cnc),    offsetof(bd_mn, vold),
    offsetof(bd_mn, wdn),    offsetof(bd_mn, gw),     offsetof(bd_mn, pin),
    offsetof(bd_mn, sweep_c), offsetof(bd_mn, sweep_d), offsetof(bd_mn, kap)};
static const size_t MODEL_DOUBLES[] = {
    offsetof(bd_mn_model, nx),         offsetof(bd_mn_model, ny),
    offsetof(bd_mn_model, arc_len),
    offsetof(bd_mn_model, rolling),    offsetof(bd_mn_model, idler_mass),
    offsetof(bd_mn_model, belt_mass),  offsetof(bd_mn_model, inv_cell),
    offsetof(bd_mn_model, mx),
    offsetof(bd_mn_model, my),         offsetof(bd_mn_model, x0),
    offsetof(bd_mn_model, y0),         offsetof(bd_mn_model, ds0),
    offsetof(bd_mn_model, dsq),        offsetof(bd_mn_model, k),
    offsetof(bd_mn_model, c),          offsetof(bd_mn_model, radius),
    offsetof(bd_mn_model, kw)};
#define COUNT(a) ((int)(sizeof a / sizeof a[0]))

static void alloc_arrays(bd_sim *sim)
{
    size_t n = (size_t)sim->model->n, np = (size_t)sim->model->pulley_count;
    bd_node_arrays_alloc(sim);
    bd_mn *mn = bd_mn_of(sim);
    bd_mn_model *mm = bd_mn_model_build(sim);
    bd_doubles_alloc(mn, STATE_DOUBLES, COUNT(STATE_DOUBLES), n);
    bd_doubles_alloc(mm, MODEL_DOUBLES, COUNT(MODEL_DOUBLES), n);
    mn->contact = bd_xcalloc(n, 1);
    mn->Q = bd_xcalloc(np, sizeof *mn->Q);
    mn->A = bd_xcalloc(np * np, sizeof *mn->A);
    mn->b = bd_xcalloc(np, sizeof *mn->b);
    mn->omega = bd_xcalloc(np, sizeof *mn->omega);
    mn->q_seen = bd_xcalloc(np, sizeof *mn->q_seen);
    mn->frg = bd_xcalloc(3 * n, sizeof *mn->frg);
    mn->frp = bd_xcalloc(3 * n, sizeof *mn->frp);
    mn->run_prev = bd_xcalloc(n, sizeof *mn->run_prev);
    mn->run_next = bd_xcalloc(n, sizeof *mn->run_next);
    mm->kind = bd_xcalloc(n, 1);
    mm->idler_nodes = bd_xcalloc(n, sizeof *mm->idler_nodes);
    mm->on_arc = bd_xcalloc(n, 1);
    mm->pulley = bd_xcalloc(n, sizeof *mm->pulley);
    mm->mover = bd_xcalloc(n, sizeof *mm->mover);
    mm->eq = bd_xcalloc(n, sizeof *mm->eq);
    mm->pulleys = bd_xcalloc(np, sizeof *mm->pulleys);
}

static double loaded_length(const bd_sim *sim, double a, double b)
{
    return bd_fronts_loaded_length(sim, &bd_mn_of(sim)->fronts, 0, a, b);
}

static double weight_between(const bd_sim *sim, double a, double b)
{
    return bd_fronts_weight(sim, &bd_mn_of(sim)->fronts, a, b, WEIGHT_SAMPLES);
}

/* node i's cell: half of each element beside it, [a, z] */
static void cell(const bd_sim *sim, int i, double *a, double *z)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    int b = bd_node_prev(i, sim->model->n);
    *a = sim->model->s_node0[i] - 0.5 * mm->ds0[b];
    *z = sim->model->s_node0[i] + 0.5 * mm->ds0[i];
}

/* node i's share of the loaded region: its material and mass, its weight
 * along the path and along its normal. The build and a moving load front
 * (integrate.c) both set a node's load here. */
void bd_mn_node_load(bd_sim *sim, int i)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    bd_mn *mn = bd_mn_of(sim);
    double a, z;
    cell(sim, i, &a, &z);
    double m = sim->model->def->material.mass_per_length * loaded_length(sim, a, z);
    sim->material[i] = m;
    sim->mass[i] = mm->belt_mass[i] + m + mm->idler_mass[i];
    if (sim->model->dt > 0.0)
        bd_node_mass_changed(sim, i);
    double s = sim->model->s_node0[i];
    mn->f_grav[i] = -(weight_between(sim, a, s) + weight_between(sim, s, z));
    mn->f_norm[i] = -(mm->belt_mass[i] + m) * sim->model->gravity * mm->ny[i];
}

/* the stretches of span next to a movable pulley that move with it: from
 * its tangent point back (in) or on (out) to the first idler or arc node;
 * their nodes follow the carriage in proportion, their elements change
 * length by dsq·q (docs/physics.md §14) */
static int setup_movers(bd_sim *sim, bd_diag *diag)
{
    bd_mn_model *mm = bd_mn_model_build(sim);
    const int n = sim->model->n, np = sim->model->pulley_count;
    const bd_path *path = &sim->model->path;
    for (int p = 0; p < np; p++) {
        bd_pulley_model *pm = &sim->own->pulleys[p];
        if (!pm->movable)
            continue;
        bd_mn_pulley *pp = &mm->pulleys[p];
        const double *a = pm->axis;
        const double *u_in, *u_out;
        bd_path_wrap_dirs(path, p, &u_in, &u_out);
        double c_in = u_in[0] * a[0] + u_in[1] * a[1];
        double c_out = u_out[0] * a[0] + u_out[1] * a[1];
        /* in: back from the tangent-in node */
        int tin = pp->first, start = bd_node_prev(tin, n);
        while (mm->kind[start] == BD_MN_FREE)
            start = bd_node_prev(start, n);
        int tout = (pp->first + pp->count - 1) % n, end = bd_node_next(tout, n);
        while (mm->kind[end] == BD_MN_FREE)
            end = bd_node_next(end, n);
        pp->in.first = start;
        pp->in.count = (tin - start + n) % n;
        pp->out.first = tout;
        pp->out.count = (end - tout + n) % n;
        double Lin = 0.0, Lout = 0.0;
        for (int k = 0; k < pp->in.count; k++)
            Lin += mm->ds0[(start + k) % n];
        for (int k = 0; k < pp->out.count; k++)
            Lout += mm->ds0[(tout + k) % n];
        int clash = mm->mover[start] >= 0 || mm->mover[end] >= 0;
        for (int k = 0; k < pp->in.count && !clash; k++)
            clash = mm->eq[(start + k) % n] >= 0;
        for (int k = 0; k < pp->out.count && !clash; k++)
            clash = mm->eq[(tout + k) % n] >= 0;
        if (clash || Lin <= 0.0 || Lout <= 0.0) {
            bd_diag_error(diag, sim->model->def->source, pm->def->takeup.mark,
                          "pulleys[%d] '%s': moving_node needs an idler or a fixed pulley "
                          "between two takeup pulleys", p, pm->def->name);
            return 1;
        }
        /* the nodes moving with the carriage and their share of its travel */
        double acc = 0.0;
        for (int k = 1; k < pp->in.count; k++) {
            int e = (start + k - 1) % n, i = (start + k) % n;
            acc += mm->ds0[e];
            mm->mover[i] = p;
            mm->mx[i] = acc / Lin * a[0];
            mm->my[i] = acc / Lin * a[1];
        }
        for (int k = 0; k < pp->count; k++) {
            int i = (pp->first + k) % n;
            mm->mover[i] = p;
            mm->mx[i] = a[0];
            mm->my[i] = a[1];
        }
        acc = 0.0;
        for (int k = 1; k < pp->out.count; k++) {
            int e = (tout + k - 1) % n, i = (tout + k) % n;
            acc += mm->ds0[e];
            mm->mover[i] = p;
            mm->mx[i] = (1.0 - acc / Lout) * a[0];
            mm->my[i] = (1.0 - acc / Lout) * a[1];
        }
        for (int k = 0; k < pp->in.count; k++) {
            int e = (start + k) % n;
            mm->eq[e] = p;
            mm->dsq[e] = c_in * mm->ds0[e] / Lin;
        }
        for (int k = 0; k < pp->out.count; k++) {
            int e = (tout + k) % n;
            mm->eq[e] = p;
            mm->dsq[e] = -c_out * mm->ds0[e] / Lout;
        }
    }
    return 0;
}

/* the weight of the nodes moving with carriage p along its axis: the
 * belt's pull on the carriage besides the tensions (−∂/∂q of their
 * gravity potential, with their mass at the start) */
static void wrap_pulls(bd_sim *sim)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    for (int p = 0; p < sim->model->pulley_count; p++)
        sim->own->pulleys[p].wrap_pull = 0.0;
    for (int i = 0; i < sim->model->n; i++) {
        int p = mm->mover[i];
        if (p >= 0)
            sim->own->pulleys[p].wrap_pull -= (sim->mass[i] - mm->idler_mass[i])
                                              * sim->model->gravity * mm->my[i];
    }
}

/* the tension level T_c: the takeup carriage's force balance along its
 * axis, pull + wrap_pull − Σ_e (T_c + W_e)·dsq_e = 0 (virtual work of a
 * carriage displacement on the stretches beside it, physics.md §14
 * "Takeups"; model-format.md's T = force/((u_in − u_out)·a) when the
 * weights W_e vanish); or the installed
 * tension without a takeup (model-format.md `initial_tension`) */
static int tension_level(bd_sim *sim, const double *W_mid, double *Tc, bd_diag *diag)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    const bd_model_def *def = sim->model->def;
    *Tc = def->belt.initial_tension;
    for (int p = 0; p < sim->model->pulley_count; p++) {
        const bd_pulley_model *pm = &sim->model->pulleys[p];
        if (!pm->movable)
            continue;
        double F = bd_table_eval(&pm->def->takeup.force, 0.0);
        double pull = F - pm->def->mass * sim->model->gravity * pm->axis[1] + pm->wrap_pull;
        double sum = 0.0, wsum = 0.0;
        for (int e = 0; e < sim->model->n; e++)
            if (mm->eq[e] == p) {
                sum += mm->dsq[e];
                wsum += W_mid[e] * mm->dsq[e];
            }
        if (fabs(sum) < 1e-6) {
            bd_diag_error(diag, def->source, pm->def->takeup.mark,
                          "pulleys[%d] '%s': takeup axis is perpendicular to the belt's pull "
                          "on the pulley; it cannot set the tension", p, pm->def->name);
            return 1;
        }
        *Tc = (pull - wsum) / sum;
        return 0;
    }
    return 0;
}

/* the at-rest tension of every element, from the weight integrated from
 * the middle of the first drive pulley's wrap */
static int rest_tension(bd_sim *sim, double *T, bd_diag *diag)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    const bd_model_def *def = sim->model->def;
    const int n = sim->model->n;
    int origin = mm->pulleys[0].first;
    for (int p = 0; p < sim->model->pulley_count; p++)
        if (def->pulleys[p].has_drive) {
            origin = (mm->pulleys[p].first + mm->pulleys[p].count / 2) % n;
            break;
        }
    double W = 0.0;
    for (int k = 0; k < n; k++) {
        int e = (origin + k) % n;
        double s0 = sim->model->s_node0[e], half = 0.5 * mm->ds0[e];
        double h1 = weight_between(sim, s0, s0 + half), h2 = weight_between(sim, s0 + half, s0 + 2.0 * half);
        T[e] = W + h1;
        W += h1 + h2;
    }
    double Tc;
    if (tension_level(sim, T, &Tc, diag))
        return 1;
    for (int e = 0; e < n; e++)
        T[e] += Tc;
    return 0;
}

/* the bound on the tension the transverse step is taken for: the rated
 * tension, else twice the largest at rest, and at least 2 % strain */
static double tension_bound(const bd_sim *sim, const double *T)
{
    double hi = 0.0;
    for (int e = 0; e < sim->model->n; e++)
        hi = fmax(hi, T[e]);
    double b = fmax(2.0 * hi, 0.02 * sim->model->EA);
    return fmax(b, sim->model->def->belt.rated_tension);
}

int bd_mn_build(bd_sim *sim, bd_diag *diag)
{
    const bd_model_def *def = sim->model->def;
    if (bd_path_build(def, &sim->own->path, diag))
        return 1;
    sim->belt_data = bd_xcalloc(1, sizeof(bd_mn));
    sim->own->belt_model = bd_xcalloc(1, sizeof(bd_mn_model));
    bd_mn_model *mm = bd_mn_model_build(sim);
    bd_mn *mn = bd_mn_of(sim);
    int n = (int)bd_mn_layout_count(def, &sim->model->path, NULL);
    sim->own->n = n;
    sim->own->s_node0 = bd_xcalloc((size_t)n, sizeof *sim->own->s_node0);
    alloc_arrays(sim);
    bd_mn_layout_fill(sim);

    /* the idlers: counted per set (the layout placed them), no bodies */
    sim->own->idlers_per_set =
        bd_xcalloc((size_t)def->idler_set_count, sizeof *sim->own->idlers_per_set);
    sim->own->idler_spacing =
        bd_xcalloc((size_t)def->idler_set_count, sizeof *sim->own->idler_spacing);
    for (int k = 0; k < def->idler_set_count; k++)
        bd_idler_set_layout(sim, k, &sim->own->idler_spacing[k]);

    /* the loaded region, as the axial belt's */
    const bd_material_def *mat = &def->material;
    bd_fronts_init(sim, &mn->fronts, 0);

    /* masses and loads */
    for (int i = 0; i < n; i++) {
        double a, z;
        cell(sim, i, &a, &z);
        mm->belt_mass[i] = sim->model->belt_mpl * (z - a);
        mm->inv_cell[i] = 1.0 / (z - a);
        bd_mn_node_load(sim, i);
        sim->x[i] = mm->x0[i];
        sim->y[i] = mm->y0[i];
    }
    if (setup_movers(sim, diag))
        return 1;
    wrap_pulls(sim);

    double *T = bd_xcalloc((size_t)n, sizeof *T);
    if (rest_tension(sim, T, diag)) {
        free(T);
        return 1;
    }
    int rest = def->simulation.initial_state == BD_INITIAL_REST;
    double EA = sim->model->EA, zeta = def->belt.damping_ratio, l0_sum = 0.0;
    for (int e = 0; e < n; e++) {
        double Te = rest ? 0.0 : T[e];
        double dX = mm->ds0[e] / (1.0 + Te / EA);
        mn->dX[e] = dX;
        mn->len[e] = mm->ds0[e];
        mn->cos_e[e] = 1.0;
        mm->k[e] = EA / dX;
        /* seed 001 eq 4.3 per element: c = 2ζ·√(k·m_e) */
        mm->c[e] = 2.0 * zeta * sqrt(mm->k[e] * sim->model->belt_mpl * dX);
        sim->tension[e] = Te;
        l0_sum += dX;
    }
    sim->own->l0 = l0_sum / n;
    mm->tension_bound = tension_bound(sim, T);
    mm->wave_speed = sqrt(EA / sim->model->belt_mpl);
    free(T);
    for (int i = 0; i < n; i++)
        mn->contact[i] = BD_MN_STICK;

    bd_setup_probes_and_feed(sim);
    mm->feed_node = -1;
    mm->first_arc = 0;
    mm->idler_node_count = 0;
    for (int i = n - 1; i >= 0; i--) {
        if (mm->kind[i] == BD_MN_ARC)
            mm->first_arc = i;
        if (mm->kind[i] == BD_MN_IDLER)
            mm->idler_nodes[mm->idler_node_count++] = i;
    }
    if (mat->present && sim->has_feed)
        mm->feed_node = sim->feed.gamma < 0.5 ? sim->feed.element
                                              : bd_node_next(sim->feed.element, n);
    if (mat->present)
        mn->fronts.e_tail = mn->fronts.e_head = sim->feed.element;
    mn->liftoff_first_node = -1;
    return 0;
}

/* the mean span element the layout aims at: the spans' length over
 * their elements, each span cut into whole elements of at most its
 * target */
static double mean_span_element(const bd_model_def *def, const bd_path *path)
{
    double length = 0.0, count = 0.0;
    for (int j = 0; j < path->pulley_count; j++) {
        double l = bd_path_span(path, j)->length;
        length += l;
        count += fmax(1.0, ceil(l / bd_mn_span_target(def, path, j) - 1e-9));
    }
    return length / count;
}

/* The step: the axial motion is implicit (solve.c), stable at any step,
 * so the step is set by accuracy there: a wave crosses the mean span
 * element in no less than a step (seed 001 eq 6.1 at ζ = 0), the mesh
 * where the belt is; shorter elements keep the trapezoidal rule, which
 * only delays their own fastest waves. Except those that follow a takeup
 * carriage, whose lengths change with its travel, which the parts advance
 * explicitly: there a wave must cross each element in a step. On the
 * cement plant (1.2 m carry, 3 m return, 1 m loop elements) the mean gave
 * Δt 1.9 ms; with the drive's speed loop no longer holding the step down
 * (650bf43) its 40 s start diverged in the loop's spans at 15.6 s (at
 * 1.7 ms at 16.5 s), and ran to the end with the carriage fixed. Its loop
 * elements (0.84 m where a span is split) now give 0.94 ms (1.5 ms ran
 * too), and every figure of its summary lies within 0.03 % of the run at
 * 0.45 ms (issue 10). The
 * transverse motion is explicit: a
 * free node between elements l_a, l_b at the tension bound has
 * ω² ≤ 2·T·(1/l_a + 1/l_b)/m, plus 16·EI/(m·l⁴)·l per unit mass for
 * bending (Gershgorin bounds of the string's and the bending stencil's
 * rows, derived here; 16 = 1 + 4 + 6 + 4 + 1 of the five-point row); a
 * carriage ω² ≤ Σ k_e·dsq_e·(|dsq_e| + 2)/M as the axial belt's.
 * And the belt may pass no more than TRANSPORT_CFL of an element per step
 * at 1.2 × the fastest drive speed (at least 1 m/s): the strain carried
 * through the nodes is explicit (upwind), and with the implicit solve its
 * odd-even mode on a slipping wrap grew at v·Δt/l = 0.72 (a dual drive's
 * 24 mm tail-arc elements, generated conveyor 41) and did not at 0.54. */
double bd_mn_stable_step(const bd_sim *sim, bd_time_step_limit *limit)
{
    const bd_mn_model *mm = bd_mn_model_of(sim);
    const bd_model_def *def = sim->model->def;
    const int n = sim->model->n;
    double c = mm->wave_speed;
    double lref = mean_span_element(def, &sim->model->path);
    /* the elements that follow a takeup carriage: a wave crosses each in
     * no less than a step (below) */
    for (int e = 0; e < n; e++)
        if (mm->eq[e] >= 0)
            lref = fmin(lref, mm->ds0[e]);
    double dt = bd_central_difference_limit(2.0 * c / lref, 0.0);
    *limit = BD_LIMIT_AXIAL;
    double EI = sim->model->EI, Tb = mm->tension_bound;
    for (int i = 0; i < n; i++) {
        if (mm->kind[i] == BD_MN_ARC)
            continue;
        int b = bd_node_prev(i, n);
        double m = sim->mass[i] - sim->material[i] - mm->idler_mass[i];
        double la = mm->ds0[b], lb = mm->ds0[i], lmin = fmin(la, lb);
        double K = 2.0 * Tb * (1.0 / la + 1.0 / lb);
        double Kb = EI > 0.0 ? 16.0 * EI / (lmin * lmin * lmin) : 0.0;
        double d = bd_central_difference_limit(sqrt((K + Kb) / m), 0.0);
        if (d < dt) {
            dt = d;
            *limit = Kb > K ? BD_LIMIT_BENDING : BD_LIMIT_TRANSVERSE;
        }
    }
    double v_ref = 1.2 * fmax(bd_drives_reference_speed(sim->model->def), 1.0);
    for (int e = 0; e < n; e++) {
        double d = TRANSPORT_CFL * mm->ds0[e] / v_ref;
        if (d < dt) {
            dt = d;
            *limit = BD_LIMIT_TRANSPORT;
        }
    }
    for (int p = 0; p < sim->model->pulley_count; p++) {
        const bd_pulley_model *pm = &sim->model->pulleys[p];
        if (!pm->movable)
            continue;
        double K = 0.0;
        for (int e = 0; e < n; e++)
            if (mm->eq[e] == p)
                K += mm->k[e] * fabs(mm->dsq[e]) * (fabs(mm->dsq[e]) + 2.0);
        double d = K > 0.0 ? bd_central_difference_limit(sqrt(K / pm->carriage_mass), 0.0)
                           : INFINITY;
        if (d < dt) {
            dt = d;
            *limit = BD_LIMIT_AXIAL;
        }
    }
    return dt;
}

void bd_mn_free(bd_sim *sim)
{
    bd_mn *mn = bd_mn_of(sim);
    if (!mn)
        return;
    bd_doubles_free(mn, STATE_DOUBLES, COUNT(STATE_DOUBLES));
    free(mn->contact);
    free(mn->Q);
    free(mn->A);
    free(mn->b);
    free(mn->omega);
    free(mn->q_seen);
    free(mn->frg);
    free(mn->frp);
    free(mn->run_prev);
    free(mn->run_next);
    free(mn);
    sim->belt_data = NULL;
}

void bd_mn_free_model(bd_model *model)
{
    bd_mn_model *mm = model->belt_model;
    if (!mm)
        return;
    bd_doubles_free(mm, MODEL_DOUBLES, COUNT(MODEL_DOUBLES));
    free(mm->kind);
    free(mm->idler_nodes);
    free(mm->on_arc);
    free(mm->pulley);
    free(mm->mover);
    free(mm->eq);
    free(mm->pulleys);
    free(mm);
    model->belt_model = NULL;
}

/* dst's state as a copy of src's (dst owns every pointer once set) */
void bd_mn_clone(bd_sim *dst, const bd_sim *src)
{
    const bd_mn *S = bd_mn_of(src);
    size_t n = (size_t)src->model->n, np = (size_t)src->model->pulley_count;
    bd_mn *mn = bd_xcalloc(1, sizeof *mn);
    dst->belt_data = mn;
    *mn = *S;
    mn->contact = NULL;
    mn->Q = mn->A = mn->b = mn->omega = mn->frg = mn->q_seen = NULL;
    mn->frp = mn->run_prev = mn->run_next = NULL;
    bd_doubles_dup(mn, S, STATE_DOUBLES, COUNT(STATE_DOUBLES), n);
    mn->contact = bd_xdup(S->contact, n, 1);
    mn->Q = bd_xdup(S->Q, np, sizeof *mn->Q);
    mn->A = bd_xdup(S->A, np * np, sizeof *mn->A);
    mn->b = bd_xdup(S->b, np, sizeof *mn->b);
    mn->omega = bd_xdup(S->omega, np, sizeof *mn->omega);
    mn->q_seen = bd_xdup(S->q_seen, np, sizeof *mn->q_seen);
    mn->frg = bd_xdup(S->frg, 3 * n, sizeof *mn->frg);
    mn->frp = bd_xdup(S->frp, 3 * n, sizeof *mn->frp);
    mn->run_prev = bd_xdup(S->run_prev, n, sizeof *mn->run_prev);
    mn->run_next = bd_xdup(S->run_next, n, sizeof *mn->run_next);
}

/* node-steps per second: the cement-plant example as moving_node, 40 s
 * (1291 nodes, 42 517 steps) in 3.4 s on the two-core machine (1.6e7;
 * issue 10's implicit Coriolis force) */
#define MN_RATE 1.6e7

/* what bd_mn_build would make: the layout's node count, and the step of
 * the mean span element (bd_mn_stable_step without the transverse
 * limit, which needs the tensions) */
void bd_mn_estimate(const bd_model_def *def, const bd_path *path, bd_belt_estimate *out)
{
    double lref = mean_span_element(def, path), arcs;
    out->element_length = lref;
    out->nodes = bd_mn_layout_count(def, path, &arcs);
    /* what sets the count, for a refusal's message (sim/estimate.c) */
    if (arcs > out->nodes - arcs) {
        snprintf(out->element_what, sizeof out->element_what,
                 "belt.wrap_element_angle_deg: %g° on the wraps",
                 def->belt.wrap_element_angle / BD_DEG);
        snprintf(out->element_advice, sizeof out->element_advice,
                 "a larger wrap_element_angle_deg");
    } else if (def->belt.span_element_length > 0.0) {
        snprintf(out->element_what, sizeof out->element_what, "belt.span_element_length: %g m",
                 def->belt.span_element_length);
        snprintf(out->element_advice, sizeof out->element_advice, "a longer span_element_length");
    } else {
        snprintf(out->element_what, sizeof out->element_what,
                 "belt.span_element_length (not given: each span's idler spacing, the mean "
                 "element %.3g m)", lref);
        snprintf(out->element_advice, sizeof out->element_advice, "a longer span_element_length");
    }
    out->idlers = 0.0;
    out->node_bytes = (double)(bd_node_arrays_bytes()
                               + (size_t)(COUNT(STATE_DOUBLES) + COUNT(MODEL_DOUBLES) + 2)
                                     * sizeof(double)
                               + 6 * sizeof(int) + 3);
    out->idler_bytes = 0.0;
    double c = sqrt(def->belt.axial_stiffness / def->belt.mass_per_length);
    out->stable_step = bd_central_difference_limit(2.0 * c / lref, 0.0);
    out->rate = MN_RATE;
}
