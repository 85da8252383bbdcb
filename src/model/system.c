/* The system's warning list (system.h). */
#include "model/system.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
