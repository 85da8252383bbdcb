/* The system's node arrays and warning list (system.h). */
#include "model/system.h"

#include <stddef.h>

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"

void bd_sim_warn(bd_sim *sim, const char *fmt, ...)
{
    char buf[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    for (int i = 0; i < sim->warning_count; i++)
        if (strcmp(sim->warnings[i], buf) == 0)
            return;
    char **w = realloc(sim->warnings, (size_t)(sim->warning_count + 1) * sizeof *w);
    if (!w)
        return;
    sim->warnings = w;
    sim->warnings[sim->warning_count] = malloc(strlen(buf) + 1);
    if (sim->warnings[sim->warning_count]) {
        strcpy(sim->warnings[sim->warning_count], buf);
        sim->warning_count++;
    }
}

/* every [n] array of the state, named once */
static const size_t NODE_ARRAYS[] = {
    offsetof(bd_sim, x),    offsetof(bd_sim, y),        offsetof(bd_sim, vx),
    offsetof(bd_sim, vy),   offsetof(bd_sim, fx),       offsetof(bd_sim, fy),
    offsetof(bd_sim, fnx),  offsetof(bd_sim, fny),      offsetof(bd_sim, mass),
    offsetof(bd_sim, material), offsetof(bd_sim, tension), offsetof(bd_sim, dt_per_mass)};
#define NODE_ARRAY_COUNT ((int)(sizeof NODE_ARRAYS / sizeof NODE_ARRAYS[0]))

void bd_node_arrays_alloc(bd_sim *sim)
{
    bd_doubles_alloc(sim, NODE_ARRAYS, NODE_ARRAY_COUNT, (size_t)sim->model->n);
}

size_t bd_node_arrays_bytes(void)
{
    return (size_t)NODE_ARRAY_COUNT * sizeof(double);
}

void bd_node_arrays_dup(bd_sim *dst, const bd_sim *src)
{
    bd_doubles_dup(dst, src, NODE_ARRAYS, NODE_ARRAY_COUNT, (size_t)src->model->n);
}

void bd_node_arrays_free(bd_sim *sim)
{
    bd_doubles_free(sim, NODE_ARRAYS, NODE_ARRAY_COUNT);
}
