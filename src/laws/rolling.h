/* Idler rolling (indentation) resistance, model-format.md
 * `rolling_resistance`: a force rr·f_n against the belt's motion over the
 * idler, DIN 22101's main resistance taken idler by idler (docs/physics.md
 * §5). It fades linearly to zero below BD_ROLLING_SPEED, so that a belt at
 * rest is not pushed; both belt formulations use it. */
#ifndef BD_ROLLING_H
#define BD_ROLLING_H

/* m/s */
#define BD_ROLLING_SPEED 0.01

/* a Coulomb force's share at speed v, faded linearly below `fade`:
 * v/fade clipped to ±1 */
static inline double bd_coulomb_share(double v, double fade)
{
    double sat = v / fade;
    return sat > 1.0 ? 1.0 : (sat < -1.0 ? -1.0 : sat);
}

/* the fade speed of a Coulomb force F on a body the explicit step moves
 * (mass, or inertia with lever² = R²): at least BD_ROLLING_SPEED, and no
 * steeper than a quarter of what the step bears, c·Δt/m ≤ 1/4 with
 * c = F·lever²/fade (central differences on a damper c alone are stable
 * for c·Δt/m < 2: the limit Δt ≤ (2/ω)(√(1 + ζ²) − ζ), seed 001 eq 6.1 damped,
 * docs/physics.md §3, for ζ → ∞ with 2ζω = c/m) */
static inline double bd_coulomb_fade(double F, double lever2, double dt, double mass)
{
    double f = 4.0 * F * lever2 * dt / mass;
    return f > BD_ROLLING_SPEED ? f : BD_ROLLING_SPEED;
}

#endif
