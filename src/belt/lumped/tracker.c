/* Trackers: which belt element is over a fixed point of the path. The belt
 * moves less than one element per step, so a tracker walks at most a few
 * elements from where it was: O(1) per step. */
#include "belt/lumped/lumped.h"

#include <math.h>

static double foot_gamma(const bd_sim *sim, int e, const double p[2])
{
    int j = e + 1 == sim->model->n ? 0 : e + 1;
    double ax = sim->x[j] - sim->x[e], ay = sim->y[j] - sim->y[e];
    double aa = ax * ax + ay * ay;
    if (aa <= 0.0)
        return 0.5;
    return ((p[0] - sim->x[e]) * ax + (p[1] - sim->y[e]) * ay) / aa;
}

void bd_tracker_init(const bd_sim *sim, bd_tracker *tr, double s)
{
    bd_belt_point_place(sim, tr, s);
    bd_tracker_update(sim, tr);
}

void bd_tracker_update(const bd_sim *sim, bd_tracker *tr)
{
    int n = sim->model->n;
    int e = tr->element;
    double g = foot_gamma(sim, e, tr->p);
    for (int it = 0; it < 8 && (g > 1.0 || g < 0.0); it++) {
        int next = g > 1.0 ? (e + 1) % n : (e + n - 1) % n;
        double gn = foot_gamma(sim, next, tr->p);
        /* over the node between two elements (a kink): stay, clamped */
        if ((g > 1.0 && gn < 0.0) || (g < 0.0 && gn > 1.0)) {
            g = g > 1.0 ? 1.0 : 0.0;
            break;
        }
        e = next;
        g = gn;
    }
    if (g > 1.0)
        g = 1.0;
    if (g < 0.0)
        g = 0.0;
    tr->element = e;
    tr->gamma = g;
}

/* belt speed at the tracked point along the travel, m/s: the nodes'
 * velocities interpolated */
double bd_tracker_speed(const bd_sim *sim, const bd_tracker *tr)
{
    int e = tr->element, j = e + 1 == sim->model->n ? 0 : e + 1;
    double g = tr->gamma;
    return (1.0 - g) * (tr->dir[0] * sim->vx[e] + tr->dir[1] * sim->vy[e])
         + g * (tr->dir[0] * sim->vx[j] + tr->dir[1] * sim->vy[j]);
}

void bd_lumped_sample(const bd_sim *sim, const bd_tracker *tr, bd_belt_sample *out)
{
    bd_belt_point_position(sim, tr, &out->x, &out->y);
    out->tension = bd_belt_point_tension(sim, tr);
    out->speed = bd_tracker_speed(sim, tr);
}

/* Eulerian path coordinate of element e's midpoint: its projection on the
 * path, searched from the segment it was on last time */
double bd_lumped_element_s(const bd_sim *sim, int e)
{
    int *seg_hint = bd_lumped_of(sim)->seg_hint;
    int j = e + 1 == sim->model->n ? 0 : e + 1;
    double mx = 0.5 * (sim->x[e] + sim->x[j]), my = 0.5 * (sim->y[e] + sim->y[j]);
    int nseg = sim->model->path.segment_count;
    int seg = seg_hint[e];
    double u = 0.0;
    for (int it = 0; it < 6; it++) {
        const bd_path_segment *g = &sim->model->path.segments[seg];
        if (g->kind == BD_SEGMENT_SPAN) {
            u = bd_path_span_project(&sim->model->path, g, mx, my);
        } else {
            u = bd_path_arc_position(g->centre, g->radius, g->angle0, g->sweep, mx, my);
        }
        if (u < 0.0 && it < 5)
            seg = (seg + nseg - 1) % nseg;
        else if (u > g->length && it < 5)
            seg = (seg + 1) % nseg;
        else
            break;
    }
    seg_hint[e] = seg;   /* a cache, not state */
    const bd_path_segment *g = &sim->model->path.segments[seg];
    if (u < 0.0)
        u = 0.0;
    if (u > g->length)
        u = g->length;
    return g->s0 + u;
}

/* belt speed along element e, m/s */
double bd_lumped_element_speed(const bd_sim *sim, int e)
{
    const bd_lumped *L = bd_lumped_of(sim);
    int j = e + 1 == sim->model->n ? 0 : e + 1;
    return 0.5 * (L->ux[e] * (sim->vx[e] + sim->vx[j]) + L->uy[e] * (sim->vy[e] + sim->vy[j]));
}

double bd_lumped_element_strain(const bd_sim *sim, int e)
{
    /* from the tension: an element wrapped on a pulley has the belt's
     * length there, not its chord's (wrap_elements.c) */
    return (sim->tension[e] - bd_lumped_of(sim)->td[e]) / sim->model->EA;
}

/* along the element that leaves the node */
double bd_lumped_node_speed(const bd_sim *sim, int i)
{
    const bd_lumped *L = bd_lumped_of(sim);
    return sim->vx[i] * L->ux[i] + sim->vy[i] * L->uy[i];
}
