/* The lumped-mass belt of seed 001 §4.1: nodes joined by Kelvin–Voigt
 * axial elements and rotational bending springs, under gravity.
 *
 * Element e (node e → node e+1), length l, unit vector u:
 *   T = k·(l − l0) + c·dl/dt,   k = EA/l0 (eq 4.1), c from eq 4.3,
 *   dl/dt = u·(v_{e+1} − v_e)                              (eq 4.54)
 * and the element pulls its nodes together with T (eqs 4.40, 4.56).
 * Bending at node i between element b = i−1 and a = i: θ = angle from b to
 * a, moment M = k_θ·θ with k_θ = EI/l0 (eq 4.11), potential ½k_θθ² (4.31);
 * the forces are −M·∂θ/∂x (eq 4.47, written with unit vectors):
 *   ∂θ/∂x_{i+1} = perp(â)/l_a,  ∂θ/∂x_{i−1} = perp(b̂)/l_b,
 *   ∂θ/∂x_i = −(both),          perp(u) = (−u_y, u_x).
 * Gravity −m·g on every node (eq 4.49). */
#include "belt/lumped/lumped.h"

#include <math.h>

/* elements 0 .. count−1 of the node arrays x, y, vx, vy (element e from
 * node e to e + 1): length, direction, tension and its dashpot part. No
 * node is written, so the loop vectorizes. */
static void elements(int count, const double *restrict x, const double *restrict y,
                     const double *restrict vx, const double *restrict vy, double k, double c,
                     double l0, double *restrict ux, double *restrict uy, double *restrict len,
                     double *restrict td, double *restrict tension)
{
    for (int e = 0; e < count; e++) {
        double dx = x[e + 1] - x[e], dy = y[e + 1] - y[e];
        double l = sqrt(dx * dx + dy * dy);
        double inv = 1.0 / l;
        double ex = dx * inv, ey = dy * inv;
        double ldot = ex * (vx[e + 1] - vx[e]) + ey * (vy[e + 1] - vy[e]);
        double Td = c * ldot;
        ux[e] = ex;
        uy[e] = ey;
        len[e] = l;
        td[e] = Td;
        tension[e] = k * (l - l0) + Td;
    }
}

/* the element pass: elements 0 .. n−2, then the one that closes the loop
 * (node n−1 to node 0) from a copy of its two nodes */
static void element_pass(bd_sim *sim)
{
    bd_lumped *L = bd_lumped_of(sim);
    const int n = sim->model->n, z = n - 1;
    const bd_lumped_model *LM = bd_lumped_model_of(sim);
    const double k = LM->k_axial, c = LM->c_axial, l0 = sim->model->l0;
    const double *x = sim->x, *y = sim->y, *vx = sim->vx, *vy = sim->vy;
    elements(z, x, y, vx, vy, k, c, l0, L->ux, L->uy, L->len, L->td, sim->tension);
    double cx[2] = {x[z], x[0]}, cy[2] = {y[z], y[0]};
    double cvx[2] = {vx[z], vx[0]}, cvy[2] = {vy[z], vy[0]};
    elements(1, cx, cy, cvx, cvy, k, c, l0, L->ux + z, L->uy + z, L->len + z, L->td + z,
             sim->tension + z);
}

/* the node pass: node i is pulled forward by element i and back by
 * element i − 1, under its weight. The sums are written in the order the
 * element-by-element scatter added them (element i − 1 first, except at
 * node 0 where element n − 1 came last), so the result is the same to the
 * bit. */
static void nodes(int n, double g, const double *restrict ux, const double *restrict uy,
                  const double *restrict T, const double *restrict td,
                  const double *restrict m, double *restrict fx, double *restrict fy,
                  double *restrict fnx, double *restrict fny)
{
    int b = n - 1;
    fx[0] = (0.0 + T[0] * ux[0]) - T[b] * ux[b];
    fy[0] = (-m[0] * g + T[0] * uy[0]) - T[b] * uy[b];
    fnx[0] = (0.0 + td[0] * ux[0]) - td[b] * ux[b];
    fny[0] = (0.0 + td[0] * uy[0]) - td[b] * uy[b];
    for (int i = 1; i < n; i++) {
        fx[i] = (0.0 - T[i - 1] * ux[i - 1]) + T[i] * ux[i];
        fy[i] = (-m[i] * g - T[i - 1] * uy[i - 1]) + T[i] * uy[i];
        fnx[i] = (0.0 - td[i - 1] * ux[i - 1]) + td[i] * ux[i];
        fny[i] = (0.0 - td[i - 1] * uy[i - 1]) + td[i] * uy[i];
    }
}

static void node_pass(bd_sim *sim)
{
    const bd_lumped *L = bd_lumped_of(sim);
    nodes(sim->model->n, sim->model->gravity, L->ux, L->uy, sim->tension, L->td, sim->mass, sim->fx,
          sim->fy, sim->fnx, sim->fny);
}

static void bending_forces(bd_sim *sim)
{
    const bd_lumped *L = bd_lumped_of(sim);
    const int n = sim->model->n;
    const double kb = bd_lumped_model_of(sim)->k_bend;
    const double *ux = L->ux, *uy = L->uy, *len = L->len;
    double *fx = sim->fx, *fy = sim->fy;
    for (int i = 0; i < n; i++) {
        int b = i == 0 ? n - 1 : i - 1;       /* element before node i */
        int a = i;                             /* element after node i */
        int next = i + 1 == n ? 0 : i + 1;
        double sn = ux[b] * uy[a] - uy[b] * ux[a];
        double cs = ux[b] * ux[a] + uy[b] * uy[a];
        double M = kb * atan2(sn, cs);
        double gax = -uy[a] * M / len[a], gay = ux[a] * M / len[a];
        double gbx = -uy[b] * M / len[b], gby = ux[b] * M / len[b];
        fx[next] -= gax;
        fy[next] -= gay;
        fx[b] -= gbx;
        fy[b] -= gby;
        fx[i] += gax + gbx;
        fy[i] += gay + gby;
    }
}

/* design.secondary: individual: the skirts at the feed point rub the belt
 * (belt.h bd_feed_force), shared by the two nodes of the element under it
 * as the landing material is (material.c) */
static void feed_skirts(bd_sim *sim)
{
    const bd_tracker *fd = &sim->feed;
    int e = fd->element, j = e + 1 == sim->model->n ? 0 : e + 1;
    double v = bd_tracker_speed(sim, fd);
    int loaded = sim->material[e] > 0.0 || sim->material[j] > 0.0;
    double F = bd_feed_force(sim, v, sim->mass[e] + sim->mass[j], 0, loaded);
    double share[2] = {1.0 - fd->gamma, fd->gamma};
    int nodes[2] = {e, j};
    for (int k = 0; k < 2; k++) {
        double fx = F * share[k] * fd->dir[0], fy = F * share[k] * fd->dir[1];
        sim->fx[nodes[k]] += fx;
        sim->fy[nodes[k]] += fy;
        sim->fnx[nodes[k]] += fx;
        sim->fny[nodes[k]] += fy;
    }
}

void bd_lumped_forces(bd_sim *sim)
{
    element_pass(sim);
    /* elements that run round a pulley: the belt's length, not the chord */
    bd_lumped_wrap_elements(sim);
    node_pass(sim);
    bd_lumped_wrap_forces(sim);
    bd_tension_extremes(sim);
    if (bd_lumped_model_of(sim)->k_bend > 0.0)
        bending_forces(sim);
    if (sim->model->feed_individual)
        feed_skirts(sim);
}

/* elements e0 .. e0 + count − 1 round the loop, in contiguous pieces
 * (the one closing the loop from a copy of its two nodes, as element_pass) */
static void element_range(bd_sim *sim, int e0, int count)
{
    bd_lumped *L = bd_lumped_of(sim);
    const int n = sim->model->n, z = n - 1;
    const bd_lumped_model *LM = bd_lumped_model_of(sim);
    const double k = LM->k_axial, c = LM->c_axial, l0 = sim->model->l0;
    const double *x = sim->x, *y = sim->y, *vx = sim->vx, *vy = sim->vy;
    int e = e0, left = count < n ? count : n;
    while (left > 0) {
        if (e == z) {
            double cx[2] = {x[z], x[0]}, cy[2] = {y[z], y[0]};
            double cvx[2] = {vx[z], vx[0]}, cvy[2] = {vy[z], vy[0]};
            elements(1, cx, cy, cvx, cvy, k, c, l0, L->ux + z, L->uy + z, L->len + z,
                     L->td + z, sim->tension + z);
            e = 0;
            left--;
            continue;
        }
        int piece = z - e < left ? z - e : left;
        elements(piece, x + e, y + e, vx + e, vy + e, k, c, l0, L->ux + e, L->uy + e, L->len + e,
                 L->td + e, sim->tension + e);
        e += piece;
        left -= piece;
    }
}

/* nodes first .. first + count − 1 round the loop, as the node pass */
static void node_range(bd_sim *sim, int first, int count)
{
    const bd_lumped *L = bd_lumped_of(sim);
    const int n = sim->model->n;
    const double g = sim->model->gravity;
    const double *ux = L->ux, *uy = L->uy, *T = sim->tension, *td = L->td, *m = sim->mass;
    for (int q = 0, i = first, b = bd_node_prev(first, n); q < count && q < n;
         q++, b = i, i = bd_node_next(i, n)) {
        sim->fx[i] = T[i] * ux[i] - T[b] * ux[b];
        sim->fy[i] = -m[i] * g + T[i] * uy[i] - T[b] * uy[b];
        sim->fnx[i] = td[i] * ux[i] - td[b] * ux[b];
        sim->fny[i] = td[i] * uy[i] - td[b] * uy[b];
    }
}

/* the tension extremes (bd_tension_extremes) of the elements of the runs */
static void extremes_range(bd_sim *sim, int e0, int count, double *hi, double *lo, int *nan)
{
    const int n = sim->model->n;
    const double *T = sim->tension;
    for (int q = 0, e = e0; q < count && q < n; q++, e = bd_node_next(e, n)) {
        double t = T[e];
        *nan |= !(t == t);
        *hi = t > *hi ? t : *hi;
        *lo = t < *lo ? t : *lo;
    }
}

/* The forces phase on runs of nodes only (the rfe belt's free belt and
 * the ends of its long sections, belt/rfe/sections.c): run r's nodes
 * first[r] .. first[r] + count[r] − 1 round the loop, with the elements
 * from the one before its first node to its last node's; no other node or
 * element is written. The step's tension extremes are those of these
 * elements; the caller adds what it holds elsewhere. No bending (the rfe
 * belt's is its own). */
void bd_lumped_forces_runs(bd_sim *sim, const int *first, const int *count, int runs)
{
    const int n = sim->model->n;
    for (int r = 0; r < runs; r++)
        element_range(sim, bd_node_prev(first[r], n), count[r] + 1);
    bd_lumped_wrap_elements(sim);
    for (int r = 0; r < runs; r++)
        node_range(sim, first[r], count[r]);
    bd_lumped_wrap_forces(sim);
    double hi = -INFINITY, lo = INFINITY;
    int nan = 0;
    for (int r = 0; r < runs; r++)
        extremes_range(sim, bd_node_prev(first[r], n), count[r] + 1, &hi, &lo, &nan);
    sim->step_tension_max = hi;
    sim->step_tension_min = lo;
    sim->step_tension_nan = nan;
    if (sim->model->feed_individual)
        feed_skirts(sim);
}

/* nodes: velocities to t + Δt/2, positions to t + Δt (seed 001 eqs
 * 4.58–4.60); the kinetic energy and the non-conservative work are booked
 * with mid-step velocities v(t) = (v⁻ + v⁺)/2, for which the scheme's
 * kinetic-energy change is exactly Σ F·v(t)·Δt */
static void advance(int n, double dt, const double *restrict mass,
                    const double *restrict dt_per_mass, const double *restrict fx,
                    const double *restrict fy, const double *restrict fnx,
                    const double *restrict fny, double *restrict x, double *restrict y,
                    double *restrict vx, double *restrict vy, double *restrict pw,
                    double *restrict ek)
{
    for (int i = 0; i < n; i++) {
        double inv = dt_per_mass[i];   /* dt / mass[i] */
        double ax = fx[i] * inv, ay = fy[i] * inv;
        double mx = vx[i] + 0.5 * ax, my = vy[i] + 0.5 * ay;
        pw[i] = fnx[i] * mx + fny[i] * my;
        ek[i] = mass[i] * (mx * mx + my * my);
        vx[i] += ax;
        vy[i] += ay;
        x[i] += vx[i] * dt;
        y[i] += vy[i] * dt;
    }
}

void bd_lumped_advance_range(bd_sim *sim, int first, int count)
{
    bd_lumped *L = bd_lumped_of(sim);
    const int f = first;
    advance(count, sim->model->dt, sim->mass + f, sim->dt_per_mass + f, sim->fx + f, sim->fy + f,
            sim->fnx + f, sim->fny + f, sim->x + f, sim->y + f, sim->vx + f, sim->vy + f,
            L->pw + f, L->ek + f);
}

/* the update vectorizes; the two sums stay in node order, so the energy
 * account is the same to the bit as one fused loop's */
void bd_lumped_integrate(bd_sim *sim, double *ke_out, double *w_nc_out)
{
    bd_lumped *L = bd_lumped_of(sim);
    const int n = sim->model->n;
    advance(n, sim->model->dt, sim->mass, sim->dt_per_mass, sim->fx, sim->fy, sim->fnx, sim->fny, sim->x, sim->y,
            sim->vx, sim->vy, L->pw, L->ek);
    double w_nc = 0.0, ke = 0.0;
    const double *restrict pw = L->pw, *restrict ek = L->ek;
    for (int i = 0; i < n; i++) {
        w_nc += pw[i];
        ke += ek[i];
    }
    *w_nc_out = w_nc * sim->model->dt;
    *ke_out = ke * 0.5;
}

double bd_lumped_elastic_energy(const bd_sim *sim)
{
    const bd_lumped_model *L = bd_lumped_model_of(sim);
    const int n = sim->model->n;
    double e = 0.0;
    for (int i = 0; i < n; i++) {
        int j = i + 1 == n ? 0 : i + 1;
        double l = hypot(sim->x[j] - sim->x[i], sim->y[j] - sim->y[i]);
        e += 0.5 * L->k_axial * (l - sim->model->l0) * (l - sim->model->l0);
        if (L->k_bend > 0.0) {
            int b = i == 0 ? n - 1 : i - 1;
            double bx = sim->x[i] - sim->x[b], by = sim->y[i] - sim->y[b];
            double ax = sim->x[j] - sim->x[i], ay = sim->y[j] - sim->y[i];
            double th = atan2(bx * ay - by * ax, bx * ax + by * ay);
            e += 0.5 * L->k_bend * th * th;
        }
    }
    return e + bd_lumped_wrap_elastic_correction(sim);
}

/* gravity of belt (y = 0 the datum) and material (from the discharge
 * pulley's height, bd_lumped_material_datum) and the elastic energy */
double bd_lumped_potential(const bd_sim *sim)
{
    double g = sim->model->gravity, yd = bd_lumped_material_datum(sim);
    double e = 0.0;
    for (int i = 0; i < sim->model->n; i++)
        e += sim->mass[i] * g * sim->y[i] - sim->material[i] * g * yd;
    return e + bd_lumped_elastic_energy(sim);
}
