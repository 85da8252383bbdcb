/* Elements that run round a pulley: their length is the belt's, along the
 * shell, not the chord between their nodes.
 *
 * A chain of straight elements wrapped on a pulley is a polygon: its nodes
 * sit on R, its chords cut the arc. Run over the pulley it acts as a chain
 * on a sprocket (chordal action): the span that leaves from the last node
 * on the shell swings and rises with every node, the next node lands on the
 * shell with a normal speed v·sin(θ/2) that the contact stops (a loss of
 * ½m(v·sin(θ/2))² per node and tangent point), and a shell turning at ω
 * moves the belt at R·ω·sin(θ/2)/(θ/2), 1.1 % slow at the default 30°
 * element. At that element the running force of generated conveyors was
 * 5–200 % above their own resistance law and converged only as l0²
 * (issue 10). A real belt has none of this: between its nodes it follows
 * the shell and leaves it along the tangent.
 *
 * So an element whose chord would cut into a pulley takes the length of
 * the shortest path between its nodes round the shell: from node i along
 * its tangent to the circle, round the arc in the sense the belt wraps,
 * and along the tangent to node j (a node on or in the shell starts or
 * ends the arc at its own angle):
 *   l = L_i + L_j + R·Δ,   Δ = Δψ_ij − β_i − β_j > 0,
 *   L_k = √(a_k² − R²),  β_k = acos(R/a_k)   (node k off the shell, a_k > R),
 *   L_k = β_k = 0                             (node k on or in the shell),
 * with a_k the node's distance from the centre and Δψ_ij the angle from i
 * to j in the wrap's sense. Where Δ reaches 0 the path is the straight
 * chord touching the circle once: l and its gradient are continuous there.
 * The tension T = k·(l − l0) + c·dl/dt acts on the nodes along −∂l/∂x_i
 * and −∂l/∂x_j, with ê_r,k radial and ê_t,k the wrap's tangent at node k,
 *   ∂l/∂x_j = (L_j·ê_r,j + R·ê_t,j)/a_j,   ∂l/∂x_i = (L_i·ê_r,i − R·ê_t,i)/a_i,
 * the tangent lines' unit vectors off the shell, the shell's tangent on
 * it: a node on a tangent is pulled along it (it lands tangentially, no
 * impact) and leaves from the tangent point. The arc's pressure,
 * T·(∂l/∂x_i + ∂l/∂x_j) = −T·∂l/∂c, acts on the shell (a takeup carriage
 * feels it). ½k(l − l0)² is the elastic energy, so these forces are
 * conservative (the dashpot apart).
 *
 * The friction on the arc is lumped on the element's nodes by the lever
 * rule: the arc's pressure P = |T·(∂l/∂x_i + ∂l/∂x_j)| acts at its middle,
 * L_i + R·Δ/2 along the element from node i, and each node's friction may
 * reach μ times its share (pulley_contact.c adds it to the node's normal
 * force from the shell, which now carries only its weight and inertia).
 * Moving the pressure itself onto the nodes was tried and dropped: a node
 * pushed onto the shell by its share of the arc behind it rides half an
 * element past the tangent point, the polygon's fault again, and the
 * force it moves does work (a frictionless loop "dissipated" −17 J of a
 * 2.8 kJ swing).
 *
 * Derived here (plane geometry of a string wrapped on a circle); the
 * lumped belt it changes is seed 001 §4.1, §4.3.1; docs/physics.md §4. */
#include "belt/lumped/lumped.h"

#include <math.h>
#include <string.h>

#include "base/constants.h"

/* the belt's length between nodes i and j round pulley (c, R) turning
 * the `wrap` way (±1): 1 and l, the lever (the arc's middle along the
 * element from i, a fraction of l; NULL: not wanted) and the gradients
 * ∂l/∂x_i, ∂l/∂x_j when the element runs round it, else 0 */
static int geodesic(double cx, double cy, double R, double wrap, double xi, double yi,
                    double xj, double yj, double *l, double *lever, double gi[2], double gj[2])
{
    double rix = xi - cx, riy = yi - cy, rjx = xj - cx, rjy = yj - cy;
    double ai = sqrt(rix * rix + riy * riy), aj = sqrt(rjx * rjx + rjy * rjy);
    /* the angle from i to j in the wrap's sense; an element turns less
     * than a half turn, elements far round the circle are not wrapped */
    double dpsi = wrap * atan2(rix * rjy - riy * rjx, rix * rjx + riy * rjy);
    if (!(dpsi > 0.0))
        return 0;
    double Li = 0.0, Lj = 0.0, bi = 0.0, bj = 0.0;
    if (ai > R) {
        Li = sqrt(ai * ai - R * R);
        bi = acos(R / ai);
    }
    if (aj > R) {
        Lj = sqrt(aj * aj - R * R);
        bj = acos(R / aj);
    }
    double arc = dpsi - bi - bj;
    if (!(arc > 0.0))
        return 0;
    *l = Li + Lj + R * arc;
    if (lever)
        *lever = (Li + 0.5 * R * arc) / *l;
    double eix = rix / ai, eiy = riy / ai, ejx = rjx / aj, ejy = rjy / aj;
    /* the wrap's tangent: wrap·perp(ê_r), as pulley_contact.c's t̂ */
    double tix = -wrap * eiy, tiy = wrap * eix, tjx = -wrap * ejy, tjy = wrap * ejx;
    double cri = ai > R ? Li / ai : 0.0, crj = aj > R ? Lj / aj : 0.0;
    double cti = -R / ai, ctj = R / aj;
    gi[0] = cri * eix + cti * tix;
    gi[1] = cri * eiy + cti * tiy;
    gj[0] = crj * ejx + ctj * tjx;
    gj[1] = crj * ejy + ctj * tjy;
    return 1;
}

/* The forces phase, after the chords (forces.c element_pass): every
 * element with a node in a wrap's sector that the geodesic finds wrapped
 * gets its length, tension and dashpot from it; listed for the node forces
 * (bd_lumped_wrap_forces) and its pull on the shell summed. The sector's
 * run is kept for the contact (pulley_contact.c gather). O(nodes in the
 * sectors). */
void bd_lumped_wrap_elements(bd_sim *sim)
{
    bd_lumped *L = bd_lumped_of(sim);
    const bd_lumped_model *LM = bd_lumped_model_of(sim);
    const int n = sim->model->n;
    const double k = LM->k_axial, c = LM->c_axial, l0 = sim->model->l0;
    L->wrapped_count = 0;
    for (int pi = 0; pi < sim->model->pulley_count; pi++) {
        bd_pulley_body *p = &sim->pulleys[pi];
        bd_wrap_contact *W = &L->wraps[pi];
        int first, count;
        W->anchor = bd_lumped_find_sector(sim, p, W, &first, &count);
        W->run_first = first;
        W->run_count = count;
        W->react[0] = W->react[1] = 0.0;
        W->react_d[0] = W->react_d[1] = 0.0;
        for (int w = 0; w < count; w++)
            W->run_arc[w] = 0.0;
        const double R = p->m->radius, wrap = p->m->wrap;
        const double vcx = p->qdot * p->m->axis[0], vcy = p->qdot * p->m->axis[1];
        /* the elements of the run, and the one that enters it */
        int e = bd_node_prev(first, n);
        for (int w = 0; w <= count; w++, e = bd_node_next(e, n)) {
            if (L->wrap_mark[e])
                continue;
            int j = bd_node_next(e, n);
            double len, lever, gi[2], gj[2];
            if (!geodesic(p->cx, p->cy, R, wrap, sim->x[e], sim->y[e], sim->x[j],
                                    sim->y[j], &len, &lever, gi, gj))
                continue;
            double ldot = gi[0] * (sim->vx[e] - vcx) + gi[1] * (sim->vy[e] - vcy)
                        + gj[0] * (sim->vx[j] - vcx) + gj[1] * (sim->vy[j] - vcy);
            double td = c * ldot, T = k * (len - l0) + td;
            sim->tension[e] = T;
            L->td[e] = td;
            L->wrap_mark[e] = 1;
            bd_wrapped_element *we = &L->wrapped[L->wrapped_count++];
            we->e = e;
            memcpy(we->gi, gi, sizeof we->gi);
            memcpy(we->gj, gj, sizeof we->gj);
            /* −T·∂l/∂c = T·(∂l/∂x_i + ∂l/∂x_j) on the shell */
            W->react[0] += T * (gi[0] + gj[0]);
            W->react[1] += T * (gi[1] + gj[1]);
            W->react_d[0] += td * (gi[0] + gj[0]);
            W->react_d[1] += td * (gi[1] + gj[1]);
            /* the arc's pressure, shared by its nodes' friction by the
             * lever rule about the arc's middle (pulley_contact.c), kept
             * by the nodes' places in this pulley's run: a node in two
             * pulleys' runs carries each one's share to its own shell */
            if (T > 0.0) {
                double P = T * hypot(gi[0] + gj[0], gi[1] + gj[1]);
                if (w > 0)
                    W->run_arc[w - 1] += (1.0 - lever) * P;
                if (w < count)
                    W->run_arc[w] += lever * P;
            }
        }
    }
}

/* after the node pass, which pulled the nodes of every element along its
 * chord u with its tension: a wrapped element's nodes are pulled along
 * −∂l/∂x instead (node i got +T·u, node j −T·u) */
void bd_lumped_wrap_forces(bd_sim *sim)
{
    bd_lumped *L = bd_lumped_of(sim);
    const int n = sim->model->n;
    for (int w = 0; w < L->wrapped_count; w++) {
        const bd_wrapped_element *we = &L->wrapped[w];
        int e = we->e, j = bd_node_next(e, n);
        double ux = L->ux[e], uy = L->uy[e];
        const double T = sim->tension[e], td = L->td[e];
        sim->fx[e] -= T * (we->gi[0] + ux);
        sim->fy[e] -= T * (we->gi[1] + uy);
        sim->fx[j] -= T * (we->gj[0] - ux);
        sim->fy[j] -= T * (we->gj[1] - uy);
        sim->fnx[e] -= td * (we->gi[0] + ux);
        sim->fny[e] -= td * (we->gi[1] + uy);
        sim->fnx[j] -= td * (we->gj[0] - ux);
        sim->fny[j] -= td * (we->gj[1] - uy);
        L->wrap_mark[e] = 0;
    }
}

/* the elastic energy of the wrapped elements, ½k(l − l0)², less what the
 * chord count gave them (forces.c bd_lumped_elastic_energy); the same
 * elements as the forces phase takes: the first pulley whose sector run
 * holds the element and finds it wrapped */
double bd_lumped_wrap_elastic_correction(const bd_sim *sim)
{
    const bd_lumped *L = bd_lumped_of(sim);
    const double k = bd_lumped_model_of(sim)->k_axial, l0 = sim->model->l0;
    const int n = sim->model->n;
    double de = 0.0;
    for (int pi = 0; pi < sim->model->pulley_count; pi++) {
        const bd_pulley_body *p = &sim->pulleys[pi];
        int first, count;
        bd_lumped_find_sector(sim, p, &L->wraps[pi], &first, &count);
        int e = bd_node_prev(first, n);
        for (int w = 0; w <= count; w++, e = bd_node_next(e, n)) {
            int j = bd_node_next(e, n);
            double len, gi[2], gj[2];
            if (!geodesic(p->cx, p->cy, p->m->radius, p->m->wrap, sim->x[e],
                                    sim->y[e], sim->x[j], sim->y[j], &len, NULL, gi, gj))
                continue;
            /* taken by an earlier pulley? (only where two sectors meet) */
            int taken = 0;
            for (int q = 0; q < pi && !taken; q++) {
                const bd_pulley_body *o = &sim->pulleys[q];
                double l2, g1[2], g2[2];
                taken = (bd_lumped_in_sector(sim, o, e) || bd_lumped_in_sector(sim, o, j))
                     && geodesic(o->cx, o->cy, o->m->radius, o->m->wrap, sim->x[e],
                                           sim->y[e], sim->x[j], sim->y[j], &l2, NULL, g1, g2);
            }
            if (taken)
                continue;
            double chord = hypot(sim->x[j] - sim->x[e], sim->y[j] - sim->y[e]);
            de += 0.5 * k * ((len - l0) * (len - l0) - (chord - l0) * (chord - l0));
        }
    }
    return de;
}
