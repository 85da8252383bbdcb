/* Belt–pulley contact (seed 001 §4.3.1): penalty contact of belt nodes with
 * the pulley shell and stick–slip friction by the stick-force method.
 *
 * Normal: a node at distance a < R from the centre is pushed out along
 * n̂ = (x − x_p)/a by a penalty spring (eqs 4.70–4.75; our k_c is in N/m).
 * The tension presses the shell through the wrapped elements' arcs
 * (wrap_elements.c), not through the nodes, so the spring holds only a
 * node's weight and inertia; it is stiff (k_c = 100·EA/l0), far stiffer
 * than the belt, so it is taken linearly implicit: the force is the one the spring has at the end of the
 * step, given the node's other forces F_o and its velocity,
 *   f_n = k_c·(δ − Δt·v_n − Δt²·F_o,n/m) / (1 + k_c·Δt²/m)  ≥ 0,
 * stable for any k_c. A node just off the shell (δ < 0) is in contact when
 * this force is positive: it would reach the shell during the step. Without
 * that, nodes resting on the shell chatter in and out of contact and the
 * belt creeps on the pulley for want of friction. The whole of f_n is
 * booked as non-conservative work, and what the spring holds,
 * (f_k² + f_k−1²)/(4k_c) of this step's and the last one's force, as
 * potential energy (bd_energy `springs`): f_k is the spring's force at the
 * end of the step, k_c·δ_k+1, and its work is booked with the mid-step
 * velocity, so the booked work less that energy's change is
 * k_c·(δ_k+1 − δ_k−1)²/4 ≥ 0 (docs/physics.md §9). Until issue 10 the
 * spring's own force k_c·δ_k was conservative with ½k_c·δ_k² and only the
 * rest of f_n non-conservative: on belts settling from a static start the
 * rest put 0.1 W into the belt (the dissipated energy fell, seed 1403).
 *
 * Friction: t̂ points the way the belt travels at the node: wrap·perp(n̂)
 * on the shell or where the shell pushes the node, and off the shell
 * otherwise (a node carrying a share of a wrapped arc's pressure, below)
 * along the tangent line from the node to the shell,
 *   t̂ = (R·wrap·perp(n̂) ∓ L·n̂)/a,   L = √(a² − R²)
 * (− before the arc, + after it), the line the wrapped element runs along
 * (wrap_elements.c; derived here, plane geometry of a tangent to a circle,
 * docs/physics.md §4). Until issue 10 an off-shell node took the shell's
 * tangent at its own angle, which leans by acos(R/a) from its path: the
 * stick force held its speed along that line to the shell's, which a node
 * running down the tangent line never has, so it slipped and dragged on
 * every pulley in turn (generated empty belts: 40 W at each idle pulley,
 * seed 1058 16 % above its law). Where the shell pushes the node its
 * tangent is kept: there the spring acts, solved before the friction, and
 * a friction with a part along the normal pushed the node against it (the
 * dissipated energy fell at a start); such a node is at most a step's
 * travel off the shell, where the two lines differ by a few mrad. Until
 * late in issue 10 every node within the predictive gap (2 % of l0) took the
 * shell's tangent, pushed or not: on 30° elements a node running down its
 * tangent line is inside that gap for its last 28 % of an element, where
 * the line leans up to 8° from the shell's tangent; the stick force held
 * v·cos β to R·ω there, every step, and dragged (about 1.7 N of running
 * force at each idle pulley of seed 7270 at 24 kN, +5.7 % above its law in
 * all; −0.6 % now; seed 1058 +3.2 %, now 0 %). The slip speed is
 * v_r = t̂·(v_i − v_p) − R·ω (eq 4.78); the moment of the force about the
 * centre is R·f on either line. The stick force f_i
 * (on the node −f_i·t̂, on the pulley +f_i·R as torque) is the one that makes
 * every sticking node's v_r zero at the end of the step, given the other
 * forces F_i on the nodes and the external torque T_p on the pulley
 * (eqs 4.84–4.92); on a pulley whose axle stays put:
 *   α = (R·A + R·F_k + T_p)/(I + R²·M),   A = Σ_S (m_i·v_r,i/Δt + t̂·F_i),
 *   f_i = m_i·(v_r,i/Δt − R·α) + t̂·F_i   for sticking nodes S,
 * with M = Σ_S m_i and F_k = Σ of the dynamic forces of slipping nodes.
 * A node whose |f_i| exceeds μ_s·f_n slips with f_i = ±μ_d·f_n (4.93–4.94)
 * and the sticking set is solved again. Since issue 10 the belt's tension
 * presses on the shell through the elements round it (wrap_elements.c),
 * whose arcs' pressure each node's friction carries its lever-rule share
 * of: the friction limit is μ·(f_n + that share), and a node off the shell
 * with a share takes part in the solve with f_n = 0. α is the pulley's angular
 * acceleration (I·α = R·Σf + T_p); it is exact for I → 0 too. A takeup
 * pulley's carriage is a second unknown, solved with α (solve() below;
 * 4.84 neglects the pulley's translation). */
#include "belt/lumped/lumped.h"

#include <math.h>

#include "parts/parts.h"

#include "base/constants.h"

/* Which nodes are tested: every node of the wrap's sector, every step.
 * The sector is the arc's angle widened on each side by SECTOR_MARGIN_DEG
 * plus two elements' angle (the tangent points move as spans swing and a
 * takeup travels), out to SECTOR_REACH_ELEMENTS element lengths beyond
 * the shell. The belt passes through it as one run of consecutive nodes;
 * the step finds it from the node nearest the arc's middle (the anchor,
 * which moves by at most a node or two per step) by walking out to both
 * ends of the run: O(nodes in the sector). Until issue 10 only last step's
 * contact set ± 3 nodes was tested: when a wrap unloaded the window shrank
 * and regrew 3 nodes per step, nodes outside it sank 15–46 mm into the
 * shell unseen and were then thrown out by a force 200× the wrap's normal
 * load, and the run diverged. The contact energy is summed over the same
 * nodes. */
#define SECTOR_MARGIN_DEG 15.0
#define SECTOR_REACH_ELEMENTS 2.0
/* predictive contact gap, as a fraction of the element length */
#define CONTACT_GAP 0.02

static bd_wrap_contact *wrap_of(const bd_sim *sim, const bd_pulley_body *p)
{
    return &bd_lumped_of(sim)->wraps[p - sim->pulleys];
}

static const bd_wrap_sector *sector_of(const bd_sim *sim, const bd_pulley_body *p)
{
    return &bd_lumped_model_of(sim)->sectors[p - sim->pulleys];
}

void bd_lumped_sector_init(bd_sim *sim, int pulley, bd_wrap_sector *S)
{
    const bd_path_segment *arc = bd_path_arc(&sim->model->path, pulley);
    const double R = arc->radius, l0 = sim->model->l0;
    double mid = arc->angle0 + 0.5 * arc->sweep;
    S->mid[0] = cos(mid);
    S->mid[1] = sin(mid);
    double half = 0.5 * fabs(arc->sweep) + SECTOR_MARGIN_DEG * BD_DEG + 2.0 * l0 / R;
    S->cos_limit = half >= BD_PI ? -2.0 : cos(half);
    S->reach = R + SECTOR_REACH_ELEMENTS * l0;
    /* no more than the belt has, so the run's walks (bd_lumped_find_sector)
     * never take a node twice (compared in double: an absurd l0 would
     * overflow the int) */
    double most = ceil(2.0 * half * S->reach / l0) + 8.0;
    S->node_max = most < (double)sim->model->n ? (int)most : sim->model->n;
}

/* the node nearest the arc's middle, once by a full search (the belt laid) */
void bd_lumped_sector_anchor(bd_sim *sim, int pulley, bd_wrap_contact *W)
{
    const bd_pulley_body *p = &sim->pulleys[pulley];   /* a takeup's centre as laid */
    const bd_wrap_sector *S = sector_of(sim, p);
    const double R = p->m->radius;
    double mx = p->cx + R * S->mid[0], my = p->cy + R * S->mid[1];
    double best = INFINITY;
    for (int k = 0; k < sim->model->n; k++) {
        double d = hypot(sim->x[k] - mx, sim->y[k] - my);
        if (d < best) {
            best = d;
            W->anchor = k;
        }
    }
}

int bd_lumped_in_sector(const bd_sim *sim, const bd_pulley_body *p, int k)
{
    const bd_wrap_sector *S = sector_of(sim, p);
    double rx = sim->x[k] - p->cx, ry = sim->y[k] - p->cy;
    double a2 = rx * rx + ry * ry;
    if (a2 >= S->reach * S->reach)
        return 0;
    double c = rx * S->mid[0] + ry * S->mid[1];   /* a·cos(angle to mid) */
    if (S->cos_limit >= 0.0)
        return c >= 0.0 && c * c >= S->cos_limit * S->cos_limit * a2;
    return c >= S->cos_limit * sqrt(a2);
}

/* the node nearest the arc's middle, from the last one; then the run of
 * sector nodes through it: *first and *count (count ≤ node_max) */
int bd_lumped_find_sector(const bd_sim *sim, const bd_pulley_body *p, const bd_wrap_contact *W,
                          int *first, int *count)
{
    const int n = sim->model->n;
    const bd_wrap_sector *S = sector_of(sim, p);
    double mx = p->cx + p->m->radius * S->mid[0], my = p->cy + p->m->radius * S->mid[1];
    int a = W->anchor;
    double da = hypot(sim->x[a] - mx, sim->y[a] - my);
    for (int it = 0; it < n; it++) {
        int f = bd_node_next(a, n), b = bd_node_prev(a, n);
        double df = hypot(sim->x[f] - mx, sim->y[f] - my);
        double db = hypot(sim->x[b] - mx, sim->y[b] - my);
        if (df < da && df <= db) {
            a = f;
            da = df;
        } else if (db < da) {
            a = b;
            da = db;
        } else {
            break;
        }
    }
    int lo = a, c = 1;
    while (c < S->node_max) {
        int b = bd_node_prev(lo, n);
        if (!bd_lumped_in_sector(sim, p, b))
            break;
        lo = b;
        c++;
    }
    for (int k = bd_node_next(a, n); c < S->node_max; k = bd_node_next(k, n)) {
        if (!bd_lumped_in_sector(sim, p, k))
            break;
        c++;
    }
    *first = lo;
    *count = c;
    return a;
}

/* a candidate's state in the solve (c_state) */
#define STICKING 0
#define SLIPPING_FORWARD 1     /* slips, friction +μ_d·f_n */
#define SLIPPING_BACK (-1)     /* slips, friction −μ_d·f_n */
#define OFF 2                  /* no normal force and no arc share */
/* passes of the carriage's contact set (moving takeups only): the set is
 * the one its acceleration A gives; one pass more when A changes it */
#define CARRIAGE_PASSES 4

/* The candidates: every node of the sector's run within the predictive gap
 * of the shell or carrying a share of a wrapped arc's pressure (its
 * friction's normal, c_arc), with the normal force it gets as a function of the
 * carriage's acceleration A this step (0 for a pulley that does not
 * move): the shell then ends the step at a velocity larger by Δt·A along
 * the axis a, so the node's end-of-step gap closes by Δt²·A·(n̂·a) more,
 *   f_n = f_n0 + g·A,   g = k_c·Δt²·(n̂·a)/(1 + k_c·Δt²/m)
 * (derived here from seed 001's penalty contact, eqs 4.70–4.75, taken
 * linearly implicit, with the shell's motion added; docs/physics.md §4).
 * Until issue 10 the shell's end-of-step velocity was taken with the last
 * step's acceleration and the carriage got the reaction explicitly: a lag
 * that feeds the belt's mass on the wrap back against the carriage's, a
 * negative damping of the takeup mode (a 10 kg carriage's run booked
 * 88 kW of phantom dissipation; test_takeup_step). */
static void gather(bd_sim *sim, bd_pulley_body *p, int moving)
{
    bd_wrap_contact *W = wrap_of(sim, p);
    const double l0 = sim->model->l0, k_c = bd_lumped_model_of(sim)->k_contact;
    const double dt = sim->model->dt;
    const int n = sim->model->n;
    const double R = p->m->radius, ax = p->m->axis[0], ay = p->m->axis[1];
    /* predictive contact: a node within this gap of the shell may reach it
     * during the step; the implicit force says whether it does */
    double Rc = R + CONTACT_GAP * l0;
    /* the shell's velocity at the start of the step (central differences:
     * the carriage's, as the nodes', at t − Δt/2) */
    double vpx = p->qdot * ax, vpy = p->qdot * ay;
    W->contact_count = 0;
    /* the sector's run, found in the forces phase (wrap_elements.c) */
    const int first = W->run_first, count = W->run_count;
    const double *mid = sector_of(sim, p)->mid;
    for (int w = 0, k = first; w < count; w++, k = bd_node_next(k, n)) {
        /* the run's share of the wrapped arcs' pressure (wrap_elements.c) */
        double arc = W->run_arc[w];
        double rx = sim->x[k] - p->cx, ry = sim->y[k] - p->cy;
        double a2 = rx * rx + ry * ry;
        int near = a2 < Rc * Rc;
        if (!near && arc <= 0.0)
            continue;
        double a = sqrt(a2);
        double nx = rx / a, ny = ry / a;
        double delta = R - a, fn0 = -1.0, g = 0.0;
        if (near) {
            double vn = nx * (sim->vx[k] - vpx) + ny * (sim->vy[k] - vpy);   /* v_n − v_p,n */
            double m = sim->mass[k];
            double Fo = nx * sim->fx[k] + ny * sim->fy[k];
            double den = 1.0 + k_c * dt * dt / m;
            fn0 = k_c * (delta - dt * vn - dt * dt * Fo / m) / den;
            g = moving ? k_c * dt * dt * (nx * ax + ny * ay) / den : 0.0;
        }
        if (!moving && fn0 <= 0.0 && arc <= 0.0)
            continue;
        int c = W->contact_count++;
        W->c_node[c] = k;
        W->c_fn0[c] = fn0;
        W->c_g[c] = g;
        W->c_arc[c] = arc;
        W->c_nx[c] = nx;
        W->c_ny[c] = ny;
        /* the belt's direction at the node: the shell's tangent on it or
         * where the shell pushes it (so that its friction has no part
         * along the normal, which the spring above did not see), else the
         * tangent line from the node to the shell (the way the wrapped
         * element runs, wrap_elements.c), towards the shell before the
         * arc's middle and away from it after */
        double tx = -p->m->wrap * ny, ty = p->m->wrap * nx;
        if (a > R && !(fn0 > 0.0)) {
            double L = sqrt(a2 - R * R);
            double side = p->m->wrap * (mid[0] * ny - mid[1] * nx) < 0.0 ? -1.0 : 1.0;
            tx = (R * tx + side * L * nx) / a;
            ty = (R * ty + side * L * ny) / a;
        }
        W->c_tx[c] = tx;
        W->c_ty[c] = ty;
    }
}

/* the contact springs' energy at t (bd_energy `springs`): the mean of
 * this step's Σ f_n²/(2k_c), e, and the last step's (the file's header) */
static void spring_energy(bd_sim *sim, bd_wrap_contact *W, double e)
{
    sim->energy.springs += 0.5 * (e + W->spring_e);
    W->spring_e = e;
}

/* The wrap's stick–slip solve, the carriage with it. Unknowns: the
 * pulley's α and the carriage's A. A sticking node's friction is the one
 * that makes its slip speed zero at the end of the step, the shell's
 * surface there moving at t̂·a·(q̇ + Δt·A) + R·(ω + Δt·α):
 *   f_i = b_i − m_i·R·α − m_i·d_i·A,   b_i = m_i·v_r,i/Δt + t̂·F_i,  d_i = t̂·a;
 * a slipping one's is σ_i·μ_d·(f_n0 + g_i·A + arc_i), the shell's push
 * counted only while it pushes. The pulley and the carriage:
 *   I_s·α = T_p + R·Σ f_i,
 *   M_c·A = P + Σ (f_i·d_i − f_n,i·(n̂·a)),
 * two linear equations, solved exactly (Cramer); seed 001 eqs 4.84–4.94
 * for the pulley alone, the carriage row derived here (docs/physics.md §4).
 * A node whose |f_i| passes
 * μ_s·(f_n + arc_i) slips and the set is solved again; on a moving carriage the
 * contact set is the one A gives, solved again when A changes it. */
static void solve(bd_sim *sim, bd_pulley_body *p, double T_p, double P, double Mc)
{
    bd_wrap_contact *W = wrap_of(sim, p);
    const double dt = sim->model->dt, R = p->m->radius;
    const double ax = p->m->axis[0], ay = p->m->axis[1];
    const double vpx = p->qdot * ax, vpy = p->qdot * ay;
    const int nc = W->contact_count;
    const int moving = Mc > 0.0;
    double alpha = 0.0, A = moving ? p->qddot : 0.0;
    for (int outer = 0; outer < CARRIAGE_PASSES; outer++) {
        for (int c = 0; c < nc; c++) {
            double fn = W->c_fn0[c] + W->c_g[c] * A;
            W->c_press[c] = fn > 0.0;
            W->c_state[c] = fn > 0.0 || W->c_arc[c] > 0.0 ? STICKING : OFF;
        }
        for (int pass = 0; pass <= nc; pass++) {
            /* [a11 a12; a21 a22]·(α, A) = (r1, r2), r1 without T_p */
            double Asum = 0.0, M = 0.0, Fk = 0.0;
            double a12 = 0.0, a21 = 0.0, a22 = Mc, r2 = P;
            for (int c = 0; c < nc; c++) {
                int st = W->c_state[c];
                if (st == OFF)
                    continue;
                int k = W->c_node[c];
                double d = W->c_tx[c] * ax + W->c_ty[c] * ay;
                /* n̂·a, the shell's normal along the axis */
                double cn = W->c_nx[c] * ax + W->c_ny[c] * ay;
                const int press = W->c_press[c];
                if (press) {
                    r2 -= W->c_fn0[c] * cn;
                    a22 += W->c_g[c] * cn;
                }
                if (st == STICKING) {
                    double vr = W->c_tx[c] * (sim->vx[k] - vpx) + W->c_ty[c] * (sim->vy[k] - vpy)
                              - R * p->omega;
                    double b = sim->mass[k] * vr / dt + W->c_tx[c] * sim->fx[k]
                             + W->c_ty[c] * sim->fy[k];
                    Asum += b;
                    M += sim->mass[k];
                    a12 += R * sim->mass[k] * d;
                    a21 += R * sim->mass[k] * d;
                    a22 += sim->mass[k] * d * d;
                    r2 += d * b;
                } else {
                    /* μ_d·(f_n + arc), f_n = f_n0 + g·A while the shell
                     * pushes the node */
                    double s = st * p->m->mu_d;
                    double f0 = (press ? W->c_fn0[c] : 0.0) + W->c_arc[c];
                    double gA = press ? W->c_g[c] : 0.0;
                    Fk += s * f0;
                    a12 -= R * s * gA;
                    a22 -= d * s * gA;
                    r2 += d * s * f0;
                }
            }
            double a11 = bd_pulley_solve_inertia(sim, p) + R * R * M;
            double r1 = R * Asum + R * Fk + T_p;
            if (p->held) {
                /* a held pulley (stabilization's holdback) does not turn */
                alpha = 0.0;
                A = moving ? r2 / a22 : 0.0;
            } else if (!moving) {
                alpha = r1 / a11;
                A = 0.0;
            } else {
                double det = a11 * a22 - a12 * a21;
                alpha = (r1 * a22 - a12 * r2) / det;
                A = (a11 * r2 - a21 * r1) / det;
            }
            /* a drive that would pass its max_torque: at the limit, solve
             * again (once: it is explicit then) */
            if (!p->held && bd_pulley_drive_clip(sim, p, alpha, &T_p)) {
                pass--;
                continue;
            }
            int changed = 0;
            for (int c = 0; c < nc; c++) {
                if (W->c_state[c] != STICKING)
                    continue;
                int k = W->c_node[c];
                double d = W->c_tx[c] * ax + W->c_ty[c] * ay;
                double vr = W->c_tx[c] * (sim->vx[k] - vpx) + W->c_ty[c] * (sim->vy[k] - vpy)
                          - R * p->omega;
                double f = sim->mass[k] * (vr / dt - R * alpha - d * A)
                         + W->c_tx[c] * sim->fx[k] + W->c_ty[c] * sim->fy[k];
                W->c_f[c] = f;
                double fn = W->c_fn0[c] + W->c_g[c] * A;
                double N = (W->c_press[c] ? fn : 0.0) + W->c_arc[c];
                if (fabs(f) > p->m->mu_s * N) {
                    W->c_state[c] = f > 0.0 ? SLIPPING_FORWARD : SLIPPING_BACK;
                    changed = 1;
                }
            }
            if (!changed)
                break;
        }
        if (!moving)
            break;
        /* the contact set A gives: the same as solved, or once more */
        int same = 1;
        for (int c = 0; c < nc && same; c++)
            same = (W->c_fn0[c] + W->c_g[c] * A > 0.0) == W->c_press[c];
        if (same)
            break;
    }
    /* apply, and keep only the nodes the shell pushes or whose friction
     * carries an arc's share (c_node; the material's discharge reads them,
     * so material leaves a node up to an element before the tangent point
     * when the element entering the wrap runs round it) */
    double sum = 0.0;
    int kept = 0;
    const double half_per_k = 0.5 / bd_lumped_model_of(sim)->k_contact;
    double spring_e = 0.0;
    /* the wrapped elements' arcs press on the shell directly (wrap_elements.c) */
    p->f_axis = W->react[0] * ax + W->react[1] * ay;
    p->fnc_axis = W->react_d[0] * ax + W->react_d[1] * ay;
    for (int c = 0; c < nc; c++) {
        int st = W->c_state[c];
        /* exactly the set solved for α and A (when the carriage passes ran
         * out, a node may end with f_n ≤ 0: skipping it would put on the
         * nodes other forces than the pulley and carriage were solved with) */
        double fn = W->c_press[c] ? W->c_fn0[c] + W->c_g[c] * A : 0.0;
        if (st == OFF)
            continue;
        int k = W->c_node[c];
        double tx = W->c_tx[c], ty = W->c_ty[c];
        double nx = W->c_nx[c], ny = W->c_ny[c];
        double f = st == STICKING ? W->c_f[c] : st * p->m->mu_d * (fn + W->c_arc[c]);
        sim->fx[k] += fn * nx - f * tx;
        sim->fy[k] += fn * ny - f * ty;
        sim->fnx[k] += fn * nx - f * tx;
        sim->fny[k] += fn * ny - f * ty;
        double cn = nx * ax + ny * ay, d = tx * ax + ty * ay;
        p->f_axis += f * d - fn * cn;
        p->fnc_axis += f * d - fn * cn;
        spring_e += fn * fn * half_per_k;
        sum += f;
        W->c_node[kept++] = k;
    }
    W->contact_count = kept;
    spring_energy(sim, W, spring_e);
    p->torque_friction = R * sum;
    p->alpha = alpha;
}

void bd_lumped_wrap(bd_sim *sim, bd_pulley_body *p, double external_torque)
{
    /* the carriage's pull and mass (0: it does not move this step), with
     * what the wrapped elements' arcs press on the shell (wrap_elements.c) */
    double Mc;
    bd_wrap_contact *W = wrap_of(sim, p);
    const double react = W->react[0] * p->m->axis[0] + W->react[1] * p->m->axis[1];
    const double P = bd_pulley_carriage(sim, p, &Mc) + react;
    gather(sim, p, Mc > 0.0);
    p->torque_friction = 0.0;
    if (W->contact_count == 0) {
        spring_energy(sim, W, 0.0);
        p->f_axis = react;
        p->fnc_axis = W->react_d[0] * p->m->axis[0] + W->react_d[1] * p->m->axis[1];
        p->alpha = p->held ? 0.0 : external_torque / bd_pulley_solve_inertia(sim, p);
        if (!p->held && bd_pulley_drive_clip(sim, p, p->alpha, &external_torque))
            p->alpha = external_torque / bd_pulley_solve_inertia(sim, p);
        return;
    }
    solve(sim, p, external_torque, P, Mc);
}
