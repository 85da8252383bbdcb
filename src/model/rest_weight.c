/* The weight of belt and material along the path (rest_weight.h). */
#include "model/rest_weight.h"

#include <math.h>

double bd_loop_overlap(double a, double b, double c, double d, double L, double *lo,
                       double *hi)
{
    double total = 0.0;
    for (int k = -1; k <= 1; k++) {
        double l = a > c + k * L ? a : c + k * L;
        double h = b < d + k * L ? b : d + k * L;
        if (h > l) {
            if (total == 0.0 && lo) {
                *lo = l;
                *hi = h;
            }
            total += h - l;
        }
    }
    return total;
}

/* the loaded length of [a, b] (a ≤ b) */
static double loaded(const bd_path *path, const bd_rest_load *load, double a, double b)
{
    if (load->to <= load->from)
        return 0.0;
    return bd_loop_overlap(a, b, load->from, load->to, path->length, NULL, NULL);
}

double bd_rest_weight(const bd_path *path, const bd_rest_load *load, double a, double b,
                      int pieces)
{
    const double g = load->gravity, mL = load->material_mpl;
    double ds = (b - a) / pieces, w = 0.0;
    double p[2], t[2], yprev;
    bd_path_point(path, a, p, t);
    yprev = p[1];
    for (int k = 0; k < pieces; k++) {
        double lo = a + k * ds;
        bd_path_point(path, lo + ds, p, t);
        double on = 0.0;
        if (mL > 0.0 && ds != 0.0)
            on = loaded(path, load, ds > 0.0 ? lo : lo + ds, ds > 0.0 ? lo + ds : lo) / fabs(ds);
        w += (load->belt_mpl + mL * on) * g * (p[1] - yprev);
        yprev = p[1];
    }
    return w;
}

double bd_rest_mass(const bd_path *path, const bd_rest_load *load, double a, double b)
{
    return load->belt_mpl * (b - a) + load->material_mpl * loaded(path, load, a, b);
}
