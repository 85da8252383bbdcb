/* beltdyn report on a load-cases directory (`beltdyn cases`, cli.md): the
 * five standard cases compared in one DIR/report.html.
 *
 * - plots/cases_peaks: a bar per case of the peak and the lowest belt
 *   tension anywhere and the peak drive torque (a stop case's from its
 *   stop on: its records start there);
 * - the table of cases (what each sets, its status and numbers), each
 *   case's name linking to its own report, DIR/CASE/report.html, which is
 *   written first for every case that has a run (summary.json). */
#include "io/cases_report.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/file.h"
#include "base/json_util.h"
#include "beltdyn/report.h"
#include "io/html.h"
#include "io/plot.h"

#define PATH_LEN 4096
#define MAX_CASES 8
#define NQ 3   /* panels: tension peak, lowest tension, torque */

typedef struct quantity {
    const char *column, *label;
    double scale;
} quantity;

static const quantity Q[NQ] = {
    {"belt_tension_max_N", "Peak belt tension [kN]", 1e-3},
    {"belt_tension_min_N", "Lowest belt tension [kN]", 1e-3},
    {"drive_torque_max_Nm", "Peak drive torque [kN·m]", 1e-3},
};

/* bars as thick vertical segments, one series per case, x = its index */
static int plot_peaks(const char *plots, const char *model, const cJSON *cases, int n,
                      char *err, size_t errlen)
{
    double xs[NQ][MAX_CASES][2], ys[NQ][MAX_CASES][2];
    double base_x[2], base_y[2];
    char title[400];
    char names[MAX_CASES][96];
    bd_plot_figure f;
    snprintf(title, sizeof title, "%s — load cases compared", model);
    bd_plot_figure_init(&f, title, 1100, 1100);
    f.subtitle = "a bar per case, left to right as in the table; a stop case from its stop on";
    f.npanels = NQ;
    f.share_x = 1;
    int w, h;
    bd_plot_area_size(&f, 0, &w, &h);
    double bar = 0.5 * w / (n + 1.0);
    base_x[0] = 0.5;
    base_x[1] = n + 0.5;
    base_y[0] = base_y[1] = 0.0;
    for (int q = 0; q < NQ; q++) {
        bd_plot_axes *a = &f.panel[q];
        a->ylabel = Q[q].label;
        a->include_zero = 1;
        int zi = bd_plot_add_series(a, base_x, base_y, 2, NULL, (bd_rgb){0.25, 0.25, 0.25});
        if (zi >= 0) a->series[zi].width = 1.0;
        int i = 0;
        const cJSON *o;
        cJSON_ArrayForEach(o, cases) {
            if (i >= MAX_CASES) break;
            double v = bd_json_num(o, Q[q].column) * Q[q].scale;
            snprintf(names[i], sizeof names[i], "%d %s", i + 1, bd_json_str(o, "case"));
            xs[q][i][0] = xs[q][i][1] = i + 1;
            ys[q][i][0] = 0.0;
            ys[q][i][1] = isfinite(v) ? v : 0.0;
            int k = bd_plot_add_series(a, xs[q][i], ys[q][i], 2, q == 0 ? names[i] : NULL,
                                       bd_plot_palette(i));
            if (k >= 0) a->series[k].width = bar;
            i++;
        }
    }
    f.panel[NQ - 1].xlabel = "Case (numbered as in the legend and the table)";
    char png[PATH_LEN], svg[PATH_LEN];
    if (snprintf(png, sizeof png, "%s/cases_peaks.png", plots) >= (int)sizeof png ||
        snprintf(svg, sizeof svg, "%s/cases_peaks.svg", plots) >= (int)sizeof svg) {
        snprintf(err, errlen, "%s: path too long", plots);
        return BD_REPORT_EOUTPUT;
    }
    return bd_plot_write(&f, png, svg, err, errlen) ? BD_REPORT_EOUTPUT : 0;
}

static void html_table(bd_strbuf *b, const char *dir, const cJSON *cases)
{
    static const char *const keys[] = {
        "setup", "status", "belt_tension_max_N", "belt_tension_min_N", "tight_tension_max_N",
        "slack_tension_min_N", "drive_torque_max_Nm", "takeup_travel_range_m", "slipped",
        "belt_accel_max_mps2", "message"};
    static const char *const heads[] = {
        "case", "what it sets", "status", "peak belt tension [N]", "lowest belt tension [N]",
        "peak tight-side tension [N]", "lowest slack-side tension [N]", "peak drive torque [N·m]",
        "takeup travel range [m]", "drive slipped", "peak belt acceleration [m/s²]",
        "message"};
    const int nk = (int)(sizeof keys / sizeof keys[0]);
    bd_sb_puts(b, "<table><tr>");
    for (int k = 0; k <= nk; k++) bd_sb_printf(b, "<th>%s</th>", heads[k]);
    bd_sb_puts(b, "</tr>\n");
    const cJSON *o;
    cJSON_ArrayForEach(o, cases) {
        const char *name = bd_json_str(o, "case");
        char report[PATH_LEN];
        int linked = bd_case_name_ok(name)
                     && snprintf(report, sizeof report, "%s/%s/report.html", dir, name)
                            < (int)sizeof report
                     && access(report, R_OK) == 0;
        bd_sb_puts(b, "<tr><td>");
        if (linked) {
            bd_sb_puts(b, "<a href=\"");
            bd_sb_html(b, name);
            bd_sb_puts(b, "/report.html\">");
        }
        bd_sb_html(b, name);
        bd_sb_puts(b, linked ? "</a></td>" : "</td>");
        for (int k = 0; k < nk; k++) {
            bd_sb_json_cell(b, cJSON_GetObjectItemCaseSensitive(o, keys[k]));
        }
        bd_sb_puts(b, "</tr>\n");
    }
    bd_sb_puts(b, "</table>\n");
}

int bd_cases_report_write(const char *dir, char *err, size_t errlen)
{
    char path[PATH_LEN], plots[PATH_LEN];
    if (bd_path_join(path, sizeof path, dir, "cases.json")
        || bd_path_join(plots, sizeof plots, dir, "plots")) {
        snprintf(err, errlen, "%s: path too long", dir);
        return BD_REPORT_EINPUT;
    }
    cJSON *json = bd_json_load(path);
    if (!json && errno) {
        snprintf(err, errlen, "%s: %s (cases.csv without cases.json?)", path, strerror(errno));
        return BD_REPORT_EINPUT;
    }
    const cJSON *cases = cJSON_GetObjectItemCaseSensitive(json, "cases");
    if (!cJSON_IsArray(cases)) {
        cJSON_Delete(json);
        snprintf(err, errlen, "%s: not a load-cases table (no \"cases\" list)", path);
        return BD_REPORT_EINPUT;
    }
    int n = cJSON_GetArraySize(cases);
    const char *model = bd_json_str(json, "model");
    int rc = 0, case_rc = 0;
    /* each case's own report, where the case has a run; one failing keeps
     * the comparison page, and its error is returned at the end */
    const cJSON *o;
    cJSON_ArrayForEach(o, cases) {
        const char *name = bd_json_str(o, "case");
        char sub[PATH_LEN], summary[PATH_LEN], cerr[1024];
        if (!bd_case_name_ok(name) || bd_path_join(sub, sizeof sub, dir, name)
            || bd_path_join(summary, sizeof summary, sub, "summary.json")
            || access(summary, R_OK) != 0)
            continue;
        if (bd_report_write(sub, cerr, sizeof cerr) != BD_REPORT_OK && !case_rc) {
            snprintf(err, errlen, "%s: %s", sub, cerr);
            case_rc = BD_REPORT_EOUTPUT;
        }
    }
    if (mkdir(plots, 0777) != 0 && errno != EEXIST) {
        snprintf(err, errlen, "%s: %s", plots, strerror(errno));
        rc = BD_REPORT_EOUTPUT;
    }
    if (!rc && n > 0)
        rc = plot_peaks(plots, model, cases, n < MAX_CASES ? n : MAX_CASES, err, errlen);
    if (!rc) {
        bd_strbuf b = {0};
        bd_sb_page_start(&b, model, "load cases");
        bd_sb_printf(&b, "<p class=sub>beltdyn load cases · %d cases · each case's own run "
                         "and report in its directory (the case's name links to it)</p>\n"
                         "<h2>Cases</h2>\n", n);
        html_table(&b, dir, cases);
        bd_sb_puts(&b, "<p class=sub>A stop case's records (its peaks, its envelope, this "
                       "table's numbers) start when its drives stop "
                       "(<code>records_from_s</code>); its time history is the whole run. "
                       "Slip: ");
        bd_sb_html(&b, bd_json_str(json, "slip_definition"));
        bd_sb_puts(&b, ".</p>\n<h2 id=plots>Cases compared</h2>\n");
        if (n > 0 && bd_sb_figure(&b, plots, "cases_peaks",
                                  "Peak and lowest belt tension and peak drive torque of every "
                                  "case.", err, errlen)) {
            free(b.p);
            rc = BD_REPORT_EOUTPUT;
        } else {
            rc = bd_html_page_finish(&b, dir, err, errlen) ? BD_REPORT_EOUTPUT : 0;
        }
    }
    cJSON_Delete(json);
    return rc ? rc : case_rc;
}
