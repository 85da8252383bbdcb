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

int bd_path_build(const bd_model_def *m, bd_path *path, bd_diag *diag)
{
    int n = m->pulley_count;
    memset(path, 0, sizeof *path);
    if (n < 2)
        return 1;
    double (*dir)[2] = calloc((size_t)n, sizeof *dir);
    double *span_len = calloc((size_t)n, sizeof *span_len);
    path->segments = calloc((size_t)(2 * n), sizeof *path->segments);
    if (!dir || !span_len || !path->segments) {
        free(dir);
        free(span_len);
        bd_path_free(path);
        return 1;
    }
    int bad = 0;

    /* no two pulleys may overlap, neighbours or not */
    for (int i = 0; i < n; i++)
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
    if (bad) {
        free(dir);
        free(span_len);
        bd_path_free(path);
        return 1;
    }

    /* spans: common tangent from pulley i to pulley i+1 */
    for (int i = 0; i < n; i++) {
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
        double phi = atan2(dy, dx);
        double theta = phi - asin(k / L);
        dir[i][0] = cos(theta);
        dir[i][1] = sin(theta);
        span_len[i] = sqrt(L * L - k * k);
    }
    if (bad) {
        free(dir);
        free(span_len);
        bd_path_free(path);
        return 1;
    }

    path->pulley_count = n;
    path->segment_count = 2 * n;
    double s = 0.0;
    for (int i = 0; i < n; i++) {
        const bd_pulley_def *a = &m->pulleys[i];
        int j = (i + 1) % n;
        const bd_pulley_def *b = &m->pulleys[j];
        double na[2] = {dir[i][1], -dir[i][0]};

        bd_path_segment *sp = &path->segments[2 * i];
        sp->kind = BD_SEGMENT_SPAN;
        sp->pulley = i;
        sp->s0 = s;
        sp->length = span_len[i];
        sp->dir[0] = dir[i][0];
        sp->dir[1] = dir[i][1];
        sp->p0[0] = a->x + a->wrap * a->radius * na[0];
        sp->p0[1] = a->y + a->wrap * a->radius * na[1];
        sp->p1[0] = sp->p0[0] + span_len[i] * dir[i][0];
        sp->p1[1] = sp->p0[1] + span_len[i] * dir[i][1];
        s += sp->length;

        /* arc of pulley j: from the end of span i to the start of span j */
        bd_path_segment *arc = &path->segments[2 * i + 1];
        double wrap = turn_angle(dir[i], dir[j], b->wrap);
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
    free(dir);
    free(span_len);

    /* no span may run through a pulley it does not leave or reach: the
     * common tangents above do not look at the others (a snub placed
     * across the carry strand laid the belt through it, and the discrete
     * belt's static layout diverged at its first step) */
    for (int i = 0; i < n; i++) {
        const bd_path_segment *sp = &path->segments[2 * i];
        int j = (i + 1) % n;
        for (int k = 0; k < n; k++) {
            if (k == i || k == j)
                continue;
            const bd_pulley_def *c = &m->pulleys[k];
            double t = (c->x - sp->p0[0]) * sp->dir[0] + (c->y - sp->p0[1]) * sp->dir[1];
            t = t < 0.0 ? 0.0 : (t > sp->length ? sp->length : t);
            double d = hypot(sp->p0[0] + t * sp->dir[0] - c->x, sp->p0[1] + t * sp->dir[1] - c->y);
            if (d < c->radius * (1.0 - 1e-9)) {
                bd_diag_error(diag, m->source, c->mark,
                              "pulleys[%d] '%s': the belt span from '%s' to '%s' runs through "
                              "it (%.4g m from its centre, radius %.4g m); move the pulley or "
                              "change a wrap direction", k, c->name, m->pulleys[i].name,
                              m->pulleys[j].name, d, c->radius);
                bad = 1;
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
    memset(path, 0, sizeof *path);
}

int bd_path_segment_at(const bd_path *path, double s)
{
    s = fmod(s, path->length);
    if (s < 0.0)
        s += path->length;
    /* binary search on s0 */
    int lo = 0, hi = path->segment_count - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (path->segments[mid].s0 <= s)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

void bd_path_point(const bd_path *path, double s, double p[2], double tangent[2])
{
    s = fmod(s, path->length);
    if (s < 0.0)
        s += path->length;
    const bd_path_segment *g = &path->segments[bd_path_segment_at(path, s)];
    double u = s - g->s0;
    if (g->kind == BD_SEGMENT_SPAN) {
        p[0] = g->p0[0] + u * g->dir[0];
        p[1] = g->p0[1] + u * g->dir[1];
        tangent[0] = g->dir[0];
        tangent[1] = g->dir[1];
        return;
    }
    double sense = g->sweep >= 0.0 ? 1.0 : -1.0;
    double ang = g->angle0 + sense * u / g->radius;
    double c = cos(ang), sn = sin(ang);
    p[0] = g->centre[0] + g->radius * c;
    p[1] = g->centre[1] + g->radius * sn;
    /* travel direction: radial unit vector turned by 90° in the wrap sense */
    tangent[0] = -sense * sn;
    tangent[1] = sense * c;
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
