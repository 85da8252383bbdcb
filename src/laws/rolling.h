/* Idler rolling (indentation) resistance, model-format.md
 * `rolling_resistance`: a force rr·f_n against the belt's motion over the
 * idler, DIN 22101's main resistance taken idler by idler (docs/physics.md
 * §5). It fades linearly to zero below BD_ROLLING_SPEED, so that a belt at
 * rest is not pushed; both belt formulations use it. */
#ifndef BD_ROLLING_H
#define BD_ROLLING_H

/* m/s */
#define BD_ROLLING_SPEED 0.01

#endif
