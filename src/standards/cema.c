/* CEMA belt tensions (seed 001 §2.2, eqs 2.1-2.4 with Table 2.1).
 *
 * Seed 001 writes eqs 2.1, 2.2 and 2.4 in SI (N, m, kg/m, g), but Table 2.1
 * keeps CEMA's imperial basis: its rows are average belt tensions in lbf
 * (1000..16000; the kN column is a rounded conversion), its columns idler
 * spacings in ft (3.0..5.0), and eq 2.3 takes W_b + W_m in lb/ft. So Ky is
 * looked up with T in lbf, S in ft and W in lb/ft; Ky itself is a plain
 * ratio (resistance per weight) and needs no conversion. */
#include "standards/standards_internal.h"

#include <math.h>

/* unit conversions (exact definitions of the pound and the foot) */
static const double N_PER_LBF = 4.4482216152605;    /* N per lbf */
static const double M_PER_FT = 0.3048;              /* m per ft */
static const double KGPM_PER_LBPFT = 1.4881639435695537; /* (kg/m) per (lb/ft) */

/* CEMA Ky above the table (seed 001, below Table 2.1) and on return runs */
static const double KY_HIGH_TENSION = 0.016;
static const double KY_RETURN = 0.015;
/* seed 001 §2.2.1: C1 = 0.5..0.7 for regenerative conveyors; the lowest
 * friction gives the largest braking force and T2 demand (conservative) */
static const double C1_REGENERATIVE = 0.5;

#define KY_ROWS 16
#define KY_COLS 5
/* Table 2.1 (seed 001): rows average belt tension, lbf; columns idler spacing, ft */
static const double KY_T_LBF[KY_ROWS] = {1000, 2000, 3000, 4000, 5000, 6000,
    7000, 8000, 9000, 10000, 11000, 12000, 13000, 14000, 15000, 16000};
static const double KY_S_FT[KY_COLS] = {3.0, 3.5, 4.0, 4.5, 5.0};
static const double KY_A[KY_ROWS][KY_COLS] = {
    {1.4447, 1.4753, 1.4783, 1.4825, 1.4615},
    {1.2412, 1.1186, 1.0856, 1.0511, 1.0368},
    {1.0943, 0.9856, 0.9626, 0.9538, 0.9890},
    {0.9827, 0.9085, 0.8934, 0.8903, 0.9307},
    {0.8620, 0.8014, 0.7934, 0.7937, 0.8254},
    {0.7646, 0.7217, 0.7139, 0.7164, 0.7366},
    {0.6766, 0.6349, 0.6420, 0.6576, 0.6984},
    {0.6163, 0.5747, 0.5808, 0.5964, 0.6443},
    {0.5515, 0.5376, 0.5304, 0.5603, 0.5988},
    {0.4866, 0.4947, 0.4835, 0.5255, 0.5556},
    {0.4356, 0.4460, 0.4464, 0.4956, 0.5220},
    {0.3916, 0.3916, 0.4188, 0.4536, 0.4980},
    {0.3499, 0.3522, 0.3852, 0.4152, 0.4583},
    {0.3151, 0.3232, 0.3504, 0.3743, 0.4092},
    {0.2803, 0.2977, 0.3180, 0.3480, 0.3768},
    {0.2502, 0.2665, 0.2851, 0.3084, 0.3396},
};
static const double KY_B[KY_ROWS][KY_COLS] = {
    {1.565, 1.925, 2.250, 2.584, 2.910},
    {1.345, 1.744, 1.982, 2.197, 2.331},
    {1.237, 1.593, 1.799, 1.991, 2.091},
    {1.164, 1.465, 1.659, 1.825, 1.938},
    {1.122, 1.381, 1.559, 1.714, 1.839},
    {1.076, 1.318, 1.472, 1.627, 1.761},
    {1.039, 1.256, 1.404, 1.549, 1.657},
    {0.998, 1.194, 1.337, 1.472, 1.583},
    {0.958, 1.120, 1.272, 1.388, 1.507},
    {0.918, 1.066, 1.216, 1.314, 1.430},
    {0.885, 1.024, 1.167, 1.238, 1.340},
    {0.842, 0.992, 1.100, 1.180, 1.242},
    {0.798, 0.938, 1.040, 1.116, 1.169},
    {0.763, 0.897, 0.996, 1.069, 1.123},
    {0.718, 0.841, 0.935, 1.006, 1.063},
    {0.663, 0.780, 0.875, 0.958, 1.009},
};

/* index i and fraction u of x in the increasing grid v[0..n-1], clamped */
static void locate(const double *v, int n, double x, int *i, double *u, int *clamped)
{
    if (x < v[0]) {
        x = v[0];
        *clamped = 1;
    } else if (x > v[n - 1]) {
        x = v[n - 1];
        *clamped = 1;
    }
    int k = 0;
    while (k < n - 2 && x > v[k + 1])
        k++;
    *i = k;
    *u = (x - v[k]) / (v[k + 1] - v[k]);
}

double bd_cema_ky(double T_avg, double spacing, double W_kg_per_m, int *clamped)
{
    double T_lbf = T_avg / N_PER_LBF;
    /* above 71.17 kN (16000 lbf): Ky = 0.016 (seed 001, below Table 2.1) */
    if (T_lbf > KY_T_LBF[KY_ROWS - 1])
        return KY_HIGH_TENSION;
    double S_ft = spacing / M_PER_FT;
    double W_lbft = W_kg_per_m / KGPM_PER_LBPFT;
    int i, j;
    double u, w;
    locate(KY_T_LBF, KY_ROWS, T_lbf, &i, &u, clamped);
    locate(KY_S_FT, KY_COLS, S_ft, &j, &w, clamped);
    /* bilinear interpolation of A and B in Table 2.1 */
    double A = (1 - u) * ((1 - w) * KY_A[i][j] + w * KY_A[i][j + 1])
             + u * ((1 - w) * KY_A[i + 1][j] + w * KY_A[i + 1][j + 1]);
    double B = (1 - u) * ((1 - w) * KY_B[i][j] + w * KY_B[i][j + 1])
             + u * ((1 - w) * KY_B[i + 1][j] + w * KY_B[i + 1][j + 1]);
    /* eq 2.3: Ky = (Wm + Wb)·A·1e-4 + B·1e-2, W in lb/ft */
    return W_lbft * A * 1e-4 + B * 1e-2;
}

/* CEMA Ai (N per idler set) by roll diameter, seed 001 §2.2.1 list:
 * 4 in 10.23, 5 in 8.01, 6 in 6.67 (C6, D6), 7 in 10.68 (E7) */
static double ai_by_roll(double radius)
{
    static const double dia_in[] = {4.0, 5.0, 6.0, 7.0};
    static const double ai[] = {10.23, 8.01, 6.67, 10.68};
    double d = 2.0 * radius / 0.0254;
    int best = 0;
    for (int i = 1; i < 4; i++)
        if (fabs(d - dia_in[i]) < fabs(d - dia_in[best]))
            best = i;
    return ai[best];
}

/* resistances of every section for the current tensions; returns the number
 * of sections whose Ky lookup left Table 2.1 */
static int cema_pass(bd_std_ctx *c, double Kt, double Ai, int ai_auto, double C1)
{
    double g = c->g, Wb = c->mG;
    double Kx_user = c->design.cema.Kx_extra;
    const bd_material_def *mat = &c->m->material;
    int clamped_sections = 0, tam_done = 0;
    for (int k = 0; k < c->nsec; k++) {
        bd_std_section *s = &c->sec[k];
        double L = s->length, Wm = s->mL;
        if (s->spacing <= 0.0) {
            /* no idlers on this span (vertical takeup loops, bends): no
             * flexure or idler friction, only the lift terms below */
            s->main = 0.0;
            s->Kx = s->Ky = 0.0;
        } else if (s->carry) {
            /* eq 2.2: Kx = 0.00068·(Wb + Wm)·g + Ai/Si (N/m), Si the carry
             * idler spacing; it lumps carry and return idler friction */
            double ai = ai_auto ? ai_by_roll(s->roll_radius) : Ai;
            double Kx = 0.00068 * (Wb + Wm) * g + (s->spacing > 0.0 ? ai / s->spacing : 0.0);
            if (Kx_user >= 0.0)
                Kx = Kx_user;
            /* Ky from Table 2.1 / eq 2.3 at the section's average tension */
            int cl = 0;
            double Ky = bd_cema_ky(0.5 * (s->T0 + s->T1), s->spacing, Wb + Wm, &cl);
            clamped_sections += cl;
            /* eq 2.4 without the lift terms:
             * L·Kt·(Kx + C1·Ky·Wb·g) + Wm·g·C1·L·Ky */
            s->main = L * Kt * (Kx + C1 * Ky * Wb * g) + Wm * g * C1 * L * Ky;
            s->Kx = Kx;
            s->Ky = Ky;
        } else {
            /* eq 2.4 on the return run: Kx = 0, C1 = 1, Ky = 0.015 (seed
             * 001 §2.2.2 and below Table 2.1) — eq 2.1's 0.015·Wb·g term */
            s->main = L * Kt * KY_RETURN * Wb * g + Wm * g * L * KY_RETURN;
            s->Kx = 0.0;
            s->Ky = KY_RETURN;
        }
        /* eq 2.4 lift terms: Wm·g·ΔY + Wb·g·ΔY (their loop sum is eq 2.1's Wm·g·H) */
        s->slope = (Wm + Wb) * g * s->lift;
        /* eq 2.1 T_am: force to accelerate the material fed onto the belt,
         * mass flow times speed gained, Wm·v·(v - 0), at the feed point */
        s->secondary = 0.0;
        if (!tam_done && Wm > 0.0 && mat->present && mat->feeding) {
            s->secondary = Wm * c->speed * c->speed;
            tam_done = 1;
        }
    }
    return clamped_sections;
}

/* iterate resistances and tensions until Ky settles (Ky depends on the
 * tensions it produces, seed 001 §2.2.1); returns the iterations taken,
 * or -1 when they did not settle */
static int cema_iterate(bd_std_ctx *c, double Kt, double Ai, int ai_auto, double C1,
                        int *clamped)
{
    for (int it = 1; it <= 200; it++) {
        /* resistances at the current tensions */
        *clamped = cema_pass(c, Kt, Ai, ai_auto, C1);
        /* new tensions; stop when no section end moved */
        double change = 0.0, scale = 1.0;
        for (int k = 0; k < c->nsec; k++) {
            c->sec[k].T0_prev = c->sec[k].T0;
            c->sec[k].T1_prev = c->sec[k].T1;
        }
        bd_std_propagate(c);
        for (int k = 0; k < c->nsec; k++) {
            change = fmax(change, fabs(c->sec[k].T0 - c->sec[k].T0_prev));
            change = fmax(change, fabs(c->sec[k].T1 - c->sec[k].T1_prev));
            scale = fmax(scale, fabs(c->sec[k].T0));
        }
        if (it > 1 && change <= 1e-10 * scale)
            return it;
    }
    return -1;
}

int bd_cema_resistances(bd_std_ctx *c)
{
    bd_static_result *r = c->out;
    double Kt = c->design.cema.Kt > 0.0 ? c->design.cema.Kt : 1.0;
    double Ai = c->design.cema.Ai;
    int ai_auto = !(Ai > 0.0);  /* Ai not given: by the carry idlers' roll diameter */
    double C1 = 1.0;  /* seed 001 §2.2.1: C1 = 1 for non-regenerative */
    int clamped = 0;

    /* start from zero tensions; the level rule sets them on the first pass */
    for (int k = 0; k < c->nsec; k++)
        c->sec[k].T0 = c->sec[k].T1 = 0.0;
    int it = cema_iterate(c, Kt, Ai, ai_auto, C1, &clamped);

    /* regenerative (Te < 0): seed 001 §2.2.1, Ai = 0 and C1 = 0.5..0.7 */
    if (it > 0 && bd_std_total(c) < 0.0) {
        Ai = 0.0;
        ai_auto = 0;
        C1 = C1_REGENERATIVE;
        it = cema_iterate(c, Kt, Ai, ai_auto, C1, &clamped);
        bd_std_note(r, "CEMA regenerative: Ai = 0 and friction modification "
                       "factor C1 = %.2f on the carrying run (seed 001 sec. 2.2.1)", C1);
    }
    if (it < 0)
        bd_std_warn(r, "CEMA: belt tensions and Ky did not settle in 200 iterations; "
                       "the results are those of the last iteration");
    if (ai_auto) {
        /* report the value of the first carry section */
        for (int k = 0; k < c->nsec; k++)
            if (c->sec[k].carry && c->sec[k].spacing > 0.0) {
                Ai = ai_by_roll(c->sec[k].roll_radius);
                break;
            }
        bd_std_note(r, "CEMA Ai not given: %.2f N per idler set from the carry idlers' "
                       "roll diameter (seed 001 sec. 2.2.1)", Ai);
    }
    if (clamped)
        bd_std_warn(r, "CEMA Ky: on %d section(s) the average tension or idler spacing "
                       "lies outside Table 2.1 (4.45-71.17 kN, 0.91-1.52 m); "
                       "the nearest table edge was used", clamped);
    r->cema_Kt = Kt;
    r->cema_Ai_N = Ai;
    r->cema_C1 = C1;
    r->cema_iterations = it;
    return 0;
}
