/* The layout of a conveyor given by its route (profile.h).
 *
 * Travel runs tail → head on the carry strand (chainage increasing, +x),
 * so the belt turns clockwise round the tail and the head. Each end pulley
 * touches the carry line at its end point: centre = P − R·up(d), up(d) the
 * leg's direction turned 90° counter-clockwise. The inner points are the
 * corners of the carry span's route, rounded by their curves' radii. The
 * return strand runs return_drop below the carry strand at the inner
 * points (the same corners moved down, the same radii: a vertical shift
 * keeps an arc's radius) and meets the pulleys along tangents.
 *
 * A head loop (takeup at: head): the belt leaves the head's underside
 * travelling −x, passes over bend1 (its top level with the head's bottom,
 * 0.5 m of clear space between their shells), drops to the takeup pulley
 * hanging `depth` below the bends, rises to bend2 and leaves over its top
 * as the return strand. A tail takeup: the tail pulley itself, pulled
 * horizontally away from the head. */
#include "model/profile.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define LOOP_GAP 0.5   /* m of clear space between the head and bend1 */

static bd_pulley_def loop_pulley(const char *name, double x, double y, double r, int wrap,
                                 bd_mark mark)
{
    bd_pulley_def p = bd_pulley_default();
    snprintf(p.name, sizeof p.name, "%s", name);
    p.x = x;
    p.y = y;
    p.radius = r;
    p.wrap = wrap;
    p.mark = mark;
    return p;
}

void bd_profile_free_tables(bd_profile_def *p)
{
    bd_table_free(&p->head.drive.torque);
    bd_table_free(&p->tail.drive.torque);
    bd_table_free(&p->takeup.t.force);
}

static int route(const bd_profile_def *p, double drop, int reverse, bd_route_vertex **out)
{
    int k = p->point_count - 2;
    *out = NULL;
    if (k <= 0)
        return 0;
    bd_route_vertex *v = calloc((size_t)k, sizeof *v);
    if (!v)
        return -1;
    for (int j = 0; j < k; j++) {
        int i = reverse ? k - j : j + 1;
        v[j].x = p->points[i][0];
        v[j].y = p->points[i][1] - drop;
        v[j].mark = p->point_marks[i];
        for (int c = 0; c < p->curve_count; c++)
            if ((int)p->curves[c].at == i) {
                v[j].radius = p->curves[c].radius;
                v[j].mark = p->curves[c].mark;
            }
    }
    *out = v;
    return k;
}

int bd_profile_layout(bd_profile_def *p, bd_model_def *m, bd_diag *diag)
{
    int n = p->point_count, loop = p->takeup.at_head;
    const double (*P)[2] = (const double (*)[2])p->points;
    double d0[2], d1[2];
    double l0 = hypot(P[1][0] - P[0][0], P[1][1] - P[0][1]);
    double l1 = hypot(P[n - 1][0] - P[n - 2][0], P[n - 1][1] - P[n - 2][1]);
    d0[0] = (P[1][0] - P[0][0]) / l0;
    d0[1] = (P[1][1] - P[0][1]) / l0;
    d1[0] = (P[n - 1][0] - P[n - 2][0]) / l1;
    d1[1] = (P[n - 1][1] - P[n - 2][1]) / l1;

    int np = loop ? 5 : 2;
    bd_pulley_def *pl = calloc((size_t)np, sizeof *pl);
    if (!pl) {
        bd_profile_free_tables(p);
        return 1;
    }
    pl[0] = p->tail;
    snprintf(pl[0].name, sizeof pl[0].name, "tail");
    pl[0].wrap = -1;
    pl[0].x = P[0][0] + p->tail.radius * d0[1];
    pl[0].y = P[0][1] - p->tail.radius * d0[0];
    pl[1] = p->head;
    snprintf(pl[1].name, sizeof pl[1].name, "head");
    pl[1].wrap = -1;
    pl[1].x = P[n - 1][0] + p->head.radius * d1[1];
    pl[1].y = P[n - 1][1] - p->head.radius * d1[0];

    bd_takeup_def tu = p->takeup.t;
    int bad = 0;
    if (loop) {
        double rb = p->bend_radius > 0.0 ? p->bend_radius : p->tail.radius, Rh = p->head.radius;
        /* room above the takeup pulley for its upward travel */
        double up = isfinite(tu.travel_min) ? -tu.travel_min : 0.0;
        double depth = p->takeup.depth > 0.0 ? p->takeup.depth : fmax(4.0, 2.0 * rb + 1.0 + up);
        if (depth - 2.0 * rb < up) {
            bd_diag_error(diag, m->source, p->takeup.t.mark,
                          "profile.takeup: depth %.4g m leaves %.4g m between the takeup "
                          "pulley and the bends, less than its upward travel %.4g m",
                          depth, depth - 2.0 * rb, up);
            bad = 1;
        }
        double yb = pl[1].y - Rh - rb;
        double xb1 = pl[1].x - (Rh + rb + LOOP_GAP);
        double xt = xb1 - 2.0 * rb, xb2 = xt - 2.0 * rb;
        pl[2] = loop_pulley("bend1", xb1, yb, rb, 1, p->takeup.t.mark);
        pl[3] = loop_pulley("takeup", xt, yb - depth, rb, -1, p->takeup.t.mark);
        pl[4] = loop_pulley("bend2", xb2, yb, rb, 1, p->takeup.t.mark);
        tu.axis[0] = 0.0;
        tu.axis[1] = -1.0;
        pl[3].has_takeup = 1;
        pl[3].takeup = tu;
        /* the return strand leaves bend2 towards the inner points */
        for (int i = 1; i < n - 1; i++)
            if (P[i][0] >= xb2 - rb) {
                bd_diag_error(diag, m->source, p->mark,
                              "profile.points[%d]: at chainage %.4g m it lies over the takeup "
                              "loop, which reaches back to %.4g m; the loop needs the last "
                              "%.4g m before the head straight", i, P[i][0], xb2 - rb,
                              P[n - 1][0] - (xb2 - rb));
                bad = 1;
            }
    } else {
        tu.axis[0] = -1.0;
        tu.axis[1] = 0.0;
        pl[0].has_takeup = 1;
        pl[0].takeup = tu;
    }
    for (int i = 1; i < n - 1; i++)
        if (P[i][0] <= pl[0].x) {
            bd_diag_error(diag, m->source, p->mark,
                          "profile.points[%d]: at chainage %.4g m it lies over the tail "
                          "pulley (centre at %.4g m)", i, P[i][0], pl[0].x);
            bad = 1;
        }
    if (bad) {
        free(pl);
        bd_profile_free_tables(p);
        return 1;
    }
    m->pulleys = pl;
    m->pulley_count = np;
    if (route(p, 0.0, 0, &pl[0].route) < 0 || route(p, p->return_drop, 1, &pl[np - 1].route) < 0)
        return 1;
    pl[0].route_count = n - 2;
    pl[np - 1].route_count = n - 2;

    m->idler_sets = calloc(2, sizeof *m->idler_sets);
    if (!m->idler_sets)
        return 1;
    m->idler_set_count = 2;
    m->idler_sets[0] = p->carry;
    m->idler_sets[0].span = 0;
    m->idler_sets[1] = p->ret;
    m->idler_sets[1].span = np - 1;
    m->from_profile = 1;
    return 0;
}

void bd_profile_free(bd_profile_def *p)
{
    free(p->points);
    free(p->point_marks);
    free(p->curves);
    memset(p, 0, sizeof *p);
}
