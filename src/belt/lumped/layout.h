/* Initial belt layout (layout.c): node path coordinates and element
 * tensions of the at-rest state, see the comment at the top of layout.c. */
#ifndef BD_LAYOUT_H
#define BD_LAYOUT_H

#include <stddef.h>
#include <stdio.h>

#include "beltdyn/model.h"
#include "model/path.h"
#include "model/rest_weight.h"

typedef struct bd_layout_request {
    const bd_path *path;     /* the path of the model as given */
    double target_length;    /* m, target element length */
} bd_layout_request;

typedef struct bd_layout {
    int n;                   /* elements = nodes */
    double l0;               /* m, unstretched element length */
    double level;            /* N, tension constant T_c */
    int takeup;              /* pulley index setting the level, or -1 */
    double takeup_shift;     /* m the takeup pulley moved along its axis */
    bd_path path;            /* the path the belt was laid on (shifted) */
    double *s;               /* [n] path coordinate of node i */
    double *tension;         /* [n] N in element i */
} bd_layout;

int bd_layout_belt(const bd_model_def *def, const bd_layout_request *req, bd_layout *out,
                   char *err, size_t errlen);
void bd_layout_free(bd_layout *l);
/* belt and material at rest on path: the material from the feed point to
 * where the belt reaches the discharge pulley, when the belt starts loaded */
bd_rest_load bd_layout_rest_load(const bd_model_def *def, const bd_path *path);

#endif
