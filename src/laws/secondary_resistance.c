/* ISO 5048:1989 §5.2, Table 3 (DIN 22101 has the same rules): each
 * function says its formula in secondary_resistance.h. */
#include "laws/secondary_resistance.h"

double bd_res_loading_inertia(double mL, double v, double v0)
{
    /* I_V·ρ = m'_L·v: the material's volume flow times its density */
    return mL * v * (v - v0);
}

double bd_res_acceleration_length(double v, double v0, double g, double mu1)
{
    if (mu1 <= 0.0 || v <= v0)
        return 0.0;
    return (v * v - v0 * v0) / (2.0 * g * mu1);
}

double bd_res_skirt_friction(double mu2, double mL, double v, double v_m, double rho, double g,
                             double length, double b1)
{
    if (rho <= 0.0 || b1 <= 0.0 || v_m <= 0.0)
        return 0.0;
    double Iv = mL * v / rho; /* m³/s */
    return mu2 * Iv * Iv * rho * g * length / (v_m * v_m * b1 * b1);
}

double bd_res_cleaners(double count, double width, double thickness, double pressure,
                       double mu3)
{
    return count * width * thickness * pressure * mu3;
}

void bd_res_wrap_coeffs(int steel_cord, double B, double d, double D, double *a, double *b)
{
    *a = *b = 0.0;
    if (D <= 0.0 || B <= 0.0)
        return;
    double k = steel_cord ? 12.0 : 9.0, base = steel_cord ? 200.0 : 140.0;
    *a = k * B * base * d / D;
    *b = k * 0.01 * d / D;
}

double bd_res_bearing(double d0, double D, double FT)
{
    if (D <= 0.0)
        return 0.0;
    return 0.005 * d0 / D * FT;
}
