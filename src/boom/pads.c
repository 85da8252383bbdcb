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
 * Friction along the axis: mu rises linearly to mu_static at the switch
 * speed (the regularized stick), then falls to mu_dynamic
 * (mu = mu_d + (mu_s - mu_d) exp(-(|v| - v_s)/v_s)), at each pad's face.
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

static void one_contact(bd_boom *b, boom_contact *c, double *elastic, double *diss)
{
    const bd_boom_pads_def *pd = &b->def.pads;
    double xa, ya, pa, vxa, vya, wa, xb, yb, pb, vxb, vyb, wb;
    boom_eval(b, &c->A, &xa, &ya, &pa, &vxa, &vya, &wa);
    boom_eval(b, &c->B, &xb, &yb, &pb, &vxb, &vyb, &wb);
    /* the frame of the surface the pads slide on, at the contact point
     * (the point found by projection): with it the pad's compression is
     * stationary as that point moves along the surface, so moving it
     * (boom_remap, the projection) neither makes nor takes energy; with
     * the pads' own frame at the outer contact each remap released
     * F ds dphi (21 kJ over the seed's frictionless extension) */
    double pf = c->surface_on_A ? pa : pb;
    double tx = cos(pf), ty = sin(pf), nx = -ty, ny = tx;
    double d = (xa - xb) * nx + (ya - yb) * ny;
    double dd = (vxa - vxb) * nx + (vya - vyb) * ny;
    double dphi = pa - pb, dw = wa - wb;
    double ima = boom_inv_mass(b, &c->A), imb = boom_inv_mass(b, &c->B);
    double m_light = 1.0 / (ima > imb ? ima : imb);
    double k_end = 0.5 * pd->stiffness;
    double c_end = 2.0 * pd->damping_ratio * sqrt(k_end * m_light);
    double hw = 0.5 * pd->width;
    double F = 0.0, M = 0.0;       /* on A along n, moment on A */
    double Npad[2] = {0.0, 0.0};   /* upper, lower */
    for (int p = 0; p < 2; p++) {
        double sgn = p == 0 ? 1.0 : -1.0;
        for (int e = 0; e < 2; e++) {
            double xe = e == 0 ? -hw : hw;
            double del = sgn * (d + dphi * xe) - b->def.gap;
            if (del <= 0.0)
                continue;
            double deld = sgn * (dd + dw * xe);
            double fe = spring_stiffness(k_end, pd->smoothing, del) * del;
            double f = fe + c_end * deld;
            if (f < 0.0)
                f = 0.0;   /* a pad never pulls */
            *elastic += spring_energy(k_end, pd->smoothing, del);
            *diss += (f - fe) * deld;
            F -= sgn * f;
            M -= sgn * f * xe;
            Npad[p] += f;
        }
    }
    double Ntot = Npad[0] + Npad[1];
    /* friction along the outer axis at each pad's face, +-h/2 off the
     * axis, where the sections' rotations add to the sliding: the face of
     * pad p slides at vs - p (h/2)(wA - wB), and its force F_p t there
     * gives A the moment -p (h/2) F_p; B takes the opposite of both */
    double vs = (vxa - vxb) * tx + (vya - vyb) * ty;
    double hh = 0.5 * c->h;
    double ija = boom_inv_inertia(b, &c->A), ijb = boom_inv_inertia(b, &c->B);
    double meff = 1.0 / (ima + imb + hh * hh * (ija + ijb));
    double Ff = 0.0, Mf = 0.0;
    for (int p = 0; p < 2; p++) {
        c->face_force[p] = 0.0;
        if (!(Npad[p] > 0.0))
            continue;
        double sgn = p == 0 ? 1.0 : -1.0;
        double vf = vs - sgn * hh * dw;
        double Fp;
        if (fabs(vf) <= pd->switch_speed) {
            /* the stick ramp, implicit on the face's effective mass */
            double cf = pd->mu_static * Npad[p] / pd->switch_speed;
            Fp = -cf * vf / (1.0 + cf * b->dt / meff);
        } else {
            /* sliding, but never more than stops the face within the
             * step: the explicit force would reverse the face's speed and
             * chatter (at a rotation-dominated face, period 2 at the
             * dynamic force's bound, seen settling a 25 t boom at 8 m) */
            double Fstop = meff * fabs(vf) / b->dt;
            Fp = -(vf > 0.0 ? 1.0 : -1.0) * fmin(mu_of(pd, vf) * Npad[p], Fstop);
        }
        *diss += -Fp * vf;
        c->face_force[p] = Fp;
        c->face_speed[p] = vf;
        Ff += Fp;
        Mf -= sgn * hh * Fp;
    }
    double fxa = F * nx + Ff * tx, fya = F * ny + Ff * ty;
    boom_apply(b, &c->A, fxa, fya, M + Mf);
    boom_apply(b, &c->B, -fxa, -fya, -(M + Mf));
    c->normal = Ntot;
    c->friction = Ff;
    c->slide = vs;
}

void boom_pads(bd_boom *b, double *elastic, double *diss_power)
{
    double U = 0.0, D = 0.0;
    for (int j = 0; j + 1 < b->ns; j++) {
        boom_contact *ci = &b->c[2 * j], *co = &b->c[2 * j + 1];
        /* inner contact: section j+1's bottom node in section j */
        int bot = b->sec[j + 1].first;
        boom_project(b, j, b->x[bot], b->y[bot], &ci->B);
        one_contact(b, ci, &U, &D);
        /* outer contact: section j's top node on section j+1's key node
         * (boom_remap put the key node where the top is) */
        one_contact(b, co, &U, &D);
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
        double xa, ya, pa, vxa, vya, wa, xb, yb, pb, vxb, vyb, wb;
        boom_eval(b, &c->A, &xa, &ya, &pa, &vxa, &vya, &wa);
        boom_eval(b, &c->B, &xb, &yb, &pb, &vxb, &vyb, &wb);
        double pf = c->surface_on_A ? pa : pb;
        double vs = (vxa - vxb) * cos(pf) + (vya - vyb) * sin(pf);
        for (int p = 0; p < 2; p++) {
            double sgn = p == 0 ? 1.0 : -1.0;
            double vf = vs - sgn * 0.5 * c->h * (wa - wb);
            P += -c->face_force[p] * 0.5 * (vf - c->face_speed[p]);
        }
    }
    return P;
}
