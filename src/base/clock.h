/* Wall-clock time, for progress reports (never for the simulation). */
#ifndef BD_CLOCK_H
#define BD_CLOCK_H

#include <time.h>

/* seconds on a monotonic clock */
static inline double bd_wall_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

#endif
