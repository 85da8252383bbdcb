/* TEMPORARY until the loader lands */
#include "beltdyn/boom.h"
#include <stdlib.h>
#include <string.h>
void bd_boom_def_init(bd_boom_def *d)
{
    memset(d, 0, sizeof *d);
    d->gravity = 9.81; d->gap = 0.005; d->synchronized = 1; d->elements_per_segment = 8;
    d->damping_ratio = 0.01; d->pads.damping_ratio = 0.2; d->pads.smoothing = 1e-4;
    d->luffing_cylinder.stiffness = 1e9; d->telescopic_cylinder.stiffness = 1e8;
    d->telescopic_cylinder.damping_ratio = 0.2; d->ropes.axial_stiffness = 2e8;
    d->simulation.output_interval = 0.01; d->stroke.direction = 1;
}
void bd_boom_def_free(bd_boom_def *d)
{
    free(d->sections); bd_table_free(&d->luffing_angle); bd_table_free(&d->stroke.table);
    d->sections = NULL;
}
