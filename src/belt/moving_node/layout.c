/* The moving-node belt's nodes on the path (model-format.md
 * `wrap_element_angle_deg`, `span_element_length`).
 *
 * The loop starts where the belt leaves pulley 0 (s = 0). Each span gets a
 * node at every idler station, the feed point and every probe; between two
 * of these, equal elements of at most the span's target length. Each wrap
 * arc gets equal elements of at most wrap_element_angle, its two tangent
 * points included. The nodes are fixed in space (seed 003 §4: they stand
 * where the physics is), so this is done once. */
#include "belt/moving_node/moving_node.h"

#include <math.h>
#include <stdlib.h>

#include "base/alloc.h"

/* hard points on a span closer than this fraction of its target length
 * merge into one (an idler wins): no sliver elements */
#define MERGE_FRACTION 0.3

/* a hard point on a span: relative position, and the idler set standing
 * there (−1: a feed point or probe) */
typedef struct hard_point {
    double rel;
    int set;
} hard_point;

double bd_mn_span_target(const bd_model_def *def, const bd_path *path, int span)
{
    if (def->belt.span_element_length > 0.0)
        return def->belt.span_element_length;
    for (int k = 0; k < def->idler_set_count; k++) {
        double a;
        if (def->idler_sets[k].span != span || bd_span_vertical(path, span))
            continue;
        /* the spacing the idlers get; the given one on a span too short
         * for any */
        return bd_idler_count(def, path, k, &a) > 0 ? a : def->idler_sets[k].spacing;
    }
    return 1.0;
}

static int cmp_hard(const void *a, const void *b)
{
    double x = ((const hard_point *)a)->rel, y = ((const hard_point *)b)->rel;
    return (x > y) - (x < y);
}

/* the hard points of span j, sorted and merged, ends excluded, in a new
 * array *hp_out */
static int span_points(const bd_model_def *def, const bd_path *path, int j, hard_point **hp_out)
{
    const bd_path_segment *sp = bd_path_span(path, j);
    double len = sp->length, target = bd_mn_span_target(def, path, j);
    int cap = 2 + def->simulation.probe_count;
    for (int k = 0; k < def->idler_set_count; k++)
        if (def->idler_sets[k].span == j)
            cap += (int)lround(len / def->idler_sets[k].spacing) + 1;
    hard_point *hp = bd_xcalloc((size_t)cap, sizeof *hp);
    int m = 0;
    for (int k = 0; k < def->idler_set_count; k++) {
        double a;
        if (def->idler_sets[k].span != j)
            continue;
        int count = bd_idler_count(def, path, k, &a);
        for (int c = 0; c < count; c++)
            hp[m++] = (hard_point){(c + 1) * len / (count + 1), k};
    }
    if (def->material.present && def->material.feed_span == j)
        hp[m++] = (hard_point){def->material.feed_at * len, -1};
    for (int i = 0; i < def->simulation.probe_count; i++)
        if (def->simulation.probes[i].span == j)
            hp[m++] = (hard_point){def->simulation.probes[i].at * len, -1};
    qsort(hp, (size_t)m, sizeof *hp, cmp_hard);
    /* merge: drop points at the ends and points close to the one kept
     * before them, an idler replacing a feed point or probe */
    double gap = MERGE_FRACTION * fmin(target, len);
    int kept = 0;
    double last = 0.0;
    for (int i = 0; i < m; i++) {
        if (hp[i].rel < gap || hp[i].rel > len - gap)
            continue;
        if (kept > 0 && hp[i].rel - last < gap) {
            if (hp[i].set >= 0 && hp[kept - 1].set < 0)
                hp[kept - 1] = hp[i];
            continue;
        }
        hp[kept++] = hp[i];
        last = hp[i].rel;
    }
    *hp_out = hp;
    return kept;
}

/* elements over a piece of span of length d */
static double piece_elements(double d, double target)
{
    double k = ceil(d / target - 1e-9);
    return k < 1.0 ? 1.0 : k;
}

/* elements on the arc of pulley p. Counted in doubles: a tiny
 * wrap_element_angle_deg (the loader takes any above 0) made 1.8e11 per
 * arc, past any int, and `check` then said 8 nodes; the estimate
 * (sim/estimate.c) refuses such a count before the build asks for it */
static double arc_elements(const bd_model_def *def, const bd_path *path, int p)
{
    double wrap = bd_path_wrap_angle(path, p);
    if (wrap < 1e-9)
        return 0.0;
    double k = ceil(wrap / def->belt.wrap_element_angle - 1e-9);
    return k < 1.0 ? 1.0 : k;
}

/* walk the loop: spans with their hard points, then the arcs; each node
 * reported to `put` (NULL: count only); the wraps' nodes into *arcs (may
 * be NULL) */
typedef void (*put_fn)(bd_sim *sim, int i, double s, int kind, int pulley, int set);

static double walk(const bd_model_def *def, const bd_path *path, bd_sim *sim, put_fn put,
                   double *arcs)
{
    const int np = path->pulley_count;
    double n = 0.0, on_arcs = 0.0;
    for (int j = 0; j < np; j++) {
        const bd_path_segment *sp = bd_path_span(path, j);
        double target = bd_mn_span_target(def, path, j);
        hard_point *hp;
        int m = span_points(def, path, j, &hp);
        /* the span's first node is pulley j's tangent-out point */
        if (put)
            put(sim, (int)n, sp->s0, BD_MN_ARC, j, -1);
        n++;
        double from = 0.0;
        for (int h = 0; h <= m; h++) {
            double to = h < m ? hp[h].rel : sp->length;
            double k = piece_elements(to - from, target);
            if (put)
                for (int c = 1; c < (int)k; c++)
                    put(sim, (int)n + c - 1, sp->s0 + from + c * (to - from) / k, BD_MN_FREE,
                        -1, -1);
            n += k - 1.0;
            if (h < m) {
                if (put)
                    put(sim, (int)n, sp->s0 + to,
                        hp[h].set >= 0 ? BD_MN_IDLER : BD_MN_FREE, -1, hp[h].set);
                n++;
            }
            from = to;
        }
        free(hp);
        /* the arc of the next pulley, its tangent-in point first, the
         * tangent-out being the next span's first node */
        int p = (j + 1) % np;
        const bd_path_segment *arc = bd_path_arc(path, p);
        double k = arc_elements(def, path, p);
        if (put)
            for (int c = 0; c < (int)k; c++)
                put(sim, (int)n + c, arc->s0 + c * arc->length / k, BD_MN_ARC, p, -1);
        n += k;
        on_arcs += k;
    }
    if (arcs)
        *arcs = on_arcs;
    return n;
}

double bd_mn_layout_count(const bd_model_def *def, const bd_path *path, double *arc_nodes)
{
    return walk(def, path, NULL, NULL, arc_nodes);
}

/* the node's place and what stands there (the arrays are allocated) */
static void put_node(bd_sim *sim, int i, double s, int kind, int pulley, int set)
{
    bd_mn_model *mm = bd_mn_model_build(sim);
    const bd_path *path = &sim->model->path;
    double L = path->length;
    s = fmod(s, L);
    if (s < 0.0)
        s += L;
    sim->own->s_node0[i] = s;
    mm->kind[i] = (unsigned char)kind;
    mm->pulley[i] = pulley;
    mm->mover[i] = -1;
    double p[2], t[2];
    bd_path_point(path, s, p, t);
    mm->x0[i] = p[0];
    mm->y0[i] = p[1];
    if (kind == BD_MN_ARC) {
        const bd_path_segment *arc = bd_path_arc(path, pulley);
        double dx = arc->centre[0] - p[0], dy = arc->centre[1] - p[1], r = hypot(dx, dy);
        mm->nx[i] = r > 0.0 ? dx / r : 0.0;
        mm->ny[i] = r > 0.0 ? dy / r : 0.0;
    } else {
        /* the span's normal, pointing up (idlers stand below the belt) */
        double up[2];
        bd_path_up_normal(t, up);
        mm->nx[i] = up[0];
        mm->ny[i] = up[1];
    }
    if (kind == BD_MN_IDLER) {
        const bd_idler_set_def *st = &sim->model->def->idler_sets[set];
        double inertia = st->inertia > 0.0 ? st->inertia : 1e-6;
        mm->rolling[i] = st->rolling_resistance;
        mm->idler_mass[i] = inertia / (st->radius * st->radius);
    }
}

/* the element e's geometry: its length along the path, on an arc or not */
static void element_geometry(bd_sim *sim)
{
    bd_mn_model *mm = bd_mn_model_build(sim);
    const int n = sim->model->n;
    const bd_path *path = &sim->model->path;
    double L = path->length;
    for (int e = 0; e < n; e++) {
        int j = bd_node_next(e, n);
        double ds = sim->model->s_node0[j] - sim->model->s_node0[e];
        if (ds <= 0.0)
            ds += L;
        mm->ds0[e] = ds;
        mm->eq[e] = -1;
        /* on an arc when both ends are arc nodes of one pulley (a span
         * joins the arc nodes of two different pulleys) */
        int on = mm->kind[e] == BD_MN_ARC && mm->kind[j] == BD_MN_ARC
              && mm->pulley[e] == mm->pulley[j];
        mm->on_arc[e] = (unsigned char)on;
        mm->radius[e] = on ? bd_path_arc(path, mm->pulley[e])->radius : 0.0;
        /* a vertical curve: the path turns between the nodes; half the
         * turn at each end, signed towards the normal (up) */
        mm->kw[e] = 0.0;
        if (!on && path->segments[bd_path_segment_at(path, sim->model->s_node0[e])].piece_count > 0) {
            double p[2], ta[2], tz[2], up[2];
            bd_path_point(path, sim->model->s_node0[e], p, ta);
            bd_path_point(path, sim->model->s_node0[j], p, tz);
            double turn = atan2(ta[0] * tz[1] - ta[1] * tz[0], ta[0] * tz[0] + ta[1] * tz[1]);
            /* the span's up normal (an arc node's own points at its pulley)
             * is the travel direction's left or right */
            bd_path_up_normal(ta, up);
            mm->kw[e] = 0.5 * turn * (-ta[1] * up[0] + ta[0] * up[1] >= 0.0 ? 1.0 : -1.0);
        }
    }
}

/* the nodes' places and kinds, the elements' geometry and each pulley's
 * arc nodes (the arrays of [n] are allocated, n from bd_mn_layout_count) */
void bd_mn_layout_fill(bd_sim *sim)
{
    walk(sim->model->def, &sim->model->path, sim, put_node, NULL);
    element_geometry(sim);
    /* the arc length each arc node stands for, and each pulley's arc nodes */
    bd_mn_model *mm = bd_mn_model_build(sim);
    const int n = sim->model->n;
    for (int p = 0; p < sim->model->pulley_count; p++)
        mm->pulleys[p].count = 0;
    for (int i = 0; i < n; i++) {
        if (mm->kind[i] != BD_MN_ARC)
            continue;
        int b = bd_node_prev(i, n);
        double half = 0.0;
        if (mm->on_arc[b]) {
            half += 0.5 * mm->ds0[b];
        }
        if (mm->on_arc[i]) {
            half += 0.5 * mm->ds0[i];
        }
        mm->arc_len[i] = half;
    }
    /* a pulley's arc nodes run from its tangent-in point to its
     * tangent-out point, which is node 0 for pulley 0 */
    for (int i = 0; i < n; i++) {
        if (mm->kind[i] != BD_MN_ARC)
            continue;
        bd_mn_pulley *pp = &mm->pulleys[mm->pulley[i]];
        int b = bd_node_prev(i, n);
        if (!(mm->kind[b] == BD_MN_ARC && mm->pulley[b] == mm->pulley[i]))
            pp->first = i;
        pp->count++;
    }
}
