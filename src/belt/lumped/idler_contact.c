/* Belt–idler contact (seed 001 §4.3.2, changed by issue 10): an idler
 * presses on the belt's smoothed line at the point nearest its centre.
 *
 * The smoothed line: round node k, the quadratic Bézier from the middle of
 * element k − 1 through the corner at node k to the middle of element k
 * (piece_at below); the pieces meet with one tangent. Seed 001 presses
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
 * clearance that counts as lift-off (system.h) */
static void note_lifted(bd_sim *sim, const bd_idler *id, double d)
{
    if (d - id->m->radius > BD_LIFT_OFF_CLEARANCE && !sim->stabilizing)
        bd_lift_off_note(sim, id->m->s);
}

/* the belt's smoothed line round node k: the quadratic Bézier from the
 * middle of element k − 1 (t = 0) through the corner at node k to the
 * middle of element k (t = 1); the pieces of neighbouring nodes meet at
 * the element middles with one tangent (C1). The weights of nodes k − 1,
 * k, k + 1 in its point at t, and that point from c. Derived here
 * (docs/physics.md §5). */
static void piece_at(const bd_sim *sim, int k, double t, const double c[2], bd_idler_touch *pc,
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
    r[0] = pc->w[0] * sim->x[a] + pc->w[1] * sim->x[k] + pc->w[2] * sim->x[b] - c[0];
    r[1] = pc->w[0] * sim->y[a] + pc->w[1] * sim->y[k] + pc->w[2] * sim->y[b] - c[1];
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
    t -= step;
    /* past the piece's end: onto the neighbouring piece, the previous
     * one's end or the next one's start (where the two pieces meet) */
    if (t < 0.0) {
        *kp = a;
        *tp = t + 1.0 < 0.0 ? 0.0 : t + 1.0;
        return 1.0;
    }
    if (t > 1.0) {
        *kp = b;
        *tp = t - 1.0 > 1.0 ? 1.0 : t - 1.0;
        return 1.0;
    }
    *tp = t;
    return fabs(step);
}

/* the squared distance from c of the smoothed line's point at t on the
 * piece round node k */
static double distance2(const bd_sim *sim, int k, double t, const double c[2])
{
    bd_idler_touch scratch;
    double r[2];
    piece_at(sim, k, t, c, &scratch, r);
    return r[0] * r[0] + r[1] * r[1];
}

/* more Newton steps from (k, t), to convergence; the nearest of the
 * points they pass. Rarely taken, and kept out of the hot path: inlined
 * into every idler's search it made bench_long_conveyor 8 % slower */
__attribute__((noinline)) static void converge(const bd_sim *sim, const double c[2], int *kp,
                                               double *tp)
{
    int k = *kp;
    double t = *tp, best = distance2(sim, k, t, c);
    for (int it = 0; it < NEAREST_STEPS; it++) {
        double step = newton_step(sim, c[0], c[1], &k, &t);
        double d2 = distance2(sim, k, t, c);
        if (d2 < best) {
            best = d2;
            *kp = k;
            *tp = t;
        }
        if (step < NEAREST_CONVERGED)
            break;
    }
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
        converge(sim, id->m->centre, &k, &t);
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

static void idler_contact(bd_sim *sim, bd_idler *id, const bd_idler_touch *pc)
{
    id->alpha = 0.0;
    id->torque = 0.0;
    const bd_idler_model *im = id->m;
    const double d = pc->d, nx = pc->n[0], ny = pc->n[1];
    if (d >= im->radius + IDLER_CONTACT_GAP * sim->model->l0) {
        note_lifted(sim, id, d);
        spring_energy(sim, id, 0.0);
        return;
    }
    const int *nd = pc->node;
    const double *w = pc->w;
    /* w_m/m_m from dt/m (no division in the step); the tangential
     * acceleration the other forces give the contact point */
    const double tx0 = -ny, ty0 = nx;
    double vcx = 0.0, vcy = 0.0, inv_m_eff = 0.0, aon = 0.0, aot = 0.0;
    for (int q = 0; q < 3; q++) {
        int m = nd[q];
        double wm = w[q] * sim->dt_per_mass[m] * sim->model->inv_dt;
        vcx += w[q] * sim->vx[m];
        vcy += w[q] * sim->vy[m];
        inv_m_eff += w[q] * wm;
        aon += wm * (nx * sim->fx[m] + ny * sim->fy[m]);
        aot += wm * (tx0 * sim->fx[m] + ty0 * sim->fy[m]);
    }
    double dt = sim->model->dt, delta = im->radius - d;
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
    /* normal, rolling resistance and friction on the three nodes, all
     * non-conservative */
    double Fx = fn * nx - (frr + f) * tx, Fy = fn * ny - (frr + f) * ty;
    for (int q = 0; q < 3; q++) {
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


