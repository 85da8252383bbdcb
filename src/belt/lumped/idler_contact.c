/* Belt–idler contact (seed 001 §4.3.2): an idler touches the belt element
 * that is over it, at the foot point of its centre on the element.
 *
 * Normal: foot point p = x_e + γ·(x_j − x_e); the belt is pushed away from
 * the centre along n̂ = (p − c)/|p − c| by a penalty spring on the
 * penetration δ = R − |p − c|, shared by the element's nodes by the lever
 * rule, (1−γ) and γ (eqs 4.95–4.102; the thesis' 4.100 gives node i the
 * share d_i/l, which puts more force on the farther node). As for pulleys
 * (pulley_contact.c) the spring is stiff and linearly implicit: with the
 * contact point's effective mass m* = 1/((1−γ)²/m_e + γ²/m_j), its normal
 * velocity v_n and the normal acceleration a_o,n the other forces give it,
 *   f_n = k_c·(δ − Δt·v_n − Δt²·a_o,n) / (1 + k_c·Δt²/m*)  ≥ 0,
 * stable for any k_c (an explicit contact this stiff would ring near the
 * step's stability limit). The whole of f_n is booked as non-conservative
 * work, unlike at a pulley: the belt slides over the idler, so δ belongs to
 * a foot point that moves along the polygon, and in the stiff limit
 * (k_c·Δt²/m* ≫ 1) the contact holds δ ≥ Δt·v_n, not k_c·δ ≈ f_n. Booked
 * as a spring, k_c·δ did kilowatts of "work" on a belt running over loaded
 * idlers that ½k_c·δ² never stored (head_drive: +6.9 kW against −6.9 kW in
 * the rest of f_n; net 18 W), and the energy balance failed by 900%. The
 * energy the contact really stores, f_n²/(2k_c), is millijoules.
 *
 * Rolling (indentation) resistance: a force rr·f_n on the belt against its
 * motion over the idler (model-format.md `rolling_resistance`), smoothed
 * below BD_ROLLING_SPEED (laws/rolling.h) so a belt at rest carries none.
 *
 * Friction: t̂ along the belt in the direction of travel, slip speed
 * v_r = t̂·((1−γ)v_e + γv_j) − ω·R (eq 4.107). The stick force f (−f·t̂ on
 * the belt shared by the lever rule, +f·R on the idler) that makes v_r zero
 * at the end of the step solves eq 4.113:
 *   f = [v_r/Δt + (1−γ)·t̂·F_e/m_e + γ·t̂·F_j/m_j] / [(1−γ)²/m_e + γ²/m_j + R²/I]
 * (eq 4.114 rearranged; the idler has no other torque). |f| > μ_s·f_n slips
 * with ±μ_d·f_n (eqs 4.116–4.117). */
#include "belt/lumped/lumped.h"

#include <math.h>

#include "laws/rolling.h"

/* predictive contact gap, as a fraction of the element length */
#define IDLER_CONTACT_GAP 0.02

/* the belt, d from the idler's centre, off it by more than the
 * clearance that counts as lift-off (system.h) */
static void note_lifted(bd_sim *sim, const bd_idler *id, double d)
{
    if (d - id->m->radius > BD_LIFT_OFF_CLEARANCE && !sim->stabilizing)
        bd_lift_off_note(sim, id->m->s);
}

static void idler_contact(bd_sim *sim, bd_idler *id)
{
    bd_tracker_update(sim, &id->tr);
    id->alpha = 0.0;
    id->torque = 0.0;
    const bd_idler_model *im = id->m;
    int e = id->tr.element, j = e + 1 == sim->model->n ? 0 : e + 1;
    double g = id->tr.gamma, h = 1.0 - g;
    double px = sim->x[e] + g * (sim->x[j] - sim->x[e]);
    double py = sim->y[e] + g * (sim->y[j] - sim->y[e]);
    double rx = px - im->centre[0], ry = py - im->centre[1];
    double d2 = rx * rx + ry * ry;
    double Rc = im->radius + IDLER_CONTACT_GAP * sim->model->l0;
    if (d2 >= Rc * Rc) {
        note_lifted(sim, id, sqrt(d2));
        return;
    }
    /* reciprocals once: the divider is what bounds this loop */
    double d = sqrt(d2), inv_d = 1.0 / d;
    double nx = rx * inv_d, ny = ry * inv_d;
    double vcx = h * sim->vx[e] + g * sim->vx[j];
    double vcy = h * sim->vy[e] + g * sim->vy[j];
    double ie = 1.0 / sim->mass[e], ij = 1.0 / sim->mass[j];
    double he = h * ie, gj = g * ij;              /* lever share / node mass */
    double inv_m_eff = h * he + g * gj;           /* 1/m* */
    double aon = nx * (he * sim->fx[e] + gj * sim->fx[j]) + ny * (he * sim->fy[e] + gj * sim->fy[j]);
    double dt = sim->model->dt;
    double fn = im->k_contact * (im->radius - d - dt * (nx * vcx + ny * vcy) - dt * dt * aon)
              / (1.0 + im->k_contact * dt * dt * inv_m_eff);
    if (fn <= 0.0) {
        note_lifted(sim, id, d);
        return;
    }
    /* tangent along the travel direction */
    double tx = -ny, ty = nx;
    if (tx * id->tr.dir[0] + ty * id->tr.dir[1] < 0.0) {
        tx = -tx;
        ty = -ty;
    }
    double vt = tx * vcx + ty * vcy;
    double sat = vt * (1.0 / BD_ROLLING_SPEED);
    if (sat > 1.0)
        sat = 1.0;
    if (sat < -1.0)
        sat = -1.0;
    double frr = im->rolling * fn * sat;
    /* normal + rolling resistance on the two nodes, all non-conservative */
    double Fx = fn * nx - frr * tx, Fy = fn * ny - frr * ty;
    sim->fx[e] += h * Fx;
    sim->fy[e] += h * Fy;
    sim->fx[j] += g * Fx;
    sim->fy[j] += g * Fy;
    sim->fnx[e] += h * Fx;
    sim->fny[e] += h * Fy;
    sim->fnx[j] += g * Fx;
    sim->fny[j] += g * Fy;
    double R = im->radius;
    double vr = vt - id->omega * R;
    double num = vr * sim->model->inv_dt + he * (tx * sim->fx[e] + ty * sim->fy[e])
               + gj * (tx * sim->fx[j] + ty * sim->fy[j]);
    double den = inv_m_eff + im->r2_per_inertia;
    double f = num / den;
    if (fabs(f) > im->mu_s * fn)
        f = copysign(im->mu_d * fn, f);
    sim->fx[e] -= h * f * tx;
    sim->fy[e] -= h * f * ty;
    sim->fx[j] -= g * f * tx;
    sim->fy[j] -= g * f * ty;
    sim->fnx[e] -= h * f * tx;
    sim->fny[e] -= h * f * ty;
    sim->fnx[j] -= g * f * tx;
    sim->fny[j] -= g * f * ty;
    id->torque = f * R;
    id->alpha = id->torque * im->inv_inertia;
}

/* the supports phase: every idler, after the wraps */
void bd_lumped_idlers(bd_sim *sim)
{
    for (int i = 0; i < sim->model->idler_count; i++)
        idler_contact(sim, &sim->idlers[i]);
}
