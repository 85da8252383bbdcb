/* The secondary and special resistances of a belt conveyor one by one, as
 * ISO 5048:1989 §5.2 (Table 3) and DIN 22101 give them, as pure functions
 * of numbers in SI units. The static calculation (standards/) sums them;
 * the run applies them where they act (sim/pulley_resistance.c for the
 * pulleys, belt/common.c for the feed point). docs/standards.md lists each
 * with its clause. */
#ifndef BD_SECONDARY_RESISTANCE_H
#define BD_SECONDARY_RESISTANCE_H

/* inertia and friction at the loading point, F_bA = I_V·ρ·(v − v0)
 * (ISO 5048 Table 3), with I_V·ρ = m'_L·v the mass flow: material of
 * m'_L kg/m on a belt at v m/s, landing with v0 m/s along the belt */
double bd_res_loading_inertia(double mL, double v, double v0);

/* the acceleration length l_b = (v² − v0²)/(2·g·μ1) (ISO 5048 Table 3):
 * where the material slides on the belt until it has its speed */
double bd_res_acceleration_length(double v, double v0, double g, double mu1);

/* friction between the material and the skirt plates over a length l,
 * F = μ2·I_V²·ρ·g·l / (v_m²·b1²) (ISO 5048 Table 3): with v_m = (v + v0)/2
 * and l = l_b it is F_f (the acceleration zone), with v_m = v and l the
 * skirts' length F_gl (special resistance). mL kg/m on the belt at v,
 * rho kg/m³ bulk density, b1 m between the plates. */
double bd_res_skirt_friction(double mu2, double mL, double v, double v_m, double rho, double g,
                             double length, double b1);

/* belt cleaners, F_r = A·p·μ3 (ISO 5048 Table 3), A = count × width ×
 * thickness of contact */
double bd_res_cleaners(double count, double width, double thickness, double pressure,
                       double mu3);

/* wrap (bending) resistance of the belt over a pulley (ISO 5048 Table 3):
 * fabric carcass 9·B·(140 + 0.01·F/B)·d/D, steel cord 12·B·(200 + 0.01·F/B)·d/D,
 * B belt width (m), F the mean belt tension on the pulley (N), d belt
 * thickness (m), D pulley diameter (m); as F_l = a + b·F (the run takes F
 * as it changes): a = 9·140·B·d/D, b = 0.09·d/D (fabric), or
 * a = 12·200·B·d/D, b = 0.12·d/D (steel cord) */
void bd_res_wrap_coeffs(int steel_cord, double B, double d, double D, double *a, double *b);

/* pulley bearing resistance, F_t = 0.005·(d0/D)·F_T (ISO 5048 Table 3),
 * F_T the vector sum of the belt tensions on the pulley and the weight of
 * its rotating parts (N), d0 bearing diameter, D pulley diameter (m) */
double bd_res_bearing(double d0, double D, double FT);

#endif
