/* beltdyn report DIR: plots of a run and one self-contained report.html */
#include "beltdyn/report.h"

#include "base/constants.h"
#include "base/file.h"
#include "base/json_util.h"
#include "io/csv_read.h"
#include "io/html.h"
#include "io/layout_plot.h"
#include "io/cases_report.h"
#include "io/report_internal.h"
#include "io/study_report.h"
#include "io/plot.h"
#include "laws/belt_pulley_law.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

#define MAX_GROUP BD_PLOT_MAX_SERIES
/* a summary.json from before design.safety_factor: its default for starts
 * and stops, which a run's peak is judged by */
#define SAFETY_FACTOR_DEFAULT 4.8

/* ---- small helpers (report_internal.h) ---- */

void bd_rep_err(char *err, size_t errlen, const char *fmt, ...)
{
    if (!err || errlen == 0) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

int bd_rep_file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

static int ends_with(const char *s, const char *suffix)
{
    size_t a = strlen(s), b = strlen(suffix);
    return a > b && strcmp(s + a - b, suffix) == 0;
}

void bd_rep_fmt_num(char *buf, size_t len, double v)
{
    if (!isfinite(v)) {
        snprintf(buf, len, "%s", isnan(v) ? "NaN" : v > 0 ? "inf" : "-inf");
        return;
    }
    double a = fabs(v);
    if (a != 0.0 && (a < 1e-3 || a >= 1e12)) {
        snprintf(buf, len, "%.3e", v);
        return;
    }
    int dec = 0;
    if (a > 0.0 && a < 1000.0) dec = 3 - (int)floor(log10(a));
    if (dec > 6) dec = 6;
    if (dec < 0) dec = 0;
    if (v == floor(v) && a < 1e12) dec = 0;
    char raw[64];
    snprintf(raw, sizeof raw, "%.*f", dec, v);
    /* group the integer digits */
    const char *p = raw;
    char *o = buf, *end = buf + len - 1;
    if (*p == '-') {
        if (o < end) *o++ = '-';
        p++;
    }
    size_t nint = strcspn(p, ".");
    for (size_t i = 0; i < nint && o < end; i++) {
        if (i > 0 && (nint - i) % 3 == 0 && nint > 4) {
            /* U+2009 thin space */
            if (o + 3 < end) {
                *o++ = (char)0xE2;
                *o++ = (char)0x80;
                *o++ = (char)0x89;
            }
        }
        *o++ = p[i];
    }
    for (p += nint; *p && o < end; p++) *o++ = *p;
    *o = '\0';
}

bd_rep_unit bd_rep_pick_unit(double maxabs, const char *base)
{
    static const char *const prefixed[3] = {"N", "N·m", "J"};
    static const char *const pre[4] = {"", "k", "M", "G"};
    bd_rep_unit u;
    int k = 0, scalable = 0;
    for (int i = 0; i < 3; i++)
        if (strcmp(base, prefixed[i]) == 0) scalable = 1;
    if (scalable) {
        if (maxabs >= 1e10) k = 3;
        else if (maxabs >= 1e7) k = 2;
        else if (maxabs >= 1e4) k = 1;
    }
    u.scale = pow(1000.0, (double)k);
    snprintf(u.name, sizeof u.name, "%s%s", pre[k], base);
    return u;
}

static double maxabs_of(const double *v, size_t n)
{
    double m = 0.0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(v[i]) && fabs(v[i]) > m) m = fabs(v[i]);
    return m;
}

double *bd_rep_scaled(const double *v, size_t n, double scale)
{
    double *o = malloc((n ? n : 1) * sizeof *o);
    if (!o) return NULL;
    for (size_t i = 0; i < n; i++) o[i] = v[i] / scale;
    return o;
}

/* ---- what the report knows (bd_rep, report_internal.h) ---- */

double *bd_rep_own(bd_rep *r, double *p)
{
    if (p && r->nowned < (int)(sizeof r->owned / sizeof r->owned[0])) {
        r->owned[r->nowned++] = p;
        return p;
    }
    free(p);
    return NULL;
}

char *bd_rep_label(bd_rep *r)
{
    if (r->nlabels >= BD_REP_MAX_LABELS) r->nlabels = BD_REP_MAX_LABELS - 1;  /* reuse the last */
    return r->labels[r->nlabels++];
}

int bd_rep_write_plot(bd_rep *r, const bd_plot_figure *f, const char *name, const char *caption,
                      char *err, size_t errlen)
{
    char png[BD_REP_PATH_LEN], svg[BD_REP_PATH_LEN];
    if (snprintf(png, sizeof png, "%s/%s.png", r->plots, name) >= (int)sizeof png ||
        snprintf(svg, sizeof svg, "%s/%s.svg", r->plots, name) >= (int)sizeof svg) {
        bd_rep_err(err, errlen, "%s: path too long", r->plots);
        return BD_REPORT_EOUTPUT;
    }
    if (bd_plot_write(f, png, svg, err, errlen)) return BD_REPORT_EOUTPUT;
    if (r->nplots < (int)(sizeof r->plot / sizeof r->plot[0])) {
        snprintf(r->plot[r->nplots].name, sizeof r->plot[0].name, "%s", name);
        snprintf(r->plot[r->nplots].caption, sizeof r->plot[0].caption, "%s", caption);
        r->nplots++;
    }
    return 0;
}

void bd_rep_set_title(bd_rep *r, char *buf, size_t len, const char *what)
{
    snprintf(buf, len, "%s — %s", r->model, what);
}

/* ---- tension surface: s x t colour map ---- */

/* bin the long-format field into a w x h raster: each time block becomes
 * one row of w columns (the largest tension per column, gaps between
 * elements interpolated); several blocks in one pixel row keep the
 * largest; pixel rows without a block take the nearest one */
static float *raster_field(const double *t, const double *s, const double *T, size_t n,
                           double smin, double smax, double tmin, double tmax, int w, int h)
{
    float *img = malloc((size_t)w * (size_t)h * sizeof *img);
    float *row = malloc((size_t)w * sizeof *row);
    char *filled = calloc((size_t)h, 1);
    if (!img || !row || !filled) {
        free(img);
        free(row);
        free(filled);
        return NULL;
    }
    for (size_t i = 0; i < (size_t)w * (size_t)h; i++) img[i] = NAN;
    double sx = (double)w / (smax - smin);
    double ty = tmax > tmin ? (double)h / (tmax - tmin) : 0.0;
    size_t a = 0;
    while (a < n) {
        /* one block: rows with the same time */
        size_t b = a;
        while (b < n && t[b] == t[a]) b++;
        for (int c = 0; c < w; c++) row[c] = NAN;
        for (size_t k = a; k < b; k++) {
            if (!isfinite(s[k]) || !isfinite(T[k])) continue;
            long c = (long)((s[k] - smin) * sx);
            if (c < 0) c = 0;
            if (c >= w) c = w - 1;
            float v = (float)T[k];
            if (!(row[c] >= v)) row[c] = v;
        }
        /* interpolate across empty columns between filled ones */
        int last = -1;
        for (int c = 0; c < w; c++) {
            if (isnan(row[c])) continue;
            if (last >= 0 && c - last > 1) {
                for (int g = last + 1; g < c; g++) {
                    float f = (float)(g - last) / (float)(c - last);
                    row[g] = row[last] + f * (row[c] - row[last]);
                }
            }
            last = c;
        }
        /* into its pixel row */
        if (isfinite(t[a])) {
            long y = (long)((t[a] - tmin) * ty);
            if (y < 0) y = 0;
            if (y >= h) y = h - 1;
            float *dst = img + (size_t)y * (size_t)w;
            for (int c = 0; c < w; c++)
                if (!isnan(row[c]) && !(dst[c] >= row[c])) dst[c] = row[c];
            filled[y] = 1;
        }
        a = b;
    }
    /* empty pixel rows copy the nearest filled row */
    int any = 0;
    for (int y = 0; y < h; y++) any |= filled[y];
    if (any) {
        for (int y = 0; y < h; y++) {
            if (filled[y]) continue;
            int lo = y - 1, hi = y + 1;
            while (lo >= 0 && !filled[lo]) lo--;
            while (hi < h && !filled[hi]) hi++;
            int src = lo < 0 ? hi : hi >= h ? lo : (y - lo <= hi - y ? lo : hi);
            memcpy(img + (size_t)y * (size_t)w, img + (size_t)src * (size_t)w, (size_t)w * sizeof *img);
        }
    }
    free(row);
    free(filled);
    return img;
}

static int plot_tension_surface(bd_rep *r, char *err, size_t errlen)
{
    char path[BD_REP_PATH_LEN];
    if (bd_path_join(path, sizeof path, r->dir, "tension.csv") || !bd_rep_file_exists(path)) return 0;
    static const char *const want[3] = {"t_s", "s_m", "tension_N"};
    bd_csv csv;
    if (bd_csv_read(path, want, 3, &csv, err, errlen)) return BD_REPORT_EINPUT;
    int rc = 0;
    size_t n = csv.nrows;
    const double *t = csv.col[0], *s = csv.col[1], *T = csv.col[2];
    double smin = INFINITY, smax = -INFINITY, tmin = INFINITY, tmax = -INFINITY;
    bd_rep_point hi = {0, -INFINITY, 0, 0}, lo = {0, INFINITY, 0, 0};
    size_t nblocks = 0, first_block = 0;
    for (size_t i = 0; i < n; i++) {
        if (i == 0 || t[i] != t[i - 1]) nblocks++;
        if (nblocks == 1) first_block++;
        if (!isfinite(t[i]) || !isfinite(s[i]) || !isfinite(T[i])) continue;
        if (s[i] < smin) smin = s[i];
        if (s[i] > smax) smax = s[i];
        if (t[i] < tmin) tmin = t[i];
        if (t[i] > tmax) tmax = t[i];
        if (T[i] > hi.value) hi = (bd_rep_point){1, T[i], t[i], s[i]};
        if (T[i] < lo.value) lo = (bd_rep_point){1, T[i], t[i], s[i]};
    }
    if (!hi.known || !(smax > smin)) goto done;  /* nothing to draw */
    if (!r->tmax.known) r->tmax = hi;
    if (!r->tmin.known) r->tmin = lo;

    bd_rep_unit u = bd_rep_pick_unit(fmax(fabs(hi.value), fabs(lo.value)), "N");
    char *cbar = bd_rep_label(r), *title = bd_rep_label(r), *sub = bd_rep_label(r), *mlabel = bd_rep_label(r), *nlabel = bd_rep_label(r);
    snprintf(cbar, BD_REP_LABEL_LEN, "Belt tension T [%s]", u.name);
    bd_rep_set_title(r, title, BD_REP_LABEL_LEN, "belt tension along the belt over time");
    snprintf(sub, BD_REP_LABEL_LEN,
             "%zu points along the belt × %zu times; colour: the largest tension within each pixel",
             first_block, nblocks);
    bd_plot_figure f;
    bd_plot_figure_init(&f, title, BD_REP_FIG_W, BD_REP_FIG_H + 100);
    f.subtitle = sub;
    bd_plot_axes *a = &f.panel[0];
    a->xlabel = "Position along the belt s [m]";
    a->ylabel = "Time t [s]";
    bd_plot_map map;
    memset(&map, 0, sizeof map);
    map.x0 = smin;
    map.x1 = smax;
    map.y0 = tmin;
    map.y1 = tmax > tmin ? tmax : tmin + 1.0;
    map.vmin = lo.value / u.scale;
    map.vmax = hi.value > lo.value ? hi.value / u.scale : lo.value / u.scale + 1.0;
    map.label = cbar;
    a->map = &map;
    bd_layout_mark_s_axis(r->summary, a);
    /* markers first: they take part in the layout (legend rows none) */
    char v1[64], v2[64];
    bd_rep_fmt_num(v1, sizeof v1, hi.value / u.scale);
    snprintf(mlabel, BD_REP_LABEL_LEN, "max %s %s at s = %.1f m, t = %.2f s", v1, u.name, hi.s, hi.t);
    bd_rep_fmt_num(v2, sizeof v2, lo.value / u.scale);
    snprintf(nlabel, BD_REP_LABEL_LEN, "min %s %s at s = %.1f m, t = %.2f s", v2, u.name, lo.s, lo.t);
    bd_plot_add_marker(a, hi.s, hi.t, mlabel);
    bd_plot_add_marker(a, lo.s, lo.t, nlabel);
    int w, h;
    bd_plot_area_size(&f, 0, &w, &h);
    if (w < 16) w = 16;
    if (h < 16) h = 16;
    float *img = raster_field(t, s, T, n, smin, smax, tmin, map.y1, w, h);
    if (!img) {
        bd_rep_err(err, errlen, "%s: out of memory", path);
        rc = BD_REPORT_EOUTPUT;
        goto done;
    }
    /* to the display unit */
    for (size_t i = 0; i < (size_t)w * (size_t)h; i++) img[i] = (float)((double)img[i] / u.scale);
    map.v = img;
    map.w = w;
    map.h = h;
    rc = bd_rep_write_plot(r, &f, "tension_surface",
                    "Belt tension over position s along the belt and time t; the rings mark the "
                    "highest and the lowest tension.",
                    err, errlen);
    free(img);
done:
    bd_csv_free(&csv);
    return rc;
}

/* ---- the conveyor's layout (summary.json "layout") ---- */

static int plot_layout(bd_rep *r, char *err, size_t errlen)
{
    char *title = bd_rep_label(r);
    bd_rep_set_title(r, title, BD_REP_LABEL_LEN, "layout");
    bd_plot_figure f;
    bd_plot_figure_init(&f, title, BD_REP_FIG_W, BD_REP_FIG_H - 120);
    bd_layout_drawing d;
    int got = bd_layout_figure(r->summary, &f, &d);
    if (got < 0) {
        bd_rep_err(err, errlen, "out of memory");
        return BD_REPORT_EOUTPUT;
    }
    if (got == 0) return 0;   /* a run from before summary.json had a layout */
    int rc = bd_rep_write_plot(r, &f, "layout",
                        "The conveyor as built: the belt path, the pulleys by name (drives red, "
                        "takeups blue), the loaded stretch, and where the belt lifted off its "
                        "idlers if it did.",
                        err, errlen);
    bd_layout_drawing_free(&d);
    return rc;
}

/* ---- envelope: max/min tension along s ---- */

static int plot_envelope(bd_rep *r, char *err, size_t errlen)
{
    char path[BD_REP_PATH_LEN];
    if (bd_path_join(path, sizeof path, r->dir, "envelope.csv") || !bd_rep_file_exists(path)) return 0;
    static const char *const want[3] = {"s_m", "tension_max_N", "tension_min_N"};
    bd_csv csv;
    if (bd_csv_read(path, want, 3, &csv, err, errlen)) return BD_REPORT_EINPUT;
    int rc = 0;
    size_t n = csv.nrows;
    if (n == 0) goto done;
    double m = fmax(maxabs_of(csv.col[1], n), maxabs_of(csv.col[2], n));
    if (isfinite(r->rated_N)) m = fmax(m, r->rated_N / r->safety_factor);
    bd_rep_unit u = bd_rep_pick_unit(m, "N");
    double *x = csv.col[0];
    double *hi = bd_rep_own(r, bd_rep_scaled(csv.col[1], n, u.scale));
    double *lo = bd_rep_own(r, bd_rep_scaled(csv.col[2], n, u.scale));
    if (!hi || !lo) {
        bd_rep_err(err, errlen, "out of memory");
        rc = BD_REPORT_EOUTPUT;
        goto done;
    }
    char *title = bd_rep_label(r), *ylabel = bd_rep_label(r), *allow = bd_rep_label(r), *sag = bd_rep_label(r), *mlabel = bd_rep_label(r);
    bd_rep_set_title(r, title, BD_REP_LABEL_LEN, "tension envelope along the belt");
    snprintf(ylabel, BD_REP_LABEL_LEN, "Belt tension T [%s]", u.name);
    bd_plot_figure f;
    bd_plot_figure_init(&f, title, BD_REP_FIG_W, BD_REP_FIG_H);
    f.subtitle = "highest and lowest tension reached at each position during the run";
    bd_plot_axes *a = &f.panel[0];
    a->xlabel = "Position along the belt s [m]";
    a->ylabel = ylabel;
    a->include_zero = 1;
    a->has_band = 1;
    a->band = (bd_plot_band){x, lo, hi, n, "range during the run", {0.0, 0.447, 0.698}, 0.15};
    bd_layout_mark_s_axis(r->summary, a);
    int k = bd_plot_add_series(a, x, hi, n, "maximum tension", (bd_rgb){0.80, 0.15, 0.10});
    a->series[k].width = 2.5;
    k = bd_plot_add_series(a, x, lo, n, "minimum tension", (bd_rgb){0.0, 0.35, 0.70});
    a->series[k].width = 2.5;
    char v[64], v2[64];
    if (isfinite(r->rated_N)) {
        double allow_N = r->rated_N / r->safety_factor;
        bd_rep_fmt_num(v, sizeof v, allow_N / u.scale);
        bd_rep_fmt_num(v2, sizeof v2, r->rated_N / u.scale);
        snprintf(allow, BD_REP_LABEL_LEN, "allowable in starts and stops %s %s = rated %s %s / "
                 "safety factor %.3g%s", v, u.name, v2, u.name, r->safety_factor,
                 r->sf_default ? " (default)" : "");
        bd_plot_add_hline(a, allow_N / u.scale, allow, (bd_rgb){0.80, 0.0, 0.0}, 1);
    }
    if (isfinite(r->t_min_sag_N)) {
        bd_rep_fmt_num(v, sizeof v, r->t_min_sag_N / u.scale);
        snprintf(sag, BD_REP_LABEL_LEN, "minimum tension for the sag limit %s %s", v, u.name);
        bd_plot_add_hline(a, r->t_min_sag_N / u.scale, sag, (bd_rgb){0.0, 0.55, 0.30}, 1);
    }
    /* mark the peak */
    size_t im = 0;
    for (size_t i = 1; i < n; i++)
        if (hi[i] > hi[im] || !isfinite(hi[im])) im = i;
    if (isfinite(hi[im])) {
        bd_rep_fmt_num(v, sizeof v, hi[im]);
        snprintf(mlabel, BD_REP_LABEL_LEN, "peak %s %s at s = %.1f m", v, u.name, x[im]);
        bd_plot_add_marker(a, x[im], hi[im], mlabel);
    }
    {
        char *cap = bd_rep_label(r);
        snprintf(cap, BD_REP_LABEL_LEN,
                 "Highest and lowest belt tension at each position over the run.%s%s",
                 isfinite(r->rated_N) ? " Dashed red: allowable tension (rated / safety factor)."
                                      : " No rated tension in summary.json: no allowable line.",
                 isfinite(r->t_min_sag_N) ? " Dashed green: minimum tension for the sag limit."
                                          : "");
        rc = bd_rep_write_plot(r, &f, "envelope", cap, err, errlen);
    }
done:
    bd_csv_free(&csv);
    return rc;
}

/* ---- history.csv plots ---- */

typedef struct group {
    int n;
    char name[MAX_GROUP][64];
    int col[MAX_GROUP][2];   /* column indices, -1 absent */
} group;

/* columns NAME<suffix_a> and NAME<suffix_b> (b optional) by name */
static void find_group(const bd_csv *h, const char *suffix_a, const char *suffix_b, group *g)
{
    memset(g, 0, sizeof *g);
    for (int j = 0; j < h->ncols && g->n < MAX_GROUP; j++) {
        const char *nm = h->names[j];
        const char *sfx = ends_with(nm, suffix_a) ? suffix_a
                          : (suffix_b && ends_with(nm, suffix_b)) ? suffix_b : NULL;
        if (!sfx) continue;
        size_t len = strlen(nm) - strlen(sfx);
        char base[64];
        snprintf(base, sizeof base, "%.*s", (int)len, nm);
        int which = sfx == suffix_a ? 0 : 1, i;
        for (i = 0; i < g->n; i++)
            if (strcmp(g->name[i], base) == 0) break;
        if (i == g->n) {
            snprintf(g->name[i], sizeof g->name[i], "%s", base);
            g->col[i][0] = g->col[i][1] = -1;
            g->n++;
        }
        g->col[i][which] = j;
    }
}

int bd_rep_columns_panel(bd_rep *r, bd_plot_axes *a, const bd_csv *h, const int *cols,
                         const char *const *names, int n, const char *quantity,
                         const char *base_unit, char *ylabel, size_t ylen, int with_range,
                         bd_rep_unit *uout)
{
    const double *t = h->col[0];
    double m = 0.0;
    int any = 0;
    for (int i = 0; i < n; i++)
        if (cols[i] >= 0) {
            m = fmax(m, maxabs_of(h->col[cols[i]], h->nrows));
            any = 1;
        }
    if (!any) return 0;
    bd_rep_unit u = bd_rep_pick_unit(m, base_unit);
    if (uout) *uout = u;
    snprintf(ylabel, ylen, "%s [%s]", quantity, u.name);
    a->ylabel = ylabel;
    for (int i = 0, k = 0; i < n; i++) {
        int c = cols[i];
        if (c < 0) continue;
        double *y = bd_rep_own(r, bd_rep_scaled(h->col[c], h->nrows, u.scale));
        if (!y) return -1;
        char *label = bd_rep_label(r);
        if (with_range) {
            /* the name and the range of values */
            double lo = INFINITY, hi = -INFINITY;
            for (size_t q = 0; q < h->nrows; q++)
                if (isfinite(y[q])) {
                    lo = fmin(lo, y[q]);
                    hi = fmax(hi, y[q]);
                }
            char a1[64], a2[64];
            bd_rep_fmt_num(a1, sizeof a1, lo);
            bd_rep_fmt_num(a2, sizeof a2, hi);
            snprintf(label, BD_REP_LABEL_LEN, "%s (%s … %s %s)", names[i], a1, a2, u.name);
        } else {
            snprintf(label, BD_REP_LABEL_LEN, "%s", names[i]);
        }
        bd_plot_add_series(a, t, y, h->nrows, label, bd_plot_palette(k++));
    }
    return 1;
}

/* one panel of NAME columns, scaled to a readable unit */
static int fill_panel(bd_rep *r, bd_plot_axes *a, const bd_csv *h, const group *g, int which,
                      const char *quantity, const char *base_unit, char *ylabel, size_t ylen,
                      int with_range, bd_rep_unit *uout)
{
    int cols[MAX_GROUP];
    const char *names[MAX_GROUP];
    for (int i = 0; i < g->n; i++) {
        cols[i] = g->col[i][which];
        names[i] = g->name[i];
    }
    return bd_rep_columns_panel(r, a, h, cols, names, g->n, quantity, base_unit, ylabel, ylen,
                                with_range, uout);
}

int bd_rep_find_extreme(const bd_plot_axes *a, int magnitude, double from, int *series,
                        size_t *sample)
{
    double best = -INFINITY;
    *series = -1;
    *sample = 0;
    for (int i = 0; i < a->nseries; i++) {
        const bd_plot_series *s = &a->series[i];
        for (size_t k = 0; k < s->n; k++) {
            double v = magnitude ? fabs(s->y[k]) : s->y[k];
            if (isfinite(v) && isfinite(s->x[k]) && s->x[k] >= from - 1e-9 && v > best) {
                best = v;
                *series = i;
                *sample = k;
            }
        }
    }
    return *series >= 0;
}

void bd_rep_mark_sample(bd_rep *r, bd_plot_axes *a, int bs, size_t bi, const char *what,
                        const char *unit_name, int magnitude, double exact)
{
    const bd_plot_series *s = &a->series[bs];
    char num[64], *label = bd_rep_label(r);
    double value = s->y[bi];
    const char *at = "at";
    if (isfinite(exact)) {
        value = magnitude ? copysign(exact, s->y[bi]) : exact;
        at = "near";   /* the step's own peak, by the sample that shows it */
    }
    bd_rep_fmt_num(num, sizeof num, value);
    if (a->nseries > 1)
        snprintf(label, BD_REP_LABEL_LEN, "%s %s %s %s t = %.3g s (%.40s)", what, num, unit_name, at,
                 s->x[bi], s->label ? s->label : "");
    else
        snprintf(label, BD_REP_LABEL_LEN, "%s %s %s %s t = %.3g s", what, num, unit_name, at, s->x[bi]);
    bd_plot_add_marker(a, s->x[bi], s->y[bi], label);
}

/* mark the largest value (or largest magnitude) over a panel's series.
 * The curves are sampled at the output interval; where summary.json has
 * the series' peak from every step (in.SERIES.key, in base units, scale
 * the panel's unit), the label gives that value, the one the cards show,
 * so that card and plot agree (issue 15) */
static void mark_extreme(bd_rep *r, bd_plot_axes *a, const char *what, const char *unit_name,
                         int magnitude, const char *in, const char *key, double scale)
{
    int bs;
    size_t bi;
    /* a run whose records start late (a stop case, records_from_s): its
     * summary's extremes are from then on, and so is the marked sample */
    double from = bd_json_num(r->summary, "records_from_s");
    if (!isfinite(from)) from = -INFINITY;
    if (!bd_rep_find_extreme(a, magnitude, from, &bs, &bi)) return;
    const bd_plot_series *s = &a->series[bs];
    double exact = NAN;
    if (in && s->label && scale > 0.0) {
        const cJSON *g = cJSON_GetObjectItemCaseSensitive(r->summary, in);
        exact = bd_json_num(cJSON_GetObjectItemCaseSensitive(g, s->label), key) / scale;
    }
    bd_rep_mark_sample(r, a, bs, bi, what, unit_name, magnitude, exact);
}

/* a drive's radius from summary.json, NaN when it is not there */
static double drive_radius(const bd_rep *r, const char *name)
{
    const cJSON *p = cJSON_GetObjectItemCaseSensitive(r->summary, "pulleys");
    return bd_json_num(cJSON_GetObjectItemCaseSensitive(p, name), "radius_m");
}

/* the drives' surface speed ω·R in m/s (1), or 0 when a radius is
 * unknown (an older summary.json: the caller plots ω), −1 out of memory */
static int drive_speed_panel(bd_rep *r, bd_plot_axes *a, const bd_csv *h, const group *g,
                             char *ylabel)
{
    for (int i = 0; i < g->n; i++)
        if (g->col[i][0] >= 0 && !(drive_radius(r, g->name[i]) > 0.0)) return 0;
    snprintf(ylabel, BD_REP_LABEL_LEN, "Belt speed at the drive ω·R [m/s]");
    a->ylabel = ylabel;
    for (int i = 0, k = 0; i < g->n; i++) {
        if (g->col[i][0] < 0) continue;
        double *y = bd_rep_own(r, bd_rep_scaled(h->col[g->col[i][0]], h->nrows, 1.0 / drive_radius(r, g->name[i])));
        if (!y) return -1;
        bd_plot_add_series(a, h->col[0], y, h->nrows, g->name[i], bd_plot_palette(k++));
    }
    return a->nseries > 0;
}

/* the power each drive delivers to its pulley, M·ω in kW (negative:
 * braking), for the drives with both columns; 0, or −1 out of memory */
static int drive_power_panel(bd_rep *r, bd_plot_axes *a, const bd_csv *h, const group *g,
                             char *ylabel)
{
    snprintf(ylabel, BD_REP_LABEL_LEN, "Drive power M·ω [kW]");
    a->ylabel = ylabel;
    for (int i = 0, k = 0; i < g->n; i++) {
        int cw = g->col[i][0], cm = g->col[i][1];
        if (cw < 0 || cm < 0) continue;
        double *y = bd_rep_own(r, malloc((h->nrows ? h->nrows : 1) * sizeof *y));
        if (!y) return -1;
        for (size_t q = 0; q < h->nrows; q++)
            y[q] = h->col[cw][q] * h->col[cm][q] / 1000.0;
        bd_plot_add_series(a, h->col[0], y, h->nrows, g->name[i], bd_plot_palette(k++));
    }
    return 0;
}

/* a pulley's entry in summary.json's layout (io/layout.c), or NULL */
static const cJSON *layout_pulley(const bd_rep *r, const char *name)
{
    const cJSON *lay = cJSON_GetObjectItemCaseSensitive(r->summary, "layout"), *p;
    cJSON_ArrayForEach(p, cJSON_GetObjectItemCaseSensitive(lay, "pulleys")) {
        const char *n = bd_json_str(p, "name");
        if (strcmp(n, name) == 0) return p;
    }
    return NULL;
}

/* a drive's torque rating at the pulley: its motor's rated torque, else its
 * max_torque; NaN when it has neither. *what says which. */
static double drive_rating(const bd_rep *r, const char *name, const char **what)
{
    const cJSON *p = layout_pulley(r, name);
    double T = bd_json_num(p, "rated_torque_Nm");
    *what = "motor rated";
    if (!(T > 0.0)) {
        T = bd_json_num(p, "max_torque_Nm");
        *what = "max_torque";
    }
    return T > 0.0 ? T : NAN;
}

/* the drives' torque as % of their rating (1) when every drive has one, 0
 * when one has none (the caller plots N·m), −1 out of memory */
static int drive_torque_percent_panel(bd_rep *r, bd_plot_axes *a, const bd_csv *h, const group *g,
                                      char *ylabel, double *scale)
{
    int n = 0;
    for (int i = 0; i < g->n; i++) {
        const char *what;
        if (g->col[i][1] < 0) continue;
        if (!isfinite(drive_rating(r, g->name[i], &what))) return 0;
        n++;
    }
    if (n == 0) return 0;
    snprintf(ylabel, BD_REP_LABEL_LEN, "Drive torque M [%% of rating]");
    a->ylabel = ylabel;
    *scale = NAN;
    for (int i = 0, k = 0; i < g->n; i++) {
        if (g->col[i][1] < 0) continue;
        const char *what;
        double rating = drive_rating(r, g->name[i], &what);
        double *y = bd_rep_own(r, bd_rep_scaled(h->col[g->col[i][1]], h->nrows, rating / 100.0));
        char *label = bd_rep_label(r), num[64];
        if (!y) return -1;
        bd_rep_fmt_num(num, sizeof num, rating);
        /* one 100 % line: one drive's rating on it; several drives carry
         * theirs in their legend entries (the series label of a single
         * drive stays its name: mark_extreme finds its summary peak by it) */
        if (n == 1) {
            char *line = bd_rep_label(r);
            snprintf(label, BD_REP_LABEL_LEN, "%s", g->name[i]);
            snprintf(line, BD_REP_LABEL_LEN, "100 %% = %s N·m (%s)", num, what);
            bd_plot_add_hline(a, 100.0, line, (bd_rgb){0.80, 0.0, 0.0}, 1);
            /* its summary peak converts with its rating */
            *scale = rating / 100.0;
        } else {
            snprintf(label, BD_REP_LABEL_LEN, "%s (100 %% = %s N·m, %s)", g->name[i], num, what);
        }
        bd_plot_add_series(a, h->col[0], y, h->nrows, label, bd_plot_palette(k++));
    }
    if (n > 1) bd_plot_add_hline(a, 100.0, "each drive's rating", (bd_rgb){0.80, 0.0, 0.0}, 1);
    return 1;
}

/* the friction each drive pulley uses, ln(T₁/T₂)/(μ·φ) in % (Euler–
 * Eytelwein: the belt slips at 100 %), from parts.csv and the layout's
 * wrap and static friction; 0 when there is no parts.csv, −1 out of memory */
static int drive_friction_panel(bd_rep *r, bd_plot_axes *a, const group *g, const bd_csv *parts,
                                char *ylabel)
{
    if (!parts) return 0;
    snprintf(ylabel, BD_REP_LABEL_LEN, "Friction used ln(T₁/T₂)/(μ·φ) [%%]");
    a->ylabel = ylabel;
    for (int i = 0, k = 0; i < g->n; i++) {
        char c1[96], c2[96];
        snprintf(c1, sizeof c1, "%s.tight_N", g->name[i]);
        snprintf(c2, sizeof c2, "%s.slack_N", g->name[i]);
        int a1 = bd_csv_find(parts, c1), a2 = bd_csv_find(parts, c2);
        const cJSON *p = layout_pulley(r, g->name[i]);
        double mu = bd_json_num(p, "friction_static"), phi = bd_json_num(p, "wrap_deg");
        if (a1 < 0 || a2 < 0 || !(mu > 0.0) || !(phi > 0.0)) continue;
        double cap = mu * phi * BD_PI / 180.0;
        double *y = bd_rep_own(r, malloc((parts->nrows ? parts->nrows : 1) * sizeof *y));
        if (!y) return -1;
        /* as the drive monitor computes the check's value */
        for (size_t q = 0; q < parts->nrows; q++)
            y[q] = 100.0 * bd_capstan_friction_used(parts->col[a1][q], parts->col[a2][q], cap);
        /* the drive stays its name: mark_extreme finds its summary peak,
         * the check's value, by it */
        bd_plot_add_series(a, parts->col[0], y, parts->nrows, g->name[i], bd_plot_palette(k++));
    }
    if (a->nseries > 0)
        bd_plot_add_hline(a, 100.0, "slip: the whole wrap's friction used", (bd_rgb){0.80, 0.0, 0.0}, 1);
    a->include_zero = 1;
    return 0;
}

/* parts.csv (io/outputs.c) when the run wrote one: 1 read, 0 absent */
static int read_parts(bd_rep *r, bd_csv *parts, char *err, size_t errlen)
{
    char path[BD_REP_PATH_LEN];
    if (bd_path_join(path, sizeof path, r->dir, "parts.csv") || !bd_rep_file_exists(path)) return 0;
    if (bd_csv_read(path, NULL, 0, parts, err, errlen)) return -1;
    if (parts->ncols < 1 || parts->nrows == 0) {
        bd_csv_free(parts);
        return 0;
    }
    return 1;
}

int bd_rep_plot_energy(bd_rep *r, const bd_csv *h, const char *input_name, char *err,
                       size_t errlen)
{
    int ck = bd_csv_find(h, "kinetic_J"), cp = bd_csv_find(h, "potential_J"),
        cd = bd_csv_find(h, "dissipated_J"), ci = bd_csv_find(h, "input_J");
    if (ck >= 0 && cp >= 0 && cd >= 0 && ci >= 0 && h->nrows > 0) {
        size_t n = h->nrows;
        const double *t = h->col[0];
        char *title = bd_rep_label(r), *ylabel = bd_rep_label(r);
        const double *K = h->col[ck], *P = h->col[cp], *D = h->col[cd], *I = h->col[ci];
        double E0 = K[0] + P[0] + D[0] - I[0];
        double ref = fmax(fabs(E0), 1.0);
        for (size_t i = 0; i < n; i++) {
            if (isfinite(I[i])) ref = fmax(ref, fabs(I[i]));
            if (isfinite(K[i])) ref = fmax(ref, fabs(K[i]));
        }
        double *dv[5], m = 0.0;
        for (int q = 0; q < 5; q++) {
            dv[q] = bd_rep_own(r, malloc(n * sizeof(double)));
            if (!dv[q]) goto oom;
        }
        double *rel = bd_rep_own(r, malloc(n * sizeof(double)));
        if (!rel) goto oom;
        for (size_t i = 0; i < n; i++) {
            dv[0][i] = K[i] - K[0];
            dv[1][i] = P[i] - P[0];
            dv[2][i] = D[i] - D[0];
            dv[3][i] = I[i] - I[0];
            dv[4][i] = K[i] + P[i] + D[i] - I[i] - E0;
            rel[i] = 100.0 * dv[4][i] / ref;
            for (int q = 0; q < 5; q++)
                if (isfinite(dv[q][i])) m = fmax(m, fabs(dv[q][i]));
        }
        bd_rep_unit ue = bd_rep_pick_unit(m, "J");
        for (int q = 0; q < 5; q++)
            for (size_t i = 0; i < n; i++) dv[q][i] /= ue.scale;
        const char *names[5] = {"kinetic", "potential (gravity, elastic)", "dissipated",
                                input_name, "balance: kinetic + potential + dissipated − input"};
        bd_plot_figure f;
        bd_rep_set_title(r, title, BD_REP_LABEL_LEN, "energy balance");
        bd_plot_figure_init(&f, title, BD_REP_FIG_W, BD_REP_FIG_H + 100);
        f.subtitle = "energies as changes from t = 0; the balance should stay at zero";
        f.npanels = 2;
        f.share_x = 1;
        snprintf(ylabel, BD_REP_LABEL_LEN, "Energy change ΔE [%s]", ue.name);
        f.panel[0].ylabel = ylabel;
        f.panel[0].include_zero = 1;
        for (int q = 0; q < 5; q++) {
            bd_rgb c = q == 4 ? (bd_rgb){0.0, 0.0, 0.0} : bd_plot_palette(q);
            int k = bd_plot_add_series(&f.panel[0], t, dv[q], n, names[q], c);
            if (q == 4) f.panel[0].series[k].dashed = 1;
        }
        f.panel[1].ylabel = "Balance error [%]";
        f.panel[1].xlabel = "Time t [s]";
        f.panel[1].include_zero = 1;
        char *relab = bd_rep_label(r);
        char rv[64];
        bd_rep_fmt_num(rv, sizeof rv, ref / ue.scale);
        snprintf(relab, BD_REP_LABEL_LEN, "balance error relative to %s %s (largest of |E0|, input, kinetic)",
                 rv, ue.name);
        bd_plot_add_series(&f.panel[1], t, rel, n, relab, (bd_rgb){0.8, 0.0, 0.0});
        return bd_rep_write_plot(r, &f, "energy",
                                 "Kinetic, potential, dissipated and input energy as changes "
                                 "from the start, and the energy balance error.",
                                 err, errlen);
    }
    return 0;
oom:
    bd_rep_err(err, errlen, "out of memory");
    return BD_REPORT_EOUTPUT;
}

static int plot_history(bd_rep *r, char *err, size_t errlen)
{
    char path[BD_REP_PATH_LEN];
    if (bd_path_join(path, sizeof path, r->dir, "history.csv") || !bd_rep_file_exists(path)) return 0;
    bd_csv h;
    if (bd_csv_read(path, NULL, 0, &h, err, errlen)) return BD_REPORT_EINPUT;
    int rc = 0, have_parts = 0;
    bd_csv parts;
    memset(&parts, 0, sizeof parts);
    if (h.ncols < 1 || strcmp(h.names[0], "t_s") != 0) {
        bd_rep_err(err, errlen, "%s:1: the first column is not t_s", path);
        rc = BD_REPORT_EINPUT;
        goto done;
    }
    if (h.nrows == 0) goto done;
    have_parts = read_parts(r, &parts, err, errlen);
    if (have_parts < 0) {
        rc = BD_REPORT_EINPUT;
        goto done;
    }
    char *title[3], *yl[6];
    for (int i = 0; i < 3; i++) title[i] = bd_rep_label(r);
    for (int i = 0; i < 6; i++) yl[i] = bd_rep_label(r);
    group g;
    bd_rep_unit u[5];
    memset(u, 0, sizeof u);

    /* probes: tension and speed */
    find_group(&h, ".tension_N", ".speed_mps", &g);
    if (g.n > 0) {
        bd_plot_figure f;
        bd_rep_set_title(r, title[0], BD_REP_LABEL_LEN, "belt tension and speed at the probes");
        bd_plot_figure_init(&f, title[0], BD_REP_FIG_W, BD_REP_FIG_H + 100);
        f.npanels = 2;
        f.share_x = 1;
        f.panel[1].xlabel = "Time t [s]";
        if (fill_panel(r, &f.panel[0], &h, &g, 0, "Belt tension T", "N", yl[0], BD_REP_LABEL_LEN, 0, &u[0]) < 0 ||
            fill_panel(r, &f.panel[1], &h, &g, 1, "Belt speed v", "m/s", yl[1], BD_REP_LABEL_LEN, 0, &u[1]) < 0)
            goto oom;
        f.panel[0].include_zero = 1;
        mark_extreme(r, &f.panel[0], "peak", u[0].name, 0, "probes", "tension_max_N", u[0].scale);
        if (f.panel[1].nseries == 0) f.npanels = 1, f.panel[0].xlabel = "Time t [s]";
        if ((rc = bd_rep_write_plot(r, &f, "probes",
                             "Belt tension and speed against time at the probes of the model.", err,
                             errlen)))
            goto done;
    }

    /* drives: speed, torque, power and the friction they use */
    find_group(&h, ".omega_rad_s", ".torque_Nm", &g);
    if (g.n > 0) {
        bd_plot_figure f;
        bd_rep_set_title(r, title[1], BD_REP_LABEL_LEN, "drive pulleys");
        bd_plot_figure_init(&f, title[1], BD_REP_FIG_W, BD_REP_FIG_H + 100);
        f.npanels = 4;
        f.share_x = 1;
        double pct_scale = NAN;
        int speed_ok = drive_speed_panel(r, &f.panel[0], &h, &g, yl[2]);
        int pct = speed_ok < 0 ? -1
                : drive_torque_percent_panel(r, &f.panel[1], &h, &g, yl[3], &pct_scale);
        if (speed_ok < 0 || pct < 0 ||
            (!speed_ok && fill_panel(r, &f.panel[0], &h, &g, 0, "Pulley speed ω", "rad/s", yl[2],
                                     BD_REP_LABEL_LEN, 0, &u[2]) < 0) ||
            (!pct && fill_panel(r, &f.panel[1], &h, &g, 1, "Drive torque M", "N·m", yl[3],
                                BD_REP_LABEL_LEN, 0, &u[3]) < 0) ||
            drive_power_panel(r, &f.panel[2], &h, &g, bd_rep_label(r)) < 0 ||
            drive_friction_panel(r, &f.panel[3], &g, have_parts ? &parts : NULL, bd_rep_label(r)) < 0)
            goto oom;
        if (pct)
            mark_extreme(r, &f.panel[1], "peak", "%", 1, isfinite(pct_scale) ? "pulleys" : NULL,
                         "torque_max_Nm", pct_scale);
        else
            mark_extreme(r, &f.panel[1], "peak", u[3].name, 1, "pulleys", "torque_max_Nm",
                         u[3].scale);
        mark_extreme(r, &f.panel[2], "peak", "kW", 1, NULL, NULL, 0.0);
        mark_extreme(r, &f.panel[3], "most", "%", 0, "pulleys", "friction_used_max_pct", 1.0);
        /* the panels that have curves, top to bottom */
        int np = 0;
        for (int k = 0; k < 4; k++)
            if (f.panel[k].nseries > 0) f.panel[np++] = f.panel[k];
        f.npanels = np > 0 ? np : 1;
        f.height = BD_REP_FIG_H + 100 + 200 * (f.npanels - 2 > 0 ? f.npanels - 2 : 0);
        f.panel[f.npanels - 1].xlabel = "Time t [s]";
        f.panel[f.npanels - 1].include_zero = 1;
        char *cap = bd_rep_label(r);
        snprintf(cap, BD_REP_LABEL_LEN, "%s%s%s",
                 speed_ok ? "Belt speed at the drive pulleys (ω·R), their torque"
                          : "Angular speed of the drive pulleys, their torque",
                 pct ? " as a share of its rating (the motor's rated torque, else max_torque; "
                       "dashed: 100 %)" : "",
                 f.npanels == 4 ? ", the power they deliver (M·ω) and the friction they use "
                                  "against time: ln(T₁/T₂) over μ·φ (μ the static friction, φ the "
                                  "wrap, as the layout table gives them), the belt slips at 100 %."
                                : " and the power they deliver (M·ω) against time.");
        if ((rc = bd_rep_write_plot(r, &f, "drives", cap, err, errlen)))
            goto done;
    }

    /* takeups: travel, and the belt's pull on the carriage */
    find_group(&h, ".travel_m", NULL, &g);
    if (g.n > 0) {
        bd_plot_figure f;
        bd_rep_set_title(r, title[2], BD_REP_LABEL_LEN, "takeups");
        bd_plot_figure_init(&f, title[2], BD_REP_FIG_W, BD_REP_FIG_H);
        f.subtitle = "carriage travel along its axis from the initial position, and the belt's "
                     "pull on it";
        f.share_x = 1;
        if (fill_panel(r, &f.panel[0], &h, &g, 0, "Takeup travel x", "m", yl[4], BD_REP_LABEL_LEN, 1, &u[4]) < 0)
            goto oom;
        mark_extreme(r, &f.panel[0], "largest", u[4].name, 1, NULL, NULL, 0.0);
        f.panel[0].include_zero = 1;
        group gp;
        if (have_parts) find_group(&parts, ".pull_N", NULL, &gp);
        if (have_parts && gp.n > 0) {
            if (fill_panel(r, &f.panel[1], &parts, &gp, 0, "Belt pull on the takeup F", "N",
                           yl[5], BD_REP_LABEL_LEN, 1, &u[1]) < 0)
                goto oom;
            mark_extreme(r, &f.panel[1], "largest", u[1].name, 1, NULL, NULL, 0.0);
            f.npanels = 2;
            f.height = BD_REP_FIG_H + 100;
        }
        f.panel[f.npanels - 1].xlabel = "Time t [s]";
        if ((rc = bd_rep_write_plot(r, &f, "takeups",
                             f.npanels == 2 ? "Takeup carriage travel and the belt's pull on the "
                                              "carriage along its axis against time (legend: "
                                              "lowest … highest)."
                                            : "Takeup carriage travel against time (legend: "
                                              "lowest … highest).", err, errlen)))
            goto done;
    }

    /* a belt whose topology varies (the rfe belt's long sections): its
     * degrees of freedom */
    int cdof = bd_csv_find(&h, "belt_dof");
    if (cdof >= 0 && h.nrows > 0) {
        bd_plot_figure f;
        char *t = bd_rep_label(r);
        bd_rep_set_title(r, t, BD_REP_LABEL_LEN, "belt degrees of freedom");
        bd_plot_figure_init(&f, t, BD_REP_FIG_W, BD_REP_FIG_H);
        f.subtitle = "free elements (3 each) and long sections (2 each), as the belt flows "
                     "through the sections' windows";
        f.npanels = 1;
        f.panel[0].ylabel = "Belt degrees of freedom";
        f.panel[0].xlabel = "Time t [s]";
        f.panel[0].include_zero = 1;
        bd_plot_add_series(&f.panel[0], h.col[0], h.col[cdof], h.nrows, "belt", bd_plot_palette(0));
        if ((rc = bd_rep_write_plot(r, &f, "topology",
                                    "The belt's active degrees of freedom against time: 3 per "
                                    "free rigid element (x, y, φ), 2 per long section (its two "
                                    "ends along its line; docs/physics.md §15).",
                                    err, errlen)))
            goto done;
    }

    /* energy: changes from t = 0 and the balance error */
    if ((rc = bd_rep_plot_energy(r, &h, "input (drive work)", err, errlen)))
        goto done;
    goto done;
oom:
    bd_rep_err(err, errlen, "out of memory");
    rc = BD_REPORT_EOUTPUT;
done:
    bd_csv_free(&h);
    if (have_parts > 0) bd_csv_free(&parts);
    return rc;
}

/* ---- report.html ---- */


/* a key like "tension_max_N" split into "tension max" and "N" (unit NULL
 * when the key has no unit suffix) */
static const char *key_split(char *base, size_t len, const char *key)
{
    static const struct {
        const char *sfx, *unit;
    } units[] = {{"_rad_s", "rad/s"}, {"_mps2", "m/s²"}, {"_mps", "m/s"}, {"_Nm", "N·m"},
                 {"_kW", "kW"},       {"_N", "N"},        {"_J", "J"},     {"_s", "s"},
                 {"_m", "m"},         {"_deg", "°"},      {"_rel", "relative"}};
    const char *unit_name = NULL;
    size_t n = strlen(key);
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
        if (ends_with(key, units[i].sfx)) {
            unit_name = units[i].unit;
            n -= strlen(units[i].sfx);
            break;
        }
    snprintf(base, len, "%.*s", (int)n, key);
    for (char *p = base; *p; p++)
        if (*p == '_') *p = ' ';
    return unit_name;
}

/* "tension_max_N" as "tension max [N]"; parent: the enclosing key, whose
 * unit applies when the key has none ("resistances_N": {"main": ..}) */
static void key_label2(char *buf, size_t len, const char *parent, const char *key)
{
    char b[128], pb[128];
    const char *unit_name = key_split(b, sizeof b, key);
    if (parent) {
        const char *pu = key_split(pb, sizeof pb, parent);
        if (!unit_name) unit_name = pu;
        if (unit_name) snprintf(buf, len, "%s: %s [%s]", pb, b, unit_name);
        else snprintf(buf, len, "%s: %s", pb, b);
    } else {
        if (unit_name) snprintf(buf, len, "%s [%s]", b, unit_name);
        else snprintf(buf, len, "%s", b);
    }
}

static void key_label(char *buf, size_t len, const char *key) { key_label2(buf, len, NULL, key); }

static void html_value(bd_strbuf *b, const cJSON *v)
{
    char num[64];
    if (cJSON_IsNumber(v)) {
        bd_rep_fmt_num(num, sizeof num, v->valuedouble);
        bd_sb_puts(b, num);
    } else if (cJSON_IsString(v)) {
        bd_sb_html(b, v->valuestring);
    } else if (cJSON_IsBool(v)) {
        bd_sb_puts(b, cJSON_IsTrue(v) ? "yes" : "no");
    } else if (cJSON_IsNull(v)) {
        bd_sb_puts(b, "—");
    } else {
        char *s = cJSON_PrintUnformatted(v);
        bd_sb_html(b, s ? s : "");
        free(s);
    }
}

static int is_scalar(const cJSON *v) { return !cJSON_IsObject(v) && !cJSON_IsArray(v); }

/* a table of rows (objects) by name or index: one column per key seen */
static void html_row_table(bd_strbuf *b, const cJSON *rows, const char *first)
{
    const char *keys[32];
    int nk = 0;
    const cJSON *row, *v;
    cJSON_ArrayForEach(row, rows) {
        cJSON_ArrayForEach(v, row) {
            int k;
            if (!v->string || !is_scalar(v)) continue;
            for (k = 0; k < nk; k++)
                if (strcmp(keys[k], v->string) == 0) break;
            if (k == nk && nk < 32) keys[nk++] = v->string;
        }
    }
    bd_sb_puts(b, "<table><tr>");
    if (first) {
        bd_sb_puts(b, "<th>");
        bd_sb_html(b, first);
        bd_sb_puts(b, "</th>");
    }
    for (int k = 0; k < nk; k++) {
        char lab[160];
        key_label(lab, sizeof lab, keys[k]);
        bd_sb_puts(b, "<th>");
        bd_sb_html(b, lab);
        bd_sb_puts(b, "</th>");
    }
    bd_sb_puts(b, "</tr>\n");
    cJSON_ArrayForEach(row, rows) {
        bd_sb_puts(b, "<tr>");
        if (first) {
            bd_sb_puts(b, "<th>");
            bd_sb_html(b, row->string ? row->string : "");
            bd_sb_puts(b, "</th>");
        }
        for (int k = 0; k < nk; k++) {
            const cJSON *c = cJSON_GetObjectItemCaseSensitive(row, keys[k]);
            bd_sb_puts(b, cJSON_IsNumber(c) ? "<td class=n>" : "<td>");
            if (c) html_value(b, c);
            bd_sb_puts(b, "</td>");
        }
        bd_sb_puts(b, "</tr>\n");
    }
    bd_sb_puts(b, "</table>\n");
}

/* an object as tables: scalars (and objects of scalars, prefixed) as
 * name/value rows; objects of objects and arrays of objects as their own
 * tables; lists of strings as lists. skip: keys left out */
static void html_object(bd_strbuf *b, const cJSON *obj, const char *const *skip, int nskip)
{
    const cJSON *v;
    int open = 0;
    cJSON_ArrayForEach(v, obj) {
        int s = 0;
        for (int i = 0; i < nskip; i++)
            if (v->string && strcmp(v->string, skip[i]) == 0) s = 1;
        if (s) continue;
        const cJSON *inner[16];
        int ni = 0;
        if (is_scalar(v)) {
            inner[ni++] = v;
        } else if (cJSON_IsObject(v)) {
            const cJSON *c;
            int all = 1;
            cJSON_ArrayForEach(c, v) if (!is_scalar(c)) all = 0;
            if (!all) continue;
            cJSON_ArrayForEach(c, v) if (ni < 16) inner[ni++] = c;
        } else {
            continue;
        }
        for (int i = 0; i < ni; i++) {
            char full[300];
            if (!open) {
                bd_sb_puts(b, "<table><tr><th>quantity</th><th>value</th></tr>\n");
                open = 1;
            }
            key_label2(full, sizeof full, inner[i] != v ? v->string : NULL,
                       inner[i]->string ? inner[i]->string : "");
            bd_sb_puts(b, "<tr><th>");
            bd_sb_html(b, full);
            bd_sb_puts(b, cJSON_IsNumber(inner[i]) ? "</th><td class=n>" : "</th><td>");
            html_value(b, inner[i]);
            bd_sb_puts(b, "</td></tr>\n");
        }
    }
    if (open) bd_sb_puts(b, "</table>\n");
    /* nested tables */
    cJSON_ArrayForEach(v, obj) {
        int s = 0;
        for (int i = 0; i < nskip; i++)
            if (v->string && strcmp(v->string, skip[i]) == 0) s = 1;
        if (s || is_scalar(v)) continue;
        const cJSON *c = v->child;
        if (!c) continue;
        if (cJSON_IsObject(v) && cJSON_IsObject(c)) {
            bd_sb_puts(b, "<h3>");
            bd_sb_html(b, v->string);
            bd_sb_puts(b, "</h3>\n");
            html_row_table(b, v, v->string);
        } else if (cJSON_IsArray(v) && cJSON_IsObject(c)) {
            bd_sb_puts(b, "<h3>");
            bd_sb_html(b, v->string);
            bd_sb_puts(b, "</h3>\n");
            html_row_table(b, v, NULL);
        } else if (cJSON_IsArray(v)) {
            bd_sb_puts(b, "<h3>");
            bd_sb_html(b, v->string);
            bd_sb_puts(b, "</h3><ul>\n");
            cJSON_ArrayForEach(c, v) {
                bd_sb_puts(b, "<li>");
                html_value(b, c);
                bd_sb_puts(b, "</li>\n");
            }
            bd_sb_puts(b, "</ul>\n");
        }
    }
}


void bd_rep_card(bd_strbuf *b, const char *cls, const char *key, const char *value, const char *detail)
{
    bd_sb_printf(b, "<div class=\"card%s%s\"><div class=k>", cls ? " " : "", cls ? cls : "");
    bd_sb_html(b, key);
    bd_sb_puts(b, "</div><div class=v>");
    bd_sb_html(b, value);
    bd_sb_puts(b, "</div><div class=d>");
    bd_sb_html(b, detail);
    bd_sb_puts(b, "</div></div>\n");
}

/* lowest and highest of a history column, or NaN */
static void history_range(const char *dir, const char *column, double *lo, double *hi)
{
    char path[BD_REP_PATH_LEN], err[256];
    const char *want[1] = {column};
    bd_csv c;
    *lo = *hi = NAN;
    if (bd_path_join(path, sizeof path, dir, "history.csv") || bd_csv_read(path, want, 1, &c, err, sizeof err)) return;
    for (size_t i = 0; i < c.nrows; i++) {
        double v = c.col[0][i];
        if (!isfinite(v)) continue;
        if (!(v >= *lo)) *lo = v;
        if (!(v <= *hi)) *hi = v;
    }
    bd_csv_free(&c);
}

/* the run's warnings and the static design's (summary.json "static"), one
 * count for the card and the list */
static const cJSON *static_warnings(const bd_rep *r)
{
    const cJSON *stat = cJSON_GetObjectItemCaseSensitive(r->summary, "static");
    return cJSON_GetObjectItemCaseSensitive(stat, "warnings");
}

static int warning_count(const bd_rep *r)
{
    const cJSON *warn = cJSON_GetObjectItemCaseSensitive(r->summary, "warnings");
    return cJSON_GetArraySize(warn) + cJSON_GetArraySize(static_warnings(r));
}

static void warning_items(bd_strbuf *b, const cJSON *list, const char *prefix)
{
    const cJSON *w;
    cJSON_ArrayForEach(w, list) {
        bd_sb_puts(b, "<li>");
        bd_sb_puts(b, prefix);
        html_value(b, w);
        bd_sb_puts(b, "</li>\n");
    }
}

void bd_rep_run_cards(bd_rep *r, bd_strbuf *b)
{
    char v[64];
    const cJSON *energy = cJSON_GetObjectItemCaseSensitive(r->summary, "energy");
    double be = bd_json_num(energy, "balance_error_rel");
    if (isfinite(be)) {
        snprintf(v, sizeof v, "%.3g %%", 100.0 * be);
        bd_rep_card(b, be > 0.01 ? "bad" : "ok", "energy balance error", v,
             "largest over the run, relative");
    }
    /* the rfe chain let go where the layout lays it (sim/stabilize.c) */
    const cJSON *settle = cJSON_GetObjectItemCaseSensitive(r->summary, "settle");
    if (settle) {
        snprintf(v, sizeof v, "%.3g J", bd_json_num(settle, "released_J"));
        char note[96];
        snprintf(note, sizeof note, "let go before t = 0 in %.0f steps where the layout lays "
                 "the belt", bd_json_num(settle, "steps"));
        bd_rep_card(b, NULL, "settled", v, note);
    }
    /* steady running against the model's own law (sensors/running.c) */
    const cJSON *rf = cJSON_GetObjectItemCaseSensitive(r->summary, "running_force");
    if (rf) {
        double e = bd_json_num(rf, "error_rel"), tol = bd_json_num(rf, "tolerance_rel");
        if (cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(rf, "checked")) && isfinite(e)
            && isfinite(tol)) {
            char note[96];
            snprintf(v, sizeof v, "%+.1f %%", 100.0 * e);
            snprintf(note, sizeof note, "steady drive force against the model's own law "
                     "(within %.0f %%)", 100.0 * tol);
            bd_rep_card(b, fabs(e) > tol ? "bad" : "ok", "running force", v, note);
        } else {
            bd_rep_card(b, NULL, "running force", "not checked",
                        "the run does not end in steady running (summary.json says why)");
        }
    }
    /* the mesh check (io/mesh_check.c; run --mesh-check) */
    const cJSON *mc = cJSON_GetObjectItemCaseSensitive(r->summary, "mesh_check");
    const cJSON *conv = cJSON_GetObjectItemCaseSensitive(mc, "converged");
    if (cJSON_IsBool(conv)) {
        const cJSON *mesh = cJSON_GetObjectItemCaseSensitive(mc, "mesh");
        bd_rep_card(b, cJSON_IsTrue(conv) ? "ok" : "bad", "mesh check",
                    cJSON_IsTrue(conv) ? "converged" : "not converged",
                    cJSON_IsString(mesh) ? mesh->valuestring : "");
    }
    int nw = warning_count(r);
    snprintf(v, sizeof v, "%d", nw);
    bd_rep_card(b, nw ? "bad" : "ok", "warnings", v,
                nw ? (static_warnings(r) ? "the run's and the static design's, listed below"
                                         : "listed below")
                   : "none");
}

static void headline(bd_rep *r, bd_strbuf *b)
{
    char v[128], d[BD_REP_LABEL_LEN];
    bd_sb_puts(b, "<div class=cards>\n");
    double allow = isfinite(r->rated_N) ? r->rated_N / r->safety_factor : NAN;
    if (r->tmax.known) {
        bd_rep_unit u = bd_rep_pick_unit(fabs(r->tmax.value), "N");
        char num[64];
        bd_rep_fmt_num(num, sizeof num, r->tmax.value / u.scale);
        snprintf(v, sizeof v, "%s %s", num, u.name);
        int n = snprintf(d, sizeof d, "at t = %.3g s, s = %.1f m", r->tmax.t, r->tmax.s);
        if (isfinite(allow) && n > 0 && (size_t)n < sizeof d)
            snprintf(d + n, sizeof d - (size_t)n, "; %.0f %% of the allowable in starts and "
                     "stops (rated / %.3g%s)",
                     100.0 * r->tmax.value / allow, r->safety_factor,
                     r->sf_default ? ", default" : "");
        bd_rep_card(b, isfinite(allow) ? (r->tmax.value > allow ? "bad" : "ok") : NULL,
             "peak belt tension", v, d);
    }
    if (r->tmin.known) {
        bd_rep_unit u = bd_rep_pick_unit(fabs(r->tmin.value), "N");
        char num[64];
        bd_rep_fmt_num(num, sizeof num, r->tmin.value / u.scale);
        snprintf(v, sizeof v, "%s %s", num, u.name);
        int n = snprintf(d, sizeof d, "at t = %.3g s, s = %.1f m", r->tmin.t, r->tmin.s);
        int bad = r->tmin.value <= 0.0;
        if (isfinite(r->t_min_sag_N) && n > 0 && (size_t)n < sizeof d) {
            char sg[64];
            bd_rep_unit us = bd_rep_pick_unit(r->t_min_sag_N, "N");
            bd_rep_fmt_num(sg, sizeof sg, r->t_min_sag_N / us.scale);
            snprintf(d + n, sizeof d - (size_t)n, "; sag limit needs %s %s", sg, us.name);
            if (r->tmin.value < r->t_min_sag_N) bad = 1;
        }
        bd_rep_card(b, bad ? "bad" : NULL, "lowest belt tension", v, d);
    }
    /* takeups and drives from summary.pulleys, else from history.csv */
    const cJSON *pulleys = cJSON_GetObjectItemCaseSensitive(r->summary, "pulleys");
    const cJSON *p;
    cJSON_ArrayForEach(p, pulleys) {
        double lo = bd_json_num(p, "travel_min_m"), hi = bd_json_num(p, "travel_max_m");
        if (isfinite(lo) || isfinite(hi)) {
            char a1[64], a2[64], a3[64];
            bd_rep_fmt_num(a1, sizeof a1, lo);
            bd_rep_fmt_num(a2, sizeof a2, hi);
            bd_rep_fmt_num(a3, sizeof a3, hi - lo);
            snprintf(v, sizeof v, "%s m", a3);
            snprintf(d, sizeof d, "%s: from %s m to %s m", p->string, a1, a2);
            bd_rep_card(b, NULL, "takeup travel range", v, d);
        }
    }
    cJSON_ArrayForEach(p, pulleys) {
        double tq = bd_json_num(p, "torque_max_Nm");
        if (isfinite(tq)) {
            bd_rep_unit u = bd_rep_pick_unit(fabs(tq), "N·m");
            char num[64];
            bd_rep_fmt_num(num, sizeof num, tq / u.scale);
            snprintf(v, sizeof v, "%s %s", num, u.name);
            double w = bd_json_num(p, "omega_final_rad_s");
            if (isfinite(w)) snprintf(d, sizeof d, "%s; final speed %.4g rad/s", p->string, w);
            else snprintf(d, sizeof d, "%s", p->string);
            bd_rep_card(b, NULL, "drive peak torque", v, d);
        }
    }
    if (!cJSON_IsObject(pulleys) || !pulleys->child) {
        /* no pulley summary: take the ranges from history.csv */
        char path[BD_REP_PATH_LEN];
        bd_csv hd;
        char err[256];
        if (!bd_path_join(path, sizeof path, r->dir, "history.csv") && bd_rep_file_exists(path) &&
            !bd_csv_read_header(path, &hd, err, sizeof err)) {
            for (int j = 0; j < hd.ncols; j++) {
                double lo, hi;
                const char *nm = hd.names[j];
                if (ends_with(nm, ".travel_m")) {
                    history_range(r->dir, nm, &lo, &hi);
                    char a1[64], a2[64], a3[64];
                    bd_rep_fmt_num(a1, sizeof a1, lo);
                    bd_rep_fmt_num(a2, sizeof a2, hi);
                    bd_rep_fmt_num(a3, sizeof a3, hi - lo);
                    snprintf(v, sizeof v, "%s m", a3);
                    snprintf(d, sizeof d, "%.*s: from %s m to %s m",
                             (int)(strlen(nm) - strlen(".travel_m")), nm, a1, a2);
                    bd_rep_card(b, NULL, "takeup travel range", v, d);
                } else if (ends_with(nm, ".torque_Nm")) {
                    history_range(r->dir, nm, &lo, &hi);
                    double tq = fabs(hi) >= fabs(lo) ? hi : lo;
                    bd_rep_unit u = bd_rep_pick_unit(fabs(tq), "N·m");
                    char num[64];
                    bd_rep_fmt_num(num, sizeof num, tq / u.scale);
                    snprintf(v, sizeof v, "%s %s", num, u.name);
                    snprintf(d, sizeof d, "%.*s", (int)(strlen(nm) - strlen(".torque_Nm")), nm);
                    bd_rep_card(b, NULL, "drive peak torque", v, d);
                }
            }
            bd_csv_free(&hd);
        }
    }
    bd_rep_run_cards(r, b);
    bd_sb_puts(b, "</div>\n");
}

/* a check's limit_is as a sign: at most ≤, at least ≥, below <, above > */
static const char *rule_sign(const char *limit_is)
{
    return strcmp(limit_is, "at least") == 0 ? "≥" : strcmp(limit_is, "below") == 0 ? "<"
         : strcmp(limit_is, "above") == 0 ? ">" : "≤";
}

int bd_rep_write_html(bd_rep *r, const char *what, void (*cards)(bd_rep *, bd_strbuf *),
                      char *err, size_t errlen)
{
    bd_strbuf b = {0};
    bd_sb_puts(&b, "<!DOCTYPE html>\n<html lang=en><head><meta charset=utf-8>\n"
                "<meta name=viewport content=\"width=device-width, initial-scale=1\">\n<title>");
    bd_sb_html(&b, r->model);
    bd_sb_puts(&b, " — beltdyn report</title>\n<style>");
    bd_sb_puts(&b, bd_html_css);
    bd_sb_puts(&b, "</style></head><body><main>\n<h1>");
    bd_sb_html(&b, r->model);
    bd_sb_printf(&b, "</h1>\n<p class=sub>beltdyn %s", what);
    double dur = bd_json_num(r->summary, "duration_s"), len = bd_json_num(r->summary, "belt_length_m");
    if (isfinite(dur)) bd_sb_printf(&b, " · %.4g s simulated", dur);
    if (isfinite(len)) bd_sb_printf(&b, " · belt length %.1f m", len);
    double nodes = bd_json_num(r->summary, "nodes");
    if (isfinite(nodes)) bd_sb_printf(&b, " · %.0f nodes", nodes);
    bd_sb_puts(&b, "</p>\n<nav>");
    bd_sb_puts(&b, "<a href=\"#plots\">plots</a><a href=\"#summary\">summary</a>");
    const cJSON *stat = cJSON_GetObjectItemCaseSensitive(r->summary, "static");
    if (cJSON_IsObject(stat)) bd_sb_puts(&b, "<a href=\"#static\">static design</a>");
    bd_sb_puts(&b, "</nav>\n");

    cards(r, &b);

    /* the pass/fail table (summary.json "checks", io/checks.c) */
    const cJSON *checks = cJSON_GetObjectItemCaseSensitive(r->summary, "checks");
    if (cJSON_IsArray(checks) && cJSON_GetArraySize(checks) > 0) {
        bd_sb_puts(&b, "<h2 id=checks>Checks</h2>\n<table><tr><th>check</th><th>result</th>"
                       "<th>value</th><th>limit</th><th>unit</th></tr>\n");
        const cJSON *c;
        cJSON_ArrayForEach(c, checks) {
            int pass = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(c, "pass"));
            bd_sb_puts(&b, "<tr><td>");
            bd_sb_html(&b, bd_json_str(c, "check"));
            bd_sb_printf(&b, "</td><td class=%s>%s</td>", pass ? "ok" : "bad",
                         pass ? "pass" : "FAIL");
            bd_sb_json_cell(&b, cJSON_GetObjectItemCaseSensitive(c, "value"));
            bd_sb_printf(&b, "<td class=n>%s %.4g</td>", rule_sign(bd_json_str(c, "limit_is")),
                         bd_json_num(c, "limit"));
            bd_sb_puts(&b, "<td>");
            bd_sb_html(&b, bd_json_str(c, "unit"));
            bd_sb_puts(&b, "</td></tr>\n");
        }
        bd_sb_puts(&b, "</table>\n");
    }

    /* warnings: the run's, then the static design's */
    const cJSON *warn = cJSON_GetObjectItemCaseSensitive(r->summary, "warnings");
    bd_sb_puts(&b, "<h2 id=warnings>Warnings</h2>\n");
    if (warning_count(r) > 0) {
        bd_sb_puts(&b, "<ul class=warn>\n");
        warning_items(&b, warn, "");
        warning_items(&b, static_warnings(r), "static design: ");
        bd_sb_puts(&b, "</ul>\n");
    } else {
        bd_sb_puts(&b, "<p class=none>No warnings.</p>\n");
    }

    /* plots */
    bd_sb_puts(&b, "<h2 id=plots>Plots</h2>\n");
    if (r->nplots == 0) bd_sb_puts(&b, "<p class=none>No data to plot in this run directory.</p>\n");
    for (int i = 0; i < r->nplots; i++) {
        char png[BD_REP_PATH_LEN];
        if (snprintf(png, sizeof png, "%s/%s.png", r->plots, r->plot[i].name) >= (int)sizeof png)
            continue;
        bd_sb_printf(&b, "<figure id=\"%s\"><img alt=\"%s\" src=\"", r->plot[i].name, r->plot[i].name);
        if (bd_sb_embed_png(&b, png)) {
            free(b.p);
            bd_rep_err(err, errlen, "%s: cannot read back", png);
            return BD_REPORT_EOUTPUT;
        }
        bd_sb_puts(&b, "\"><figcaption>");
        bd_sb_html(&b, r->plot[i].caption);
        bd_sb_printf(&b, " (also plots/%s.svg)</figcaption></figure>\n", r->plot[i].name);
    }

    /* summary */
    bd_sb_puts(&b, "<h2 id=summary>Run summary</h2>\n");
    static const char *const skip[3] = {"warnings", "static", "model"};
    html_object(&b, r->summary, skip, 3);

    /* static design table */
    if (cJSON_IsObject(stat)) {
        bd_sb_puts(&b, "<h2 id=static>Static design calculation</h2>\n");
        html_object(&b, stat, NULL, 0);
    }
    return bd_html_page_finish(&b, r->dir, err, errlen) ? BD_REPORT_EOUTPUT : 0;
}

/* ---- entry ---- */

static int read_summary(bd_rep *r, char *err, size_t errlen)
{
    char path[BD_REP_PATH_LEN];
    if (bd_path_join(path, sizeof path, r->dir, "summary.json")) {
        bd_rep_err(err, errlen, "%s: path too long", r->dir);
        return BD_REPORT_EINPUT;
    }
    char *text;
    size_t len;
    int rd = bd_read_file(path, &text, &len);
    if (rd == BD_READ_OPEN) {
        bd_rep_err(err, errlen, "%s: %s (not the output directory of beltdyn run?)", path,
                strerror(errno));
        return BD_REPORT_EINPUT;
    }
    if (rd != BD_READ_OK || len == 0) {
        free(text);
        bd_rep_err(err, errlen, "%s: empty or unreadable", path);
        return BD_REPORT_EINPUT;
    }
    r->summary = cJSON_ParseWithLength(text, len);
    if (!r->summary || !cJSON_IsObject(r->summary)) {
        /* the line of the parse error */
        const char *at = cJSON_GetErrorPtr();
        int line = 1;
        if (at && at >= text && at <= text + len)
            for (const char *q = text; q < at; q++) line += *q == '\n';
        bd_rep_err(err, errlen, "%s:%d: not a JSON object", path, line);
        cJSON_Delete(r->summary);
        r->summary = NULL;
        free(text);
        return BD_REPORT_EINPUT;
    }
    free(text);

    const cJSON *model = cJSON_GetObjectItemCaseSensitive(r->summary, "model");
    if (cJSON_IsString(model) && model->valuestring[0])
        snprintf(r->model, sizeof r->model, "%s", model->valuestring);
    else snprintf(r->model, sizeof r->model, "%s", r->dir);

    /* design limits: top level, else from the static table */
    const cJSON *stat = cJSON_GetObjectItemCaseSensitive(r->summary, "static");
    r->rated_N = bd_json_num(r->summary, "rated_tension_N");
    r->safety_factor = bd_json_num(r->summary, "safety_factor_starting");
    if (!(r->safety_factor > 0.0))
        r->safety_factor = bd_json_num(r->summary, "safety_factor");   /* older outputs */
    r->t_min_sag_N = bd_json_num(r->summary, "T_min_sag_N");
    if (!isfinite(r->t_min_sag_N)) r->t_min_sag_N = bd_json_num(stat, "T_min_sag_N");
    if (!isfinite(r->rated_N)) r->rated_N = bd_json_num(stat, "rated_tension_N");
    /* the static table's "safety_factor" is rated / computed maximum tension,
     * an outcome, not the design factor: never take the allowable from it */
    if (!(r->rated_N > 0.0)) r->rated_N = NAN;
    if (!(r->t_min_sag_N > 0.0)) r->t_min_sag_N = NAN;
    if (!(r->safety_factor > 0.0)) {
        r->safety_factor = SAFETY_FACTOR_DEFAULT;
        r->sf_default = 1;
    }

    const cJSON *ten = cJSON_GetObjectItemCaseSensitive(r->summary, "tension");
    double v = bd_json_num(ten, "max_N");
    if (isfinite(v))
        r->tmax = (bd_rep_point){1, v, bd_json_num(ten, "max_time_s"), bd_json_num(ten, "max_s_m")};
    v = bd_json_num(ten, "min_N");
    if (isfinite(v))
        r->tmin = (bd_rep_point){1, v, bd_json_num(ten, "min_time_s"), bd_json_num(ten, "min_s_m")};
    return 0;
}

int bd_report_print_checks(const char *dir, FILE *f)
{
    char path[BD_REP_PATH_LEN];
    cJSON *root = bd_path_join(path, sizeof path, dir, "summary.json") ? NULL
                                                                        : bd_json_load(path);
    const cJSON *checks = cJSON_GetObjectItemCaseSensitive(root, "checks"), *c;
    if (!cJSON_IsArray(checks)) {
        cJSON_Delete(root);
        return -1;
    }
    int failed = 0, n = cJSON_GetArraySize(checks);
    cJSON_ArrayForEach(c, checks) failed += !cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(c, "pass"));
    fprintf(f, "checks: %d of %d failed\n", failed, n);
    cJSON_ArrayForEach(c, checks) {
        int pass = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(c, "pass"));
        fprintf(f, "  %-4s %-42s %12.5g %s %-12.5g %s\n", pass ? "pass" : "FAIL",
                bd_json_str(c, "check"), bd_json_num(c, "value"),
                rule_sign(bd_json_str(c, "limit_is")),
                bd_json_num(c, "limit"), bd_json_str(c, "unit"));
    }
    cJSON_Delete(root);
    return failed;
}

int bd_report_write(const char *dir, char *err, size_t errlen)
{
    bd_rep *r;
    struct stat st;
    int rc;
    if (err && errlen) err[0] = '\0';
    if (!dir || !dir[0]) {
        bd_rep_err(err, errlen, "no run directory given");
        return BD_REPORT_EINPUT;
    }
    if (stat(dir, &st) != 0) {
        bd_rep_err(err, errlen, "%s: %s", dir, strerror(errno));
        return BD_REPORT_EINPUT;
    }
    if (!S_ISDIR(st.st_mode)) {
        bd_rep_err(err, errlen, "%s: not a directory", dir);
        return BD_REPORT_EINPUT;
    }
    /* a start study's directory (beltdyn study): its own comparison report */
    char study_csv[BD_REP_PATH_LEN], summary[BD_REP_PATH_LEN], cases_csv[BD_REP_PATH_LEN];
    /* a load-cases directory (beltdyn cases): the cases compared */
    if (bd_path_join(cases_csv, sizeof cases_csv, dir, "cases.csv") == 0 && bd_rep_file_exists(cases_csv)
        && (bd_path_join(summary, sizeof summary, dir, "summary.json") != 0
            || !bd_rep_file_exists(summary)))
        return bd_cases_report_write(dir, err, errlen);
    if (bd_path_join(study_csv, sizeof study_csv, dir, "study.csv") == 0 && bd_rep_file_exists(study_csv) &&
        (bd_path_join(summary, sizeof summary, dir, "summary.json") != 0 || !bd_rep_file_exists(summary)))
        return bd_study_report_write(dir, err, errlen);
    r = calloc(1, sizeof *r);
    if (!r) {
        bd_rep_err(err, errlen, "out of memory");
        return BD_REPORT_EOUTPUT;
    }
    r->dir = dir;
    if ((rc = read_summary(r, err, errlen))) goto done;
    if (bd_path_join(r->plots, sizeof r->plots, dir, "plots")) {
        bd_rep_err(err, errlen, "%s: path too long", dir);
        rc = BD_REPORT_EINPUT;
        goto done;
    }
    if (mkdir(r->plots, 0777) != 0 && errno != EEXIST) {
        bd_rep_err(err, errlen, "%s: %s", r->plots, strerror(errno));
        rc = BD_REPORT_EOUTPUT;
        goto done;
    }
    if (strcmp(bd_json_str(r->summary, "kind"), "boom") == 0) {
        rc = bd_boom_report_write(r, err, errlen);
        goto done;
    }
    if ((rc = plot_layout(r, err, errlen))) goto done;
    if ((rc = plot_tension_surface(r, err, errlen))) goto done;
    if ((rc = plot_envelope(r, err, errlen))) goto done;
    if ((rc = plot_history(r, err, errlen))) goto done;
    rc = bd_rep_write_html(r, "transient run", headline, err, errlen);
done:
    for (int i = 0; i < r->nowned; i++) free(r->owned[i]);
    cJSON_Delete(r->summary);
    free(r);
    return rc;
}
