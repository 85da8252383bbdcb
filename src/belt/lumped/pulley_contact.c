/* Belt–pulley contact (seed 001 §4.3.1): penalty contact of belt nodes with
 * the pulley shell and stick–slip friction by the stick-force method.
 *
 * Normal: a node at distance a < R from the centre is pushed out along
 * n̂ = (x − x_p)/a by a penalty spring (eqs 4.70–4.75; our k_c is in N/m).
 * The spring must be stiff: a wrapped node sinks δ = T·l/(R·k_c), which
 * shortens its chords by δ/R and so lowers the tension on the wrap by
 * EA·δ/R = T·(l/R)²·(EA/l)/k_c. With k_c = 100·EA/l0 that is 0.3% of T for
 * 30° elements. Such a spring is far stiffer than the belt, so it is taken
 * linearly implicit: the force is the one the spring has at the end of the
 * step, given the node's other forces F_o and its velocity,
 *   f_n = k_c·(δ − Δt·v_n − Δt²·F_o,n/m) / (1 + k_c·Δt²/m)  ≥ 0,
 * stable for any k_c. A node just off the shell (δ < 0) is in contact when
 * this force is positive: it would reach the shell during the step. Without
 * that, nodes resting on the shell chatter in and out of contact and the
 * belt creeps on the pulley for want of friction. The spring's own force
 * k_c·δ is conservative (½k_cδ² is potential energy); the rest of f_n, what
 * the implicit step adds to stop the node, is booked as non-conservative.
 *
 * Friction: tangent t̂ = wrap·perp(n̂) points the way the belt travels;
 * the slip speed is v_r = t̂·(v_i − v_p) − R·ω (eq 4.78). The stick force f_i
 * (on the node −f_i·t̂, on the pulley +f_i·R as torque) is the one that makes
 * every sticking node's v_r zero at the end of the step, given the other
 * forces F_i on the nodes and the external torque T_p on the pulley
 * (eqs 4.84–4.92, with the pulley's translation neglected as in 4.84):
 *   α = (R·A + R·F_k + T_p)/(I + R²·M),   A = Σ_S (m_i·v_r,i/Δt + t̂·F_i),
 *   f_i = m_i·(v_r,i/Δt − R·α) + t̂·F_i   for sticking nodes S,
 * with M = Σ_S m_i and F_k = Σ of the dynamic forces of slipping nodes.
 * A node whose |f_i| exceeds μ_s·f_n slips with f_i = ±μ_d·f_n (4.93–4.94)
 * and the sticking set is solved again. α is the pulley's angular
 * acceleration (I·α = R·Σf + T_p); it is exact for I → 0 too. */
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
    S->node_max = (int)ceil(2.0 * half * S->reach / l0) + 8;
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
    W->win_first = W->anchor;
    W->win_count = 0;
}

static int in_sector(const bd_sim *sim, const bd_pulley_body *p, const bd_wrap_sector *S, int k)
{
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
static int find_sector(const bd_sim *sim, const bd_pulley_body *p, const bd_wrap_contact *W,
                       int *first, int *count)
{
    const int n = sim->model->n;
    const bd_wrap_sector *S = sector_of(sim, p);
    double mx = p->cx + p->m->radius * S->mid[0], my = p->cy + p->m->radius * S->mid[1];
    int a = W->anchor;
    double da = hypot(sim->x[a] - mx, sim->y[a] - my);
    for (int it = 0; it < n; it++) {
        int f = a + 1 == n ? 0 : a + 1, b = a == 0 ? n - 1 : a - 1;
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
        int b = lo == 0 ? n - 1 : lo - 1;
        if (!in_sector(sim, p, S, b))
            break;
        lo = b;
        c++;
    }
    for (int k = a + 1 == n ? 0 : a + 1; c < S->node_max; k = k + 1 == n ? 0 : k + 1) {
        if (!in_sector(sim, p, S, k))
            break;
        c++;
    }
    *first = lo;
    *count = c;
    return a;
}

static void normal_forces(bd_sim *sim, bd_pulley_body *p)
{
    bd_wrap_contact *W = wrap_of(sim, p);
    const double l0 = sim->model->l0, k_c = bd_lumped_model_of(sim)->k_contact;
    const int n = sim->model->n;
    double R = p->m->radius;
    /* predictive contact: a node within this gap of the shell may reach it
     * during the step; the implicit force says whether it does */
    double Rc = R + CONTACT_GAP * l0;
    /* the shell's velocity at the end of the step, with the carriage's
     * acceleration of the last step (a moving takeup pulley) */
    double vp_end = p->qdot + sim->model->dt * p->qddot;
    double vpx = vp_end * p->m->axis[0], vpy = vp_end * p->m->axis[1];
    W->contact_count = 0;
    p->f_axis = 0.0;
    p->fnc_axis = 0.0;
    W->anchor = find_sector(sim, p, W, &W->win_first, &W->win_count);
    for (int w = 0, k = W->win_first; w < W->win_count; w++, k = k + 1 == n ? 0 : k + 1) {
        double rx = sim->x[k] - p->cx, ry = sim->y[k] - p->cy;
        double a2 = rx * rx + ry * ry;
        if (a2 >= Rc * Rc)
            continue;
        double a = sqrt(a2);
        double nx = rx / a, ny = ry / a;
        double vn = nx * (sim->vx[k] - vpx) + ny * (sim->vy[k] - vpy);   /* v_n − v_p,n */
        double m = sim->mass[k];
        double Fo = nx * sim->fx[k] + ny * sim->fy[k];
        double delta = R - a;
        double dt = sim->model->dt;
        double fn = k_c * (delta - dt * vn - dt * dt * Fo / m)
                  / (1.0 + k_c * dt * dt / m);
        if (fn <= 0.0)
            continue;
        double fd = fn - (delta > 0.0 ? k_c * delta : 0.0);
        sim->fx[k] += fn * nx;
        sim->fy[k] += fn * ny;
        sim->fnx[k] += fd * nx;
        sim->fny[k] += fd * ny;
        p->f_axis -= fn * (nx * p->m->axis[0] + ny * p->m->axis[1]);
        p->fnc_axis -= fd * (nx * p->m->axis[0] + ny * p->m->axis[1]);
        int c = W->contact_count++;
        W->c_node[c] = k;
        W->c_normal[c] = fn;
        W->c_tx[c] = -p->m->wrap * ny;
        W->c_ty[c] = p->m->wrap * nx;
    }
}

static void friction_forces(bd_sim *sim, bd_pulley_body *p, double T_p)
{
    bd_wrap_contact *W = wrap_of(sim, p);
    const double dt = sim->model->dt, R = p->m->radius;
    const double vpx = p->qdot * p->m->axis[0], vpy = p->qdot * p->m->axis[1];
    const int nc = W->contact_count;
    double alpha = 0.0;
    for (int c = 0; c < nc; c++)
        W->c_slip[c] = 0;
    /* solve the sticking set, move violators to slip, repeat */
    for (int pass = 0; pass <= nc; pass++) {
        double A = 0.0, M = 0.0, Fk = 0.0;
        for (int c = 0; c < nc; c++) {
            if (W->c_slip[c]) {
                Fk += W->c_f[c];
                continue;
            }
            int k = W->c_node[c];
            double vr = W->c_tx[c] * (sim->vx[k] - vpx) + W->c_ty[c] * (sim->vy[k] - vpy)
                      - R * p->omega;
            A += sim->mass[k] * vr / dt + W->c_tx[c] * sim->fx[k] + W->c_ty[c] * sim->fy[k];
            M += sim->mass[k];
        }
        /* a held pulley (p->held: stabilization's holdback) does not turn */
        alpha = p->held ? 0.0 : (R * A + R * Fk + T_p) / (bd_pulley_solve_inertia(sim, p) + R * R * M);
        /* a drive that would pass its max_torque: at the limit, solve again
         * (once: it is explicit then) */
        if (bd_pulley_drive_clip(sim, p, alpha, &T_p)) {
            pass--;
            continue;
        }
        int changed = 0;
        for (int c = 0; c < nc; c++) {
            if (W->c_slip[c])
                continue;
            int k = W->c_node[c];
            double vr = W->c_tx[c] * (sim->vx[k] - vpx) + W->c_ty[c] * (sim->vy[k] - vpy)
                      - R * p->omega;
            double f = sim->mass[k] * (vr / dt - R * alpha)
                     + W->c_tx[c] * sim->fx[k] + W->c_ty[c] * sim->fy[k];
            W->c_f[c] = f;
            if (fabs(f) > p->m->mu_s * W->c_normal[c]) {
                W->c_slip[c] = 1;
                W->c_f[c] = copysign(p->m->mu_d * W->c_normal[c], f);
                changed = 1;
            }
        }
        if (!changed)
            break;
    }
    /* apply */
    double sum = 0.0;
    for (int c = 0; c < nc; c++) {
        int k = W->c_node[c];
        double f = W->c_f[c];
        sim->fx[k] -= f * W->c_tx[c];
        sim->fy[k] -= f * W->c_ty[c];
        sim->fnx[k] -= f * W->c_tx[c];
        sim->fny[k] -= f * W->c_ty[c];
        double fa = f * (W->c_tx[c] * p->m->axis[0] + W->c_ty[c] * p->m->axis[1]);
        p->f_axis += fa;
        p->fnc_axis += fa;
        sum += f;
    }
    p->torque_friction = R * sum;
    p->alpha = alpha;
}

void bd_lumped_wrap(bd_sim *sim, bd_pulley_body *p, double external_torque)
{
    normal_forces(sim, p);
    const bd_wrap_contact *W = wrap_of(sim, p);
    p->torque_friction = 0.0;
    if (W->contact_count == 0) {
        p->alpha = p->held ? 0.0 : external_torque / bd_pulley_solve_inertia(sim, p);
        if (!p->held && bd_pulley_drive_clip(sim, p, p->alpha, &external_torque))
            p->alpha = external_torque / bd_pulley_solve_inertia(sim, p);
        return;
    }
    friction_forces(sim, p, external_torque);
}

/* elastic energy of the contact springs: ½k_c·δ² of every node inside the
 * shell, among the nodes of the wrap's sector */
double bd_lumped_wrap_energy(const bd_sim *sim, const bd_pulley_body *p)
{
    const bd_wrap_contact *W = wrap_of(sim, p);
    const int n = sim->model->n;
    double e = 0.0, R = p->m->radius;
    int first, count;
    find_sector(sim, p, W, &first, &count);
    for (int w = 0, k = first; w < count; w++, k = k + 1 == n ? 0 : k + 1) {
        double a = hypot(sim->x[k] - p->cx, sim->y[k] - p->cy);
        if (a < R)
            e += 0.5 * bd_lumped_model_of(sim)->k_contact * (R - a) * (R - a);
    }
    return e;
}
