/* beltdyn report on a sweep's directory (study.json with "sweep"): each
 * output against each varied key, and the keys ranked by their influence
 * on the peak tension, the lowest tension and the slip.
 *
 * - plots/sweep_k<i>: for varied key i, three panels (peak tight-side
 *   tension, lowest slack-side tension, largest slip speed) against the
 *   key, a dot per completed case; on a grid also the mean at each of the
 *   key's values (its main effect);
 * - plots/sweep_more_k<i>: the same for peak belt acceleration, peak drive
 *   torque and takeup travel range;
 * - plots/sensitivity: per ranked output, a bar per key of Spearman's rank
 *   correlation of the output with the key (io/sensitivity.c);
 * - DIR/sensitivity.csv: output, rank, key, spearman_rho (ranked by |rho|,
 *   keys without a coefficient last);
 * - DIR/report.html: the ranking, the plots and the table of cases. */
#include "io/sweep_report.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/file.h"
#include "base/json_util.h"
#include "beltdyn/report.h"
#include "io/html.h"
#include "io/plot.h"
#include "io/sensitivity.h"

#define PATH_LEN 4096
#define MAX_KEYS 16
#define FIG_W 1100

typedef struct outspec {
    const char *column;
    const char *label;     /* axis label */
    double scale;          /* column × scale is plotted */
} outspec;

/* the outputs the keys are ranked by: peak tension, lowest tension, slip */
static const outspec ranked[3] = {
    {"tight_tension_max_N", "Peak tight-side tension [kN]", 1e-3},
    {"slack_tension_min_N", "Lowest slack-side tension [kN]", 1e-3},
    {"slip_speed_max_mps", "Largest drive slip speed [m/s]", 1.0},
};
static const outspec more[3] = {
    {"belt_accel_max_mps2", "Peak belt acceleration [m/s²]", 1.0},
    {"drive_torque_max_Nm", "Peak drive torque [kN·m]", 1e-3},
    {"takeup_travel_range_m", "Takeup travel range [m]", 1.0},
};

typedef struct sweep {
    const char *dir;
    const cJSON *root;
    char plots[PATH_LEN];
    const char *model;
    int grid;
    int nkeys;
    const char *key[MAX_KEYS];
    int n;                  /* completed cases */
    double *x[MAX_KEYS];    /* [n] key values */
    double *y[6];           /* [n] ranked then more, scaled */
    double rho[3][MAX_KEYS];
} sweep;

/* a table cell as a number: slipped (a bool) as 0 or 1 */
static double jnum(const cJSON *o, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    if (cJSON_IsBool(v))
        return cJSON_IsTrue(v) ? 1.0 : 0.0;
    return bd_json_num(o, key);
}

static const outspec *spec_of(int q)
{
    return q < 3 ? &ranked[q] : &more[q - 3];
}

static int read_sweep(sweep *s, char *err, size_t errlen)
{
    const cJSON *sw = cJSON_GetObjectItemCaseSensitive(s->root, "sweep");
    const cJSON *keys = cJSON_GetObjectItemCaseSensitive(sw, "keys");
    const cJSON *cases = cJSON_GetObjectItemCaseSensitive(s->root, "cases");
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(s->root, "model");
    const cJSON *method = cJSON_GetObjectItemCaseSensitive(sw, "method");
    s->model = cJSON_IsString(m) ? m->valuestring : "";
    s->grid = cJSON_IsString(method) && strcmp(method->valuestring, "grid") == 0;
    if (!cJSON_IsArray(keys) || !cJSON_IsArray(cases)) {
        snprintf(err, errlen, "%s/study.json: a sweep without \"keys\" or \"cases\"", s->dir);
        return BD_REPORT_EINPUT;
    }
    const cJSON *k;
    cJSON_ArrayForEach(k, keys) {
        const cJSON *name = cJSON_GetObjectItemCaseSensitive(k, "key");
        if (s->nkeys < MAX_KEYS && cJSON_IsString(name))
            s->key[s->nkeys++] = name->valuestring;
    }
    int total = cJSON_GetArraySize(cases);
    for (int i = 0; i < s->nkeys; i++)
        s->x[i] = calloc((size_t)(total > 0 ? total : 1), sizeof(double));
    for (int q = 0; q < 6; q++)
        s->y[q] = calloc((size_t)(total > 0 ? total : 1), sizeof(double));
    for (int i = 0; i < s->nkeys; i++)
        if (!s->x[i]) goto oom;
    for (int q = 0; q < 6; q++)
        if (!s->y[q]) goto oom;
    const cJSON *c;
    cJSON_ArrayForEach(c, cases) {
        const cJSON *st = cJSON_GetObjectItemCaseSensitive(c, "status");
        if (!cJSON_IsString(st) || strcmp(st->valuestring, "completed") != 0)
            continue;
        for (int i = 0; i < s->nkeys; i++)
            s->x[i][s->n] = jnum(c, s->key[i]);
        for (int q = 0; q < 6; q++)
            s->y[q][s->n] = jnum(c, spec_of(q)->column) * spec_of(q)->scale;
        s->n++;
    }
    return 0;
oom:
    snprintf(err, errlen, "out of memory");
    return BD_REPORT_EOUTPUT;
}

static int write_fig(sweep *s, const bd_plot_figure *f, const char *name, char *err,
                     size_t errlen)
{
    char png[PATH_LEN], svg[PATH_LEN];
    if (snprintf(png, sizeof png, "%s/%s.png", s->plots, name) >= (int)sizeof png
        || snprintf(svg, sizeof svg, "%s/%s.svg", s->plots, name) >= (int)sizeof svg) {
        snprintf(err, errlen, "%s: path too long", s->plots);
        return BD_REPORT_EOUTPUT;
    }
    return bd_plot_write(f, png, svg, err, errlen) ? BD_REPORT_EOUTPUT : 0;
}

static int by_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* a grid's main effect of key k on output q: the mean at each of its
 * values; *m points */
static void main_effect(const sweep *s, int k, int q, double *mx, double *my, size_t *m)
{
    double *vals = malloc((size_t)(s->n > 0 ? s->n : 1) * sizeof *vals);
    *m = 0;
    if (!vals)
        return;
    memcpy(vals, s->x[k], (size_t)s->n * sizeof *vals);
    qsort(vals, (size_t)s->n, sizeof *vals, by_double);
    for (int i = 0; i < s->n; i++) {
        if (!isfinite(vals[i]) || (*m > 0 && vals[i] == mx[*m - 1]))
            continue;
        double sum = 0.0;
        int cnt = 0;
        for (int j = 0; j < s->n; j++)
            if (s->x[k][j] == vals[i] && isfinite(s->y[q][j])) {
                sum += s->y[q][j];
                cnt++;
            }
        mx[*m] = vals[i];
        my[(*m)++] = cnt > 0 ? sum / cnt : NAN;
    }
    free(vals);
}

static int plot_key(sweep *s, int k, int second, char *err, size_t errlen)
{
    static char title[600], xlabel[400];
    snprintf(title, sizeof title, "%s — %s", s->model, s->key[k]);
    snprintf(xlabel, sizeof xlabel, "%s", s->key[k]);
    bd_plot_figure f;
    bd_plot_figure_init(&f, title, FIG_W, 900);
    f.subtitle = s->grid ? "a dot per completed case; the line: the mean at each value of the "
                           "key (its main effect over the other keys)"
                         : "a dot per completed case of the Latin hypercube sample";
    f.npanels = 3;
    f.share_x = 1;
    size_t cap = (size_t)(s->n > 0 ? s->n : 1);
    double *mx = malloc(3 * cap * sizeof *mx), *my = malloc(3 * cap * sizeof *my);
    if (!mx || !my) {
        free(mx);
        free(my);
        snprintf(err, errlen, "out of memory");
        return BD_REPORT_EOUTPUT;
    }
    for (int p = 0; p < 3; p++) {
        int q = p + (second ? 3 : 0);
        bd_plot_axes *a = &f.panel[p];
        a->ylabel = spec_of(q)->label;
        a->xlabel = xlabel;
        if (s->grid) {
            size_t m;
            main_effect(s, k, q, mx + (size_t)p * cap, my + (size_t)p * cap, &m);
            if (m >= 2)
                bd_plot_add_series(a, mx + (size_t)p * cap, my + (size_t)p * cap, m, NULL,
                                   bd_plot_palette(1));
        }
        int i = bd_plot_add_series(a, s->x[k], s->y[q], (size_t)s->n, NULL, bd_plot_palette(0));
        if (i >= 0)
            a->series[i].points = 1;
    }
    char name[64];
    snprintf(name, sizeof name, "sweep_%sk%d", second ? "more_" : "", k + 1);
    int rc = write_fig(s, &f, name, err, errlen);
    free(mx);
    free(my);
    return rc;
}

/* keys in order of |rho| for output q, those without one last */
static void rank_keys(const sweep *s, int q, int *order)
{
    for (int i = 0; i < s->nkeys; i++)
        order[i] = i;
    for (int i = 1; i < s->nkeys; i++)
        for (int j = i; j > 0; j--) {
            double a = s->rho[q][order[j - 1]], b = s->rho[q][order[j]];
            double fa = isnan(a) ? -1.0 : fabs(a), fb = isnan(b) ? -1.0 : fabs(b);
            if (fb <= fa)
                break;
            int t = order[j];
            order[j] = order[j - 1];
            order[j - 1] = t;
        }
}

static int plot_sensitivity(sweep *s, char *err, size_t errlen)
{
    static char title[400];
    static double xs[3][MAX_KEYS][2], ys[3][MAX_KEYS][2];
    static double zx[2], zy[2] = {0.0, 0.0};
    static const char *const panel_label[3] = {"ρ with peak tension", "ρ with lowest tension",
                                               "ρ with slip speed"};
    snprintf(title, sizeof title, "%s — which key matters (Spearman rank correlation)",
             s->model);
    bd_plot_figure f;
    bd_plot_figure_init(&f, title, FIG_W, 900);
    f.subtitle = "a bar per key: +1 the output rises with the key in every case, −1 it falls, "
                 "0 no monotone relation";
    f.npanels = 3;
    f.share_x = 1;
    zx[0] = 0.5;
    zx[1] = s->nkeys + 0.5;
    int w, h;
    bd_plot_area_size(&f, 0, &w, &h);
    double bar = fmin(60.0, 0.6 * w / (s->nkeys + 1.0));
    for (int p = 0; p < 3; p++) {
        bd_plot_axes *a = &f.panel[p];
        a->ylabel = panel_label[p];
        a->xlabel = "varied key (the legend names them)";
        a->include_zero = 1;
        int zi = bd_plot_add_series(a, zx, zy, 2, NULL, (bd_rgb){0.25, 0.25, 0.25});
        if (zi >= 0)
            a->series[zi].width = 1.0;
        for (int k = 0; k < s->nkeys; k++) {
            double r = s->rho[p][k];
            xs[p][k][0] = xs[p][k][1] = k + 1;
            ys[p][k][0] = 0.0;
            ys[p][k][1] = isnan(r) ? 0.0 : r;
            int i = bd_plot_add_series(a, xs[p][k], ys[p][k], 2, p == 0 ? s->key[k] : NULL,
                                       bd_plot_palette(k));
            if (i >= 0)
                a->series[i].width = bar;
        }
        /* the bars span ±1 */
        bd_plot_add_hline(a, 1.0, NULL, (bd_rgb){0.7, 0.7, 0.7}, 1);
        bd_plot_add_hline(a, -1.0, NULL, (bd_rgb){0.7, 0.7, 0.7}, 1);
    }
    return write_fig(s, &f, "sensitivity", err, errlen);
}

static int write_ranking(sweep *s, char *err, size_t errlen)
{
    char path[PATH_LEN];
    if (bd_path_join(path, sizeof path, s->dir, "sensitivity.csv")) {
        snprintf(err, errlen, "%s: path too long", s->dir);
        return BD_REPORT_EOUTPUT;
    }
    bd_strbuf b = {0};
    bd_sb_puts(&b, "output,rank,key,spearman_rho\n");
    for (int q = 0; q < 3; q++) {
        int order[MAX_KEYS];
        rank_keys(s, q, order);
        for (int i = 0; i < s->nkeys; i++) {
            double r = s->rho[q][order[i]];
            bd_sb_printf(&b, "%s,%d,%s,", ranked[q].column, i + 1, s->key[order[i]]);
            if (isnan(r))
                bd_sb_puts(&b, "\n");
            else
                bd_sb_printf(&b, "%.4f\n", r);
        }
    }
    return bd_html_write(&b, path, err, errlen) ? BD_REPORT_EOUTPUT : 0;
}

static void html_ranking(const sweep *s, bd_strbuf *b)
{
    static const char *const what[3] = {"peak tight-side tension", "lowest slack-side tension",
                                        "largest slip speed"};
    bd_sb_puts(b, "<table><tr><th>rank</th>");
    for (int q = 0; q < 3; q++)
        bd_sb_printf(b, "<th>%s: key</th><th>ρ</th>", what[q]);
    bd_sb_puts(b, "</tr>\n");
    int order[3][MAX_KEYS];
    for (int q = 0; q < 3; q++)
        rank_keys(s, q, order[q]);
    for (int i = 0; i < s->nkeys; i++) {
        bd_sb_printf(b, "<tr><td class=n>%d</td>", i + 1);
        for (int q = 0; q < 3; q++) {
            double r = s->rho[q][order[q][i]];
            bd_sb_puts(b, "<td>");
            bd_sb_html(b, s->key[order[q][i]]);
            if (isnan(r))
                bd_sb_puts(b, "</td><td class=n>—</td>");
            else
                bd_sb_printf(b, "</td><td class=n>%+.3f</td>", r);
        }
        bd_sb_puts(b, "</tr>\n");
    }
    bd_sb_puts(b, "</table>\n");
}

static void html_cases(const sweep *s, bd_strbuf *b)
{
    static const char *const cols[] = {"status", "tight_tension_max_N", "slack_tension_min_N",
                                       "belt_accel_max_mps2", "takeup_travel_range_m",
                                       "drive_torque_max_Nm", "slipped", "slip_speed_max_mps",
                                       "belt_tension_max_N"};
    const int nc = (int)(sizeof cols / sizeof cols[0]);
    bd_sb_puts(b, "<table><tr><th>case</th>");
    for (int k = 0; k < s->nkeys; k++) {
        bd_sb_puts(b, "<th>");
        bd_sb_html(b, s->key[k]);
        bd_sb_puts(b, "</th>");
    }
    for (int i = 0; i < nc; i++)
        bd_sb_printf(b, "<th>%s</th>", cols[i]);
    bd_sb_puts(b, "</tr>\n");
    const cJSON *c;
    cJSON_ArrayForEach(c, cJSON_GetObjectItemCaseSensitive(s->root, "cases")) {
        const cJSON *name = cJSON_GetObjectItemCaseSensitive(c, "case");
        bd_sb_puts(b, "<tr><td>");
        bd_sb_html(b, cJSON_IsString(name) ? name->valuestring : "");
        bd_sb_puts(b, "</td>");
        for (int k = 0; k < s->nkeys; k++)
            bd_sb_printf(b, "<td class=n>%.6g</td>", jnum(c, s->key[k]));
        for (int i = 0; i < nc; i++)
            bd_sb_json_cell(b, cJSON_GetObjectItemCaseSensitive(c, cols[i]));
        bd_sb_puts(b, "</tr>\n");
    }
    bd_sb_puts(b, "</table>\n");
}

static int embed(sweep *s, bd_strbuf *b, const char *plot, const char *caption, char *err,
                 size_t errlen)
{
    return bd_sb_figure(b, s->plots, plot, caption, err, errlen) ? BD_REPORT_EOUTPUT : 0;
}

static int write_html(sweep *s, char *err, size_t errlen)
{
    bd_strbuf b = {0};
    bd_sb_page_start(&b, s->model, "sweep");
    bd_sb_printf(&b, "<p class=sub>beltdyn sweep (%s) · %d keys · %d completed cases · "
                 "each case's own run in its directory</p>\n",
                 s->grid ? "grid" : "Latin hypercube", s->nkeys, s->n);
    bd_sb_puts(&b, "<h2>Which key matters</h2>\n<p>The keys ranked by the magnitude of "
                   "Spearman's rank correlation ρ of each output with the key over the "
                   "completed cases (docs/studies.md): +1 the output rises with the key in "
                   "every case, −1 it falls, 0 no monotone relation.</p>\n");
    html_ranking(s, &b);
    int rc = embed(s, &b, "sensitivity", "Spearman's ρ of each output with each key.", err,
                   errlen);
    bd_sb_puts(&b, "<h2>Outputs against the keys</h2>\n");
    for (int k = 0; k < s->nkeys && rc == 0; k++) {
        char name[64], cap[600];
        snprintf(name, sizeof name, "sweep_k%d", k + 1);
        snprintf(cap, sizeof cap, "Peak tension, lowest tension and slip against %s.",
                 s->key[k]);
        rc = embed(s, &b, name, cap, err, errlen);
        snprintf(name, sizeof name, "sweep_more_k%d", k + 1);
        snprintf(cap, sizeof cap, "Peak belt acceleration, peak drive torque and takeup travel "
                 "against %s.", s->key[k]);
        if (rc == 0)
            rc = embed(s, &b, name, cap, err, errlen);
    }
    if (rc) {
        free(b.p);
        return rc;
    }
    bd_sb_puts(&b, "<h2>Cases</h2>\n");
    html_cases(s, &b);
    return bd_html_page_finish(&b, s->dir, err, errlen) ? BD_REPORT_EOUTPUT : 0;
}

int bd_sweep_report_write(const char *dir, const cJSON *root, char *err, size_t errlen)
{
    sweep *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, errlen, "out of memory");
        return BD_REPORT_EOUTPUT;
    }
    s->dir = dir;
    s->root = root;
    int rc = read_sweep(s, err, errlen);
    if (rc == 0) {
        if (bd_path_join(s->plots, sizeof s->plots, dir, "plots")) {
            snprintf(err, errlen, "%s: path too long", dir);
            rc = BD_REPORT_EOUTPUT;
        } else if (mkdir(s->plots, 0777) != 0 && errno != EEXIST) {
            snprintf(err, errlen, "%s: %s", s->plots, strerror(errno));
            rc = BD_REPORT_EOUTPUT;
        }
    }
    for (int q = 0; rc == 0 && q < 3; q++)
        for (int k = 0; k < s->nkeys; k++)
            s->rho[q][k] = bd_spearman(s->x[k], s->y[q], (size_t)s->n);
    for (int k = 0; rc == 0 && k < s->nkeys; k++) {
        rc = plot_key(s, k, 0, err, errlen);
        if (rc == 0)
            rc = plot_key(s, k, 1, err, errlen);
    }
    if (rc == 0)
        rc = plot_sensitivity(s, err, errlen);
    if (rc == 0)
        rc = write_ranking(s, err, errlen);
    if (rc == 0)
        rc = write_html(s, err, errlen);
    for (int k = 0; k < MAX_KEYS; k++)
        free(s->x[k]);
    for (int q = 0; q < 6; q++)
        free(s->y[q]);
    free(s);
    return rc;
}
