/* Where the boom's nodes stand: the rigid boom, the nodes' material
 * coordinates, interpolation along a section, and the remap that moves the
 * spatial nodes through the material (seed 003 §3-§5).
 *
 * Interpolation on an element of material length l0 between nodes a and b
 * is cubic Hermite in the parameter xi (seed 003 eq. 6 with the slopes of
 * the nodes' cross-sections, Euler-Bernoulli: the tangent is the section's
 * normal): r(xi) = h00 r_a + h10 l0 r'_a + h01 r_b + h11 l0 r'_b, with
 * r' = lambda (cos phi, sin phi) and lambda the element's stretch. The
 * material velocity uses the same functions with v' = w x r'. The angle
 * and the angular velocity are linear in xi. */
#include "boom/boom_internal.h"

#include <math.h>
#include <string.h>

static void hermite(double xi, double *h00, double *h10, double *h01, double *h11)
{
    double x2 = xi * xi, x3 = x2 * xi;
    *h00 = 2.0 * x3 - 3.0 * x2 + 1.0;
    *h10 = x3 - 2.0 * x2 + xi;
    *h01 = -2.0 * x3 + 3.0 * x2;
    *h11 = x3 - x2;
}

/* the fields of a section a remap reads while it writes the nodes */
typedef struct field_view {
    const double *x, *y, *phi, *vx, *vy, *w, *s;
} field_view;

static field_view live_view(const bd_boom *b)
{
    field_view f = {b->x, b->y, b->phi, b->vx, b->vy, b->w, b->s};
    return f;
}

/* the element from node a: its material length l0 and the nodes' slopes
 * r' = lambda (cos phi, sin phi), lambda its stretch */
typedef struct elem_slopes {
    double l0, ta_x, ta_y, tb_x, tb_y;
} elem_slopes;

static elem_slopes slopes_of(const field_view *f, int a)
{
    int c = a + 1;
    elem_slopes e;
    e.l0 = f->s[c] - f->s[a];
    double dx = f->x[c] - f->x[a], dy = f->y[c] - f->y[a];
    double lam = e.l0 > 0.0 ? sqrt(dx * dx + dy * dy) / e.l0 : 1.0;
    e.ta_x = lam * cos(f->phi[a]);
    e.ta_y = lam * sin(f->phi[a]);
    e.tb_x = lam * cos(f->phi[c]);
    e.tb_y = lam * sin(f->phi[c]);
    return e;
}

/* evaluate at parameter xi of the element starting at node a */
static void eval_on(const field_view *f, int a, double xi, double *x, double *y, double *phi,
                    double *vx, double *vy, double *w)
{
    int c = a + 1;
    elem_slopes e = slopes_of(f, a);
    double l0 = e.l0, ta_x = e.ta_x, ta_y = e.ta_y, tb_x = e.tb_x, tb_y = e.tb_y;
    double h00, h10, h01, h11;
    hermite(xi, &h00, &h10, &h01, &h11);
    *x = h00 * f->x[a] + h10 * l0 * ta_x + h01 * f->x[c] + h11 * l0 * tb_x;
    *y = h00 * f->y[a] + h10 * l0 * ta_y + h01 * f->y[c] + h11 * l0 * tb_y;
    *phi = (1.0 - xi) * f->phi[a] + xi * f->phi[c];
    /* v' = w x r' */
    *vx = h00 * f->vx[a] + h10 * l0 * (-f->w[a] * ta_y) + h01 * f->vx[c]
        + h11 * l0 * (-f->w[c] * tb_y);
    *vy = h00 * f->vy[a] + h10 * l0 * (f->w[a] * ta_x) + h01 * f->vy[c]
        + h11 * l0 * (f->w[c] * tb_x);
    *w = (1.0 - xi) * f->w[a] + xi * f->w[c];
}

/* ---- the rigid boom ---- */

double boom_rigid_offset(const bd_boom *b, int k, double stroke)
{
    double off = 0.0;
    for (int j = 1; j <= k; j++)
        off += (j == 1 || b->def.synchronized) ? stroke : b->def.stroke.initial;
    return off;
}

/* how fast section k's bottom moves along the axis for a stroke speed v */
static double rigid_offset_rate(const bd_boom *b, int k, double v)
{
    if (k == 0)
        return 0.0;
    return b->def.synchronized ? k * v : v;
}

void boom_rigid_point(const bd_boom *b, int k, double s, double *x, double *y, double *vx,
                      double *vy)
{
    double c = b->cos_theta, sn = b->sin_theta;
    /* (d, n): the point in the boom frame from the pivot */
    double d = b->base_a + boom_rigid_offset(b, k, b->stroke_ref) + s, n = b->base_n;
    double dd = rigid_offset_rate(b, k, b->stroke_v);
    double rx = d * c - n * sn, ry = d * sn + n * c;
    *x = b->def.pivot[0] + rx;
    *y = b->def.pivot[1] + ry;
    /* along the axis, plus the luffing rotation */
    *vx = dd * c - b->theta_dot * ry;
    *vy = dd * sn + b->theta_dot * rx;
}

void boom_distribute(bd_boom *b, int k)
{
    const boom_section *S = &b->sec[k];
    int i0 = S->first;
    if (S->key == BOOM_KEY_NONE) {
        for (int i = 0; i < S->n; i++)
            b->s[i0 + i] = S->L * i / (S->n - 1);
        return;
    }
    int p = S->per_seg;
    for (int i = 0; i <= p; i++)
        b->s[i0 + i] = S->key_s * i / p;
    for (int i = 1; i <= p; i++)
        b->s[i0 + p + i] = S->key_s + (S->L - S->key_s) * i / p;
}

void boom_masses(bd_boom *b)
{
    for (int k = 0; k < b->ns; k++) {
        const boom_section *S = &b->sec[k];
        for (int i = S->first; i < S->first + S->n; i++) {
            double lm = i > S->first ? b->s[i] - b->s[i - 1] : 0.0;
            double lp = i < S->first + S->n - 1 ? b->s[i + 1] - b->s[i] : 0.0;
            b->m[i] = S->rhoA * 0.5 * (lm + lp);
            /* rotary inertia of the half elements about the node (the
             * section's own rho*I is far smaller); it sets only the
             * highest frequencies */
            b->J[i] = S->rhoA * (lm * lm * lm + lp * lp * lp) / 24.0;
        }
    }
    b->m[b->N - 1] += b->tip_mass;
}

/* the outer contact point of section k >= 1 on the rigid boom: where
 * section k-1's top stands, in section k's material */
static double rigid_outer_contact(const bd_boom *b, int k)
{
    double sig = boom_rigid_offset(b, k, b->stroke_ref)
               - boom_rigid_offset(b, k - 1, b->stroke_ref);
    return b->sec[k - 1].L - sig;
}

double boom_key_clamp(const boom_section *S, double key_s)
{
    double lo = S->L / 6.0, hi = S->L - lo;
    return key_s < lo ? lo : (key_s > hi ? hi : key_s);
}

void boom_place_rigid(bd_boom *b)
{
    for (int k = 0; k < b->ns; k++) {
        boom_section *S = &b->sec[k];
        if (S->key == BOOM_KEY_OUTER)
            S->key_s = boom_key_clamp(S, rigid_outer_contact(b, k));
        else if (S->key == BOOM_KEY_ATTACH)
            S->key_s = b->attach_s;
        boom_distribute(b, k);
        for (int i = S->first; i < S->first + S->n; i++) {
            boom_rigid_point(b, k, b->s[i], &b->x[i], &b->y[i], &b->vx[i], &b->vy[i]);
            b->phi[i] = b->theta;
            b->w[i] = b->theta_dot;
        }
    }
    boom_masses(b);
}

/* ---- located points ---- */

double boom_where_s(const bd_boom *b, const boom_where *at)
{
    return b->s[at->a] + at->xi * (b->s[at->a + 1] - b->s[at->a]);
}

void boom_eval(const bd_boom *b, const boom_where *at, double *x, double *y, double *phi,
               double *vx, double *vy, double *w)
{
    field_view f = live_view(b);
    eval_on(&f, at->a, at->xi, x, y, phi, vx, vy, w);
}

void boom_apply(bd_boom *b, const boom_where *at, double fx, double fy, double mz)
{
    int a = at->a, c = a + 1;
    double xi = at->xi;
    field_view f = live_view(b);
    elem_slopes e = slopes_of(&f, a);
    double l0 = e.l0, ta_x = e.ta_x, ta_y = e.ta_y, tb_x = e.tb_x, tb_y = e.tb_y;
    double h00, h10, h01, h11;
    hermite(xi, &h00, &h10, &h01, &h11);
    b->fx[a] += h00 * fx;
    b->fy[a] += h00 * fy;
    b->fx[c] += h01 * fx;
    b->fy[c] += h01 * fy;
    /* the slope's virtual rotation: F . (dphi z x r') = dphi (r' x F) */
    b->mz[a] += h10 * l0 * (ta_x * fy - ta_y * fx) + (1.0 - xi) * mz;
    b->mz[c] += h11 * l0 * (tb_x * fy - tb_y * fx) + xi * mz;
}

double boom_inv_mass(const bd_boom *b, const boom_where *at)
{
    double h00, h10, h01, h11;
    hermite(at->xi, &h00, &h10, &h01, &h11);
    return h00 * h00 / b->m[at->a] + h01 * h01 / b->m[at->a + 1];
}

double boom_inv_inertia(const bd_boom *b, const boom_where *at)
{
    double xi = at->xi;
    return (1.0 - xi) * (1.0 - xi) / b->J[at->a] + xi * xi / b->J[at->a + 1];
}

/* nearest point of section k to p, walking elements from *at then two
 * Gauss-Newton steps on the Hermite curve */
static void project_on(const field_view *f, const boom_section *S, double px, double py,
                       boom_where *at)
{
    int lo = S->first, hi = S->first + S->n - 2;
    int a = at->a < lo || at->a > hi ? lo : at->a;
    double xi = 0.0;
    for (int it = 0; it < S->n + 1; it++) {
        double dx = f->x[a + 1] - f->x[a], dy = f->y[a + 1] - f->y[a];
        double d2 = dx * dx + dy * dy;
        xi = d2 > 0.0 ? ((px - f->x[a]) * dx + (py - f->y[a]) * dy) / d2 : 0.0;
        if (xi < 0.0 && a > lo)
            a--;
        else if (xi > 1.0 && a < hi)
            a++;
        else
            break;
    }
    for (int it = 0; it < 2; it++) {
        double x, y, phi, vx, vy, w, x2, y2;
        const double h = 1e-6;
        eval_on(f, a, xi, &x, &y, &phi, &vx, &vy, &w);
        eval_on(f, a, xi + h, &x2, &y2, &phi, &vx, &vy, &w);
        double tx = (x2 - x) / h, ty = (y2 - y) / h;
        double t2 = tx * tx + ty * ty;
        if (t2 > 0.0)
            xi += ((px - x) * tx + (py - y) * ty) / t2;
    }
    if (xi < 0.0)
        xi = 0.0;
    if (xi > 1.0)
        xi = 1.0;
    at->a = a;
    at->xi = xi;
}

void boom_project(const bd_boom *b, int k, double px, double py, boom_where *at)
{
    field_view f = live_view(b);
    at->sec = k;
    project_on(&f, &b->sec[k], px, py, at);
}

/* ---- the remap ---- */

/* move section k's nodes to the material coordinates of its key node
 * key_s: each takes the state interpolated at its new s from the section
 * as it stood (masses not updated: boom_masses) */
void boom_move_key(bd_boom *b, int k, double key_s)
{
    boom_section *S = &b->sec[k];
    int i0 = S->first, n = S->n;
    size_t bytes = (size_t)n * sizeof(double);
    memcpy(b->tx + i0, b->x + i0, bytes);
    memcpy(b->ty + i0, b->y + i0, bytes);
    memcpy(b->tphi + i0, b->phi + i0, bytes);
    memcpy(b->tvx + i0, b->vx + i0, bytes);
    memcpy(b->tvy + i0, b->vy + i0, bytes);
    memcpy(b->tw + i0, b->w + i0, bytes);
    memcpy(b->ts + i0, b->s + i0, bytes);
    field_view old = {b->tx, b->ty, b->tphi, b->tvx, b->tvy, b->tw, b->ts};
    S->key_s = key_s;
    boom_distribute(b, k);
    int a = i0;
    /* the ends are material points: they stay */
    for (int i = i0 + 1; i < i0 + n - 1; i++) {
        double s = b->s[i];
        while (a < i0 + n - 2 && old.s[a + 1] < s)
            a++;
        while (a > i0 && old.s[a] > s)
            a--;
        double l0 = old.s[a + 1] - old.s[a];
        double xi = l0 > 0.0 ? (s - old.s[a]) / l0 : 0.0;
        eval_on(&old, a, xi, &b->x[i], &b->y[i], &b->phi[i], &b->vx[i], &b->vy[i], &b->w[i]);
    }
}

void boom_remap(bd_boom *b)
{
    for (int k = 1; k < b->ns; k++) {
        boom_section *S = &b->sec[k];
        if (S->key != BOOM_KEY_OUTER)
            continue;
        /* section k-1's top node, located on section k */
        int top = b->sec[k - 1].first + b->sec[k - 1].n - 1;
        boom_where at = {k, S->first + S->per_seg - 1, 1.0};
        boom_project(b, k, b->x[top], b->y[top], &at);
        double key_s = boom_key_clamp(S, boom_where_s(b, &at));
        if (key_s != S->key_s)
            boom_move_key(b, k, key_s);
    }
    boom_masses(b);
}
