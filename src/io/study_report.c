/* beltdyn report on a start-study directory (one made by `beltdyn study`;
 * a sweep's goes to sweep_report.c):
 * the comparison of the start curves (issue 6) as plots in DIR/plots and
 * one self-contained DIR/report.html with the study table.
 *
 * - study_tension: belt tension against time at the model's tight-side
 *   probe (the probe with the highest peak in the first case), one panel
 *   per start time, a colour per curve, dashed with a pre-start delay;
 * - study_peaks: bars of the peak tight-side tension and of the peak belt
 *   acceleration per case, grouped by start time and delay. */
#include "io/study_report.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/file.h"
#include "base/json_util.h"
#include "beltdyn/report.h"
#include "io/csv_read.h"
#include "io/html.h"
#include "io/plot.h"
#include "io/sweep_report.h"

#define PATH_LEN 4096
#define MAX_CASES 64
#define MAX_GROUPS 16
#define FIG_W 1200

typedef struct scase {
    const char *name, *curve, *status;
    double time, delay;
    double tight_max, accel_max;
    int curve_index;       /* 0..3 in the order linear, harrison, nordell, s-curve */
    bd_csv hist;           /* t_s and the probe's tension (may be empty) */
} scase;

typedef struct study {
    const char *dir;
    char plots[PATH_LEN];
    cJSON *json;
    const char *model;
    scase c[MAX_CASES];
    int n;
    char probe[160];       /* history column plotted, "" = none */
    double times[3];       /* start times with a panel */
    int ntimes;
} study;

static int curve_index(const char *name)
{
    static const char *const names[4] = {"linear", "harrison", "nordell", "s-curve"};
    for (int i = 0; i < 4; i++)
        if (strcmp(name, names[i]) == 0) return i;
    return 0;
}

static int read_study(study *s, char *err, size_t errlen)
{
    char path[PATH_LEN];
    if (bd_path_join(path, sizeof path, s->dir, "study.json")) {
        snprintf(err, errlen, "%s: path too long", s->dir);
        return BD_REPORT_EINPUT;
    }
    s->json = bd_json_load(path);
    if (!s->json && errno) {
        snprintf(err, errlen, "%s: %s (study.csv without study.json?)", path, strerror(errno));
        return BD_REPORT_EINPUT;
    }
    const cJSON *cases = cJSON_GetObjectItemCaseSensitive(s->json, "cases");
    if (!cJSON_IsArray(cases)) {
        snprintf(err, errlen, "%s: not a study table (no \"cases\" list)", path);
        return BD_REPORT_EINPUT;
    }
    s->model = bd_json_str(s->json, "model");
    const cJSON *o;
    cJSON_ArrayForEach(o, cases) {
        if (s->n >= MAX_CASES) break;
        scase *c = &s->c[s->n++];
        c->name = bd_json_str(o, "case");
        c->curve = bd_json_str(o, "curve");
        c->status = bd_json_str(o, "status");
        c->time = bd_json_num(o, "start_time_s");
        c->delay = bd_json_num(o, "delay_s");
        c->tight_max = bd_json_num(o, "tight_tension_max_N");
        c->accel_max = fabs(bd_json_num(o, "belt_accel_max_mps2"));
        c->curve_index = curve_index(c->curve);
        if (!bd_case_name_ok(c->name)) {
            snprintf(err, errlen, "%s: case %d has no usable name", path, s->n);
            return BD_REPORT_EINPUT;
        }
    }
    for (int i = 0; i < s->n; i++) {
        int k;
        for (k = 0; k < s->ntimes; k++)
            if (s->times[k] == s->c[i].time) break;
        if (k == s->ntimes && s->ntimes < 3) s->times[s->ntimes++] = s->c[i].time;
    }
    return 0;
}

/* DIR/<case i>/history.csv; 0, or -1 when the path is too long */
static int case_history(char *path, size_t cap, const study *s, int i)
{
    char dir[PATH_LEN];
    return bd_path_join(dir, sizeof dir, s->dir, s->c[i].name)
           || bd_path_join(path, cap, dir, "history.csv") ? -1 : 0;
}

/* the probe column with the highest tension in the first case's history */
static void choose_probe(study *s)
{
    for (int i = 0; i < s->n && !s->probe[0]; i++) {
        char path[PATH_LEN], err[256];
        bd_csv h;
        if (case_history(path, sizeof path, s, i) || bd_csv_read(path, NULL, 0, &h, err, sizeof err))
            continue;
        double best = -INFINITY;
        for (int k = 0; k < h.ncols; k++) {
            size_t len = strlen(h.names[k]);
            if (len < 10 || strcmp(h.names[k] + len - 10, ".tension_N") != 0) continue;
            for (size_t r = 0; r < h.nrows; r++)
                if (h.col[k][r] > best) {
                    best = h.col[k][r];
                    snprintf(s->probe, sizeof s->probe, "%s", h.names[k]);
                }
        }
        bd_csv_free(&h);
    }
}

static void read_histories(study *s)
{
    if (!s->probe[0]) return;
    const char *want[2] = {"t_s", s->probe};
    for (int i = 0; i < s->n; i++) {
        char path[PATH_LEN], err[256];
        if (case_history(path, sizeof path, s, i)
            || bd_csv_read(path, want, 2, &s->c[i].hist, err, sizeof err))
            memset(&s->c[i].hist, 0, sizeof s->c[i].hist);
        for (size_t r = 0; r < s->c[i].hist.nrows; r++) s->c[i].hist.col[1][r] /= 1e3;
    }
}

static int write_fig(study *s, const bd_plot_figure *f, const char *name, char *err,
                     size_t errlen)
{
    char png[PATH_LEN], svg[PATH_LEN];
    if (snprintf(png, sizeof png, "%s/%s.png", s->plots, name) >= (int)sizeof png ||
        snprintf(svg, sizeof svg, "%s/%s.svg", s->plots, name) >= (int)sizeof svg) {
        snprintf(err, errlen, "%s: path too long", s->plots);
        return BD_REPORT_EOUTPUT;
    }
    return bd_plot_write(f, png, svg, err, errlen) ? BD_REPORT_EOUTPUT : 0;
}

static int plot_tension(study *s, char *title, char *err, size_t errlen)
{
    static char ylabel[200];
    bd_plot_figure f;
    snprintf(title, 400, "%s — start curves compared", s->model);
    bd_plot_figure_init(&f, title, FIG_W, 330 * (s->ntimes > 0 ? s->ntimes : 1) + 120);
    snprintf(ylabel, sizeof ylabel, "Tension at %.*s [kN]",
             (int)(strlen(s->probe) > 10 ? strlen(s->probe) - 10 : 0), s->probe);
    f.subtitle = "belt tension against time at the tight-side probe; one colour per start "
                 "curve, dashed: with pre-start delay";
    f.npanels = s->ntimes;
    for (int p = 0; p < s->ntimes; p++) {
        bd_plot_axes *a = &f.panel[p];
        a->ylabel = ylabel;
        a->xlabel = "Time t [s]";
        a->include_zero = 1;
        for (int i = 0; i < s->n; i++) {
            const scase *c = &s->c[i];
            if (c->time != s->times[p] || c->hist.nrows == 0) continue;
            int k = bd_plot_add_series(a, c->hist.col[0], c->hist.col[1], c->hist.nrows, c->name,
                                       bd_plot_palette(c->curve_index));
            if (k >= 0) a->series[k].dashed = c->delay > 0.0;
        }
    }
    return write_fig(s, &f, "study_tension", err, errlen);
}

/* bars as thick vertical segments: one series per curve, its cases
 * separated by NaN; x = group (start time, delay) + an offset per curve */
static int plot_peaks(study *s, char *title, char *subtitle, char *err, size_t errlen)
{
    double gt[MAX_GROUPS], gd[MAX_GROUPS];
    int ng = 0, group[MAX_CASES];
    for (int i = 0; i < s->n; i++) {
        int g;
        for (g = 0; g < ng; g++)
            if (gt[g] == s->c[i].time && gd[g] == s->c[i].delay) break;
        if (g == ng && ng < MAX_GROUPS) {
            gt[ng] = s->c[i].time;
            gd[ng++] = s->c[i].delay;
        }
        group[i] = g < MAX_GROUPS ? g : MAX_GROUPS - 1;
    }
    static double xs[2][4][3 * MAX_CASES], ys[2][4][3 * MAX_CASES];
    size_t len[2][4] = {{0}};
    for (int i = 0; i < s->n; i++) {
        const scase *c = &s->c[i];
        double x = group[i] + 1 + 0.2 * (c->curve_index - 1.5);
        double v[2] = {c->tight_max / 1e3, c->accel_max};
        for (int q = 0; q < 2; q++) {
            size_t *l = &len[q][c->curve_index];
            double *X = xs[q][c->curve_index], *Y = ys[q][c->curve_index];
            X[*l] = x, Y[(*l)++] = 0.0;
            X[*l] = x, Y[(*l)++] = v[q];
            X[*l] = NAN, Y[(*l)++] = NAN;
        }
    }
    bd_plot_figure f;
    snprintf(title, 400, "%s — peaks per start case", s->model);
    bd_plot_figure_init(&f, title, FIG_W, 820);
    int o = snprintf(subtitle, 400, "groups left to right:");
    for (int g = 0; g < ng && o < 380; g++)
        o += snprintf(subtitle + o, (size_t)(400 - o), " %d: T = %g s, delay %g s%s", g + 1, gt[g],
                      gd[g], g + 1 < ng ? ";" : "");
    f.subtitle = subtitle;
    f.npanels = 2;
    f.share_x = 1;
    f.panel[0].ylabel = "Peak tight-side tension [kN]";
    f.panel[1].ylabel = "Peak belt acceleration [m/s²]";
    f.panel[1].xlabel = "Case group (start time T, delay)";
    static const char *const names[4] = {"linear", "harrison", "nordell", "s-curve"};
    int w, h;
    bd_plot_area_size(&f, 0, &w, &h);
    double bar = 0.16 * w / (ng + 1.0);
    /* a zero line over the whole width keeps the outer bars inside */
    static double base_x[2], base_y[2] = {0.0, 0.0};
    base_x[0] = 0.5;
    base_x[1] = ng + 0.5;
    for (int q = 0; q < 2; q++) {
        f.panel[q].include_zero = 1;
        int zi = bd_plot_add_series(&f.panel[q], base_x, base_y, 2, NULL,
                                    (bd_rgb){0.25, 0.25, 0.25});
        if (zi >= 0) f.panel[q].series[zi].width = 1.0;
        for (int k = 0; k < 4; k++) {
            if (len[q][k] == 0) continue;
            int i = bd_plot_add_series(&f.panel[q], xs[q][k], ys[q][k], len[q][k], names[k],
                                       bd_plot_palette(k));
            if (i >= 0) f.panel[q].series[i].width = bar;
        }
    }
    return write_fig(s, &f, "study_peaks", err, errlen);
}

static void html_table(bd_strbuf *b, const cJSON *cases)
{
    static const char *const keys[] = {
        "case", "curve", "start_time_s", "delay_s", "status", "tight_tension_max_N",
        "tight_tension_max_time_s", "slack_tension_min_N", "belt_accel_max_mps2",
        "takeup_travel_range_m", "drive_torque_max_Nm", "slipped", "belt_tension_max_N"};
    static const char *const heads[] = {
        "case", "curve", "start time [s]", "delay [s]", "status", "peak tight-side tension [N]",
        "at [s]", "lowest slack-side tension [N]", "peak belt acceleration [m/s²]",
        "takeup travel range [m]", "peak drive torque [N·m]", "drive slipped",
        "peak belt tension anywhere [N]"};
    const int nk = (int)(sizeof keys / sizeof keys[0]);
    bd_sb_puts(b, "<table><tr>");
    for (int k = 0; k < nk; k++) bd_sb_printf(b, "<th>%s</th>", heads[k]);
    bd_sb_puts(b, "</tr>\n");
    const cJSON *o;
    cJSON_ArrayForEach(o, cases) {
        bd_sb_puts(b, "<tr>");
        for (int k = 0; k < nk; k++) {
            bd_sb_json_cell(b, cJSON_GetObjectItemCaseSensitive(o, keys[k]));
        }
        bd_sb_puts(b, "</tr>\n");
    }
    bd_sb_puts(b, "</table>\n");
}

static int write_html(study *s, const char *const *plots, const char *const *captions,
                      int nplots, char *err, size_t errlen)
{
    bd_strbuf b = {0};
    bd_sb_page_start(&b, s->model, "start study");
    bd_sb_printf(&b, "<p class=sub>beltdyn start study · %d cases · each case's own run "
                     "and report in its directory</p>\n<h2>Cases</h2>\n", s->n);
    html_table(&b, cJSON_GetObjectItemCaseSensitive(s->json, "cases"));
    bd_sb_puts(&b, "<p class=sub>Slip: ");
    bd_sb_html(&b, bd_json_str(s->json, "slip_definition"));
    bd_sb_puts(&b, ".</p>\n<h2 id=plots>Start curves compared</h2>\n");
    for (int i = 0; i < nplots; i++)
        if (bd_sb_figure(&b, s->plots, plots[i], captions[i], err, errlen)) {
            free(b.p);
            return BD_REPORT_EOUTPUT;
        }
    return bd_html_page_finish(&b, s->dir, err, errlen) ? BD_REPORT_EOUTPUT : 0;
}

int bd_study_report_write(const char *dir, char *err, size_t errlen)
{
    study *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, errlen, "out of memory");
        return BD_REPORT_EOUTPUT;
    }
    s->dir = dir;
    static char title[2][400], subtitle[400];
    int rc = read_study(s, err, errlen);
    if (rc) goto done;
    if (cJSON_GetObjectItemCaseSensitive(s->json, "sweep")) {
        rc = bd_sweep_report_write(dir, s->json, err, errlen);
        goto done;
    }
    if (bd_path_join(s->plots, sizeof s->plots, dir, "plots")) {
        snprintf(err, errlen, "%s: path too long", dir);
        rc = BD_REPORT_EOUTPUT;
        goto done;
    }
    if (mkdir(s->plots, 0777) != 0 && errno != EEXIST) {
        snprintf(err, errlen, "%s: %s", s->plots, strerror(errno));
        rc = BD_REPORT_EOUTPUT;
        goto done;
    }
    choose_probe(s);
    read_histories(s);
    const char *plots[2];
    const char *captions[2];
    int np = 0;
    if (s->probe[0] && s->ntimes > 0) {
        if ((rc = plot_tension(s, title[0], err, errlen))) goto done;
        plots[np] = "study_tension";
        captions[np++] = "Belt tension at the tight-side probe against time for every case.";
    }
    if (s->n > 0) {
        if ((rc = plot_peaks(s, title[1], subtitle, err, errlen))) goto done;
        plots[np] = "study_peaks";
        captions[np++] = "Peak tight-side tension and peak belt acceleration of every case, "
                         "grouped by start time and delay, one colour per start curve.";
    }
    rc = write_html(s, plots, captions, np, err, errlen);
done:
    for (int i = 0; i < s->n; i++) bd_csv_free(&s->c[i].hist);
    cJSON_Delete(s->json);
    free(s);
    return rc;
}
