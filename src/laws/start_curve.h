/* Start and stop curves of a speed-controlled drive (start_curve.c). */
#ifndef BD_START_CURVE_H
#define BD_START_CURVE_H

#include "beltdyn/model.h"

/* target belt speed of a speed drive at time t (m/s): pre-start, start
 * curve, and a ramp stop */
double bd_start_curve_speed(const bd_drive_def *d, double t);

#endif
