/* The nested boom's static deflection under its weight and a tip load
 * against stepped-beam theory with the overlaps stiffened by the pads
 * (issue 13's acceptance: within 1 %).
 *
 * The reference: horizontal (no axial load, so no second-order effect),
 * every inner section resting on its outer neighbour at two points, its
 * bottom end and the outer section's top (the pads, here stiff, narrow and
 * without clearance). Each inner section is then a statically determinate
 * beam on two supports with an overhang, the outermost a cantilever; the
 * reactions follow from statics, the bending moment from the loads, the
 * deflection from integrating M/EI twice with the section's two support
 * points moving with its outer neighbour. Through the overlap both
 * sections carry the moment: the stiffening is in the reference exactly
 * as the pads make it. The tolerance allows the lumping of the weight at
 * the nodes and the pads' compliance (both < 0.1 % here). */
#include "beltdyn/boom.h"
#include "boom/boom_internal.h"
#include "testlib.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NS 3
#define GRID 20000

static const double LEN = 10.0, STROKE = 5.0, TIP = 1000.0, G = 9.81;
static const double RHO[NS] = {318.86, 304.07, 289.27};
static const double EIS[NS] = {7.22e8, 6.30e8, 5.46e8};

/* point loads on one section (N, downward positive) at x (m from pivot) */
typedef struct { double x, F; } point_load;

/* bending moment at x of section k from its own weight over [x0, x1] and
 * point loads beyond x (hogging negative) */
static double moment(double x, double x0, double x1, double q, const point_load *p, int np)
{
    double M = 0.0;
    double a = fmax(x, x0);
    if (x1 > a)
        M -= q * (x1 - a) * (0.5 * (x1 + a) - x);
    for (int i = 0; i < np; i++)
        if (p[i].x > x)
            M -= p[i].F * (p[i].x - x);
    return M;
}

static double reference_tip(void)
{
    double X[NS], q[NS];
    for (int k = 0; k < NS; k++) {
        X[k] = k * STROKE;
        q[k] = RHO[k] * G;
    }
    /* reactions, innermost first: R1 at the section's bottom, R2 at the
     * outer section's top (upward on the inner section) */
    double R1[NS] = {0}, R2[NS] = {0};
    point_load loads[NS][4];
    int nl[NS] = {0};
    loads[NS - 1][nl[NS - 1]++] = (point_load){X[NS - 1] + LEN, TIP * G};
    for (int k = NS - 1; k >= 1; k--) {
        double W = q[k] * LEN, MW = q[k] * LEN * 0.5 * LEN;
        for (int i = 0; i < nl[k]; i++) {
            W += loads[k][i].F;
            MW += loads[k][i].F * (loads[k][i].x - X[k]);
        }
        double x2 = X[k - 1] + LEN;
        R2[k] = MW / (x2 - X[k]);
        R1[k] = W - R2[k];
        /* the supports as negative loads on section k, their reactions as
         * loads on section k-1 */
        loads[k][nl[k]++] = (point_load){X[k], -R1[k]};
        loads[k][nl[k]++] = (point_load){x2, -R2[k]};
        loads[k - 1][nl[k - 1]++] = (point_load){X[k], R1[k]};
        loads[k - 1][nl[k - 1]++] = (point_load){x2, R2[k]};
    }
    /* deflection, outermost first, on a grid of each section */
    static double w[NS][GRID + 1];
    double h = LEN / GRID;
    for (int k = 0; k < NS; k++) {
        /* curvature -> slope and deflection from 0, 0 at the section's bottom */
        double th = 0.0, y = 0.0;
        w[k][0] = 0.0;
        double kap_prev = moment(X[k], X[k], X[k] + LEN, q[k], loads[k], nl[k]) / EIS[k];
        for (int i = 1; i <= GRID; i++) {
            double x = X[k] + i * h;
            double kap = moment(x, X[k], X[k] + LEN, q[k], loads[k], nl[k]) / EIS[k];
            double th_new = th + 0.5 * h * (kap_prev + kap);
            y += 0.5 * h * (th + th_new);
            th = th_new;
            kap_prev = kap;
            w[k][i] = y;
        }
        if (k == 0)
            continue;
        /* add the rigid line through the two supports' deflections */
        int i2 = (int)lround((X[k - 1] + LEN - X[k]) / h);
        int i1o = (int)lround((X[k] - X[k - 1]) / h), i2o = GRID;
        double wa = w[k - 1][i1o], wb = w[k - 1][i2o];
        double ca = wa - w[k][0], cb = wb - w[k][i2];
        double slope = (cb - ca) / (i2 * h);
        for (int i = 0; i <= GRID; i++)
            w[k][i] += ca + slope * i * h;
    }
    return w[NS - 1][GRID];
}

int main(void)
{
    bd_boom_def d;
    bd_boom_def_init(&d);
    strcpy(d.name, "static");
    strcpy(d.source, "test");
    d.section_count = NS;
    d.sections = calloc(NS, sizeof *d.sections);
    for (int k = 0; k < NS; k++) {
        d.sections[k].length = LEN;
        d.sections[k].mass_per_length = RHO[k];
        d.sections[k].axial_stiffness = 2.1e11 * RHO[k] / 7850.0;
        d.sections[k].bending_stiffness = EIS[k];
        d.sections[k].height = 0.8 - 0.04 * k;
    }
    d.luffing_angle.n = 1;
    d.luffing_angle.t = calloc(1, sizeof(double));
    d.luffing_angle.v = calloc(1, sizeof(double));
    d.pads.width = 0.01;
    d.pads.stiffness = 1e11;
    d.pads.mu_static = d.pads.mu_dynamic = 0.0;
    d.pads.switch_speed = 0.01;
    d.gap = 0.0;
    d.stroke.initial = STROKE;
    d.stroke.kind = BD_STROKE_TABLE;
    d.stroke.table.n = 1;
    d.stroke.table.t = calloc(1, sizeof(double));
    d.stroke.table.v = calloc(1, sizeof(double));
    d.stroke.table.v[0] = STROKE;
    d.tip_mass = TIP;
    d.gravity = G;
    d.simulation.duration = 1e-5;
    bd_diag diag;
    bd_diag_init(&diag);
    bd_boom *b = NULL;
    CHECK(bd_boom_create(&d, &b, &diag) == 0);
    if (!b)
        return bd_test_finish("boom_static_deflection");
    char err[512];
    bd_run_options opt;
    memset(&opt, 0, sizeof opt);
    CHECK(bd_boom_run(b, &opt, err, sizeof err) == BD_RUN_OK);
    double x, y, vx, vy;
    boom_tip(b, &x, &y, &vx, &vy);
    double want = reference_tip();
    printf("static tip deflection %.4f mm, stepped-beam theory %.4f mm (%+.3f %%)\n", 1e3 * y,
           1e3 * want, 100.0 * (y / want - 1.0));
    CHECK(want < 0.0);
    CHECK_REL(y, want, 0.01);
    bd_boom_free(b);
    bd_boom_def_free(&d);
    bd_diag_free(&diag);
    return bd_test_finish("boom_static_deflection");
}
