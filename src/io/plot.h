/* a small cairo plotting layer for the report: figures of one to three
 * stacked panels, each with labelled axes (quantity [unit]), ticks at round
 * numbers, line series with a legend strip above the panel, horizontal
 * reference lines, scatter series of dots, a filled band, point markers
 * with a label, and a colour
 * map (a raster image with a colour bar). The same drawing goes to a PNG
 * (pixels) and an SVG (points, the colour map embedded as one image). */
#ifndef BD_IO_PLOT_H
#define BD_IO_PLOT_H

#include <stddef.h>

typedef struct bd_rgb {
    double r, g, b;  /* 0..1 */
} bd_rgb;

typedef struct bd_plot_series {
    const double *x;    /* [n] abscissae (NaN breaks the line) */
    const double *y;    /* [n] ordinates (NaN breaks the line) */
    size_t n;
    const char *label;  /* legend text; NULL = not in the legend */
    bd_rgb color;
    double width;       /* line width, px; 0 = 2 */
    int dashed;         /* 1 = dashed */
    int points;         /* 1 = a dot at each point and no line (a scatter) */
} bd_plot_series;

/* a horizontal line across the panel at ordinate y */
typedef struct bd_plot_hline {
    double y;
    const char *label;  /* legend text */
    bd_rgb color;
    int dashed;
} bd_plot_hline;

/* the area between ylo and yhi, filled */
typedef struct bd_plot_band {
    const double *x, *ylo, *yhi;  /* [n] */
    size_t n;
    const char *label;            /* legend text; NULL = not in the legend */
    bd_rgb color;
    double alpha;                 /* fill opacity 0..1 */
} bd_plot_band;

/* a marked point with a text label beside it */
typedef struct bd_plot_marker {
    double x, y;
    const char *label;
} bd_plot_marker;

/* a place on the x axis marked by a thin vertical line and a short name
 * at the top of the panel (the pulleys on an s axis) */
typedef struct bd_plot_xmark {
    double x;
    const char *label;
} bd_plot_xmark;

/* a stretch of the x axis shaded over the panel's height; x1 < x0 wraps:
 * [x0, right edge] and [left edge, x1] (a region of a closed belt loop) */
typedef struct bd_plot_xspan {
    double x0, x1;
    const char *label;   /* legend text */
    bd_rgb color;
    double alpha;
} bd_plot_xspan;

/* a short text beside a data point */
typedef struct bd_plot_text {
    double x, y;
    const char *label;
} bd_plot_text;

/* a colour map: a raster of values over the data rectangle
 * [x0, x1] x [y0, y1]; row 0 is at y0 (the bottom of the panel) */
typedef struct bd_plot_map {
    const float *v;      /* [h][w] values; NaN = no data (drawn light grey) */
    int w, h;
    double x0, x1, y0, y1;
    double vmin, vmax;   /* colour bar range */
    const char *label;   /* colour bar label: quantity [unit] */
} bd_plot_map;

#define BD_PLOT_MAX_SERIES 12
#define BD_PLOT_MAX_HLINES 4
#define BD_PLOT_MAX_MARKERS 4
#define BD_PLOT_MAX_PANELS 4
#define BD_PLOT_MAX_XMARKS 32
#define BD_PLOT_MAX_TEXTS 32

typedef struct bd_plot_axes {
    const char *xlabel;           /* quantity [unit] */
    const char *ylabel;           /* quantity [unit] */
    bd_plot_series series[BD_PLOT_MAX_SERIES];
    int nseries;
    bd_plot_hline hlines[BD_PLOT_MAX_HLINES];
    int nhlines;
    bd_plot_band band;
    int has_band;
    bd_plot_marker markers[BD_PLOT_MAX_MARKERS];
    int nmarkers;
    bd_plot_xmark xmarks[BD_PLOT_MAX_XMARKS];
    int nxmarks;
    bd_plot_xspan xspan;
    int has_xspan;
    bd_plot_text texts[BD_PLOT_MAX_TEXTS];
    int ntexts;
    const bd_plot_map *map;       /* colour map, or NULL */
    int include_zero;             /* 1 = the y range includes 0 */
    double aspect;                /* > 0: px per y unit = aspect × px per x
                                     unit (1 = true shape; a drawing) */
} bd_plot_axes;

typedef struct bd_plot_figure {
    const char *title;
    const char *subtitle;         /* smaller second line, or NULL */
    int width, height;            /* px (PNG) = pt (SVG) */
    bd_plot_axes panel[BD_PLOT_MAX_PANELS];  /* stacked top to bottom */
    int npanels;
    int share_x;                  /* 1 = one x range, x labels on the bottom panel only */
} bd_plot_figure;

/* an empty figure of one panel */
void bd_plot_figure_init(bd_plot_figure *f, const char *title, int width, int height);

/* add a series to panel p; returns its index or -1 when full */
int bd_plot_add_series(bd_plot_axes *a, const double *x, const double *y, size_t n,
                       const char *label, bd_rgb color);
int bd_plot_add_hline(bd_plot_axes *a, double y, const char *label, bd_rgb color, int dashed);
int bd_plot_add_marker(bd_plot_axes *a, double x, double y, const char *label);
int bd_plot_add_xmark(bd_plot_axes *a, double x, const char *label);
int bd_plot_add_text(bd_plot_axes *a, double x, double y, const char *label);

/* size in px of panel p's plot area (where data is drawn) for this figure */
void bd_plot_area_size(const bd_plot_figure *f, int p, int *w, int *h);

/* draw the figure to png_path and svg_path (either may be NULL); each file
 * is written to a temporary name and renamed. Returns 0, or -1 + message */
int bd_plot_write(const bd_plot_figure *f, const char *png_path, const char *svg_path,
                  char *err, size_t errlen);

/* colour i of the line palette (distinct, colour-blind friendly) */
bd_rgb bd_plot_palette(int i);

/* the colour map's colour at u in [0, 1] (perceptually uniform, dark blue
 * to yellow) */
bd_rgb bd_plot_colormap(double u);

#endif
