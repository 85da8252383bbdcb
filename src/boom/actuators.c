/* What moves and holds the boom: the telescopic cylinder, the ropes that
 * synchronise the further sections, the luffing rod or pivot moment.
 *
 * Telescopic cylinder (sections 1 -> 2): a position servo following the
 * stroke profile in series with its oil column, a spring-dashpot between
 * the profile's stroke and section 2's bottom measured along section 1:
 * F = k (s_ref - s) + c (s_ref' - s'). Its input power is F s_ref' (the
 * servo's), of which F s' does work on the boom.
 *
 * Ropes, one pair per further section (2:1 per stage, seed 003 §9): the
 * extend rope from section j-1's bottom over a sheave at section j's top
 * to section j+1's bottom, the retract rope from section j-1's top under a
 * sheave at section j's bottom to section j+1's top. Their lengths
 * 2 L_j + s_{j-1} - s_j and L_{j-1} + L_{j+1} - s_{j-1} + s_j are constant
 * exactly when the strokes are equal; each is a tension-only spring EA/l0,
 * slack-free at the rigid initial state. Unsynchronised booms hold the
 * further strokes with the same springs at the initial stroke.
 *
 * Luffing: a rod from a fixed base to section 1's attachment, its length
 * following the luffing angle (a position servo like the cylinder), or
 * without a rod the angle of section 1 at the pivot held directly and the
 * moment that takes reported. */
#include "boom/boom_internal.h"

#include <math.h>

static int top_node(const bd_boom *b, int k)
{
    return b->sec[k].first + b->sec[k].n - 1;
}

static double dist(const bd_boom *b, int i, int j)
{
    return hypot(b->x[i] - b->x[j], b->y[i] - b->y[j]);
}

/* rope nodes of stage j: extend (anchor, sheave, end), retract likewise */
static void rope_nodes(const bd_boom *b, int j, int ext[3], int ret[3])
{
    ext[0] = b->sec[j - 1].first;
    ext[1] = top_node(b, j);
    ext[2] = b->sec[j + 1].first;
    ret[0] = top_node(b, j - 1);
    ret[1] = b->sec[j].first;
    ret[2] = top_node(b, j + 1);
}

/* the rigid attachment point of the luffing rod at angle th */
static void attach_rigid(const bd_boom *b, double th, double *px, double *py)
{
    const double *at = b->def.luffing_cylinder.attach;
    double c = cos(th), s = sin(th);
    *px = b->def.pivot[0] + at[0] * c - at[1] * s;
    *py = b->def.pivot[1] + at[0] * s + at[1] * c;
}

void boom_actuators_init(bd_boom *b)
{
    /* at the rigid initial state: rope rest lengths, and the masses the
     * cylinder and the rod move, for their dashpots */
    for (int j = 1; j + 1 < b->ns; j++) {
        int e[3], r[3];
        rope_nodes(b, j, e, r);
        b->rope_ext_l0[j] = dist(b, e[0], e[1]) + dist(b, e[1], e[2]);
        b->rope_ret_l0[j] = dist(b, r[0], r[1]) + dist(b, r[1], r[2]);
    }
    double Mc = 0.0, I = 0.0;
    for (int k = 0; k < b->ns; k++) {
        double r = b->def.synchronized ? k : (k > 0 ? 1.0 : 0.0);
        for (int i = b->sec[k].first; i < b->sec[k].first + b->sec[k].n; i++) {
            Mc += r * r * b->m[i];
            double dx = b->x[i] - b->def.pivot[0], dy = b->y[i] - b->def.pivot[1];
            I += b->m[i] * (dx * dx + dy * dy);
        }
    }
    const bd_telescopic_cylinder_def *tc = &b->def.telescopic_cylinder;
    b->cyl_c = 2.0 * tc->damping_ratio * sqrt(tc->stiffness * Mc);
    b->rod_c = 0.0;
    if (b->def.luffing_cylinder.present) {
        double px, py;
        attach_rigid(b, b->theta, &px, &py);
        const double *base = b->def.luffing_cylinder.base;
        double ux = px - base[0], uy = py - base[1], l = hypot(ux, uy);
        /* lever of the rod about the pivot */
        double lever = fabs((px - b->def.pivot[0]) * uy - (py - b->def.pivot[1]) * ux) / l;
        double Mrod = lever > 0.0 ? I / (lever * lever) : I;
        b->rod_c = 2.0 * tc->damping_ratio * sqrt(b->def.luffing_cylinder.stiffness * Mrod);
        /* the dashpot acts on one node, through the attachment's offset on
         * its rotation: keep it within what the explicit step can carry
         * (c dt / m_local <= 1); the boom's luffing mode is damped by the
         * structural damping as well */
        int i = b->attach_node;
        double off = b->attach_n;
        double m_local = 1.0 / (1.0 / b->m[i] + off * off / b->J[i]);
        b->rod_c = fmin(b->rod_c, m_local / b->dt);
    }
    {
        int i2 = b->sec[1].first;
        /* the same bound at section 2's bottom node; its lightest layout
         * (shortest elements) is a quarter of the mass at worst */
        b->cyl_c = fmin(b->cyl_c, 0.25 * b->m[i2] / b->dt);
    }
}

/* a tension-only rope over nodes n[0] -> n[1] (sheave) -> n[2] */
static double rope(bd_boom *b, const int n[3], double l0, double k_ea, double *U)
{
    double ax = b->x[n[1]] - b->x[n[0]], ay = b->y[n[1]] - b->y[n[0]];
    double bx = b->x[n[1]] - b->x[n[2]], by = b->y[n[1]] - b->y[n[2]];
    double la = hypot(ax, ay), lb = hypot(bx, by);
    double stretch = la + lb - l0;
    if (stretch <= 0.0)
        return 0.0;
    double k = k_ea / l0;
    double T = k * stretch;
    *U += 0.5 * k * stretch * stretch;
    b->fx[n[0]] += T * ax / la;
    b->fy[n[0]] += T * ay / la;
    b->fx[n[2]] += T * bx / lb;
    b->fy[n[2]] += T * by / lb;
    b->fx[n[1]] -= T * (ax / la + bx / lb);
    b->fy[n[1]] -= T * (ay / la + by / lb);
    return T;
}

/* unsynchronised: section j+1 pinned at the initial stroke in section j,
 * a spring as stiff as a rope of that length; its pull returned */
static double pin(bd_boom *b, int j, double *U)
{
    int i1 = b->sec[j].first, i2 = b->sec[j + 1].first;
    double tx = cos(b->phi[i1]), ty = sin(b->phi[i1]);
    double s = (b->x[i2] - b->x[i1]) * tx + (b->y[i2] - b->y[i1]) * ty;
    double s0 = b->def.stroke.initial > 0.1 ? b->def.stroke.initial : 0.1;
    double k = b->def.ropes.axial_stiffness / s0;
    double F = k * (b->def.stroke.initial - s);
    b->fx[i2] += F * tx;
    b->fy[i2] += F * ty;
    b->fx[i1] -= F * tx;
    b->fy[i1] -= F * ty;
    *U += 0.5 * F * F / k;
    return F;
}

void boom_actuators(bd_boom *b, double *elastic, double *diss_power, double *in_power)
{
    double U = 0.0, D = 0.0, P = 0.0;
    /* telescopic cylinder along section 1's axis at the pivot end */
    {
        int i1 = b->sec[0].first, i2 = b->sec[1].first;
        double tx = cos(b->phi[i1]), ty = sin(b->phi[i1]);
        double s = (b->x[i2] - b->x[i1]) * tx + (b->y[i2] - b->y[i1]) * ty;
        double sd = (b->vx[i2] - b->vx[i1]) * tx + (b->vy[i2] - b->vy[i1]) * ty;
        double k = b->def.telescopic_cylinder.stiffness;
        double e = b->stroke_ref - s, ed = b->stroke_v - sd;
        double F = k * e + b->cyl_c * ed;
        b->fx[i2] += F * tx;
        b->fy[i2] += F * ty;
        b->fx[i1] -= F * tx;
        b->fy[i1] -= F * ty;
        U += 0.5 * k * e * e;
        D += b->cyl_c * ed * ed;
        P += F * b->stroke_v;
        b->cyl_force = F;
    }
    for (int j = 1; j + 1 < b->ns; j++) {
        if (!b->def.synchronized) {
            b->rope_ext[j] = pin(b, j, &U);
            b->rope_ret[j] = 0.0;
            continue;
        }
        int e[3], r[3];
        rope_nodes(b, j, e, r);
        b->rope_ext[j] = rope(b, e, b->rope_ext_l0[j], b->def.ropes.axial_stiffness, &U);
        b->rope_ret[j] = rope(b, r, b->rope_ret_l0[j], b->def.ropes.axial_stiffness, &U);
    }
    if (b->def.luffing_cylinder.present) {
        int i = b->attach_node;
        const bd_luffing_cylinder_def *lc = &b->def.luffing_cylinder;
        double off = b->attach_n;
        double c = cos(b->phi[i]), s = sin(b->phi[i]);
        double ox = -off * s, oy = off * c;           /* node -> attachment */
        double px = b->x[i] + ox, py = b->y[i] + oy;
        double vx = b->vx[i] - b->w[i] * oy, vy = b->vy[i] + b->w[i] * ox;
        double ux = px - lc->base[0], uy = py - lc->base[1];
        double l = hypot(ux, uy);
        ux /= l;
        uy /= l;
        double rx, ry;
        attach_rigid(b, b->theta, &rx, &ry);
        double lrx = rx - lc->base[0], lry = ry - lc->base[1];
        double lref = hypot(lrx, lry);
        /* d lref/dt: the rigid attachment turns about the pivot */
        double lref_d = (lrx * (-b->theta_dot * (ry - b->def.pivot[1]))
                         + lry * (b->theta_dot * (rx - b->def.pivot[0]))) / lref;
        double ld = ux * vx + uy * vy;
        double e = lref - l, ed = lref_d - ld;
        double F = lc->stiffness * e + b->rod_c * ed;
        b->fx[i] += F * ux;
        b->fy[i] += F * uy;
        b->mz[i] += ox * F * uy - oy * F * ux;
        U += 0.5 * lc->stiffness * e * e;
        D += b->rod_c * ed * ed;
        P += F * lref_d;
        b->luff_force = F;
    }
    *elastic = U;
    *diss_power = D;
    *in_power = P;
}
