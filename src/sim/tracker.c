/* Trackers: which belt element is over a fixed point of the path. The belt
 * moves less than one element per step, so a tracker walks at most a few
 * elements from where it was: O(1) per step. */
#include "sim/system.h"

#include <math.h>

static double foot_gamma(const bd_sim *sim, int e, const double p[2])
{
    int j = e + 1 == sim->n ? 0 : e + 1;
    double ax = sim->x[j] - sim->x[e], ay = sim->y[j] - sim->y[e];
    double aa = ax * ax + ay * ay;
    if (aa <= 0.0)
        return 0.5;
    return ((p[0] - sim->x[e]) * ax + (p[1] - sim->y[e]) * ay) / aa;
}

void bd_tracker_init(const bd_sim *sim, bd_tracker *tr, double s)
{
    double L = sim->path.length;
    s = fmod(s, L);
    if (s < 0.0)
        s += L;
    tr->s = s;
    bd_path_point(&sim->path, s, tr->p, tr->dir);
    /* the node with the largest initial s not beyond the point */
    int lo = 0, hi = sim->n - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (sim->s_node0[mid] <= s)
            lo = mid;
        else
            hi = mid - 1;
    }
    tr->element = lo;
    if (sim->axial) {
        /* fixed stations: the point's place between its two nodes */
        double rel = s - sim->s_node0[lo];
        if (rel < 0.0) {
            tr->element = sim->n - 1;
            rel = s + L - sim->s_node0[sim->n - 1];
        }
        tr->gamma = rel / sim->ax.s_len[tr->element];
        return;
    }
    bd_tracker_update(sim, tr);
}

void bd_tracker_update(const bd_sim *sim, bd_tracker *tr)
{
    if (sim->axial)
        return;
    int n = sim->n;
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

/* belt tension at the tracked point: element tensions belong to element
 * midpoints; interpolate linearly between the two nearest */
double bd_tracker_tension(const bd_sim *sim, const bd_tracker *tr)
{
    int n = sim->n, e = tr->element;
    double g = tr->gamma;
    if (g >= 0.5) {
        int j = e + 1 == n ? 0 : e + 1;
        return sim->tension[e] + (g - 0.5) * (sim->tension[j] - sim->tension[e]);
    }
    int b = e == 0 ? n - 1 : e - 1;
    return sim->tension[b] + (g + 0.5) * (sim->tension[e] - sim->tension[b]);
}

/* belt speed at the tracked point along the travel, m/s: the nodes'
 * velocities interpolated (the axial belt's are along the path already) */
double bd_tracker_speed(const bd_sim *sim, const bd_tracker *tr)
{
    int e = tr->element, j = e + 1 == sim->n ? 0 : e + 1;
    double g = tr->gamma;
    if (sim->axial)
        return (1.0 - g) * sim->vx[e] + g * sim->vx[j];
    return (1.0 - g) * (tr->dir[0] * sim->vx[e] + tr->dir[1] * sim->vy[e])
         + g * (tr->dir[0] * sim->vx[j] + tr->dir[1] * sim->vy[j]);
}
