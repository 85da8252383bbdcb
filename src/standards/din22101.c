/* DIN 22101 / ISO 5048 resistances per section (seed 001 §2.3,
 * model-format.md `design`): both standards use the same rules here. */
#include "standards/standards_internal.h"

#include <math.h>

/* Table 2.3 (seed 001, DIN 22101 / ISO 5048): C by length L in m */
static const double C_TABLE_L[] = {80, 100, 150, 200, 300, 400, 500, 600,
                                   700, 800, 900, 1000, 1500, 2000};
static const double C_TABLE_C[] = {1.92, 1.78, 1.58, 1.45, 1.31, 1.25, 1.20,
                                   1.17, 1.14, 1.12, 1.10, 1.09, 1.06, 1.05};

double bd_din22101_C(double L)
{
    int n = (int)(sizeof C_TABLE_L / sizeof C_TABLE_L[0]);
    /* below 80 m: 1.92 (the caller warns); 2000 m and longer: 1.05 */
    if (L <= C_TABLE_L[0])
        return C_TABLE_C[0];
    if (L >= C_TABLE_L[n - 1])
        return C_TABLE_C[n - 1];
    /* linear interpolation between the table's points (model-format.md) */
    int i = 0;
    while (L > C_TABLE_L[i + 1])
        i++;
    double u = (L - C_TABLE_L[i]) / (C_TABLE_L[i + 1] - C_TABLE_L[i]);
    return C_TABLE_C[i] + u * (C_TABLE_C[i + 1] - C_TABLE_C[i]);
}

void bd_din22101_resistances(bd_std_ctx *c)
{
    double f = c->design.f, g = c->g, mG = c->mG;
    double C = c->out->C;

    /* main and slope resistance of every section */
    for (int k = 0; k < c->nsec; k++) {
        bd_std_section *s = &c->sec[k];
        /* eq 2.10 (DIN 22101, f_i ≈ f): F_H,i = f·g·[m'_R,i + (m'_G + m'_L,i)·cos δ_i]·l_i */
        s->main = f * g * (s->mR + (mG + s->mL) * s->cos_delta) * s->length;
        /* eq 2.11: F_St,i = g·(m'_G + m'_L,i)·sin δ_i·l_i, sin δ_i·l_i = Δh_i */
        s->slope = g * (mG + s->mL) * s->lift;
        s->Kx = s->Ky = 0.0;
    }

    /* secondary resistances: eq 2.7, F_N = (C - 1)·F_H, shared among the
     * sections in proportion to F_H,i (model-format.md) */
    if (c->design.secondary == BD_SECONDARY_INDIVIDUAL)
        return;   /* one by one instead (individual.c); the sections'
                     secondary stay 0 as allocated */
    for (int k = 0; k < c->nsec; k++)
        c->sec[k].secondary = (C - 1.0) * c->sec[k].main;
}
