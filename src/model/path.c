/* Belt path geometry: common tangents between consecutive pulleys and the
 * wrap arcs that join them (model-format.md, "The belt path is ...").
 *
 * Tangent between pulley A (centre a, radius ra, sense wa = ±1) and B: the
 * belt touches a pulley at c + w·r·n, where n = (d_y, -d_x) is the travel
 * direction d turned clockwise (a point moving ccw about c has velocity
 * direction n turned ccw). B's touch point minus A's must be parallel to d:
 *   (b - a)·n + (wb·rb - wa·ra) = 0  →  sin(θ - φ) = -k/L,  k = wb·rb - wa·ra,
 * with (b - a) = L(cos φ, sin φ), d = (cos θ, sin θ), and cos(θ - φ) > 0 so
 * the span runs forward; its length is √(L² - k²). Same senses give the
 * external tangent, opposite senses the crossed one. */
#include "model/path.h"
#include "base/constants.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>


/* angle swept from direction din to dout turning in sense w (±1), in [0, 2π) */
static double turn_angle(const double din[2], const double dout[2], int w)
{
    double a = atan2(dout[1], dout[0]) - atan2(din[1], din[0]);
    a *= (double)w;
    while (a < 0.0)
        a += BD_TWO_PI;
    while (a >= BD_TWO_PI)
        a -= BD_TWO_PI;
    /* a numerically straight-through pulley wraps 0, not 2π */
    if (a > BD_TWO_PI - 1e-12)
        a = 0.0;
    return a;
}

/* the common tangent's direction d and length between two circles whose
 * centres are (dx, dy) apart, k the difference of their signed radii
 * (w_b·r_b − w_a·r_a): θ = atan2(dy, dx) − asin(k/L), length √(L² − k²).
 * The caller has checked L > |k|. */
static void tangent_line(double dx, double dy, double L, double k, double d[2], double *len)
{
    double theta = atan2(dy, dx) - asin(k / L);
    d[0] = cos(theta);
    d[1] = sin(theta);
    *len = sqrt(L * L - k * k);
}

/* a circle (centre c, radius r, sense w) and a point v: the direction of
 * the belt line leaving the circle towards v (to_point) or arriving at it
 * from v, and where it touches the circle (tangent_line
 * with a zero radius at v). 0 = ok, 1 = v lies inside the circle */
static int point_tangent(const double c[2], double r, int w, const double v[2], int to_point,
                         double d[2], double touch[2], double *len)
{
    double dx = v[0] - c[0], dy = v[1] - c[1];
    if (!to_point) {
        dx = -dx;
        dy = -dy;
    }
    double L = hypot(dx, dy), k = to_point ? -w * r : w * r;
    if (L <= fabs(k) * (1.0 + 1e-12))
        return 1;
    tangent_line(dx, dy, L, k, d, len);
    touch[0] = c[0] + w * r * d[1];
    touch[1] = c[1] - w * r * d[0];
    return 0;
}

static int by_from(const void *x, const void *y)
{
    double a = (*(const bd_idler_set_def *const *)x)->curve_from;
    double b = (*(const bd_idler_set_def *const *)y)->curve_from;
    return (a > b) - (a < b);
}

/* the corners of span i: its pulley's route (*route), or those of the
 * idler curves on it, made into *owned: a curve between fractions a < b
 * of the straight span is the fillet at the corner v where the arc's
 * tangents at the span's points A and B meet (plane geometry: the chord
 * c = |AB| subtends 2·asin(c/2R), v lies c/2·tan of half that off the
 * chord); A and B are sharp corners, one corner where two curves touch.
 * Returns their number, 0 for a straight span, −1 on an error (in diag) */
static int span_corners(const bd_model_def *m, int i, const double p0[2], const double d[2],
                        double len, const bd_route_vertex **route, bd_route_vertex **owned,
                        bd_diag *diag)
{
    const bd_pulley_def *a = &m->pulleys[i];
    *route = a->route;
    *owned = NULL;
    if (a->route_count > 0)
        return a->route_count;
    int curves = 0;
    for (int k = 0; k < m->idler_set_count; k++)
        curves += m->idler_sets[k].span == i && m->idler_sets[k].has_curve;
    if (curves == 0)
        return 0;
    const bd_idler_set_def **sets = malloc((size_t)curves * sizeof *sets);
    bd_route_vertex *v = malloc((size_t)(3 * curves) * sizeof *v);
    if (!sets || !v) {
        free(sets), free(v);
        bd_diag_error(diag, m->source, a->mark, "out of memory laying out a vertical curve");
        return -1;
    }
    curves = 0;
    for (int k = 0; k < m->idler_set_count; k++)
        if (m->idler_sets[k].span == i && m->idler_sets[k].has_curve)
            sets[curves++] = &m->idler_sets[k];
    qsort(sets, (size_t)curves, sizeof *sets, by_from);
    /* the lower side of the span: where the idlers stand */
    double down[2];
    bd_path_up_normal(d, down);
    down[0] = -down[0];
    down[1] = -down[1];
    int n = 0, bad = 0;
    for (int q = 0; q < curves; q++) {
        const bd_idler_set_def *st = sets[q];
        double ua = st->curve_from * len, ub = st->curve_to * len, c = ub - ua;
        double R = st->curve_radius;
        if (c >= 2.0 * R) {
            bd_diag_error(diag, m->source, st->curve_mark,
                          "curve: a radius of %.4g m cannot bend the %.4g m between from and to "
                          "(it needs more than %.4g m)", R, c, 0.5 * c);
            bad = 1;
            continue;
        }
        double half = asin(c / (2.0 * R));
        double sag = 0.5 * c * tan(half) * (st->curve_convex ? -1.0 : 1.0);
        double um = 0.5 * (ua + ub);
        if (q == 0 || ua > sets[q - 1]->curve_to * len)
            v[n++] = (bd_route_vertex){p0[0] + ua * d[0], p0[1] + ua * d[1], 0.0, st->curve_mark};
        v[n++] = (bd_route_vertex){p0[0] + um * d[0] + sag * down[0],
                                   p0[1] + um * d[1] + sag * down[1], R, st->curve_mark};
        v[n++] = (bd_route_vertex){p0[0] + ub * d[0], p0[1] + ub * d[1], 0.0, st->curve_mark};
    }
    free(sets);
    if (bad) {
        free(v);
        return -1;
    }
    *route = *owned = v;
    return n;
}

/* a corner's mark for messages: its own, else its span's pulley's */
static bd_mark corner_mark(const bd_route_vertex *v, const bd_pulley_def *a)
{
    return v->mark.line > 0 ? v->mark : a->mark;
}

/* pieces of a routed span from pulley a to pulley b through corners v[k]:
 * the legs, rounded at each corner by its radius (tangent length
 * R·tan(|turn|/2), plane geometry); appended to pieces (capacity 2k+1
 * free). Sets the span's ends and end directions. 0 = ok */
static int route_pieces(const bd_model_def *m, int i, const bd_route_vertex *v, int k,
                        bd_path_piece *out, int *count, double ps[2], double ds[2],
                        double pe[2], double de[2], bd_diag *diag)
{
    const bd_pulley_def *a = &m->pulleys[i];
    const bd_pulley_def *b = &m->pulleys[(i + 1) % m->pulley_count];
    double ca[2] = {a->x, a->y}, cb[2] = {b->x, b->y};
    /* legs 0..k (direction, length), corners 1..k (turn, tangent length;
     * t[0] = t[k+1] = 0 at the pulleys) */
    double (*D)[2] = malloc((size_t)(k + 1) * sizeof *D);
    double *leg = malloc((size_t)(k + 1) * sizeof *leg), *t = malloc((size_t)(k + 2) * sizeof *t);
    double *turn = malloc((size_t)(k + 2) * sizeof *turn);
    int bad = 0;
    if (!D || !leg || !t || !turn) {
        free(D), free(leg), free(t), free(turn);
        bd_diag_error(diag, m->source, a->mark, "out of memory laying out a vertical curve");
        return 1;
    }
    double v0[2] = {v[0].x, v[0].y}, vk[2] = {v[k - 1].x, v[k - 1].y};
    if (point_tangent(ca, a->radius, a->wrap, v0, 1, D[0], ps, &leg[0])
        || point_tangent(cb, b->radius, b->wrap, vk, 0, D[k], pe, &leg[k])) {
        bd_diag_error(diag, m->source, a->mark,
                      "pulleys[%d] '%s': the route of the span to '%s' has a corner inside a "
                      "pulley", i, a->name, b->name);
        bad = 1;
    }
    for (int j = 1; !bad && j < k; j++) {
        double dx = v[j].x - v[j - 1].x, dy = v[j].y - v[j - 1].y, l = hypot(dx, dy);
        if (l <= 0.0) {
            bd_diag_error(diag, m->source, corner_mark(&v[j], a),
                          "pulleys[%d] '%s': two corners of the span's route coincide", i, a->name);
            bad = 1;
            break;
        }
        D[j][0] = dx / l;
        D[j][1] = dy / l;
        leg[j] = l;
    }
    if (bad) {
        free(D), free(leg), free(t), free(turn);
        return 1;
    }
    t[0] = t[k + 1] = 0.0;
    for (int j = 1; j <= k; j++) {
        const double *din = D[j - 1], *dout = D[j];
        turn[j] = atan2(din[0] * dout[1] - din[1] * dout[0], din[0] * dout[0] + din[1] * dout[1]);
        t[j] = v[j - 1].radius * tan(0.5 * fabs(turn[j]));
    }
    /* each leg holds the two tangent lengths at its ends; a curve too big
     * is said once, at its corner */
    int said = 0;   /* the corner (1..k) last said */
    for (int j = 0; j <= k; j++) {
        if (t[j] + t[j + 1] > leg[j] * (1.0 + 1e-9) + 1e-9) {
            int c = t[j + 1] >= t[j] ? j + 1 : j;   /* the corner that takes more */
            if (c == said)
                continue;
            said = c;
            bd_diag_error(diag, m->source, corner_mark(&v[c - 1], a),
                          "pulleys[%d] '%s': a vertical curve of the span to '%s' does not fit "
                          "between its neighbours (it needs %.4g m of a %.4g m straight); "
                          "use a smaller radius", i, a->name, b->name, t[j] + t[j + 1], leg[j]);
            bad = 1;
        }
    }
    int n = 0;
    double at[2] = {ps[0], ps[1]};
    for (int j = 0; j <= k; j++) {
        double l = fmax(0.0, leg[j] - t[j] - t[j + 1]);
        out[n++] = (bd_path_piece){.is_arc = 0, .length = l, .p0 = {at[0], at[1]},
                                   .dir = {D[j][0], D[j][1]}};
        at[0] += l * D[j][0];
        at[1] += l * D[j][1];
        if (j == k || t[j + 1] <= 0.0)
            continue;
        const double *din = D[j];
        double tn = turn[j + 1], sigma = tn >= 0.0 ? 1.0 : -1.0, R = v[j].radius;
        bd_path_piece *arc = &out[n++];
        *arc = (bd_path_piece){.is_arc = 1, .radius = R, .sweep = tn, .length = R * fabs(tn),
                               .p0 = {at[0], at[1]}};
        arc->centre[0] = at[0] - sigma * R * din[1];
        arc->centre[1] = at[1] + sigma * R * din[0];
        arc->angle0 = atan2(at[1] - arc->centre[1], at[0] - arc->centre[0]);
        at[0] = arc->centre[0] + R * cos(arc->angle0 + tn);
        at[1] = arc->centre[1] + R * sin(arc->angle0 + tn);
    }
    ds[0] = D[0][0];
    ds[1] = D[0][1];
    de[0] = D[k][0];
    de[1] = D[k][1];
    *count = n;
    free(D), free(leg), free(t), free(turn);
    return bad;
}

/* the point at distance u along a straight line (p0, unit dir), and the
 * tangent */
static void line_point(const double p0[2], const double dir[2], double u, double p[2],
                       double tangent[2])
{
    p[0] = p0[0] + u * dir[0];
    p[1] = p0[1] + u * dir[1];
    tangent[0] = dir[0];
    tangent[1] = dir[1];
}

/* the point at distance u along a circular arc (centre, radius, polar
 * angle of its start, signed sweep), and the travel direction there: the
 * radial unit vector turned by 90° in the arc's sense */
static void arc_point(const double centre[2], double radius, double angle0, double sweep, double u,
                      double p[2], double tangent[2])
{
    double sense = sweep >= 0.0 ? 1.0 : -1.0;
    double ang = angle0 + sense * u / radius;
    double c = cos(ang), sn = sin(ang);
    p[0] = centre[0] + radius * c;
    p[1] = centre[1] + radius * sn;
    tangent[0] = -sense * sn;
    tangent[1] = sense * c;
}

void bd_path_piece_point(const bd_path_piece *g, double u, double p[2], double tangent[2])
{
    if (g->is_arc)
        arc_point(g->centre, g->radius, g->angle0, g->sweep, u, p, tangent);
    else
        line_point(g->p0, g->dir, u, p, tangent);
}

/* distance along a piece of the point nearest (x, y), not clamped to it */
static double piece_project(const bd_path_piece *g, double x, double y)
{
    if (!g->is_arc)
        return (x - g->p0[0]) * g->dir[0] + (y - g->p0[1]) * g->dir[1];
    return bd_path_arc_position(g->centre, g->radius, g->angle0, g->sweep, x, y);
}

double bd_path_arc_position(const double centre[2], double radius, double angle0, double sweep,
                            double x, double y)
{
    double sense = sweep >= 0.0 ? 1.0 : -1.0;
    double rel = sense * (atan2(y - centre[1], x - centre[0]) - angle0);
    /* put the gap outside the arc half before, half after it */
    double gap = 0.5 * (BD_TWO_PI - fabs(sweep));
    while (rel < -gap)
        rel += BD_TWO_PI;
    while (rel >= BD_TWO_PI - gap)
        rel -= BD_TWO_PI;
    return rel * radius;
}

int bd_path_build(const bd_model_def *m, bd_path *path, bd_diag *diag)
{
    int n = m->pulley_count;
    memset(path, 0, sizeof *path);
    if (n < 2)
        return 1;
    double (*dir)[2] = calloc((size_t)n, sizeof *dir);
    double (*dir1)[2] = calloc((size_t)n, sizeof *dir1);
    double (*ps)[2] = calloc((size_t)n, sizeof *ps);
    double (*pe)[2] = calloc((size_t)n, sizeof *pe);
    double *span_len = calloc((size_t)n, sizeof *span_len);
    int *pfirst = calloc((size_t)n, sizeof *pfirst), *pcount = calloc((size_t)n, sizeof *pcount);
    path->segments = calloc((size_t)(2 * n), sizeof *path->segments);
    int bad = !dir || !dir1 || !ps || !pe || !span_len || !pfirst || !pcount || !path->segments;

    /* no two pulleys may overlap, neighbours or not */
    for (int i = 0; !bad && i < n; i++)
        for (int j = i + 1; j < n; j++) {
            const bd_pulley_def *a = &m->pulleys[i], *b = &m->pulleys[j];
            double gap = hypot(b->x - a->x, b->y - a->y) - a->radius - b->radius;
            if (gap < 0.0) {
                bd_diag_error(diag, m->source, b->mark,
                              "pulleys[%d] '%s': overlaps pulley '%s' (their shells "
                              "intersect by %.4g m)", j, b->name, a->name, -gap);
                bad = 1;
            }
        }

    /* spans: common tangent from pulley i to pulley i+1, then through the
     * corners of its route when it has one */
    for (int i = 0; !bad && i < n; i++) {
        const bd_pulley_def *a = &m->pulleys[i];
        const bd_pulley_def *b = &m->pulleys[(i + 1) % n];
        double dx = b->x - a->x, dy = b->y - a->y;
        double L = hypot(dx, dy);
        double k = b->wrap * b->radius - a->wrap * a->radius;
        if (L <= fabs(k) + 1e-9 * (a->radius + b->radius)) {
            bd_diag_error(diag, m->source, b->mark,
                          "pulleys[%d] '%s': overlaps pulley '%s' (centres %.4g m apart); "
                          "no belt span can run between them",
                          (i + 1) % n, b->name, a->name, L);
            bad = 1;
            continue;
        }
        tangent_line(dx, dy, L, k, dir[i], &span_len[i]);
        dir1[i][0] = dir[i][0];
        dir1[i][1] = dir[i][1];
        double na[2] = {dir[i][1], -dir[i][0]};
        ps[i][0] = a->x + a->wrap * a->radius * na[0];
        ps[i][1] = a->y + a->wrap * a->radius * na[1];
        pe[i][0] = ps[i][0] + span_len[i] * dir[i][0];
        pe[i][1] = ps[i][1] + span_len[i] * dir[i][1];
        const bd_route_vertex *v;
        bd_route_vertex *owned;
        int nv = span_corners(m, i, ps[i], dir[i], span_len[i], &v, &owned, diag);
        if (nv <= 0) {
            bad |= nv < 0;
            continue;
        }
        bd_path_piece *grown =
            realloc(path->pieces, (size_t)(path->piece_count + 2 * nv + 1) * sizeof *grown);
        if (!grown) {
            free(owned);
            bad = 1;
            continue;
        }
        path->pieces = grown;
        int made = 0;
        bad |= route_pieces(m, i, v, nv, path->pieces + path->piece_count, &made, ps[i], dir[i],
                            pe[i], dir1[i], diag);
        free(owned);
        pfirst[i] = path->piece_count;
        pcount[i] = made;
        path->piece_count += made;
        span_len[i] = 0.0;
        for (int q = 0; q < made; q++)
            span_len[i] += path->pieces[pfirst[i] + q].length;
    }
    if (bad) {
        free(dir), free(dir1), free(ps), free(pe), free(span_len), free(pfirst), free(pcount);
        bd_path_free(path);
        return 1;
    }

    path->pulley_count = n;
    path->segment_count = 2 * n;
    double s = 0.0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        const bd_pulley_def *b = &m->pulleys[j];

        bd_path_segment *sp = &path->segments[2 * i];
        sp->kind = BD_SEGMENT_SPAN;
        sp->pulley = i;
        sp->s0 = s;
        sp->length = span_len[i];
        memcpy(sp->dir, dir[i], sizeof sp->dir);
        memcpy(sp->dir1, dir1[i], sizeof sp->dir1);
        memcpy(sp->p0, ps[i], sizeof sp->p0);
        memcpy(sp->p1, pe[i], sizeof sp->p1);
        sp->piece_first = pfirst[i];
        sp->piece_count = pcount[i];
        for (int q = 0; q < pcount[i]; q++) {
            path->pieces[pfirst[i] + q].s0 = s;
            s += path->pieces[pfirst[i] + q].length;
        }
        s = sp->s0 + sp->length;

        /* arc of pulley j: from the end of span i to the start of span j */
        bd_path_segment *arc = &path->segments[2 * i + 1];
        double wrap = turn_angle(dir1[i], dir[j], b->wrap);
        arc->kind = BD_SEGMENT_ARC;
        arc->pulley = j;
        arc->s0 = s;
        arc->radius = b->radius;
        arc->length = b->radius * wrap;
        arc->centre[0] = b->x;
        arc->centre[1] = b->y;
        arc->p0[0] = sp->p1[0];
        arc->p0[1] = sp->p1[1];
        arc->angle0 = atan2(arc->p0[1] - b->y, arc->p0[0] - b->x);
        arc->sweep = b->wrap * wrap;
        arc->p1[0] = b->x + b->radius * cos(arc->angle0 + arc->sweep);
        arc->p1[1] = b->y + b->radius * sin(arc->angle0 + arc->sweep);
        arc->dir[0] = dir[j][0];
        arc->dir[1] = dir[j][1];
        s += arc->length;
    }
    path->length = s;
    free(dir), free(dir1), free(ps), free(pe), free(span_len), free(pfirst), free(pcount);

    /* no span may run through a pulley it does not leave or reach: the
     * common tangents above do not look at the others (a snub placed
     * across the carry strand laid the belt through it, and the discrete
     * belt's static layout diverged at its first step). Measured on the
     * straight pieces; a vertical curve is hundreds of metres round */
    for (int i = 0; i < n; i++) {
        const bd_path_segment *sp = &path->segments[2 * i];
        int j = (i + 1) % n;
        int pieces = sp->piece_count > 0 ? sp->piece_count : 1;
        for (int q = 0; q < pieces; q++) {
            const double *p0 = sp->p0, *d = sp->dir;
            double len = sp->length;
            if (sp->piece_count > 0) {
                const bd_path_piece *g = &path->pieces[sp->piece_first + q];
                if (g->is_arc)
                    continue;
                p0 = g->p0, d = g->dir, len = g->length;
            }
            for (int k = 0; k < n; k++) {
                if (k == i || k == j)
                    continue;
                const bd_pulley_def *c = &m->pulleys[k];
                double t = (c->x - p0[0]) * d[0] + (c->y - p0[1]) * d[1];
                t = t < 0.0 ? 0.0 : (t > len ? len : t);
                double dd = hypot(p0[0] + t * d[0] - c->x, p0[1] + t * d[1] - c->y);
                if (dd < c->radius * (1.0 - 1e-9)) {
                    bd_diag_error(diag, m->source, c->mark,
                                  "pulleys[%d] '%s': the belt span from '%s' to '%s' runs "
                                  "through it (%.4g m from its centre, radius %.4g m); move the "
                                  "pulley or change a wrap direction", k, c->name,
                                  m->pulleys[i].name, m->pulleys[j].name, dd, c->radius);
                    bad = 1;
                }
            }
        }
    }
    if (bad) {
        bd_path_free(path);
        return 1;
    }
    return 0;
}

void bd_path_free(bd_path *path)
{
    free(path->segments);
    free(path->pieces);
    memset(path, 0, sizeof *path);
}

/* the last of items lo..hi (in s0 order) that starts at or before s: a
 * binary search on the double `s0` at offset `at` of items `stride`
 * bytes apart (segments and route pieces alike) */
static int last_starting_by(const void *items, size_t stride, size_t at, int lo, int hi, double s)
{
    const char *base = (const char *)items + at;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        double s0;
        memcpy(&s0, base + (size_t)mid * stride, sizeof s0);
        if (s0 <= s)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

int bd_path_segment_at(const bd_path *path, double s)
{
    s = fmod(s, path->length);
    if (s < 0.0)
        s += path->length;
    return last_starting_by(path->segments, sizeof *path->segments,
                            offsetof(bd_path_segment, s0), 0, path->segment_count - 1, s);
}

/* the piece of routed span g holding s */
static const bd_path_piece *span_piece_at(const bd_path *path, const bd_path_segment *g, double s)
{
    return &path->pieces[last_starting_by(path->pieces, sizeof *path->pieces,
                                          offsetof(bd_path_piece, s0), g->piece_first,
                                          g->piece_first + g->piece_count - 1, s)];
}

void bd_path_point(const bd_path *path, double s, double p[2], double tangent[2])
{
    s = fmod(s, path->length);
    if (s < 0.0)
        s += path->length;
    const bd_path_segment *g = &path->segments[bd_path_segment_at(path, s)];
    double u = s - g->s0;
    if (g->kind == BD_SEGMENT_SPAN && g->piece_count > 0) {
        const bd_path_piece *q = span_piece_at(path, g, s);
        bd_path_piece_point(q, s - q->s0, p, tangent);
        return;
    }
    if (g->kind == BD_SEGMENT_SPAN)
        line_point(g->p0, g->dir, u, p, tangent);
    else
        arc_point(g->centre, g->radius, g->angle0, g->sweep, u, p, tangent);
}

double bd_path_span_project(const bd_path *path, const bd_path_segment *g, double x, double y)
{
    if (g->piece_count == 0)
        return (x - g->p0[0]) * g->dir[0] + (y - g->p0[1]) * g->dir[1];
    double best = INFINITY, u_best = 0.0;
    for (int q = 0; q < g->piece_count; q++) {
        const bd_path_piece *pc = &path->pieces[g->piece_first + q];
        double u = piece_project(pc, x, y), uc = fmin(fmax(u, 0.0), pc->length);
        /* before the first piece and beyond the last, unclamped */
        if ((q == 0 && u < 0.0) || (q == g->piece_count - 1 && u > pc->length))
            uc = u;
        double p[2], t[2];
        bd_path_piece_point(pc, fmin(fmax(uc, 0.0), pc->length), p, t);
        double off = uc - fmin(fmax(uc, 0.0), pc->length);
        double d = hypot(p[0] + off * t[0] - x, p[1] + off * t[1] - y);
        if (d < best) {
            best = d;
            u_best = pc->s0 - g->s0 + uc;
        }
    }
    return u_best;
}

void bd_path_wrap_dirs(const bd_path *path, int pulley, const double **u_in,
                       const double **u_out)
{
    int n = path->pulley_count;
    *u_in = bd_path_span(path, (pulley + n - 1) % n)->dir1;
    *u_out = bd_path_span(path, pulley)->dir;
}

const bd_path_segment *bd_path_span(const bd_path *path, int pulley)
{
    return &path->segments[2 * pulley];
}

const bd_path_segment *bd_path_arc(const bd_path *path, int pulley)
{
    int n = path->pulley_count;
    return &path->segments[2 * ((pulley + n - 1) % n) + 1];
}

double bd_path_span_s(const bd_path *path, int pulley, double at)
{
    const bd_path_segment *g = bd_path_span(path, pulley);
    return g->s0 + at * g->length;
}

double bd_path_wrap_angle(const bd_path *path, int pulley)
{
    return fabs(bd_path_arc(path, pulley)->sweep);
}

void bd_path_loaded_region(const bd_path *path, const bd_material_def *mat, double *s_feed,
                           double *length)
{
    double L = path->length;
    double s_dis = bd_path_arc(path, mat->discharge)->s0;
    *s_feed = bd_path_span_s(path, mat->feed_span, mat->feed_at);
    *length = fmod(s_dis - *s_feed + 2.0 * L, L);
}

int bd_path_in_region(const bd_path *path, double s, double s_from, double length)
{
    double L = path->length;
    return fmod(s - s_from + 2.0 * L, L) <= length;
}

double bd_path_region_overlap(const bd_path *path, double x0, double w, double s_from,
                              double length)
{
    /* the interval measured from the region's start, and once more a loop
     * further on for a region that wraps past s = 0 */
    const double L = path->length;
    double u = fmod(x0 - s_from + 2.0 * L, L), part = 0.0;
    for (double start = 0.0; start <= L; start += L) {
        double lo = fmax(u, start), hi = fmin(u + w, start + length);
        if (hi > lo)
            part += hi - lo;
    }
    return part;
}
