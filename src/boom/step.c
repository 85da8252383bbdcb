/* One step of the boom: forces, then symplectic Euler (velocities, then
 * positions, explicit: the stable step is found in build.c), then the
 * spatial nodes move to where the contacts are (boom/layout.c).
 *
 * Structural damping is Rayleigh's pair: beta on the strain rates
 * (boom/beam.c) and alpha on the mass, applied to the velocity relative to
 * the rigid boom (the profile's motion): the sections' elastic motion is
 * damped, their commanded motion is not dragged. Its work splits into a
 * dissipation alpha m |v - v_rigid|^2 >= 0 and an exchange with the
 * commanded motion counted as input. */
#include "boom/boom_internal.h"

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "base/constants.h"

void boom_kinematics(bd_boom *b, double t)
{
    bd_boom_stroke_eval(&b->def.stroke, t, &b->stroke_ref, &b->stroke_v, &b->stroke_a);
    const double h = 1e-6;
    b->theta = bd_table_eval(&b->def.luffing_angle, t);
    b->cos_theta = cos(b->theta);
    b->sin_theta = sin(b->theta);
    b->theta_dot = (bd_table_eval(&b->def.luffing_angle, t + h)
                    - bd_table_eval(&b->def.luffing_angle, t > h ? t - h : 0.0))
                 / (t > h ? 2.0 * h : h + t);
}

void boom_forces(bd_boom *b, double *elastic, double *diss_power, double *in_power)
{
    int N = b->N;
    memset(b->fx, 0, (size_t)N * sizeof *b->fx);
    memset(b->fy, 0, (size_t)N * sizeof *b->fy);
    memset(b->mz, 0, (size_t)N * sizeof *b->mz);
    for (int i = 0; i < N; i++)
        b->fy[i] -= b->m[i] * b->g;
    double U = 0.0, D = 0.0, P = 0.0, u, d, p;
    boom_beam_forces(b, &u, &d);
    U += u;
    D += d;
    if (b->alpha > 0.0) {
        for (int k = 0; k < b->ns; k++) {
            const boom_section *S = &b->sec[k];
            for (int i = S->first; i < S->first + S->n; i++) {
                double rx, ry, rvx, rvy;
                boom_rigid_point(b, k, b->s[i], &rx, &ry, &rvx, &rvy);
                double ex = b->vx[i] - rvx, ey = b->vy[i] - rvy, ew = b->w[i] - b->theta_dot;
                double am = b->alpha * b->m[i], aj = b->alpha * b->J[i];
                b->fx[i] -= am * ex;
                b->fy[i] -= am * ey;
                b->mz[i] -= aj * ew;
                D += am * (ex * ex + ey * ey) + aj * ew * ew;
                P -= am * (ex * rvx + ey * rvy) + aj * ew * b->theta_dot;
            }
        }
    }
    boom_pads(b, &u, &d);
    U += u;
    D += d;
    boom_actuators(b, &u, &d, &p);
    U += u;
    D += d;
    P += p;
    *elastic = U;
    *diss_power = D;
    *in_power = P;
}

void boom_tip(const bd_boom *b, double *x, double *y, double *vx, double *vy)
{
    int i = b->N - 1;
    *x = b->x[i];
    *y = b->y[i];
    *vx = b->vx[i];
    *vy = b->vy[i];
}

void boom_tip_rigid(const bd_boom *b, double *x, double *y)
{
    double vx, vy;
    boom_rigid_point(b, b->ns - 1, b->sec[b->ns - 1].L, x, y, &vx, &vy);
}

static double kinetic(const bd_boom *b)
{
    double K = 0.0;
    for (int i = 0; i < b->N; i++)
        K += b->m[i] * (b->vx[i] * b->vx[i] + b->vy[i] * b->vy[i]) + b->J[i] * b->w[i] * b->w[i];
    return 0.5 * K;
}

static double gravity_energy(const bd_boom *b)
{
    double G = 0.0;
    for (int i = 0; i < b->N; i++)
        G += b->m[i] * b->g * b->y[i];
    return G;
}

/* NaN, an element stretched or crushed past any steel's, a pad pushed
 * through: where and why into err; 1 = out of bounds */
static int out_of_bounds(const bd_boom *b, char *err, size_t errlen)
{
    for (int k = 0; k < b->ns; k++) {
        int last = b->sec[k].first + b->sec[k].n - 1;
        for (int i = b->sec[k].first; i <= last; i++) {
            if (!isfinite(b->x[i]) || !isfinite(b->y[i]) || !isfinite(b->vx[i])
                || !isfinite(b->vy[i]) || !isfinite(b->phi[i])) {
                snprintf(err, errlen, "at t = %.4f s the state of section %d at s = %.2f m is "
                         "not finite: the run diverged (time step %.3g s)", b->t, k + 1, b->s[i],
                         b->dt);
                return 1;
            }
            if (i < last) {
                double l = hypot(b->x[i + 1] - b->x[i], b->y[i + 1] - b->y[i]);
                double l0 = b->s[i + 1] - b->s[i];
                if (l < 0.5 * l0 || l > 1.5 * l0) {
                    snprintf(err, errlen, "at t = %.4f s section %d between s = %.2f and %.2f m "
                             "is %s to %.0f %% of its length: the run diverged (time step %.3g "
                             "s)",
                             b->t, k + 1, b->s[i], b->s[i + 1], l < l0 ? "crushed" : "stretched",
                             100.0 * l / l0, b->dt);
                    return 1;
                }
            }
        }
    }
    /* the pads' offsets as their forces last found them (boom_pads) */
    for (int j = 0; j < b->nc; j++) {
        const boom_contact *c = &b->c[j];
        double d = c->offset;
        if (fabs(d) > b->def.gap + 0.25 * c->h) {
            snprintf(err, errlen, "at t = %.4f s section %d's %s pads are %.0f mm across the "
                     "axis of section %d (clearance %.0f mm): the pads let go or the run "
                     "diverged (time step %.3g s)", b->t, c->inner_sec + 1,
                     j % 2 == 0 ? "bottom" : "outer-contact", 1e3 * fabs(d), c->outer_sec + 1,
                     1e3 * b->def.gap, b->dt);
            return 1;
        }
    }
    return 0;
}

void boom_evaluate(bd_boom *b)
{
    double U, D, P;
    boom_kinematics(b, b->t);
    boom_forces(b, &U, &D, &P);
    int pin = b->sec[0].first;
    if (!b->def.luffing_cylinder.present) {
        /* the moment about the pivot that holds section 1 at the angle:
         * J theta'' - sum of the others (theta'' = 0 on a linear table
         * segment) */
        double rx = b->x[pin] - b->def.pivot[0], ry = b->y[pin] - b->def.pivot[1];
        b->luff_force = -(b->mz[pin] + rx * b->fy[pin] - ry * b->fx[pin]);
        P += b->luff_force * b->theta_dot;
    }
    b->pend_diss = D;
    b->pend_in = P;
    /* the energy of this state: positions now, the velocity the mean of
     * the half steps around it (the second half added in boom_advance) */
    b->e_pot = gravity_energy(b) + U;
    b->pend_kin = kinetic(b);
}

int boom_advance(bd_boom *b, int settle, char *err, size_t errlen)
{
    double dt = b->dt;
    int pin = b->sec[0].first;
    int held_angle = !b->def.luffing_cylinder.present;
    double w_pin = b->w[pin];
    for (int i = 0; i < b->N; i++) {
        b->vx[i] += dt * b->fx[i] / b->m[i];
        b->vy[i] += dt * b->fy[i] / b->m[i];
        b->w[i] += dt * b->mz[i] / b->J[i];
    }
    /* section 1's bottom node turns about the pivot, r from the pivot to
     * it (zero without a pivot_offset): J_p w' = mz + r x f, J_p = J + m r²,
     * v = w x r; held: w = theta' */
    double rx = b->x[pin] - b->def.pivot[0], ry = b->y[pin] - b->def.pivot[1];
    double r2 = rx * rx + ry * ry;
    if (held_angle) {
        b->w[pin] = b->theta_dot;
    } else if (r2 > 0.0) {
        double Mp = b->mz[pin] + rx * b->fy[pin] - ry * b->fx[pin];
        b->w[pin] = w_pin + dt * Mp / (b->J[pin] + b->m[pin] * r2);
    }
    b->vx[pin] = -b->w[pin] * ry;
    b->vy[pin] = b->w[pin] * rx;
    /* the friction's work at the step's mean sliding speed (the stick
     * ramp's force reverses the speed within a step: booked at the
     * starting speed alone it was the balance's largest error) */
    if (!settle)
        b->pend_diss += boom_pads_friction_correction(b);
    double K_after = kinetic(b);
    if (!settle) {
        b->e_kin = 0.5 * (b->pend_kin + K_after);
        if (b->t == 0.0)
            b->e_0 = b->e_kin + b->e_pot;
        if (b->e_kin > b->e_norm)
            b->e_norm = b->e_kin;
        double bal = fabs(b->e_kin + b->e_pot + b->e_diss - b->e_in - b->e_0);
        double ref = fmax(fmax(fabs(b->e_0), b->e_in), fmax(b->e_norm, 1.0));
        if (bal / ref > b->balance_rel)
            b->balance_rel = bal / ref;
    }
    for (int i = 0; i < b->N; i++) {
        b->x[i] += dt * b->vx[i];
        b->y[i] += dt * b->vy[i];
        b->phi[i] += dt * b->w[i];
    }
    if (held_angle) {
        boom_kinematics(b, settle ? b->t : b->t + dt);
        b->phi[pin] = b->theta;
    }
    /* back onto the circle about the pivot (the Euler step leaves it by
     * O(dt²)); the pin itself when there is no offset */
    {
        double c = cos(b->phi[pin]), sn = sin(b->phi[pin]);
        b->x[pin] = b->def.pivot[0] + b->base_a * c - b->base_n * sn;
        b->y[pin] = b->def.pivot[1] + b->base_a * sn + b->base_n * c;
    }
    boom_remap(b);
    b->steps++;
    if (!settle) {
        b->t += dt;
        b->e_diss += b->pend_diss * dt;
        b->e_in += b->pend_in * dt;
    }
    return out_of_bounds(b, err, errlen);
}

int boom_step(bd_boom *b, int settle, char *err, size_t errlen)
{
    boom_evaluate(b);
    return boom_advance(b, settle, err, errlen);
}

int boom_settle(bd_boom *b, long max_steps, volatile sig_atomic_t *interrupted, char *err,
                size_t errlen)
{
    const long window = 2000;
    double vmax = 0.0;
    /* the first bending mode critically damped (on the velocity: the
     * rigid boom is at rest at t = 0). Kinetic damping (velocities zeroed
     * at every peak of kinetic energy) was tried and stalls here: the
     * pads' and the rod's fast modes peak every few steps and the reset
     * kills the slow sag before it gets anywhere */
    double alpha = b->alpha;
    b->alpha = fmax(alpha, 2.0 * BD_TWO_PI * b->f1_hz);
    int rc = 1;
    long n = 1;
    for (; n <= max_steps && rc == 1; n++) {
        if (boom_step(b, 1, err, errlen)) {
            rc = -1;
            break;
        }
        for (int i = 0; i < b->N; i++)
            vmax = fmax(vmax, hypot(b->vx[i], b->vy[i]));
        if (n % window == 0) {
            if (vmax < 1e-5)
                rc = 0;
            vmax = 0.0;
            if (interrupted && *interrupted)
                rc = 2;
        }
    }
    b->alpha = alpha;
    b->settle_steps = n - 1;
    if (rc == 1)
        snprintf(err, errlen, "the boom did not come to rest under gravity within %ld steps; "
                 "the run starts from where it stood", max_steps);
    return rc;
}
