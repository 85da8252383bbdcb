/* The conveyor drawn from summary.json's "layout" (io/layout.c), and the
 * pulleys and loaded region marked on a plot's s axis (layout_plot.c) */
#ifndef BD_IO_LAYOUT_PLOT_H
#define BD_IO_LAYOUT_PLOT_H

#include <cjson/cJSON.h>
#include <stddef.h>

#include "io/plot.h"

/* the arrays and texts a layout figure draws from, owned until freed */
typedef struct bd_layout_drawing {
    double *x, *y, *loaded_y, *lifted_y;   /* [n] the belt path */
    size_t n;
    double px[3][BD_PLOT_MAX_TEXTS], py[3][BD_PLOT_MAX_TEXTS];  /* pulleys:
                                       plain, drive, takeup */
    int np[3];
    char names[BD_PLOT_MAX_TEXTS][64];
    char subtitle[160];
    char loaded_label[96], lifted_label[128];
    double exaggeration;   /* vertical scale over horizontal, 1 = true */
} bd_layout_drawing;

/* the layout figure's one panel from summary (its "layout" and
 * "lift_off"); 1 when drawn, 0 when summary has no layout, -1 out of
 * memory. d must be freed with bd_layout_drawing_free after the figure is
 * written. */
int bd_layout_figure(const cJSON *summary, bd_plot_figure *f, bd_layout_drawing *d);
void bd_layout_drawing_free(bd_layout_drawing *d);

/* pulleys (where the belt arrives on them) on an s axis, and the loaded
 * region shaded unless the panel is a colour map (whose colours are data);
 * nothing when summary has no layout */
void bd_layout_mark_s_axis(const cJSON *summary, bd_plot_axes *a);

#endif
