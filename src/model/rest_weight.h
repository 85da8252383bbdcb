/* The weight of belt and material along the path: what the at-rest tension
 * distribution of every belt formulation rests on. Seed 001 eq 2.9 sums a
 * section's tension change from its resistances; at rest the main,
 * secondary and special ones are zero and only the slope term of eq 2.11
 * remains, g·(m'_G + m'_L)·sin δ·l per section, i.e. dT/ds = m'(s)·g·dy/ds
 * and T(s) = T_c + W(s) with W = ∫ m'·g dy (docs/physics.md §7, §11). */
#ifndef BD_REST_WEIGHT_H
#define BD_REST_WEIGHT_H

#include "model/path.h"

/* what loads the belt at rest */
typedef struct bd_rest_load {
    double belt_mpl;       /* kg/m, the belt */
    double material_mpl;   /* kg/m, the material on [from, to] */
    double from, to;       /* m, the loaded region (to − from < loop length;
                              empty when to <= from) */
    double gravity;        /* m/s² */
} bd_rest_load;

/* overlap of [a, b] with [c, d] on a loop of length L (each shorter than
 * L); the first overlapping piece's bounds in *lo, *hi (either may be NULL) */
double bd_loop_overlap(double a, double b, double c, double d, double L, double *lo,
                       double *hi);

/* ∫ m'(s)·g dy from a to b along the path (negative when b < a), in
 * `pieces` equal pieces, each weighted by the loaded fraction it covers */
double bd_rest_weight(const bd_path *path, const bd_rest_load *load, double a, double b,
                      int pieces);

/* ∫ m'(s) ds from a to b (a ≤ b), kg */
double bd_rest_mass(const bd_path *path, const bd_rest_load *load, double a, double b);

#endif
