/* Takeups (model-format.md `takeup`, seed 001 §4.2.2 eqs 4.63–4.65): the
 * carriage slides along its axis a under the takeup pull F(t) (gravity: the
 * counterweight's weight; constant_force: the set force or its table), the
 * pulley's own weight and the belt's forces on the pulley:
 *   (m_pulley + m_takeup)·q̈ = F(t) + m_pulley·g·(−a_y) + F_belt·a
 * The carriage stops at the ends of `travel`. */
#include "parts/parts.h"

#include <math.h>

double bd_takeup_force(const bd_takeup *tk, double t)
{
    return bd_table_eval(&tk->def->force, t);
}

/* the carriage's outside pull along its axis at the present time: the
 * takeup force and the pulley's weight (the belt's force apart) */
double bd_takeup_pull(const bd_sim *sim, const bd_takeup *tk, const bd_pulley_body *p)
{
    return bd_takeup_force(tk, sim->t) - p->m->def->mass * sim->model->gravity * p->m->axis[1];
}

/* advance the carriage one step; returns the non-conservative work done on
 * it this step (J) and adds the set-point work to *input */
double bd_takeup_advance(bd_sim *sim, bd_takeup *tk, bd_pulley_body *p, double *input,
                         double *input_at_t)
{
    const bd_takeup_def *td = tk->def;
    double F = bd_takeup_force(tk, sim->t);
    /* a changing set force changes the potential −F·q: that is work put in,
     * −∫q·dF, with q at the middle of the interval the force changed over */
    double w_set = -(F - tk->force_prev) * (p->q - 0.5 * p->qdot * sim->model->dt);
    *input += w_set;
    *input_at_t += w_set;
    tk->force_prev = F;
    double pull = bd_takeup_pull(sim, tk, p) + p->f_axis;
    double q_old = p->qdot;
    p->qddot = pull / p->m->carriage_mass;
    p->qdot += p->qddot * sim->model->dt;
    double q_new = p->q + p->qdot * sim->model->dt;
    if (td->has_travel && (q_new < td->travel_min || q_new > td->travel_max)) {
        q_new = q_new < td->travel_min ? td->travel_min : td->travel_max;
        p->qdot = 0.0;
        p->qddot = 0.0;
        /* counted here, said once after the run (part.c): no allocation or
         * text in the step loop, and one line however often it bangs */
        if (!tk->at_limit) {
            if (tk->limit_hits == 0) {
                tk->limit_first_t = sim->t;
                tk->limit_first_q = q_new;
            }
            tk->limit_hits++;
        }
        tk->at_limit = 1;
    } else {
        tk->at_limit = 0;
    }
    double dq = q_new - p->q;
    p->q = q_new;
    p->cx += dq * p->m->axis[0];
    p->cy += dq * p->m->axis[1];
    if (p->q < p->travel_min)
        p->travel_min = p->q;
    if (p->q > p->travel_max)
        p->travel_max = p->q;
    return p->fnc_axis * 0.5 * (q_old + p->qdot) * sim->model->dt;
}
