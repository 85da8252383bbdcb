/* Variable topology (seed 000 §3.1): the rfe belt's free stretches tied
 * into long sections, released before they reach a pulley or an idler
 * curve.
 *
 * Seed 000 ties the belt sections out of contact with the pulleys by
 * fixed constraints into long sections, releases them before they can
 * touch a pulley and carries their idlers as running resistance. Here the
 * long sections stand on windows fixed on the path: stretches of a
 * straight span on its idlers, each from the middle of one bay to the
 * middle of another, up to `group_length` long, at least `margin` clear
 * of the span's pulleys and idler curves. The belt flows through a
 * window: an element is tied as it enters it and free again as it leaves
 * (at the window's end it is then still a margin from the pulley). Two
 * windows may meet; an element then passes from one section to the next.
 *
 * **A section is one belt element of many nodes.** Its elements stand on
 * the line through the idlers' tops, turned along it, evenly spaced from
 * its first to its last: its two degrees of freedom are their places
 * along the line, s1 and s2, and every element between moves with
 * weight ξ = j/(count − 1) (the linear shape function of a two-node
 * element). It keeps the belt's mass (each element's, with its material)
 * and its elasticity: the SDEs inside it are stretched evenly, ½k·x² each
 * as on the free belt, so its stiffness is the series stiffness of the
 * SDEs it stands for, and the tension inside it is theirs. Lagrange's
 * equations in (s1, s2) give the 2×2 mass matrix M = Σ m_j·N_j·N_jᵀ,
 * N_j = (1 − ξ_j, ξ_j), and the forces Σ N_j·(f_j·d) of every force on
 * its elements along the line; across the line and in rotation the
 * idlers hold it (no work). The SDEs between two tied elements have no
 * shear or bending (forces.c), the tied elements no alignment.
 * Waves cross it at √(EA/m′) when long against it (a two-node element's
 * dispersion, as the axial belt's); group_length sets where that stops.
 *
 * **The idlers it carries** (those inside the window more than half an
 * element from the section's ends: with its ends within an element of the
 * window's, in mid-bay at least two elements from any idler, all of them,
 * and no idler passes from contact to being carried or back) turn with
 * the belt (stuck) and
 * resist it by rr·N, N the weight of belt and load they carry normal to
 * the span (sim/running_law.c's share): the model's own law. With the
 * rolls' inertia in the step (central differences, the stick impulse in
 * it),
 *   (M + K)·V⁺ = M·V⁻ + P + Δt·(F − F_rr(V⁻)),
 * K = Σ I/R²·N_k·N_kᵀ, P = Σ (I·ω_k/R)·N_k, each roll then at ω⁺ = v_k⁺/R;
 * the friction that turns it is booked as the contact's friction is (on
 * the belt at v_k, on the roll at ω·R: no work while they roll together).
 * Once its rolls turn with it (every one carried the step before, each at
 * v_k/R), K, P, F_rr, their kinetic energy and the torques' work are
 * quadratic and linear in the idlers' places x_k, so they come in O(1)
 * from the window's sums of I/R², I/R²·x, I/R²·x², c and c·x (c = rr·g·
 * cos δ·share), with the load over each idler the section's mean (the
 * law's uniform load); the rolls' speeds are written when read.
 *
 * **Its step costs O(1)**, not O(count): inside it every SDE pulls its
 * two elements alike, T·d forward and back, so the elements inside feel
 * their weight alone, and Σ N_j·(f_j·d) is the forces on its two ends
 * (the forces phase takes them, with the SDE to the free belt) plus the
 * weight inside from the kept mass matrix. The elements inside are placed
 * when read (bd_rfe_sync, the sensors' points, joins and leaves). A
 * section whose window holds the feed point, or with an idler of its
 * window not carried, is summed element by element (full).
 *
 * **Joining and leaving.** An element leaving at an end keeps its place
 * and velocity, and the section's others keep theirs. An element joining
 * is put on the line where its SDE to the free belt keeps its length,
 * the section's elements are spaced evenly again and its speeds taken
 * from their momentum. The section's new end is turned so that its SDE
 * to the free belt has no shear, and the free belt's turns beside it
 * relax (with an element that leaves likewise); an element that such a
 * turn would set more than JOIN_TURN off the line waits. What that
 * changes in the mechanical energy (the joining element lifted out of
 * its sag by a few millimetres, its speed across the line, the turns) is
 * measured over the elements concerned: a loss is booked as dissipated
 * (an inelastic tie), a gain is paid from the section's motion along its
 * line (pay_gain: a topology change makes no energy), counted from the
 * state the step ends in. The free belt's end bay is held by the
 * section's end at the height of the idler tops, a support in mid-bay:
 * that bay's half sags as a half bay, and the idler nearest that end
 * carries the weight the end holds (end_resistance). docs/physics.md §15
 * has the measurements behind each of these choices. */
#include "belt/rfe/rfe.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "laws/rolling.h"
#include "model/path.h"
#include "parts/parts.h"

/* free elements beyond the half bay beside a section's end whose turns
 * are relaxed when it is first tied (build.c bd_rfe_relax_turns) */
#define RELAX_AROUND 8
/* elements beside an idler its contact reaches, kept as a window is
 * first tied */
#define IDLER_REACH 3
#define RELAX_JOIN 8
/* an element leaves a section this many elements beyond its window's end */
#define LEAVE_BEYOND 0.5
/* the most a joining element may be turned from its section's line, rad.
 * Turned so that its SDE to the free belt has no shear (reflect_turn),
 * a section's end keeps that turn, and the stiff shear (GA = 10·EA) holds
 * the free belt on it: the next element to join comes from below the
 * line by as much, its chord from the line steeper, and the reflection
 * (twice the chord less the free element's own turn) turns the next end
 * further. On generated seed 34 (rfe, filling with load) the ends' turns
 * so grew from 0.04 to 0.56 rad over 12 s, no element joined, and an
 * idler the section's end was carried past pressed on its held elements
 * (docs/physics.md §15). A belt settled in its bays meets a section's end
 * at the slope of a half bay, w·a/(4T) (the sag parabola h = w·a²/(8T)
 * of DIN 22101's sag limit, as belt/lumped/idler_turn.c takes it, on half
 * the span), 0.1 rad at a sag of 5 % of the bay; a belt steeper than that waits, the section ending short. (At
 * 0.05 rad vt_loop's sections drew 2.65 % less running force than its
 * every element free, against 1.61 % at 0.1 and 1.71 % without.) */
#define JOIN_TURN 0.1

/* ------------------------------------------------------------------ */
/* build                                                              */

/* the idlers' shares of their span, as sim/running_law.c takes them:
 * idler i of count at i·spacing carries from the midpoint to the one
 * before to the midpoint to the next (the span's end after the last) */
static void idler_shares(bd_sim *sim, bd_rfe_model *RM)
{
    const bd_model_def *def = sim->model->def;
    RM->idler_share = bd_xcalloc((size_t)sim->model->idler_count + 1, sizeof *RM->idler_share);
    int at = 0;
    for (int k = 0; k < def->idler_set_count; k++) {
        int count = sim->model->idlers_per_set[k];
        double sp = sim->model->idler_spacing[k];
        double p0[2], p1[2];
        bd_sim_span_ends(sim, def->idler_sets[k].span, p0, p1);
        double Ls = hypot(p1[0] - p0[0], p1[1] - p0[1]);
        for (int i = 1; i <= count; i++) {
            double next = i == count ? Ls : (i + 1) * sp;
            RM->idler_share[at++] = 0.5 * (i * sp + next) - (i - 0.5) * sp;
        }
    }
}

/* a point's place along window w's line and above it (the normal to d
 * on the side of positive y) */
static inline double along(const bd_rfe_window *w, double x, double y)
{
    return (x - w->p0[0]) * w->d[0] + (y - w->p0[1]) * w->d[1];
}

/* the bays a set of idlers `bay` apart on a straight span Ls long holds
 * windows in: from the mid-bay point (i0 + ½)·bay to (i1 + ½)·bay, clear
 * of a pulley or a curve by two bays and five elements (the free belt
 * settles into its sag on at least two bays), beside an idler curve the
 * longer of the stretches before and after it; *per: the bays of a window
 * of at most group_length. None (i1 ≤ i0) where half a bay would not keep
 * the idlers clear of an element at a window's end, nor a window hold a
 * few elements (bay < 4·l0), on a vertical span, or on a span with a second
 * row of idlers */
static void window_bays(const bd_model_def *def, const bd_path *path, int k, double bay,
                        double Ls, double l0, int *i0, int *i1, int *per)
{
    const bd_idler_set_def *set = &def->idler_sets[k];
    *i0 = *i1 = 0;
    *per = (int)floor(def->belt.group_length / bay + 1e-9);
    if (*per < 1)
        *per = 1;
    for (int q = 0; q < def->idler_set_count; q++)
        if (q != k && def->idler_sets[q].span == set->span)
            return;
    if (bay < 4.0 * l0 || bd_span_vertical(path, set->span))
        return;
    const double margin = 2.0 * bay + 5.0 * l0;
    double from = 0.0, to = Ls;
    if (set->has_curve) {
        double c0 = set->curve_from * Ls, c1 = set->curve_to * Ls;
        if (c0 >= Ls - c1)
            to = c0;
        else
            from = c1;
    }
    *i0 = (int)ceil((from + margin) / bay - 0.5);
    *i1 = (int)floor((to - margin) / bay - 0.5);
}

/* The kink at a section's ends. The free end bay hangs from a section's
 * end at the slope θ = w·d/(2T) of the sag parabola over d (DIN 22101's,
 * as end_resistance), d = a/2 (θ = φ/4 of the belt's turn
 * φ = w·a/T at an idler; w its weight per metre normal to the span, T
 * less m′v²), and the end holds R = ½·w·d = w·a/4 of it (end_resistance).
 * Each element that joins is lifted the last θ·l0 onto the line against
 * R, and each that leaves drops as much: R·θ·v of power at each end,
 * w²a²v/(16T), whatever the element. A string running over a sharp
 * support does no such work; the joins and leaves do, and where it goes
 * depends on the belt. Measured: on generated seed 8522 (ζ 0.1,
 * 1.67 m/s) it came back to the belt's motion; on 8504 (undamped,
 * 4.68 m/s; its kinks estimated at 6 % of its running resistance) the
 * shear's swing it left was dissipated at the idlers, and its sections
 * drew +5.48 % over its law against +1.46 % with every element free
 * (the return left free: +2.47 %). So a span gets windows
 * only while the kinks at the two ends of its run of sections,
 * w²a²v/(8T), with those of the spans taken before it (least first),
 * cost at most KINK_SHARE_MAX of the running resistance (polygon.c's
 * scale); the others stay free. allowed[k] for idler set k; *kept the
 * share the kept spans' kinks cost, *dropped how many were left free. */
#define KINK_SHARE_MAX 0.01
static void kink_spans(const bd_model_def *def, const bd_path *path, double l0, const double *bays,
                       int *allowed, double *kept, int *dropped)
{
    const int sets = def->idler_set_count;
    *kept = 0.0;
    *dropped = 0;
    double *share = bd_xcalloc((size_t)sets + 1, sizeof *share);
    bd_span_rest *rest = bd_xcalloc((size_t)sets + 1, sizeof *rest);
    bd_lumped_span_rest(def, path, rest);
    const double v = bd_drives_reference_speed(def);
    const double F = bd_lumped_resistance_scale(def, path, v);
    for (int k = 0; k < sets; k++) {
        const bd_span_rest *r = &rest[k];
        const bd_path_segment *sp = bd_path_span(path, def->idler_sets[k].span);
        const double Ls = hypot(sp->p1[0] - sp->p0[0], sp->p1[1] - sp->p0[1]);
        int i0, i1, per;
        window_bays(def, path, k, bays[k], Ls, l0, &i0, &i1, &per);
        allowed[k] = i1 > i0;
        share[k] = 0.0;
        const double tc = r->tension - r->mass_per_length * v * v;
        /* not assessed (kept): no belt laid at rest, or no running
         * resistance to weigh the kink against (every roll frictionless) */
        if (!allowed[k] || r->mass_per_length <= 0.0 || !(F > 0.0))
            continue;
        const double w = r->mass_per_length * def->gravity * r->cos_slope;
        share[k] = tc > 0.0 ? w * w * r->spacing * r->spacing / (8.0 * tc * F) : INFINITY;
    }
    /* least first, while the sum stays within the share */
    for (;;) {
        int best = -1;
        for (int k = 0; k < sets; k++)
            if (allowed[k] == 1 && (best < 0 || share[k] < share[best]))
                best = k;
        if (best < 0)
            break;
        if (*kept + share[best] <= KINK_SHARE_MAX) {
            *kept += share[best];
            allowed[best] = 2;
        } else {
            allowed[best] = 0;
            (*dropped)++;
        }
    }
    for (int k = 0; k < sets; k++)
        allowed[k] = allowed[k] == 2;
    free(rest);
    free(share);
}

/* the windows of idler set k's span (window_bays), in windows of at most
 * group_length */
static int set_windows(bd_sim *sim, int k, bd_rfe_window *out, int room)
{
    const bd_model_def *def = sim->model->def;
    const int span = def->idler_sets[k].span;
    const double bay = sim->model->idler_spacing[k], l0 = sim->model->l0;
    if (sim->model->idlers_per_set[k] == 0)
        return 0;
    double p0[2], p1[2];
    bd_sim_span_ends(sim, span, p0, p1);
    double Ls = hypot(p1[0] - p0[0], p1[1] - p0[1]);
    int i0, i1, per;
    window_bays(def, &sim->model->path, k, bay, Ls, l0, &i0, &i1, &per);
    int made = 0;
    for (int i = i0; i + 1 <= i1 && made < room;) {
        int j = i + per <= i1 ? i + per : i1;
        bd_rfe_window *w = &out[made];
        /* indices within `out`; made absolute by the caller */
        w->before = made > 0 ? made - 1 : -1;
        w->after = -1;
        if (made > 0)
            out[made - 1].after = made;
        made++;
        w->p0[0] = p0[0];
        w->p0[1] = p0[1];
        w->d[0] = (p1[0] - p0[0]) / Ls;
        w->d[1] = (p1[1] - p0[1]) / Ls;
        w->cos_slope = fabs(w->d[0]);
        w->a = (i + 0.5) * bay;
        w->bay = bay;
        w->b = (j + 0.5) * bay;
        i = j;
    }
    return made;
}

double bd_rfe_windows_estimate(const bd_model_def *def, const bd_path *path, double l0,
                               double *windows)
{
    *windows = 0.0;
    if (!def->belt.group_sections || def->belt.group_length <= 0.0)
        return 0.0;
    double tied = 0.0, kept;
    int dropped;
    int *allowed = bd_xcalloc((size_t)def->idler_set_count + 1, sizeof *allowed);
    double *bays = bd_xcalloc((size_t)def->idler_set_count + 1, sizeof *bays);
    for (int k = 0; k < def->idler_set_count; k++)
        bays[k] = def->idler_sets[k].spacing;
    kink_spans(def, path, l0, bays, allowed, &kept, &dropped);
    free(bays);
    for (int k = 0; k < def->idler_set_count; k++) {
        if (!allowed[k])
            continue;
        const double bay = def->idler_sets[k].spacing;
        const bd_path_segment *sp = bd_path_span(path, def->idler_sets[k].span);
        double Ls = hypot(sp->p1[0] - sp->p0[0], sp->p1[1] - sp->p0[1]);
        int i0, i1, per;
        window_bays(def, path, k, bay, Ls, l0, &i0, &i1, &per);
        if (i1 <= i0)
            continue;
        tied += (i1 - i0) * bay;
        *windows += ceil((i1 - i0) / (double)per);
    }
    free(allowed);
    return tied;
}

void bd_rfe_sections_build(bd_sim *sim, bd_rfe_model *RM)
{
    const bd_model_def *def = sim->model->def;
    const int ni = sim->model->idler_count;
    idler_shares(sim, RM);
    RM->window_count = 0;
    RM->windows = NULL;
    RM->idler_window = bd_xcalloc((size_t)ni + 1, sizeof *RM->idler_window);
    RM->idler_list = bd_xcalloc((size_t)ni + 1, sizeof *RM->idler_list);
    RM->idler_along = bd_xcalloc((size_t)ni + 1, sizeof *RM->idler_along);
    for (int i = 0; i < ni; i++)
        RM->idler_window[i] = -1;
    if (!def->belt.group_sections || def->belt.group_length <= 0.0)
        return;
    /* at most a window per idler */
    RM->windows = bd_xcalloc((size_t)ni + 1, sizeof *RM->windows);
    int *allowed = bd_xcalloc((size_t)def->idler_set_count + 1, sizeof *allowed);
    kink_spans(def, &sim->model->path, sim->model->l0, sim->model->idler_spacing, allowed,
               &RM->kink_share, &RM->kink_free_spans);
    for (int k = 0; k < def->idler_set_count; k++) {
        if (!allowed[k])
            continue;
        int base = RM->window_count;
        int made = set_windows(sim, k, RM->windows + base, ni - base);
        for (int w = base; w < base + made; w++) {
            bd_rfe_window *W = &RM->windows[w];
            W->before = W->before >= 0 ? W->before + base : -1;
            W->after = W->after >= 0 ? W->after + base : -1;
        }
        RM->window_count += made;
    }
    free(allowed);
    /* the idlers inside each window, in their order along it */
    int listed = 0;
    for (int w = 0; w < RM->window_count; w++) {
        bd_rfe_window *W = &RM->windows[w];
        W->idler_first = listed;
        for (int i = 0; i < ni; i++) {
            const bd_idler *id = &sim->idlers[i];
            double a = along(W, id->tr.p[0], id->tr.p[1]);
            double off = (id->tr.p[1] - W->p0[1]) * W->d[0] - (id->tr.p[0] - W->p0[0]) * W->d[1];
            if (a > W->a && a < W->b && fabs(off) < 1e-6 * (1.0 + W->b) && RM->idler_window[i] < 0) {
                RM->idler_window[i] = w;
                RM->idler_along[i] = a;
                RM->idler_list[listed++] = i;
            }
        }
        W->idler_count = listed - W->idler_first;
        /* the sums that carry its idlers while its rolls turn with it
         * (bd_rfe_supports) */
        W->k0 = W->k1 = W->k2 = W->c0 = W->c1 = 0.0;
        W->along_min = W->b;
        W->along_max = W->a;
        W->idler_lo = W->idler_hi = -1;
        for (int q = W->idler_first; q < listed; q++) {
            int i = RM->idler_list[q];
            const bd_idler_model *im = sim->idlers[i].m;
            double x = RM->idler_along[i] - W->a, kr = im->inertia / (im->radius * im->radius);
            double c = im->rolling * sim->model->gravity * W->cos_slope * RM->idler_share[i];
            W->k0 += kr;
            W->k1 += kr * x;
            W->k2 += kr * x * x;
            W->c0 += c;
            W->c1 += c * x;
            if (RM->idler_along[i] < W->along_min) {
                W->along_min = RM->idler_along[i];
                W->idler_lo = i;
            }
            if (RM->idler_along[i] > W->along_max) {
                W->along_max = RM->idler_along[i];
                W->idler_hi = i;
            }
        }
        /* the loading zone (a bay either side of the feed point): mass
         * lands there every step, the skirts rub */
        if (def->material.present) {
            const double *f = sim->feed.p;
            double a = along(W, f[0], f[1]);
            double off = (f[1] - W->p0[1]) * W->d[0] - (f[0] - W->p0[0]) * W->d[1];
            W->has_feed = a > W->a - W->bay && a < W->b + W->bay && fabs(off) < 0.5 * W->bay;
        }
    }
}

void bd_rfe_sections_alloc(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const size_t n = (size_t)sim->model->n;
    R->sec = bd_xcalloc(n, sizeof *R->sec);
    for (size_t i = 0; i < n; i++)
        R->sec[i] = -1;
    R->sections = bd_xcalloc((size_t)RM->window_count + 1, sizeof *R->sections);
    R->carried = bd_xcalloc((size_t)sim->model->idler_count + 1, sizeof *R->carried);
    R->free_idlers = bd_xcalloc((size_t)sim->model->idler_count + 1, sizeof *R->free_idlers);
    R->idlers_stale = 1;
    for (int i = 0; i < sim->model->idler_count; i++)
        R->carried[i] = -1;
    R->run_first = bd_xcalloc(n, sizeof *R->run_first);
    R->run_count = bd_xcalloc(n, sizeof *R->run_count);
    R->run_first[0] = 0;
    R->run_count[0] = (int)n;
    R->run_n = 1;
    R->live_first = bd_xcalloc(n, sizeof *R->live_first);
    R->live_count = bd_xcalloc(n, sizeof *R->live_count);
    R->live_stale = 1;
    R->order = bd_xcalloc((size_t)RM->window_count + 1, sizeof *R->order);
    R->belt_dof_min = R->belt_dof_max = 3 * (int)n;
}

void bd_rfe_sections_free(bd_rfe *R)
{
    free(R->sec);
    free(R->sections);
    free(R->carried);
    free(R->free_idlers);
    free(R->run_first);
    free(R->run_count);
    free(R->live_first);
    free(R->live_count);
    free(R->order);
}

void bd_rfe_sections_free_model(bd_rfe_model *RM)
{
    free(RM->windows);
    free(RM->idler_list);
    free(RM->idler_window);
    free(RM->idler_share);
    free(RM->idler_along);
}

void bd_rfe_sections_clone(bd_sim *dst, const bd_sim *src)
{
    bd_rfe *D = bd_rfe_of(dst);
    const bd_rfe *S = bd_rfe_of(src);
    const size_t n = (size_t)src->model->n;
    D->sec = bd_xdup(S->sec, n, sizeof *D->sec);
    D->sections = bd_xdup(S->sections, (size_t)bd_rfe_model_of(src)->window_count + 1,
                          sizeof *D->sections);
    D->carried = bd_xdup(S->carried, (size_t)src->model->idler_count + 1, sizeof *D->carried);
    D->free_idlers = bd_xdup(S->free_idlers, (size_t)src->model->idler_count + 1,
                             sizeof *D->free_idlers);
    D->free_idler_n = S->free_idler_n;
    D->idlers_stale = S->idlers_stale;
    D->run_first = bd_xdup(S->run_first, n, sizeof *D->run_first);
    D->run_count = bd_xdup(S->run_count, n, sizeof *D->run_count);
    D->live_first = bd_xdup(S->live_first, n, sizeof *D->live_first);
    D->live_count = bd_xdup(S->live_count, n, sizeof *D->live_count);
    D->live_n = S->live_n;
    D->live_stale = S->live_stale;
    D->order = bd_xdup(S->order, (size_t)bd_rfe_model_of(src)->window_count + 1,
                       sizeof *D->order);
    D->tied = S->tied;
    D->run_n = S->run_n;
    D->joined = S->joined;
    D->left = S->left;
    D->booked_lost = S->booked_lost;
    D->booked_gained = S->booked_gained;
    D->belt_dof_min = S->belt_dof_min;
    D->belt_dof_max = S->belt_dof_max;
}

/* ------------------------------------------------------------------ */
/* the step                                                           */

static inline int last_of(const bd_rfe_section *S, int n)
{
    int l = S->first + S->count - 1;
    return l >= n ? l - n : l;
}

/* whether the step sums section S from its ends and its mass alone
 * (carry): inside it, the forces phase takes no node */
static inline int aggregated(const bd_rfe_section *S)
{
    return S->count >= 3 && !S->full;
}

static inline void ensure_placed(bd_sim *sim, int w);

/* an affine function of an idler's place x (from its window's start a):
 * f0 + f1·x */
typedef bd_rfe_affine affine;

/* Σ kr·f(x)·g(x) over the window's idlers, from its sums */
static inline double kr_sum(const bd_rfe_window *W, affine f, affine g)
{
    return f.f0 * g.f0 * W->k0 + (f.f0 * g.f1 + f.f1 * g.f0) * W->k1 + f.f1 * g.f1 * W->k2;
}

/* ξ of an idler at x in a section whose ends stand at s1, s2 */
static inline affine weight_at(const bd_rfe_window *W, double s1, double s2)
{
    double inv = 1.0 / (s2 - s1);
    return (affine){(W->a - s1) * inv, inv};
}

/* a point's speed along the line, v1 + ξ·(v2 − v1), for ξ = w */
static inline affine speed_at(affine w, double v1, double v2)
{
    return (affine){v1 + w.f0 * (v2 - v1), w.f1 * (v2 - v1)};
}

/* a carried idler's tracker: the element of section S over it, at its
 * weight xi in the section */
static inline void carried_tracker(const bd_sim *sim, const bd_rfe_section *S, double xi,
                                   bd_tracker *tr)
{
    const int n = sim->model->n;
    double at = xi * (S->count - 1);
    int j = (int)at, e = S->first + j;
    tr->element = e >= n ? e - n : e;
    tr->gamma = at - j;
}

/* section w's rolls written out from where they stand in it: each at
 * ω = v(ξ)/R of last step's ξ and its speeds now, its tracker over the
 * element there (once after each step that kept them: rolls_written) */
static void write_rolls(bd_sim *sim, int w)
{
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const bd_rfe_window *W = &RM->windows[w];
    bd_rfe_section *S = &bd_rfe_of(sim)->sections[w];
    if (S->rolls_written)
        return;
    for (int q = 0; q < W->idler_count; q++) {
        int i = RM->idler_list[W->idler_first + q];
        bd_idler *id = &sim->idlers[i];
        double xp = (RM->idler_along[i] - S->s1p) / (S->s2p - S->s1p);
        id->omega = (S->v1 + xp * (S->v2 - S->v1)) / id->m->radius;
        carried_tracker(sim, S, (RM->idler_along[i] - S->s1) / (S->s2 - S->s1), &id->tr);
    }
    S->rolls_written = 1;
}

/* section w's rolls given back to the parts (before anything changes the
 * section between steps, or it stops carrying them all) */
static void unstick(bd_sim *sim, int w)
{
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const bd_rfe_window *W = &RM->windows[w];
    bd_rfe_section *S = &bd_rfe_of(sim)->sections[w];
    if (S->lazy_idlers) {
        write_rolls(sim, w);
        for (int q = 0; q < W->idler_count; q++)
            sim->idlers[RM->idler_list[W->idler_first + q]].lazy = 0;
        S->lazy_idlers = 0;
    }
    S->stuck = 0;
}

/* idler i carried by section w (or none: −1), the list of the idlers
 * pressing on the belt then rebuilt (bd_rfe_supports) */
static inline void set_carried(bd_rfe *R, int i, int w)
{
    if (R->carried[i] != w) {
        R->carried[i] = w;
        R->idlers_stale = 1;
    }
}

/* the forces phase: which idlers each section carries (those of its
 * window more than half an element inside its ends: all of them while its
 * ends stand within an element of the window's, in mid-bay, half a bay of
 * at least four elements from the nearest idler; with two elements the
 * first element joining a little over one element inside its window, the
 * chord from the sagging free belt, left the nearest idler out, a quarter
 * of the cement plant's sections summed element by element at speed;
 * should the belt not join it, an element too far off the
 * line, the idlers beyond its ends press on the free belt again), and
 * whether it is summed element by element (full): the feed in its window,
 * or an idler of its window pressing on it. Else only its ends take
 * forces: an idler outside its window stands at least half a bay less
 * half an element (LEAVE_BEYOND) from its end, 1.5 elements or more, and
 * its contact's three nodes (idler_contact.c) reach its end, not the
 * element inside it; on the quintic line (nine elements or more to a bay)
 * it stands four elements or more from the end, and its six nodes reach
 * three. */
static void carry(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const double l0 = sim->model->l0;
    for (int w = 0; w < RM->window_count; w++) {
        const bd_rfe_window *W = &RM->windows[w];
        bd_rfe_section *S = &R->sections[w];
        const int *list = RM->idler_list + W->idler_first;
        int full = W->has_feed;
        if (S->count < 2) {
            for (int q = 0; q < W->idler_count; q++)
                set_carried(R, list[q], -1);
        } else if (W->idler_count > 0) {
            /* an idler's weight ξ: where it stands between the section's
             * first and last element; the window's first and last idler
             * inside it, all are (ξ grows along the window) */
            const double inv = 1.0 / (S->s2 - S->s1), inner = 0.5 * l0 * inv;
            double x0 = (W->along_min - S->s1) * inv, x1 = (W->along_max - S->s1) * inv;
            if (x0 >= inner && 1.0 - x1 >= inner) {
                if (R->carried[list[0]] != w || R->carried[list[W->idler_count - 1]] != w)
                    for (int q = 0; q < W->idler_count; q++)
                        set_carried(R, list[q], w);
            } else {
                full = 1;
                for (int q = 0; q < W->idler_count; q++) {
                    double xi = (RM->idler_along[list[q]] - S->s1) * inv;
                    set_carried(R, list[q], xi < inner || 1.0 - xi < inner ? -1 : w);
                }
            }
        }
        if (full != S->full) {
            S->full = full;
            R->live_stale = 1;
            /* the forces phase takes its every element from now on, and
             * an idler of it presses on it */
            ensure_placed(sim, w);
            unstick(sim, w);
        }
    }
}

/* the tied sections round the loop, by their first element */
static int loop_order(bd_rfe *R, int windows, int aggregated_only)
{
    int k = 0;
    for (int w = 0; w < windows; w++) {
        const bd_rfe_section *S = &R->sections[w];
        if (aggregated_only ? S->count < 3 || S->full : S->count < 1)
            continue;
        /* insertion: the order changes little from call to call */
        int at = k++;
        while (at > 0 && R->sections[R->order[at - 1]].first > S->first) {
            R->order[at] = R->order[at - 1];
            at--;
        }
        R->order[at] = w;
    }
    return k;
}

/* the nodes the forces phase takes, in runs: everything but the inside of
 * a section summed from its ends (more than two elements, not full); a
 * run from one such section's last element to the next one's first */
static void live_runs(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    const int n = sim->model->n;
    int k = loop_order(R, bd_rfe_model_of(sim)->window_count, 1);
    R->live_n = 0;
    if (k == 0) {
        R->live_first[0] = 0;
        R->live_count[0] = n;
        R->live_n = 1;
        return;
    }
    for (int q = 0; q < k; q++) {
        const bd_rfe_section *S = &R->sections[R->order[q]];
        const bd_rfe_section *N = &R->sections[R->order[(q + 1) % k]];
        int a = last_of(S, n);
        R->live_first[R->live_n] = a;
        R->live_count[R->live_n++] = (N->first - a + n) % n + 1;
    }
}

void bd_rfe_sections_forces(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    carry(sim);
    if (R->live_stale) {
        live_runs(sim);
        R->live_stale = 0;
    }
    bd_lumped_forces_runs(sim, R->live_first, R->live_count, R->live_n);
}

/* The free belt beside a section's end hangs from it: the end, held on
 * the line at the idlers' height, is a support of no rolling resistance,
 * and it holds half the weight of the free stretch from it to the next
 * idler outside (a string between two supports at one height, the sag
 * parabola h = w·d²/(8T) of DIN 22101's sag limit, as
 * belt/lumped/idler_turn.c takes it; seed 8522,
 * 32 m, its return's bays sagging 5 %: 48–142 N at each of its four
 * outer ends, measured as the forces across the line on them, and 2.3 %
 * of its running force missing). On a belt free everywhere the idlers
 * carry it, so the section's idler next to that end does: rr·½·w·d, w
 * the free belt's weight per length normal to the span, d that stretch.
 * The static weight, not the force measured on the end: that is the stiff
 * shear's too, swinging by kilonewtons at its own frequency on an
 * undamped belt (generated seed 8504: 1.7–5.3 kN rms about a mean of
 * 44–253 N), and a roll's resistance, which cannot pull, would rectify
 * it. None where the next section meets this one (its end the adjacent
 * element: no free stretch). Idler i (carried by S, its place `at` along
 * the line; none: −1) is next to the section's first end if that end lies
 * less than a bay before it (the window's idlers stand a bay apart, so
 * none is between), likewise for the last; sat the sign of the belt's
 * speed over it (saturated, idler.c). */
static inline void end_resistance(const bd_sim *sim, const bd_rfe_window *W, bd_rfe_section *S,
                                  int i, double sat)
{
    if (i < 0)
        return;
    const bd_rfe *R = bd_rfe_of(sim);
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const int n = sim->model->n;
    const double at = RM->idler_along[i];
    double d = 0.0;
    int outside = -1;
    if (at >= S->s1 && at - S->s1 < W->bay) {
        outside = bd_node_prev(S->first, n);
        if (R->sec[outside] < 0)
            d += S->s1 - (at - W->bay);
    }
    if (at <= S->s2 && S->s2 - at < W->bay) {
        outside = bd_node_next(last_of(S, n), n);
        if (R->sec[outside] < 0)
            d += at + W->bay - S->s2;
    }
    if (!(d > 0.0))
        return;
    const double w = sim->model->gravity * W->cos_slope * sim->mass[outside] / sim->model->l0;
    const double fr = sim->idlers[i].m->rolling * 0.5 * w * d * sat;
    const double xi = (at - S->s1) / (S->s2 - S->s1);
    S->f1 += (1.0 - xi) * fr;
    S->f2 += xi * fr;
}

/* the supports phase: the idlers the sections carry (their sums for the
 * step; which they are the forces phase found, carry), every other idler
 * pressing on the belt as on the lumped belt */
void bd_rfe_supports(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    if (!R->tied) {
        bd_lumped_idlers(sim);
        return;
    }
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const double g = sim->model->gravity, inv_l0 = 1.0 / sim->model->l0;
    for (int w = 0; w < RM->window_count; w++) {
        const bd_rfe_window *W = &RM->windows[w];
        bd_rfe_section *S = &R->sections[w];
        S->k11 = S->k12 = S->k22 = S->p1 = S->p2 = S->f1 = S->f2 = 0.0;
        S->idler_sums = 0;
        if (S->count < 2)
            continue;
        /* Its rolls turning with it, the belt over them rolling one way:
         * the same sums from the window's, in O(1) (kr_sum). The load over
         * each idler is then the section's mean, m̄ = Σm/(count·l0), the
         * running law's uniform load (where a load front stands in the
         * section, its mean). The rolls are the section's until it
         * changes (unstick): the parts leave them. */
        const double vr = BD_ROLLING_SPEED;
        if (aggregated(S) && S->stuck
            && ((S->v1 >= vr && S->v2 >= vr) || (S->v1 <= -vr && S->v2 <= -vr))) {
            S->idler_sums = 1;
            if (!S->lazy_idlers) {
                for (int q = 0; q < W->idler_count; q++)
                    sim->idlers[RM->idler_list[W->idler_first + q]].lazy = 1;
                S->lazy_idlers = 1;
                S->rolls_written = 0;
            }
            affine xi = weight_at(W, S->s1, S->s2), xj = {1.0 - xi.f0, -xi.f1};
            /* ω⁻·R of each roll: last step's ξ, this step's speeds */
            affine wm = speed_at(weight_at(W, S->s1p, S->s2p), S->v1, S->v2);
            S->xi = xi;
            S->wm = wm;
            S->k11 = kr_sum(W, xj, xj);
            S->k12 = kr_sum(W, xj, xi);
            S->k22 = kr_sum(W, xi, xi);
            S->p1 = kr_sum(W, wm, xj);
            S->p2 = kr_sum(W, wm, xi);
            double mbar = S->mbar;
            double f = (S->v1 > 0.0 ? 1.0 : -1.0) * mbar;
            S->f1 = f * (xj.f0 * W->c0 + xj.f1 * W->c1);
            S->f2 = f * (xi.f0 * W->c0 + xi.f1 * W->c1);
            const double sat = S->v1 > 0.0 ? 1.0 : -1.0;
            end_resistance(sim, W, S, W->idler_lo, sat);
            if (W->idler_hi != W->idler_lo)
                end_resistance(sim, W, S, W->idler_hi, sat);
            continue;
        }
        /* else roll by roll: their speeds from the section first */
        if (S->lazy_idlers)
            unstick(sim, w);
        for (int q = 0; q < W->idler_count; q++) {
            int i = RM->idler_list[W->idler_first + q];
            if (R->carried[i] != w)
                continue;
            bd_idler *id = &sim->idlers[i];
            const bd_idler_model *im = id->m;
            double xi = (RM->idler_along[i] - S->s1) / (S->s2 - S->s1), xj = 1.0 - xi;
            /* its contact let go (its spring's energy to 0) */
            bd_lumped_idler_release(sim, i);
            /* its tracker: the element over it, from the section */
            carried_tracker(sim, S, xi, &id->tr);
            /* the belt and load over it */
            double m = sim->mass[id->tr.element] * inv_l0;
            double N = g * W->cos_slope * m * RM->idler_share[i];
            double v = xj * S->v1 + xi * S->v2;
            double sat = v * (1.0 / BD_ROLLING_SPEED);
            sat = sat > 1.0 ? 1.0 : sat < -1.0 ? -1.0 : sat;
            double fr = im->rolling * N * sat;
            double kr = im->inertia / (im->radius * im->radius);
            double pr = im->inertia * id->omega / im->radius;
            S->f1 += xj * fr;
            S->f2 += xi * fr;
            S->k11 += kr * xj * xj;
            S->k12 += kr * xj * xi;
            S->k22 += kr * xi * xi;
            S->p1 += pr * xj;
            S->p2 += pr * xi;
            end_resistance(sim, W, S, i, sat);
        }
    }
    /* the idlers no section carries press on the belt */
    if (R->idlers_stale) {
        R->free_idler_n = 0;
        for (int i = 0; i < sim->model->idler_count; i++)
            if (R->carried[i] < 0)
                R->free_idlers[R->free_idler_n++] = i;
        R->idlers_stale = 0;
    }
    for (int k = 0; k < R->free_idler_n; k++)
        bd_tracker_update(sim, &sim->idlers[R->free_idlers[k]].tr);
    bd_lumped_idlers_listed(sim, R->free_idlers, R->free_idler_n);
}

/* the section's mass matrix: Σ m_j·N_j·N_jᵀ, kept in it */
static void mass_matrix(const bd_sim *sim, bd_rfe_section *S)
{
    const int n = sim->model->n;
    const double inv = 1.0 / (S->count - 1);
    double a = 0.0, b = 0.0, c = 0.0;
    for (int q = 0, i = S->first; q < S->count; q++, i = bd_node_next(i, n)) {
        double xi = q * inv, xj = 1.0 - xi, m = sim->mass[i];
        a += m * xj * xj;
        b += m * xj * xi;
        c += m * xi * xi;
    }
    S->m11 = a;
    S->m12 = b;
    S->m22 = c;
    S->mbar = (a + 2.0 * b + c) / (S->count * sim->model->l0);
}


/* element q of section S (on window W) where the section's ends are, at
 * its velocity; inside a section summed from its ends, the SDE after it
 * takes the tension and dashpot force of the section's first (the forces
 * phase took only those at its ends: all are stretched alike) */
static inline void place_one(bd_sim *sim, const bd_rfe_window *W, const bd_rfe_section *S, int q,
                             int i, double inv)
{
    const double xi = q * inv;
    const double s = S->s1 + xi * (S->s2 - S->s1), v = S->v1 + xi * (S->v2 - S->v1);
    sim->x[i] = W->p0[0] + s * W->d[0];
    sim->y[i] = W->p0[1] + s * W->d[1];
    sim->vx[i] = v * W->d[0];
    sim->vy[i] = v * W->d[1];
    if (aggregated(S) && q > 0 && q + 2 < S->count) {
        bd_lumped *L = &bd_rfe_of(sim)->lumped;
        sim->tension[i] = sim->tension[S->first];
        L->td[i] = L->td[S->first];
    }
}

/* the section's elements where its ends are, at their velocities */
static void place(bd_sim *sim, const bd_rfe_window *W, bd_rfe_section *S)
{
    const int n = sim->model->n;
    const double inv = 1.0 / (S->count - 1);
    for (int q = 0, i = S->first; q < S->count; q++, i = bd_node_next(i, n))
        place_one(sim, W, S, q, i, inv);
    S->placed = 1;
}

/* in the step, a section summed from its ends: its two elements at
 * either end (the forces phase and the idler contacts beside it read
 * them), the others when read */
static void place_ends(bd_sim *sim, const bd_rfe_window *W, bd_rfe_section *S)
{
    const int n = sim->model->n;
    const int last = last_of(S, n);
    const double inv = 1.0 / (S->count - 1);
    place_one(sim, W, S, 0, S->first, inv);
    place_one(sim, W, S, 1, bd_node_next(S->first, n), inv);
    place_one(sim, W, S, S->count - 2, bd_node_prev(last, n), inv);
    place_one(sim, W, S, S->count - 1, last, inv);
    S->placed = 0;
}

static inline void ensure_placed(bd_sim *sim, int w)
{
    bd_rfe_section *S = &bd_rfe_of(sim)->sections[w];
    if (S->count >= 2 && !S->placed)
        place(sim, &bd_rfe_model_of(sim)->windows[w], S);
}

void bd_rfe_sync(bd_sim *sim)
{
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    if (!bd_rfe_of(sim)->tied)
        return;
    for (int w = 0; w < RM->window_count; w++) {
        ensure_placed(sim, w);
        if (bd_rfe_of(sim)->sections[w].lazy_idlers)
            write_rolls(sim, w);
    }
}

/* elements from SENSOR_REACH before a sensor's element to SENSOR_REACH
 * after it placed, if tied: what bd_tracker_update walks in a step (the
 * belt moves less than an element) and the sample reads */
#define SENSOR_REACH 3

void bd_rfe_point_update(const bd_sim *sim_c, bd_tracker *tr)
{
    /* the sensors see the belt through its elements' places (belt.h); a
     * section's are written here, as bd_rfe_sync writes them */
    bd_sim *sim = (bd_sim *)sim_c;
    const bd_rfe *R = bd_rfe_of(sim);
    if (R->tied) {
        const int n = sim->model->n;
        int i = (tr->element - SENSOR_REACH + n) % n;
        for (int k = 0; k <= 2 * SENSOR_REACH + 1; k++, i = bd_node_next(i, n)) {
            int w = R->sec[i];
            if (w < 0 || R->sections[w].placed)
                continue;
            const bd_rfe_section *S = &R->sections[w];
            place_one(sim, &bd_rfe_model_of(sim)->windows[w], S, (i - S->first + n) % n, i,
                      1.0 / (S->count - 1));
        }
    }
    bd_tracker_update(sim, tr);
}

/* the integrate phase for the sections: each to t + Δt/2 with its rolls
 * (above), its elements with it; twice its kinetic energy into *ke and the
 * work of its non-conservative forces into *w_nc (both summed by the
 * caller) */
void bd_rfe_sections_move(bd_sim *sim, double *ke_out, double *w_nc_out)
{
    bd_rfe *R = bd_rfe_of(sim);
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const int n = sim->model->n;
    const double dt = sim->model->dt, inv_dt = 1.0 / dt, g = sim->model->gravity;
    double ke = 0.0, w_nc = 0.0, ke_rolls = 0.0, w_rolls = 0.0;
    for (int w = 0; w < RM->window_count; w++) {
        const bd_rfe_window *W = &RM->windows[w];
        bd_rfe_section *S = &R->sections[w];
        if (S->count < 2)
            continue;
        const double dx = W->d[0], dy = W->d[1], inv = 1.0 / (S->count - 1);
        double F1 = 0.0, F2 = 0.0, N1 = 0.0, N2 = 0.0, m11 = 0.0, m12 = 0.0, m22 = 0.0;
        if (aggregated(S)) {
            /* inside it every SDE pulls alike, T·d forward and back: the
             * elements inside feel their weight alone, and the SDEs next
             * to its ends pull the ends (their forces, with the free
             * belt's, the forces phase summed); ξ = 0 at its first, 1 at
             * its last, so Σ (1 − ξ)·m over the inside is m11 + m12 less
             * its first's m, and Σ ξ·m is m12 + m22 less its last's */
            const int a = S->first, b = last_of(S, n);
            const double gd = -g * dy;
            m11 = S->m11;
            m12 = S->m12;
            m22 = S->m22;
            F1 = sim->fx[a] * dx + sim->fy[a] * dy + gd * (m11 + m12 - sim->mass[a]);
            F2 = sim->fx[b] * dx + sim->fy[b] * dy + gd * (m12 + m22 - sim->mass[b]);
            N1 = sim->fnx[a] * dx + sim->fny[a] * dy;
            N2 = sim->fnx[b] * dx + sim->fny[b] * dy;
        } else {
            /* full: every element's force along the line, weighted */
            for (int q = 0, i = S->first; q < S->count; q++, i = bd_node_next(i, n)) {
                double xi = q * inv, xj = 1.0 - xi, m = sim->mass[i];
                double f = sim->fx[i] * dx + sim->fy[i] * dy;
                double fn = sim->fnx[i] * dx + sim->fny[i] * dy;
                F1 += xj * f;
                F2 += xi * f;
                N1 += xj * fn;
                N2 += xi * fn;
                m11 += m * xj * xj;
                m12 += m * xj * xi;
                m22 += m * xi * xi;
            }
        }
        /* (M + K)·V⁺ = M·V⁻ + P + Δt·(F − F_rr) */
        double a11 = m11 + S->k11, a12 = m12 + S->k12, a22 = m22 + S->k22;
        double r1 = m11 * S->v1 + m12 * S->v2 + S->p1 + dt * (F1 - S->f1);
        double r2 = m12 * S->v1 + m22 * S->v2 + S->p2 + dt * (F2 - S->f2);
        double det = a11 * a22 - a12 * a12;
        double u1 = (a22 * r1 - a12 * r2) / det, u2 = (a11 * r2 - a12 * r1) / det;
        double h1 = 0.5 * (S->v1 + u1), h2 = 0.5 * (S->v2 + u2);
        ke += m11 * h1 * h1 + 2.0 * m12 * h1 * h2 + m22 * h2 * h2;
        w_nc += (N1 - S->f1) * h1 + (N2 - S->f2) * h2;
        /* the rolls' stick: the torque that brings each to v_k⁺/R (idler.c
         * advances it and books its work at ω), its friction on the belt
         * against it at v_k; the rolls the section keeps (idler_sums),
         * their energy and work here from the window's sums: each roll's
         * kinetic energy ½kr·(½(w⁻ + w⁺))², the torque's work on it
         * ½kr·(w⁺² − w⁻²) and on the belt −kr·(w⁺ − w⁻)·h(ξ), w = ω·R */
        if (S->idler_sums) {
            const affine xi = S->xi, wm = S->wm;
            affine wp = speed_at(xi, u1, u2), hb = speed_at(xi, h1, h2);
            affine dw = {wp.f0 - wm.f0, wp.f1 - wm.f1};
            affine mid = {0.5 * (wp.f0 + wm.f0), 0.5 * (wp.f1 + wm.f1)};
            ke_rolls += 0.5 * kr_sum(W, mid, mid);
            w_rolls += kr_sum(W, dw, mid);
            w_nc -= kr_sum(W, dw, hb) * inv_dt;
        } else {
            for (int q = 0; q < W->idler_count; q++) {
                int i = RM->idler_list[W->idler_first + q];
                if (R->carried[i] != w)
                    continue;
                bd_idler *id = &sim->idlers[i];
                double xi = (RM->idler_along[i] - S->s1) / (S->s2 - S->s1), xj = 1.0 - xi;
                double Rr = id->m->radius;
                double torque = id->m->inertia * ((xj * u1 + xi * u2) / Rr - id->omega) * inv_dt;
                id->torque = torque;
                id->alpha = torque * id->m->inv_inertia;
                w_nc -= torque / Rr * (xj * h1 + xi * h2);
            }
        }
        /* every roll of its window carried this step: each at v(ξ)/R now,
         * ξ from where its ends stood (supports) */
        S->stuck = !S->full;
        S->rolls_written = 0;
        S->s1p = S->s1;
        S->s2p = S->s2;
        S->v1 = u1;
        S->v2 = u2;
        S->s1 += u1 * dt;
        S->s2 += u2 * dt;
        if (aggregated(S))
            place_ends(sim, W, S);
        else
            place(sim, W, S);
    }
    *ke_out += 0.5 * ke + ke_rolls;
    *w_nc_out += w_nc * dt + w_rolls;
}

/* ------------------------------------------------------------------ */
/* joining and leaving                                                */

/* the free nodes' runs round the loop (the step moves them), each
 * between two tied elements; all of it one run when none is tied. From
 * the sections in loop order, O(sections) (a join or leave calls it,
 * several times a step on a long belt): the gaps between them, the first
 * after the section that holds the lowest tied index (as a scan from node
 * 0 would find them, so sums over runs keep their order) */
static void free_runs(bd_rfe *R, int windows, int n)
{
    R->run_n = 0;
    int k = loop_order(R, windows, 0);
    if (k == 0) {
        R->run_first[0] = 0;
        R->run_count[0] = n;
        R->run_n = 1;
        return;
    }
    /* sorted by first: the lowest tied index is 0 in the last section if
     * that one wraps past node n − 1, else the first section's first */
    const bd_rfe_section *L = &R->sections[R->order[k - 1]];
    int start = L->first + L->count > n ? k - 1 : 0;
    for (int q = 0; q < k; q++) {
        const bd_rfe_section *S = &R->sections[R->order[(start + q) % k]];
        const bd_rfe_section *N = &R->sections[R->order[(start + q + 1) % k]];
        int a = last_of(S, n);
        int gap = (N->first - a - 1 + n) % n;
        if (gap > 0) {
            R->run_first[R->run_n] = a + 1 == n ? 0 : a + 1;
            R->run_count[R->run_n++] = gap;
        }
    }
}

/* the mechanical energy of nodes from .. to (round the loop) and of the
 * SDEs from the one before `from` to the one after `to`: kinetic
 * (translation at the half step, rotation), gravity, elastic */
static double local_energy(const bd_sim *sim, int from, int to)
{
    const bd_rfe *R = bd_rfe_of(sim);
    const int n = sim->model->n;
    const double g = sim->model->gravity, J = bd_rfe_model_of(sim)->inertia;
    double e = 0.0;
    for (int i = from;; i = bd_node_next(i, n)) {
        e += 0.5 * sim->mass[i] * (sim->vx[i] * sim->vx[i] + sim->vy[i] * sim->vy[i])
           + 0.5 * J * R->omega[i] * R->omega[i] + sim->mass[i] * g * sim->y[i]
           + bd_rfe_align_energy(sim, i);
        if (i == to)
            break;
    }
    for (int e0 = bd_node_prev(from, n);; e0 = bd_node_next(e0, n)) {
        e += bd_rfe_sde_energy(sim, e0);
        if (e0 == to)
            break;
    }
    /* the alignments beside: their angles follow the ends */
    e += bd_rfe_align_energy(sim, bd_node_prev(from, n))
       + bd_rfe_align_energy(sim, bd_node_next(to, n));
    return e;
}

/* the energy a topology change took out (lost > 0) or put in: a change
 * of the state the step ends in, counted from then on (not spread over
 * the step as the forces' work is, sim/energy.c bd_energy_at_t) */
static void book(bd_sim *sim, double lost)
{
    bd_rfe *R = bd_rfe_of(sim);
    bd_energy *en = &sim->energy;
    if (lost >= 0.0) {
        en->dissipated += lost;
        en->step_dissipated_after += lost;
        R->booked_lost += lost;
    } else {
        en->input -= lost;
        en->step_input_after -= lost;
        R->booked_gained -= lost;
    }
}

/* the section's speeds from its elements' momentum along its line (the
 * least change of their kinetic energy), its elements then where and as
 * fast as it says */
static void take_momentum(bd_sim *sim, const bd_rfe_window *W, bd_rfe_section *S)
{
    const int n = sim->model->n;
    /* its speeds change: its rolls are given back first */
    unstick(sim, (int)(S - bd_rfe_of(sim)->sections));
    const double inv = 1.0 / (S->count - 1);
    double p1 = 0.0, p2 = 0.0;
    for (int q = 0, i = S->first; q < S->count; q++, i = bd_node_next(i, n)) {
        double xi = q * inv, p = sim->mass[i] * (sim->vx[i] * W->d[0] + sim->vy[i] * W->d[1]);
        p1 += (1.0 - xi) * p;
        p2 += xi * p;
    }
    mass_matrix(sim, S);
    const double m11 = S->m11, m12 = S->m12, m22 = S->m22, det = m11 * m22 - m12 * m12;
    S->v1 = (m22 * p1 - m12 * p2) / det;
    S->v2 = (m11 * p2 - m12 * p1) / det;
    place(sim, W, S);
}

/* node i tied into section w: not turning, moved only with the section
 * (a contact beside it sees it held) */
static void tie_node(bd_sim *sim, int i, int w)
{
    bd_rfe *R = bd_rfe_of(sim);
    const int n = sim->model->n;
    R->sec[i] = w;
    R->omega[i] = 0.0;
    R->rb[i] = 0.0;
    sim->dt_per_mass[i] = 0.0;
    /* what the forces phase no longer writes for it (forces.c) */
    R->h[i] = R->hd[i] = R->tq[i] = R->tqn[i] = 0.0;
    int es[2] = {bd_node_prev(i, n), i};
    for (int k = 0; k < 2; k++) {
        int e = es[k];
        if (bd_rfe_sde_held(R, e, bd_node_next(e, n)))
            R->q[e] = R->qd[e] = R->mb[e] = R->mbd[e] = 0.0;
    }
}

/* a tied element turned along its section's line: one inside it, whose
 * turn counts for nothing (its SDEs are both to tied elements). A
 * section's end keeps the turn it was given when it became the end (a
 * join's reflect_turn, a leave's relax), so that its SDE to the free
 * belt does not jump; inside, turned along the line, it leaves as it
 * would stand there */
static void along_line(bd_sim *sim, int i, const bd_rfe_window *W)
{
    bd_rfe *R = bd_rfe_of(sim);
    R->ct[i] = W->d[0];
    R->st[i] = W->d[1];
}

static void free_node(bd_sim *sim, int i)
{
    bd_rfe_of(sim)->sec[i] = -1;
    bd_node_mass_changed(sim, i);
}

/* the place along W's line at the chord L from point (px, py), ahead of
 * it (dir +1) or behind (−1) */
static double chord_from(const bd_rfe_window *W, double px, double py, double L, double dir)
{
    double a = along(W, px, py);
    double c = (py - W->p0[1]) * W->d[0] - (px - W->p0[0]) * W->d[1];
    double h = L * L - c * c;
    return a + dir * (h > 0.0 ? sqrt(h) : 0.0);
}

/* the turn (tx, ty) of a section's end at (px, py) whose SDE to free
 * element q has no shear: t_q reflected about the SDE's line,
 * γ = θ_u − ½(φ_p + φ_q) = 0 (seed 000 §2.3) */
static void reflected(const bd_sim *sim, double px, double py, int q, double *tx, double *ty)
{
    const bd_rfe *R = bd_rfe_of(sim);
    double ux = sim->x[q] - px, uy = sim->y[q] - py;
    double inv = 1.0 / hypot(ux, uy);
    ux *= inv;
    uy *= inv;
    double c = R->ct[q] * ux + R->st[q] * uy;
    double x = 2.0 * c * ux - R->ct[q], y = 2.0 * c * uy - R->st[q];
    double tn = 1.0 / hypot(x, y);
    *tx = x * tn;
    *ty = y * tn;
}

/* a section's end p turned so that its SDE to q has no shear */
static void reflect_turn(bd_sim *sim, int p, int q)
{
    bd_rfe *R = bd_rfe_of(sim);
    reflected(sim, sim->x[p], sim->y[p], q, &R->ct[p], &R->st[p]);
}

/* A topology change makes no energy. What a join or a leave adds to the
 * belt's mechanical energy (a join lifts its element the last millimetres
 * onto the line, and the stiff shear beside it takes the new turn: on
 * generated seed 8522's return 0.2–0.3 J a join, booked as input it was
 * 8 W, and the drive drew 1.8 % less than the law) is taken from the
 * section's motion along its line, both ends' speeds scaled alike: a drag
 * the drive then pays, as it pays the idlers. A change takes at most a
 * quarter of the section's kinetic energy (a section near rest, as at
 * the first tie, would be stopped); what that cannot give stays a gain,
 * booked as input. Returns what a change with this energy balance leaves
 * to book: a loss as it was, a gain less what the section paid. */
static double pay_gain(bd_sim *sim, const bd_rfe_window *W, bd_rfe_section *S, double lost)
{
    if (!(lost < 0.0) || S->count < 2)
        return lost;
    const double v1 = S->v1, v2 = S->v2;
    const double ke2 = S->m11 * v1 * v1 + 2.0 * S->m12 * v1 * v2 + S->m22 * v2 * v2;
    const double take = fmin(-lost, 0.25 * 0.5 * ke2);
    if (!(take > 0.0))
        return lost;
    const double f = sqrt(1.0 - 2.0 * take / ke2);
    S->v1 = f * v1;
    S->v2 = f * v2;
    if (aggregated(S))
        place_ends(sim, W, S);
    else
        place(sim, W, S);
    return lost + take;
}

/* the free node next to section w's first element (end 0) or last (end
 * 1) joins it; returns the energy the section's elements and the SDEs at
 * its ends lost by it */
static double join(bd_sim *sim, int w, int end)
{
    bd_rfe *R = bd_rfe_of(sim);
    const bd_rfe_window *W = &bd_rfe_model_of(sim)->windows[w];
    bd_rfe_section *S = &R->sections[w];
    const int n = sim->model->n;
    int p = end == 0 ? bd_node_prev(S->first, n) : bd_node_next(last_of(S, n), n);
    int q = end == 0 ? bd_node_prev(p, n) : bd_node_next(p, n);   /* its free neighbour */
    /* the section, the joining element and the free ones whose turns
     * relax (below) */
    int from = end == 0 ? (p - RELAX_JOIN + n) % n : S->first;
    int to = end == 0 ? last_of(S, n) : (p + RELAX_JOIN) % n;
    double e0 = local_energy(sim, from, to);
    double L = hypot(sim->x[p] - sim->x[q], sim->y[p] - sim->y[q]);
    double s = chord_from(W, sim->x[q], sim->y[q], L, end == 0 ? 1.0 : -1.0);
    tie_node(sim, p, w);
    if (end == 0) {
        along_line(sim, S->first, W);
        S->first = p;
        S->s1 = s;
    } else {
        along_line(sim, last_of(S, n), W);
        S->s2 = s;
    }
    S->count++;
    take_momentum(sim, W, S);
    /* the new end turned so that its SDE to the free belt has no shear
     * (its SDE inside the section has none, whatever its turn), then the
     * free belt's turns beside it relaxed to it */
    reflect_turn(sim, p, q);
    if (end == 0)
        bd_rfe_relax_turns(sim, (p - RELAX_JOIN + n) % n, RELAX_JOIN, 0);
    else
        bd_rfe_relax_turns(sim, bd_node_next(p, n), RELAX_JOIN, 0);
    R->joined++;
    return pay_gain(sim, W, S, e0 - local_energy(sim, from, to));
}

/* the first (end 0) or last (end 1) element of section w leaves it where
 * it is, as fast as it is: the others stay on the same even spacing */
static double leave(bd_sim *sim, int w, int end)
{
    bd_rfe *R = bd_rfe_of(sim);
    bd_rfe_section *S = &R->sections[w];
    const int n = sim->model->n;
    double r = 1.0 / (S->count - 1);
    /* its SDE to the section and its alignment count again (a section's
     * end keeps the turn it was given when it became the end) */
    int k = end == 0 ? S->first : last_of(S, n);
    int from = end == 0 ? (k - RELAX_JOIN - 1 + n) % n : bd_node_prev(bd_node_prev(k, n), n);
    int to = end == 0 ? bd_node_next(bd_node_next(k, n), n) : (k + RELAX_JOIN + 1) % n;
    double e0 = local_energy(sim, from, to);
    if (end == 0) {
        free_node(sim, S->first);
        S->first = bd_node_next(S->first, n);
        S->s1 += r * (S->s2 - S->s1);
        S->v1 += r * (S->v2 - S->v1);
    } else {
        free_node(sim, last_of(S, n));
        S->s2 -= r * (S->s2 - S->s1);
        S->v2 -= r * (S->v2 - S->v1);
    }
    S->count--;
    mass_matrix(sim, S);
    /* the element that left, and the free belt beyond it, turned to the
     * least energy (a section's end that joined it from the free belt
     * keeps the turn it came with, and carried off unrelaxed it would
     * swing), and the section's new end with them, on its SDE to the
     * free belt alone: the end is the section's hinge, as a join makes it
     * (reflect_turn). Held in the line's turn, it met the turn the
     * element beside it had kept since it joined, and the shear that SDE
     * hid while both were tied counted at once: on generated seed 8526,
     * settling undamped from rest, with the free belt beside a section
     * 0.06 rad off its line, one leave made 42 J (docs/physics.md §15,
     * The sections' ends). */
    if (end == 0)
        bd_rfe_relax_turns(sim, (k - RELAX_JOIN + 1 + n) % n, RELAX_JOIN + 1, 1);
    else
        bd_rfe_relax_turns(sim, bd_node_prev(k, n), RELAX_JOIN + 1, 1);
    R->left++;
    return pay_gain(sim, &bd_rfe_model_of(sim)->windows[w], S, e0 - local_energy(sim, from, to));
}

/* whether node i stands in window W no further than `off` from its line
 * (not another strand passing near; not the belt lifted off its idlers) */
static int inside(const bd_sim *sim, const bd_rfe_window *W, int i, double off)
{
    double a = along(W, sim->x[i], sim->y[i]);
    double c = (sim->y[i] - W->p0[1]) * W->d[0] - (sim->x[i] - W->p0[0]) * W->d[1];
    if (!(a >= W->a && a < W->b && fabs(c) <= off))
        return 0;
    /* and running along it: near a pulley the other strand may pass
     * within a sag's depth (generated seed 10: the carry 0.17 m above the
     * return beside its snub, tied onto the return's line, diverged) */
    int j = bd_node_next(i, sim->model->n);
    double ux = sim->x[j] - sim->x[i], uy = sim->y[j] - sim->y[i];
    return ux * W->d[0] + uy * W->d[1] > 0.9 * hypot(ux, uy);
}

/* how far off its line an element may be to be tied: the first time, a
 * sag of 10 % of a bay; joining a section's end, which it leaves a slope
 * of at most ¼ rad from, a quarter element (it is put on the line with
 * its SDE to the free belt kept, and an element further off has lifted
 * or swings: it joins later or not at all, the section ending short of
 * its window and its end idlers pressing on the free belt) */
static double tie_off(const bd_rfe_window *W)
{
    return 0.1 * W->bay + 0.02;
}

static double join_off(const bd_sim *sim)
{
    return 0.25 * sim->model->l0 + 0.002;
}

/* whether free element p, joining a section's end (dir −1: before its
 * first element, +1: after its last) beside free element q, would be
 * turned no more than JOIN_TURN from the window's line (put on the line
 * as join does it, its turn as reflect_turn gives it) */
static int join_turn_ok(const bd_sim *sim, const bd_rfe_window *W, int p, int q, double dir)
{
    double L = hypot(sim->x[p] - sim->x[q], sim->y[p] - sim->y[q]);
    double s = chord_from(W, sim->x[q], sim->y[q], L, -dir);
    double tx, ty;
    reflected(sim, W->p0[0] + s * W->d[0], W->p0[1] + s * W->d[1], q, &tx, &ty);
    double dev = atan2(W->d[0] * ty - W->d[1] * tx, W->d[0] * tx + W->d[1] * ty);
    return fabs(dev) <= JOIN_TURN;
}

/* the belt's whole mechanical energy, as local_energy counts it */
static double belt_energy(const bd_sim *sim)
{
    const bd_rfe *R = bd_rfe_of(sim);
    const double g = sim->model->gravity, J = bd_rfe_model_of(sim)->inertia;
    double e = 0.0;
    for (int i = 0; i < sim->model->n; i++)
        e += 0.5 * sim->mass[i] * (sim->vx[i] * sim->vx[i] + sim->vy[i] * sim->vy[i])
           + 0.5 * J * R->omega[i] * R->omega[i] + sim->mass[i] * g * sim->y[i]
           + bd_rfe_align_energy(sim, i) + bd_rfe_sde_energy(sim, i);
    return e;
}

/* a point's offset from W's line, up */
static inline double offset(const bd_rfe_window *W, double x, double y)
{
    double c = (y - W->p0[1]) * W->d[0] - (x - W->p0[0]) * W->d[1];
    return W->d[0] >= 0.0 ? c : -c;
}

static inline void at_offset(const bd_rfe_window *W, double s, double off, double *x, double *y)
{
    double up0 = W->d[0] >= 0.0 ? -W->d[1] : W->d[1], up1 = W->d[0] >= 0.0 ? W->d[0] : -W->d[0];
    *x = W->p0[0] + s * W->d[0] + off * up0;
    *y = W->p0[1] + s * W->d[1] + off * up1;
}

/* The free bay beside a window's end (dir −1: before its first element;
 * +1: after its last), from the idler outside it to the window's end in
 * mid-bay, laid as a half bay: the end of a section holds the belt at the
 * idlers' height there, so the bay's full sag (its deepest point at the
 * window's end) becomes the half bay's, the same parabola less the line
 * from the idler to the end, −κ·(σ − σ_I)·(σ_end − σ). Each element keeps
 * its SDE's length (the tension does not jump), walked from the element
 * at the idler; returns the window end element's place along the line. */
static double lay_half_bay(bd_sim *sim, const bd_rfe_window *W, int end_node, int dir)
{
    const int n = sim->model->n;
    const double s_idler = dir < 0 ? W->a - 0.5 * W->bay : W->b + 0.5 * W->bay;
    const double s_end = dir < 0 ? W->a : W->b;
    /* κ of the bay's present sag at the window's end element */
    double se = along(W, sim->x[end_node], sim->y[end_node]);
    double oe = offset(W, sim->x[end_node], sim->y[end_node]);
    double q = (se - s_idler) * (s_idler - dir * W->bay - se);
    double kappa = q != 0.0 ? -oe / q : 0.0;
    /* the element nearest the idler, walking out from the end */
    int k0 = end_node;
    for (int guard = 0; guard < n; guard++) {
        int nb = dir < 0 ? bd_node_prev(k0, n) : bd_node_next(k0, n);
        double a0 = along(W, sim->x[k0], sim->y[k0]), a1 = along(W, sim->x[nb], sim->y[nb]);
        if (fabs(a1 - s_idler) >= fabs(a0 - s_idler))
            break;
        k0 = nb;
    }
    /* the elements that the idler's contact reaches (within 1.5 elements
     * of its roll on the quadratic line, 3 on the quintic: the nearest
     * and three beyond; idler_contact.c) kept where
     * they are: moved, they sank into the roll, whose stiff contact threw
     * them off (generated seed 5, 8 m/s) */
    for (int r = 0; r < IDLER_REACH && k0 != end_node; r++)
        k0 = dir < 0 ? bd_node_next(k0, n) : bd_node_prev(k0, n);
    double sp = along(W, sim->x[k0], sim->y[k0]), op = offset(W, sim->x[k0], sim->y[k0]);
    /* From there to the window's end a cubic (Hermite) that leaves the
     * belt as it lies there (its offset and slope, the latter from the
     * element behind) and reaches the line at the half bay's slope there,
     * κ·(σ_end − σ_I): no kink where the laying begins (a parabola begun
     * there kinked the belt by 7–20 mrad, and the stiff shear threw the
     * elements off) */
    int kb = dir < 0 ? bd_node_prev(k0, n) : bd_node_next(k0, n);
    double sb = along(W, sim->x[kb], sim->y[kb]), ob = offset(W, sim->x[kb], sim->y[kb]);
    const double s0 = sp, o0 = op, span = s_end - s0;
    const double m0 = sp != sb ? (op - ob) / (sp - sb) : 0.0, m1 = kappa * (s_end - s_idler);
    /* where the element last walked stood before it moved */
    double kx = sim->x[k0], ky = sim->y[k0];
    for (int k = k0; k != end_node;) {
        int nx = dir < 0 ? bd_node_next(k, n) : bd_node_prev(k, n);
        double L = hypot(sim->x[nx] - kx, sim->y[nx] - ky);
        kx = sim->x[nx];
        ky = sim->y[nx];
        double s = along(W, sim->x[nx], sim->y[nx]), o = 0.0;
        for (int it = 0; it < 4; it++) {
            double t = span != 0.0 ? (s - s0) / span : 1.0;
            if (t < 1.0) {
                double t2 = t * t, t3 = t2 * t;
                o = (2.0 * t3 - 3.0 * t2 + 1.0) * o0 + (t3 - 2.0 * t2 + t) * span * m0
                  + (t3 - t2) * span * m1;
            } else {
                o = 0.0;
            }
            double h = L * L - (o - op) * (o - op);
            s = sp - dir * (h > 0.0 ? sqrt(h) : 0.0);
        }
        at_offset(W, s, o, &sim->x[nx], &sim->y[nx]);
        sp = s;
        op = o;
        k = nx;
    }
    return sp;
}

/* the first time: every element inside a window tied into its section,
 * put on the line (its place along it kept for the ends, the others
 * spaced evenly between); the energy that changes booked */
static void tie_all(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    const int n = sim->model->n;
    double e0 = belt_energy(sim);
    for (int w = 0; w < RM->window_count; w++) {
        const bd_rfe_window *W = &RM->windows[w];
        bd_rfe_section *S = &R->sections[w];
        /* the run inside it that starts after a node outside it */
        int first = -1;
        for (int i = 0; i < n && first < 0; i++)
            if (inside(sim, W, i, tie_off(W)) && !inside(sim, W, bd_node_prev(i, n), tie_off(W)))
                first = i;
        if (first < 0)
            continue;
        int count = 0;
        for (int i = first; count < n && inside(sim, W, i, tie_off(W)) && R->sec[i] < 0;
             i = bd_node_next(i, n))
            count++;
        if (count < 2)
            continue;
        S->first = first;
        S->count = count;
        int last = last_of(S, n);
        /* where it meets the window before it, the element there (tied
         * by that window, on the line) keeps its SDE's length */
        /* where two windows meet, in mid-bay (the sag's slope 0 there),
         * the elements on either side are put on the line as they are:
         * their SDE keeps its length to the second order of the slope */
        S->s1 = W->before >= 0 ? along(W, sim->x[first], sim->y[first])
                               : lay_half_bay(sim, W, first, -1);
        S->s2 = W->after >= 0 ? along(W, sim->x[last], sim->y[last])
                              : lay_half_bay(sim, W, last, 1);
        for (int q = 0, i = first; q < count; q++, i = bd_node_next(i, n)) {
            tie_node(sim, i, w);
            along_line(sim, i, W);
        }
        take_momentum(sim, W, S);
    }
    /* the free belt beside each end turned to meet it with the least
     * energy */
    for (int w = 0; w < RM->window_count; w++) {
        const bd_rfe_section *S = &R->sections[w];
        if (S->count < 2)
            continue;
        /* the whole half bay laid beside a free end, and a few beyond */
        const bd_rfe_window *W = &RM->windows[w];
        int around = (int)ceil(0.5 * W->bay / sim->model->l0) + RELAX_AROUND;
        bd_rfe_relax_turns(sim, (S->first - around + n) % n, around, 0);
        bd_rfe_relax_turns(sim, bd_node_next(last_of(S, n), n), around, 0);
    }
    book(sim, e0 - belt_energy(sim));
    R->tied = 1;
}

int bd_rfe_belt_dof(const bd_sim *sim)
{
    const bd_rfe *R = bd_rfe_of(sim);
    const int windows = bd_rfe_model_of(sim)->window_count;
    int tied = 0, sections = 0;
    for (int w = 0; w < windows; w++)
        if (R->sections[w].count >= 2) {
            tied += R->sections[w].count;
            sections++;
        }
    return 3 * (sim->model->n - tied) + 2 * sections;
}

/* section w's elements, and those of the sections that may meet it
 * (a join or a leave measures and relaxes the belt a few elements beyond
 * its end: into the next section only where their windows meet, the free
 * belt between two others being longer than a margin), placed */
static void ensure_near(bd_sim *sim, int w)
{
    const bd_rfe_window *W = &bd_rfe_model_of(sim)->windows[w];
    ensure_placed(sim, w);
    if (W->before >= 0)
        ensure_placed(sim, W->before);
    if (W->after >= 0)
        ensure_placed(sim, W->after);
}

/* after the integrate phase: the elements that left a window leave its
 * section, those that entered one join it (the first time, every section
 * is tied; none while stabilizing, whose time stands still) */
void bd_rfe_sections_regroup(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    if (RM->window_count == 0 || sim->stabilizing)
        return;
    const int n = sim->model->n;
    int changed = 0;
    if (!R->tied) {
        tie_all(sim);
        changed = 1;
    }
    double lost = 0.0;
    for (int w = 0; w < RM->window_count; w++) {
        bd_rfe_section *S = &R->sections[w];
        /* an element joins inside [a, b] and leaves outside [a − h, b + h]
         * (put on the line as it joins, it may land a little outside) */
        const double a = RM->windows[w].a - LEAVE_BEYOND * sim->model->l0;
        const double b = RM->windows[w].b + LEAVE_BEYOND * sim->model->l0;
        while (S->count > 2 && (S->s2 >= b || S->s1 < a)) {
            ensure_near(sim, w);
            unstick(sim, w);
            lost += leave(sim, w, S->s2 >= b ? 1 : 0);
            changed = 1;
        }
    }
    for (int w = 0; w < RM->window_count; w++) {
        const bd_rfe_window *W = &RM->windows[w];
        bd_rfe_section *S = &R->sections[w];
        if (S->count < 2)
            continue;
        for (;;) {
            int p = bd_node_prev(S->first, n), q = bd_node_next(last_of(S, n), n);
            int end = R->sec[p] < 0 && inside(sim, W, p, join_off(sim)) &&
                              join_turn_ok(sim, W, p, bd_node_prev(p, n), -1.0)
                        ? 0
                    : R->sec[q] < 0 && inside(sim, W, q, join_off(sim)) &&
                              join_turn_ok(sim, W, q, bd_node_next(q, n), 1.0)
                        ? 1
                        : -1;
            if (end < 0)
                break;
            ensure_near(sim, w);
            unstick(sim, w);
            lost += join(sim, w, end);
            changed = 1;
        }
    }
    if (!changed)
        return;
    if (lost != 0.0)
        book(sim, lost);
    free_runs(R, RM->window_count, n);
    R->live_stale = 1;
    /* the rotations' system changes with the tied elements */
    R->rdt = 0.0;
    int dof = bd_rfe_belt_dof(sim);
    if (dof < R->belt_dof_min)
        R->belt_dof_min = dof;
    if (dof > R->belt_dof_max)
        R->belt_dof_max = dof;
}

/* material lands on the elements at the feed point (lumped/material.c);
 * on a section, the section takes their momentum (what that costs in
 * kinetic energy booked as dissipated) */
static void retake(bd_sim *sim, int w)
{
    const bd_rfe_window *W = &bd_rfe_model_of(sim)->windows[w];
    bd_rfe_section *S = &bd_rfe_of(sim)->sections[w];
    const int n = sim->model->n;
    double ke = 0.0;
    for (int q = 0, i = S->first; q < S->count; q++, i = bd_node_next(i, n))
        ke += sim->mass[i] * (sim->vx[i] * sim->vx[i] + sim->vy[i] * sim->vy[i]);
    take_momentum(sim, W, S);
    for (int q = 0, i = S->first; q < S->count; q++, i = bd_node_next(i, n)) {
        ke -= sim->mass[i] * (sim->vx[i] * sim->vx[i] + sim->vy[i] * sim->vy[i]);
        sim->dt_per_mass[i] = 0.0;
    }
    sim->energy.dissipated += 0.5 * ke;
}

void bd_rfe_material(bd_sim *sim)
{
    bd_lumped_material(sim);
    bd_rfe *R = bd_rfe_of(sim);
    if (!R->tied || !sim->has_feed)
        return;
    int e = sim->feed.element, j = bd_node_next(e, sim->model->n);
    if (R->sec[e] >= 0)
        retake(sim, R->sec[e]);
    if (R->sec[j] >= 0 && R->sec[j] != R->sec[e])
        retake(sim, R->sec[j]);
}

void bd_rfe_topology(const bd_sim *sim, bd_belt_topology *out)
{
    const bd_rfe *R = bd_rfe_of(sim);
    const bd_rfe_model *RM = bd_rfe_model_of(sim);
    out->windows = RM->window_count;
    out->window_length = 0.0;
    for (int w = 0; w < RM->window_count; w++)
        out->window_length += RM->windows[w].b - RM->windows[w].a;
    out->dof_now = bd_rfe_belt_dof(sim);
    out->dof_min = R->belt_dof_min < out->dof_now ? R->belt_dof_min : out->dof_now;
    out->dof_max = R->belt_dof_max > out->dof_now ? R->belt_dof_max : out->dof_now;
    out->joined = R->joined;
    out->left = R->left;
    out->lost_J = R->booked_lost;
    out->gained_J = R->booked_gained;
    out->kink_share = RM->kink_share;
    out->kink_free_spans = RM->kink_free_spans;
}
