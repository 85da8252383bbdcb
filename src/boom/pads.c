/* Pads between neighbouring sections (seed 003 §6-§8, regularized).
 *
 * Two contacts per pair of sections k / k+1: the inner contact (section
 * k+1's bottom pads against section k's inside, at the point of section k
 * nearest to section k+1's bottom node) and the outer contact (section k's
 * top pads against section k+1's outside, at section k+1's outer contact
 * node), each measured in the frame of the surface its pads slide on. At
 * each, two pads at +-h/2 across the axis, the upper one pressed when the
 * inner axis moves up relative to the outer, each pad with its two
 * ends at +-w/2 along the axis (seed eq. 59: the resultants at the pad's
 * front and back ends), so a relative rotation loads one end more: the
 * pads carry a moment, as the seed's distributed contact does.
 *
 * Each end is a compression-only spring of half the pad's stiffness behind
 * the clearance `gap`, its stiffness rising smoothly over `smoothing`
 * (seed eq. 65: k = k0 (3 (d/e)^2 - 2 (d/e)^3) for 0 <= d < e), with a
 * dashpot that never pulls. This is the regularized equivalent of the
 * seed's contact multipliers with auxiliary equations (§6-§8): the same
 * pad law, without the extra algebraic unknowns; docs/boom.md says why.
 *
 * Friction along the axis: the seed's f = mu sign(s') f_n (§8, after eq.
 * 65) with the static coefficient below its threshold speed and the
 * dynamic one above (§9: mu_a, mu_r, v_eps). Regularized here (this code's
 * choice, the seed gives no curve between them): mu rises linearly to
 * mu_static at the switch speed (the regularized stick), then falls to
 * mu_dynamic (mu = mu_d + (mu_s - mu_d) exp(-(|v| - v_s)/v_s)), at each
 * pad's face.
 * The stick ramp is a stiff dashpot, integrated implicitly on the face's
 * effective mass (the two points' masses and, through the face's offset
 * h/2, their rotary inertias) so it stays stable at any normal force; the
 * sliding force is capped at what stops the face within the step, so it
 * never reverses the sliding. */
#include "boom/boom_internal.h"

#include <math.h>

/* energy of one smoothed spring end at compression d (its force's integral) */
static double spring_energy(double k0, double e, double d)
{
    if (d <= 0.0)
        return 0.0;
    if (d >= e)
        return k0 * (0.35 * e * e + 0.5 * (d * d - e * e));
    double r = d / e;
    return k0 * e * e * (0.75 * r * r * r * r - 0.4 * r * r * r * r * r);
}

static double spring_stiffness(double k0, double e, double d)
{
    if (d <= 0.0)
        return 0.0;
    if (d >= e)
        return k0;
    double r = d / e;
    return k0 * (3.0 * r * r - 2.0 * r * r * r);
}

static double mu_of(const bd_boom_pads_def *p, double v)
{
    double av = fabs(v), vs = p->switch_speed;
    if (av <= vs)
        return p->mu_static * av / vs;
    return p->mu_dynamic + (p->mu_static - p->mu_dynamic) * exp(-(av - vs) / vs);
}

/* the contact's two points now, in the frame of the surface its pads
 * slide on (the point found by projection): with it the pad's compression
 * is stationary as that point moves along the surface, so moving it
 * (boom_remap, the projection) neither makes nor takes energy; with the
 * pads' own frame at the outer contact each remap released F ds dphi (21
 * kJ over the seed's frictionless extension) */
typedef struct pad_state {
    double tx, ty, nx, ny;    /* the surface's tangent and normal */
    double d, dd;             /* A's offset from B along n, its rate */
    double vs;                /* A's sliding speed on B along t */
    double dphi, dw;          /* relative rotation, its rate */
    double ima, imb;          /* 1 / effective masses of the points */
} pad_state;

static pad_state pad_state_of(const bd_boom *b, const boom_contact *c)
{
    double xa, ya, pa, vxa, vya, wa, xb, yb, pb, vxb, vyb, wb;
    boom_eval(b, &c->A, &xa, &ya, &pa, &vxa, &vya, &wa);
    boom_eval(b, &c->B, &xb, &yb, &pb, &vxb, &vyb, &wb);
    pad_state q;
    double pf = c->surface_on_A ? pa : pb;
    q.tx = cos(pf);
    q.ty = sin(pf);
    q.nx = -q.ty;
    q.ny = q.tx;
    q.d = (xa - xb) * q.nx + (ya - yb) * q.ny;
    q.dd = (vxa - vxb) * q.nx + (vya - vyb) * q.ny;
    q.vs = (vxa - vxb) * q.tx + (vya - vyb) * q.ty;
    q.dphi = pa - pb;
    q.dw = wa - wb;
    q.ima = boom_inv_mass(b, &c->A);
    q.imb = boom_inv_mass(b, &c->B);
    return q;
}

/* the pads' normal forces: springs at the pad ends and their dashpots */
static void contact_normal(bd_boom *b, boom_contact *c, const pad_state *qp, double *elastic,
                           double *diss)
{
    const bd_boom_pads_def *pd = &b->def.pads;
    pad_state q = *qp;
    double m_light = 1.0 / (q.ima > q.imb ? q.ima : q.imb);
    double k_end = 0.5 * pd->stiffness;
    double c_end = 2.0 * pd->damping_ratio * sqrt(k_end * m_light);
    double hw = 0.5 * pd->width;
    double F = 0.0, M = 0.0;       /* on A along n, moment on A */
    c->npad[0] = c->npad[1] = 0.0; /* upper, lower */
    for (int p = 0; p < 2; p++) {
        double sgn = p == 0 ? 1.0 : -1.0;
        for (int e = 0; e < 2; e++) {
            double xe = e == 0 ? -hw : hw;
            double del = sgn * (q.d + q.dphi * xe) - b->def.gap;
            if (del <= 0.0)
                continue;
            double deld = sgn * (q.dd + q.dw * xe);
            double fe = spring_stiffness(k_end, pd->smoothing, del) * del;
            double f = fe + c_end * deld;
            if (f < 0.0)
                f = 0.0;   /* a pad never pulls */
            *elastic += spring_energy(k_end, pd->smoothing, del);
            *diss += (f - fe) * deld;
            F -= sgn * f;
            M -= sgn * f * xe;
            c->npad[p] += f;
        }
    }
    boom_apply(b, &c->A, F * q.nx, F * q.ny, M);
    boom_apply(b, &c->B, -F * q.nx, -F * q.ny, -M);
    c->normal = c->npad[0] + c->npad[1];
    c->offset = q.d;
}

/* friction along the surface at each pad's face, +-h/2 off the axis, where
 * the sections' rotations add to the sliding: the face of pad p slides at
 * vs - p (h/2)(wA - wB), and its force F_p t there gives A the moment
 * -p (h/2) F_p; B takes the opposite of both. `share`: the loaded faces
 * whose points touch the same nodes, this one's included; each face takes
 * 1/share of the nodes' inertia, so faces sharing a node cannot together
 * reverse it within a step (alone, each would stop it: together they
 * overshot, a period-2 chatter where every section's top met at a fully
 * retracted boom) */
static void contact_friction(bd_boom *b, boom_contact *c, const pad_state *qp, int share,
                             double *diss)
{
    const bd_boom_pads_def *pd = &b->def.pads;
    pad_state q = *qp;
    double hh = 0.5 * c->h;
    double ija = boom_inv_inertia(b, &c->A), ijb = boom_inv_inertia(b, &c->B);
    double meff = 1.0 / (q.ima + q.imb + hh * hh * (ija + ijb)) / share;
    double Ff = 0.0, Mf = 0.0;
    for (int p = 0; p < 2; p++) {
        c->face_force[p] = 0.0;
        if (!(c->npad[p] > 0.0))
            continue;
        double sgn = p == 0 ? 1.0 : -1.0;
        double vf = q.vs - sgn * hh * q.dw;
        double Fp;
        if (fabs(vf) <= pd->switch_speed) {
            /* the stick ramp, implicit on the face's effective mass */
            double cf = pd->mu_static * c->npad[p] / pd->switch_speed;
            Fp = -cf * vf / (1.0 + cf * b->dt / meff);
        } else {
            /* sliding, but never more than stops the face within the
             * step: the explicit force would reverse the face's speed and
             * chatter (at a rotation-dominated face, period 2 at the
             * dynamic force's bound, seen settling a 25 t boom at 8 m) */
            double Fstop = meff * fabs(vf) / b->dt;
            Fp = -(vf > 0.0 ? 1.0 : -1.0) * fmin(mu_of(pd, vf) * c->npad[p], Fstop);
        }
        *diss += -Fp * vf;
        c->face_force[p] = Fp;
        c->face_speed[p] = vf;
        Ff += Fp;
        Mf -= sgn * hh * Fp;
    }
    boom_apply(b, &c->A, Ff * q.tx, Ff * q.ty, Mf);
    boom_apply(b, &c->B, -Ff * q.tx, -Ff * q.ty, -Mf);
    c->friction = Ff;
    c->slide = q.vs;
}

static int loaded_faces(const boom_contact *c)
{
    return (c->npad[0] > 0.0) + (c->npad[1] > 0.0);
}

static int share_nodes(const boom_contact *c, const boom_contact *o)
{
    int n[4] = {c->A.a, c->A.a + 1, c->B.a, c->B.a + 1};
    int m[4] = {o->A.a, o->A.a + 1, o->B.a, o->B.a + 1};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            if (n[i] == m[j])
                return 1;
    return 0;
}

void boom_pads(bd_boom *b, double *elastic, double *diss_power)
{
    double U = 0.0, D = 0.0;
    /* each contact's state once, for both passes */
    pad_state q[2 * BD_BOOM_MAX_SECTIONS];
    for (int j = 0; j + 1 < b->ns; j++) {
        boom_contact *ci = &b->c[2 * j], *co = &b->c[2 * j + 1];
        /* inner contact: section j+1's bottom node in section j */
        int bot = b->sec[j + 1].first;
        boom_project(b, j, b->x[bot], b->y[bot], &ci->B);
        q[2 * j] = pad_state_of(b, ci);
        contact_normal(b, ci, &q[2 * j], &U, &D);
        /* outer contact: section j's top node on section j+1, at the
         * point nearest to it: the key node where boom_remap could put
         * it there, else between nodes (boom_key_clamp) */
        int top = b->sec[j].first + b->sec[j].n - 1;
        boom_project(b, j + 1, b->x[top], b->y[top], &co->A);
        q[2 * j + 1] = pad_state_of(b, co);
        contact_normal(b, co, &q[2 * j + 1], &U, &D);
    }
    for (int j = 0; j < b->nc; j++) {
        boom_contact *c = &b->c[j];
        c->face_force[0] = c->face_force[1] = 0.0;
        c->friction = 0.0;
        if (loaded_faces(c) == 0)
            continue;
        int share = 0;
        for (int o = 0; o < b->nc; o++)
            if (o == j || share_nodes(c, &b->c[o]))
                share += loaded_faces(&b->c[o]);
        contact_friction(b, c, &q[j], share, &D);
    }
    *elastic = U;
    *diss_power = D;
}

double boom_pads_friction_correction(const bd_boom *b)
{
    double P = 0.0;
    for (int j = 0; j < b->nc; j++) {
        const boom_contact *c = &b->c[j];
        if (c->face_force[0] == 0.0 && c->face_force[1] == 0.0)
            continue;
        pad_state q = pad_state_of(b, c);
        for (int p = 0; p < 2; p++) {
            double sgn = p == 0 ? 1.0 : -1.0;
            double vf = q.vs - sgn * 0.5 * c->h * q.dw;
            P += -c->face_force[p] * 0.5 * (vf - c->face_speed[p]);
        }
    }
    return P;
}
