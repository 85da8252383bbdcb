/* The stability limit of explicit central differences (DESIGN.md; seed 001
 * eq 6.1 for ζ = 0): a mode of circular frequency ω (rad/s) and damping
 * ratio ζ is stable for Δt ≤ (2/ω)·(√(1+ζ²) − ζ). Each belt formulation
 * bounds its highest ω and that mode's ζ its own way, then asks this. */
#ifndef BD_STABLE_STEP_H
#define BD_STABLE_STEP_H

#include <math.h>

static inline double bd_central_difference_limit(double omega, double zeta)
{
    return 2.0 / omega * (sqrt(1.0 + zeta * zeta) - zeta);
}

#endif
