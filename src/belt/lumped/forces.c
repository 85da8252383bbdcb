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

static void element_forces(bd_sim *sim)
{
    bd_lumped *L = bd_lumped_of(sim);
    const int n = sim->n;
    const double k = L->k_axial, c = L->c_axial, l0 = sim->l0;
    const double *x = sim->x, *y = sim->y, *vx = sim->vx, *vy = sim->vy;
    double *fx = sim->fx, *fy = sim->fy, *fnx = sim->fnx, *fny = sim->fny;
    double *ux = L->ux, *uy = L->uy, *len = L->len, *tension = sim->tension;
    /* the extremes of this step, for the run's record and divergence check;
     * a NaN anywhere makes the sum NaN */
    bd_extremes ext = {-INFINITY, INFINITY, 0.0, 0, 0};
    for (int e = 0; e < n; e++) {
        int j = e + 1 == n ? 0 : e + 1;
        double dx = x[j] - x[e], dy = y[j] - y[e];
        double l = sqrt(dx * dx + dy * dy);
        double inv = 1.0 / l;
        double ex = dx * inv, ey = dy * inv;
        double ldot = ex * (vx[j] - vx[e]) + ey * (vy[j] - vy[e]);
        double Td = c * ldot;
        double T = k * (l - l0) + Td;
        ux[e] = ex;
        uy[e] = ey;
        len[e] = l;
        tension[e] = T;
        bd_extremes_add(&ext, T, e);
        fx[e] += T * ex;
        fy[e] += T * ey;
        fx[j] -= T * ex;
        fy[j] -= T * ey;
        fnx[e] += Td * ex;
        fny[e] += Td * ey;
        fnx[j] -= Td * ex;
        fny[j] -= Td * ey;
    }
    bd_extremes_store(sim, &ext);
}

static void bending_forces(bd_sim *sim)
{
    const bd_lumped *L = bd_lumped_of(sim);
    const int n = sim->n;
    const double kb = L->k_bend;
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

void bd_lumped_forces(bd_sim *sim)
{
    const int n = sim->n;
    const double g = sim->gravity;
    for (int i = 0; i < n; i++) {
        sim->fx[i] = 0.0;
        sim->fy[i] = -sim->mass[i] * g;
        sim->fnx[i] = 0.0;
        sim->fny[i] = 0.0;
    }
    element_forces(sim);
    if (bd_lumped_of(sim)->k_bend > 0.0)
        bending_forces(sim);
}

/* nodes: velocities to t + Δt/2, positions to t + Δt (seed 001 eqs
 * 4.58–4.60); the kinetic energy and the non-conservative work are booked
 * with mid-step velocities v(t) = (v⁻ + v⁺)/2, for which the scheme's
 * kinetic-energy change is exactly Σ F·v(t)·Δt */
void bd_lumped_integrate(bd_sim *sim, double *ke_out, double *w_nc_out)
{
    const double dt = sim->dt;
    double w_nc = 0.0, ke = 0.0;
    const int n = sim->n;
    double *x = sim->x, *y = sim->y, *vx = sim->vx, *vy = sim->vy;
    const double *fx = sim->fx, *fy = sim->fy, *fnx = sim->fnx, *fny = sim->fny;
    const double *mass = sim->mass;
    for (int i = 0; i < n; i++) {
        double inv = dt / mass[i];
        double ax = fx[i] * inv, ay = fy[i] * inv;
        double mx = vx[i] + 0.5 * ax, my = vy[i] + 0.5 * ay;
        w_nc += fnx[i] * mx + fny[i] * my;
        ke += mass[i] * (mx * mx + my * my);
        vx[i] += ax;
        vy[i] += ay;
        x[i] += vx[i] * dt;
        y[i] += vy[i] * dt;
    }
    *w_nc_out = w_nc * dt;
    *ke_out = ke * 0.5;
}

double bd_lumped_elastic_energy(const bd_sim *sim)
{
    const bd_lumped *L = bd_lumped_of(sim);
    const int n = sim->n;
    double e = 0.0;
    for (int i = 0; i < n; i++) {
        int j = i + 1 == n ? 0 : i + 1;
        double l = hypot(sim->x[j] - sim->x[i], sim->y[j] - sim->y[i]);
        e += 0.5 * L->k_axial * (l - sim->l0) * (l - sim->l0);
        if (L->k_bend > 0.0) {
            int b = i == 0 ? n - 1 : i - 1;
            double bx = sim->x[i] - sim->x[b], by = sim->y[i] - sim->y[b];
            double ax = sim->x[j] - sim->x[i], ay = sim->y[j] - sim->y[i];
            double th = atan2(bx * ay - by * ax, bx * ax + by * ay);
            e += 0.5 * L->k_bend * th * th;
        }
    }
    return e;
}

/* gravity of belt and material (y = 0 the datum) and the elastic energy */
double bd_lumped_potential(const bd_sim *sim)
{
    double g = sim->gravity;
    double e = 0.0;
    for (int i = 0; i < sim->n; i++)
        e += sim->mass[i] * g * sim->y[i];
    return e + bd_lumped_elastic_energy(sim);
}
