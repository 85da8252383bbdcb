/* beltdyn report: plots and a self-contained HTML report from the output
 * directory of a finished (or interrupted) run. */
#ifndef BELTDYN_REPORT_H
#define BELTDYN_REPORT_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* bd_report_write return codes */
#define BD_REPORT_OK 0
#define BD_REPORT_EOUTPUT 1   /* a plot or report.html could not be written */
#define BD_REPORT_EINPUT 2    /* DIR missing, not a run directory, or a file in it is malformed */

/* read DIR/summary.json (required) and DIR/history.csv, DIR/tension.csv,
 * DIR/envelope.csv (each optional: plots whose data is absent are left out)
 * and write DIR/plots/{tension_surface,envelope,probes,drives,takeups,
 * energy}.{png,svg} and DIR/report.html (one file: images embedded, no
 * outside references). Every file is written to a temporary name and
 * renamed when complete. Returns BD_REPORT_OK, or a BD_REPORT_E* code with
 * a one-line message in err (which may be NULL).
 * A start-study directory (study.csv and study.json from `beltdyn study`,
 * no summary.json) gets the start-curve comparison instead:
 * DIR/plots/study_{tension,peaks}.{png,svg} and DIR/report.html.
 * A boom run's directory (summary.json "kind": "boom", history.csv and
 * beams.csv, each required) gets the boom's report:
 * DIR/plots/{boom_tip,boom_cylinders,boom_pads,boom_moment,boom_shape,
 * energy}.{png,svg} and DIR/report.html (docs/report.md). */
int bd_report_write(const char *dir, char *err, size_t errlen);

/* the pass/fail table of a finished run (DIR/summary.json "checks") on f,
 * one line per check, failures first marked FAIL; returns the number of
 * failed checks, or -1 when DIR has no readable summary.json */
int bd_report_print_checks(const char *dir, FILE *f);

#ifdef __cplusplus
}
#endif

#endif
