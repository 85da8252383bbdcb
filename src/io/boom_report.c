/* beltdyn report DIR of a boom run (summary.json "kind": "boom";
 * boom-format.md "Outputs of run", written by io/boom_run.c): from
 * history.csv the tip's path beside the rigid boom's and its deflection,
 * the cylinder, rope and pad forces and the energy balance over time; from
 * beams.csv the bending moment along each section and the boom's shape at
 * the start, at the largest bending moment and at the end; report.html
 * with the summary's figures as cards. Drawn with report.c's pieces
 * (report_internal.h). */
#include "io/report_internal.h"

#include "base/file.h"
#include "base/json_util.h"
#include "beltdyn/boom.h"
#include "beltdyn/report.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_TIMES 3
#define MAX_PADS (BD_BOOM_MAX_SECTIONS - 1)

/* history.csv's columns the boom report needs (boom-format.md and the
 * added tip_rigid.*, tip.deflection_m) */
enum { H_T, H_X, H_Y, H_RX, H_RY, H_DEF, H_CYL, H_LUFF, H_COUNT };
static const char *const h_names[H_COUNT] = {
    "t_s", "tip.x_m", "tip.y_m", "tip_rigid.x_m", "tip_rigid.y_m", "tip.deflection_m",
    "telescopic_cylinder_N", "luffing_N"};

/* beams.csv's columns read */
enum { B_T, B_SEC, B_S, B_X, B_Y, B_M, B_COUNT };
static const char *const b_names[B_COUNT] = {"t_s", "section", "s_m", "x_m", "y_m", "moment_Nm"};

typedef struct boom_rep {
    bd_rep *r;
    const cJSON *boom;        /* summary.json "boom" */
    bd_csv h;                 /* history.csv, every column */
    int hc[H_COUNT];          /* its columns above */
    bd_csv b;                 /* beams.csv, b_names */
    int ns;                   /* sections */
    int luff_moment;          /* luffing_N is the pivot moment, N·m */
    /* the times drawn from beams.csv: rows [a, e) of the block at t */
    int nt;
    struct {
        size_t a, e;
        double t;
        char label[96];
    } at[MAX_TIMES];
    /* the largest |moment| anywhere: row of beams.csv */
    size_t peak;
} boom_rep;

/* DIR/NAME when it is a file; else a message naming it */
static int need_file(const bd_rep *r, const char *name, char *path, size_t len, char *err,
                     size_t errlen)
{
    if (bd_path_join(path, len, r->dir, name)) {
        bd_rep_err(err, errlen, "%s: path too long", r->dir);
        return BD_REPORT_EINPUT;
    }
    if (!bd_rep_file_exists(path)) {
        bd_rep_err(err, errlen, "%s: missing: a boom run's directory has summary.json, "
                   "history.csv and beams.csv (boom-format.md)", path);
        return BD_REPORT_EINPUT;
    }
    return 0;
}

static int read_history(boom_rep *B, char *err, size_t errlen)
{
    char path[BD_REP_PATH_LEN];
    int rc = need_file(B->r, "history.csv", path, sizeof path, err, errlen);
    if (rc) return rc;
    if (bd_csv_read(path, NULL, 0, &B->h, err, errlen)) return BD_REPORT_EINPUT;
    for (int k = 0; k < H_COUNT; k++)
        if ((B->hc[k] = bd_csv_find(&B->h, h_names[k])) < 0) {
            bd_rep_err(err, errlen, "%s:1: no column '%s' (a boom run's history.csv has it)",
                       path, h_names[k]);
            return BD_REPORT_EINPUT;
        }
    if (B->hc[H_T] != 0) {
        bd_rep_err(err, errlen, "%s:1: the first column is not t_s", path);
        return BD_REPORT_EINPUT;
    }
    if (B->h.nrows == 0) {
        bd_rep_err(err, errlen, "%s: no rows after the header", path);
        return BD_REPORT_EINPUT;
    }
    return 0;
}

/* the row range of the block of equal times around row i */
static void block_of(const bd_csv *b, size_t i, size_t *a, size_t *e)
{
    const double *t = b->col[B_T];
    *a = i;
    while (*a > 0 && t[*a - 1] == t[i]) (*a)--;
    *e = i;
    while (*e < b->nrows && t[*e] == t[i]) (*e)++;
}

/* beams.csv: every row's time finite and not decreasing, its section a
 * whole number 1 … BD_BOOM_MAX_SECTIONS; the times to draw */
static int read_beams(boom_rep *B, char *err, size_t errlen)
{
    char path[BD_REP_PATH_LEN];
    int rc = need_file(B->r, "beams.csv", path, sizeof path, err, errlen);
    if (rc) return rc;
    if (bd_csv_read(path, b_names, B_COUNT, &B->b, err, errlen)) return BD_REPORT_EINPUT;
    size_t n = B->b.nrows;
    if (n == 0) {
        bd_rep_err(err, errlen, "%s: no rows after the header", path);
        return BD_REPORT_EINPUT;
    }
    const double *t = B->b.col[B_T], *sec = B->b.col[B_SEC], *M = B->b.col[B_M];
    double best = -1.0;
    B->ns = 0;
    for (size_t i = 0; i < n; i++) {
        /* line i + 2: the header is line 1 */
        if (!isfinite(t[i]) || (i > 0 && t[i] < t[i - 1])) {
            bd_rep_err(err, errlen, "%s:%zu: t_s %g is not a number, or is before the time of "
                       "the row above", path, i + 2, t[i]);
            return BD_REPORT_EINPUT;
        }
        if (!(sec[i] >= 1.0 && sec[i] <= BD_BOOM_MAX_SECTIONS) || sec[i] != floor(sec[i])) {
            bd_rep_err(err, errlen, "%s:%zu: section %g is not a section number 1 … %d", path,
                       i + 2, sec[i], BD_BOOM_MAX_SECTIONS);
            return BD_REPORT_EINPUT;
        }
        if ((int)sec[i] > B->ns) B->ns = (int)sec[i];
        if (isfinite(M[i]) && fabs(M[i]) > best) {
            best = fabs(M[i]);
            B->peak = i;
        }
    }
    /* the first time, the time of the largest |moment|, the last time */
    size_t a[3], e[3];
    block_of(&B->b, 0, &a[0], &e[0]);
    block_of(&B->b, B->peak, &a[1], &e[1]);
    block_of(&B->b, n - 1, &a[2], &e[2]);
    static const char *const why[3] = {"start", "largest |M|", "end"};
    B->nt = 0;
    for (int k = 0; k < 3; k++) {
        if (B->nt > 0 && B->at[B->nt - 1].a == a[k]) {
            /* the same time: both reasons on one line */
            size_t len = strlen(B->at[B->nt - 1].label);
            snprintf(B->at[B->nt - 1].label + len - 1, sizeof B->at[0].label - len + 1,
                     ", %s)", why[k]);
            continue;
        }
        B->at[B->nt].a = a[k];
        B->at[B->nt].e = e[k];
        B->at[B->nt].t = t[a[k]];
        snprintf(B->at[B->nt].label, sizeof B->at[0].label, "t = %.4g s (%s)", t[a[k]], why[k]);
        B->nt++;
    }
    return 0;
}

/* a figure of the model's name and WHAT, extra px higher than the usual */
static void figure_start(bd_rep *r, bd_plot_figure *f, const char *what, int extra,
                         const char *subtitle)
{
    char *title = bd_rep_label(r);
    bd_rep_set_title(r, title, BD_REP_LABEL_LEN, what);
    bd_plot_figure_init(f, title, BD_REP_FIG_W, BD_REP_FIG_H + extra);
    f->subtitle = subtitle;
}

/* ---- the tip's path and its deflection ---- */

static int plot_tip(boom_rep *B, char *err, size_t errlen)
{
    bd_rep *r = B->r;
    const bd_csv *h = &B->h;
    size_t n = h->nrows;
    char *ylabel = bd_rep_label(r), *m0 = bd_rep_label(r), *m1 = bd_rep_label(r);
    bd_plot_figure f;
    figure_start(r, &f, "tip path and deflection", 300,
                 "where the tip went, beside where the rigid boom would have it, drawn to "
                 "scale; below, the distance between the two");
    f.npanels = 2;
    bd_plot_axes *a = &f.panel[0];
    a->xlabel = "Horizontal x [m]";
    a->ylabel = "Height y [m]";
    a->aspect = 1.0;
    int k = bd_plot_add_series(a, h->col[B->hc[H_RX]], h->col[B->hc[H_RY]], n,
                               "tip of the rigid boom", (bd_rgb){0.45, 0.45, 0.45});
    a->series[k].dashed = 1;
    k = bd_plot_add_series(a, h->col[B->hc[H_X]], h->col[B->hc[H_Y]], n, "tip",
                           bd_plot_palette(0));
    a->series[k].width = 2.5;
    const double *t = h->col[0], *x = h->col[B->hc[H_X]], *y = h->col[B->hc[H_Y]];
    snprintf(m0, BD_REP_LABEL_LEN, "t = %.4g s", t[0]);
    snprintf(m1, BD_REP_LABEL_LEN, "t = %.4g s", t[n - 1]);
    bd_plot_add_marker(a, x[0], y[0], m0);
    bd_plot_add_marker(a, x[n - 1], y[n - 1], m1);

    /* the deflection, in mm when it stays below 0.1 m */
    const double *d = h->col[B->hc[H_DEF]];
    double dmax = 0.0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(d[i])) dmax = fmax(dmax, fabs(d[i]));
    int mm = dmax < 0.1;
    double scale = mm ? 1e-3 : 1.0;
    const char *un = mm ? "mm" : "m";
    double *dv = bd_rep_own(r, bd_rep_scaled(d, n, scale));
    if (!dv) {
        bd_rep_err(err, errlen, "out of memory");
        return BD_REPORT_EOUTPUT;
    }
    a = &f.panel[1];
    snprintf(ylabel, BD_REP_LABEL_LEN, "Tip deflection from the rigid boom [%s]", un);
    a->ylabel = ylabel;
    a->xlabel = "Time t [s]";
    a->include_zero = 1;
    bd_plot_add_series(a, t, dv, n, "distance of the tip from the rigid boom's tip",
                       bd_plot_palette(1));
    int bs;
    size_t bi;
    if (bd_rep_find_extreme(a, 1, -INFINITY, &bs, &bi))
        bd_rep_mark_sample(r, a, bs, bi, "largest", un, 1,
                           bd_json_num(B->boom, "tip_deflection_max_m") / scale);
    return bd_rep_write_plot(r, &f, "boom_tip",
                             "Top: the path of the boom's tip in the plane of the boom (solid) "
                             "and of the rigid boom's tip (dashed), at true scale. Bottom: the "
                             "tip's distance from where the rigid boom would have it "
                             "(tip.deflection_m) against time.",
                             err, errlen);
}

/* ---- cylinders and ropes ---- */

/* the columns of h named PREFIX<number>.SUFFIX in order, up to max;
 * names[i] (labels of r) "PREFIX<number> what" */
static int numbered_columns(bd_rep *r, const bd_csv *h, const char *prefix, const char *suffix,
                            const char *what, int *cols, const char **names, int max)
{
    int n = 0;
    size_t lp = strlen(prefix), ls = strlen(suffix);
    for (int j = 0; j < h->ncols && n < max; j++) {
        const char *nm = h->names[j];
        size_t len = strlen(nm);
        if (len <= lp + ls || strncmp(nm, prefix, lp) != 0 || strcmp(nm + len - ls, suffix) != 0)
            continue;
        int digits = (int)(len - lp - ls);
        if ((int)strspn(nm + lp, "0123456789") != digits) continue;
        char *label = bd_rep_label(r);
        snprintf(label, BD_REP_LABEL_LEN, "%.*s %s", (int)(len - ls), nm, what);
        cols[n] = j;
        names[n++] = label;
    }
    return n;
}

static int plot_cylinders(boom_rep *B, char *err, size_t errlen)
{
    bd_rep *r = B->r;
    const bd_csv *h = &B->h;
    int cols[BD_PLOT_MAX_SERIES];
    const char *names[BD_PLOT_MAX_SERIES];
    cols[0] = B->hc[H_CYL];
    names[0] = "telescopic cylinder";
    /* the ropes: their extend and retract forces while they fit */
    int re[MAX_PADS], rr[MAX_PADS];
    const char *ne[MAX_PADS], *nr[MAX_PADS];
    int ropes = numbered_columns(r, h, "rope", ".extend_N", "extend", re, ne, MAX_PADS);
    int ropes_r = numbered_columns(r, h, "rope", ".retract_N", "retract", rr, nr, MAX_PADS);
    int n = 1, half = (BD_PLOT_MAX_SERIES - 1) / 2, left_out = ropes > half || ropes_r > half;
    for (int k = 0; k < ropes && k < half; k++) cols[n] = re[k], names[n++] = ne[k];
    for (int k = 0; k < ropes_r && k < half; k++) cols[n] = rr[k], names[n++] = nr[k];
    char *yl0 = bd_rep_label(r), *yl1 = bd_rep_label(r);
    bd_plot_figure f;
    figure_start(r, &f, "cylinder and rope forces", 100,
                 B->luff_moment ? "the telescopic cylinder and the synchronising ropes; the "
                                  "moment that holds the luffing angle at the pivot"
                                : "the telescopic cylinder and the synchronising ropes; the "
                                  "luffing cylinder");
    f.npanels = 2;
    f.share_x = 1;
    bd_rep_unit u0, u1;
    const char *luff_name = B->luff_moment ? "moment at the pivot" : "luffing cylinder";
    if (bd_rep_columns_panel(r, &f.panel[0], h, cols, names, n, "Force F", "N", yl0,
                             BD_REP_LABEL_LEN, 1, &u0) < 0 ||
        bd_rep_columns_panel(r, &f.panel[1], h, &B->hc[H_LUFF], &luff_name, 1,
                             B->luff_moment ? "Luffing moment at the pivot M"
                                            : "Luffing cylinder force F",
                             B->luff_moment ? "N·m" : "N", yl1, BD_REP_LABEL_LEN, 1, &u1) < 0) {
        bd_rep_err(err, errlen, "out of memory");
        return BD_REPORT_EOUTPUT;
    }
    f.panel[0].include_zero = 1;
    f.panel[1].include_zero = 1;
    f.panel[1].xlabel = "Time t [s]";
    int bs;
    size_t bi;
    if (bd_rep_find_extreme(&f.panel[0], 1, -INFINITY, &bs, &bi))
        bd_rep_mark_sample(r, &f.panel[0], bs, bi, "largest", u0.name, 1,
                           bs == 0 ? bd_json_num(B->boom, "telescopic_cylinder_force_max_N") /
                                         u0.scale
                                   : NAN);
    if (bd_rep_find_extreme(&f.panel[1], 1, -INFINITY, &bs, &bi))
        bd_rep_mark_sample(r, &f.panel[1], bs, bi, "largest", u1.name, 1,
                           bd_json_num(B->boom, "luffing_force_max_N") / u1.scale);
    char *cap = bd_rep_label(r);
    snprintf(cap, BD_REP_LABEL_LEN,
             "Top: the telescopic cylinder's force and the ropes' (2:1 per stage: rope K "
             "extends or retracts section K + 1) against time. Bottom: luffing_N against time, "
             "%s. Legend: lowest … highest.%s",
             B->luff_moment ? "the moment about the pivot that holds the luffing angle (the "
                              "model has no luffing cylinder)"
                            : "the luffing cylinder's force",
             left_out ? " Only the first 5 ropes are drawn." : "");
    return bd_rep_write_plot(r, &f, "boom_cylinders", cap, err, errlen);
}

/* ---- pads ---- */

static int plot_pads(boom_rep *B, char *err, size_t errlen)
{
    bd_rep *r = B->r;
    const bd_csv *h = &B->h;
    static const char *const suffix[3] = {".inner_normal_N", ".outer_normal_N", ".friction_N"};
    static const char *const what[3] = {"inner", "outer", "friction"};
    static const char *const quantity[3] = {"Inner pads' normal force N",
                                            "Outer pads' normal force N", "Pad friction F"};
    bd_plot_figure f;
    figure_start(r, &f, "pad forces", 300,
                 "normal force of each pad on the section it slides on, and the friction "
                 "along the axis");
    f.share_x = 1;
    f.npanels = 0;
    bd_rep_unit u[3];
    int panel_of[3] = {-1, -1, -1}, left_out = 0;
    for (int q = 0; q < 3; q++) {
        int cols[MAX_PADS];
        const char *names[MAX_PADS];
        int n = numbered_columns(r, h, "pad", suffix[q], what[q], cols, names, MAX_PADS);
        if (n > BD_PLOT_MAX_SERIES) {
            n = BD_PLOT_MAX_SERIES;
            left_out = 1;
        }
        /* pad K has the same colour in every panel: its place in the list */
        bd_plot_axes *a = &f.panel[f.npanels];
        int got = bd_rep_columns_panel(r, a, h, cols, names, n, quantity[q], "N",
                                       bd_rep_label(r), BD_REP_LABEL_LEN, 1, &u[q]);
        if (got < 0) {
            bd_rep_err(err, errlen, "out of memory");
            return BD_REPORT_EOUTPUT;
        }
        if (got == 0) continue;
        a->include_zero = 1;
        panel_of[q] = f.npanels++;
    }
    if (f.npanels == 0) return 0;   /* a history without pad columns */
    f.panel[f.npanels - 1].xlabel = "Time t [s]";
    /* the largest normal force, inner or outer: summary.json's (from every
     * step) on the panel whose samples show it */
    int bs[3];
    size_t bi[3];
    double top[2] = {-INFINITY, -INFINITY};
    for (int q = 0; q < 3; q++) {
        int p = panel_of[q];
        if (p < 0 || !bd_rep_find_extreme(&f.panel[p], q == 2, -INFINITY, &bs[q], &bi[q])) {
            panel_of[q] = -1;
            continue;
        }
        if (q < 2) top[q] = f.panel[p].series[bs[q]].y[bi[q]] * u[q].scale;
    }
    double exact = bd_json_num(B->boom, "pad_normal_force_max_N");
    for (int q = 0; q < 3; q++) {
        if (panel_of[q] < 0) continue;
        int has_peak = q < 2 && top[q] >= top[1 - q];
        bd_rep_mark_sample(r, &f.panel[panel_of[q]], bs[q], bi[q], q == 2 ? "peak" : "largest",
                           u[q].name, q == 2, has_peak ? exact / u[q].scale : NAN);
    }
    char *cap = bd_rep_label(r);
    snprintf(cap, BD_REP_LABEL_LEN,
             "Pad K sits between section K and section K + 1. Inner: section K + 1's bottom "
             "pads against section K's inside; outer: section K's top pads against section "
             "K + 1's outside; friction: both pads' together, along the axis. Against time; "
             "legend: lowest … highest.%s",
             left_out ? " Only the first 12 pads are drawn." : "");
    return bd_rep_write_plot(r, &f, "boom_pads", cap, err, errlen);
}

/* ---- beams.csv at the drawn times ---- */

/* the rows of one section at one drawn time, in the file's order (along
 * the section) */
typedef struct sec_rows {
    const double *s, *x, *y, *M;   /* [n], in one allocation owned by the report */
    size_t n;
} sec_rows;

/* rows[j][k]: section k + 1 at drawn time j; 0, or −1 out of memory */
static int gather_rows(boom_rep *B, sec_rows rows[MAX_TIMES][BD_BOOM_MAX_SECTIONS])
{
    const bd_csv *b = &B->b;
    for (int j = 0; j < B->nt; j++)
        for (int k = 0; k < B->ns; k++) {
            size_t n = 0;
            for (size_t i = B->at[j].a; i < B->at[j].e; i++) n += (int)b->col[B_SEC][i] == k + 1;
            double *v = bd_rep_own(B->r, malloc((4 * n + 1) * sizeof *v));
            if (!v) return -1;
            size_t q = 0;
            for (size_t i = B->at[j].a; i < B->at[j].e; i++)
                if ((int)b->col[B_SEC][i] == k + 1) {
                    v[q] = b->col[B_S][i];
                    v[n + q] = b->col[B_X][i];
                    v[2 * n + q] = b->col[B_Y][i];
                    v[3 * n + q] = b->col[B_M][i];
                    q++;
                }
            rows[j][k] = (sec_rows){v, v + n, v + 2 * n, v + 3 * n, n};
        }
    return 0;
}

/* the order the drawn times are drawn in: the largest moment's last, dashed
 * over the others (it is often next to the end, and would hide under it) */
static int draw_order(const boom_rep *B, int i)
{
    static const int order[MAX_TIMES] = {0, 2, 1};
    return B->nt == 3 ? order[i] : i;
}

/* ---- bending moment along the sections ---- */

static int plot_moment(boom_rep *B, sec_rows rows[MAX_TIMES][BD_BOOM_MAX_SECTIONS], char *err,
                       size_t errlen)
{
    bd_rep *r = B->r;
    const bd_csv *b = &B->b;
    double Mpeak = b->col[B_M][B->peak];
    int ksec = (int)b->col[B_SEC][B->peak] - 1;
    bd_rep_unit u = bd_rep_pick_unit(fabs(Mpeak), "N·m");
    /* a panel a section while they fit, else a few sections a panel */
    int np = B->ns < BD_PLOT_MAX_PANELS ? B->ns : BD_PLOT_MAX_PANELS;
    int per = (B->ns + np - 1) / np;
    np = (B->ns + per - 1) / per;
    char *mark = bd_rep_label(r);
    bd_plot_figure f;
    figure_start(r, &f, "bending moment along the sections", 100 + 200 * (np > 2 ? np - 2 : 0),
                 "at the start, when the bending moment is largest anywhere, and at the end");
    f.npanels = np;
    f.share_x = 1;
    for (int p = 0; p < np; p++) {
        bd_plot_axes *a = &f.panel[p];
        int k0 = p * per, k1 = k0 + per < B->ns ? k0 + per : B->ns;
        char *yl = bd_rep_label(r);
        if (k1 - k0 == 1) snprintf(yl, BD_REP_LABEL_LEN, "Section %d: M [%s]", k0 + 1, u.name);
        else snprintf(yl, BD_REP_LABEL_LEN, "Sections %d–%d: M [%s]", k0 + 1, k1, u.name);
        a->ylabel = yl;
        a->include_zero = 1;
        for (int k = k0; k < k1; k++)
            for (int i = 0; i < B->nt; i++) {
                int j = draw_order(B, i);
                const sec_rows *sr = &rows[j][k];
                double *m = bd_rep_own(r, bd_rep_scaled(sr->M, sr->n, u.scale));
                if (!m) {
                    bd_rep_err(err, errlen, "out of memory");
                    return BD_REPORT_EOUTPUT;
                }
                char *label = B->at[j].label;
                if (k1 - k0 > 1) {
                    label = bd_rep_label(r);
                    snprintf(label, BD_REP_LABEL_LEN, "section %d, %s", k + 1, B->at[j].label);
                }
                int q = bd_plot_add_series(a, sr->s, m, sr->n, label, bd_plot_palette(j));
                if (q >= 0) {
                    /* one section: the largest moment's time dashed; a few:
                     * solid and dashed in turn */
                    a->series[q].dashed = k1 - k0 > 1 ? (k - k0) % 2 : B->nt == 3 && j == 1;
                    a->series[q].width = k - k0 < 2 ? 2.5 : 1.2;
                }
            }
        if (ksec >= k0 && ksec < k1 && isfinite(Mpeak)) {
            char num[64];
            bd_rep_fmt_num(num, sizeof num, Mpeak / u.scale);
            snprintf(mark, BD_REP_LABEL_LEN, "largest |M| %s %s at t = %.4g s, s = %.3g m", num,
                     u.name, b->col[B_T][B->peak], b->col[B_S][B->peak]);
            bd_plot_add_marker(a, b->col[B_S][B->peak], Mpeak / u.scale, mark);
        }
    }
    f.panel[np - 1].xlabel = "Position along the section from its bottom end s [m]";
    char *cap = bd_rep_label(r);
    snprintf(cap, BD_REP_LABEL_LEN,
             "The bending moment in each section (beams.csv moment_Nm) along the section, at "
             "the first time of beams.csv, at the time of the largest |M| in any section%s and "
             "at the last time.",
             per > 1 ? " (sections sharing a panel: solid and dashed in turn)" : " (dashed)");
    return bd_rep_write_plot(r, &f, "boom_moment", cap, err, errlen);
}

/* ---- the boom's shape ---- */

/* the history row nearest time t */
static size_t history_row(const bd_csv *h, double t)
{
    size_t best = 0;
    for (size_t i = 1; i < h->nrows; i++)
        if (fabs(h->col[0][i] - t) < fabs(h->col[0][best] - t)) best = i;
    return best;
}

/* the smallest of 1, 2, 5 × 10^k at least w */
static double nice_up(double w)
{
    double d = pow(10.0, floor(log10(w)));
    return w <= d ? d : w <= 2.0 * d ? 2.0 * d : w <= 5.0 * d ? 5.0 * d : 10.0 * d;
}

/* a line of time j: section by section while they fit (section 1 widest),
 * else one line with gaps; x, y hold every section's points one after the
 * other, each section followed by a NaN, start[k] where section k begins */
static void add_time_line(boom_rep *B, bd_plot_axes *a, int j, const double *x, const double *y,
                          const size_t *start, size_t total,
                          sec_rows rows[MAX_TIMES][BD_BOOM_MAX_SECTIONS], int per_section)
{
    bd_rgb c = bd_plot_palette(j);
    int peak = B->nt == 3 && j == 1;
    if (per_section) {
        for (int k = 0; k < B->ns; k++) {
            int s = bd_plot_add_series(a, x + start[k], y + start[k], rows[j][k].n,
                                       k == 0 ? B->at[j].label : NULL, c);
            if (s < 0) continue;
            a->series[s].width = fmax(4.5 - 1.5 * k, 1.2);
            a->series[s].dashed = peak;
        }
    } else {
        int s = bd_plot_add_series(a, x, y, total, B->at[j].label, c);
        if (s >= 0) {
            a->series[s].width = 2.5;
            a->series[s].dashed = peak;
        }
    }
}

static int plot_shape(boom_rep *B, sec_rows rows[MAX_TIMES][BD_BOOM_MAX_SECTIONS], char *err,
                      size_t errlen)
{
    bd_rep *r = B->r;
    const bd_csv *h = &B->h;
    /* each point of time j: X, Y as drawn, A its distance from section
     * 1's bottom end along the rigid boom's axis (towards the rigid boom's
     * tip), D its distance off it (positive to the upper side) */
    double *X[MAX_TIMES], *Y[MAX_TIMES], *A[MAX_TIMES], *D[MAX_TIMES], *axis[MAX_TIMES];
    size_t start[MAX_TIMES][BD_BOOM_MAX_SECTIONS], total[MAX_TIMES];
    double dmax = 0.0, lmax = 0.0;
    for (int j = 0; j < B->nt; j++) {
        total[j] = 0;
        for (int k = 0; k < B->ns; k++) total[j] += rows[j][k].n + 1;
        X[j] = bd_rep_own(r, malloc(4 * total[j] * sizeof *X[j]));
        axis[j] = bd_rep_own(r, malloc(4 * sizeof *axis[j]));
        if (!X[j] || !axis[j]) {
            bd_rep_err(err, errlen, "out of memory");
            return BD_REPORT_EOUTPUT;
        }
        Y[j] = X[j] + total[j];
        A[j] = Y[j] + total[j];
        D[j] = A[j] + total[j];
        const sec_rows *base = &rows[j][0];
        size_t i0 = 0;
        for (size_t i = 1; i < base->n; i++)
            if (base->s[i] < base->s[i0]) i0 = i;
        size_t hr = history_row(h, B->at[j].t);
        double rx = h->col[B->hc[H_RX]][hr], ry = h->col[B->hc[H_RY]][hr];
        double px = base->n ? base->x[i0] : NAN, py = base->n ? base->y[i0] : NAN;
        double len = hypot(rx - px, ry - py), ex = (rx - px) / len, ey = (ry - py) / len;
        /* the axis as a line: x0, x1, y0, y1 (NaN when unknown) */
        axis[j][0] = px;
        axis[j][1] = rx;
        axis[j][2] = py;
        axis[j][3] = ry;
        if (isfinite(len) && len > 0.0) lmax = fmax(lmax, len);
        size_t q = 0;
        for (int k = 0; k < B->ns; k++) {
            const sec_rows *sr = &rows[j][k];
            start[j][k] = q;
            for (size_t i = 0; i < sr->n; i++, q++) {
                double dx = sr->x[i] - px, dy = sr->y[i] - py;
                A[j][q] = dx * ex + dy * ey;
                D[j][q] = -dx * ey + dy * ex;
                if (isfinite(D[j][q])) dmax = fmax(dmax, fabs(D[j][q]));
                X[j][q] = sr->x[i];
                Y[j][q] = sr->y[i];
            }
            X[j][q] = Y[j][q] = A[j][q] = D[j][q] = NAN;   /* a gap before the next section */
            q++;
        }
    }
    /* the deflection drawn about a tenth of the boom's length when it is
     * less: each point moved off the axis by F times its distance */
    double F = 1.0;
    if (dmax > 0.0 && lmax > 0.0 && 0.1 * lmax / dmax >= 1.5)
        F = fmin(nice_up(0.1 * lmax / dmax), 1000.0);
    for (int j = 0; j < B->nt && F > 1.0; j++) {
        double len = hypot(axis[j][1] - axis[j][0], axis[j][3] - axis[j][2]);
        double ex = (axis[j][1] - axis[j][0]) / len, ey = (axis[j][3] - axis[j][2]) / len;
        if (!(len > 0.0) || !isfinite(len)) continue;
        for (size_t q = 0; q < total[j]; q++) {
            X[j][q] = axis[j][0] + A[j][q] * ex - F * D[j][q] * ey;
            Y[j][q] = axis[j][2] + A[j][q] * ey + F * D[j][q] * ex;
        }
    }
    int mm = dmax < 0.1;
    double dscale = mm ? 1e-3 : 1.0;
    for (int j = 0; j < B->nt; j++)
        for (size_t q = 0; q < total[j]; q++) D[j][q] /= dscale;

    char *sub = bd_rep_label(r), *cap = bd_rep_label(r), *yl = bd_rep_label(r);
    if (F > 1.0)
        snprintf(sub, BD_REP_LABEL_LEN, "top: the sections, their distance from the rigid "
                 "boom's axis (thin dashed) exaggerated ×%g; bottom: that distance to scale", F);
    else
        snprintf(sub, BD_REP_LABEL_LEN, "top: the sections at true scale (deflection not "
                 "exaggerated), the rigid boom's axis thin dashed; bottom: their distance from "
                 "that axis");
    bd_plot_figure f;
    figure_start(r, &f, "boom shape", 500, sub);
    f.npanels = 2;
    bd_plot_axes *a = &f.panel[0];
    a->xlabel = "Horizontal x [m]";
    a->ylabel = "Height y [m]";
    a->aspect = 1.0;
    bd_plot_axes *b = &f.panel[1];
    b->xlabel = "Distance from section 1's bottom end along the rigid boom's axis [m]";
    snprintf(yl, BD_REP_LABEL_LEN, "Deflection from the axis [%s]", mm ? "mm" : "m");
    b->ylabel = yl;
    b->include_zero = 1;
    int per_section = B->nt * B->ns + B->nt <= BD_PLOT_MAX_SERIES;
    for (int i = 0; i < B->nt; i++) {
        int j = draw_order(B, i);
        add_time_line(B, a, j, X[j], Y[j], start[j], total[j], rows, per_section);
        add_time_line(B, b, j, A[j], D[j], start[j], total[j], rows, per_section);
    }
    for (int j = 0; j < B->nt; j++) {
        int s = bd_plot_add_series(a, axis[j], axis[j] + 2, 2,
                                   j == B->nt - 1 ? "rigid boom's axis" : NULL,
                                   bd_plot_palette(j));
        if (s >= 0) {
            a->series[s].dashed = 1;
            a->series[s].width = 1.0;
        }
    }
    if (isfinite(axis[0][0])) bd_plot_add_text(a, axis[0][0], axis[0][2], "section 1's bottom");
    snprintf(cap, BD_REP_LABEL_LEN,
             "The boom's sections (beams.csv x_m, y_m) at the start, at the largest bending "
             "moment (dashed) and at the end%s. Top: in the plane, %s. Bottom: each point's "
             "distance from the rigid boom's axis (from section 1's bottom end to the rigid "
             "boom's tip, history.csv tip_rigid.*), positive to the upper side, against its "
             "place along the axis.",
             per_section ? "; section 1 widest, the inner sections narrower" : "",
             F > 1.0 ? "that distance exaggerated by the factor in the subtitle"
                     : "at true scale");
    return bd_rep_write_plot(r, &f, "boom_shape", cap, err, errlen);
}

/* ---- report.html ---- */

/* "VALUE UNIT" with a prefixed unit */
static void value_unit(char *buf, size_t len, double v, const char *base)
{
    bd_rep_unit u = bd_rep_pick_unit(fabs(v), base);
    char num[64];
    bd_rep_fmt_num(num, sizeof num, v / u.scale);
    snprintf(buf, len, "%s %s", num, u.name);
}

static void boom_cards(bd_rep *r, bd_strbuf *b)
{
    const cJSON *boom = cJSON_GetObjectItemCaseSensitive(r->summary, "boom");
    int moment = cJSON_GetObjectItemCaseSensitive(boom, "luffing_moment_max_Nm") != NULL;
    char v[128], d[BD_REP_LABEL_LEN], n1[64], n2[64];
    bd_sb_puts(b, "<div class=cards>\n");
    double def = bd_json_num(boom, "tip_deflection_max_m");
    if (isfinite(def)) {
        if (fabs(def) < 0.1) {
            bd_rep_fmt_num(n1, sizeof n1, 1000.0 * def);
            snprintf(v, sizeof v, "%s mm", n1);
        } else {
            bd_rep_fmt_num(n1, sizeof n1, def);
            snprintf(v, sizeof v, "%s m", n1);
        }
        bd_rep_fmt_num(n1, sizeof n1, bd_json_num(boom, "tip_x_max_m"));
        bd_rep_fmt_num(n2, sizeof n2, bd_json_num(boom, "tip_y_max_m"));
        snprintf(d, sizeof d, "from where the rigid boom has its tip; the tip's furthest x "
                 "%s m, highest y %s m", n1, n2);
        bd_rep_card(b, NULL, "tip deflection max", v, d);
    }
    double cyl = bd_json_num(boom, "telescopic_cylinder_force_max_N");
    if (isfinite(cyl)) {
        value_unit(v, sizeof v, cyl, "N");
        bd_rep_card(b, NULL, "telescopic cylinder force max", v, "largest |force| over the run");
    }
    double luff = bd_json_num(boom, moment ? "luffing_moment_max_Nm" : "luffing_force_max_N");
    if (isfinite(luff)) {
        value_unit(v, sizeof v, luff, moment ? "N·m" : "N");
        bd_rep_card(b, NULL, moment ? "luffing moment max" : "luffing force max", v,
                    moment ? "about the pivot, holding the luffing angle (no luffing cylinder)"
                           : "the luffing cylinder's largest |force|");
    }
    double pad = bd_json_num(boom, "pad_normal_force_max_N");
    if (isfinite(pad)) {
        value_unit(v, sizeof v, pad, "N");
        bd_rep_card(b, NULL, "pad normal force max", v, "the largest of every pad's");
    }
    const char *status = bd_json_str(r->summary, "status");
    if (status[0]) {
        double dur = bd_json_num(r->summary, "duration_s"), wall = bd_json_num(r->summary,
                                                                               "wall_time_s");
        snprintf(d, sizeof d, "%.4g s simulated in %.3g s of wall time", dur, wall);
        bd_rep_card(b, strcmp(status, "completed") == 0 ? "ok" : "bad", "status", status, d);
    }
    bd_rep_run_cards(r, b);
    bd_sb_puts(b, "</div>\n");
}

/* summary.json's luffing_force_max_N of a boom without a luffing cylinder
 * is a moment: shown in the page's table as luffing_moment_max_Nm, whose
 * unit the table reads from the name (N·m) */
static void name_the_moment(bd_rep *r)
{
    cJSON *boom = cJSON_GetObjectItemCaseSensitive(r->summary, "boom");
    cJSON *old = cJSON_GetObjectItemCaseSensitive(boom, "luffing_force_max_N");
    cJSON *tmp = cJSON_CreateObject();
    if (!old || !tmp ||
        !cJSON_AddItemToObject(tmp, "luffing_moment_max_Nm", cJSON_Duplicate(old, 1))) {
        cJSON_Delete(tmp);
        return;
    }
    cJSON *item = cJSON_DetachItemFromObjectCaseSensitive(tmp, "luffing_moment_max_Nm");
    cJSON_Delete(tmp);
    if (!cJSON_ReplaceItemViaPointer(boom, old, item)) cJSON_Delete(item);
}

/* ---- entry ---- */

int bd_boom_report_write(bd_rep *r, char *err, size_t errlen)
{
    boom_rep *B = calloc(1, sizeof *B);
    sec_rows (*rows)[BD_BOOM_MAX_SECTIONS] = calloc(MAX_TIMES, sizeof *rows);
    int rc = 0;
    if (!B || !rows) {
        free(B);
        free(rows);
        bd_rep_err(err, errlen, "out of memory");
        return BD_REPORT_EOUTPUT;
    }
    B->r = r;
    B->boom = cJSON_GetObjectItemCaseSensitive(r->summary, "boom");
    const char *lu = bd_json_str(B->boom, "luffing_unit");
    if (!cJSON_IsObject(B->boom)) {
        bd_rep_err(err, errlen, "%s/summary.json: \"kind\" is \"boom\" but there is no \"boom\" "
                   "object (boom-format.md)", r->dir);
        rc = BD_REPORT_EINPUT;
    } else if (lu[0] && strcmp(lu, "N") != 0 && strcmp(lu, "N*m") != 0) {
        bd_rep_err(err, errlen, "%s/summary.json: boom.luffing_unit is \"%s\", not \"N\" or "
                   "\"N*m\"", r->dir, lu);
        rc = BD_REPORT_EINPUT;
    }
    B->luff_moment = strcmp(lu, "N*m") == 0;
    if (rc || (rc = read_history(B, err, errlen)) || (rc = read_beams(B, err, errlen)))
        goto done;
    if (gather_rows(B, rows)) {
        bd_rep_err(err, errlen, "out of memory");
        rc = BD_REPORT_EOUTPUT;
        goto done;
    }
    if ((rc = plot_tip(B, err, errlen)) || (rc = plot_cylinders(B, err, errlen)) ||
        (rc = plot_pads(B, err, errlen)) || (rc = plot_moment(B, rows, err, errlen)) ||
        (rc = plot_shape(B, rows, err, errlen)) ||
        (rc = bd_rep_plot_energy(r, &B->h, "input (cylinder work)", err, errlen)))
        goto done;
    if (B->luff_moment) name_the_moment(r);
    rc = bd_rep_write_html(r, "boom run", boom_cards, err, errlen);
done:
    bd_csv_free(&B->h);
    bd_csv_free(&B->b);
    free(rows);
    free(B);
    return rc;
}
