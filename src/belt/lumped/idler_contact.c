/* Belt–idler contact (seed 001 §4.3.2, changed by issue 10): an idler
 * presses on the belt's running line at the point nearest its centre.
 *
 * The discrete belt's running line, where the idler's bay holds nine
 * elements or more and the belt turns over it by 0.0225 rad or more
 * (build.c), is the uniform quintic B-spline of its nodes (quintic_*
 * below): each point a weighted mean of six nodes, C4, the weights smooth
 * in the point's place along the belt. An idler is a
 * load fixed in space that the nodes pass at v/l0; what it gives each
 * node is a weight of the spline, so the force's harmonics at that
 * passage fall as the weights' spectrum, as (l0·q/2π)⁶ for the spline of
 * degree 5 against the cube for the quadratic below. With the quadratic
 * the passage radiated short transverse waves into the spans that their
 * dashpots and contacts dissipated: the minimal loop of docs/physics.md
 * §10 (3 m return bays turning the belt by 0.225 rad) drew +19, +27 and
 * +29 % over its law at 4, 5 and 6 m/s; on the quintic +0.5, +2.8 and
 * +0.3 % (§5). A line cuts the corner of the belt's free lines over a
 * roll by ½·Ḡ·φ·l0 (φ the turn, Ḡ the weights' mean difference, derived
 * in §5: 0.7321 within ±0.2 % whatever the nodes' phase for the quintic,
 * 7/15 ± 7 % for the quadratic); the discrete belt's idler presses at its
 * contact_radius, the radius less that cut at the set's turn at rest
 * (build.c), so the belt's free lines meet on the roll's top and its sag
 * is the string's.
 *
 * The rfe belt's running line is its element centres' chain, chosen and
 * placed by the same rule (build.c). The quintic's six nodes reach three
 * elements past the roll; an idler outside a long section's window
 * (belt/rfe/sections.c) stands at least half a bay less half an element
 * from the section's end, four elements or more on a quintic bay, so its
 * line never reaches the elements a section sums from its ends. On
 * generated seed 12 (rfe, φ 0.06 at 0.22·c, nine or more elements to a
 * bay) the running force went from +3.56 to +2.75 % of its law.
 *
 * The quadratic line: round node k, the quadratic Bézier from the middle
 * of element k − 1 through the corner at node k to the middle of element
 * k (piece_at below); the pieces meet with one tangent. Seed 001 presses
 * the roll on the foot point of its centre on the straight element
 * (eqs 4.95–4.102): when a node passes the roll the element over it
 * changes and the normal turns at once by the belt's angle β there, an
 * impact of ½m_e(v·β)² per passage that the stiff contact stopped. It cost
 * running force the model does not declare (4–30 % on generated empty
 * belts), did not fall with the element length, and its booked work
 * changed sign from passage to passage (the dissipated energy fell).
 * On the smoothed line the normal turns as the nodes move. (Running the
 * belt round the roll as at a pulley, wrap_elements.c, was tried: on an
 * arc of a few millimetres the node turns within a step or two, the same
 * impact.)
 *
 * Normal: contact point B = Σ w_m·x_m (nodes k − 1, k, k + 1), the belt
 * pushed away from the centre along n̂ = (B − c)/|B − c| by a penalty on
 * δ = R − |B − c|; B is the nearest point, so ∂|B − c|/∂x_m = w_m·n̂ and
 * the force is shared by w_m. As for pulleys (pulley_contact.c) the spring
 * is stiff and linearly implicit: with the contact point's effective mass
 * m* = 1/Σ(w_m²/m_m), its normal velocity v_n and the normal acceleration
 * a_o,n the other forces give it,
 *   f_n = k_c·(δ − Δt·v_n − Δt²·a_o,n) / (1 + k_c·Δt²/m*)  ≥ 0,
 * stable for any k_c. The whole of f_n is booked as non-conservative work:
 * in the stiff limit (k_c·Δt²/m* ≫ 1) the contact holds δ ≥ Δt·v_n, not
 * k_c·δ ≈ f_n, and booked as a spring k_c·δ did "work" that ½k_c·δ² never
 * stored (the balance of a belt falling onto its rolls from rest, generated
 * seed 1028: 0.77 % against 0.03 %). The energy the contact really stores,
 * f_n²/(2k_c), is millijoules; it is counted as potential energy (summed
 * here, sim/energy.c), since the spring gives it back as the belt lifts:
 * booked as dissipated only, that read as negative dissipation at starts
 * from rest (generated seeds 1162, 1335, 1403, 1441, issue 10).
 *
 * Rolling (indentation) resistance: a force rr·f_n on the belt against its
 * motion over the idler (model-format.md `rolling_resistance`), smoothed
 * below BD_ROLLING_SPEED (laws/rolling.h) so a belt at rest carries none.
 *
 * Friction: t̂ along the belt in the direction of travel, slip speed
 * v_r = t̂·Σ w_m·v_m − ω·R (eq 4.107). The stick force f (−f·t̂ on the belt
 * shared by w_m, +f·R on the idler) that makes v_r zero at the end of the
 * step solves eq 4.113:
 *   f = [v_r/Δt + Σ w_m·t̂·F_m/m_m] / [Σ w_m²/m_m + R²/I]
 * (eq 4.114 rearranged; the idler has no other torque). |f| > μ_s·f_n slips
 * with ±μ_d·f_n (eqs 4.116–4.117). */
#include "belt/lumped/lumped.h"

#include <math.h>

#include "laws/rolling.h"

/* Ḡ: the weights' mean difference Σ_jm w_j·w_m·|j − m| averaged over the
 * piece, exactly (docs/physics.md §5): the quintic's 292223/399168
 * (0.73056 to 0.73359 along it), the quadratic's 7/15 (0.4375 to 0.5) */
#define QUINTIC_MEAN_DIFFERENCE (292223.0 / 399168.0)
#define QUADRATIC_MEAN_DIFFERENCE (7.0 / 15.0)

/* predictive contact gap, as a fraction of the element length */
#define IDLER_CONTACT_GAP 0.02
/* the nearest point (nearest_point): a first Newton step longer than this
 * (of the piece's parameter) is followed by up to NEAREST_STEPS more,
 * until one is shorter than NEAREST_CONVERGED (Newton's error is then of
 * its square, 10⁻¹² of the piece) */
#define NEAREST_ONE_STEP 1e-2
#define NEAREST_STEPS 8
#define NEAREST_CONVERGED 1e-6

/* the belt, d from the idler's centre, off it by more than the
 * clearance that counts as lift-off (system.h), once it has stood within
 * BD_LIFT_OFF_LANDED of it (landed, contact_on): the belt is laid straight on
 * the roll tops, and where it turns over an idler (its sag, a curve) the
 * contact stands a corner below them (contact_radius); at the start it
 * falls that far onto the rolls, which is no lift-off (the cement plant's
 * carry at 0.2 m: 1.04 mm over all 809 stations for 15 ms) */
static void note_lifted(bd_sim *sim, const bd_idler *id, double d)
{
    if (id->landed && d - id->m->contact_radius > BD_LIFT_OFF_CLEARANCE && !sim->stabilizing)
        bd_lift_off_note(sim, id->m->s);
}

/* the belt's smoothed line round node k: the quadratic Bézier from the
 * middle of element k − 1 (t = 0) through the corner at node k to the
 * middle of element k (t = 1); the pieces of neighbouring nodes meet at
 * the element middles with one tangent (C1). The weights of nodes k − 1,
 * k, k + 1 in its point at t, and that point from c. Derived here
 * (docs/physics.md §5). */
static inline __attribute__((always_inline)) void piece_at(const bd_sim *sim, int k, double t,
                                                            const double c[2], bd_idler_touch *pc,
                     double r[2])
{
    const int n = sim->model->n;
    int a = bd_node_prev(k, n), b = bd_node_next(k, n);
    pc->node[0] = a;
    pc->node[1] = k;
    pc->node[2] = b;
    pc->w[0] = 0.5 * (1.0 - t) * (1.0 - t);
    pc->w[2] = 0.5 * t * t;
    pc->w[1] = 1.0 - pc->w[0] - pc->w[2];
    pc->count = 3;
    r[0] = pc->w[0] * sim->x[a] + pc->w[1] * sim->x[k] + pc->w[2] * sim->x[b] - c[0];
    r[1] = pc->w[0] * sim->y[a] + pc->w[1] * sim->y[k] + pc->w[2] * sim->y[b] - c[1];
}

/* after a Newton step to t on piece *kp (pieces are numbered by node, or
 * by element on the quintic line, either way one after another): past
 * the piece's end, onto the neighbouring piece, the previous one's end or
 * the next one's start (where the two pieces meet), and 1; else t and the
 * step's size */
static inline double onto_piece(int n, double t, double step, int *kp, double *tp)
{
    if (t < 0.0) {
        *kp = bd_node_prev(*kp, n);
        *tp = t + 1.0 < 0.0 ? 0.0 : t + 1.0;
        return 1.0;
    }
    if (t > 1.0) {
        *kp = bd_node_next(*kp, n);
        *tp = t - 1.0 > 1.0 ? 1.0 : t - 1.0;
        return 1.0;
    }
    *tp = t;
    return fabs(step);
}

/* one Newton step on (B − c)·B' = 0 along the piece round node k from t,
 * onto the neighbouring piece when t leaves [0, 1]; the step's size, or 1
 * on leaving the piece */
static double newton_step(const bd_sim *sim, double cx, double cy, int *kp, double *tp)
{
    const int n = sim->model->n;
    const double *x = sim->x, *y = sim->y;
    int k = *kp;
    double t = *tp;
    int a = bd_node_prev(k, n), b = bd_node_next(k, n);
    /* B(t) = m + t·e1 + ½t²·(e2 − e1), from the centre */
    double e1x = x[k] - x[a], e1y = y[k] - y[a];
    double ddx = x[b] - x[k] - e1x, ddy = y[b] - y[k] - e1y;
    double mx = 0.5 * (x[a] + x[k]) - cx, my = 0.5 * (y[a] + y[k]) - cy;
    double dBx = e1x + t * ddx, dBy = e1y + t * ddy;
    double Bx = mx + t * (e1x + 0.5 * t * ddx), By = my + t * (e1y + 0.5 * t * ddy);
    double dB2 = dBx * dBx + dBy * dBy;
    double h = dB2 + Bx * ddx + By * ddy;
    /* h > 0 unless the roll sat inside the corner's own curvature, which
     * a belt bent round a roll by less than an element's length does not;
     * the tangent step then */
    double den = h > 0.0 ? h : dB2;
    double step = den > 0.0 ? (Bx * dBx + By * dBy) / den : 0.0;
    return onto_piece(n, t - step, step, kp, tp);
}

/* The quintic running line on element e (t = 0 at node e, 1 at node
 * e + 1): B(t) = Σ w_i(t)·x_i over the nodes e − 2 … e + 3, w_i(t) the
 * uniform quintic B-spline's basis, here as polynomials in t (times 120):
 *   w_0 = (1 − t)⁵, w_5 = t⁵,
 *   w_1 = 26 − 50t + 20t² + 20t³ − 20t⁴ + 5t⁵,
 *   w_2 = 66 − 60t² + 30t⁴ − 10t⁵,
 *   w_3 = 26 + 50t + 20t² − 20t³ − 20t⁴ + 10t⁵,
 *   w_4 = 1 + 5t + 10t² + 10t³ + 5t⁴ − 5t⁵
 * (the cardinal B-spline N₅(t + 5 − i); they sum to 1 and reproduce a
 * straight belt). The pieces meet with four continuous derivatives. */
static void quintic_nodes(int n, int e, int node[6])
{
    if (e >= 2 && e + 3 < n) {
        for (int i = 0; i < 6; i++)
            node[i] = e - 2 + i;
        return;
    }
    node[2] = e;
    node[1] = bd_node_prev(e, n);
    node[0] = bd_node_prev(node[1], n);
    node[3] = bd_node_next(e, n);
    node[4] = bd_node_next(node[3], n);
    node[5] = bd_node_next(node[4], n);
}

/* the weights at t from the powers of t and u = 1 − t (the basis is
 * symmetric, w_5−i(t) = w_i(u)): independent products, not six Horner
 * chains (3 % of bench_long_conveyor's time in perf) */
static void quintic_weights(double t, double w[6])
{
    const double u = 1.0 - t, c = 1.0 / 120.0;
    const double t2 = t * t, t3 = t2 * t, t4 = t2 * t2, t5 = t4 * t;
    const double u2 = u * u, u3 = u2 * u, u4 = u2 * u2, u5 = u4 * u;
    w[0] = c * u5;
    w[5] = c * t5;
    w[4] = c * (1.0 + 5.0 * (t + t4 - t5) + 10.0 * (t2 + t3));
    w[1] = c * (1.0 + 5.0 * (u + u4 - u5) + 10.0 * (u2 + u3));
    w[2] = c * (66.0 - 60.0 * t2 + 30.0 * t4 - 10.0 * t5);
    w[3] = c * (66.0 - 60.0 * u2 + 30.0 * u4 - 10.0 * u5);
}

/* the piece's coefficients in the power basis, times 120: 120·B(t) =
 * Σ_j p_j·t^j from one coordinate q of its six nodes (the polynomials
 * above, gathered) */
static void quintic_coefficients(const double *q, const int nd[6], double p[6])
{
    double x0 = q[nd[0]], x1 = q[nd[1]], x2 = q[nd[2]], x3 = q[nd[3]], x4 = q[nd[4]],
           x5 = q[nd[5]];
    double sa = x0 + x4, sb = x1 + x3, da = x4 - x0, db = x3 - x1;
    p[0] = sa + 26.0 * sb + 66.0 * x2;
    p[1] = 5.0 * da + 50.0 * db;
    p[2] = 10.0 * sa + 20.0 * sb - 60.0 * x2;
    p[3] = 10.0 * da - 20.0 * db;
    p[4] = 5.0 * sa - 20.0 * sb + 30.0 * x2;
    p[5] = x5 - x0 + 5.0 * (x1 - x4) + 10.0 * (x3 - x2);
}

static inline double quintic_value(const double p[6], double t)
{
    return p[0] + t * (p[1] + t * (p[2] + t * (p[3] + t * (p[4] + t * p[5]))));
}

/* Newton's step on (B − c)·B' = 0 at t, B from the coefficients of the
 * two coordinates (120·B: the factor cancels from (B·B')/(B'² + B·B'')) */
static double quintic_newton(const double px[6], const double py[6], double cx, double cy,
                             double t)
{
    const double *p[2] = {px, py};
    const double c[2] = {cx, cy};
    double B[2], D1[2], D2[2];
    const double t2 = t * t, t3 = t2 * t, t4 = t2 * t2, t5 = t4 * t;
    for (int a = 0; a < 2; a++) {
        const double *q = p[a];
        B[a] = (q[0] - 120.0 * c[a]) + q[1] * t + q[2] * t2 + q[3] * t3 + q[4] * t4 + q[5] * t5;
        D1[a] = q[1] + 2.0 * q[2] * t + 3.0 * q[3] * t2 + 4.0 * q[4] * t3 + 5.0 * q[5] * t4;
        D2[a] = 2.0 * q[2] + 6.0 * q[3] * t + 12.0 * q[4] * t2 + 20.0 * q[5] * t3;
    }
    double dB2 = D1[0] * D1[0] + D1[1] * D1[1];
    double h = dB2 + B[0] * D2[0] + B[1] * D2[1];
    /* h > 0 unless the roll sat inside the line's own curvature; the
     * tangent step then (as newton_step) */
    double den = h > 0.0 ? h : dB2;
    return den > 0.0 ? (B[0] * D1[0] + B[1] * D1[1]) / den : 0.0;
}

/* one Newton step along the quintic piece on element *ep from *tp, onto
 * the neighbouring piece when t leaves [0, 1]; the step's size, or 1 on
 * leaving the piece (as newton_step) */
static double quintic_step(const bd_sim *sim, double cx, double cy, int *ep, double *tp)
{
    const int n = sim->model->n;
    int nd[6];
    double px[6], py[6];
    quintic_nodes(n, *ep, nd);
    quintic_coefficients(sim->x, nd, px);
    quintic_coefficients(sim->y, nd, py);
    double step = quintic_newton(px, py, cx, cy, *tp);
    return onto_piece(n, *tp - step, step, ep, tp);
}

/* the quintic line's point at t on element e, from c, and its weights */
static void quintic_at(const bd_sim *sim, int e, double t, const double c[2], bd_idler_touch *pc,
                       double r[2])
{
    quintic_nodes(sim->model->n, e, pc->node);
    quintic_weights(t, pc->w);
    pc->count = 6;
    r[0] = -c[0];
    r[1] = -c[1];
    for (int q = 0; q < 6; q++) {
        r[0] += pc->w[q] * sim->x[pc->node[q]];
        r[1] += pc->w[q] * sim->y[pc->node[q]];
    }
}

/* the squared distance from c of the running line's point at t on piece
 * k (round node k on the quadratic line, on element k on the quintic) */
static double distance2(const bd_sim *sim, int quintic, int k, double t, const double c[2])
{
    bd_idler_touch scratch;
    double r[2];
    if (quintic)
        quintic_at(sim, k, t, c, &scratch, r);
    else
        piece_at(sim, k, t, c, &scratch, r);
    return r[0] * r[0] + r[1] * r[1];
}

/* more Newton steps from (k, t) along either line, to convergence; the
 * nearest of the points they pass. Rarely taken, and kept out of the hot
 * path: inlined into every idler's search it made bench_long_conveyor
 * 8 % slower */
__attribute__((noinline)) static void converge(const bd_sim *sim, const double c[2],
                                               int quintic, int *kp, double *tp)
{
    int k = *kp;
    double t = *tp, best = distance2(sim, quintic, k, t, c);
    for (int it = 0; it < NEAREST_STEPS; it++) {
        double step = quintic ? quintic_step(sim, c[0], c[1], &k, &t)
                              : newton_step(sim, c[0], c[1], &k, &t);
        double d2 = distance2(sim, quintic, k, t, c);
        if (d2 < best) {
            best = d2;
            *kp = k;
            *tp = t;
        }
        if (step < NEAREST_CONVERGED)
            break;
    }
}

/* How far the running line passes inside the corner of the belt's free
 * lines over a roll that turns it by φ: a node m takes the share w_m of
 * the roll's force and turns by φ·w_m, so the free lines meet over
 * Σ w_m·x_m and the line's point lies ½·φ·l0·Σ_jm w_j·w_m·|j − m| below
 * their corner (derived here, docs/physics.md §5) */
double bd_lumped_line_corner(double phi, double l0, int quintic)
{
    return 0.5 * (quintic ? QUINTIC_MEAN_DIFFERENCE : QUADRATIC_MEAN_DIFFERENCE) * phi * l0;
}

/* the quintic line's point nearest the roll's centre, by Newton steps from
 * the tracker's foot point, as nearest_point below */
static void quintic_nearest(const bd_sim *sim, const bd_idler *id, bd_idler_touch *pc)
{
    const double *c = id->m->centre;
    int e = id->tr.element;
    double t = id->tr.gamma, r[2];
    /* one step, and the point from the same coefficients: the usual case */
    double px[6], py[6];
    quintic_nodes(sim->model->n, e, pc->node);
    quintic_coefficients(sim->x, pc->node, px);
    quintic_coefficients(sim->y, pc->node, py);
    double step = quintic_newton(px, py, c[0], c[1], t);
    double t1 = t - step;
    if (fabs(step) <= NEAREST_ONE_STEP && t1 >= 0.0 && t1 <= 1.0) {
        quintic_weights(t1, pc->w);
        pc->count = 6;
        r[0] = quintic_value(px, t1) * (1.0 / 120.0) - c[0];
        r[1] = quintic_value(py, t1) * (1.0 / 120.0) - c[1];
    } else {
        quintic_step(sim, c[0], c[1], &e, &t);
        converge(sim, c, 1, &e, &t);
        quintic_at(sim, e, t, c, pc, r);
    }
    pc->d = sqrt(r[0] * r[0] + r[1] * r[1]);
    double inv_d = 1.0 / pc->d;
    pc->n[0] = r[0] * inv_d;
    pc->n[1] = r[1] * inv_d;
}

/* the point of the smoothed belt line nearest the roll's centre c, by
 * Newton steps from the point the tracker's foot point maps to. One step
 * is exact on a straight belt and off by the square of its size on a bent
 * one. That is all a belt running over its rolls needs, and a second step
 * in every idler's chain made bench_long_conveyor 15 % slower. A step
 * longer than NEAREST_ONE_STEP of the piece, or one onto a neighbouring
 * piece, is followed by more, to convergence, and the nearest of the
 * points they pass is kept (a roll inside a sharp corner converges only
 * slowly, and the steps may swing between two pieces). A belt falling
 * onto its rolls bends sharply at them, and there the point one step
 * found was on the wrong piece. A node then sank 0.85 mm into a roll
 * unseen, and the contact threw it out with 70 kN. The account had not
 * booked that energy as stored, so the dissipated energy fell: by
 * 5.2·10⁻⁵ of the energy scale in the first 0.6 s of generated seed 2089
 * at a 0.043 m element (started from rest), by 5.4·10⁻⁴ over torture's
 * 51 s (issue 10; tests/cli/falling_onto_rolls.sh). The normal then
 * turns smoothly as the nodes pass the roll. */
static void nearest_point(const bd_sim *sim, const bd_idler *id, bd_idler_touch *pc)
{
    if (id->m->line_quintic) {
        quintic_nearest(sim, id, pc);
        return;
    }
    const int n = sim->model->n;
    const double cx = id->m->centre[0], cy = id->m->centre[1];
    int e = id->tr.element, k;
    double t;
    if (id->tr.gamma >= 0.5) {
        k = bd_node_next(e, n);
        t = id->tr.gamma - 0.5;
    } else {
        k = e;
        t = id->tr.gamma + 0.5;
    }
    if (newton_step(sim, cx, cy, &k, &t) > NEAREST_ONE_STEP)
        converge(sim, id->m->centre, 0, &k, &t);
    double r[2];
    piece_at(sim, k, t, id->m->centre, pc, r);
    pc->d = sqrt(r[0] * r[0] + r[1] * r[1]);
    double inv_d = 1.0 / pc->d;
    pc->n[0] = r[0] * inv_d;
    pc->n[1] = r[1] * inv_d;
}

/* What the contact's spring holds at t (bd_energy `springs`), as the
 * account needs it: the linearly implicit force is the spring's at the end
 * of the step, f_k = k_c·δ_k+1, and its work is booked with the mid-step
 * velocity, −(δ_k+1 − δ_k−1)/2 per step, so the booked work less the change
 * of E_k = (f_k² + f_k−1²)/(4k_c) is k_c·(δ_k+1 − δ_k−1)²/4 ≥ 0 (derived
 * here, docs/physics.md §9): with this step's f²/(2k_c) alone the
 * dissipated energy still fell by millijoules as the belt settled on its
 * rolls (generated seeds 1162, 1403). e is f_n²/(2k_c) now. */
static void spring_energy(bd_sim *sim, bd_idler *id, double e)
{
    sim->energy.springs += 0.5 * (e + id->spring_energy);
    id->spring_energy = e;
}

/* count: the line's nodes, 3 or 6, a constant in each of the two calls
 * below (idler_contact), so that each loop is unrolled as the three
 * nodes' loop was before the quintic line */
static inline __attribute__((always_inline)) void
contact_on(bd_sim *sim, bd_idler *id, const bd_idler_touch *pc, const int count)
{
    id->alpha = 0.0;
    id->torque = 0.0;
    const bd_idler_model *im = id->m;
    const double d = pc->d, nx = pc->n[0], ny = pc->n[1];
    if (d - im->contact_radius <= BD_LIFT_OFF_LANDED)
        id->landed = 1;
    if (d >= im->contact_radius + IDLER_CONTACT_GAP * sim->model->l0) {
        note_lifted(sim, id, d);
        spring_energy(sim, id, 0.0);
        return;
    }
    const int *nd = pc->node;
    const double *w = pc->w;
    /* w_m/m_m from dt/m (no division in the step; Δt taken out once);
     * the acceleration the other forces give the contact point, along the
     * normal and the tangent */
    const double tx0 = -ny, ty0 = nx, inv_dt = sim->model->inv_dt;
    double vcx = 0.0, vcy = 0.0, inv_m_eff = 0.0, acx = 0.0, acy = 0.0;
    for (int q = 0; q < count; q++) {
        int m = nd[q];
        double wm = w[q] * sim->dt_per_mass[m];
        vcx += w[q] * sim->vx[m];
        vcy += w[q] * sim->vy[m];
        inv_m_eff += w[q] * wm;
        acx += wm * sim->fx[m];
        acy += wm * sim->fy[m];
    }
    inv_m_eff *= inv_dt;
    acx *= inv_dt;
    acy *= inv_dt;
    double aon = nx * acx + ny * acy, aot = tx0 * acx + ty0 * acy;
    double dt = sim->model->dt, delta = im->contact_radius - d;
    double fn = im->k_contact * (delta - dt * (nx * vcx + ny * vcy) - dt * dt * aon)
              / (1.0 + im->k_contact * dt * dt * inv_m_eff);
    if (fn <= 0.0) {
        note_lifted(sim, id, d);
        spring_energy(sim, id, 0.0);
        return;
    }
    /* tangent along the travel direction */
    double tx = tx0, ty = ty0;
    if (tx * id->tr.dir[0] + ty * id->tr.dir[1] < 0.0) {
        tx = -tx;
        ty = -ty;
        aot = -aot;
    }
    double vt = tx * vcx + ty * vcy;
    double sat = vt * (1.0 / BD_ROLLING_SPEED);
    if (sat > 1.0)
        sat = 1.0;
    if (sat < -1.0)
        sat = -1.0;
    double frr = im->rolling * fn * sat;
    /* the stick force (eq 4.113 with the weights), with the rolling
     * resistance's share of the contact point's tangential acceleration
     * (−frr·Σ w_m²/m_m, derived here; the normal force has none) */
    double R = im->radius;
    double vr = vt - id->omega * R;
    double ft = aot - frr * inv_m_eff;
    double f = (vr * sim->model->inv_dt + ft) / (inv_m_eff + im->r2_per_inertia);
    if (fabs(f) > im->mu_s * fn)
        f = copysign(im->mu_d * fn, f);
    /* normal, rolling resistance and friction on the line's nodes, all
     * non-conservative */
    double Fx = fn * nx - (frr + f) * tx, Fy = fn * ny - (frr + f) * ty;
    for (int q = 0; q < count; q++) {
        int m = nd[q];
        sim->fx[m] += w[q] * Fx;
        sim->fy[m] += w[q] * Fy;
        sim->fnx[m] += w[q] * Fx;
        sim->fny[m] += w[q] * Fy;
    }
    id->torque = f * R;
    id->alpha = id->torque * im->inv_inertia;
    spring_energy(sim, id, fn * fn * im->half_per_k);
}

static void idler_contact(bd_sim *sim, bd_idler *id, const bd_idler_touch *pc)
{
    if (pc->count == 6)
        contact_on(sim, id, pc, 6);
    else
        contact_on(sim, id, pc, 3);
}

/* the supports phase for the idlers listed only (belt/rfe: those no long
 * section carries), whose trackers the caller has updated */
void bd_lumped_idlers_listed(bd_sim *sim, const int *list, int count)
{
    bd_idler_touch *touch = bd_lumped_of(sim)->touch;
    /* two passes of short bodies, so that the processor overlaps the
     * idlers' independent division and square-root chains */
    for (int k = 0; k < count; k++)
        nearest_point(sim, &sim->idlers[list[k]], &touch[list[k]]);
    for (int k = 0; k < count; k++)
        idler_contact(sim, &sim->idlers[list[k]], &touch[list[k]]);
}

void bd_lumped_idler_release(bd_sim *sim, int i)
{
    bd_idler *id = &sim->idlers[i];
    id->alpha = 0.0;
    id->torque = 0.0;
    spring_energy(sim, id, 0.0);
}

/* the supports phase: every idler, after the wraps; where each touches
 * the belt first (positions only: the idlers' iterations overlap), then
 * the forces */
void bd_lumped_idlers(bd_sim *sim)
{
    /* the lumped belt's own loop, without the test for carried idlers
     * (with it bench_long_conveyor ran 3.7 % slower) */
    bd_idler_touch *touch = bd_lumped_of(sim)->touch;
    const int count = sim->model->idler_count;
    for (int i = 0; i < count; i++)
        bd_tracker_update(sim, &sim->idlers[i].tr);
    for (int i = 0; i < count; i++)
        nearest_point(sim, &sim->idlers[i], &touch[i]);
    for (int i = 0; i < count; i++)
        idler_contact(sim, &sim->idlers[i], &touch[i]);
}


