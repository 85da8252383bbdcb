/* The sections' beam elements: corotational planar Euler-Bernoulli.
 *
 * Geometrically exact in the sense of seed 003 §5 for a plane: the strains
 * are the stretch of the axis and its curvature, measured in the element's
 * own rotating frame (the chord), so rigid motions of any size leave them
 * zero. In that frame the element is linear: axial force
 * N = EA (l - l0)/l0, end moments Ma = EI/l0 (4 ta + 2 tb),
 * Mb = EI/l0 (2 ta + 4 tb), ta and tb the nodes' cross-section angles
 * against the chord (the two-node Euler-Bernoulli element's end moments in
 * its corotated frame: M. A. Crisfield, Non-linear Finite Element Analysis
 * of Solids and Structures, vol. 1, Wiley 1991, ch. 7). Their virtual
 * work N dl + Ma dta + Mb dtb with dl = e.(drb - dra) and
 * dta = dphia - n.(drb - dra)/l gives the nodal forces. l0 is the
 * element's material length s_b - s_a, which changes as the spatial nodes
 * move through the material.
 *
 * Damping: Kelvin-Voigt on the material strain rates, beta times the
 * stiffness (the stiffness-proportional half of Rayleigh damping). */
#include "boom/boom_internal.h"

#include <math.h>

#include "base/constants.h"

static double wrap_angle(double a)
{
    while (a > BD_PI)
        a -= 2.0 * BD_PI;
    while (a <= -BD_PI)
        a += 2.0 * BD_PI;
    return a;
}

void boom_beam_forces(bd_boom *b, double *elastic, double *damp_power)
{
    double U = 0.0, P = 0.0;
    const double beta = b->beta;
    for (int k = 0; k < b->ns; k++) {
        const boom_section *S = &b->sec[k];
        for (int a = S->first; a < S->first + S->n - 1; a++) {
            int c = a + 1;
            double dx = b->x[c] - b->x[a], dy = b->y[c] - b->y[a];
            double l = sqrt(dx * dx + dy * dy);
            double l0 = b->s[c] - b->s[a];
            double ex = dx / l, ey = dy / l;
            double nx = -ey, ny = ex;
            double bet = atan2(dy, dx);
            double ta = wrap_angle(b->phi[a] - bet), tb = wrap_angle(b->phi[c] - bet);
            double ka = S->EA / l0, kb = S->EI / l0;
            double Ne = ka * (l - l0);
            double Ma = kb * (4.0 * ta + 2.0 * tb), Mb = kb * (2.0 * ta + 4.0 * tb);
            U += 0.5 * Ne * (l - l0) + kb * (2.0 * ta * ta + 2.0 * ta * tb + 2.0 * tb * tb);
            /* material rates: the nodes' velocities are the material's */
            double dvx = b->vx[c] - b->vx[a], dvy = b->vy[c] - b->vy[a];
            double ldot = ex * dvx + ey * dvy;
            double bdot = (nx * dvx + ny * dvy) / l;
            double tad = b->w[a] - bdot, tbd = b->w[c] - bdot;
            double Nd = beta * ka * ldot;
            double Mad = beta * kb * (4.0 * tad + 2.0 * tbd);
            double Mbd = beta * kb * (2.0 * tad + 4.0 * tbd);
            P += Nd * ldot + Mad * tad + Mbd * tbd;
            Ne += Nd;
            Ma += Mad;
            Mb += Mbd;
            double Q = (Ma + Mb) / l;
            double gx = Ne * ex - Q * nx, gy = Ne * ey - Q * ny;
            b->fx[a] += gx;
            b->fy[a] += gy;
            b->fx[c] -= gx;
            b->fy[c] -= gy;
            b->mz[a] -= Ma;
            b->mz[c] -= Mb;
            b->eN[a] = Ne;
            b->eMa[a] = Ma;
            b->eMb[a] = Mb;
            b->eV[a] = Q;
        }
    }
    *elastic = U;
    *damp_power = P;
}
