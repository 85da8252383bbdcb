/* cairo plotting layer: layout, axes, ticks, lines, legend, colour map */
#include "io/plot.h"
#include "base/constants.h"

#include <cairo.h>
#include <cairo-svg.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FONT "DejaVu Sans"
#define FS_TITLE 20.0
#define FS_SUB 14.0
#define FS_LABEL 15.0
#define FS_TICK 13.0
#define FS_LEGEND 13.0
#define LEGEND_ROW 20.0
#define MAX_TICKS 16
#define LONG_MIN_GUARD LONG_MIN

static const bd_rgb grid_rgb = {0.88, 0.88, 0.88};
static const bd_rgb frame_rgb = {0.25, 0.25, 0.25};
static const bd_rgb text_rgb = {0.10, 0.10, 0.10};

bd_rgb bd_plot_palette(int i)
{
    /* Okabe-Ito, reordered for contrast on white */
    static const bd_rgb pal[8] = {
        {0.000, 0.447, 0.698}, {0.835, 0.369, 0.000}, {0.000, 0.620, 0.451},
        {0.800, 0.475, 0.655}, {0.337, 0.706, 0.914}, {0.902, 0.624, 0.000},
        {0.000, 0.000, 0.000}, {0.941, 0.894, 0.259}};
    if (i < 0) i = -i;
    return pal[i % 8];
}

bd_rgb bd_plot_colormap(double u)
{
    /* viridis, sampled at 1/8 steps, linear in between */
    static const double k[9][3] = {
        {0.267, 0.005, 0.329}, {0.283, 0.141, 0.458}, {0.254, 0.265, 0.530},
        {0.207, 0.372, 0.553}, {0.164, 0.471, 0.558}, {0.128, 0.567, 0.551},
        {0.135, 0.659, 0.518}, {0.267, 0.749, 0.441}, {0.993, 0.906, 0.144}};
    /* the last interval of viridis bends through green-yellow: add it */
    static const double k8[3] = {0.478, 0.821, 0.318};
    bd_rgb c;
    if (!(u > 0.0)) u = 0.0;
    if (u > 1.0) u = 1.0;
    double x = u * 8.0;
    int i = (int)floor(x);
    if (i >= 8) i = 7;
    double f = x - (double)i;
    const double *a = k[i], *b = k[i + 1];
    if (i == 7) {
        /* two half-intervals: k[7] -> k8 -> k[8] */
        if (f < 0.5) {
            b = k8;
            f *= 2.0;
        } else {
            a = k8;
            f = 2.0 * f - 1.0;
        }
    }
    c.r = a[0] + (b[0] - a[0]) * f;
    c.g = a[1] + (b[1] - a[1]) * f;
    c.b = a[2] + (b[2] - a[2]) * f;
    return c;
}

void bd_plot_figure_init(bd_plot_figure *f, const char *title, int width, int height)
{
    memset(f, 0, sizeof *f);
    f->title = title;
    f->width = width;
    f->height = height;
    f->npanels = 1;
}

int bd_plot_add_series(bd_plot_axes *a, const double *x, const double *y, size_t n,
                       const char *label, bd_rgb color)
{
    if (a->nseries >= BD_PLOT_MAX_SERIES) return -1;
    bd_plot_series *s = &a->series[a->nseries];
    memset(s, 0, sizeof *s);
    s->x = x;
    s->y = y;
    s->n = n;
    s->label = label;
    s->color = color;
    return a->nseries++;
}

int bd_plot_add_hline(bd_plot_axes *a, double y, const char *label, bd_rgb color, int dashed)
{
    if (a->nhlines >= BD_PLOT_MAX_HLINES || !isfinite(y)) return -1;
    bd_plot_hline *h = &a->hlines[a->nhlines];
    h->y = y;
    h->label = label;
    h->color = color;
    h->dashed = dashed;
    return a->nhlines++;
}

int bd_plot_add_marker(bd_plot_axes *a, double x, double y, const char *label)
{
    if (a->nmarkers >= BD_PLOT_MAX_MARKERS || !isfinite(x) || !isfinite(y)) return -1;
    a->markers[a->nmarkers].x = x;
    a->markers[a->nmarkers].y = y;
    a->markers[a->nmarkers].label = label;
    return a->nmarkers++;
}

int bd_plot_add_xmark(bd_plot_axes *a, double x, const char *label)
{
    if (a->nxmarks >= BD_PLOT_MAX_XMARKS || !isfinite(x)) return -1;
    a->xmarks[a->nxmarks] = (bd_plot_xmark){x, label};
    return a->nxmarks++;
}

int bd_plot_add_text(bd_plot_axes *a, double x, double y, const char *label)
{
    if (a->ntexts >= BD_PLOT_MAX_TEXTS || !isfinite(x) || !isfinite(y)) return -1;
    a->texts[a->ntexts] = (bd_plot_text){x, y, label};
    return a->ntexts++;
}

/* ---- ranges and ticks ---- */

typedef struct range {
    double lo, hi;
} range;

typedef struct ticks {
    int n;
    double v[MAX_TICKS];
    double step;
} ticks;

static void range_add(range *r, double v)
{
    if (!isfinite(v)) return;
    if (v < r->lo) r->lo = v;
    if (v > r->hi) r->hi = v;
}

static double nice_step(double span, int target)
{
    double raw = span / (double)target;
    double mag = pow(10.0, floor(log10(raw)));
    double f = raw / mag;
    double nice = f < 1.5 ? 1.0 : f < 3.0 ? 2.0 : f < 7.0 ? 5.0 : 10.0;
    return nice * mag;
}

/* ticks at multiples of a round step inside [lo, hi] */
static ticks make_ticks(range r, int target)
{
    ticks t;
    t.n = 0;
    t.step = nice_step(r.hi - r.lo, target);
    double first = ceil(r.lo / t.step - 1e-9) * t.step;
    for (int i = 0; i < MAX_TICKS; i++) {
        double v = first + (double)i * t.step;
        if (v > r.hi + 1e-9 * t.step) break;
        if (fabs(v) < 1e-12 * t.step) v = 0.0;
        t.v[t.n++] = v;
    }
    return t;
}

static void format_tick(char *buf, size_t len, double v, double step)
{
    double a = fabs(step);
    if (a >= 1e6 || (a < 1e-3 && a > 0.0)) {
        snprintf(buf, len, "%.3g", v);
        return;
    }
    int dec = a >= 1.0 ? 0 : (int)ceil(-log10(a) - 1e-9);
    if (dec > 6) dec = 6;
    snprintf(buf, len, "%.*f", dec, v);
}

/* the data range of a panel's x or y values */
static range axes_range(const bd_plot_axes *a, int want_y)
{
    range r = {INFINITY, -INFINITY};
    for (int i = 0; i < a->nseries; i++) {
        const double *v = want_y ? a->series[i].y : a->series[i].x;
        for (size_t k = 0; k < a->series[i].n; k++) range_add(&r, v[k]);
    }
    if (a->has_band) {
        for (size_t k = 0; k < a->band.n; k++) {
            if (want_y) {
                range_add(&r, a->band.ylo[k]);
                range_add(&r, a->band.yhi[k]);
            } else {
                range_add(&r, a->band.x[k]);
            }
        }
    }
    if (want_y)
        for (int i = 0; i < a->nhlines; i++) range_add(&r, a->hlines[i].y);
    for (int i = 0; i < a->nmarkers; i++) range_add(&r, want_y ? a->markers[i].y : a->markers[i].x);
    if (a->map) {
        range_add(&r, want_y ? a->map->y0 : a->map->x0);
        range_add(&r, want_y ? a->map->y1 : a->map->x1);
    }
    if (want_y && a->include_zero) range_add(&r, 0.0);
    if (!(r.lo <= r.hi)) {
        r.lo = 0.0;
        r.hi = 1.0;
    }
    if (r.hi - r.lo <= 1e-12 * fmax(fabs(r.lo), fabs(r.hi))) {
        double d = fabs(r.lo) > 0.0 ? 0.1 * fabs(r.lo) : 1.0;
        r.lo -= d;
        r.hi += d;
    }
    return r;
}

/* y: pad by 5 % and widen to whole tick steps (never for a colour map,
 * whose extent is exact) */
static range pad_y(const bd_plot_axes *a, range r)
{
    if (a->map) return r;
    double pad = 0.05 * (r.hi - r.lo);
    range p = {r.lo - pad, r.hi + pad};
    if (a->aspect > 0.0) return p;   /* a drawing: the aspect sets the rest */
    double step = nice_step(p.hi - p.lo, 6);
    p.lo = floor(p.lo / step + 1e-9) * step;
    p.hi = ceil(p.hi / step - 1e-9) * step;
    /* data that never crosses zero does not get an axis that does */
    if (r.lo >= 0.0 && p.lo < 0.0) p.lo = r.lo - 0.5 * pad;
    if (r.hi <= 0.0 && p.hi > 0.0) p.hi = r.hi + 0.5 * pad;
    return p;
}

/* ---- layout ---- */

typedef struct layout {
    double left, right;               /* plot area x extent, px */
    double top[BD_PLOT_MAX_PANELS];   /* plot area y extent, px */
    double bottom[BD_PLOT_MAX_PANELS];
    double legend_top[BD_PLOT_MAX_PANELS];
    range xr[BD_PLOT_MAX_PANELS], yr[BD_PLOT_MAX_PANELS];
    ticks xt[BD_PLOT_MAX_PANELS], yt[BD_PLOT_MAX_PANELS];
    int has_map;
    double cbar_x;                    /* colour bar left edge */
} layout;

static void set_font(cairo_t *cr, double size, int bold)
{
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}

static double text_width(cairo_t *cr, const char *s)
{
    cairo_text_extents_t e;
    cairo_text_extents(cr, s, &e);
    return e.x_advance;
}

typedef struct legend_item {
    const char *label;
    bd_rgb color;
    int kind;     /* 0 line, 1 dashed line, 2 filled box, 3 dot, 4 solid box (a bar) */
    double width;
} legend_item;

static int legend_items(const bd_plot_axes *a, legend_item *items, int max)
{
    int n = 0;
    if (a->has_band && a->band.label && n < max)
        items[n++] = (legend_item){a->band.label, a->band.color, 2, 0.0};
    if (a->has_xspan && a->xspan.label && n < max)
        items[n++] = (legend_item){a->xspan.label, a->xspan.color, 2, 0.0};
    for (int i = 0; i < a->nseries && n < max; i++)
        if (a->series[i].label)
            items[n++] = (legend_item){a->series[i].label, a->series[i].color,
                                       a->series[i].points ? 3
                                       : a->series[i].width > 8.0 ? 4 : a->series[i].dashed,
                                       a->series[i].width};
    for (int i = 0; i < a->nhlines && n < max; i++)
        if (a->hlines[i].label)
            items[n++] = (legend_item){a->hlines[i].label, a->hlines[i].color,
                                       a->hlines[i].dashed, 2.0};
    return n;
}

#define LEGEND_SAMPLE 28.0
#define LEGEND_GAP 22.0

/* rows the legend needs in a strip of the given width */
static int legend_rows(cairo_t *cr, const bd_plot_axes *a, double width)
{
    legend_item items[BD_PLOT_MAX_SERIES + BD_PLOT_MAX_HLINES + 2];
    int n = legend_items(a, items, (int)(sizeof items / sizeof items[0]));
    if (n == 0) return 0;
    set_font(cr, FS_LEGEND, 0);
    int rows = 1;
    double x = 0.0;
    for (int i = 0; i < n; i++) {
        double w = LEGEND_SAMPLE + 6.0 + text_width(cr, items[i].label);
        if (x > 0.0 && x + w > width) {
            rows++;
            x = 0.0;
        }
        x += w + LEGEND_GAP;
    }
    return rows;
}

static void compute_layout(cairo_t *cr, const bd_plot_figure *f, layout *L)
{
    int np = f->npanels < 1 ? 1 : f->npanels > BD_PLOT_MAX_PANELS ? BD_PLOT_MAX_PANELS : f->npanels;
    double W = (double)f->width, H = (double)f->height;
    memset(L, 0, sizeof *L);

    /* ranges and ticks first: the tick labels set the left margin */
    range shared = {INFINITY, -INFINITY};
    for (int p = 0; p < np; p++) {
        L->xr[p] = axes_range(&f->panel[p], 0);
        L->yr[p] = pad_y(&f->panel[p], axes_range(&f->panel[p], 1));
        range_add(&shared, L->xr[p].lo);
        range_add(&shared, L->xr[p].hi);
        if (f->panel[p].map) L->has_map = 1;
    }
    double ylabel_w = 0.0;
    set_font(cr, FS_TICK, 0);
    for (int p = 0; p < np; p++) {
        if (f->share_x) L->xr[p] = shared;
        L->xt[p] = make_ticks(L->xr[p], 8);
        L->yt[p] = make_ticks(L->yr[p], np > 1 ? 4 : 6);
        for (int i = 0; i < L->yt[p].n; i++) {
            char buf[64];
            format_tick(buf, sizeof buf, L->yt[p].v[i], L->yt[p].step);
            ylabel_w = fmax(ylabel_w, text_width(cr, buf));
        }
    }
    L->left = 16.0 + FS_LABEL + 12.0 + ylabel_w + 8.0;
    double right_margin = 24.0;
    if (L->has_map) {
        double cw = 0.0;
        for (int p = 0; p < np; p++) {
            const bd_plot_map *m = f->panel[p].map;
            if (!m) continue;
            ticks ct = make_ticks((range){m->vmin, m->vmax}, 6);
            for (int i = 0; i < ct.n; i++) {
                char buf[64];
                format_tick(buf, sizeof buf, ct.v[i], ct.step);
                cw = fmax(cw, text_width(cr, buf));
            }
        }
        right_margin = 20.0 + 22.0 + 8.0 + cw + 12.0 + FS_LABEL + 16.0;
    }
    L->right = W - right_margin;
    L->cbar_x = L->right + 20.0;

    /* vertical: title, then per panel legend strip + plot area, then the
     * x tick labels and x label */
    double title_h = f->title ? 42.0 : 12.0;
    if (f->subtitle) title_h += 20.0;
    double xaxis_h = 8.0 + FS_TICK + 10.0 + FS_LABEL + 12.0;
    double used = title_h, legend_h[BD_PLOT_MAX_PANELS];
    for (int p = 0; p < np; p++) {
        int rows = legend_rows(cr, &f->panel[p], L->right - L->left);
        legend_h[p] = rows > 0 ? (double)rows * LEGEND_ROW + 8.0 : 10.0;
        used += legend_h[p];
        if (!f->share_x || p == np - 1) used += xaxis_h;
        else used += 6.0;
    }
    double ph = (H - used) / (double)np;
    if (ph < 40.0) ph = 40.0;
    double y = title_h;
    for (int p = 0; p < np; p++) {
        L->legend_top[p] = y;
        y += legend_h[p];
        L->top[p] = y;
        y += ph;
        L->bottom[p] = y;
        y += (!f->share_x || p == np - 1) ? xaxis_h : 6.0;
    }
    /* a drawing: widen the y or the x range about its middle until a unit
     * of y is `aspect` times as long as a unit of x */
    for (int p = 0; p < np; p++) {
        double aspect = f->panel[p].aspect;
        if (aspect <= 0.0) continue;
        double w = L->right - L->left, h = L->bottom[p] - L->top[p];
        range *xr = &L->xr[p], *yr = &L->yr[p];
        double xpad = 0.02 * (xr->hi - xr->lo);
        xr->lo -= xpad;
        xr->hi += xpad;
        double ppx = w / (xr->hi - xr->lo);           /* px per x unit */
        double yspan = h / (aspect * ppx);              /* y shown at that scale */
        if (yspan >= yr->hi - yr->lo) {
            double mid = 0.5 * (yr->lo + yr->hi);
            *yr = (range){mid - 0.5 * yspan, mid + 0.5 * yspan};
        } else {
            double xspan = w * aspect * (yr->hi - yr->lo) / h;
            double mid = 0.5 * (xr->lo + xr->hi);
            *xr = (range){mid - 0.5 * xspan, mid + 0.5 * xspan};
        }
        L->xt[p] = make_ticks(*xr, 8);
        L->yt[p] = make_ticks(*yr, np > 1 ? 4 : 6);
    }
}

void bd_plot_area_size(const bd_plot_figure *f, int p, int *w, int *h)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 4, 4);
    cairo_t *cr = cairo_create(s);
    layout L;
    compute_layout(cr, f, &L);
    if (p < 0) p = 0;
    if (p >= BD_PLOT_MAX_PANELS) p = BD_PLOT_MAX_PANELS - 1;
    *w = (int)lround(L.right - L.left);
    *h = (int)lround(L.bottom[p] - L.top[p]);
    cairo_destroy(cr);
    cairo_surface_destroy(s);
}

/* ---- drawing ---- */

static void set_rgb(cairo_t *cr, bd_rgb c) { cairo_set_source_rgb(cr, c.r, c.g, c.b); }

typedef struct xform {
    double x0, x1, y0, y1;    /* px */
    double dx0, dx1, dy0, dy1;  /* data */
} xform;

static double px(const xform *t, double x) { return t->x0 + (x - t->dx0) / (t->dx1 - t->dx0) * (t->x1 - t->x0); }
static double py(const xform *t, double y) { return t->y1 - (y - t->dy0) / (t->dy1 - t->dy0) * (t->y1 - t->y0); }

/* draw text with its anchor: ax, ay in {0, 0.5, 1} of its box */
static void draw_text(cairo_t *cr, double x, double y, double ax, double ay, const char *s)
{
    cairo_text_extents_t e;
    cairo_font_extents_t fe;
    cairo_text_extents(cr, s, &e);
    cairo_font_extents(cr, &fe);
    double h = fe.ascent * 0.78;  /* cap height, roughly */
    cairo_move_to(cr, x - ax * e.x_advance, y + (1.0 - ay) * h);
    cairo_show_text(cr, s);
}

static void draw_line_series(cairo_t *cr, const xform *t, const bd_plot_series *s)
{
    if (s->n == 0) return;
    set_rgb(cr, s->color);
    if (s->points) {
        for (size_t k = 0; k < s->n; k++) {
            if (!isfinite(s->x[k]) || !isfinite(s->y[k])) continue;
            cairo_new_path(cr);
            cairo_arc(cr, px(t, s->x[k]), py(t, s->y[k]), 3.5, 0.0, 2.0 * BD_PI);
            cairo_fill(cr);
        }
        return;
    }
    cairo_set_line_width(cr, s->width > 0.0 ? s->width : 2.0);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    if (s->dashed) {
        double d[2] = {8.0, 5.0};
        cairo_set_dash(cr, d, 2, 0.0);
    } else {
        cairo_set_dash(cr, NULL, 0, 0.0);
    }
    /* many points per pixel column (x increasing): draw each column's
     * min..max once, which looks the same and keeps the SVG small */
    double width_px = t->x1 - t->x0;
    int mono = 1;
    for (size_t k = 1; k < s->n && mono; k++)
        if (s->x[k] < s->x[k - 1]) mono = 0;
    int pen = 0;
    if (mono && (double)s->n > 3.0 * width_px) {
        long col = LONG_MIN_GUARD;
        double lo = 0.0, hi = 0.0, first = 0.0, last = 0.0;
        for (size_t k = 0; k <= s->n; k++) {
            int valid = k < s->n && isfinite(s->x[k]) && isfinite(s->y[k]);
            long c = valid ? (long)floor(px(t, s->x[k])) : LONG_MIN_GUARD;
            if (col != LONG_MIN_GUARD && (c != col || !valid)) {
                /* flush the column: enter at first, span lo..hi, leave at last */
                double X = (double)col + 0.5;
                if (!pen) cairo_move_to(cr, X, py(t, first));
                else cairo_line_to(cr, X, py(t, first));
                cairo_line_to(cr, X, py(t, lo));
                cairo_line_to(cr, X, py(t, hi));
                cairo_line_to(cr, X, py(t, last));
                pen = 1;
                if (!valid) pen = 0;
                col = LONG_MIN_GUARD;
            }
            if (!valid) continue;
            double v = s->y[k];
            if (col == LONG_MIN_GUARD) {
                col = c;
                lo = hi = first = last = v;
            } else {
                lo = fmin(lo, v);
                hi = fmax(hi, v);
                last = v;
            }
        }
    } else {
        for (size_t k = 0; k < s->n; k++) {
            if (!isfinite(s->x[k]) || !isfinite(s->y[k])) {
                pen = 0;
                continue;
            }
            double X = px(t, s->x[k]), Y = py(t, s->y[k]);
            if (!pen) cairo_move_to(cr, X, Y);
            else cairo_line_to(cr, X, Y);
            pen = 1;
        }
        /* a single point: draw a dot */
        if (s->n == 1 && isfinite(s->x[0]) && isfinite(s->y[0])) {
            cairo_new_path(cr);
            cairo_arc(cr, px(t, s->x[0]), py(t, s->y[0]), 3.0, 0.0, 2.0 * BD_PI);
            cairo_fill(cr);
        }
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0.0);
}

static void draw_band(cairo_t *cr, const xform *t, const bd_plot_band *b)
{
    /* fill each run of finite points separately */
    size_t k = 0;
    cairo_set_source_rgba(cr, b->color.r, b->color.g, b->color.b, b->alpha);
    while (k < b->n) {
        while (k < b->n && !(isfinite(b->x[k]) && isfinite(b->ylo[k]) && isfinite(b->yhi[k]))) k++;
        size_t a = k;
        while (k < b->n && isfinite(b->x[k]) && isfinite(b->ylo[k]) && isfinite(b->yhi[k])) k++;
        if (k - a < 2) continue;
        cairo_move_to(cr, px(t, b->x[a]), py(t, b->yhi[a]));
        for (size_t i = a + 1; i < k; i++) cairo_line_to(cr, px(t, b->x[i]), py(t, b->yhi[i]));
        for (size_t i = k; i-- > a;) cairo_line_to(cr, px(t, b->x[i]), py(t, b->ylo[i]));
        cairo_close_path(cr);
        cairo_fill(cr);
    }
}

static cairo_surface_t *map_image(const bd_plot_map *m)
{
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, m->w, m->h);
    if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) return img;
    cairo_surface_flush(img);
    unsigned char *data = cairo_image_surface_get_data(img);
    int stride = cairo_image_surface_get_stride(img);
    /* 256-entry lookup of the colour map */
    uint32_t lut[256];
    for (int i = 0; i < 256; i++) {
        bd_rgb c = bd_plot_colormap((double)i / 255.0);
        lut[i] = ((uint32_t)lround(c.r * 255.0) << 16) | ((uint32_t)lround(c.g * 255.0) << 8) |
                 (uint32_t)lround(c.b * 255.0);
    }
    double span = m->vmax - m->vmin;
    double scale = span > 0.0 ? 255.0 / span : 0.0;
    for (int r = 0; r < m->h; r++) {
        /* row 0 of the data is the bottom of the image */
        uint32_t *row = (uint32_t *)(void *)(data + (size_t)(m->h - 1 - r) * (size_t)stride);
        const float *v = m->v + (size_t)r * (size_t)m->w;
        for (int c = 0; c < m->w; c++) {
            double x = (double)v[c];
            if (!isfinite(x)) {
                row[c] = 0xECECECu;
                continue;
            }
            double u = (x - m->vmin) * scale;
            int i = u <= 0.0 ? 0 : u >= 255.0 ? 255 : (int)(u + 0.5);
            row[c] = lut[i];
        }
    }
    cairo_surface_mark_dirty(img);
    return img;
}

static void draw_map(cairo_t *cr, const xform *t, const bd_plot_map *m)
{
    cairo_surface_t *img = map_image(m);
    if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(img);
        return;
    }
    double X0 = px(t, m->x0), X1 = px(t, m->x1), Y0 = py(t, m->y1), Y1 = py(t, m->y0);
    cairo_save(cr);
    cairo_rectangle(cr, X0, Y0, X1 - X0, Y1 - Y0);
    cairo_clip(cr);
    cairo_translate(cr, X0, Y0);
    cairo_scale(cr, (X1 - X0) / (double)m->w, (Y1 - Y0) / (double)m->h);
    cairo_set_source_surface(cr, img, 0.0, 0.0);
    int same = fabs(X1 - X0 - (double)m->w) < 1.0 && fabs(Y1 - Y0 - (double)m->h) < 1.0;
    cairo_pattern_set_filter(cairo_get_source(cr), same ? CAIRO_FILTER_NEAREST : CAIRO_FILTER_GOOD);
    cairo_pattern_set_extend(cairo_get_source(cr), CAIRO_EXTEND_PAD);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_surface_destroy(img);
}

static void draw_colorbar(cairo_t *cr, const layout *L, int p, const bd_plot_map *m)
{
    double x = L->cbar_x, w = 22.0, top = L->top[p], bot = L->bottom[p];
    /* the bar: a 1 x 256 image stretched */
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 256);
    cairo_surface_flush(img);
    unsigned char *data = cairo_image_surface_get_data(img);
    int stride = cairo_image_surface_get_stride(img);
    for (int i = 0; i < 256; i++) {
        bd_rgb c = bd_plot_colormap((double)(255 - i) / 255.0);
        *(uint32_t *)(void *)(data + (size_t)i * (size_t)stride) =
            ((uint32_t)lround(c.r * 255.0) << 16) | ((uint32_t)lround(c.g * 255.0) << 8) |
            (uint32_t)lround(c.b * 255.0);
    }
    cairo_surface_mark_dirty(img);
    cairo_save(cr);
    cairo_rectangle(cr, x, top, w, bot - top);
    cairo_clip(cr);
    cairo_translate(cr, x, top);
    cairo_scale(cr, w, (bot - top) / 256.0);
    cairo_set_source_surface(cr, img, 0.0, 0.0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_BILINEAR);
    cairo_pattern_set_extend(cairo_get_source(cr), CAIRO_EXTEND_PAD);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_surface_destroy(img);

    set_rgb(cr, frame_rgb);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, x + 0.5, top + 0.5, w, bot - top);
    cairo_stroke(cr);

    /* ticks and labels on the right */
    ticks ct = make_ticks((range){m->vmin, m->vmax}, 6);
    set_font(cr, FS_TICK, 0);
    double maxw = 0.0;
    for (int i = 0; i < ct.n; i++) {
        double Y = bot - (ct.v[i] - m->vmin) / (m->vmax - m->vmin) * (bot - top);
        char buf[64];
        format_tick(buf, sizeof buf, ct.v[i], ct.step);
        cairo_move_to(cr, x + w, Y);
        cairo_line_to(cr, x + w + 5.0, Y);
        cairo_stroke(cr);
        set_rgb(cr, text_rgb);
        draw_text(cr, x + w + 8.0, Y, 0.0, 0.5, buf);
        set_rgb(cr, frame_rgb);
        maxw = fmax(maxw, text_width(cr, buf));
    }
    if (m->label) {
        set_font(cr, FS_LABEL, 0);
        set_rgb(cr, text_rgb);
        cairo_save(cr);
        cairo_translate(cr, x + w + 8.0 + maxw + 12.0 + FS_LABEL * 0.8, 0.5 * (top + bot));
        cairo_rotate(cr, -BD_PI / 2.0);
        draw_text(cr, 0.0, 0.0, 0.5, 0.5, m->label);
        cairo_restore(cr);
    }
}

static void draw_legend(cairo_t *cr, const layout *L, int p, const bd_plot_axes *a)
{
    legend_item items[BD_PLOT_MAX_SERIES + BD_PLOT_MAX_HLINES + 2];
    int n = legend_items(a, items, (int)(sizeof items / sizeof items[0]));
    if (n == 0) return;
    set_font(cr, FS_LEGEND, 0);
    double x = L->left, y = L->legend_top[p] + LEGEND_ROW * 0.5 + 2.0;
    double width = L->right - L->left;
    for (int i = 0; i < n; i++) {
        double w = LEGEND_SAMPLE + 6.0 + text_width(cr, items[i].label);
        if (x > L->left && x + w > L->left + width) {
            x = L->left;
            y += LEGEND_ROW;
        }
        if (items[i].kind == 2) {
            cairo_set_source_rgba(cr, items[i].color.r, items[i].color.g, items[i].color.b, 0.35);
            cairo_rectangle(cr, x, y - 6.0, LEGEND_SAMPLE, 12.0);
            cairo_fill(cr);
        } else if (items[i].kind == 4) {
            set_rgb(cr, items[i].color);
            cairo_rectangle(cr, x + 4.0, y - 6.0, LEGEND_SAMPLE - 8.0, 12.0);
            cairo_fill(cr);
        } else if (items[i].kind == 3) {
            set_rgb(cr, items[i].color);
            cairo_new_path(cr);
            cairo_arc(cr, x + 0.5 * LEGEND_SAMPLE, y, 3.5, 0.0, 2.0 * BD_PI);
            cairo_fill(cr);
        } else {
            set_rgb(cr, items[i].color);
            cairo_set_line_width(cr, items[i].width > 0.0 ? items[i].width + 0.5 : 2.5);
            if (items[i].kind == 1) {
                double d[2] = {6.0, 4.0};
                cairo_set_dash(cr, d, 2, 0.0);
            }
            cairo_move_to(cr, x, y);
            cairo_line_to(cr, x + LEGEND_SAMPLE, y);
            cairo_stroke(cr);
            cairo_set_dash(cr, NULL, 0, 0.0);
        }
        set_rgb(cr, text_rgb);
        draw_text(cr, x + LEGEND_SAMPLE + 6.0, y, 0.0, 0.5, items[i].label);
        x += w + LEGEND_GAP;
    }
}

static void draw_marker(cairo_t *cr, const xform *t, const bd_plot_marker *m)
{
    double X = px(t, m->x), Y = py(t, m->y);
    /* a ring visible on any colour: black outside, white inside */
    cairo_new_path(cr);
    cairo_set_line_width(cr, 4.0);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_arc(cr, X, Y, 8.0, 0.0, 2.0 * BD_PI);
    cairo_stroke(cr);
    cairo_set_line_width(cr, 2.0);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_arc(cr, X, Y, 8.0, 0.0, 2.0 * BD_PI);
    cairo_stroke(cr);
    if (!m->label) return;
    /* the label in a white box, on the side with room */
    set_font(cr, FS_LEGEND, 1);
    double w = text_width(cr, m->label), h = FS_LEGEND + 8.0;
    double bx = X + 14.0, by = Y - h - 6.0;
    if (bx + w + 10.0 > t->x1) bx = X - 14.0 - w - 10.0;
    if (bx < t->x0) bx = t->x0 + 2.0;
    if (by < t->y0) by = Y + 10.0;
    cairo_new_path(cr);
    cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, 0.9);
    cairo_rectangle(cr, bx, by, w + 10.0, h);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_set_line_width(cr, 1.0);
    cairo_stroke(cr);
    draw_text(cr, bx + 5.0, by + 0.5 * h, 0.0, 0.5, m->label);
}

static void draw_xspan(cairo_t *cr, const xform *t, const bd_plot_xspan *x)
{
    cairo_set_source_rgba(cr, x->color.r, x->color.g, x->color.b, x->alpha);
    if (x->x1 >= x->x0) {
        cairo_rectangle(cr, px(t, x->x0), t->y0, px(t, x->x1) - px(t, x->x0), t->y1 - t->y0);
    } else {   /* wraps round the loop's end */
        cairo_rectangle(cr, px(t, x->x0), t->y0, t->x1 - px(t, x->x0), t->y1 - t->y0);
        cairo_rectangle(cr, t->x0, t->y0, px(t, x->x1) - t->x0, t->y1 - t->y0);
    }
    cairo_fill(cr);
}

/* thin dotted lines with their names written upward from the top */
static void draw_xmarks(cairo_t *cr, const xform *t, const bd_plot_axes *a)
{
    set_font(cr, FS_TICK - 2.0, 0);
    for (int i = 0; i < a->nxmarks; i++) {
        double X = floor(px(t, a->xmarks[i].x)) + 0.5;
        if (X < t->x0 || X > t->x1) continue;
        double d[2] = {2.0, 3.0};
        cairo_set_dash(cr, d, 2, 0.0);
        cairo_set_line_width(cr, 1.0);
        cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
        cairo_move_to(cr, X, t->y0);
        cairo_line_to(cr, X, t->y1);
        cairo_stroke(cr);
        cairo_set_dash(cr, NULL, 0, 0.0);
        if (!a->xmarks[i].label) continue;
        cairo_save(cr);
        cairo_translate(cr, X - 3.0, t->y0 + 4.0);
        cairo_rotate(cr, -BD_PI / 2.0);
        draw_text(cr, 0.0, 0.0, 1.0, 1.0, a->xmarks[i].label);
        cairo_restore(cr);
    }
}

/* a short text up and right of its point, on a white halo */
static void draw_note(cairo_t *cr, const xform *t, const bd_plot_text *n)
{
    if (!n->label) return;
    set_font(cr, FS_TICK - 1.0, 0);
    double X = px(t, n->x) + 6.0, Y = py(t, n->y) - 9.0;
    double w = text_width(cr, n->label);
    if (X + w > t->x1) X = px(t, n->x) - 6.0 - w;
    cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, 0.8);
    cairo_rectangle(cr, X - 2.0, Y - FS_TICK * 0.6, w + 4.0, FS_TICK * 1.2);
    cairo_fill(cr);
    set_rgb(cr, text_rgb);
    draw_text(cr, X, Y, 0.0, 0.5, n->label);
}

static void render(cairo_t *cr, const bd_plot_figure *f)
{
    layout L;
    int np = f->npanels < 1 ? 1 : f->npanels > BD_PLOT_MAX_PANELS ? BD_PLOT_MAX_PANELS : f->npanels;
    compute_layout(cr, f, &L);

    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);

    /* title and subtitle */
    set_rgb(cr, text_rgb);
    if (f->title) {
        set_font(cr, FS_TITLE, 1);
        draw_text(cr, L.left, 24.0, 0.0, 0.5, f->title);
    }
    if (f->subtitle) {
        set_font(cr, FS_SUB, 0);
        cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
        draw_text(cr, L.left, f->title ? 46.0 : 20.0, 0.0, 0.5, f->subtitle);
    }

    for (int p = 0; p < np; p++) {
        const bd_plot_axes *a = &f->panel[p];
        xform t = {L.left, L.right, L.top[p], L.bottom[p],
                   L.xr[p].lo, L.xr[p].hi, L.yr[p].lo, L.yr[p].hi};

        /* grid */
        cairo_set_line_width(cr, 1.0);
        set_rgb(cr, grid_rgb);
        if (!a->map) {
            for (int i = 0; i < L.xt[p].n; i++) {
                double X = floor(px(&t, L.xt[p].v[i])) + 0.5;
                cairo_move_to(cr, X, t.y0);
                cairo_line_to(cr, X, t.y1);
            }
            for (int i = 0; i < L.yt[p].n; i++) {
                double Y = floor(py(&t, L.yt[p].v[i])) + 0.5;
                cairo_move_to(cr, t.x0, Y);
                cairo_line_to(cr, t.x1, Y);
            }
            cairo_stroke(cr);
        }

        /* data, clipped to the plot area */
        cairo_save(cr);
        cairo_rectangle(cr, t.x0, t.y0, t.x1 - t.x0, t.y1 - t.y0);
        cairo_clip(cr);
        if (a->map) draw_map(cr, &t, a->map);
        if (a->has_band) draw_band(cr, &t, &a->band);
        if (a->has_xspan) draw_xspan(cr, &t, &a->xspan);
        draw_xmarks(cr, &t, a);
        /* a zero line when the range crosses zero */
        if (!a->map && L.yr[p].lo < 0.0 && L.yr[p].hi > 0.0) {
            double Y = floor(py(&t, 0.0)) + 0.5;
            cairo_set_source_rgb(cr, 0.55, 0.55, 0.55);
            cairo_set_line_width(cr, 1.0);
            cairo_move_to(cr, t.x0, Y);
            cairo_line_to(cr, t.x1, Y);
            cairo_stroke(cr);
        }
        for (int i = 0; i < a->nhlines; i++) {
            const bd_plot_hline *h = &a->hlines[i];
            double Y = py(&t, h->y);
            set_rgb(cr, h->color);
            cairo_set_line_width(cr, 2.0);
            if (h->dashed) {
                double d[2] = {8.0, 5.0};
                cairo_set_dash(cr, d, 2, 0.0);
            }
            cairo_move_to(cr, t.x0, Y);
            cairo_line_to(cr, t.x1, Y);
            cairo_stroke(cr);
            cairo_set_dash(cr, NULL, 0, 0.0);
        }
        for (int i = 0; i < a->nseries; i++) draw_line_series(cr, &t, &a->series[i]);
        cairo_restore(cr);
        for (int i = 0; i < a->ntexts; i++) draw_note(cr, &t, &a->texts[i]);
        for (int i = 0; i < a->nmarkers; i++) draw_marker(cr, &t, &a->markers[i]);

        /* frame and ticks */
        set_rgb(cr, frame_rgb);
        cairo_set_line_width(cr, 1.0);
        cairo_rectangle(cr, floor(t.x0) + 0.5, floor(t.y0) + 0.5, floor(t.x1 - t.x0), floor(t.y1 - t.y0));
        cairo_stroke(cr);
        int xlabels = !f->share_x || p == np - 1;
        set_font(cr, FS_TICK, 0);
        for (int i = 0; i < L.xt[p].n; i++) {
            double X = floor(px(&t, L.xt[p].v[i])) + 0.5;
            set_rgb(cr, frame_rgb);
            cairo_move_to(cr, X, t.y1);
            cairo_line_to(cr, X, t.y1 + 5.0);
            cairo_stroke(cr);
            if (xlabels) {
                char buf[64];
                format_tick(buf, sizeof buf, L.xt[p].v[i], L.xt[p].step);
                set_rgb(cr, text_rgb);
                draw_text(cr, X, t.y1 + 8.0, 0.5, 0.0, buf);
            }
        }
        for (int i = 0; i < L.yt[p].n; i++) {
            double Y = floor(py(&t, L.yt[p].v[i])) + 0.5;
            char buf[64];
            format_tick(buf, sizeof buf, L.yt[p].v[i], L.yt[p].step);
            set_rgb(cr, frame_rgb);
            cairo_move_to(cr, t.x0 - 5.0, Y);
            cairo_line_to(cr, t.x0, Y);
            cairo_stroke(cr);
            set_rgb(cr, text_rgb);
            draw_text(cr, t.x0 - 8.0, Y, 1.0, 0.5, buf);
        }

        /* axis labels */
        set_font(cr, FS_LABEL, 0);
        set_rgb(cr, text_rgb);
        if (xlabels && a->xlabel)
            draw_text(cr, 0.5 * (t.x0 + t.x1), t.y1 + 8.0 + FS_TICK + 10.0, 0.5, 0.0, a->xlabel);
        if (a->ylabel) {
            cairo_save(cr);
            cairo_translate(cr, 16.0 + FS_LABEL * 0.5, 0.5 * (t.y0 + t.y1));
            cairo_rotate(cr, -BD_PI / 2.0);
            draw_text(cr, 0.0, 0.0, 0.5, 0.5, a->ylabel);
            cairo_restore(cr);
        }

        draw_legend(cr, &L, p, a);
        if (a->map) draw_colorbar(cr, &L, p, a->map);
    }
}

static int finish_file(const char *tmp, const char *path, char *err, size_t errlen)
{
    if (rename(tmp, path) != 0) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        remove(tmp);
        return -1;
    }
    return 0;
}

int bd_plot_write(const bd_plot_figure *f, const char *png_path, const char *svg_path,
                  char *err, size_t errlen)
{
    char tmp[4096];
    if (png_path) {
        cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, f->width, f->height);
        cairo_t *cr = cairo_create(s);
        render(cr, f);
        cairo_status_t st = cairo_status(cr);
        cairo_destroy(cr);
        snprintf(tmp, sizeof tmp, "%s.tmp", png_path);
        if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_write_to_png(s, tmp);
        cairo_surface_destroy(s);
        if (st != CAIRO_STATUS_SUCCESS) {
            snprintf(err, errlen, "%s: %s", png_path, cairo_status_to_string(st));
            remove(tmp);
            return -1;
        }
        if (finish_file(tmp, png_path, err, errlen)) return -1;
    }
    if (svg_path) {
        snprintf(tmp, sizeof tmp, "%s.tmp", svg_path);
        cairo_surface_t *s = cairo_svg_surface_create(tmp, (double)f->width, (double)f->height);
        cairo_t *cr = cairo_create(s);
        render(cr, f);
        cairo_status_t st = cairo_status(cr);
        cairo_destroy(cr);
        cairo_surface_finish(s);
        if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_status(s);
        cairo_surface_destroy(s);
        if (st != CAIRO_STATUS_SUCCESS) {
            snprintf(err, errlen, "%s: %s", svg_path, cairo_status_to_string(st));
            remove(tmp);
            return -1;
        }
        if (finish_file(tmp, svg_path, err, errlen)) return -1;
    }
    return 0;
}
