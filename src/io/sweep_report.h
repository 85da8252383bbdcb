/* `beltdyn report` on a sweep's directory (sweep_report.c) */
#ifndef BD_IO_SWEEP_REPORT_H
#define BD_IO_SWEEP_REPORT_H

#include <stddef.h>

#include <cjson/cJSON.h>

/* DIR's study.json, parsed (root), is a sweep's: write DIR/plots/sweep_*,
 * DIR/plots/sensitivity, DIR/sensitivity.csv and DIR/report.html.
 * BD_REPORT_OK or a BD_REPORT_E* code with a message in err. */
int bd_sweep_report_write(const char *dir, const cJSON *root, char *err, size_t errlen);

#endif
