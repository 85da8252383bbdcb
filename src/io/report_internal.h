/* The pieces of `beltdyn report DIR` (report.c) that the report of a boom
 * run (boom_report.c) draws with too: what a report knows while it is being
 * written, numbers and units for people, plots kept for the page, panels of
 * CSV columns, the energy figure, headline cards and the page itself.
 * Internal to src/io. */
#ifndef BD_IO_REPORT_INTERNAL_H
#define BD_IO_REPORT_INTERNAL_H

#include <cjson/cJSON.h>
#include <stddef.h>

#include "io/csv_read.h"
#include "io/html.h"
#include "io/plot.h"

#define BD_REP_PATH_LEN 4096
#define BD_REP_LABEL_LEN 512
#define BD_REP_MAX_LABELS 512
#define BD_REP_MAX_PLOTS 10
#define BD_REP_FIG_W 1200
#define BD_REP_FIG_H 700

/* a unit that keeps the numbers short: divide by scale, show name */
typedef struct bd_rep_unit {
    double scale;
    char name[16];
} bd_rep_unit;

/* a value of a run and where it was (a conveyor's peak tension) */
typedef struct bd_rep_point {
    int known;
    double value, t, s;
} bd_rep_point;

/* what the report knows */
typedef struct bd_rep {
    const char *dir;
    char plots[BD_REP_PATH_LEN];   /* DIR/plots */
    char model[200];
    char title[BD_REP_LABEL_LEN];
    cJSON *summary;
    /* a conveyor's, from summary.json, NaN when absent */
    double rated_N, safety_factor, t_min_sag_N;
    int sf_default;
    /* a conveyor's peak and lowest tension: from summary.json, else from
     * tension.csv */
    bd_rep_point tmax, tmin;
    /* plots made, in order */
    int nplots;
    struct {
        char name[32];
        char caption[BD_REP_LABEL_LEN];
    } plot[BD_REP_MAX_PLOTS];
    /* temporary allocations freed at the end */
    void *owned[1024];
    int nowned;
    /* texts of the plots being drawn */
    char labels[BD_REP_MAX_LABELS][BD_REP_LABEL_LEN];
    int nlabels;
} bd_rep;

/* a message into err (which may be NULL) */
void bd_rep_err(char *err, size_t errlen, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* 1: path is a regular file */
int bd_rep_file_exists(const char *path);

/* a number for people: about 4 significant digits, no exponent in the
 * usual range, thin spaces between thousands */
void bd_rep_fmt_num(char *buf, size_t len, double v);

/* N, N·m and J get a k, M or G prefix above 10^4, 10^7, 10^10; other
 * units stay as they are */
bd_rep_unit bd_rep_pick_unit(double maxabs, const char *base);

/* a scaled copy v / scale (owned by the caller) */
double *bd_rep_scaled(const double *v, size_t n, double scale);

/* keep p to be freed with the report (NULL when p is NULL or the list is
 * full) */
double *bd_rep_own(bd_rep *r, double *p);

/* a label buffer (BD_REP_LABEL_LEN) that lives as long as the report */
char *bd_rep_label(bd_rep *r);

/* "MODEL — what" into buf */
void bd_rep_set_title(bd_rep *r, char *buf, size_t len, const char *what);

/* draw f to DIR/plots/NAME.png and .svg and keep it, with its caption, for
 * the page; 0, or BD_REPORT_EOUTPUT with a message */
int bd_rep_write_plot(bd_rep *r, const bd_plot_figure *f, const char *name, const char *caption,
                      char *err, size_t errlen);

/* a panel of the columns cols[0..n) of h (−1: left out) against h's first
 * column (time), scaled to a readable unit of base_unit, each named
 * names[i] in the legend (with_range: and its lowest … highest value);
 * ylabel (ylen) gets "quantity [unit]", *uout (may be NULL) the unit.
 * Returns 1, 0 when no column is there, −1 out of memory. */
int bd_rep_columns_panel(bd_rep *r, bd_plot_axes *a, const bd_csv *h, const int *cols,
                         const char *const *names, int n, const char *quantity,
                         const char *base_unit, char *ylabel, size_t ylen, int with_range,
                         bd_rep_unit *uout);

/* the series and sample of a panel's largest value (magnitude: largest
 * |value|) at x ≥ from; 1 found, 0 the panel has no finite point */
int bd_rep_find_extreme(const bd_plot_axes *a, int magnitude, double from, int *series,
                        size_t *sample);

/* a marker at sample bi of series bs of a time panel, "WHAT VALUE UNIT at
 * t = … s". exact: the peak from every step of the run in the panel's unit
 * (summary.json's, which the cards show; the label then gives it, "near"
 * the sample), or NaN for the sample's value */
void bd_rep_mark_sample(bd_rep *r, bd_plot_axes *a, int bs, size_t bi, const char *what,
                        const char *unit_name, int magnitude, double exact);

/* plots/energy from history.csv's kinetic_J, potential_J, dissipated_J and
 * input_J (nothing when one is missing); input_name names the input in the
 * legend. 0, or a BD_REPORT_E* code with a message */
int bd_rep_plot_energy(bd_rep *r, const bd_csv *h, const char *input_name, char *err,
                       size_t errlen);

/* a headline card; cls "ok", "bad" or NULL */
void bd_rep_card(bd_strbuf *b, const char *cls, const char *key, const char *value,
                 const char *detail);

/* the cards every run has: the energy balance error and the warnings */
void bd_rep_run_cards(bd_rep *r, bd_strbuf *b);

/* DIR/report.html: the model, "beltdyn WHAT" with the duration and nodes,
 * cards (which writes the headline cards), the checks, the warnings, the
 * plots made and summary.json as tables. 0, or BD_REPORT_EOUTPUT */
int bd_rep_write_html(bd_rep *r, const char *what, void (*cards)(bd_rep *, bd_strbuf *),
                      char *err, size_t errlen);

/* the report of a boom run (summary.json "kind": "boom", boom_report.c),
 * r's summary read and DIR/plots made; 0, or a BD_REPORT_E* code */
int bd_boom_report_write(bd_rep *r, char *err, size_t errlen);

#endif
