/* Constants every part of beltdyn shares (one definition of π). */
#ifndef BD_CONSTANTS_H
#define BD_CONSTANTS_H

#define BD_PI 3.14159265358979323846
#define BD_TWO_PI 6.283185307179586
/* radians per degree */
#define BD_DEG (BD_PI / 180.0)

#endif
